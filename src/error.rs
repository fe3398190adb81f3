//! The library's error type and the CLI exit codes (docs/reliability.md).

use crate::case::CaseError;
use std::path::PathBuf;

/// Everything that stops a run (non-convergence is not an error: it is a result with
/// `converged: false`, see [`crate::app::RunReport`]).
#[derive(Debug, thiserror::Error)]
pub enum Error {
    /// The case is unreadable or invalid.
    #[error(transparent)]
    Case(#[from] CaseError),
    /// A mesh is unreadable or inconsistent.
    #[error(transparent)]
    Mesh(#[from] crate::mesh::MeshError),
    /// A physical group of a `bem` body's mesh has no boundary condition in the case.
    #[error(
        "{case}: physical group `{group}` of {mesh} has no boundary condition: add it under the body's \
         `boundaries` (fixed, free, {{displacement: [ux, uy]}}, {{traction: [tx, ty]}} or {{pressure: p}})"
    )]
    MissingBoundary {
        /// Case file.
        case: PathBuf,
        /// Mesh file.
        mesh: PathBuf,
        /// The group.
        group: String,
    },
    /// The BEM model of a body could not be built.
    #[error(transparent)]
    Bem(#[from] crate::bem::BemError),
    /// The interior fields asked by `output.interior` cannot be computed.
    #[error("{case}: output.interior.body = {body}: {source}")]
    Interior {
        /// Case file.
        case: PathBuf,
        /// The body asked for.
        body: String,
        /// Why (boxed: a BEM error is large, and errors travel by value).
        #[source]
        source: Box<crate::body::FieldError>,
    },
    /// The stresses `output.strength` assesses cannot be computed.
    #[error("{case}: output.strength, body {body}: {source}")]
    Strength {
        /// Case file.
        case: PathBuf,
        /// The body assessed.
        body: String,
        /// Why (boxed like [`Error::Interior`]'s).
        #[source]
        source: Box<crate::body::FieldError>,
    },
    /// A body's contact segment does not cover the contact grid.
    #[error(transparent)]
    Transfer(#[from] crate::body::transfer::TransferError),
    /// The boundary solution of a body could not be evaluated for the VTK output.
    #[error("the boundary solution of a bem body for output failed: {0}")]
    BoundaryField(#[source] Box<crate::body::FieldError>),
    /// The solved contact touches the end of the grid, so the grid does not contain it.
    #[error("{case}: the contact reaches the {end} end of the grid (x = {x:.6}): the grid is too short. {advice}")]
    GridTooShort {
        /// Case file.
        case: PathBuf,
        /// "left" or "right".
        end: &'static str,
        /// x of the loaded end node.
        x: f64,
        /// The grid extent in Hertz half-widths.
        extent: f64,
        /// What to change: the grid keys, or the contact group of the mesh that gives the grid.
        advice: String,
    },
    /// The case needs more memory than is available (checked before anything large is built).
    #[error(transparent)]
    Memory(#[from] crate::limits::MemoryError),
    /// A number of the solution or of its post-processing is NaN or infinite: the numerics broke
    /// down. Exit code 2 (like non-convergence); nothing is written.
    #[error(
        "{case}: {what} is {value}, not a finite number: the solution broke down numerically and \
         nothing was written. Check that the case's values are consistent (units of E, the radii and \
         the load); try solver.formulation: psi or another solver.method"
    )]
    NotFinite {
        /// Case file.
        case: PathBuf,
        /// Which value, by its path in the output.
        what: String,
        /// The value.
        value: f64,
    },
    /// An error-controlled grid reached `contact.grid.max_elements` before the tolerance.
    /// Exit code 2 (like non-convergence); `rollbem run` writes the best solution's summary.json
    /// (`converged: false`, with the estimate).
    #[error(
        "{case}: the estimated error did not reach contact.grid.tolerance = {tolerance:e} within \
         contact.grid.max_elements = {max_elements}: at {elements} elements the estimates are \
         pressure {pressure:.2e} p0, shear {shear:.2e} mu p0, creepage {creep:.2e} (relative); raise \
         contact.grid.max_elements or the tolerance"
    )]
    ToleranceNotReached {
        /// Case file.
        case: PathBuf,
        /// The requested tolerance.
        tolerance: f64,
        /// Elements of the last grid solved.
        elements: usize,
        /// The limit.
        max_elements: usize,
        /// Its estimated RMS pressure error [p0].
        pressure: f64,
        /// Its estimated RMS shear error [μp0].
        shear: f64,
        /// Its estimated relative creepage error.
        creep: f64,
    },
    /// The contact grid met `contact.grid.tolerance`, but a body's own mesh outside the contact
    /// (free boundary, shaft, rim) stayed too coarse for it after the error control's
    /// bisections of it. Exit code 2 (like non-convergence); `rollbem run` writes the best
    /// solution's summary.json (`converged: false`, with `error_estimate.body_mesh`).
    #[error(
        "{case}: the mesh of {bodies} is too coarse for contact.grid.tolerance = {tolerance:e}: with its \
         elements outside the contact bisected {bisections} times the estimated error it adds is \
         pressure {pressure:.2e} p0, shear {shear:.2e} mu p0, creepage {creep:.2e} (relative); mesh \
         those groups finer (smaller element sizes away from the contact) or raise the tolerance"
    )]
    BodyMeshTooCoarse {
        /// Case file.
        case: PathBuf,
        /// The bodies with their meshes and groups (`body A (path, groups free, shaft)`).
        bodies: String,
        /// The requested tolerance.
        tolerance: f64,
        /// How many times the error control bisected the meshes outside the contact.
        bisections: usize,
        /// The body meshes' estimated RMS pressure error [p0].
        pressure: f64,
        /// Their estimated RMS shear error [μp0].
        shear: f64,
        /// Their estimated relative creepage error.
        creep: f64,
    },
    /// An error-controlled grid's estimate rose far above its best pass's when the grid was
    /// refined: the elements had reached a length at which the solution's own noise exceeds its
    /// discretisation error (src/adapt/floor.rs). Exit code 2; `rollbem run` writes the best
    /// pass's solution and estimate (summary.json `converged: false`).
    #[error(
        "{case}: contact.grid.tolerance = {tolerance:e} is below what this scene's solution resolves: refining \
         to elements of {shortest:.2e} (pass {risen_pass}) made the estimated traction error rise from \
         {best:.2e} to {risen:.2e} instead of fall (the solution's own noise at that element length, not its \
         discretisation error); the result is pass {best_pass}'s \
         ({elements} elements, shortest {best_shortest:.2e}) with estimates pressure {pressure:.2e} p0, shear \
         {shear:.2e} mu p0, creepage {creep:.2e} (relative); a tolerance of {reachable:.1e} or more is within reach"
    )]
    RefinementFloor {
        /// Case file.
        case: PathBuf,
        /// The requested tolerance.
        tolerance: f64,
        /// The pass whose estimate rose.
        risen_pass: usize,
        /// Its traction estimate [-].
        risen: f64,
        /// Its bisected grid's shortest element [length].
        shortest: f64,
        /// The pass returned.
        best_pass: usize,
        /// Its traction estimate [-].
        best: f64,
        /// Its bisected grid's elements.
        elements: usize,
        /// Its bisected grid's shortest element [length].
        best_shortest: f64,
        /// Its estimated RMS pressure error [p0].
        pressure: f64,
        /// Its estimated RMS shear error [μp0].
        shear: f64,
        /// Its estimated relative creepage error.
        creep: f64,
        /// The largest of its estimates, rounded up: the smallest tolerance the run met [-].
        reachable: f64,
    },
    /// An error-controlled grid cannot be built for the scene (the message names the key).
    #[error("{case}: {message}")]
    GridControl {
        /// Case file.
        case: PathBuf,
        /// What is wrong and what to do.
        message: String,
    },
    /// A step of a transient history did not converge (or could not be taken); the steps
    /// before it stand.
    #[error("{case}: {message}")]
    StepNotConverged {
        /// Case file.
        case: PathBuf,
        /// The step and why.
        message: String,
    },
    /// A body would cost far more to build than the estimates say (a viscoelastic cover far
    /// thinner than the grid is long); the message names the key.
    #[error("{message}")]
    BodyCost {
        /// What is wrong and what to do.
        message: String,
    },
    /// A sweep argument or a merge input is wrong.
    #[error("sweep: {message}")]
    Sweep {
        /// What is wrong and what to do.
        message: String,
    },
    /// A study's options or scene are unusable.
    #[error("study: {message}")]
    Study {
        /// What is wrong and what to do.
        message: String,
    },
    /// The output folder cannot be written (it holds files rollbem did not write, another
    /// process writes it, its path names no folder).
    #[error(transparent)]
    Folder(#[from] crate::files::FolderError),
    /// Writing results failed.
    #[error("cannot write results to {path}: {message}")]
    Output {
        /// File or folder.
        path: PathBuf,
        /// Cause.
        message: String,
    },
}

/// A body model that could not be built keeps its own kind of error (a BEM failure, a contact
/// segment that does not cover the grid), so that its exit code and message stay those of
/// that failure.
impl From<crate::body::BuildError> for Error {
    fn from(e: crate::body::BuildError) -> Self {
        match e {
            crate::body::BuildError::Bem(e) => Error::Bem(e),
            crate::body::BuildError::Transfer(e) => Error::Transfer(e),
            crate::body::BuildError::Cost(message) => Error::BodyCost { message },
        }
    }
}

impl Error {
    /// Exit code (docs/reliability.md): 1 for bad input (nothing written). Output failures also give 1.
    /// A solution that broke down (NaN) gives 2, as non-convergence does.
    pub fn exit_code(&self) -> i32 {
        match self {
            Error::NotFinite { .. }
            | Error::ToleranceNotReached { .. }
            | Error::BodyMeshTooCoarse { .. }
            | Error::RefinementFloor { .. }
            | Error::StepNotConverged { .. } => EXIT_NOT_CONVERGED,
            _ => EXIT_BAD_INPUT,
        }
    }
}

/// Exit code of bad input or bad usage (a message says what to change; nothing written).
pub const EXIT_BAD_INPUT: i32 = 1;

/// Exit code of a run that finished but did not converge (diagnostics written).
pub const EXIT_NOT_CONVERGED: i32 = 2;

/// Exit code of an internal error: a bug (a panic) caught before it could pass for a result;
/// nothing is written.
pub const EXIT_INTERNAL_ERROR: i32 = 3;
