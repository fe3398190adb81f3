//! What an error-controlled grid reached: the estimated errors of the solution and the grid's
//! history ([`crate::adapt`] builds it).

use serde::Serialize;

/// A fixed grid whose estimated error (the largest of [`ErrorEstimate`]'s) exceeds this [-] is
/// reported with a warning and the advice to control the error (`contact.grid.tolerance`).
pub const FIXED_GRID_WARNING: f64 = 0.01;

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
    /// Relative error of the overlap δ (the approach of the bodies' datums) [-], when it is
    /// an output that a grid controls: under force control with neither body idealised as a
    /// half-plane (whose approach is relative to a datum at a chosen depth, so that its
    /// relative error says nothing of the solution). Absent when δ is prescribed.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub overlap_rel: Option<f64>,
    /// The error the bodies' own meshes outside the contact add (a BEM body's free boundary,
    /// shaft, rim), estimated once the grid meets the tolerance; absent for bodies without a
    /// mesh and in the passes' estimates.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub body_mesh: Option<BodyMeshError>,
}

/// The error of the bodies' meshes outside the contact (summary.json
/// `error_estimate.body_mesh`), in the norms of [`ErrorEstimate`], on the final contact grid.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct BodyMeshError {
    /// Relative error of the creepage ξ [-]; 0 when ξ is prescribed or μ = 0.
    pub creepage_rel: f64,
    /// Relative error of the overlap δ [-], when the grid's estimate controls it
    /// ([`ErrorEstimate::overlap_rel`]).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub overlap_rel: Option<f64>,
    /// RMS error of p over the contact [Hertz peak pressure p0].
    pub pressure: f64,
    /// RMS error of q over the contact [μp0].
    pub shear: f64,
    /// How many times the meshes' elements outside the contact were bisected before this
    /// estimate (0: the meshes as given).
    pub bisections: usize,
    /// What the meshes were compared with for this estimate.
    pub compared_with: BodyMeshComparison,
}

/// What the bodies' meshes are compared with to estimate their error (summary.json
/// `error_estimate.body_mesh.compared_with`).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum BodyMeshComparison {
    /// Their elements outside the contact bisected: the estimate is 4/3 of the difference.
    Bisected,
    /// Their elements outside the contact merged in pairs: the estimate is 1/3 of the
    /// difference, taken only when it lies five times below the tolerance.
    Coarsened,
}

impl BodyMeshComparison {
    /// The word for the console: `bisected` or `coarsened`.
    pub fn as_str(&self) -> &'static str {
        match self {
            Self::Bisected => "bisected",
            Self::Coarsened => "coarsened",
        }
    }
}

impl BodyMeshError {
    /// The largest of the estimates.
    pub fn largest(&self) -> f64 {
        self.pressure
            .max(self.shear)
            .max(self.creepage_rel)
            .max(self.overlap_rel.unwrap_or(0.0))
    }
}

impl ErrorEstimate {
    /// The estimate plus `factor` times a difference between two solutions on the same grid
    /// (a part of the error the grid's comparison does not see: the stand-ins' own); the
    /// overlap's only where both control it.
    pub fn plus(&self, d: &BodyMeshError, factor: f64) -> Self {
        Self {
            pressure_rms: self.pressure_rms + factor * d.pressure,
            shear_rms: self.shear_rms + factor * d.shear,
            creep_rel: self.creep_rel + factor * d.creepage_rel,
            overlap_rel: self.overlap_rel.zip(d.overlap_rel).map(|(a, b)| a + factor * b),
            body_mesh: None,
        }
    }

    /// The largest of the contact grid's estimates (pressure, shear, creepage, and the
    /// overlap where it is controlled); the body mesh's is tested on its own, after the grid.
    pub fn largest(&self) -> f64 {
        self.pressure_rms
            .max(self.shear_rms)
            .max(self.creep_rel)
            .max(self.overlap_rel.unwrap_or(0.0))
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

/// Where an error-controlled grid's refinement stopped because its estimate rose instead of
/// falling (src/adapt/floor.rs): the grid had reached element lengths at which the solution's
/// own noise exceeds its discretisation error.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct RefinementFloor {
    /// The pass whose result is returned, the best on its scene (1 the first).
    pub best_pass: usize,
    /// Its traction estimate, the larger of the RMS estimates of p/p0 and q/(μp0) [-].
    pub best_estimate: f64,
    /// The pass whose estimate rose.
    pub risen_pass: usize,
    /// Its traction estimate [-].
    pub risen_estimate: f64,
    /// The shortest element of the risen pass's bisected grid [length].
    pub shortest_element: f64,
    /// The shortest element of the best pass's bisected grid [length].
    pub best_shortest_element: f64,
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
    /// `contact.grid.max_elements` first, or a body's mesh stayed too coarse, and the solution
    /// is the best one reached).
    pub reached: bool,
    /// The body meshes whose error stayed above the tolerance after the most bisections the
    /// error control makes of them (`body A (path, groups free, shaft)`), when that ended the
    /// run; None otherwise.
    #[serde(skip)]
    pub coarse_body_mesh: Option<String>,
    /// Where refining made the estimate rise instead of fall, when that ended the run (the
    /// result is then the best pass's; src/adapt/floor.rs); None otherwise.
    #[serde(skip)]
    pub floor: Option<RefinementFloor>,
    /// Whether the results on the final grid are the BEM bodies' stand-ins' (the half-plane
    /// plus the smooth remainder fitted on coarser grids, their own error estimated and
    /// included in `estimate`) rather than the full BEM bodies cut along that grid.
    pub results_from_stand_ins: bool,
}
