//! The start and restart policy of the default method (`newton`): where the line-search Newton
//! ([`super::newton`]) begins, and what to do when an attempt stalls. Every restart is tried only
//! while the run so far is stalled; the history records every Newton step of every attempt
//! (NORM steps included) and the report lists the restarts used (`fallbacks`).
//!
//! **The first attempt** depends on the friction coefficient:
//!
//! * μ ≤ [`NORMAL_START_FRICTION`] (= 1): from the paper's start vector (Eq. 74). Its first step
//!   bonds the whole grid and the next ones solve the normal and the tangential problem together:
//!   5–7 steps on Carter's and Hertz's cases, where solving the normal problem first costs
//!   about twice as many (docs/performance.md, "Solver cost at the friction limits").
//! * μ > 1: from the normal start of [`super::start`] (NORM, then the coupled problem with the
//!   first step taken in full). From the paper's start vector the friction bound μ p̂ holds the
//!   bonded edge nodes in stick while the contact shrinks from the grid to its true size, one or
//!   two nodes per step: the steps grow with μ and the grid (84 at μ = 10 on 321 elements, 530
//!   with five restarts on 481), where the normal start needs 7–12.
//!
//! **The restarts**, in order (a start already used is skipped):
//!
//! 1. **Creepage iteration** ([`super::creep_secant`]), when ξ is unknown and μ ≤ 1: near complete
//!    slip the Q equation is a staircase in ξ that the coupled step cannot follow.
//! 2. **The normal start** with the case's formulation, then with the other one (Ψ for Φ and
//!    conversely), whose friction bound switches elsewhere: at μ ≥ 200 an edge node with a
//!    near-zero pressure can trap Φ's line search against the kink of its augmented bound
//!    μ max(0, p − r_n g), which Ψ's bound μ max(0, p) does not have.
//! 3. **Creepage iteration** when ξ is unknown and μ > 1.
//! 4. **The paper's start vector**, then with the penalties divided by
//!    [`RESTART_PENALTY_DIVISORS`] (10, then 100; the projections then change branch more
//!    gradually), then with the other formulation.
//! 5. **A Gauss–Seidel start**: from the iterate of projected Gauss–Seidel sweeps
//!    ([`super::gauss_seidel`]) run to a scaled residual of [`FALLBACK_GS_TOLERANCE`] with the
//!    relaxations [`FALLBACK_GS_RELAXATIONS`] (0.5, then 0.25), which find the contact and stick
//!    sets without a merit function.
//!
//! Stalls are met near complete slip (μ → 0), and at large μ with strong coupling β, where the
//! contact shifts far from Hertz (docs/stability.md). An attempt that ends with its residual at
//! round-off ([`super::stall::roundoff_level`]: the tolerance is below what double precision
//! gives) is not stalled: no restart can do better, so none is tried.

use super::newton::{self, coupled_attempt, BlockOutcome, FirstStep, NewtonInputs};
use super::report::{GaussSeidelSettings, NewtonSettings, SolveReport};
use super::residual::{automatic_penalties, start_vector, ConvergenceMeasure, Formulation, State};
use super::start::normal_start;
use super::workspace::Workspace;
use super::{creep_secant, gauss_seidel, ContactProblem, NormalControl, TangentialControl};

/// Friction coefficient above which the first attempt starts from the normal start instead of
/// the paper's start vector (module docs).
pub const NORMAL_START_FRICTION: f64 = 1.0;

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

/// Where an attempt starts.
#[derive(Debug, Clone, Copy, PartialEq)]
enum Start {
    /// The paper's start vector with (formulation, penalty scale).
    Paper(Formulation, f64),
    /// The normal start with a formulation.
    Normal(Formulation),
}

/// One restart of the chain of the module docs.
#[derive(Debug, Clone, Copy, PartialEq)]
enum Restart {
    /// A new attempt from a start.
    From(Start),
    /// The creepage iteration from the last iterate.
    CreepIteration,
    /// A Gauss–Seidel start with relaxation ω.
    GaussSeidel(f64),
}

/// The first attempt of the default method and its restarts, in order.
fn chain(pb: &ContactProblem, settings: &NewtonSettings) -> (Start, Vec<Restart>) {
    let own = settings.formulation;
    let other = match own {
        Formulation::Phi => Formulation::Psi,
        Formulation::Psi => Formulation::Phi,
    };
    let scale = settings.penalty_scale;
    let from = Restart::From;
    let (first, mut restarts) = if pb.friction > NORMAL_START_FRICTION {
        let then = [
            from(Start::Normal(other)),
            Restart::CreepIteration,
            from(Start::Paper(own, scale)),
        ];
        (Start::Normal(own), then.to_vec())
    } else {
        let then = [
            Restart::CreepIteration,
            from(Start::Normal(own)),
            from(Start::Normal(other)),
        ];
        (Start::Paper(own, scale), then.to_vec())
    };
    restarts.extend(RESTART_PENALTY_DIVISORS.map(|d| from(Start::Paper(own, scale / d))));
    restarts.push(from(Start::Paper(other, scale)));
    restarts.extend(FALLBACK_GS_RELAXATIONS.map(Restart::GaussSeidel));
    (first, restarts)
}

/// Runs the attempts of one solve, sharing the NORM solve between the normal starts.
struct Attempts<'a> {
    pb: &'a ContactProblem,
    settings: &'a NewtonSettings,
    measure: &'a ConvergenceMeasure<'a>,
    normal: Option<BlockOutcome>,
    ws: &'a mut Workspace,
}

impl Attempts<'_> {
    /// From the paper's start vector or the normal start: the outcome (NORM steps included the
    /// first time the normal start is used) and the penalties [r_n, r_t] used.
    fn attempt_from(&mut self, start: Start) -> (BlockOutcome, [f64; 2]) {
        let (pb, settings, measure) = (self.pb, self.settings, self.measure);
        match start {
            Start::Normal(form) => {
                let first = self.normal.is_none();
                let ws = &mut *self.ws;
                let norm = self.normal.get_or_insert_with(|| normal_start(pb, settings, ws));
                let own = (form, settings.penalty_scale);
                let (out, used) = coupled_attempt(pb, own, norm.state.clone(), FirstStep::Full, settings, measure, ws);
                (if first { then(norm.clone(), out) } else { out }, used)
            }
            Start::Paper(form, scale) => coupled_attempt(
                pb,
                (form, scale),
                start_vector(pb),
                FirstStep::Searched,
                settings,
                measure,
                self.ws,
            ),
        }
    }

    /// A restart after `last`: its outcome, penalties and name in the report, or `None` when it
    /// does not apply (the creepage iteration with ξ prescribed, sweeps that diverged).
    fn restart(&mut self, restart: Restart, last: &BlockOutcome) -> Option<(BlockOutcome, [f64; 2], String)> {
        let (pb, settings, measure) = (self.pb, self.settings, self.measure);
        let own = (settings.formulation, settings.penalty_scale);
        let form = |f: Formulation| format!("{f:?}").to_lowercase();
        match restart {
            Restart::CreepIteration => {
                let out = creep_secant::solve(pb, settings, measure, &last.state, self.ws)?;
                let (rn, rt) = automatic_penalties(pb, settings.penalty_scale);
                Some((out, [rn, rt], "creep iteration".into()))
            }
            Restart::GaussSeidel(omega) => {
                let sweeps = GaussSeidelSettings {
                    relaxation: omega,
                    tolerance: FALLBACK_GS_TOLERANCE.max(settings.tolerance),
                    max_sweeps: FALLBACK_GS_SWEEPS,
                };
                let (start, gs_report) = gauss_seidel::solve(pb, &sweeps, measure);
                if !gs_report.residual.is_finite() {
                    return None;
                }
                let (out, used) = coupled_attempt(pb, own, start, FirstStep::Searched, settings, measure, self.ws);
                let label = format!("gauss_seidel start (omega {omega}, {} sweeps)", gs_report.iterations);
                Some((out, used, label))
            }
            Restart::From(start) => {
                let label = match start {
                    Start::Normal(f) if f == own.0 => "normal start".into(),
                    Start::Normal(f) => form(f),
                    Start::Paper(f, c) if f == own.0 && c == own.1 => "paper start".into(),
                    Start::Paper(f, c) if f == own.0 => format!("penalty/{}", own.1 / c),
                    Start::Paper(f, _) => format!("{} (paper start)", form(f)),
                };
                let (out, used) = self.attempt_from(start);
                Some((out, used, label))
            }
        }
    }
}

/// Most Newton iterations a warm start from a neighbouring problem's solution is given before
/// the cold start takes over ([`solve_neighbour`]'s budget in a sequence's runs and in an
/// error-controlled run started from its neighbour's result; `sequence::WARM_START_BUDGET`).
pub const NEIGHBOUR_BUDGET: usize = 20;

/// A neighbour's solution as the start of `problem`: a prescribed overlap or creepage takes
/// the problem's own value (the Newton method keeps a prescribed unknown where it starts).
pub fn with_prescribed(mut z: State, problem: &ContactProblem) -> State {
    if let NormalControl::Overlap(d) = problem.normal {
        z.overlap = d;
    }
    if let TangentialControl::Creep(c) = problem.tangential {
        z.creep = c;
    }
    z
}

/// The line-search Newton from `warm` (a solution of a neighbouring problem, e.g. a coarser grid's
/// carried to this one): when that attempt does not converge, the cold start and restarts of
/// [`solve`] follow, the warm attempt's steps kept in the history. The Newton systems are solved
/// in the memory of `ws`.
pub fn solve_warm(
    pb: &ContactProblem,
    settings: &NewtonSettings,
    measure: &ConvergenceMeasure,
    warm: State,
    ws: &mut Workspace,
) -> (State, SolveReport) {
    warm_then_cold(pb, settings, settings, measure, warm, FirstStep::Searched, ws)
}

/// The line-search Newton from `warm`, the solution of a neighbouring problem on the same grid
/// (a sequence's last run, [`crate::sequence`]), given at most `budget` iterations: when that
/// attempt has not converged within them, the cold start and restarts of [`solve`] follow (with
/// the whole iteration limit), the warm attempt's steps kept in the history.
///
/// The warm attempt's first step is taken in full, the line search applies from the second on:
/// the neighbour's solution has a small merit, so the Armijo rule cuts the first step, which
/// must move the active sets to the new controls, and the iterate then frees or locks about one
/// node an iteration (carter2d_contact on 41 elements, Q/μP from 0 to 0.95 in steps of 0.2:
/// 6–42 iterations a run with the first step searched, 3–7 with it in full, 6–10 cold;
/// measured 2026-12-05, tests/validation/sequence.rs prints the last two).
pub fn solve_neighbour(
    pb: &ContactProblem,
    settings: &NewtonSettings,
    measure: &ConvergenceMeasure,
    warm: State,
    budget: usize,
    ws: &mut Workspace,
) -> (State, SolveReport) {
    warm_then_cold(
        pb,
        settings,
        &with_budget(settings, budget),
        measure,
        warm,
        FirstStep::Full,
        ws,
    )
}

/// `settings` with at most `budget` iterations.
fn with_budget(settings: &NewtonSettings, budget: usize) -> NewtonSettings {
    NewtonSettings {
        max_iterations: budget.min(settings.max_iterations),
        ..*settings
    }
}

/// One line-search Newton attempt from `warm` with at most `budget` iterations and no restarts
/// after it: the report says whether it converged (a falling law's finish, [`super::falling`],
/// whose fallback is its own fixed point, not a cold start).
pub fn attempt_warm(
    pb: &ContactProblem,
    settings: &NewtonSettings,
    measure: &ConvergenceMeasure,
    warm: State,
    budget: usize,
    ws: &mut Workspace,
) -> (State, SolveReport) {
    let own = (settings.formulation, settings.penalty_scale);
    let limited = with_budget(settings, budget);
    let (out, used) = coupled_attempt(pb, own, warm, FirstStep::Searched, &limited, measure, ws);
    newton::report(settings, out, used, measure, Vec::new())
}

/// One warm attempt from `warm` under `attempt`'s settings (its first step `first`); when it
/// does not converge, the cold start and restarts of [`solve`] under `settings`, the warm
/// attempt's steps kept in the history.
fn warm_then_cold(
    pb: &ContactProblem,
    settings: &NewtonSettings,
    attempt: &NewtonSettings,
    measure: &ConvergenceMeasure,
    warm: State,
    first: FirstStep,
    ws: &mut Workspace,
) -> (State, SolveReport) {
    let own = (settings.formulation, settings.penalty_scale);
    let (out, used) = coupled_attempt(pb, own, warm, first, attempt, measure, ws);
    if out.converged || out.at_roundoff {
        return newton::report(settings, out, used, measure, Vec::new());
    }
    let (state, mut report) = solve(NewtonInputs::new(pb, settings, measure), ws);
    report.iterations += out.history.len();
    report.inner_iterations += out.history.len();
    report.history = [out.history, report.history].concat();
    report.fallbacks.insert(0, "cold start after the warm start".into());
    (state, report)
}

/// The line-search Newton with the start and restarts of the module docs (none when
/// `settings.max_backtracks` is 0: a run without line search is not globalized, and starts from
/// the paper's start vector), stopping on the common measure. The Newton systems are solved in
/// the memory of `ws`.
pub fn solve(inputs: NewtonInputs<'_>, ws: &mut Workspace) -> (State, SolveReport) {
    let NewtonInputs { pb, settings, measure } = inputs;
    if settings.max_backtracks == 0 {
        return newton::solve(inputs, ws);
    }
    let (first, restarts) = chain(pb, settings);
    let mut attempts = Attempts {
        pb,
        settings,
        measure,
        normal: None,
        ws,
    };
    let (mut out, mut penalties) = attempts.attempt_from(first);
    let mut fallbacks = Vec::new();
    for restart in restarts {
        if !out.stalled {
            break;
        }
        if let Some((retry, used, label)) = attempts.restart(restart, &out) {
            penalties = used;
            fallbacks.push(label);
            out = then(out, retry);
        }
    }
    newton::report(settings, out, penalties, measure, fallbacks)
}
