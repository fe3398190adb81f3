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
//!   neighbours do not exist, the first-order difference is used.
//!
//! **The upstream end node.** It has no upstream neighbour, so its row of the contact problem is
//! replaced: (D w)_end = w_end/h with no creepage term, which fixes the free datum of w (the
//! material entering the grid carries no tangential displacement yet; paper Eq. 41 with e_ξ = 0)
//! and is no slip at all. Its slip velocity, for the outputs, is the derivative of the same
//! order taken downstream instead ([`SlipOperator::end_velocity_row`]): the end node lies
//! outside the contact on any sensible grid, where w is smooth and either side gives ∂w/∂x.

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
    /// Stencil of ∂w/∂x at the upstream end node taken downstream, of the scheme's order
    /// [1/length]: the end node's slip velocity s = σ(ξ + Σ c·w) for the outputs (its row in
    /// `rows` is the datum equation, see the module docs). Empty on a one-node grid.
    pub end_velocity_row: Vec<(usize, f64)>,
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
        // Neighbour k steps downstream of node i, if it exists.
        let down = |i: usize, k: usize| -> Option<usize> {
            if flow_sign < 0.0 {
                i.checked_sub(k)
            } else {
                (i + k < m).then_some(i + k)
            }
        };
        let upstream_end = if flow_sign < 0.0 { m - 1 } else { 0 };
        let spacing = grid.node_spacing();
        let one_sided = |i: usize, n1: Option<usize>, n2: Option<usize>| match (scheme, n1, n2) {
            (SlipDerivative::SecondOrder, Some(u1), Some(u2)) => three_point(x, i, u1, u2),
            (_, Some(u1), _) => two_point(x, i, u1),
            (_, None, _) => Vec::new(),
        };
        let rows = (0..m)
            .map(|i| match up(i, 1) {
                Some(_) => one_sided(i, up(i, 1), up(i, 2)),
                None => vec![(i, 1.0 / spacing)],
            })
            .collect();
        let creep_weight = (0..m).map(|i| if i == upstream_end { 0.0 } else { 1.0 }).collect();
        let end_velocity_row = one_sided(upstream_end, down(upstream_end, 1), down(upstream_end, 2));
        Self {
            scheme,
            rows,
            creep_weight,
            upstream_end,
            end_velocity_row,
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

/// f'(x_i) of the line through x_i and x_j: (w_j − w_i)/(x_j − x_i).
fn two_point(x: &[f64], i: usize, j: usize) -> Vec<(usize, f64)> {
    vec![(i, -1.0 / (x[j] - x[i])), (j, 1.0 / (x[j] - x[i]))]
}

/// f'(x_i) of the quadratic through x_i, x_j, x_k (any spacing): with h1 = x_j − x_i,
/// h2 = x_k − x_i; (−1.5, 2, −0.5)/h when uniform.
fn three_point(x: &[f64], i: usize, j: usize, k: usize) -> Vec<(usize, f64)> {
    let (h1, h2) = (x[j] - x[i], x[k] - x[i]);
    vec![
        (i, -(h1 + h2) / (h1 * h2)),
        (j, h2 / (h1 * (h2 - h1))),
        (k, -h1 / (h2 * (h2 - h1))),
    ]
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
            // The end node's velocity row, taken downstream, is exact to the same order.
            let end = |scheme, w: &[f64]| {
                let op = SlipOperator::new(&g, scheme, flow);
                let d: f64 = op.end_velocity_row.iter().map(|&(j, c)| c * w[j]).sum();
                (d, g.nodes[op.upstream_end])
            };
            let (d, x_end) = end(SlipDerivative::SecondOrder, &quad);
            assert!((d - (2.0 - 6.0 * x_end)).abs() < 1e-11, "end node: {d}");
            let (d, _) = end(SlipDerivative::FirstOrder, &line);
            assert!((d - 2.0).abs() < 1e-12, "end node: {d}");
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
