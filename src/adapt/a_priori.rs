//! The a-priori length rule of the error control: how long an element holding a square-root
//! point of the tractions may be, whatever the estimate saw (docs/theory.md, "Error-controlled
//! grids").
//!
//! Under a friction law that falls with the slip velocity the end of a stick zone is a stronger
//! point than a square root: q − μ_s p and the slip go as d^λ at a distance d from it, with
//! λ = 1/2 − arctan(kA)/π, k = |dμ/ds|(0) p the law's slope in traction per unit slip there and
//! A = 2/E* the slip per unit Hilbert transform of the shear (the Riemann–Hilbert problem
//! linearised at the point; docs/validation.md, "Falling friction at tolerance 1e-5: measured",
//! λ = 0.36 on cases/veldep_fric.yaml, fitted 0.36). A node beside such a point has an error
//! ∝ (h/a)^λ standing for a length h, its share of the RMS ∝ (h/a)^(λ+1/2): the rule's length
//! there is a·(A_PRIORI_LENGTH·tolerance)^(1/(λ+1/2)), the square root's A_PRIORI_LENGTH·
//! tolerance·a at λ = 1/2.

use super::{Solve, A_PRIORI_LENGTH};
use crate::contact::residual::State;
use crate::contact::ContactProblem;
use crate::grid::ContactGrid;
use crate::post::{ContactSolution, NodeState};
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
    /// The ends of the stick zones under a falling law and their lengths (module docs).
    pub(super) stick_ends: Vec<(f64, f64)>,
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
        let stick_ends = falling_stick_ends(&h.problem, &h.state, scene.estimates.e_star)
            .into_iter()
            .map(|(x, lambda)| (x, half_width * (A_PRIORI_LENGTH * tolerance).powf(1.0 / (lambda + 0.5))))
            .collect();
        Self {
            everywhere,
            leading_edge,
            stick_ends,
        }
    }

    /// The length at the square-root point `x`.
    pub(super) fn at(&self, x: f64) -> f64 {
        if let Some(&(_, length)) = self.stick_ends.iter().find(|(end, _)| *end == x) {
            return length.min(self.everywhere);
        }
        match self.leading_edge {
            Some((edge, length)) if edge == x => length,
            _ => self.everywhere,
        }
    }
}

/// The ends of the stick zones of the solution `z` of `pb` under its falling law, each with its
/// exponent λ (module docs; `e_star` the contact modulus E* [stress]): the midpoints between a
/// sticking and a slipping node, as [`super::marking::singular_points`] places them. None
/// without a falling law.
fn falling_stick_ends(pb: &ContactProblem, z: &State, e_star: f64) -> Vec<(f64, f64)> {
    let Some(law) = pb.falling else {
        return Vec::new();
    };
    let sol = ContactSolution::from_state(pb, z);
    let x = &pb.grid.nodes;
    // |dμ/ds| as the slip leaves zero: the law's steepest slope.
    let slope = law.slope(pb.friction, f64::MIN_POSITIVE).abs();
    (1..x.len())
        .filter(|&i| {
            matches!(
                (sol.state[i - 1], sol.state[i]),
                (NodeState::Stick, NodeState::Slip) | (NodeState::Slip, NodeState::Stick)
            )
        })
        .map(|i| {
            let k = slope * sol.pressure[i - 1].max(sol.pressure[i]);
            let lambda = 0.5 - (2.0 * k / e_star).atan() / std::f64::consts::PI;
            (0.5 * (x[i - 1] + x[i]), lambda)
        })
        .collect()
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
