//! Creepage iteration for a prescribed tangential load (Q, or Q/μP) when the coupled Newton
//! stalls: the first restart of [`super::restart`] when ξ is unknown.
//!
//! **Why it is needed.** Near complete slip (small μ) every loaded node slips except where the
//! slip changes sign. With ξ unknown, the Q equation is the only row that fixes ξ, and ξ enters
//! the linearized problem only through the stick rows (paper Eq. 60): the discrete Q(ξ) is a
//! staircase of steep ramps, one per node whose slip reverses, and a Newton step from a node on
//! the wrong ramp is no descent direction of the merit ½‖G‖², so the Armijo search stalls. With ξ
//! prescribed (kinematic control, paper Eq. 75–77) the same Newton converges in a few steps,
//! because every shear then follows from its node's slip direction.
//!
//! **The iteration.** F(ξ) = Σ w_j q_j − c_p μ Σ w_j p_j − Q0 (the numerator of G6) evaluated at
//! the solution of the problem with ξ prescribed is continuous, monotone and piecewise linear in
//! ξ. A secant step on F, then the Illinois variant of regula falsi once a sign change brackets
//! the root (Dowell & Jarratt, BIT 11, 1971), lands on the ramp that holds the root and, the
//! ramp being linear, on the root itself. Each evaluation is warm-started from the previous
//! solution. The returned iterate solves the whole problem (G6 included) when F is below the
//! tolerance, and is judged by the common [`ConvergenceMeasure`].

use super::direction::Block;
use super::newton::{damped_newton, BlockOutcome, FirstStep};
use super::report::NewtonSettings;
use super::residual::{scaled_residual, ConvergenceMeasure, State, System};
use super::stall::at_roundoff;
use super::start::complete_slip_step;
use super::workspace::Workspace;
use super::ContactProblem;

/// Largest number of creepage evaluations (each a warm-started Newton solve with ξ fixed).
pub const MAX_CREEP_EVALUATIONS: usize = 40;

/// One evaluation: the solution with ξ prescribed and its load error F(ξ) [force/length].
struct Evaluation {
    outcome: BlockOutcome,
    load_error: f64,
}

/// Solves the problem with the creepage fixed at `creep`, from `start`, and evaluates F.
fn evaluate(
    fixed: &System,
    load: (f64, f64),
    start: &State,
    creep: f64,
    settings: &NewtonSettings,
    scale: f64,
    ws: &mut Workspace,
) -> Evaluation {
    let z = State { creep, ..start.clone() };
    let outcome = damped_newton(
        fixed,
        Block::Coupled,
        z,
        settings,
        &|g, z| scaled_residual(g, z, scale),
        FirstStep::Searched,
        ws,
    );
    let load_error = load_error(fixed.pb, load, &outcome.state);
    Evaluation { outcome, load_error }
}

/// F(z) = Σ w q − c_p μ Σ w p − Q0 of the tangential load equation (paper Eq. 39) [force/length].
fn load_error(pb: &ContactProblem, (ratio, q_total): (f64, f64), z: &State) -> f64 {
    pb.grid.integrate(&z.shear) - ratio * pb.friction * pb.grid.integrate(&z.pressure) - q_total
}

/// Iterates on ξ from the iterate `start` (typically where the coupled Newton stalled). Returns
/// `None` when ξ is prescribed by the problem, else the last iterate: converged when the whole
/// residual meets `settings.tolerance` under `measure`, with one history record per inner
/// Newton step.
pub(crate) fn solve(
    pb: &ContactProblem,
    settings: &NewtonSettings,
    measure: &ConvergenceMeasure,
    start: &State,
    ws: &mut Workspace,
) -> Option<BlockOutcome> {
    let full = System::new(pb, settings.formulation, settings.penalty_scale);
    let load = full.tangential_load()?;
    let mut fixed = System::new(pb, settings.formulation, settings.penalty_scale);
    fixed.free_creep = false;
    let scale = measure.traction_scale();
    // |F| below this (a load error of tolerance · p_ref over the grid length) meets the measure.
    let load_tolerance = settings.tolerance * scale * full.length;
    // Natural creepage scale: μ p_ref times the mean tangential slip compliance |B_q,ii|.
    let m = pb.n_nodes();
    let compliance = (0..m).map(|i| pb.bq[(i, i)].abs()).sum::<f64>() / m as f64;
    let creep_scale = pb.friction.max(1e-3) * scale * compliance;

    let mut history = Vec::new();
    let mut current = evaluate(&fixed, load, start, start.creep, settings, scale, ws);
    history.extend(current.outcome.history.iter().cloned());
    let mut previous: Option<(f64, f64)> = None;
    // Bracket ends (ξ, F) with F < 0 and F > 0, and which end was kept last (Illinois).
    let mut below: Option<(f64, f64)> = None;
    let mut above: Option<(f64, f64)> = None;
    let mut kept_twice: Option<bool> = None;
    for _ in 0..MAX_CREEP_EVALUATIONS {
        if !current.outcome.converged || current.load_error.abs() <= load_tolerance {
            break;
        }
        let (x, f) = (current.outcome.state.creep, current.load_error);
        if f < 0.0 {
            if below.is_some() && kept_twice == Some(false) {
                // The end above was kept again: halve its F (Illinois).
                above = above.map(|(xa, fa)| (xa, 0.5 * fa));
            }
            below = Some((x, f));
            kept_twice = Some(false);
        } else {
            if above.is_some() && kept_twice == Some(true) {
                below = below.map(|(xb, fb)| (xb, 0.5 * fb));
            }
            above = Some((x, f));
            kept_twice = Some(true);
        }
        // The staircase of complete slip on this solution's tractions: exact for the flips of
        // slipping nodes, off by how much their shear changes the others' slip (O(μ)).
        let z = &current.outcome.state;
        // Creepages closer than this to ξ count as ξ itself (round-off of the flip points).
        let same = 1e-9 * x.abs().max(creep_scale);
        let predicted = match complete_slip_step(&full, z) {
            // The root lies on the ramp of the node that sticks here (or sits at its flip): F is
            // linear along that ramp and the coupled Newton step (ξ free) follows it.
            Some((p, k)) if is_stick(&full, z, k) || (p - x).abs() <= same => ramp_step(&full, z, ws).map(|d| x + d),
            other => other.map(|(p, _)| p),
        }
        .filter(|&p| (p - x).abs() > same);
        let next = match (below, above, previous) {
            (Some((xl, fl)), Some((xh, fh)), _) => match predicted {
                Some(p) if (p - xl) * (p - xh) < 0.0 => p,
                _ => (xl * fh - xh * fl) / (fh - fl),
            },
            // Downhill: F decreases as ξ moves by σ (a larger ξ lowers every shear by σ μ p̂).
            _ if predicted.is_some_and(|p| (p - x) * f * pb.flow_sign > 0.0) => predicted.unwrap_or(x),
            (_, _, Some((xp, fp))) if fp != f => {
                // Secant, at most 4 × the last step until the root is bracketed.
                let secant = x - f * (x - xp) / (f - fp);
                let limit = 4.0 * (x - xp).abs();
                x + (secant - x).clamp(-limit, limit)
            }
            // First step, or a flat piece (no node sticks anywhere): step by the natural scale.
            _ => {
                x + (0.5 * x.abs()).max(creep_scale)
                    * if previous.is_some_and(|(xp, _)| xp > x) {
                        -1.0
                    } else {
                        1.0
                    }
            }
        };
        previous = Some((x, f));
        current = evaluate(&fixed, load, &current.outcome.state, next, settings, scale, ws);
        history.extend(current.outcome.history.iter().cloned());
    }
    let residual = measure.of(&current.outcome.state);
    let converged = residual <= settings.tolerance;
    let roundoff = !converged && at_roundoff(residual, m);
    Some(BlockOutcome {
        state: current.outcome.state,
        converged,
        residual,
        history,
        stalled: !converged && !roundoff,
        at_roundoff: roundoff,
    })
}

/// Whether node `k` sticks at `z` under `sys`: |q − r_t s| within its friction bound.
fn is_stick(sys: &System, z: &State, k: usize) -> bool {
    let bound = sys.friction(z, k) * sys.bound_pressure(z, k);
    bound > 0.0 && (z.shear[k] - sys.rt[k] * z.slip[k]).abs() <= bound
}

/// The creepage change of the coupled Newton step (ξ free) from `z`: on a ramp of F, where the
/// stick and slip sets do not change, the step that zeroes F.
fn ramp_step(sys: &System, z: &State, ws: &mut Workspace) -> Option<f64> {
    let g = sys.block_residual(z, Block::Coupled);
    sys.newton_direction(z, &g, Block::Coupled, ws)
        .ok()
        .map(|(dz, _)| dz.creep)
}
