//! Generalized Newton method with Armijo line search (Pang 1990; González & Abascal §4).
//!
//! The unknowns z = (g, s, p, q, δ0, ξ) and the residual G(z) (paper Eq. 43 Φ / Eq. 44 Ψ) are
//! those of [`super::residual`]; the Newton step (the B-derivative pseudo-Jacobian of paper
//! Eq. 54–73 and its reduced linear system) is that of [`super::direction`], on the coupled
//! problem or on one of its halves ([`Block`]).
//!
//! **Line search.** Armijo backtracking on the merit Θ = ½‖G‖² (paper Eq. 49–51): α = β^k, the
//! first k with Θ(z + αΔz) ≤ (1 − 2σα)Θ(z). With `max_backtracks = 0` every full step is taken:
//! that is the method `newton_plain` of [`super::methods`].
//!
//! **Attempts.** [`solve`] is one attempt from the paper's start vector. An attempt stalls when it
//! spends a budget of at least [`MIN_RESTART_BUDGET`] steps without converging, meets a singular
//! Newton matrix, when [`MAX_FAILED_SEARCHES`] line searches in a row find no decrease at all
//! (the direction is no descent direction: a kink of G lies between the iterate and the
//! solution), or when ‖G‖₂ has not improved by 10 % on its best for a number of steps
//! ([`super::stall`]: 5 from the normal start, 50 otherwise, 100 without line search). What the
//! default method does then is the start and restart policy of [`super::restart`]. An attempt
//! whose measure has reached round-off ([`super::stall::roundoff_level`]) and has not halved its
//! best there in 3 steps ([`super::stall::ROUNDOFF_STALL`]) ends too, not stalled but
//! `at_roundoff`: its tolerance is below what double precision gives.

pub use super::direction::Block;
use super::report::{IterationRecord, Method, NewtonSettings, SolveReport};
use super::residual::{axpy, merit, scaled_residual, start_vector, ConvergenceMeasure, Formulation, State, System};
use super::stall::{at_roundoff, Progress, NEWTON_STALL, NORMAL_START_STALL, PLAIN_NEWTON_STALL, ROUNDOFF_STALL};
use super::workspace::Workspace;
use super::ContactProblem;

/// What a damped Newton loop on one block ended with.
#[derive(Clone)]
pub(crate) struct BlockOutcome {
    /// The last iterate.
    pub state: State,
    /// Whether the stopping measure reached the tolerance.
    pub converged: bool,
    /// The stopping measure at the last iterate.
    pub residual: f64,
    /// One record per Newton step.
    pub history: Vec<IterationRecord>,
    /// Not converged although the attempt had a real budget: the Newton matrix was singular,
    /// an iterate overflowed, or at least [`MIN_RESTART_BUDGET`] steps did not reach the
    /// tolerance. A run cut short on purpose (`max_iterations` below that) is not stalled, so it
    /// is not restarted.
    pub stalled: bool,
    /// Not converged because the tolerance is below round-off: the stopping measure reached
    /// [`super::stall::roundoff_level`] and stopped improving there. No restart can do better,
    /// so such an outcome is not `stalled`.
    pub at_roundoff: bool,
}

/// Smallest iteration budget for which a non-converged attempt counts as stalled.
pub const MIN_RESTART_BUDGET: usize = 10;

/// Consecutive line searches without an Armijo decrease after which an attempt is stalled.
pub const MAX_FAILED_SEARCHES: usize = 2;

/// How an attempt's line search treats its first step.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) enum FirstStep {
    /// Armijo backtracking from the first step on (the paper's rule).
    Searched,
    /// The first step is taken in full, the line search applies from the second on: for a start
    /// whose merit does not measure its distance from the solution (the normal start of
    /// [`super::start`], where the friction rows vanish identically at q = s = 0). Such an
    /// attempt is also given up sooner ([`NORMAL_START_STALL`]).
    Full,
}

/// Generalized Newton with Armijo line search on `block` from `z`, stopping when
/// `measure(G_block(z), z) ≤ settings.tolerance` or after `settings.max_iterations` steps, or when
/// the Newton matrix is singular, or when the attempt stalls ([`super::stall`]). The Newton
/// systems are solved in the memory of `ws`.
pub(crate) fn damped_newton(
    sys: &System,
    block: Block,
    mut z: State,
    settings: &NewtonSettings,
    measure: &dyn Fn(&[f64], &State) -> f64,
    first_step: FirstStep,
    ws: &mut Workspace,
) -> BlockOutcome {
    let mut g = sys.block_residual(&z, block);
    let mut history = Vec::new();
    let mut converged = measure(&g, &z) <= settings.tolerance;
    let (mut singular, mut overflow) = (false, false);
    let mut failed_searches = 0;
    // Progress is judged on the merit's norm ‖G‖₂, which the Armijo search decreases
    // monotonically (the measure ‖G‖∞ may rise for a few steps of a converging run).
    let norm = |g: &[f64]| (2.0 * merit(g)).sqrt();
    let rule = match first_step {
        _ if settings.max_backtracks == 0 => PLAIN_NEWTON_STALL,
        FirstStep::Full => NORMAL_START_STALL,
        FirstStep::Searched => NEWTON_STALL,
    };
    let mut progress = Progress::new(rule, norm(&g));
    // Started when the measure first reaches round-off: a tolerance below it can never be met.
    let mut floor: Option<Progress> = None;
    while !converged
        && history.len() < settings.max_iterations
        && failed_searches < MAX_FAILED_SEARCHES
        && !progress.stalled()
        && !floor.is_some_and(|f| f.stalled())
    {
        crate::cancel::checkpoint();
        let residual = measure(&g, &z);
        let (dz, size) = match sys.newton_direction(&z, &g, block, ws) {
            Ok(d) => d,
            Err(_) => {
                singular = true;
                break;
            }
        };
        let theta = merit(&g);
        let mut alpha = 1.0;
        let mut trial = axpy(&z, alpha, &dz);
        let mut g_trial = sys.block_residual(&trial, block);
        let armijo = |g: &[f64], alpha: f64| merit(g) <= (1.0 - 2.0 * settings.armijo * alpha) * theta;
        let searched = !(first_step == FirstStep::Full && history.is_empty());
        for _ in 0..if searched { settings.max_backtracks } else { 0 } {
            if armijo(&g_trial, alpha) {
                break;
            }
            alpha *= settings.step_reduction;
            trial = axpy(&z, alpha, &dz);
            g_trial = sys.block_residual(&trial, block);
        }
        // No decrease along the direction even at the shortest step: not a descent direction
        // (a kink of G between the iterate and the solution). Repeated, the iteration is stuck.
        if searched && settings.max_backtracks > 0 && !armijo(&g_trial, alpha) {
            failed_searches += 1;
        } else {
            failed_searches = 0;
        }
        history.push(IterationRecord {
            residual,
            step: alpha,
            system_size: size,
            inner_iterations: 0,
        });
        // A full step without line search can overflow: keep the last finite iterate.
        let next = measure(&g_trial, &trial);
        log::info!(
            target: crate::logging::PROGRESS,
            "Newton step {}: scaled residual {next:.2e} (tolerance {:.0e}), step length {alpha}, system of {size}",
            history.len(),
            settings.tolerance
        );
        if !next.is_finite() {
            overflow = true;
            break;
        }
        z = trial;
        g = g_trial;
        converged = next <= settings.tolerance;
        if at_roundoff(next, sys.m()) {
            floor
                .get_or_insert_with(|| Progress::new(ROUNDOFF_STALL, f64::INFINITY))
                .record(next);
        }
        if searched {
            progress.record(norm(&g));
        } else {
            // Progress counts from where the full step landed.
            progress = Progress::new(rule, norm(&g));
        }
    }
    let residual = measure(&g, &z);
    let exhausted = history.len() >= settings.max_iterations.max(MIN_RESTART_BUDGET);
    // Ended at round-off, whichever test ended it (line searches also fail there).
    let roundoff = !converged && !singular && !overflow && at_roundoff(residual, sys.m());
    BlockOutcome {
        state: z,
        converged,
        residual,
        history,
        stalled: !converged
            && !roundoff
            && (singular || overflow || exhausted || failed_searches >= MAX_FAILED_SEARCHES || progress.stalled()),
        at_roundoff: roundoff,
    }
}

/// Solves one block of the problem from `z` and stops on the block's own scaled residual (the
/// inner solves of NORM/TANG).
pub(crate) fn solve_block(
    pb: &ContactProblem,
    block: Block,
    z: State,
    settings: &NewtonSettings,
    ws: &mut Workspace,
) -> BlockOutcome {
    // TANG works with the given traction bound μ max(0, p): Ψ's bound (see `super::direction`).
    let form = match block {
        Block::Tangential => Formulation::Psi,
        _ => settings.formulation,
    };
    let sys = System::new(pb, form, settings.penalty_scale);
    let scale = sys.traction_scale();
    damped_newton(
        &sys,
        block,
        z,
        settings,
        &|g, z| scaled_residual(g, z, scale),
        FirstStep::Searched,
        ws,
    )
}

/// One attempt of the generalized Newton method on the coupled problem from `start`, with
/// formulation `form` and the automatic penalties at scale `penalty_scale`, stopping on the
/// common `measure`. Returns the outcome and the penalties [r_n, r_t] used.
pub(crate) fn coupled_attempt(
    pb: &ContactProblem,
    (form, penalty_scale): (Formulation, f64),
    start: State,
    first_step: FirstStep,
    settings: &NewtonSettings,
    measure: &ConvergenceMeasure,
    ws: &mut Workspace,
) -> (BlockOutcome, [f64; 2]) {
    let sys = System::new(pb, form, penalty_scale);
    let out = damped_newton(
        &sys,
        Block::Coupled,
        start,
        settings,
        &|g, z| measure.of_with(&sys, g, z),
        first_step,
        ws,
    );
    (out, sys.reference)
}

/// An attempt from the paper's start vector (Eq. 74) with the formulation and penalty scale of
/// `settings` ([`coupled_attempt`]).
pub(crate) fn paper_attempt(
    pb: &ContactProblem,
    settings: &NewtonSettings,
    measure: &ConvergenceMeasure,
    ws: &mut Workspace,
) -> (BlockOutcome, [f64; 2]) {
    let own = (settings.formulation, settings.penalty_scale);
    coupled_attempt(pb, own, start_vector(pb), FirstStep::Searched, settings, measure, ws)
}

/// The common report of a Newton run that ended with `out`, the last attempt having used the
/// penalties [r_n, r_t], after the restarts `fallbacks`.
pub(crate) fn report(
    settings: &NewtonSettings,
    out: BlockOutcome,
    penalties: [f64; 2],
    measure: &ConvergenceMeasure,
    fallbacks: Vec<String>,
) -> (State, SolveReport) {
    let iterations = out.history.len();
    let report = SolveReport {
        method: Method::Newton,
        formulation: settings.formulation,
        converged: out.converged,
        iterations,
        inner_iterations: iterations,
        residual: out.residual,
        history: out.history,
        penalty_normal: penalties[0],
        penalty_tangential: penalties[1],
        traction_scale: measure.traction_scale(),
        wall_time_s: 0.0,
        fallbacks,
    };
    (out.state, report)
}

/// What a Newton-based method ([`solve`], [`super::restart::solve`], [`super::norm_tang::solve`])
/// is given besides its workspace: the problem, the Newton settings, and the measure that judges
/// convergence (the common measure of [`super::methods`], so that the methods compare).
#[derive(Clone, Copy)]
pub struct NewtonInputs<'a> {
    /// The contact problem solved.
    pub pb: &'a ContactProblem,
    /// The Newton settings (iteration limit, tolerance, line search, formulation).
    pub settings: &'a NewtonSettings,
    /// The convergence measure of `pb` (‖G_Φ‖∞/p_ref at the automatic penalties).
    pub measure: &'a ConvergenceMeasure<'a>,
}

impl<'a> NewtonInputs<'a> {
    /// The inputs of a solve of `pb` with `settings`, judged by `measure`.
    pub fn new(pb: &'a ContactProblem, settings: &'a NewtonSettings, measure: &'a ConvergenceMeasure<'a>) -> Self {
        NewtonInputs { pb, settings, measure }
    }
}

/// One attempt of the generalized Newton method from the paper's start vector (line search as
/// set by `settings.max_backtracks`), stopping on the common measure; no restart. The Newton
/// systems are solved in the memory of `ws`.
pub fn solve(inputs: NewtonInputs<'_>, ws: &mut Workspace) -> (State, SolveReport) {
    let NewtonInputs { pb, settings, measure } = inputs;
    let (out, penalties) = paper_attempt(pb, settings, measure, ws);
    report(settings, out, penalties, measure, Vec::new())
}
