//! The third stage of a falling-law solve ([`super::solve`]): a continuation in the law's
//! amplitude, tried when the Newton method with the law and the outer fixed point both failed.
//!
//! The law with amplitude λ ∈ [0, 1],
//!
//! μ_λ(v) = μ_s − λ (μ_s − μ_k)(1 − decay(v)),
//!
//! is the case's law with the kinetic coefficient μ_s − λ(μ_s − μ_k) (the same decay, the fall
//! scaled by λ): λ = 0 is Coulomb's constant μ_s, whose problem the line-search Newton method
//! solves with its restarts, λ = 1 the case's law. Each λ is solved by the Newton method with
//! the law inside ([`restart::attempt_warm`], [`super::FINISH_BUDGET`] iterations) warm from the
//! last λ solved; the step in λ doubles after a success and halves after a failure (E.L.
//! Allgower & K. Georg, *Introduction to Numerical Continuation Methods*, SIAM 2003, ch. 1 and
//! 6: embedding a hard problem in a homotopy from an easy one). Why it helps where the other two
//! stages stall: in a transient step of a steep law the nodes between the slip zones turn
//! between stick and a slip far below s_h, where the law's slope is largest (the cusp of
//! μ(|v|) at v = 0), and a Newton step from the last step's state changes their set by several
//! nodes at once; at a smaller λ the same change costs less friction, and the sets move a few
//! nodes per λ-step (docs/friction.md, "Transient histories under a falling law").
//!
//! The branch found is the one connected to Coulomb's solution by the path in λ (where the
//! problem has several solutions, Vollebregt & Schuttelaars 2012, §3, not necessarily the one
//! nearest the warm start).

use super::super::newton::NewtonInputs;
use super::super::report::{NewtonSettings, SolveReport};
use super::super::residual::{ConvergenceMeasure, State};
use super::super::workspace::Workspace;
use super::super::{restart, ContactProblem};
use super::{FallingLaw, Tally, FINISH_BUDGET};

/// The first step in λ.
pub const FIRST_STEP: f64 = 0.25;

/// The smallest step in λ before the continuation gives up: ten halvings of [`FIRST_STEP`].
pub const SMALLEST_STEP: f64 = FIRST_STEP / 1024.0;

/// How the continuation's entry in a report's fallbacks begins.
pub const LABEL: &str = "falling friction: continuation in the law's amplitude";

/// Solves `pb` (its law `law`) by the continuation of the module docs, λ = 0 from `warm` when
/// given (else the cold start), the Newton systems in `ws`: the state at λ = 1 and its report
/// (the iterations of `tally` and of every λ included) when it reached λ = 1, else None
/// (its iterations added to `tally`).
pub(super) fn solve(
    pb: &ContactProblem,
    law: &FallingLaw,
    settings: &NewtonSettings,
    warm: Option<State>,
    tally: &mut Tally,
    ws: &mut Workspace,
) -> Option<(State, SolveReport)> {
    let (mut state, mut report) = coulomb_solution(pb, pb.friction, settings, warm, ws);
    tally.add(&mut report);
    if !report.converged {
        return None;
    }
    let (mut lambda, mut step, mut solves) = (0.0_f64, FIRST_STEP, 0);
    while lambda < 1.0 {
        if step < SMALLEST_STEP {
            log::info!(
                target: crate::logging::PROGRESS,
                "{LABEL}: stopped at λ = {lambda:.4} (step below {SMALLEST_STEP:.1e})"
            );
            return None;
        }
        let next = (lambda + step).min(1.0);
        let at = at_amplitude(pb, law, next);
        let measure = ConvergenceMeasure::new(&at);
        let (trial, mut r) = restart::attempt_warm(&at, settings, &measure, state.clone(), FINISH_BUDGET, ws);
        tally.add(&mut r);
        solves += 1;
        if r.converged {
            (lambda, state, report) = (next, trial, r);
            step *= 2.0;
        } else {
            step *= 0.5;
        }
    }
    tally.total(&mut report);
    report.fallbacks.push(format!("{LABEL} ({solves} solves)"));
    Some((state, report))
}

/// `pb` under Coulomb's law at the constant coefficient `friction` (no falling law, no nodal
/// coefficients) solved warm from `warm` (else cold) by the line-search Newton method with its
/// restarts, the Newton systems in `ws`.
fn coulomb_solution(
    pb: &ContactProblem,
    friction: f64,
    settings: &NewtonSettings,
    warm: Option<State>,
    ws: &mut Workspace,
) -> (State, SolveReport) {
    let mut coulomb = pb.clone();
    coulomb.falling = None;
    coulomb.nodal_friction = None;
    coulomb.friction = friction;
    let measure = ConvergenceMeasure::new(&coulomb);
    match warm {
        Some(w) => restart::solve_warm(&coulomb, settings, &measure, w, ws),
        None => restart::solve(NewtonInputs::new(&coulomb, settings, &measure), ws),
    }
}

/// `pb` under the law `law` with amplitude `lambda` (module docs): the kinetic coefficient
/// μ_s − λ(μ_s − μ_k), everything else the case's; λ = 1 is `pb` itself.
pub fn at_amplitude(pb: &ContactProblem, law: &FallingLaw, lambda: f64) -> ContactProblem {
    let mut at = pb.clone();
    let mu_s = pb.friction;
    let mut scaled = *law;
    if lambda < 1.0 {
        scaled.law.kinetic = mu_s - lambda * (mu_s - law.law.kinetic);
    }
    at.falling = Some(scaled);
    at.nodal_friction = None;
    at
}

/// How the entry of a solve from above in a report's fallbacks begins.
pub const ABOVE_LABEL: &str = "falling friction: started from above (Coulomb at the kinetic coefficient)";

/// The start from above (CONTACT's initial slip estimate INISLP = −1, every node at μ_k): the
/// Coulomb problem at the constant μ_k solved from `warm` (else cold), then the Newton method
/// with the law from its solution, [`FINISH_BUDGET`] iterations. Where the branch of the
/// continuation ends in a fold (in a transient step, the branch of the last step's state no
/// longer exists: a slip event), this finds the branch of large slip. The state and report
/// (with `tally`'s iterations) when it converged, else None.
pub(super) fn from_above(
    pb: &ContactProblem,
    law: &FallingLaw,
    settings: &NewtonSettings,
    warm: Option<State>,
    tally: &mut Tally,
    ws: &mut Workspace,
) -> Option<(State, SolveReport)> {
    let (state, mut report) = coulomb_solution(pb, law.law.kinetic, settings, warm, ws);
    tally.add(&mut report);
    if !report.converged {
        return None;
    }
    let full = ConvergenceMeasure::new(pb);
    let (state, mut report) = restart::attempt_warm(pb, settings, &full, state, FINISH_BUDGET, ws);
    tally.add(&mut report);
    report.converged.then(|| {
        tally.total(&mut report);
        report.fallbacks.push(ABOVE_LABEL.to_string());
        (state, report)
    })
}

/// Where the solve of a problem under a falling law starts looking (CONTACT's initial slip
/// estimate INISLP; Vollebregt & Schuttelaars 2012, §3: a step of a steep law can have several
/// solutions, and the start selects one).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum InitialSlip {
    /// From the warm start (the last step's state) with the stages of [`super::solve`].
    #[default]
    Warm,
    /// From below: zero slip velocity, μ = μ_s at every node (CONTACT's INISLP = 1): the
    /// continuation of the module docs, from Coulomb's solution at μ_s.
    Below,
    /// From above: μ = μ_k at every node (CONTACT's INISLP = −1): [`from_above`].
    Above,
}

/// Solves `pb` under its law `law` from the side `side` (not [`InitialSlip::Warm`], which is
/// [`super::solve`]), warm from `warm` (the last step's state), the Newton systems in `ws`:
/// the state and report, not converged (with the iterations spent) when that side's solve failed.
pub fn solve_from_side(
    pb: &ContactProblem,
    law: &FallingLaw,
    settings: &NewtonSettings,
    warm: Option<State>,
    side: InitialSlip,
    ws: &mut Workspace,
) -> (State, SolveReport) {
    let mut tally = Tally::default();
    let found = match side {
        InitialSlip::Warm => return super::solve(pb, law, settings, warm, ws),
        InitialSlip::Below => solve(pb, law, settings, warm.clone(), &mut tally, ws),
        InitialSlip::Above => {
            let mu = vec![law.law.kinetic.min(pb.friction); pb.n_nodes()];
            return super::fixed_point(pb, law, settings, warm, mu, false, tally, ws);
        }
    };
    found.unwrap_or_else(|| {
        // Not converged: the report of the problem with the law at the warm start.
        let measure = ConvergenceMeasure::new(pb);
        let start = warm.unwrap_or_else(|| super::super::residual::start_vector(pb));
        let (state, mut report) = restart::attempt_warm(pb, settings, &measure, start, 1, ws);
        tally.add(&mut report);
        tally.total(&mut report);
        report.converged = false;
        report
            .fallbacks
            .push(format!("falling friction: no solution found from {side:?}"));
        (state, report)
    })
}
