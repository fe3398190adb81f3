//! Boundary elements: geometry (2- or 3-node) and field interpolation (quadratic, with nodes
//! at the ends or moved inside).
//!
//! **Geometry.** Gmsh node order [end0, end1, mid] at ξ = −1, +1, 0:
//! x(ξ) = ½ξ(ξ−1) x0 + ½ξ(ξ+1) x1 + (1−ξ²) xm. A 2-node element is the same map with xm the
//! midpoint of its ends (then exactly linear). The unit normal n = (x'_y, −x'_x)/|x'| points
//! out of the material when the material lies on the left (the mesh convention of
//! [`crate::mesh`]).
//!
//! **Field.** Displacements and tractions are quadratic on every element, interpolated
//! through three field nodes at ξ = (ξ_s, ξ_e, 0), in that order (start, end, mid):
//! * continuous: ξ_s = −1, ξ_e = +1, the end nodes shared with the neighbours;
//! * discontinuous: ξ_s = −2/3, ξ_e = +2/3 (the paper's contact elements, the same nodes as
//!   [`crate::grid::ElementKind::DiscontinuousQuadratic`]);
//! * partially discontinuous: one end moved to ±2/3 (at corners and where the boundary
//!   condition changes), Brebbia–Dominguez, *Boundary Elements: An Introductory Course* §5.5.
//!
//! Collocation at a moved node is at a smooth point of the boundary, where the free term is ½δij.

use crate::grid::DQE_NODE;
use crate::mesh::{BoundaryElement, BoundaryMesh};
use crate::quadrature::gauss_legendre;

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
        let (x, w) = gauss_legendre(16);
        x.iter().zip(&w).map(|(&s, &wk)| wk * self.jacobian(s)).sum()
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

/// Quadratic field interpolation through nodes at ξ = (start, end, 0), in that order.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct FieldInterpolation {
    /// ξ of the start-side node: −1 (continuous) or −2/3 (discontinuous end).
    pub start: f64,
    /// ξ of the end-side node: +1 (continuous) or +2/3 (discontinuous end).
    pub end: f64,
}

impl FieldInterpolation {
    /// Continuous quadratic element: field nodes at ξ = −1, +1, 0.
    pub const CONTINUOUS: Self = Self { start: -1.0, end: 1.0 };

    /// Discontinuous quadratic element: field nodes at ξ = −2/3, +2/3, 0.
    pub const DISCONTINUOUS: Self = Self {
        start: -DQE_NODE,
        end: DQE_NODE,
    };

    /// Quadratic element with the start and/or end node moved inside to ∓2/3.
    pub fn with_discontinuous_ends(start: bool, end: bool) -> Self {
        Self {
            start: if start { -DQE_NODE } else { -1.0 },
            end: if end { DQE_NODE } else { 1.0 },
        }
    }

    /// Whether the start node sits at the element end (shared with the neighbour).
    pub fn start_is_shared(&self) -> bool {
        self.start == -1.0
    }

    /// Whether the end node sits at the element end (shared with the neighbour).
    pub fn end_is_shared(&self) -> bool {
        self.end == 1.0
    }

    /// ξ of the field nodes, order (start, end, mid).
    pub fn node_coordinates(&self) -> [f64; 3] {
        [self.start, self.end, 0.0]
    }

    /// Lagrange shape functions N_a(ξ) through (ξ_s, ξ_e, 0).
    pub fn shape(&self, xi: f64) -> [f64; 3] {
        let (s, e) = (self.start, self.end);
        [
            xi * (xi - e) / (s * (s - e)),
            xi * (xi - s) / (e * (e - s)),
            (xi - s) * (xi - e) / (s * e),
        ]
    }

    /// Derivatives dN_a/dξ.
    pub fn shape_derivative(&self, xi: f64) -> [f64; 3] {
        let (s, e) = (self.start, self.end);
        [
            (2.0 * xi - e) / (s * (s - e)),
            (2.0 * xi - s) / (e * (e - s)),
            (2.0 * xi - s - e) / (s * e),
        ]
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn shape_functions_are_cardinal_sum_to_one_and_match_their_derivatives() {
        for f in [
            FieldInterpolation::CONTINUOUS,
            FieldInterpolation::DISCONTINUOUS,
            FieldInterpolation::with_discontinuous_ends(true, false),
            FieldInterpolation::with_discontinuous_ends(false, true),
        ] {
            let xs = f.node_coordinates();
            for (a, &xa) in xs.iter().enumerate() {
                let n = f.shape(xa);
                for (b, &v) in n.iter().enumerate() {
                    assert!((v - if a == b { 1.0 } else { 0.0 }).abs() < 1e-14);
                }
            }
            for xi in [-1.0, -0.4, 0.1, 0.9] {
                assert!((f.shape(xi).iter().sum::<f64>() - 1.0).abs() < 1e-14);
                let h = 1e-6;
                let (p, m, d) = (f.shape(xi + h), f.shape(xi - h), f.shape_derivative(xi));
                for a in 0..3 {
                    assert!(((p[a] - m[a]) / (2.0 * h) - d[a]).abs() < 1e-8);
                }
            }
        }
    }

    #[test]
    fn discontinuous_shapes_agree_with_the_contact_grid() {
        // Same Lagrange basis as the contact grid's DQE (grid order: −2/3, 0, +2/3).
        let kind = crate::grid::ElementKind::DiscontinuousQuadratic;
        let f = FieldInterpolation::DISCONTINUOUS;
        for xi in [-0.9, -0.2, 0.5] {
            let ours = f.shape(xi);
            let grid: Vec<f64> = (0..3)
                .map(|a| {
                    let [c0, c1, c2] = kind.shape_polynomial(a);
                    c0 + c1 * xi + c2 * xi * xi
                })
                .collect();
            assert!((ours[0] - grid[0]).abs() < 1e-14);
            assert!((ours[2] - grid[1]).abs() < 1e-14);
            assert!((ours[1] - grid[2]).abs() < 1e-14);
        }
    }

    #[test]
    fn quadratic_arc_geometry_has_outward_normals_and_the_right_length() {
        // Quarter circle of radius 2 walked counter-clockwise (material inside, on the left).
        let r = 2.0;
        let a = std::f64::consts::FRAC_PI_4;
        let g = ElementGeometry {
            nodes: [[r, 0.0], [0.0, r], [r * a.cos(), r * a.sin()]],
        };
        let p = g.point(0.3);
        let n = g.normal(0.3);
        let radial = (p[0] * n[0] + p[1] * n[1]) / p[0].hypot(p[1]);
        assert!(radial > 0.999, "{radial}");
        // The parabola through three points of a 90° arc is 0.53 % shorter than πr/2; its own
        // length (3.1248342506615 by a 2·10⁵-panel midpoint rule) is met by the 16-point rule.
        assert!((g.length() - 3.1248342506615).abs() < 1e-11, "{}", g.length());
        let straight = ElementGeometry {
            nodes: [[0.0, 0.0], [3.0, 4.0], [1.5, 2.0]],
        };
        assert!((straight.length() - 5.0).abs() < 1e-14);
        assert!((straight.jacobian(0.7) - 2.5).abs() < 1e-14);
    }

    /// The abscissa is found again to round-off on nearly straight arcs (a roller of R 100 cut
    /// to elements of 1e-5 mm, where the text-book root formula lost five digits), on a
    /// strongly curved one (a 90° arc), and on a straight element.
    #[test]
    fn parameter_at_x_inverts_x_of_xi_to_round_off() {
        // Nodes at angles round the roller's centre, the mid node at the mid angle (as Gmsh
        // and the cuts place them): x(ξ) is then slightly curved, c₂/c₁ ≈ 1e-11 at 1e-5 mm.
        let roller = |x: f64| {
            let t = (x / 100.0).asin();
            [100.0 * t.sin(), 100.0 - 100.0 * t.cos()]
        };
        let arc = |x0: f64, x1: f64| {
            let mid = 100.0 * (0.5 * ((x0 / 100.0).asin() + (x1 / 100.0).asin())).sin();
            [roller(x0), roller(x1), roller(mid)]
        };
        let quarter = |t: f64| [2.0 * t.cos(), 2.0 * t.sin()];
        let elements = [
            arc(0.049, 0.049_01),
            arc(-0.049_01, -0.049),
            arc(-1.2, -1.1),
            [quarter(0.0), quarter(1.2), quarter(0.6)],
            [[0.0, 0.0], [3.0, 4.0], [1.5, 2.0]],
        ];
        for nodes in elements {
            let g = ElementGeometry { nodes };
            for xi in [-1.0, -0.7, -0.2, 0.0, 1.0 / 3.0, 0.9, 1.0] {
                let x = g.point(xi)[0];
                let found = g.parameter_at_x(x).expect("x lies on the element");
                let back = g.point(found)[0];
                let scale = nodes[0][0].abs().max(nodes[1][0].abs());
                assert!(
                    (back - x).abs() <= 4.0 * f64::EPSILON * scale,
                    "{nodes:?} at ξ {xi}: x {x} found at ξ {found}, giving {back}"
                );
            }
        }
    }
}
