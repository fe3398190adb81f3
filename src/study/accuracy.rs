//! `rollbem study accuracy CASE`: speed against accuracy of the body models (issue 6).
//!
//! The scene of the case — its cylinders' radii and materials, friction and load — is solved
//! with each body model that can represent it, at a ladder of discretizations:
//!
//! * `half_space` — the closed-form half-plane influence coefficients (the classical
//!   semi-analytic model), n contact elements;
//! * `half_space_block` — a BEM block standing in for each half-space (paper Fig. 2), 40a wide
//!   and deep, with the cylinders' profile: the BEM's discretization error on a half-space;
//! * `true_geometry` — each elastic cylinder a BEM roller of its radius on a rigid shaft
//!   (radius ratio `shaft_ratio`, the paper's Fig. 14 uses 0.1), as
//!   [`crate::mesh::build::roller_on_shaft`] builds it: the model error of the half-space is
//!   what separates the two.
//!
//! Rigid bodies stay rigid in every model. Each run's error is measured against the scene's
//! closed form where it has one — Carter's shear (similar materials, Q/μP given:
//! |q − q_Carter| / μp0, reference sheet §2) or Hertz's pressure (similar materials, Q = 0:
//! |p − p_Hertz| / p0, sheet §1) — and otherwise against the finest true-geometry run (the
//! larger of the nodal differences of p/p_max and q/(μp_max) after interpolating that run to
//! the node, stated as such in the output). The nodal errors are summarised by their RMS over
//! the nodes inside the contact (the reference's |x| < a) — the chart's measure — and by their
//! maximum. The wall time is the run's own (assembly,
//! condensation and contact solve), measured while the other runs of the study use the other
//! cores: use `--jobs 1` for undisturbed times.

use crate::analytic::{hertz_pressure, Carter};
use crate::app::{self, LoadedMesh, PreparedBody};
use crate::case::{BodySpec, BoundaryKeyword, BoundarySpec, LoadedCase, NormalSpec, TangentialSpec};
use crate::contact::solution::ContactSolution;
use crate::error::Error;
use crate::mesh::build::{half_space_block, roller_on_shaft, RollerMeshSizes};
use crate::mesh::{validate_and_orient, BoundaryMesh};
use plotters::prelude::*;
use serde::Serialize;
use std::collections::BTreeMap;
use std::path::{Path, PathBuf};
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
}

impl SceneModel {
    /// All models, cheapest first.
    pub const ALL: [SceneModel; 3] = [
        SceneModel::HalfSpace,
        SceneModel::HalfSpaceBlock,
        SceneModel::TrueGeometry,
    ];

    /// Name in the CSV, the chart and `--models`.
    pub fn name(self) -> &'static str {
        match self {
            SceneModel::HalfSpace => "half_space",
            SceneModel::HalfSpaceBlock => "half_space_block",
            SceneModel::TrueGeometry => "true_geometry",
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
}

impl Default for AccuracyOptions {
    fn default() -> Self {
        Self {
            ladder: Self::default_ladder(),
            models: SceneModel::ALL.to_vec(),
            shaft_ratio: 0.1,
            jobs: 0,
        }
    }
}

/// One run of the study.
#[derive(Debug, Clone, Serialize)]
pub struct AccuracyRow {
    /// The body model.
    pub model: SceneModel,
    /// Contact elements.
    pub contact_elements: usize,
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
    /// Wall time of the whole study [s].
    pub wall_s: f64,
}

/// The closed form a scene has, if any.
#[derive(Debug, Clone, Copy)]
enum ClosedForm {
    /// Carter's shear (and creepage) for similar bodies under a load ratio.
    Carter(Carter, f64),
    /// Hertz's pressure for similar bodies at Q = 0.
    Hertz { half_width: f64, peak: f64 },
}

/// The elastic description of one body of the scene.
#[derive(Debug, Clone)]
struct SceneBody {
    /// Material name (None: rigid).
    material: Option<String>,
    radius: f64,
}

/// Runs the study on the scene of `case`; `progress` shows a bar on the terminal.
pub fn run(case: &LoadedCase, options: &AccuracyOptions, progress: bool) -> Result<AccuracyReport, Error> {
    let start = Instant::now();
    let scene = scene_bodies(case)?;
    if options.ladder.is_empty() || options.models.is_empty() {
        return Err(study_error(
            "nothing to run: give at least one rung (--ladder) and one model (--models)",
        ));
    }
    if !(options.shaft_ratio > 0.0 && options.shaft_ratio < 0.9) {
        return Err(study_error(&format!(
            "--shaft-ratio must lie in (0, 0.9) (value = {}); the paper's rollers use 0.1",
            options.shaft_ratio
        )));
    }
    let closed = closed_form(case, &scene)?;
    // The finest true-geometry run is the reference when the scene has no closed form.
    let mut models = options.models.clone();
    if closed.is_none() && !models.contains(&SceneModel::TrueGeometry) {
        models.push(SceneModel::TrueGeometry);
    }
    let mut tasks: Vec<(SceneModel, usize)> = models
        .iter()
        .flat_map(|&m| options.ladder.iter().map(move |&n| (m, n)))
        .collect();
    // Longest first, for the load balance of the parallel runs.
    tasks.sort_by_key(|&(m, n)| std::cmp::Reverse(n * if m == SceneModel::HalfSpace { 1 } else { 50 }));
    let pool = rayon::ThreadPoolBuilder::new()
        .num_threads(options.jobs)
        .build()
        .map_err(|e| study_error(&format!("cannot start the worker threads: {e}")))?;
    let outcomes: Vec<(SceneModel, usize, Result<Outcome, String>)> = pool.install(|| {
        super::run_parallel(&tasks, "runs", progress, |&(model, n)| {
            let r = run_one(case, &scene, model, n, options.shaft_ratio).map_err(|e| e.to_string());
            (model, n, r)
        })
    });
    let reference_run = match closed {
        Some(_) => None,
        None => outcomes
            .iter()
            .filter(|(m, _, r)| *m == SceneModel::TrueGeometry && r.as_ref().is_ok_and(|o| o.solution_converged))
            .max_by_key(|(_, n, _)| *n)
            .and_then(|(_, n, r)| r.as_ref().ok().map(|o| (*n, o.clone()))),
    };
    let reference = match (&closed, &reference_run) {
        (Some(ClosedForm::Carter(..)), _) => {
            "Carter's shear: |q - q_Carter| / (mu p0), RMS and max over the nodes with |x| < a".to_string()
        }
        (Some(ClosedForm::Hertz { .. }), _) => {
            "Hertz's pressure: |p - p_Hertz| / p0, RMS and max over the nodes with |x| < a".to_string()
        }
        (None, Some((n, _))) => format!(
            "no closed form for this scene: the finest true-geometry run ({n} contact elements); \
             the larger of |p - p_ref| / p_ref,max and |q - q_ref| / (mu p_ref,max), RMS and max over \
             the nodes inside its contact"
        ),
        (None, None) => {
            return Err(study_error(
                "the scene has no closed form and no true-geometry run converged to serve as the reference",
            ))
        }
    };
    let mut rows: Vec<AccuracyRow> = outcomes
        .into_iter()
        .filter(|(m, _, _)| options.models.contains(m))
        .map(|(model, n, r)| match r {
            Ok(o) => {
                let ((error, error_max), creep_error) = match (&closed, &reference_run) {
                    (Some(c), _) => measure_closed(c, &o.solution),
                    (None, Some((_, reference))) => (measure_against(&reference.solution, &o.solution, case), None),
                    (None, None) => unreachable!("checked above"),
                };
                AccuracyRow {
                    model,
                    contact_elements: n,
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
    rows.sort_by_key(|r| (r.model, r.contact_elements));
    Ok(AccuracyReport {
        rows,
        reference,
        wall_s: start.elapsed().as_secs_f64(),
    })
}

fn study_error(message: &str) -> Error {
    Error::Study {
        message: message.to_string(),
    }
}

/// The two bodies of the scene: materials and profile radii of the case's bodies.
fn scene_bodies(case: &LoadedCase) -> Result<[SceneBody; 2], Error> {
    let prepared = app::prepare_bodies(case)?;
    let body = |spec: &BodySpec, p: &PreparedBody| -> Result<SceneBody, Error> {
        let material = match spec {
            BodySpec::HalfSpace { material, .. } | BodySpec::Bem { material, .. } => Some(material.clone()),
            BodySpec::Rigid { .. } => None,
        };
        if !p.radius.is_finite() {
            return Err(study_error(
                "a body of the case has a flat profile (infinite radius): the study compares models of \
                 cylinders; give the body a radius",
            ));
        }
        Ok(SceneBody {
            material,
            radius: p.radius,
        })
    };
    let c = &case.case;
    Ok([body(&c.bodies.a, &prepared[0])?, body(&c.bodies.b, &prepared[1])?])
}

/// Carter or Hertz when both bodies are elastic and similar and P is given.
fn closed_form(case: &LoadedCase, scene: &[SceneBody; 2]) -> Result<Option<ClosedForm>, Error> {
    let c = &case.case;
    let similar = match (&scene[0].material, &scene[1].material) {
        (Some(a), Some(b)) => {
            let (ma, mb) = (case.material(a), case.material(b));
            (ma.young - mb.young).abs() <= 1e-12 * ma.young && (ma.poisson - mb.poisson).abs() <= 1e-12
        }
        _ => false,
    };
    if !similar || !matches!(c.load.normal(), NormalSpec::Force(_)) {
        return Ok(None);
    }
    let bodies = half_space_bodies(case, scene);
    let est = app::estimates(case, &bodies);
    Ok(match c.load.tangential() {
        TangentialSpec::Ratio(r) if r != 0.0 => {
            app::carter_reference(case, &est).map(|k| ClosedForm::Carter(k, est.effective_radius))
        }
        TangentialSpec::Ratio(_) => Some(ClosedForm::Hertz {
            half_width: est.hertz_half_width,
            peak: est.hertz_peak_pressure,
        }),
        _ => None,
    })
}

/// The scene's bodies as half-spaces (rigid bodies stay rigid).
fn half_space_bodies(case: &LoadedCase, scene: &[SceneBody; 2]) -> [PreparedBody; 2] {
    scene.clone().map(|b| PreparedBody {
        material: b.material.as_ref().map(|m| case.material(m)),
        radius: b.radius,
        mesh: None,
    })
}

/// What one run of a scene produced.
#[derive(Debug, Clone)]
pub struct Outcome {
    /// The contact solution (the last iterate if not converged).
    pub solution: ContactSolution,
    /// Whether the contact solver converged.
    pub solution_converged: bool,
    /// Solver iterations.
    pub iterations: usize,
    /// Boundary elements of the larger BEM body (0 for the half-space model).
    pub boundary_elements: usize,
    /// Assembly and condensation time [s].
    pub build_s: f64,
    /// Contact solve time [s].
    pub solve_s: f64,
}

/// Solves the scene of `case` (its bodies' materials and radii, its load and friction) with
/// `model` at `n` contact elements; true-geometry rollers sit on shafts of `shaft_ratio` times
/// their radius.
pub fn solve_scene(case: &LoadedCase, model: SceneModel, n: usize, shaft_ratio: f64) -> Result<Outcome, Error> {
    run_one(case, &scene_bodies(case)?, model, n, shaft_ratio)
}

fn run_one(
    case: &LoadedCase,
    scene: &[SceneBody; 2],
    model: SceneModel,
    n: usize,
    shaft_ratio: f64,
) -> Result<Outcome, Error> {
    let start = Instant::now();
    let mut c = case.clone();
    c.case.contact.grid.elements = n;
    c.case.output.interior = None;
    c.case.output.vtk = false;
    // The grid of the half-space model sets the contact segment of the BEM meshes, so that
    // every model solves on the same nodes.
    for (spec, body) in [(&mut c.case.bodies.a, &scene[0]), (&mut c.case.bodies.b, &scene[1])] {
        if let Some(material) = &body.material {
            *spec = BodySpec::HalfSpace {
                material: material.clone(),
                radius: body.radius,
            };
        }
    }
    let mut bodies = half_space_bodies(&c, scene);
    let est = app::estimates(&c, &bodies);
    let half_length = est.grid_half_length;
    let mut boundary_elements = 0;
    if model != SceneModel::HalfSpace {
        let a = est.hertz_half_width;
        for (k, (spec, body)) in [(&mut c.case.bodies.a, &scene[0]), (&mut c.case.bodies.b, &scene[1])]
            .into_iter()
            .enumerate()
        {
            let Some(material) = &body.material else { continue };
            let above = k == 0;
            let (mesh, groups, radius) = match model {
                SceneModel::HalfSpaceBlock => (
                    half_space_block(40.0 * a, 40.0 * a, half_length, n, 4.0 * a, above),
                    [("far", BoundaryKeyword::Fixed), ("free", BoundaryKeyword::Free)],
                    Some(body.radius),
                ),
                _ => (
                    roller_on_shaft(
                        body.radius,
                        shaft_ratio * body.radius,
                        half_length,
                        roller_sizes(n),
                        above,
                    ),
                    [("shaft", BoundaryKeyword::Fixed), ("free", BoundaryKeyword::Free)],
                    None,
                ),
            };
            boundary_elements = boundary_elements.max(mesh.elements.len());
            bodies[k].mesh = Some(procedural(mesh, model)?);
            *spec = BodySpec::Bem {
                mesh: format!("<procedural {}>", model.name()),
                material: material.clone(),
                contact: "contact".into(),
                boundaries: groups
                    .into_iter()
                    .map(|(g, kw)| (g.to_string(), BoundarySpec::Keyword(kw)))
                    .collect::<BTreeMap<_, _>>(),
                radius,
            };
            bodies[k].radius = radius.unwrap_or(body.radius);
        }
    }
    let solved = app::solve_prepared(&c, &bodies, start)?;
    Ok(Outcome {
        solution_converged: solved.report.converged,
        iterations: solved.report.iterations,
        boundary_elements,
        build_s: solved.timings.assembly_s + solved.timings.condense_s,
        solve_s: solved.timings.solve_s,
        solution: solved.solution,
    })
}

/// Element counts of a true-geometry roller with n contact elements: the free arc gets n/2
/// (at least 32, at most 160) graded elements, the shaft 24 (the shaft's own error is below
/// 1e-4 at 24, docs/validation.md).
fn roller_sizes(n: usize) -> RollerMeshSizes {
    RollerMeshSizes {
        contact: n,
        free: (n / 2).clamp(32, 160),
        shaft: 24,
    }
}

/// A procedural mesh, oriented, as the prepared mesh of a `bem` body.
fn procedural(mut mesh: BoundaryMesh, model: SceneModel) -> Result<LoadedMesh, Error> {
    let notices = validate_and_orient(&mut mesh)?;
    let contact_group = mesh.group_index("contact")?;
    Ok(LoadedMesh {
        path: PathBuf::from(format!("<procedural {}>", model.name())),
        mesh,
        notices,
        contact_group,
    })
}

/// ((RMS, max) error, creep error) against Carter or Hertz, over the nodes with |x| < a.
fn measure_closed(closed: &ClosedForm, sol: &ContactSolution) -> ((f64, f64), Option<f64>) {
    match *closed {
        ClosedForm::Carter(k, radius) => {
            let scale = k.friction * k.peak_pressure;
            let e = nodal_errors(sol, k.half_width, |i| (sol.shear[i] - k.shear(sol.x[i])).abs() / scale);
            (e, Some(sol.creep / k.creep(radius) - 1.0))
        }
        ClosedForm::Hertz { half_width, peak } => {
            let e = nodal_errors(sol, half_width, |i| {
                (sol.pressure[i] - hertz_pressure(sol.x[i], half_width, peak)).abs() / peak
            });
            (e, None)
        }
    }
}

/// (RMS, max) error against a reference solution interpolated to this run's nodes, over the
/// nodes inside the reference's contact.
fn measure_against(reference: &ContactSolution, sol: &ContactSolution, case: &LoadedCase) -> (f64, f64) {
    let p_max = reference
        .pressure
        .iter()
        .fold(0.0_f64, |m, &p| m.max(p))
        .max(f64::MIN_POSITIVE);
    let mu = case.case.contact.friction.max(f64::MIN_POSITIVE);
    let interp = |v: &[f64], x: f64| linear(&reference.x, v, x);
    let [x0, x1] = reference.contact_extent().unwrap_or([0.0, 0.0]);
    let (centre, half) = (0.5 * (x0 + x1), 0.5 * (x1 - x0));
    let shifted: Vec<f64> = sol.x.iter().map(|x| x - centre).collect();
    nodal_errors_at(&shifted, half, |i| {
        let dp = (sol.pressure[i] - interp(&reference.pressure, sol.x[i])).abs() / p_max;
        let dq = (sol.shear[i] - interp(&reference.shear, sol.x[i])).abs() / (mu * p_max);
        dp.max(dq)
    })
}

/// (RMS, max) of `f` over the nodes of `sol` with |x| < `half_width`.
fn nodal_errors(sol: &ContactSolution, half_width: f64, f: impl Fn(usize) -> f64) -> (f64, f64) {
    nodal_errors_at(&sol.x, half_width, f)
}

fn nodal_errors_at(x: &[f64], half_width: f64, f: impl Fn(usize) -> f64) -> (f64, f64) {
    let e: Vec<f64> = (0..x.len()).filter(|&i| x[i].abs() < half_width).map(f).collect();
    if e.is_empty() {
        return (f64::NAN, f64::NAN);
    }
    let rms = (e.iter().map(|v| v * v).sum::<f64>() / e.len() as f64).sqrt();
    (rms, e.iter().copied().fold(0.0_f64, f64::max))
}

/// Piecewise-linear interpolation of (xs, v) at x (xs increasing; constant beyond the ends).
fn linear(xs: &[f64], v: &[f64], x: f64) -> f64 {
    let k = xs.partition_point(|&t| t < x);
    if k == 0 {
        return v[0];
    }
    if k == xs.len() {
        return v[xs.len() - 1];
    }
    let t = (x - xs[k - 1]) / (xs[k] - xs[k - 1]);
    v[k - 1] + t * (v[k] - v[k - 1])
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
            if r.message.is_empty() {
                String::new()
            } else {
                format!("  ({})", r.message)
            }
        ));
    }
    t.push_str(&format!("  study wall time        {:.1} s\n", report.wall_s));
    t
}

/// Writes accuracy.csv, accuracy.svg and accuracy.json into `dir` (through a temporary folder,
/// renamed on success: [`crate::output::write_atomically`]).
pub fn write(dir: &Path, report: &AccuracyReport, title: &str) -> Result<(), Error> {
    let io = |path: &Path, e: &dyn std::fmt::Display| Error::Output {
        path: path.to_path_buf(),
        message: e.to_string(),
    };
    crate::output::write_atomically(dir, crate::output::folder::Kind::StudyAccuracy, |tmp| {
        let csv_path = tmp.join("accuracy.csv");
        let mut w = csv::Writer::from_path(&csv_path).map_err(|e| io(&csv_path, &e))?;
        w.write_record([
            "model",
            "contact_elements",
            "boundary_elements",
            "converged",
            "iterations",
            "error_rms",
            "error_max",
            "creep_error",
            "build_s",
            "solve_s",
            "total_s",
            "message",
        ])
        .map_err(|e| io(&csv_path, &e))?;
        let num = |v: f64| if v.is_finite() { format!("{v:e}") } else { String::new() };
        for r in &report.rows {
            w.write_record([
                r.model.name().to_string(),
                r.contact_elements.to_string(),
                r.boundary_elements.to_string(),
                r.converged.to_string(),
                r.iterations.to_string(),
                num(r.error),
                num(r.error_max),
                r.creep_error.map_or(String::new(), num),
                num(r.build_s),
                num(r.solve_s),
                num(r.total_s),
                r.message.clone(),
            ])
            .map_err(|e| io(&csv_path, &e))?;
        }
        w.flush().map_err(|e| io(&csv_path, &e))?;
        drop(w);
        let json_path = tmp.join("accuracy.json");
        let json = serde_json::to_string_pretty(&report).map_err(|e| io(&json_path, &e))?;
        std::fs::write(&json_path, json).map_err(|e| io(&json_path, &e))?;
        let svg_path = tmp.join("accuracy.svg");
        draw_chart(&svg_path, report, title).map_err(|e| io(&svg_path, &e))
    })
}

/// The points (time, error) of the converged runs that no other run beats in both.
pub fn pareto_front(report: &AccuracyReport) -> Vec<(f64, f64)> {
    let mut pts: Vec<(f64, f64)> = report
        .rows
        .iter()
        .filter(|r| r.converged && r.error.is_finite() && r.total_s > 0.0)
        .map(|r| (r.total_s, r.error))
        .collect();
    pts.sort_by(|a, b| a.0.total_cmp(&b.0));
    let mut front: Vec<(f64, f64)> = Vec::new();
    for p in pts {
        if front.last().is_none_or(|l| p.1 < l.1) {
            front.push(p);
        }
    }
    front
}

fn draw_chart(path: &Path, report: &AccuracyReport, title: &str) -> Result<(), Box<dyn std::error::Error>> {
    let pts: Vec<&AccuracyRow> = report
        .rows
        .iter()
        .filter(|r| r.converged && r.error.is_finite() && r.error > 0.0 && r.total_s > 0.0)
        .collect();
    let root = SVGBackend::new(path, (900, 640)).into_drawing_area();
    root.fill(&WHITE)?;
    let root = root.titled(title, ("sans-serif", 18))?;
    if pts.is_empty() {
        root.draw(&Text::new("no converged run to plot", (300, 300), ("sans-serif", 20)))?;
        root.present()?;
        return Ok(());
    }
    let bounds = |f: &dyn Fn(&AccuracyRow) -> f64| {
        let (lo, hi) = pts
            .iter()
            .fold((f64::INFINITY, 0.0_f64), |(l, h), r| (l.min(f(r)), h.max(f(r))));
        (lo / 2.0, hi * 2.0)
    };
    let (t0, t1) = bounds(&|r| r.total_s);
    let (e0, e1) = bounds(&|r| r.error);
    let mut chart = ChartBuilder::on(&root)
        .margin(15)
        .x_label_area_size(45)
        .y_label_area_size(70)
        .caption(
            format!("error against {}", short_reference(&report.reference)),
            ("sans-serif", 14),
        )
        .build_cartesian_2d((t0..t1).log_scale(), (e0..e1).log_scale())?;
    chart
        .configure_mesh()
        .x_desc("wall time of a run [s]")
        .y_desc("RMS error")
        .x_label_formatter(&|v| format!("{v:.0e}"))
        .y_label_formatter(&|v| format!("{v:.0e}"))
        .draw()?;
    let colours = [BLUE, RED, GREEN];
    for (k, model) in SceneModel::ALL.iter().enumerate() {
        let series: Vec<(f64, f64)> = pts
            .iter()
            .filter(|r| r.model == *model)
            .map(|r| (r.total_s, r.error))
            .collect();
        if series.is_empty() {
            continue;
        }
        let colour = colours[k % colours.len()];
        chart
            .draw_series(LineSeries::new(series.clone(), colour.stroke_width(2)))?
            .label(model.name())
            .legend(move |(x, y)| PathElement::new(vec![(x, y), (x + 20, y)], colour.stroke_width(2)));
        chart.draw_series(series.iter().map(|&p| Circle::new(p, 4, colour.filled())))?;
        chart.draw_series(pts.iter().filter(|r| r.model == *model).map(|r| {
            Text::new(
                format!("{}", r.contact_elements),
                (r.total_s, r.error),
                ("sans-serif", 11).into_font().color(&colour),
            )
        }))?;
    }
    let front = pareto_front(report);
    if front.len() > 1 {
        let mut steps = Vec::new();
        for w in front.windows(2) {
            steps.push(w[0]);
            steps.push((w[1].0, w[0].1));
        }
        steps.push(*front.last().expect("non-empty"));
        chart
            .draw_series(LineSeries::new(steps, BLACK.mix(0.6).stroke_width(1)))?
            .label("Pareto front")
            .legend(|(x, y)| PathElement::new(vec![(x, y), (x + 20, y)], BLACK.mix(0.6)));
    }
    chart
        .configure_series_labels()
        .border_style(BLACK)
        .background_style(WHITE.mix(0.85))
        .position(SeriesLabelPosition::UpperRight)
        .draw()?;
    root.present()?;
    Ok(())
}

fn short_reference(reference: &str) -> &str {
    reference.split(':').next().unwrap_or(reference)
}
