//! The solution methods of the contact problem and their common report.
//!
//! Every method takes the same [`ContactProblem`] (same flexibilities, slip operator, controls),
//! starts from the paper's start vector (Eq. 74: no tractions, δ0 = 0, ξ = 0 unless prescribed),
//! stops on the same [`ConvergenceMeasure`] (‖G_Φ‖∞/p_ref at the automatic penalties, scale 1)
//! and returns the same [`State`] and [`SolveReport`], so that their iteration counts, residuals
//! and failures can be set side by side (`rollbem study stability`, docs/stability.md).
//!
//! | method | what it is | its iteration | file |
//! |---|---|---|---|
//! | `newton` | generalized Newton with Armijo line search, Φ or Ψ (paper §4) | one Newton step | [`super::newton`] |
//! | `newton_plain` | the same Newton direction, always the full step (no line search) | one Newton step | [`super::newton`] |
//! | `norm_tang` | Kalker's alternation: normal problem with the shear frozen, then the tangential one with the pressure frozen | one NORM + TANG pair | [`super::norm_tang`] |
//! | `gauss_seidel` | projected Gauss–Seidel / fixed-point iteration of the projection equations, node by node in the flow direction | one sweep | [`super::gauss_seidel`] |

use super::newton::{self, NewtonSettings};
use super::residual::{ConvergenceMeasure, Formulation, State};
use super::{gauss_seidel, norm_tang, ContactProblem};
use serde::{Deserialize, Serialize};
use std::time::Instant;

/// Solution method (case key `solver.method`).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Deserialize, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum Method {
    /// Generalized Newton with Armijo line search (González & Abascal §4). The default.
    Newton,
    /// Generalized Newton without line search: every step is taken in full (α = 1).
    NewtonPlain,
    /// NORM/TANG alternation of Kalker's PANA-style codes (Panagiotopoulos process).
    NormTang,
    /// Projected Gauss–Seidel of the projection equations, in the style of CONTACT's GS solvers.
    GaussSeidel,
}

impl Method {
    /// Every method, default first.
    pub const ALL: [Method; 4] = [
        Method::Newton,
        Method::NewtonPlain,
        Method::NormTang,
        Method::GaussSeidel,
    ];

    /// Name as written in case files.
    pub fn name(self) -> &'static str {
        match self {
            Method::Newton => "newton",
            Method::NewtonPlain => "newton_plain",
            Method::NormTang => "norm_tang",
            Method::GaussSeidel => "gauss_seidel",
        }
    }

    /// What one of the method's iterations is (for reports).
    pub fn iteration_unit(self) -> &'static str {
        match self {
            Method::Newton | Method::NewtonPlain => "Newton steps",
            Method::NormTang => "NORM/TANG alternations",
            Method::GaussSeidel => "sweeps",
        }
    }
}

/// Settings of a solve: the method and the settings it shares with the others.
///
/// `newton.formulation` selects Φ or Ψ for `newton`, `newton_plain` and the inner solves of
/// `norm_tang`; `newton.penalty_scale` scales the penalties of all methods (for `gauss_seidel` it
/// is the relaxation factor of the local updates); `newton.tolerance` applies to the common
/// measure; `newton.max_iterations` counts each method's own iterations (table above).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SolverSettings {
    /// Solution method. Default = newton.
    pub method: Method,
    /// Formulation, penalty scale, tolerance, iteration limit and line search.
    pub newton: NewtonSettings,
}

impl Default for SolverSettings {
    fn default() -> Self {
        Self {
            method: Method::Newton,
            newton: NewtonSettings::default(),
        }
    }
}

/// One iteration in the history of a solve.
#[derive(Debug, Clone, Copy, Serialize)]
pub struct IterationRecord {
    /// Scaled residual ‖G‖∞ / p_ref (the common measure) before the iteration.
    pub residual: f64,
    /// Accepted step length α (Newton); 1 for the other methods.
    pub step: f64,
    /// Size of the largest linear system solved in the iteration (0 for Gauss–Seidel).
    pub system_size: usize,
    /// Inner iterations in this iteration: Newton steps of the NORM and TANG solves
    /// (`norm_tang`); 0 for single-level methods.
    pub inner_iterations: usize,
}

/// Outcome of a solve, in the same form for every method.
#[derive(Debug, Clone, Serialize)]
pub struct SolveReport {
    /// Method used.
    pub method: Method,
    /// Formulation used (Newton family and NORM/TANG inner solves).
    pub formulation: Formulation,
    /// Whether the common scaled residual reached the tolerance.
    pub converged: bool,
    /// Number of the method's own iterations taken ([`Method::iteration_unit`]).
    pub iterations: usize,
    /// Total inner iterations (NORM/TANG: Newton steps of all sub-solves; others: = iterations).
    pub inner_iterations: usize,
    /// Final scaled residual ‖G‖∞ / p_ref (the common measure).
    pub residual: f64,
    /// Residual and step of every iteration.
    pub history: Vec<IterationRecord>,
    /// Normal penalty r_n used by the method [stress/length].
    pub penalty_normal: f64,
    /// Tangential penalty r_t used by the method [stress].
    pub penalty_tangential: f64,
    /// Traction scale p_ref of the convergence test [stress].
    pub traction_scale: f64,
    /// Wall-clock time of the solve [s].
    pub wall_time_s: f64,
    /// Restarts the default method needed, in order (empty when the first Newton run converged):
    /// `penalty/10`, `penalty/100`, `psi` (or `phi`), `gauss_seidel start (omega ω, N sweeps)`.
    pub fallbacks: Vec<String>,
}

/// Solves the contact problem with the chosen method from the paper's start vector.
pub fn solve(pb: &ContactProblem, settings: &SolverSettings) -> (State, SolveReport) {
    let start = Instant::now();
    let measure = ConvergenceMeasure::new(pb);
    let (state, mut report) = match settings.method {
        Method::Newton => newton::solve_with(pb, &settings.newton, &measure),
        Method::NewtonPlain => {
            let plain = NewtonSettings {
                max_backtracks: 0,
                ..settings.newton
            };
            newton::solve_with(pb, &plain, &measure)
        }
        Method::NormTang => norm_tang::solve(pb, &settings.newton, &measure),
        Method::GaussSeidel => gauss_seidel::solve(pb, &settings.newton, &measure),
    };
    report.method = settings.method;
    report.wall_time_s = start.elapsed().as_secs_f64();
    (state, report)
}
