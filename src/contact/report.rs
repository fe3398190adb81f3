//! What every solution method is asked and what it answers: the [`Method`], the settings and
//! the common [`SolveReport`].

use super::residual::Formulation;
use serde::{Deserialize, Serialize};

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

/// Settings of the generalized Newton method.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields, default)]
pub struct NewtonSettings {
    /// Formulation of the contact conditions. Default = Phi.
    pub formulation: Formulation,
    /// Scale c of the automatic penalties r_n = c/mean diag(H_p), r_t = c/mean|diag(B_q)|. Default = 1.
    pub penalty_scale: f64,
    /// Convergence when ‖G‖∞ ≤ tolerance · p_ref (p_ref a traction scale of the problem). Default = 1e-10.
    pub tolerance: f64,
    /// Maximum number of Newton iterations. Default = 100.
    pub max_iterations: usize,
    /// Armijo constant σ in Θ(z+αΔz) ≤ (1−2σα)Θ(z) (paper §4.1). Default = 0.1.
    pub armijo: f64,
    /// Step reduction factor β of the backtracking, α = β^m (paper §4.1). Default = 0.5.
    pub step_reduction: f64,
    /// Maximum number of step reductions per iteration. Default = 40.
    pub max_backtracks: usize,
}

impl Default for NewtonSettings {
    fn default() -> Self {
        Self {
            formulation: Formulation::Phi,
            penalty_scale: 1.0,
            tolerance: 1e-10,
            max_iterations: 100,
            armijo: 0.1,
            step_reduction: 0.5,
            max_backtracks: 40,
        }
    }
}

/// Settings of projected Gauss–Seidel sweeps ([`super::gauss_seidel`]).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct GaussSeidelSettings {
    /// Relaxation factor ω of the local updates (projected SOR, 0 < ω < 2) [-].
    pub relaxation: f64,
    /// Convergence when the common measure ≤ tolerance [-].
    pub tolerance: f64,
    /// Maximum number of sweeps.
    pub max_sweeps: usize,
}

/// Settings of a solve: the method and the settings it shares with the others.
///
/// `newton.formulation` selects Φ or Ψ for `newton`, `newton_plain` and the inner solves of
/// `norm_tang`; `newton.penalty_scale` scales the penalties of the Newton family and NORM/TANG;
/// `relaxation` is the ω of `gauss_seidel`; `newton.tolerance` applies to the common measure;
/// `newton.max_iterations` counts each method's own iterations (Newton steps, NORM/TANG pairs,
/// sweeps).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SolverSettings {
    /// Solution method. Default = newton.
    pub method: Method,
    /// Formulation, penalty scale, tolerance, iteration limit and line search.
    pub newton: NewtonSettings,
    /// Relaxation factor ω of `gauss_seidel` [-]. Default = 1 (each node's local normal problem
    /// solved exactly).
    pub relaxation: f64,
}

impl Default for SolverSettings {
    fn default() -> Self {
        Self {
            method: Method::Newton,
            newton: NewtonSettings::default(),
            relaxation: 1.0,
        }
    }
}

impl SolverSettings {
    /// The Gauss–Seidel settings: ω = `relaxation`, the common tolerance and iteration limit.
    pub fn gauss_seidel(&self) -> GaussSeidelSettings {
        GaussSeidelSettings {
            relaxation: self.relaxation,
            tolerance: self.newton.tolerance,
            max_sweeps: self.newton.max_iterations,
        }
    }
}

/// One iteration in the history of a solve.
#[derive(Debug, Clone, Copy, Serialize)]
pub struct IterationRecord {
    /// Scaled residual ‖G‖∞ / p_ref (the common measure) before the iteration.
    pub residual: f64,
    /// Accepted step length α (Newton); the relaxation ω for Gauss–Seidel; 1 for NORM/TANG.
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
    /// Formulation asked for (used by the Newton family and the NORM/TANG inner solves;
    /// Gauss–Seidel uses none).
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
    /// Restarts the default method needed, in order (empty when the first attempt converged):
    /// `creep iteration`, `normal start`, `psi` (or `phi`, the other formulation from the normal
    /// start), `paper start`, `penalty/10`, `penalty/100`, `psi (paper start)` (or `phi …`),
    /// `gauss_seidel start (omega ω, N sweeps)` ([`super::restart`]).
    pub fallbacks: Vec<String>,
}
