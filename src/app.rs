//! The driver: case → scene → body models → contact problem → solver → post-processing →
//! outputs, one stage after the other (docs/architecture.md maps them to files).

use crate::case::{self, LoadedCase};
use crate::contact::{ContactProblem, SolveReport};
use crate::error::Error;
use crate::output::{self, Summary};
pub use crate::post::Solved;
use crate::post::{self, ContactSolution};
use crate::scene::Scene;
use std::path::{Path, PathBuf};
use std::time::Instant;

mod transient;
pub(crate) use transient::check_datum_bodies;

/// Where a case comes from: a file, or text in memory that stands for a file.
#[derive(Debug, Clone, Copy)]
pub enum CaseSource<'a> {
    /// A case file.
    File(&'a Path),
    /// Case text; `path` names it in messages and its folder resolves the case's relative
    /// paths (meshes).
    Text {
        /// The YAML text.
        text: &'a str,
        /// The file it stands for.
        path: &'a Path,
    },
}

impl<'a> From<&'a Path> for CaseSource<'a> {
    fn from(path: &'a Path) -> Self {
        CaseSource::File(path)
    }
}

impl<'a> From<&'a PathBuf> for CaseSource<'a> {
    fn from(path: &'a PathBuf) -> Self {
        CaseSource::File(path)
    }
}

/// Loads and validates a case with `--set`-style overrides (`key.path=value`).
pub fn load_case<'a, S: AsRef<str>>(source: impl Into<CaseSource<'a>>, overrides: &[S]) -> Result<LoadedCase, Error> {
    let set: Vec<String> = overrides.iter().map(|s| s.as_ref().to_string()).collect();
    Ok(match source.into() {
        CaseSource::File(path) => case::load(path, &set)?,
        CaseSource::Text { text, path } => case::parse(text, path, &set)?,
    })
}

/// Loads a case with overrides and solves it; nothing is written. Input errors (a value out
/// of range, an unknown key, a bad mesh) come back as `Err`; a run that does not converge is
/// `Ok` with `report.converged == false`.
pub fn solve_case<'a, S: AsRef<str>>(source: impl Into<CaseSource<'a>>, overrides: &[S]) -> Result<Solved, Error> {
    let start = Instant::now();
    let case = load_case(source, overrides)?;
    solve_scene(Scene::from_case(&case)?, start)
}

/// Solves a loaded case.
pub fn solve(case: &LoadedCase) -> Result<Solved, Error> {
    let start = Instant::now();
    solve_scene(Scene::from_case(case)?, start)
}

/// Solves a scene: builds the body models, assembles and solves the contact problem and
/// post-processes it; `start` is when the run began, for the timings. An error-controlled grid
/// that reaches `contact.grid.max_elements` before its tolerance is an error
/// ([`Error::ToleranceNotReached`]); [`run`] writes its best solution's summary first.
pub fn solve_scene(scene: Scene, start: Instant) -> Result<Solved, Error> {
    let solved = solve_scene_best(scene, start)?;
    match tolerance_not_reached(&solved) {
        Some(e) => Err(e),
        None => Ok(solved),
    }
}

/// [`solve_scene`], returning the best solution of an error-controlled grid that did not
/// reach its tolerance (its `adaptation.reached` false) instead of an error.
pub fn solve_scene_best(scene: Scene, start: Instant) -> Result<Solved, Error> {
    solve_adapted(scene, start, false)
}

/// Solves a loaded case as `rollbem run` does: [`solve`], and a fixed grid's solution gets its
/// error estimate when the case asks for it (`contact.grid.estimate`, src/adapt/fixed.rs).
pub fn solve_run(case: &LoadedCase) -> Result<Solved, Error> {
    let start = Instant::now();
    let s = solve_run_scene(Scene::from_case(case)?, start)?;
    match tolerance_not_reached(&s) {
        Some(e) => Err(e),
        None => Ok(s),
    }
}

/// Solves a loaded case as [`solve_run`] does, with a fixed grid's error estimate whatever
/// `contact.grid.estimate` says (`rollbem check --estimate`).
pub fn solve_estimated(case: &LoadedCase) -> Result<Solved, Error> {
    let start = Instant::now();
    let s = solve_adapted(Scene::from_case(case)?, start, true)?;
    match tolerance_not_reached(&s) {
        Some(e) => Err(e),
        None => Ok(s),
    }
}

/// [`solve_scene_best`] as `rollbem run` solves it (see [`solve_run`]).
fn solve_run_scene(scene: Scene, start: Instant) -> Result<Solved, Error> {
    let estimate = scene.case.case.contact.grid.estimate;
    solve_adapted(scene, start, estimate)
}

/// [`solve_scene`] with an error-controlled grid's passes started from `from`, a neighbouring
/// run's final grid and solution ([`crate::adapt::solve_from`]; a fixed grid ignores it), with
/// where the run's own neighbours may start (None unless the run met its tolerance).
pub fn solve_scene_from(
    scene: Scene,
    start: Instant,
    from: Option<&crate::adapt::GridStart>,
) -> Result<(Solved, Option<crate::adapt::GridStart>), Error> {
    let (solved, next) = solve_adapted_from(scene, start, false, from)?;
    match tolerance_not_reached(&solved) {
        Some(e) => Err(e),
        None => Ok((solved, next)),
    }
}

/// [`solve_scene_best`], estimating a fixed grid's error when `estimate_fixed`.
fn solve_adapted(scene: Scene, start: Instant, estimate_fixed: bool) -> Result<Solved, Error> {
    Ok(solve_adapted_from(scene, start, estimate_fixed, None)?.0)
}

/// [`solve_adapted`] from `from` ([`solve_scene_from`]), with the run's own grid start.
fn solve_adapted_from(
    scene: Scene,
    start: Instant,
    estimate_fixed: bool,
    from: Option<&crate::adapt::GridStart>,
) -> Result<(Solved, Option<crate::adapt::GridStart>), Error> {
    // Scenes of a study's own bodies are not checked by `Scene::from_case`.
    crate::scene::preflight::check_memory(&scene.case, &scene.bodies)?;
    // Reading the case and the meshes counts as assembly.
    let before = start.elapsed().as_secs_f64();
    let mut a = crate::adapt::solve_from(&scene, from)?;
    let next = a.grid_start.take();
    let mut timings = a.timings;
    timings.assembly_s += before;
    timings.total_s = start.elapsed().as_secs_f64();
    let converged = a.report.converged;
    let mut solved = post::process(a.scene, &a.models, a.problem, &a.state, a.report, timings)?;
    solved.adaptation = a.adaptation;
    // The bodies' models go before the halved grid's are built (a BEM body's matrices twice).
    drop(a.models);
    let fixed_grid_estimate = match estimate_fixed && converged {
        true => {
            let mut t = post::Timings::default();
            let e = crate::adapt::fixed::fixed_grid_estimate(&solved.scene, &solved.problem, &a.state, &mut t)?;
            solved.timings.solve_s += t.solve_s + t.assembly_s + t.condense_s;
            solved.timings.total_s = start.elapsed().as_secs_f64();
            e
        }
        false => None,
    };
    solved.fixed_grid_estimate = fixed_grid_estimate;
    Ok((solved, next))
}

/// The error of a solution whose error-controlled grid stopped at its limit, if it did.
fn tolerance_not_reached(s: &Solved) -> Option<Error> {
    let a = s.adaptation.as_ref().filter(|a| !a.reached)?;
    let e = a.estimate?;
    if let (Some(bodies), Some(b)) = (&a.coarse_body_mesh, e.body_mesh) {
        return Some(Error::BodyMeshTooCoarse {
            case: s.scene.case.path.clone(),
            bodies: bodies.clone(),
            tolerance: a.tolerance,
            bisections: b.bisections,
            pressure: b.pressure,
            shear: b.shear,
            creep: b.creepage_rel,
        });
    }
    if let Some(f) = a.floor {
        return Some(Error::RefinementFloor {
            case: s.scene.case.path.clone(),
            tolerance: a.tolerance,
            risen_pass: f.risen_pass,
            risen: f.risen_estimate,
            shortest: f.shortest_element,
            best_pass: f.best_pass,
            best: f.best_estimate,
            elements: s.problem.grid.n_elements(),
            best_shortest: f.best_shortest_element,
            pressure: e.pressure_rms,
            shear: e.shear_rms,
            creep: e.creep_rel,
            reachable: rounded_up(e.largest()),
        });
    }
    Some(Error::ToleranceNotReached {
        case: s.scene.case.path.clone(),
        tolerance: a.tolerance,
        elements: s.problem.grid.n_elements(),
        max_elements: s.scene.grid_control.map_or(0, |c| c.max_elements),
        pressure: e.pressure_rms,
        shear: e.shear_rms,
        creep: e.creep_rel,
    })
}

/// `v` > 0 rounded up to two significant digits (1.0651e-5 → 1.1e-5).
fn rounded_up(v: f64) -> f64 {
    if v <= 0.0 || !v.is_finite() {
        return v;
    }
    let scale = 10f64.powi(v.log10().floor() as i32 - 1);
    (v / scale).ceil() * scale
}

/// Everything a run produced.
#[derive(Debug, Clone)]
pub struct RunReport {
    /// The summary written to summary.json.
    pub summary: Summary,
    /// The solution (also for a non-converged run: the last iterate, not written as a result).
    pub solution: ContactSolution,
    /// The assembled problem.
    pub problem: ContactProblem,
    /// Solver report.
    pub report: SolveReport,
    /// The iteration budget the solver had (`solver.max_iterations`).
    pub max_iterations: usize,
    /// The scaled residual the solver had to reach (`solver.tolerance`).
    pub tolerance: f64,
    /// Where the outputs were written.
    pub output_dir: PathBuf,
}

/// Loads a case, solves it and writes its outputs (cases/README.md). A run that does not
/// converge writes only summary.json (with `converged: false` and the residual history) and
/// returns `Ok` with `summary.converged == false`.
pub fn run(case_path: &Path, overrides: &[String], out: Option<&Path>) -> Result<RunReport, Error> {
    run_with(case_path, overrides, out, false)
}

/// [`run`]; with `force`, files of an earlier result in the output folder that were changed
/// since rollbem wrote them are replaced too (`rollbem run --force`). The case's own inputs
/// never are.
pub fn run_with(case_path: &Path, overrides: &[String], out: Option<&Path>, force: bool) -> Result<RunReport, Error> {
    let start = Instant::now();
    let case = case::load(case_path, overrides)?;
    let output_dir = out.map(Path::to_path_buf).unwrap_or_else(|| case.output_dir());
    // Lock and check the output folder before solving: a foreign, busy or edited folder, or one
    // that holds an input of the case, fails at once.
    let _claim = output::folder::Claim::acquire_with(
        &output_dir,
        output::folder::Kind::Run,
        output::folder::Access::Exclusive,
        write_options(&case, force),
    )?;
    if let Some(spec) = &case.case.transient {
        return transient::run(&case, spec, &output_dir, start);
    }
    let s = solve_run_scene(Scene::from_case(&case)?, start)?;
    let missed = tolerance_not_reached(&s);
    let mut summary = output::summary(&s);
    if missed.is_some() {
        // The best solution reached is written as a result that did not converge: its summary
        // with the estimate, nothing else.
        summary.converged = false;
    }
    post::finite::check(&case.path, "summary.json", &summary)?;
    output::write_run(&output_dir, &mut summary, &s, start)?;
    if let Some(e) = missed {
        return Err(e);
    }
    Ok(RunReport {
        summary,
        solution: s.solution,
        problem: s.problem,
        report: s.report,
        max_iterations: s.scene.solver.newton.max_iterations,
        tolerance: s.scene.solver.newton.tolerance,
        output_dir,
    })
}

/// The summary of a solved run as summary.json holds it, checked finite.
pub fn checked_summary(s: &Solved) -> Result<Summary, Error> {
    let summary = output::summary(s);
    post::finite::check(&s.scene.case.path, "summary.json", &summary)?;
    Ok(summary)
}

/// Writes the outputs of a solved run into `out` as [`run`] does (the folder claimed and locked
/// while it is written); returns its summary. `start` is when the run began.
pub fn write_solved(s: &Solved, out: &Path, start: Instant) -> Result<Summary, Error> {
    let _claim = output::folder::Claim::acquire_with(
        out,
        output::folder::Kind::Run,
        output::folder::Access::Exclusive,
        write_options(&s.scene.case, false),
    )?;
    let mut summary = checked_summary(s)?;
    output::write_run(out, &mut summary, s, start)?;
    Ok(summary)
}

/// What the output folder of `case` may not hold (its inputs) and whether edited results are
/// replaced (`force`).
fn write_options(case: &LoadedCase, force: bool) -> output::folder::WriteOptions {
    output::folder::WriteOptions {
        force,
        inputs: case.input_files(),
    }
}

/// Writes the meshes rollbem generates for the `geometry:` bodies of a case (with `--set`
/// overrides) into `out` as `A.msh`, `B.msh` (Gmsh MSH 4.1 ASCII; [`crate::mesh::write_msh41_ascii`]),
/// atomically like a run's results. Returns the files written. A case without a `geometry:`
/// body is bad input; so is an `out` that holds an input of the case (a mesh its `mesh:` body
/// reads). With `force`, files of an earlier result changed since rollbem wrote them are
/// replaced too.
pub fn write_meshes(case_path: &Path, overrides: &[String], out: &Path, force: bool) -> Result<Vec<PathBuf>, Error> {
    let case = case::load(case_path, overrides)?;
    let meshes = crate::scene::registry::generated_meshes(&case)?;
    if meshes.is_empty() {
        return Err(Error::Case(case::CaseError::Invalid {
            path: case.path.clone(),
            violations: vec![case::Violation {
                key: "bodies.A.geometry, bodies.B.geometry".into(),
                message: "no body is given by `geometry:`, so rollbem generates no mesh; the meshes of \
                          `mesh:` bodies are the files the case names"
                    .into(),
            }],
        }));
    }
    let files: Vec<PathBuf> = meshes.iter().map(|(side, _)| out.join(format!("{side}.msh"))).collect();
    output::folder::write_atomically_with(out, output::folder::Kind::Mesh, write_options(&case, force), |tmp| {
        for (side, mesh) in &meshes {
            let path = tmp.join(format!("{side}.msh"));
            std::fs::write(&path, crate::mesh::write_msh41_ascii(mesh)).map_err(|e| Error::Output {
                path: path.clone(),
                message: e.to_string(),
            })?;
        }
        Ok::<(), Error>(())
    })?;
    Ok(files)
}
