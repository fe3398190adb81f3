//! The restart policy of the default method (`newton`): what to do when a line-search Newton
//! attempt stalls ([`super::newton`]). Every fallback is tried only while the previous one left
//! the run stalled; a run that converges on the first try is untouched (every shipped case).
//!
//! 1. **Creepage iteration** (`contact/creep_secant.rs`), when ξ is unknown: near complete slip the
//!    Q equation is a staircase in ξ that the coupled step cannot follow.
//! 2. **Smaller penalties**: from the start vector with the penalties divided by
//!    [`RESTART_PENALTY_DIVISORS`] (10, then 100): the projections then change branch more
//!    gradually.
//! 3. **The other formulation** (Ψ for Φ and conversely), whose friction bound switches
//!    elsewhere.
//! 4. **A Gauss–Seidel start**: from the iterate of projected Gauss–Seidel sweeps
//!    ([`super::gauss_seidel`]) run to a scaled residual of [`FALLBACK_GS_TOLERANCE`] with the
//!    relaxations [`FALLBACK_GS_RELAXATIONS`] (0.5, then 0.25), which find the contact and stick
//!    sets without a merit function.
//!
//! Stalls are met at large μ with strong coupling β, where the contact shifts far from Hertz
//! (docs/stability.md). The report lists the restarts used (`fallbacks`) and records every
//! Newton step of every attempt in its history.

use super::newton::{self, coupled_attempt, first_attempt, BlockOutcome};
use super::report::{GaussSeidelSettings, NewtonSettings, SolveReport};
use super::residual::{automatic_penalties, start_vector, ConvergenceMeasure, Formulation, State};
use super::{creep_secant, gauss_seidel, ContactProblem};

/// Penalty divisors of the restarts of a stalled line-search Newton.
pub const RESTART_PENALTY_DIVISORS: [f64; 2] = [10.0, 100.0];

/// Relaxations ω of the Gauss–Seidel sweeps that give the last restarts their start: at large
/// μβ the sweeps oscillate at ω = 1 and some still at 0.5 (docs/stability.md).
pub const FALLBACK_GS_RELAXATIONS: [f64; 2] = [0.5, 0.25];

/// The sweeps stop at this scaled residual: Newton finishes from there.
pub const FALLBACK_GS_TOLERANCE: f64 = 1e-4;

/// Sweep budget of each Gauss–Seidel start.
pub const FALLBACK_GS_SWEEPS: usize = 10_000;

/// The run so far followed by a retry: the retry's outcome with both histories.
fn then(run: BlockOutcome, retry: BlockOutcome) -> BlockOutcome {
    BlockOutcome {
        history: [run.history, retry.history.clone()].concat(),
        ..retry
    }
}

/// The line-search Newton from the paper's start vector with the restarts of the module docs
/// (none when `settings.max_backtracks` is 0: a run without line search is not globalized),
/// stopping on the common measure.
pub fn solve(pb: &ContactProblem, settings: &NewtonSettings, measure: &ConvergenceMeasure) -> (State, SolveReport) {
    let (mut out, mut penalties) = first_attempt(pb, settings, measure);
    let mut fallbacks = Vec::new();
    if settings.max_backtracks > 0 {
        if out.stalled {
            if let Some(retry) = creep_secant::solve(pb, settings, measure, &out.state) {
                let (rn, rt) = automatic_penalties(pb, settings.penalty_scale);
                penalties = [rn, rt];
                fallbacks.push("creep iteration".to_string());
                out = then(out, retry);
            }
        }
        for divisor in RESTART_PENALTY_DIVISORS {
            if !out.stalled {
                break;
            }
            let scale = settings.penalty_scale / divisor;
            let (retry, used) = coupled_attempt(pb, settings.formulation, scale, start_vector(pb), settings, measure);
            penalties = used;
            fallbacks.push(format!("penalty/{divisor}"));
            out = then(out, retry);
        }
        if out.stalled {
            let other = match settings.formulation {
                Formulation::Phi => Formulation::Psi,
                Formulation::Psi => Formulation::Phi,
            };
            let (retry, used) = coupled_attempt(pb, other, settings.penalty_scale, start_vector(pb), settings, measure);
            penalties = used;
            fallbacks.push(format!("{other:?}").to_lowercase());
            out = then(out, retry);
        }
        for omega in FALLBACK_GS_RELAXATIONS {
            if !out.stalled {
                break;
            }
            let sweeps = GaussSeidelSettings {
                relaxation: omega,
                tolerance: FALLBACK_GS_TOLERANCE.max(settings.tolerance),
                max_sweeps: FALLBACK_GS_SWEEPS,
            };
            let (start, gs_report) = gauss_seidel::solve(pb, &sweeps, measure);
            if gs_report.residual.is_finite() {
                let (retry, used) = coupled_attempt(
                    pb,
                    settings.formulation,
                    settings.penalty_scale,
                    start,
                    settings,
                    measure,
                );
                penalties = used;
                fallbacks.push(format!(
                    "gauss_seidel start (omega {omega}, {} sweeps)",
                    gs_report.iterations
                ));
                out = then(out, retry);
            }
        }
    }
    newton::report(settings, out, penalties, measure, fallbacks)
}
