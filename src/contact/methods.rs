//! The solution methods of the contact problem: one entry point that dispatches to them.
//!
//! Every method takes the same [`ContactProblem`] (same flexibilities, slip operator, controls),
//! starts from the paper's start vector (Eq. 74: no tractions, δ0 = 0, ξ = 0 unless prescribed;
//! the default `newton` above μ = 1 from the normal start of [`super::restart`]),
//! stops on the same [`ConvergenceMeasure`] (‖G_Φ‖∞/p_ref at the automatic penalties, scale 1)
//! and returns the same [`State`] and [`SolveReport`] ([`super::report`]), so that their iteration
//! counts, residuals and failures can be set side by side (`rollbem study stability`,
//! docs/stability.md). A new method is one file with a `solve` and one arm here.
//!
//! | method | what it is | its iteration | file |
//! |---|---|---|---|
//! | `newton` | generalized Newton with Armijo line search, Φ or Ψ (paper §4), with the restarts of [`super::restart`]; under a falling friction law, inside the fixed point of [`super::falling`] (the only method that takes one) | one Newton step | [`super::newton`] |
//! | `newton_plain` | the same Newton direction, always the full step (no line search) | one Newton step | [`super::newton`] |
//! | `norm_tang` | Kalker's alternation: normal problem with the shear frozen, then the tangential one with the pressure frozen | one NORM + TANG pair | [`super::norm_tang`] |
//! | `gauss_seidel` | projected Gauss–Seidel / fixed-point iteration of the projection equations, node by node in the flow direction | one sweep | [`super::gauss_seidel`] |

use super::newton::NewtonInputs;
use super::report::{Method, NewtonSettings, SolveReport, SolverSettings};
use super::residual::{ConvergenceMeasure, State};
pub use super::workspace::Workspace;
use super::{falling, gauss_seidel, newton, norm_tang, restart, ContactProblem};
use std::time::Instant;

/// Solves the contact problem with the chosen method (start and restarts as in the module docs),
/// with a workspace of its own ([`solve_in`] reuses one).
pub fn solve(pb: &ContactProblem, settings: &SolverSettings) -> (State, SolveReport) {
    solve_in(pb, settings, &mut Workspace::new())
}

/// [`solve`] with the Newton systems in the memory of `ws` (a [`Workspace`] reused from solve
/// to solve allocates its matrix once, at the size of the largest system). The result does not
/// depend on what `ws` held before.
pub fn solve_in(pb: &ContactProblem, settings: &SolverSettings, ws: &mut Workspace) -> (State, SolveReport) {
    crate::cancel::checkpoint();
    stamped(pb, settings, |measure| match settings.method {
        Method::Newton => match &pb.falling {
            Some(law) => falling::solve(pb, law, &settings.newton, None, ws),
            None => restart::solve(NewtonInputs::new(pb, &settings.newton, measure), ws),
        },
        Method::NewtonPlain => {
            let plain = NewtonSettings {
                max_backtracks: 0,
                ..settings.newton
            };
            newton::solve(NewtonInputs::new(pb, &plain, measure), ws)
        }
        Method::NormTang => norm_tang::solve(NewtonInputs::new(pb, &settings.newton, measure), ws),
        Method::GaussSeidel => gauss_seidel::solve(pb, &settings.gauss_seidel(), measure),
    })
}

/// `solve` run on `pb`'s [`ConvergenceMeasure`], its report stamped with the method and
/// formulation of `settings` and the wall time it took [s]: what every entry point here
/// returns, whichever method's own report `solve` gives back.
fn stamped(
    pb: &ContactProblem,
    settings: &SolverSettings,
    solve: impl FnOnce(&ConvergenceMeasure) -> (State, SolveReport),
) -> (State, SolveReport) {
    let start = Instant::now();
    let measure = ConvergenceMeasure::new(pb);
    let (state, mut report) = solve(&measure);
    report.method = settings.method;
    report.formulation = settings.newton.formulation;
    report.wall_time_s = start.elapsed().as_secs_f64();
    (state, report)
}

/// The default method from `warm` ([`solve_from_in`], [`solve_from_neighbour_in`]): a falling
/// law's fixed point from it (each of its solves with the whole iteration limit), else
/// `restart_from` (the measure, the warm state, the workspace); the other methods from their
/// own start ([`solve_in`]).
fn solve_warm_or_own(
    pb: &ContactProblem,
    settings: &SolverSettings,
    warm: Option<State>,
    ws: &mut Workspace,
    restart_from: impl FnOnce(&ConvergenceMeasure, State, &mut Workspace) -> (State, SolveReport),
) -> (State, SolveReport) {
    let Some(warm) = warm.filter(|_| settings.method == Method::Newton) else {
        return solve_in(pb, settings, ws);
    };
    stamped(pb, settings, |measure| match &pb.falling {
        Some(law) => falling::solve(pb, law, &settings.newton, Some(warm), ws),
        None => restart_from(measure, warm, ws),
    })
}

/// Solves the contact problem from `warm`, a state of this problem's grid close to the solution
/// (an error-controlled grid carries the previous grid's solution to the next): the default
/// method starts from it, falling back to its cold start and restarts; the other methods keep
/// their own start (their iteration counts are what `rollbem study stability` compares). With a
/// workspace of its own ([`solve_from_in`] reuses one).
pub fn solve_from(pb: &ContactProblem, settings: &SolverSettings, warm: Option<State>) -> (State, SolveReport) {
    solve_from_in(pb, settings, warm, &mut Workspace::new())
}

/// [`solve_from`] with the Newton systems in the memory of `ws`: the grids of an error-controlled
/// run pass one workspace from solve to solve, which grows to the largest grid's system.
pub fn solve_from_in(
    pb: &ContactProblem,
    settings: &SolverSettings,
    warm: Option<State>,
    ws: &mut Workspace,
) -> (State, SolveReport) {
    solve_warm_or_own(pb, settings, warm, ws, |measure, warm, ws| {
        restart::solve_warm(pb, &settings.newton, measure, warm, ws)
    })
}

/// Solves the contact problem from `warm`, the solution of a neighbouring problem on the same
/// grid (a sequence's last run, [`crate::sequence`]): the default method gives the warm start at
/// most `budget` Newton iterations, then falls back to its cold start and restarts
/// ([`super::restart::solve_neighbour`]); the other methods keep their own start.
pub fn solve_from_neighbour_in(
    pb: &ContactProblem,
    settings: &SolverSettings,
    warm: Option<State>,
    budget: usize,
    ws: &mut Workspace,
) -> (State, SolveReport) {
    solve_warm_or_own(pb, settings, warm, ws, |measure, warm, ws| {
        restart::solve_neighbour(pb, &settings.newton, measure, warm, budget, ws)
    })
}
