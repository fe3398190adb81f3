//! The NORM/TANG alternation (method `norm_tang`): Kalker's splitting of the coupled problem
//! into a normal and a tangential problem, solved in turn until the tractions stop changing.
//!
//! Source: J.J. Kalker, *Three-dimensional elastic bodies in rolling contact*, Kluwer 1990,
//! §5 (the algorithms NORM and TANG, and their alternation, the "Panagiotopoulos process", which
//! the PANA-style codes and CONTACT use for dissimilar bodies); González & Abascal §3.2.1–3.2.2,
//! which write the two halves as Eq. 26 (normal problem, p_t given) and Eq. 35 (tangential
//! problem, p_n given).
//!
//! One iteration of this method is one pair:
//!
//! 1. **NORM**: with the shear q and the creepage ξ frozen, solve G1 = G3 = 0 (and the P equation
//!    G5 with δ0 under force control) for the pressure, the gap and δ0.
//! 2. **TANG**: with the pressure p and δ0 frozen, solve G2 = G4 = 0 with the friction bound
//!    μ max(0, p) of that pressure (and the Q equation G6 with ξ under tangential load control)
//!    for the shear, the slip and ξ.
//!
//! then the coupled residual (the common measure of [`super::residual`]) is checked. For similar
//! bodies (β = 0) the halves do not interact and one pair solves the problem; with dissimilar
//! bodies the shear changes the gap through H_q and the pressure changes the slip through B_p,
//! and the alternation is a block Gauss–Seidel iteration whose convergence depends on that
//! coupling (β, μ). The load-control unknowns sit inside the halves: δ0 is solved with the
//! pressure (a Lagrange-type row Σ w p = P in NORM), ξ with the shear (Σ w q = Q in TANG).
//!
//! **What we simplify.** Kalker's NORM and TANG are active-set algorithms (iterate on the contact
//! or stick area, solve the linear system on it, fix the violations). We solve each half with our
//! generalized Newton restricted to the half ([`super::direction::Block`]): on these projection
//! equations the semismooth Newton step is itself an active-set step (contact/open and
//! stick/slip sets from the current iterate, a linear solve on them), so it plays the same role;
//! it adds the line search as a safeguard. Each half is solved to 1/10 of the outer tolerance in
//! its own scaled residual, with at most [`INNER_ITERATIONS`] Newton steps. The alternation stops
//! when it stalls ([`super::stall::NORM_TANG_STALL`]: no 10 % gain on the best residual in 5
//! pairs).

use super::direction::Block;
use super::newton::{solve_block, NewtonInputs};
use super::report::{IterationRecord, Method, NewtonSettings, SolveReport};
use super::residual::{automatic_penalties, start_vector, State};
use super::stall::{Progress, NORM_TANG_STALL};
use super::workspace::Workspace;

/// Newton steps allowed for each NORM or TANG solve.
pub const INNER_ITERATIONS: usize = 50;

/// Ratio of the inner (NORM, TANG) tolerance to the outer one.
pub const INNER_TOLERANCE_RATIO: f64 = 0.1;

/// Solves the contact problem by alternating NORM and TANG from the paper's start vector, their
/// Newton systems in the memory of `ws`.
pub fn solve(inputs: NewtonInputs<'_>, ws: &mut Workspace) -> (State, SolveReport) {
    let NewtonInputs { pb, settings, measure } = inputs;
    let inner = NewtonSettings {
        max_iterations: INNER_ITERATIONS,
        tolerance: INNER_TOLERANCE_RATIO * settings.tolerance,
        ..*settings
    };
    let mut z = start_vector(pb);
    let mut residual = measure.of(&z);
    let mut converged = residual <= settings.tolerance;
    let mut history = Vec::new();
    let mut progress = Progress::new(NORM_TANG_STALL, residual);
    while !converged && history.len() < settings.max_iterations && !progress.stalled() {
        let normal = solve_block(pb, Block::Normal, z.clone(), &inner, ws);
        let tangential = solve_block(pb, Block::Tangential, normal.state, &inner, ws);
        let steps = normal.history.iter().chain(&tangential.history);
        history.push(IterationRecord {
            residual,
            step: 1.0,
            system_size: steps.clone().map(|h| h.system_size).max().unwrap_or(0),
            inner_iterations: steps.count(),
        });
        // A diverging alternation keeps its last finite iterate (no NaN in outputs).
        let next = measure.of(&tangential.state);
        if !next.is_finite() {
            break;
        }
        z = tangential.state;
        residual = next;
        converged = residual <= settings.tolerance;
        progress.record(residual);
    }
    let (rn, rt) = automatic_penalties(pb, settings.penalty_scale);
    let report = SolveReport {
        method: Method::NormTang,
        formulation: settings.formulation,
        converged,
        iterations: history.len(),
        inner_iterations: history.iter().map(|h| h.inner_iterations).sum(),
        residual,
        history,
        penalty_normal: rn,
        penalty_tangential: rt,
        traction_scale: measure.traction_scale(),
        wall_time_s: 0.0,
        fallbacks: Vec::new(),
    };
    (z, report)
}
