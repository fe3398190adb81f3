//! `rollbem study accuracy CASE`: speed against accuracy of the body models.
//!
//! The scene of the case — its cylinders' radii and materials, friction and load — is solved
//! with each body model that can represent it, at a ladder of discretizations:
//!
//! * `half_space` — the closed-form half-plane influence coefficients (the classical
//!   semi-analytic model), n contact elements;
//! * `half_space_block` — a BEM block standing in for each half-space (paper Fig. 2), 40a wide
//!   and deep, with the cylinders' profile: the BEM's discretization error on a half-space;
//! * `half_space_adaptive` — the half-space model on error-controlled grids
//!   (`contact.grid.tolerance`, [`crate::adapt`]), one run per tolerance of `--tolerances`
//!   (its start grid the case's `contact.grid.elements`);
//! * `true_geometry` — each elastic cylinder a BEM roller of its radius on a rigid shaft
//!   (radius ratio `shaft_ratio`, the paper's Fig. 14 uses 0.1), as
//!   [`crate::mesh::build::roller_on_shaft`] builds it: the model error of the half-space is
//!   what separates the two.
//!
//! Rigid bodies stay rigid in every model. Each run's error is measured against the scene's
//! closed form where it has one — Carter's shear (similar materials, Q/μP given:
//! |q − q_Carter| / μp0, Carter 1926) or Hertz's pressure (similar materials, Q = 0:
//! |p − p_Hertz| / p0) — and otherwise against the finest true-geometry run (the
//! larger of the nodal differences of p/p_max and q/(μp_max) after interpolating that run to
//! the node, stated as such in the output). The nodal errors are summarised by their RMS over
//! the nodes inside the contact (the reference's |x| < a) — the chart's measure — and by their
//! maximum. The wall time is the run's own (assembly,
//! condensation and contact solve), measured while the other runs of the study use the other
//! cores: use `--jobs 1` for undisturbed times.

//!
//! Files: [`scenes`] builds each model's scene, [`reference`] measures the errors, [`files`]
//! writes the results (the chart is [`crate::output::charts::accuracy`]).

mod files;
mod reference;
mod scenes;

use crate::case::LoadedCase;
use crate::error::Error;
pub use files::{pareto_front, read_reference_curve, write, ReferenceCurve};
use reference::Reference;
pub use scenes::{solve_model, Outcome};
use serde::Serialize;
use std::time::Instant;

/// A body model of the study.
#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum SceneModel {
    /// Closed-form half-plane influence coefficients.
    HalfSpace,
    /// BEM blocks standing in for half-spaces, with the cylinders' profile.
    HalfSpaceBlock,
    /// BEM rollers of the true radius on rigid shafts.
    TrueGeometry,
    /// The half-space model on error-controlled grids (`contact.grid.tolerance`), one run per
    /// tolerance of `--tolerances`.
    HalfSpaceAdaptive,
}

impl SceneModel {
    /// All models, cheapest first (the error-controlled half-space last: its curve is drawn
    /// over the others).
    pub const ALL: [SceneModel; 4] = [
        SceneModel::HalfSpace,
        SceneModel::HalfSpaceBlock,
        SceneModel::TrueGeometry,
        SceneModel::HalfSpaceAdaptive,
    ];

    /// Name in the CSV, the chart and `--models`.
    pub fn name(self) -> &'static str {
        match self {
            SceneModel::HalfSpace => "half_space",
            SceneModel::HalfSpaceBlock => "half_space_block",
            SceneModel::TrueGeometry => "true_geometry",
            SceneModel::HalfSpaceAdaptive => "half_space_adaptive",
        }
    }

    /// Parses a `--models` entry.
    pub fn parse(name: &str) -> Option<Self> {
        Self::ALL.into_iter().find(|m| m.name() == name.trim())
    }
}

/// Controls of the study.
#[derive(Debug, Clone, PartialEq)]
pub struct AccuracyOptions {
    /// Contact elements of each rung.
    pub ladder: Vec<usize>,
    /// Models to run.
    pub models: Vec<SceneModel>,
    /// Shaft radius / roller radius of the true-geometry rollers.
    pub shaft_ratio: f64,
    /// Runs at once (0: one per core).
    pub jobs: usize,
    /// Tolerances of the `half_space_adaptive` runs.
    pub tolerances: Vec<f64>,
    /// A measured curve drawn on the chart for comparison (e.g. another solver's): its legend
    /// and its points (time [s], error, label).
    pub reference_curve: Option<ReferenceCurve>,
}

impl AccuracyOptions {
    /// The default ladder, 11 … 321 contact elements (about 6 minutes on 2 cores).
    pub fn default_ladder() -> Vec<usize> {
        vec![11, 21, 41, 81, 161, 321]
    }

    /// The `--quick` ladder (seconds).
    pub fn quick_ladder() -> Vec<usize> {
        vec![11, 21, 41]
    }

    /// The default tolerances of the error-controlled runs.
    pub fn default_tolerances() -> Vec<f64> {
        vec![1e-2, 1e-3, 1e-4, 1e-5]
    }

    /// The `--quick` tolerances.
    pub fn quick_tolerances() -> Vec<f64> {
        vec![1e-2, 1e-3]
    }
}

impl Default for AccuracyOptions {
    fn default() -> Self {
        Self {
            ladder: Self::default_ladder(),
            models: SceneModel::ALL.to_vec(),
            shaft_ratio: 0.1,
            jobs: 0,
            tolerances: Self::default_tolerances(),
            reference_curve: None,
        }
    }
}

/// One run of the study.
#[derive(Debug, Clone, Serialize)]
pub struct AccuracyRow {
    /// The body model.
    pub model: SceneModel,
    /// Contact elements (of the final grid of an error-controlled run).
    pub contact_elements: usize,
    /// The tolerance of an error-controlled run (`half_space_adaptive`), else none.
    pub tolerance: Option<f64>,
    /// Boundary elements per BEM body (the larger of the two; 0 for the half-space model).
    pub boundary_elements: usize,
    /// Whether the contact solver converged (errors are only meaningful if so).
    pub converged: bool,
    /// Newton iterations.
    pub iterations: usize,
    /// Root mean square of the study's nodal error over the contact (see the module docs) [-];
    /// the chart plots this one.
    pub error: f64,
    /// Largest nodal error [-]. Near Carter's stick/slip point, where q has a square-root kink,
    /// it is dominated by how close a node falls to the kink, so it does not fall steadily
    /// with the grid.
    pub error_max: f64,
    /// Relative creepage error against the closed form, when there is one [-].
    pub creep_error: Option<f64>,
    /// Assembly and condensation time [s].
    pub build_s: f64,
    /// Contact solve time [s].
    pub solve_s: f64,
    /// Total time of the run [s].
    pub total_s: f64,
    /// Why the run failed, if it did.
    pub message: String,
}

/// What a study measured.
#[derive(Debug, Clone, Serialize)]
pub struct AccuracyReport {
    /// The runs, by model and contact elements.
    pub rows: Vec<AccuracyRow>,
    /// What the errors are measured against.
    pub reference: String,
    /// The measured curve drawn for comparison (`--reference-curve`), if any.
    #[serde(skip)]
    pub reference_curve: Option<ReferenceCurve>,
    /// Wall time of the whole study [s].
    pub wall_s: f64,
}

/// The fewest contact elements a rung may have: fewer cannot hold a contact zone inside the grid.
const MIN_RUNG: usize = 3;

/// Runs the study on the scene of `case`; `progress` shows a bar on the terminal.
pub fn run(case: &LoadedCase, options: &AccuracyOptions, progress: bool) -> Result<AccuracyReport, Error> {
    let start = Instant::now();
    case.steady_only("`rollbem study accuracy`")?;
    let scene = scenes::scene_bodies(case)?;
    if options.ladder.is_empty() || options.models.is_empty() {
        return Err(study_error(
            "nothing to run: give at least one rung (--ladder) and one model (--models)",
        ));
    }
    if let Some(&rung) = options.ladder.iter().find(|&&n| n < MIN_RUNG) {
        return Err(study_error(&format!(
            "every rung of --ladder needs at least {MIN_RUNG} contact elements (value = {rung}); \
             the default ladder is 11,21,41,81,161,321"
        )));
    }
    if !(options.shaft_ratio > 0.0 && options.shaft_ratio < 0.9) {
        return Err(study_error(&format!(
            "--shaft-ratio must lie in (0, 0.9) (value = {}); the paper's rollers use 0.1",
            options.shaft_ratio
        )));
    }
    let closed = reference::closed_form(case, &scene);
    // The finest true-geometry run is the reference when the scene has no closed form.
    let mut models = options.models.clone();
    if closed.is_none() && !models.contains(&SceneModel::TrueGeometry) {
        models.push(SceneModel::TrueGeometry);
    }
    if models.contains(&SceneModel::HalfSpaceAdaptive) {
        if let Some(&t) = options.tolerances.iter().find(|&&t| !(1e-7..=0.5).contains(&t)) {
            return Err(study_error(&format!(
                "every tolerance of --tolerances must lie in [1e-7, 0.5] (value = {t})"
            )));
        }
    }
    // A rung is a number of contact elements, or for the error-controlled model the index of
    // its tolerance.
    let mut tasks: Vec<(SceneModel, usize)> = models
        .iter()
        .flat_map(|&m| {
            let rungs: Vec<usize> = if m == SceneModel::HalfSpaceAdaptive {
                (0..options.tolerances.len()).collect()
            } else {
                options.ladder.clone()
            };
            rungs.into_iter().map(move |n| (m, n))
        })
        .collect();
    // Longest first, for the load balance of the parallel runs.
    tasks.sort_by_key(|&(m, n)| {
        std::cmp::Reverse(match m {
            SceneModel::HalfSpace => n,
            SceneModel::HalfSpaceAdaptive => 100 * (n + 1),
            _ => 50 * n,
        })
    });
    let pool = rayon::ThreadPoolBuilder::new()
        .num_threads(options.jobs)
        .build()
        .map_err(|e| study_error(&format!("cannot start the worker threads: {e}")))?;
    let outcomes: Vec<(SceneModel, usize, Result<Outcome, String>)> = pool.install(|| {
        super::run_parallel(&tasks, "runs", progress, |&(model, n)| {
            let r = match model {
                SceneModel::HalfSpaceAdaptive => scenes::solve_adaptive_of(case, &scene, options.tolerances[n]),
                _ => scenes::solve_model_of(case, &scene, model, n, options.shaft_ratio),
            }
            .map_err(|e| e.to_string());
            (model, n, r)
        })
    });
    let reference = match closed {
        Some(c) => Reference::Closed(c),
        None => outcomes
            .iter()
            .filter(|(m, _, r)| *m == SceneModel::TrueGeometry && r.as_ref().is_ok_and(|o| o.solution_converged))
            .max_by_key(|(_, n, _)| *n)
            .and_then(|(_, n, r)| r.as_ref().ok().map(|o| Reference::finest_run(*n, o, case)))
            .ok_or_else(|| {
                study_error("the scene has no closed form and no true-geometry run converged to serve as the reference")
            })?,
    };
    let mut rows: Vec<AccuracyRow> = outcomes
        .into_iter()
        .filter(|(m, _, _)| options.models.contains(m))
        .map(|(model, n, r)| {
            let tolerance = (model == SceneModel::HalfSpaceAdaptive).then(|| options.tolerances[n]);
            let n = if tolerance.is_some() { 0 } else { n };
            (model, n, tolerance, r)
        })
        .map(|(model, n, tolerance, r)| match r {
            Ok(o) => {
                let (norms, creep_error) = reference.measure(&o.solution);
                let (error, error_max) = (norms.rms, norms.max);
                AccuracyRow {
                    model,
                    contact_elements: o.contact_elements,
                    tolerance,
                    boundary_elements: o.boundary_elements,
                    converged: o.solution_converged,
                    iterations: o.iterations,
                    error: if o.solution_converged { error } else { f64::NAN },
                    error_max: if o.solution_converged { error_max } else { f64::NAN },
                    creep_error,
                    build_s: o.build_s,
                    solve_s: o.solve_s,
                    total_s: o.build_s + o.solve_s,
                    message: String::new(),
                }
            }
            Err(message) => AccuracyRow {
                model,
                contact_elements: n,
                tolerance,
                boundary_elements: 0,
                converged: false,
                iterations: 0,
                error: f64::NAN,
                error_max: f64::NAN,
                creep_error: None,
                build_s: 0.0,
                solve_s: 0.0,
                total_s: 0.0,
                message,
            },
        })
        .collect();
    rows.sort_by(|a, b| {
        (a.model, a.contact_elements)
            .cmp(&(b.model, b.contact_elements))
            .then(b.tolerance.unwrap_or(0.0).total_cmp(&a.tolerance.unwrap_or(0.0)))
    });
    Ok(AccuracyReport {
        rows,
        reference: reference.describe(),
        reference_curve: options.reference_curve.clone(),
        wall_s: start.elapsed().as_secs_f64(),
    })
}

fn study_error(message: &str) -> Error {
    Error::Study {
        message: message.to_string(),
    }
}

/// The table printed by `rollbem study accuracy`.
pub fn render(report: &AccuracyReport) -> String {
    let mut t = format!("rollbem study accuracy: error against {}\n", report.reference);
    t.push_str(
        "  model              elements  boundary  converged  iterations  RMS error  max error  creep error  time [s]\n",
    );
    for r in &report.rows {
        let f = |v: f64| if v.is_finite() { format!("{v:.3e}") } else { "-".into() };
        let e = format!("{:<9}  {}", f(r.error), f(r.error_max));
        let c = r.creep_error.map_or("-".to_string(), |c| format!("{c:+.2e}"));
        t.push_str(&format!(
            "  {:<18} {:>8}  {:>8}  {:<9}  {:>10}  {:<20}  {:<11}  {:.4}{}\n",
            r.model.name(),
            r.contact_elements,
            r.boundary_elements,
            r.converged,
            r.iterations,
            e,
            c,
            r.total_s,
            match (r.tolerance, r.message.is_empty()) {
                (Some(t), true) => format!("  (tolerance {t:.0e})"),
                (Some(t), false) => format!("  (tolerance {t:.0e}: {})", r.message),
                (None, true) => String::new(),
                (None, false) => format!("  ({})", r.message),
            }
        ));
    }
    t.push_str(&format!("  study wall time        {:.1} s\n", report.wall_s));
    t
}
