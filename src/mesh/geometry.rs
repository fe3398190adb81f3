//! The geometry of one boundary element (2- or 3-node, Gmsh node order [end0, end1, mid] at
//! ξ = −1, +1, 0): x(ξ) = ½ξ(ξ−1) x0 + ½ξ(ξ+1) x1 + (1−ξ²) xm. A 2-node element is the same map
//! with xm the midpoint of its ends (then exactly linear). The unit normal n = (x'_y, −x'_x)/|x'|
//! points out of the material when the material lies on the left (the convention of this module's
//! parent). Used by the BEM's integration, by a mesh's cuts along a contact grid and by the
//! contact group's circle fit.

use super::{BoundaryElement, BoundaryMesh};
use crate::quadrature::gauss_legendre;
use std::sync::OnceLock;

/// The 16-point Gauss–Legendre rule of the arc lengths, computed once (a bisection for the
/// parameter at a given length evaluates it 60 times).
fn arc_length_rule() -> &'static (Vec<f64>, Vec<f64>) {
    static RULE: OnceLock<(Vec<f64>, Vec<f64>)> = OnceLock::new();
    RULE.get_or_init(|| gauss_legendre(16))
}

/// Geometry of one element: x(ξ) on ξ ∈ [−1, 1], see the module docs.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ElementGeometry {
    /// Nodes [end0, end1, mid] [length]; for a 2-node element the mid node is the midpoint.
    pub nodes: [[f64; 2]; 3],
}

impl ElementGeometry {
    /// The ξ ∈ [−1, 1] at which the element's x(ξ) equals x (None if x is outside its
    /// x-range): x(ξ) = x_m + ξ(x₁ − x₀)/2 + ξ²((x₀ + x₁)/2 − x_m).
    ///
    /// The roots are taken in the stable pair q = −(c₁ + sgn(c₁)√disc)/2, ξ = q/c₂ and c₀/q:
    /// the text-book (−c₁ ± √disc)/(2c₂) cancels for the nearly straight elements of a contact
    /// arc (c₂/c₁ ≈ h/4R), and lost 1e-11 mm in x on a roller of R 100 cut to 1e-5 mm elements.
    pub fn parameter_at_x(&self, x: f64) -> Option<f64> {
        let [p0, p1, pm] = self.nodes;
        let (c0, c1, c2) = (pm[0] - x, 0.5 * (p1[0] - p0[0]), 0.5 * (p0[0] + p1[0]) - pm[0]);
        let roots: Vec<f64> = if c2.abs() < 1e-14 * c1.abs() {
            vec![-c0 / c1]
        } else {
            let disc = c1 * c1 - 4.0 * c2 * c0;
            if disc < 0.0 {
                return None;
            }
            let q = -0.5 * (c1 + disc.sqrt().copysign(c1));
            if q == 0.0 {
                vec![0.0]
            } else {
                vec![c0 / q, q / c2]
            }
        };
        roots
            .into_iter()
            .find(|r| r.abs() <= 1.0 + 1e-12)
            .map(|r| r.clamp(-1.0, 1.0))
    }

    /// Geometry of element `e` of `mesh`.
    pub fn from_mesh(mesh: &BoundaryMesh, e: usize) -> Self {
        Self::of_element(&mesh.elements[e], &mesh.nodes)
    }

    /// Geometry of element `el` whose node indices point into `nodes` [length].
    pub fn of_element(el: &BoundaryElement, nodes: &[[f64; 2]]) -> Self {
        let a = nodes[el.nodes[0]];
        let b = nodes[el.nodes[1]];
        let m = if el.nodes.len() == 3 {
            nodes[el.nodes[2]]
        } else {
            [0.5 * (a[0] + b[0]), 0.5 * (a[1] + b[1])]
        };
        Self { nodes: [a, b, m] }
    }

    /// Position x(ξ) [length].
    pub fn point(&self, xi: f64) -> [f64; 2] {
        let n = [0.5 * xi * (xi - 1.0), 0.5 * xi * (xi + 1.0), 1.0 - xi * xi];
        self.combine(n)
    }

    /// Tangent dx/dξ [length].
    pub fn tangent(&self, xi: f64) -> [f64; 2] {
        self.combine([xi - 0.5, xi + 0.5, -2.0 * xi])
    }

    /// Second derivative d²x/dξ² [length] (constant).
    pub fn curvature_vector(&self) -> [f64; 2] {
        self.combine([1.0, 1.0, -2.0])
    }

    /// Jacobian J = |dx/dξ| [length] (`sqrt`, not `hypot`, as in [`Self::jacobian_and_normal`]).
    pub fn jacobian(&self, xi: f64) -> f64 {
        let t = self.tangent(xi);
        (t[0] * t[0] + t[1] * t[1]).sqrt()
    }

    /// The curve's height y [length] and slope dy/dx [-] at ξ (the contact surface of an
    /// element of a contact group, walked along x).
    pub fn height_and_slope(&self, xi: f64) -> (f64, f64) {
        let t = self.tangent(xi);
        (self.point(xi)[1], t[1] / t[0])
    }

    /// A bound on the error [rad] of the tangent's direction at ξ that comes from the nodes'
    /// coordinates alone, each off the curve it stands for by up to `node_error` [length] (their
    /// round-off: a few ulps of the largest coordinate that placed them). The tangent
    /// (ξ − ½)x₀ + (ξ + ½)x₁ − 2ξx_m weighs the nodes by at most 4 in all on ξ ∈ [−1, 1], so its
    /// component across itself is off by up to 4·`node_error`, against its length J. The bound
    /// grows as the element shrinks: on an element of 1e-6 mm whose nodes lie on a circle of
    /// radius 30 (node errors ~1e-14 mm) it is ~1e-7 rad, which is all the element's slope
    /// tells there.
    pub fn tangent_angle_round_off(&self, xi: f64, node_error: f64) -> f64 {
        4.0 * node_error / self.jacobian(xi)
    }

    /// Unit normal out of the material (material on the left of the walking direction).
    pub fn normal(&self, xi: f64) -> [f64; 2] {
        self.jacobian_and_normal(xi).1
    }

    /// (J [length], unit outward normal) at ξ from one tangent evaluation: what every
    /// boundary integrand needs at a quadrature point. J by `sqrt` rather than `hypot` (several
    /// times slower, at every quadrature point of a BEM assembly): |dx/dξ|² of a mesh element
    /// in engineering units is far from over- and underflow.
    #[inline]
    pub fn jacobian_and_normal(&self, xi: f64) -> (f64, [f64; 2]) {
        let t = self.tangent(xi);
        let j = (t[0] * t[0] + t[1] * t[1]).sqrt();
        (j, [t[1] / j, -t[0] / j])
    }

    /// Arc length [length] (16-point Gauss on J: round-off for straight elements, ~1e-12
    /// relative for a parabola through a 90° arc).
    pub fn length(&self) -> f64 {
        let (x, w) = arc_length_rule();
        x.iter().zip(w).map(|(&s, &wk)| wk * self.jacobian(s)).sum()
    }

    /// Arc length [length] from the start (ξ = −1) to ξ (16-point Gauss on J over [−1, ξ]).
    pub fn length_to(&self, xi: f64) -> f64 {
        let (x, w) = arc_length_rule();
        let half = 0.5 * (xi + 1.0);
        x.iter()
            .zip(w)
            .map(|(&s, &wk)| wk * half * self.jacobian(-1.0 + half * (s + 1.0)))
            .sum()
    }

    /// The ξ at arc length `s` [length] from the start (bisection on [`Self::length_to`]; `s`
    /// clamped to the element).
    pub fn parameter_at_length(&self, s: f64) -> f64 {
        let (mut lo, mut hi) = (-1.0_f64, 1.0_f64);
        for _ in 0..60 {
            let mid = 0.5 * (lo + hi);
            if self.length_to(mid) < s {
                lo = mid;
            } else {
                hi = mid;
            }
        }
        0.5 * (lo + hi)
    }

    fn combine(&self, n: [f64; 3]) -> [f64; 2] {
        let mut p = [0.0; 2];
        for (a, node) in self.nodes.iter().enumerate() {
            p[0] += n[a] * node[0];
            p[1] += n[a] * node[1];
        }
        p
    }
}
