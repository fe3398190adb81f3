//! The steady-rolling derivative operator D: ∂w/∂x at the nodes from nodal values of w.
//!
//! In steady state the slip is s = σ(ξ + ∂w/∂x) (paper Eq. 7). The derivative is taken towards
//! the upstream side, where the material comes from (paper Eq. 8: "backward with respect to the
//! true displacements of the surface points"), so that a stick zone is marched from the leading
//! edge. Two variants:
//!
//! * [`SlipDerivative::FirstOrder`] — the paper's Eq. 8/17: (w_up − w_i)/(x_up − x_i), O(h).
//! * [`SlipDerivative::SecondOrder`] — the derivative at x_i of the quadratic through x_i and its
//!   two upstream neighbours, (−3w_i + 4w_up1 − w_up2)/(2 Δ) with Δ = x_up1 − x_i, O(h²): the
//!   order of the quadratic traction elements. On the upstream end, where two upstream
//!   neighbours do not exist, the first-order or (last node) downstream difference is used; that
//!   node lies outside the contact on any sensible grid.

use crate::grid::ContactGrid;
use faer::Mat;
use serde::{Deserialize, Serialize};

/// Finite-difference scheme of the steady-rolling derivative.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum SlipDerivative {
    /// Paper Eq. 8/17: one-sided first-order upwind difference.
    FirstOrder,
    /// Second-order upwind difference (quadratic through the node and two upstream nodes).
    SecondOrder,
}

/// Sparse rows of D: `rows[i]` lists (node, coefficient) pairs with (D w)_i = Σ c·w_node.
#[derive(Debug, Clone)]
pub struct SlipOperator {
    /// The scheme.
    pub scheme: SlipDerivative,
    /// Stencil of each row [1/length].
    pub rows: Vec<Vec<(usize, f64)>>,
    /// Creepage weight e_ξ of each row (paper Eq. 41): 1, and 0 on the upstream end node.
    pub creep_weight: Vec<f64>,
    /// Index of the upstream end node (where material enters the grid).
    pub upstream_end: usize,
}

impl SlipOperator {
    /// Builds D on the grid for the material flow sign σ (upstream is −σ along x).
    pub fn new(grid: &ContactGrid, scheme: SlipDerivative, flow_sign: f64) -> Self {
        let m = grid.n_nodes();
        let x = &grid.nodes;
        // Upstream neighbour k steps away from node i, if it exists.
        let up = |i: usize, k: usize| -> Option<usize> {
            if flow_sign < 0.0 {
                (i + k < m).then_some(i + k)
            } else {
                i.checked_sub(k)
            }
        };
        let upstream_end = if flow_sign < 0.0 { m - 1 } else { 0 };
        let spacing = grid.node_spacing();
        let two_point = |i: usize, j: usize| vec![(i, -1.0 / (x[j] - x[i])), (j, 1.0 / (x[j] - x[i]))];
        let rows = (0..m)
            .map(|i| match (scheme, up(i, 1), up(i, 2)) {
                (SlipDerivative::SecondOrder, Some(u1), Some(u2)) => {
                    // f'(x_i) of the quadratic through x_i, x_u1, x_u2 (any spacing):
                    // with h1 = x_u1 − x_i, h2 = x_u2 − x_i; (−1.5, 2, −0.5)/h when uniform.
                    let (h1, h2) = (x[u1] - x[i], x[u2] - x[i]);
                    vec![
                        (i, -(h1 + h2) / (h1 * h2)),
                        (u1, h2 / (h1 * (h2 - h1))),
                        (u2, -h1 / (h2 * (h2 - h1))),
                    ]
                }
                (_, Some(u1), _) => two_point(i, u1),
                (_, None, _) => vec![(i, 1.0 / spacing)],
            })
            .collect();
        let creep_weight = (0..m).map(|i| if i == upstream_end { 0.0 } else { 1.0 }).collect();
        Self {
            scheme,
            rows,
            creep_weight,
            upstream_end,
        }
    }

    /// (D w)_i for a vector w.
    pub fn apply(&self, w: &[f64]) -> Vec<f64> {
        self.rows
            .iter()
            .map(|row| row.iter().map(|&(j, c)| c * w[j]).sum())
            .collect()
    }

    /// scale · D · M for a dense matrix M (row i is a combination of a few rows of M).
    pub fn apply_scaled(&self, mat: &Mat<f64>, scale: f64) -> Mat<f64> {
        Mat::from_fn(mat.nrows(), mat.ncols(), |i, j| {
            scale * self.rows[i].iter().map(|&(k, c)| c * mat[(k, j)]).sum::<f64>()
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::grid::ElementKind;

    #[test]
    fn second_order_is_exact_for_quadratics_and_first_order_for_lines() {
        let g = ContactGrid::uniform(ElementKind::DiscontinuousQuadratic, 5, -1.0, 1.0);
        let quad: Vec<f64> = g.nodes.iter().map(|x| 1.0 + 2.0 * x - 3.0 * x * x).collect();
        let line: Vec<f64> = g.nodes.iter().map(|x| 1.0 + 2.0 * x).collect();
        for flow in [-1.0, 1.0] {
            let d2 = SlipOperator::new(&g, SlipDerivative::SecondOrder, flow).apply(&quad);
            let d1 = SlipOperator::new(&g, SlipDerivative::FirstOrder, flow).apply(&line);
            for (i, x) in g.nodes.iter().enumerate() {
                let op = SlipOperator::new(&g, SlipDerivative::FirstOrder, flow);
                if i == op.upstream_end {
                    assert_eq!(op.creep_weight[i], 0.0);
                    continue;
                }
                assert!((d1[i] - 2.0).abs() < 1e-12);
                // All but the two upstream-end nodes use the full second-order stencil.
                let interior = if flow < 0.0 { i + 2 < g.n_nodes() } else { i >= 2 };
                if interior {
                    assert!((d2[i] - (2.0 - 6.0 * x)).abs() < 1e-11, "node {i}: {}", d2[i]);
                }
            }
        }
    }
}
