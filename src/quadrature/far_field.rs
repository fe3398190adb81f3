//! Whole-element Gauss rules for sources far from a quadratic element, chosen without root
//! finding from a cheap lower bound on the Bernstein-ellipse parameter (see [`super::adaptive`]).

use super::{QuadraticNodes, Quadrature};

/// A lower bound, cheap to evaluate, on the Bernstein-ellipse parameter ρ (relative to the
/// whole element ξ ∈ [−1, 1]) of every complex singularity of an off-element integrand, for
/// far-field sources: it spares the root finding of [`Quadrature::off_element_points`] for the
/// many elements far from an interior point.
///
/// With x(ξ) = x_m + bξ + cξ² (x_m the mid node), a singularity of 1/r, r² = 0 at complex ξ*,
/// satisfies x_m − X = −(bξ* + cξ*²), so D = |X − x_m| ≤ |b||ξ*| + |c||ξ*|² (the triangle
/// inequality in ℂ², b and c real vectors): |ξ*| ≥ R(D) = 2D/(|b| + √(|b|² + 4|c|D)). The zeros
/// of the Jacobian, (b + 2cξ)·(b + 2cξ) = 0, a real quadratic with complex-conjugate roots, have
/// |ξ| = |b|/(2|c|). A point s with |s| = R ≥ 1 has ρ(s) = a + √(a² − 1) with
/// a = (|s − 1| + |s + 1|)/2 ≥ R, hence ρ ≥ R + √(R² − 1) for both kinds.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SingularityBound {
    /// x_m [length].
    centre: [f64; 2],
    /// |b| [length].
    b: f64,
    /// |c| [length].
    c: f64,
    /// The bound on ρ from the Jacobian's zeros (infinite for a straight element).
    rho_jacobian: f64,
}

impl SingularityBound {
    /// The bound of an element.
    pub fn new(nodes: &QuadraticNodes) -> Self {
        let [p0, p1, pm] = *nodes;
        let b = (0.5 * (p1[0] - p0[0])).hypot(0.5 * (p1[1] - p0[1]));
        let c = (0.5 * (p0[0] + p1[0]) - pm[0]).hypot(0.5 * (p0[1] + p1[1]) - pm[1]);
        let rho_jacobian = if c > 0.0 {
            ellipse_of_radius(b / (2.0 * c))
        } else {
            f64::INFINITY
        };
        Self {
            centre: pm,
            b,
            c,
            rho_jacobian,
        }
    }

    /// A lower bound on ρ of every singularity for a source at `source` (see the type's docs).
    pub fn rho_lower_bound(&self, source: [f64; 2]) -> f64 {
        let (dx, dy) = (source[0] - self.centre[0], source[1] - self.centre[1]);
        let d = (dx * dx + dy * dy).sqrt();
        let radius = 2.0 * d / (self.b + (self.b * self.b + 4.0 * self.c * d).sqrt());
        ellipse_of_radius(radius).min(self.rho_jacobian)
    }
}

/// R + √(R² − 1) for R ≥ 1, else 1: the smallest ρ of a point at distance R from 0.
fn ellipse_of_radius(radius: f64) -> f64 {
    if radius > 1.0 {
        radius + (radius * radius - 1.0).sqrt()
    } else {
        1.0
    }
}

impl SingularityBound {
    /// The distance D from the mid node beyond which the bound reaches ρ: the inverse of
    /// [`Self::rho_lower_bound`], D = |c|R² + |b|R with R = (ρ + 1/ρ)/2 [length]; infinite when
    /// the Jacobian's zeros keep the bound below ρ at any distance.
    fn distance_for(&self, rho: f64) -> f64 {
        if self.rho_jacobian < rho {
            return f64::INFINITY;
        }
        let radius = 0.5 * (rho + 1.0 / rho);
        self.c * radius * radius + self.b * radius
    }
}

/// Far-field Gauss rules of one element for a [`Quadrature`]: the squared distances from the mid
/// node beyond which n = first, first + 1, … points on the whole element meet the tolerance by
/// the [`SingularityBound`] (without subdivision), so that choosing the rule for a source costs
/// a few comparisons.
#[derive(Debug, Clone, PartialEq)]
pub struct FarFieldRules {
    /// The mid node [length].
    centre: [f64; 2],
    /// Fewest points ([`QuadratureOptions::min_points`]).
    first: usize,
    /// distance2[n − first]: squared distance [length²] from which n points suffice
    /// (non-increasing in n).
    distance2: Vec<f64>,
}

impl FarFieldRules {
    /// The number of Gauss–Legendre points on the whole element [−1, 1] that meet the tolerance
    /// for `source`, or `None` when the source may be near (then use
    /// [`Quadrature::off_element_points`]). When it is `Some(n)`, the adaptive rule would not
    /// subdivide and would use at most n points, so this rule is at least as accurate.
    #[inline]
    pub fn points(&self, source: [f64; 2]) -> Option<usize> {
        let (dx, dy) = (source[0] - self.centre[0], source[1] - self.centre[1]);
        let d2 = dx * dx + dy * dy;
        self.distance2.iter().position(|&t| d2 >= t).map(|k| self.first + k)
    }
}

impl Quadrature {
    /// The far-field rules of an element with up to `max_points` points (see
    /// [`FarFieldRules`]): n points need ρ ≥ max(min_ellipse, tol^(−1/(2(n − 1)))), the
    /// inverse of the point count n = ⌈ln(1/tol)/(2 ln ρ)⌉ + 1 of the adaptive rule.
    pub fn far_field_rules(&self, nodes: &QuadraticNodes, max_points: usize) -> FarFieldRules {
        let bound = SingularityBound::new(nodes);
        let o = &self.options;
        let first = o.min_points.max(2);
        let distance2 = (first..=max_points.min(o.max_points))
            .map(|n| {
                let rho = (self.log_inv_tolerance / (2.0 * (n - 1) as f64))
                    .exp()
                    .max(o.min_ellipse);
                bound.distance_for(rho).powi(2)
            })
            .collect();
        FarFieldRules {
            centre: bound.centre,
            first,
            distance2,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::super::adaptive::bernstein_parameter;
    use super::super::complex_roots::complex_singularities;
    use super::super::{gauss_legendre, QuadratureOptions};
    use super::*;

    /// Arc length of the quadratic map (16-point Gauss on |x'(ξ)|).
    fn length(nodes: &QuadraticNodes) -> f64 {
        let [p0, p1, pm] = *nodes;
        let (x, w) = gauss_legendre(16);
        x.iter()
            .zip(&w)
            .map(|(&s, &wk)| {
                let d = [s - 0.5, s + 0.5, -2.0 * s];
                let tx = d[0] * p0[0] + d[1] * p1[0] + d[2] * pm[0];
                let ty = d[0] * p0[1] + d[1] * p1[1] + d[2] * pm[1];
                wk * tx.hypot(ty)
            })
            .sum()
    }

    #[test]
    fn singularity_bound_is_below_every_singularity() {
        // Arcs of 10°, 30° and 90°, a straight element and an unevenly parametrised parabola;
        // sources on a grid around each: the bound never exceeds the exact smallest ρ (the
        // roots of complex_singularities), and it is tight far away (within 25 % at 20 lengths).
        let arc = |deg: f64| {
            let h = 0.5 * deg.to_radians();
            [[-(h.sin()), h.cos()], [h.sin(), h.cos()], [0.0, 1.0]]
        };
        let elements: [QuadraticNodes; 5] = [
            arc(10.0),
            arc(30.0),
            arc(90.0),
            [[0.0, 0.0], [2.0, 0.0], [1.0, 0.0]],
            [[0.0, 0.0], [2.0, 0.3], [0.8, 0.4]],
        ];
        for g in &elements {
            let bound = SingularityBound::new(g);
            let length = length(g);
            for i in -20..=20 {
                for j in -20..=20 {
                    let source = [0.37 * length * i as f64, 0.41 * length * j as f64 + 0.013];
                    let exact = bernstein_parameter(complex_singularities(g, source).as_slice(), -1.0, 1.0);
                    let lower = bound.rho_lower_bound(source);
                    assert!(lower <= exact * (1.0 + 1e-12), "{g:?} at {source:?}: {lower} > {exact}");
                }
            }
            let far = [20.0 * length, 3.0];
            let (lower, exact) = (
                bound.rho_lower_bound(far),
                bernstein_parameter(complex_singularities(g, far).as_slice(), -1.0, 1.0),
            );
            assert!(
                lower > 0.75 * exact.min(bound.rho_jacobian),
                "{g:?}: {lower} vs {exact}"
            );
        }
    }

    #[test]
    fn far_field_rules_never_use_fewer_points_than_the_adaptive_rule() {
        // For sources all around three elements: whenever the far-field rule applies, the
        // adaptive rule does not subdivide and uses at most as many points. On the 30° arc and
        // the straight element it serves most sources; on the strongly curved parabola (mid node
        // a quarter of the chord off it) the Jacobian's complex zeros are too close to [−1, 1]
        // for 12 points, so the far-field rule never applies there.
        let q = Quadrature::new(QuadratureOptions::default());
        let h = 15f64.to_radians();
        let elements: [QuadraticNodes; 3] = [
            [[-(h.sin()), h.cos()], [h.sin(), h.cos()], [0.0, 1.0]],
            [[0.0, 0.0], [2.0, 0.0], [1.0, 0.0]],
            [[0.0, 0.0], [2.0, 0.3], [0.8, 0.4]],
        ];
        for g in elements {
            let rules = q.far_field_rules(&g, 12);
            let mut used = 0;
            for i in -30..=30 {
                for j in -30..=30 {
                    let source = [0.9 * i as f64 + 0.01, 0.7 * j as f64 + 0.02];
                    let Some(n) = rules.points(source) else { continue };
                    used += 1;
                    let mut intervals = 0;
                    let mut adaptive = 0;
                    let mut last = f64::NAN;
                    q.off_element_points(&g, source, |xi, _| {
                        adaptive += 1;
                        if xi < last {
                            intervals += 1;
                        }
                        last = xi;
                    });
                    assert!(
                        intervals == 0 && adaptive <= n,
                        "{source:?}: far {n}, adaptive {adaptive}"
                    );
                }
            }
            let curved = g[2] == [0.8, 0.4];
            assert!(
                if curved { used == 0 } else { used > 3000 },
                "{g:?} {rules:?}: far-field rule used for {used} of 3721 sources"
            );
        }
    }
}
