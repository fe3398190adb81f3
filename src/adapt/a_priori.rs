//! The a-priori length rule of the error control: how long an element holding a square-root
//! point of the tractions may be, whatever the estimate saw (docs/theory.md, "Error-controlled
//! grids").

use super::{Solve, A_PRIORI_LENGTH};
use crate::grid::ContactGrid;
use crate::post::ContactSolution;
use crate::scene::Scene;

/// The a-priori length rule's lengths [length]: [`A_PRIORI_LENGTH`]·tolerance·a at every
/// square-root point, and at the leading contact edge no more than the bodies' relaxation
/// layer there (a viscoelastic body: the material relaxes over V·τe behind the edge, and an
/// element wider than that misplaces the edge's pressure by 1–2 % of p0 at its nodes, which
/// the comparison of two such grids does not see; docs/theory.md, "Viscoelastic edges").
pub(super) struct APriori {
    /// The length at every square-root point.
    pub(super) everywhere: f64,
    /// The leading edge's square-root point and its length, where a body has a layer.
    pub(super) leading_edge: Option<(f64, f64)>,
}

impl APriori {
    pub(super) fn of_pass(scene: &Scene, h: &Solve, singular: &[f64], tolerance: f64, half_width: f64) -> Self {
        let everywhere = A_PRIORI_LENGTH * tolerance * half_width;
        let leading_edge = scene.relaxation_layer().and_then(|layer| {
            let [x0, x1] = ContactSolution::from_state(&h.problem, &h.state).contact_extent()?;
            let edge = if scene.leading_edge_sign() > 0.0 { x1 } else { x0 };
            let nearest = singular
                .iter()
                .copied()
                .min_by(|a, b| (a - edge).abs().total_cmp(&(b - edge).abs()))?;
            Some((nearest, layer.min(everywhere)))
        });
        Self {
            everywhere,
            leading_edge,
        }
    }

    /// The length at the square-root point `x`.
    pub(super) fn at(&self, x: f64) -> f64 {
        match self.leading_edge {
            Some((edge, length)) if edge == x => length,
            _ => self.everywhere,
        }
    }
}

/// Whether every element of `grid` that holds a square-root point is at most its a-priori
/// length long (the rule the marking of src/adapt.rs applies).
pub(super) fn resolved(grid: &ContactGrid, singular: &[f64], lengths: &APriori) -> bool {
    singular.iter().all(|&x| {
        (0..grid.n_elements())
            .filter(|&e| grid.edges[e] <= x && x <= grid.edges[e + 1])
            .all(|e| grid.edges[e + 1] - grid.edges[e] <= lengths.at(x))
    })
}
