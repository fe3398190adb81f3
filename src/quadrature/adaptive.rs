//! The adaptive Gauss rule for a source off a quadratic element.
//!
//! The integrand of a boundary integral is analytic on the element except where r² = 0 or the
//! Jacobian vanishes, at complex ξ ([`super::complex_roots`]). With ρ the Bernstein-ellipse
//! parameter of the nearest such point relative to the (sub)interval, n-point Gauss–Legendre
//! converges like ρ^(−2n) (Trefethen, *Approximation Theory and Approximation Practice*,
//! Thm 19.3), so n = ⌈ln(1/tol)/(2 ln ρ)⌉ + 1. When ρ is below
//! [`QuadratureOptions::min_ellipse`] the interval is halved (adaptive subdivision, as Lachat &
//! Watson's element subdivision), which keeps the accuracy down to sources at a small fraction
//! of the element length from it (nearly singular integrals of thin bodies).

use super::complex_roots::complex_singularities;
use super::{gauss_legendre, log_gauss, QuadraticNodes, SingularityBound};
use nalgebra::Complex;

/// Accuracy controls of the adaptive rule and of the rules for an element that holds the source.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct QuadratureOptions {
    /// Target relative accuracy of the regular and nearly singular integrals.
    pub tolerance: f64,
    /// Smallest Bernstein-ellipse parameter ρ accepted without subdividing (ρ = 3 needs 14
    /// points for 1e-12).
    pub min_ellipse: f64,
    /// Fewest Gauss points per (sub)interval.
    pub min_points: usize,
    /// Most Gauss points per (sub)interval.
    pub max_points: usize,
    /// Deepest subdivision (intervals of 2^−depth of the element).
    pub max_depth: usize,
    /// Gauss–Legendre points per part of a singular element.
    pub singular_points: usize,
    /// Log-weighted Gauss points per part of a singular element.
    pub log_points: usize,
}

impl Default for QuadratureOptions {
    fn default() -> Self {
        Self {
            tolerance: 1e-12,
            min_ellipse: 3.0,
            min_points: 4,
            max_points: 24,
            max_depth: 30,
            singular_points: 16,
            log_points: 12,
        }
    }
}

/// Precomputed quadrature rules shared by all element integrals of an assembly.
#[derive(Debug, Clone)]
pub struct Quadrature {
    /// The controls.
    pub options: QuadratureOptions,
    /// Gauss–Legendre rules on [−1, 1], index n − 1 for n points.
    legendre: Vec<(Vec<f64>, Vec<f64>)>,
    /// Log-weighted rule on [0, 1] for the weight ln(1/t).
    log: (Vec<f64>, Vec<f64>),
    /// ln(1/tolerance).
    pub(super) log_inv_tolerance: f64,
    /// The Bernstein-ellipse parameter ρ from which the adaptive rule takes
    /// [`QuadratureOptions::min_points`] on the whole element ([`Self::off_element_points`]).
    min_points_rho: f64,
}

impl Quadrature {
    /// Builds the rules for `options`.
    pub fn new(options: QuadratureOptions) -> Self {
        let top = options.max_points.max(options.singular_points).max(1);
        let log_inv_tolerance = (1.0 / options.tolerance).ln();
        // n points need ρ ≥ exp(ln(1/tol)/(2(n − 1))) (the inverse of `points_for`), and no
        // subdivision ρ ≥ min_ellipse. The margin keeps the adaptive rule's own rounding of ρ
        // clear of the threshold, so that both choose the same points.
        let n = options.min_points.max(2) as f64;
        let rho = (log_inv_tolerance / (2.0 * (n - 1.0))).exp().max(options.min_ellipse) * (1.0 + 1e-6);
        Self {
            options,
            legendre: (1..=top).map(gauss_legendre).collect(),
            log: log_gauss(options.log_points.max(1)),
            log_inv_tolerance,
            min_points_rho: rho,
        }
    }

    /// The n-point Gauss–Legendre rule on [−1, 1] (n clamped to the precomputed range).
    pub fn legendre(&self, n: usize) -> &(Vec<f64>, Vec<f64>) {
        &self.legendre[n.clamp(1, self.legendre.len()) - 1]
    }

    /// The [`QuadratureOptions::log_points`]-point rule (nodes, weights) on [0, 1] for the
    /// weight ln(1/t) ([`log_gauss()`]).
    pub fn log_rule(&self) -> &(Vec<f64>, Vec<f64>) {
        &self.log
    }

    /// Visits the quadrature points (ξ, weight in dξ) of the adaptive Gauss rule for the
    /// element of `nodes` and a source off it (see the module docs): intervals are halved until
    /// the nearest complex singularity of r² or J lies outside the Bernstein ellipse of parameter
    /// [`QuadratureOptions::min_ellipse`], and each interval gets the points its ellipse needs
    /// for [`QuadratureOptions::tolerance`]. The estimate is that of a 1/r kernel; it serves the
    /// 1/r² kernels (T*, V, S) as well, whose Gauss error decays at the same geometric rate.
    /// Any kernel can be integrated with it: the caller evaluates its integrand at x(ξ) and
    /// multiplies by J(ξ) and the weight.
    ///
    /// Nothing is allocated (this runs once per element and source point: millions of times
    /// for an interior grid); the subdivision depth is capped at [`MAX_DEPTH`], below which
    /// intervals are finer than the resolution of ξ in double precision.
    pub fn off_element_points(&self, nodes: &QuadraticNodes, source: [f64; 2], mut visit: impl FnMut(f64, f64)) {
        if self.far_enough_for_fewest_points(nodes, source) {
            // What the adaptive rule would choose too: no subdivision, the fewest points.
            let (x, w) = self.legendre(self.options.min_points);
            for (&s, &wk) in x.iter().zip(w) {
                visit(s, wk);
            }
            return;
        }
        self.adaptive_points(nodes, source, visit);
    }

    /// Whether every singularity of the element's integrand lies so far from the element, by
    /// the lower bound of [`SingularityBound`] (no root finding: most source–element pairs of an
    /// assembly are far apart), that the adaptive rule neither subdivides nor takes more than
    /// [`QuadratureOptions::min_points`].
    #[inline]
    fn far_enough_for_fewest_points(&self, nodes: &QuadraticNodes, source: [f64; 2]) -> bool {
        SingularityBound::new(nodes).rho_lower_bound(source) >= self.min_points_rho
    }

    /// [`Self::off_element_points`] by the roots: the adaptive rule itself.
    fn adaptive_points(&self, nodes: &QuadraticNodes, source: [f64; 2], mut visit: impl FnMut(f64, f64)) {
        let o = &self.options;
        let poles = complex_singularities(nodes, source);
        let max_depth = o.max_depth.min(MAX_DEPTH);
        // Depth-first: at most one pending sibling per level, so max_depth + 1 entries.
        let mut stack = [(0.0, 0.0, 0usize); MAX_DEPTH + 1];
        stack[0] = (-1.0, 1.0, 0);
        let mut top = 1;
        while top > 0 {
            top -= 1;
            let (lo, hi, depth) = stack[top];
            let rho = bernstein_parameter(poles.as_slice(), lo, hi);
            if rho < o.min_ellipse && depth < max_depth {
                let mid = 0.5 * (lo + hi);
                stack[top] = (lo, mid, depth + 1);
                stack[top + 1] = (mid, hi, depth + 1);
                top += 2;
                continue;
            }
            let n = points_for(rho, self.log_inv_tolerance).clamp(o.min_points, o.max_points);
            let (x, w) = self.legendre(n);
            let half = 0.5 * (hi - lo);
            for (&s, &wk) in x.iter().zip(w) {
                visit(0.5 * (lo + hi) + half * s, wk * half);
            }
        }
    }
}

/// Gauss points needed for relative accuracy tol when the nearest singularity has Bernstein
/// parameter ρ: error ≈ ρ^(−2n).
/// `log_inv_tol` = ln(1/tol), computed once per [`Quadrature`].
pub(super) fn points_for(rho: f64, log_inv_tol: f64) -> usize {
    if !rho.is_finite() {
        return 1;
    }
    let n = log_inv_tol / (2.0 * rho.max(1.0 + 1e-12).ln());
    n.ceil() as usize + 1
}

/// Deepest interval halving of [`Quadrature::off_element_points`] whatever the options: 2^−50
/// of the element is at the resolution of ξ ∈ [−1, 1] in double precision.
pub const MAX_DEPTH: usize = 50;

/// Smallest Bernstein-ellipse parameter ρ = a + √(a² − 1) of the singularities relative to the
/// interval [lo, hi], with a = (|s − 1| + |s + 1|)/2 the semi-major axis through the point s
/// in the interval's own coordinate s ∈ [−1, 1].
pub fn bernstein_parameter(poles: &[Complex<f64>], lo: f64, hi: f64) -> f64 {
    let mid = 0.5 * (lo + hi);
    let half = 0.5 * (hi - lo);
    poles
        .iter()
        .map(|p| {
            let s = (p - mid) / half;
            // |z| as √(z·z̄): Complex::norm calls hypot, several times slower.
            let a = 0.5 * ((s - 1.0).norm_sqr().sqrt() + (s + 1.0).norm_sqr().sqrt());
            a + (a * a - 1.0).max(0.0).sqrt()
        })
        .fold(f64::INFINITY, f64::min)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The points of a rule, as bits.
    fn points(q: &Quadrature, nodes: &QuadraticNodes, source: [f64; 2], adaptive: bool) -> Vec<(u64, u64)> {
        let mut out = Vec::new();
        let visit = |x: f64, w: f64| out.push((x.to_bits(), w.to_bits()));
        if adaptive {
            q.adaptive_points(nodes, source, visit);
        } else {
            q.off_element_points(nodes, source, visit);
        }
        out
    }

    /// Over sources from a thousandth of an element to ten thousand elements away, around
    /// straight and strongly bowed elements: wherever the shortcut applies, the adaptive rule
    /// takes the same points to the bit; it applies to every distant source of a nearly straight
    /// element (a boundary element on a circle bows by |c|/|b| ≈ h/(8R)) and to no near one.
    #[test]
    fn the_shortcut_takes_the_adaptive_rules_points() {
        let q = Quadrature::new(QuadratureOptions::default());
        let (mut taken, mut far) = (0, 0);
        for bow in [0.0, 1e-9, 1e-3, 0.1, 0.3] {
            let nodes: QuadraticNodes = [[-1.0, 0.0], [1.0, 0.0], [0.0, bow]];
            for k in 0..400 {
                let distance = 10f64.powf(-3.0 + 7.0 * (k as f64) / 400.0);
                let angle = 0.37 * k as f64;
                let source = [distance * angle.cos(), bow + distance * angle.sin()];
                let fast = q.far_enough_for_fewest_points(&nodes, source);
                let exact = points(&q, &nodes, source, true);
                if fast {
                    taken += 1;
                    assert_eq!(points(&q, &nodes, source, false), exact, "bow {bow}, source {source:?}");
                    assert_eq!(exact.len(), q.options.min_points, "one interval, fewest points");
                } else {
                    assert_eq!(points(&q, &nodes, source, false), exact);
                }
                if distance < 10.0 {
                    assert!(!fast, "a near source ({distance}) takes the adaptive rule");
                }
                // A bow above 1 % of the half-chord puts the Jacobian's zeros within reach of
                // any source (|ξ| = |b|/(2|c|)): the adaptive rule then takes more points.
                if distance > 1e3 && bow <= 1e-3 {
                    far += 1;
                    assert!(fast, "a distant source ({distance}) takes the shortcut, bow {bow}");
                }
            }
        }
        assert!(taken > far / 2 && far > 0, "{taken} shortcuts, {far} distant sources");
    }
}
