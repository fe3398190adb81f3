//! The normal start of the default method (its first attempt above μ = 1, a restart below, see
//! [`super::restart`]): the normal problem first (Kalker's NORM, with q = 0), and the creepage
//! of complete slip on its pressure when ξ is unknown. The creepage iteration
//! ([`super::creep_secant`]) steps with the same creepage of complete slip.
//!
//! **Why not the paper's start vector.** The paper's start (Eq. 74: p = q = 0, g = −h0) puts
//! every node of the grid at a tie with a positive augmented pressure r_n h0, so the first Newton
//! step solves the fully bonded problem on the whole grid: tension outside the contact, and the
//! shear spikes of a bonded edge at the grid ends. The following steps open the grid one or two
//! nodes per contact edge at a time, because at each step the line search stops where the first
//! of the edge nodes changes branch. With a large μ the friction bound keeps those nodes in stick
//! while they open, so that walk from the grid ends to the contact edges costs a step per node:
//! 84 steps at μ = 10 and 530 over five restarts at 481 elements (docs/performance.md, "Solver
//! cost at the friction limits"). Solving the normal problem first (its own Newton, NORM)
//! finds the contact in a handful of steps, since without shear no friction bound holds the edge
//! nodes back; the coupled problem then starts with the right contact and, at large μ, only its
//! few edge nodes change.
//!
//! **The creepage of complete slip.** With the shear q = 0 of that start the slip is affine in ξ
//! at every node, s_i(ξ) = s_i + σ e_i (ξ − ξ_start). In complete slip each node carries
//! q_i = −μ p̂_i sgn s_i(ξ), so the tangential load Q(ξ) is a monotone staircase with one step per
//! node (where its slip changes sign), and the step on which the target load lies gives ξ
//! (for free rolling of dissimilar bodies, the limit ξ = 0.914772 β a/R of Bentall & Johnson
//! 1967 as the grid is refined). That is the limit μ → 0 of the solution, and the Newton step
//! cannot find it from ξ = 0: ξ enters the linearised problem only through stick rows, and near
//! complete slip there are none where the slip changes sign (see [`super::creep_secant`]). At
//! larger μ the start creepage only moves where the first coupled step begins; that step bonds
//! every contact node (t = 0 at q = s = 0) and sets ξ itself.

use super::direction::Block;
use super::newton::{solve_block, BlockOutcome};
use super::report::NewtonSettings;
use super::residual::{start_vector, State, System};
use super::workspace::Workspace;
use super::ContactProblem;

/// The NORM solve from the paper's start vector (q and ξ frozen at their start values) with the
/// formulation and penalties of `settings`, then, when ξ is unknown, ξ set to
/// [`complete_slip_creep`] and the slip recomputed from it. The outcome's history holds the NORM
/// steps; its state is the start of the coupled attempt.
pub(crate) fn normal_start(pb: &ContactProblem, settings: &NewtonSettings, ws: &mut Workspace) -> BlockOutcome {
    let mut out = solve_block(pb, Block::Normal, start_vector(pb), settings, ws);
    let sys = System::new(pb, settings.formulation, settings.penalty_scale);
    if let Some(creep) = complete_slip_creep(&sys, &out.state) {
        out.state.creep = creep;
        out.state.slip = pb.slip(&out.state.pressure, &out.state.shear, creep);
    }
    out
}

/// The creepage at which the tangential load of complete slip, with the tractions of `z` frozen,
/// meets its target (module docs); `None` when ξ is prescribed or no step of the staircase holds
/// the target (|Q| ≥ μP: no rolling solution).
///
/// Each contact node (in the sense of `sys`) with a creepage weight e_i ≠ 0 flips at
/// ξ_i = ξ − s_i/(σ e_i), its shear going from +σμp̂_i to −σμp̂_i as ξ grows; a node with e_i = 0
/// (the upstream end) keeps the shear of its present slip. Walking the flips in order of ξ_i,
/// the first one across which Q − target changes sign is the root's step.
pub(crate) fn complete_slip_creep(sys: &System, z: &State) -> Option<f64> {
    complete_slip_step(sys, z).map(|(creep, _)| creep)
}

/// [`complete_slip_creep`] and the node whose flip holds the target load.
pub(crate) fn complete_slip_step(sys: &System, z: &State) -> Option<(f64, usize)> {
    let (ratio, q0) = sys.tangential_load()?;
    let pb = sys.pb;
    let (w, e) = (&pb.grid.weights, &pb.slip_operator.creep_weight);
    let sigma = pb.flow_sign;
    let target = ratio * pb.friction * pb.grid.integrate(&z.pressure) + q0;
    let bound = |i: usize| pb.friction * sys.bound_pressure(z, i);
    let mut load = 0.0;
    let mut flips = Vec::new();
    for i in (0..sys.m()).filter(|&i| sys.is_contact(z, i) && bound(i) > 0.0) {
        if e[i] != 0.0 {
            // Below its flip the node slips with sign −σ, so its shear is +σ μ p̂.
            load += w[i] * sigma * bound(i);
            flips.push((z.creep - z.slip[i] / (sigma * e[i]), i));
        } else {
            load -= w[i] * bound(i) * z.slip[i].signum();
        }
    }
    flips.sort_by(|a, b| a.0.total_cmp(&b.0));
    for (creep, i) in flips {
        let after = load - 2.0 * w[i] * sigma * bound(i);
        if (load - target) * (after - target) <= 0.0 {
            return Some((creep, i));
        }
        load = after;
    }
    None
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::analytic::free_rolling_creep_complete_slip;
    use crate::contact::residual::Formulation;
    use crate::contact::TangentialControl;

    /// The assembled free-rolling problem (aluminium on steel, Q = 0) at `elements`, and its
    /// Hertz estimates.
    fn free_rolling(elements: usize) -> (ContactProblem, crate::scene::Estimates) {
        let path = crate::case::shipped("free_rolling_al_steel.yaml");
        let set = [
            "contact.friction=1e-4".to_string(),
            format!("contact.grid.elements={elements}"),
            "solver.max_iterations=1".to_string(),
        ];
        let solved = crate::app::solve_case(&path, &set).expect("shipped case assembles");
        (solved.problem, solved.scene.estimates)
    }

    #[test]
    fn complete_slip_creep_of_the_normal_start_is_bentall_and_johnsons_limit() {
        // On the Hertz pressure of the NORM solve the staircase root is the μ → 0 limit
        // ξ = 0.914772 β a/R, up to the slip change between the two nodes at the reversal point
        // x ≈ 0.40a (the root is a node's flip, not interpolated): about 0.2 % at these grids.
        // Measured: −0.18 %, +0.12 %, +0.17 % at 41, 81, 161 elements.
        for elements in [41, 81, 161] {
            let (pb, e) = free_rolling(elements);
            let start = normal_start(&pb, &NewtonSettings::default(), &mut Workspace::new());
            assert!(start.converged, "NORM did not converge");
            let limit = free_rolling_creep_complete_slip(e.dundurs_beta, e.hertz_half_width, e.effective_radius);
            let err = start.state.creep / limit - 1.0;
            assert!(
                err.abs() < 5e-3,
                "{elements} elements: ξ = {} vs {limit}",
                start.state.creep
            );
            // The slip was recomputed with it: the elastic slip rows hold.
            let sys = System::new(&pb, NewtonSettings::default().formulation, 1.0);
            let g = sys.residual(&start.state);
            let m = pb.n_nodes();
            let slip_rows = g[m..2 * m].iter().fold(0.0_f64, |a, v| a.max(v.abs()));
            assert!(slip_rows < 1e-9 * sys.traction_scale(), "slip rows {slip_rows}");
        }
    }

    #[test]
    fn no_complete_slip_creep_when_it_is_prescribed_or_out_of_reach() {
        let (pb, _) = free_rolling(41);
        let z = normal_start(&pb, &NewtonSettings::default(), &mut Workspace::new()).state;
        let kinematic = ContactProblem {
            tangential: TangentialControl::Creep(1e-3),
            ..pb.clone()
        };
        let sys = System::new(&kinematic, Formulation::Phi, 1.0);
        assert_eq!(complete_slip_creep(&sys, &z), None);
        // |Q| ≥ μP: no step of the staircase holds the target.
        let sliding = ContactProblem {
            tangential: TangentialControl::Ratio(1.5),
            ..pb.clone()
        };
        let sys = System::new(&sliding, Formulation::Phi, 1.0);
        assert_eq!(complete_slip_creep(&sys, &z), None);
    }
}
