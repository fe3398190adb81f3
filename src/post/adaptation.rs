//! What an error-controlled grid reached: the estimated errors of the solution and the grid's
//! history ([`crate::adapt`] builds it).

use serde::Serialize;

/// Estimated discretisation errors of a solution (summary.json `error_estimate`).
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct ErrorEstimate {
    /// RMS error of p over the contact, each node weighted by the length it stands for
    /// [Hertz peak pressure p0].
    pub pressure_rms: f64,
    /// RMS error of q over the contact, weighted likewise [μp0].
    pub shear_rms: f64,
    /// Relative error of the creepage ξ [-]; 0 when ξ is prescribed or μ = 0.
    pub creep_rel: f64,
}

impl ErrorEstimate {
    /// The largest of the three.
    pub fn largest(&self) -> f64 {
        self.pressure_rms.max(self.shear_rms).max(self.creep_rel)
    }

    /// Whether every estimate is at most `tolerance`.
    pub fn within(&self, tolerance: f64) -> bool {
        self.largest() <= tolerance
    }
}

/// One pass of the error control: a grid, the estimate of its bisection's solution.
#[derive(Debug, Clone, Copy, Serialize)]
pub struct AdaptationStep {
    /// Elements of the bisected grid whose solution the estimate describes.
    pub elements: usize,
    /// Its contact nodes.
    pub nodes: usize,
    /// The estimate.
    pub estimate: ErrorEstimate,
    /// Newton iterations of the pass (both grids).
    pub iterations: usize,
}

/// How an error-controlled grid was reached.
#[derive(Debug, Clone, Serialize)]
pub struct GridAdaptation {
    /// The requested tolerance (`contact.grid.tolerance`).
    pub tolerance: f64,
    /// The estimate of the solution written (none when a solve did not converge before the
    /// first estimate).
    pub estimate: Option<ErrorEstimate>,
    /// Number of refinements after the start grid.
    pub refinements: usize,
    /// Every pass, the start grid's first.
    pub steps: Vec<AdaptationStep>,
    /// Whether the estimate met the tolerance (false: the grid reached
    /// `contact.grid.max_elements` first, and the solution is the best one reached).
    pub reached: bool,
}
