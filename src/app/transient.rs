//! `rollbem run` of a case with `transient:`: the history of steps (crate::transient), then the
//! last step's usual outputs and the history's own (docs/transient.md, docs/outputs.md).

use super::RunReport;
use crate::case::transient::{NormalPlan, ShiftPlan, TangentialPlan, TransientSpec};
use crate::case::{CaseError, LoadedCase, Violation};
use crate::contact::{NormalControl, TangentialControl};
use crate::error::Error;
use crate::output::transient::{transient_summary, write_steps, write_transient_csv, write_transient_svg, StepRecord};
use crate::output::{self, folder};
use crate::post::{self, ContactSolution, Timings};
use crate::scene::Scene;
use crate::transient::{History, Step, StepSolution, TransientError};
use std::path::Path;
use std::time::Instant;

/// The controls of a history, step by step.
struct Plan {
    /// Rolling distance of a step Δ [length].
    step: f64,
    steps: usize,
    normal: NormalPlan,
    tangential: TangentialPlan,
    shift: Option<ShiftPlan>,
}

impl Plan {
    /// The plan of `spec` on `scene` (Δ: `step`, speed × `time_step`, else the node spacing).
    fn of(spec: &TransientSpec, scene: &Scene) -> Self {
        let load = &scene.case.case.load;
        let step = spec.step_length(load.speed, scene.grid.node_spacing());
        Self {
            step,
            steps: spec.steps,
            normal: crate::case::normal_plan(spec, load),
            tangential: crate::case::tangential_plan(spec, load),
            shift: spec.shift.as_ref().and_then(|s| s.plan().ok()),
        }
    }

    /// The normal control of rolling step `k` (0: the press), ending at rolled distance `s`.
    fn normal(&self, k: usize, s: f64) -> NormalControl {
        match &self.normal {
            NormalPlan::Force(f) => NormalControl::Force(f.at(k, s)),
            NormalPlan::Overlap(d) => NormalControl::Overlap(d.at(k, s)),
        }
    }

    /// The tangential control of rolling step `k` ≥ 1, ending at rolled distance `s`.
    fn tangential(&self, k: usize, s: f64) -> TangentialControl {
        match &self.tangential {
            TangentialPlan::Ratio(r) => TangentialControl::Ratio(r.at(k, s)),
            TangentialPlan::Force(q) => TangentialControl::Force(q.at(k, s)),
            TangentialPlan::Creep(x) => TangentialControl::Creep(x.at(k, s)),
        }
    }

    /// The steps of step 0 without rolling: the press (Q = 0), then the shift if any (its rigid
    /// shift is the step's ξ [length]).
    fn step_zero(&self) -> Vec<Step> {
        let press = Step {
            distance: 0.0,
            normal: self.normal(0, 0.0),
            tangential: TangentialControl::Ratio(0.0),
        };
        let shift = self.shift.map(|s| Step {
            tangential: match s {
                ShiftPlan::Ratio(r) => TangentialControl::Ratio(r),
                ShiftPlan::Force(q) => TangentialControl::Force(q),
                ShiftPlan::Displacement(d) => TangentialControl::Creep(d),
            },
            ..press
        });
        std::iter::once(press).chain(shift).collect()
    }
}

/// A step longer than the contact (2a, Hertz's estimate) carries material through it without
/// touching: refused by key.
fn check_step_length(case: &LoadedCase, plan: &Plan, scene: &Scene) -> Result<(), Error> {
    let width = 2.0 * scene.estimates.hertz_half_width;
    if plan.step > width {
        let key = if case
            .case
            .transient
            .as_ref()
            .is_some_and(|t| t.step.is_none() && t.time_step.is_some())
        {
            "transient.time_step"
        } else {
            "transient.step"
        };
        return Err(Error::Case(CaseError::Invalid {
            path: case.path.clone(),
            violations: vec![Violation {
                key: key.into(),
                message: format!(
                    "a step rolls {} but the contact is only about {width:.4e} long (2a, Hertz's estimate): give a \
                     step of a fraction of the contact, e.g. the grid's node spacing {:.4e} (the default)",
                    output::number(plan.step),
                    scene.grid.node_spacing()
                ),
            }],
        }));
    }
    Ok(())
}

/// `transient.datum_length` measures the upstream end's displacement as a half-plane's: every
/// deformable body must be one.
pub(crate) fn check_datum_bodies(case: &LoadedCase, scene: &Scene) -> Result<(), Error> {
    let others: Vec<&str> = scene
        .bodies
        .iter()
        .filter(|b| !b.idealises_as_half_plane() && b.compliance() > 0.0)
        .map(|b| b.model_name())
        .collect();
    if others.is_empty() {
        return Ok(());
    }
    Err(Error::Case(CaseError::Invalid {
        path: case.path.clone(),
        violations: vec![Violation {
            key: "transient.datum_length".into(),
            message: format!(
                "the datum length measures the displacement of a half-plane (a strip of a 3D half-space), but a \
                 body is modelled as {}, whose displacement has its own datum: remove the key, or model both \
                 bodies as half_space (or rigid)",
                others.join(" and ")
            ),
        }],
    }))
}

/// An error of the history as the run's error: the scene's own, else a message naming the case.
/// `what` names the step, if one.
fn history_error(case: &LoadedCase, what: &str, e: TransientError) -> Error {
    match e {
        TransientError::Scene(e) => e,
        other => Error::StepNotConverged {
            case: case.path.clone(),
            message: format!("{what}{other}"),
        },
    }
}

/// The steps solved, and why the history stopped early if it did.
struct Solved {
    records: Vec<StepRecord>,
    stopped: Option<String>,
}

/// The record of a step just solved by `history` (its problem is the step's own).
fn record(history: &History, step: StepSolution, iterations: usize) -> StepRecord {
    let solution = ContactSolution {
        slip_strain: None,
        ..ContactSolution::from_state(history.problem(), &step.state)
    };
    StepRecord {
        solution,
        step,
        iterations,
    }
}

/// Solves the history of `plan`: step 0 (press, shift), then the rolling steps. A rolling
/// step that does not converge stops the history; the steps before it stand.
fn solve_history(case: &LoadedCase, history: &mut History, plan: &Plan) -> Result<Solved, Error> {
    let mut iterations = 0;
    let mut last = None;
    for step in plan.step_zero() {
        let s = history
            .advance(step)
            .map_err(|e| history_error(case, "step 0 (the press and shift, without rolling): ", e))?;
        iterations += s.iterations;
        last = Some(s);
    }
    let first = last.expect("step 0 presses");
    let mut records = vec![record(history, first, iterations)];
    let every = (plan.steps / 10).max(1);
    for k in 1..=plan.steps {
        let rolled = k as f64 * plan.step;
        let step = Step {
            distance: plan.step,
            normal: plan.normal(k, rolled),
            tangential: plan.tangential(k, rolled),
        };
        match history.advance(step) {
            Ok(s) => {
                let n = s.iterations;
                records.push(record(history, s, n));
            }
            Err(e) => {
                return Ok(Solved {
                    records,
                    stopped: Some(format!("step {k}: {e}")),
                })
            }
        }
        if k % every == 0 || k == plan.steps {
            log::info!(target: crate::logging::PROGRESS, "step {k} of {}: rolled {}", plan.steps, output::number(rolled));
        }
    }
    Ok(Solved { records, stopped: None })
}

/// Runs the history of a transient case and writes its folder `output_dir` (claimed by the
/// caller): the last step's outputs as a steady run writes them, transient.csv, the steps'
/// files and summary.json with its `transient` block. A step that does not converge writes
/// the steps before it and a summary with `converged: false`.
pub(super) fn run(
    case: &LoadedCase,
    spec: &TransientSpec,
    output_dir: &Path,
    start: Instant,
) -> Result<RunReport, Error> {
    let scene = Scene::from_case(case)?;
    let plan = Plan::of(spec, &scene);
    check_step_length(case, &plan, &scene)?;
    let mut history = History::new(&scene).map_err(|e| history_error(case, "", e))?;
    if let Some(side) = spec.initial_slip {
        history.set_initial_slip(side.start());
    }
    if let Some(length) = spec.datum_length {
        check_datum_bodies(case, &scene)?;
        history.set_datum_length(Some(length));
    }
    let assembled = start.elapsed().as_secs_f64();
    let Solved { records, stopped } = solve_history(case, &mut history, &plan)?;
    let last = records.last().expect("step 0 stands");
    let mut report = history.report().cloned().expect("a step was solved");
    report.converged = stopped.is_none();
    let timings = Timings {
        assembly_s: assembled,
        solve_s: start.elapsed().as_secs_f64() - assembled,
        ..Timings::default()
    };
    let problem = history.problem().clone();
    let friction = problem.friction;
    let mut solved = post::process(scene, history.models(), problem, &last.step.state, report, timings)?;
    // The boundary-integral slip derivative is the steady one: a step's slip is its own.
    solved.solution.slip_strain = None;
    solved.friction_check = None;
    let mut summary = output::summary(&solved);
    summary.transient = Some(transient_summary(
        &records,
        plan.step,
        plan.shift.is_some(),
        friction,
        stopped,
    ));
    post::finite::check(&case.path, "summary.json", &summary)?;
    log::info!(target: crate::logging::PROGRESS, "writing the results to {}", output_dir.display());
    let speed = case.case.load.speed;
    output::write_atomically(output_dir, folder::Kind::Run, |tmp| {
        write_transient_csv(tmp, &records, &solved.problem.grid, friction, speed)?;
        write_steps(tmp, &records, &solved.problem, summary.vtk, |k, last| {
            spec.writes_step(k, last)
        })?;
        let unit = |key: &str| summary.units.get(key).map_or("", String::as_str);
        let units = [unit("overlap"), unit("max_pressure"), unit("normal_force")];
        write_transient_svg(tmp, &records, friction, &summary.title, units)?;
        output::write_run_files(tmp, &mut summary, &solved, start)
    })?;
    Ok(RunReport {
        max_iterations: solved.scene.solver.newton.max_iterations,
        tolerance: solved.scene.solver.newton.tolerance,
        summary,
        solution: solved.solution,
        problem: solved.problem,
        report: solved.report,
        output_dir: output_dir.to_path_buf(),
    })
}
