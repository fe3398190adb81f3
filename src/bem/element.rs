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
pub use crate::mesh::geometry::ElementGeometry;

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
