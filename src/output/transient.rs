//! The files of a transient history (docs/outputs.md, "A transient run"): transient.csv (one
//! row a step), steps/step_NNNN.csv (each step's contact.csv), steps/step_NNNN.vtu and
//! transient.pvd (the ParaView time series over the rolled distance), transient.svg (the
//! tractions at a few steps, Q and ξ against the rolled distance) and the `transient` block of
//! summary.json.

use super::charts::transient::{profiled_steps, Profile, TransientPicture};
use super::csv_files::{number, write_csv};
use super::units::Dimension::{self, *};
use super::vtk;
use crate::contact::ContactProblem;
use crate::error::Error;
use crate::grid::ContactGrid;
use crate::post::{ContactSolution, NodeState};
use crate::transient::StepSolution;
use serde::Serialize;
use std::path::Path;

/// Largest change of the tractions over the last step, over μp_max, below which a history is
/// called steady (summary.json `transient.steady`).
pub const STEADY_TOLERANCE: f64 = 1e-6;

/// Distance of the tractions from the last step's, over μp_max, within which a history has
/// settled (summary.json `transient.settled_distance`).
pub const SETTLED_TOLERANCE: f64 = 1e-3;

/// Columns of transient.csv and what each measures (`time` needs `load.speed`).
pub const TRANSIENT_CSV_UNITS: [(&str, Dimension); 24] = [
    ("step", Count),
    ("distance", Length),
    ("rolled", Length),
    ("time", Time),
    ("normal_force", ForcePerLength),
    ("tangential_force", ForcePerLength),
    ("load_ratio", Dimensionless),
    ("overlap", Length),
    ("creep", Dimensionless),
    ("shift", Length),
    ("contact_x_min", Length),
    ("contact_x_max", Length),
    ("stick_x_min", Length),
    ("stick_x_max", Length),
    ("stick_fraction", Dimensionless),
    ("max_pressure", Stress),
    ("max_shear", Stress),
    ("iterations", Count),
    ("dissipation", EnergyPerLength),
    ("shift_work", EnergyPerLength),
    ("normal_work", EnergyPerLength),
    ("closing", EnergyPerLength),
    ("stored_change", EnergyPerLength),
    ("tangential_stored_change", EnergyPerLength),
];

/// One step of a history as the outputs need it: the solver's step and its user-facing
/// solution (built on the problem of that step, whose slip term is the step's own).
#[derive(Debug, Clone)]
pub struct StepRecord {
    /// The step and its state.
    pub step: StepSolution,
    /// Its tractions, gap, slip and zones.
    pub solution: ContactSolution,
    /// Newton iterations of the step (step 0: the press and the shift together).
    pub iterations: usize,
}

/// The `transient` block of summary.json (docs/outputs.md).
#[derive(Debug, Clone, Serialize)]
pub struct TransientSummary {
    /// Rolling steps solved (after step 0).
    pub steps: usize,
    /// Rolling distance of a step Δ [length].
    pub step: f64,
    /// Distance rolled at the end of the last step [length].
    pub rolled: f64,
    /// Step 0's rigid shift of A relative to B along +x [length] (null without `transient.shift`).
    pub shift: Option<f64>,
    /// Newton iterations of all steps.
    pub iterations: usize,
    /// Newton iterations a rolling step, on average.
    pub mean_iterations: f64,
    /// The largest change of p and q over the last step, over μp_max (over p_max when μ = 0).
    pub change: f64,
    /// Whether `change` is below [`STEADY_TOLERANCE`].
    pub steady: bool,
    /// The rolled distance from which every step's p and q lie within [`SETTLED_TOLERANCE`]
    /// μp_max of the last step's [length].
    pub settled_distance: Option<f64>,
    /// Why the history stopped early (a step that did not converge), null when it ran to the end.
    pub stopped: Option<String>,
}

/// The traction scale μp_max of a step (p_max when μ = 0) [stress].
fn traction_scale(s: &ContactSolution, friction: f64) -> f64 {
    let pmax = s.pressure.iter().fold(0.0_f64, |a, &b| a.max(b));
    if friction > 0.0 {
        friction * pmax
    } else {
        pmax
    }
}

/// The largest difference of two steps' p and q [stress].
fn traction_difference(a: &ContactSolution, b: &ContactSolution) -> f64 {
    let d = |u: &[f64], v: &[f64]| u.iter().zip(v).map(|(x, y)| (x - y).abs()).fold(0.0, f64::max);
    d(&a.pressure, &b.pressure).max(d(&a.shear, &b.shear))
}

/// The summary of a history of `records` (step 0 first, `shifted` when it shifts) with rolling
/// step `step` [length].
pub fn transient_summary(
    records: &[StepRecord],
    step: f64,
    shifted: bool,
    friction: f64,
    stopped: Option<String>,
) -> TransientSummary {
    let last = &records[records.len() - 1];
    let scale = traction_scale(&last.solution, friction).max(f64::MIN_POSITIVE);
    let change = match records.len() {
        1 => 0.0,
        n => traction_difference(&records[n - 2].solution, &last.solution) / scale,
    };
    let settled = records
        .iter()
        .rposition(|r| traction_difference(&r.solution, &last.solution) / scale >= SETTLED_TOLERANCE)
        .map_or(Some(0), |k| (k + 1 < records.len()).then_some(k + 1))
        .map(|k| records[k].step.rolled);
    let rolling = records.len() - 1;
    let iterations: usize = records.iter().map(|r| r.iterations).sum();
    TransientSummary {
        steps: rolling,
        step,
        rolled: last.step.rolled,
        shift: shifted.then_some(records[0].step.state.creep),
        iterations,
        mean_iterations: if rolling > 0 {
            (iterations - records[0].iterations) as f64 / rolling as f64
        } else {
            0.0
        },
        change,
        steady: rolling > 0 && change < STEADY_TOLERANCE,
        settled_distance: settled,
        stopped,
    }
}

/// A number, or an empty cell for none (no NaN is ever written).
fn cell(v: Option<f64>) -> String {
    v.filter(|v| v.is_finite()).map_or(String::new(), number)
}

/// The row of transient.csv of step `k`.
fn row(k: usize, r: &StepRecord, grid: &ContactGrid, friction: f64, speed: Option<f64>) -> Vec<String> {
    let s = &r.solution;
    let rolling = r.step.step.distance > 0.0;
    // The stick zones' ends as summary.json gives them: midway between nodes of different
    // state, at the contact's extrapolated edge where a zone reaches it.
    let stick = s.zones_of(NodeState::Stick);
    let stuck = s.state.iter().filter(|&&st| st == NodeState::Stick).count();
    let touching = s.state.iter().filter(|&&st| st != NodeState::Open).count();
    let extent = s.contact_extent();
    let ratio = (friction > 0.0 && s.normal_force > 0.0).then(|| s.tangential_force / (friction * s.normal_force));
    vec![
        k.to_string(),
        number(r.step.step.distance),
        number(r.step.rolled),
        cell(speed.map(|v| r.step.rolled / v)),
        number(s.normal_force),
        number(s.tangential_force),
        cell(ratio),
        number(s.overlap),
        cell(rolling.then_some(s.creep)),
        cell((!rolling).then_some(s.creep)),
        cell(extent.map(|e| e[0])),
        cell(extent.map(|e| e[1])),
        cell(stick.first().map(|z| z[0])),
        cell(stick.last().map(|z| z[1])),
        cell((touching > 0).then(|| stuck as f64 / touching as f64)),
        number(grid.interpolant_max(&s.pressure).max(0.0)),
        number(s.shear.iter().fold(0.0, |a, &b| a.max(b.abs()))),
        r.iterations.to_string(),
        cell(Some(r.step.energy.dissipation)),
        cell(Some(r.step.energy.work)),
        cell(Some(r.step.energy.normal_work)),
        cell(Some(r.step.energy.closing)),
        cell(Some(r.step.energy.stored_change)),
        cell(Some(r.step.energy.tangential_stored_change)),
    ]
}

/// Writes transient.csv into `dir`: one row a step ([`TRANSIENT_CSV_UNITS`]), each step's peak
/// pressure the largest value of its interpolant on `grid` (as summary.json's `max_pressure`).
pub fn write_transient_csv(
    dir: &Path,
    records: &[StepRecord],
    grid: &ContactGrid,
    friction: f64,
    speed: Option<f64>,
) -> Result<(), Error> {
    let path = dir.join("transient.csv");
    let io = |e: &dyn std::fmt::Display| Error::Output {
        path: path.clone(),
        message: e.to_string(),
    };
    let mut w = csv::Writer::from_path(&path).map_err(|e| io(&e))?;
    w.write_record(TRANSIENT_CSV_UNITS.map(|c| c.0)).map_err(|e| io(&e))?;
    for (k, r) in records.iter().enumerate() {
        w.write_record(row(k, r, grid, friction, speed)).map_err(|e| io(&e))?;
    }
    w.flush().map_err(|e| io(&e))
}

/// Writes the contact.csv of each step `written` picks (by its number and the last step's) as
/// steps/step_NNNN.csv and, with `vtk`, its contact line as steps/step_NNNN.vtu and the ParaView
/// series transient.pvd over them (time = the rolled distance).
pub fn write_steps(
    dir: &Path,
    records: &[StepRecord],
    pb: &ContactProblem,
    vtk: bool,
    written: impl Fn(usize, usize) -> bool,
) -> Result<(), Error> {
    let folder = dir.join("steps");
    std::fs::create_dir(&folder).map_err(|e| Error::Output {
        path: folder.clone(),
        message: e.to_string(),
    })?;
    let mut entries = Vec::new();
    let last = records.len().saturating_sub(1);
    for (k, r) in records.iter().enumerate().filter(|(k, _)| written(*k, last)) {
        write_csv(&folder.join(step_file(k, "csv")), &r.solution, pb)?;
        if vtk {
            vtk::write_contact_line(&folder.join(step_file(k, "vtu")), &r.solution, pb)?;
            entries.push(vtk::CollectionEntry {
                file: format!("steps/{}", step_file(k, "vtu")),
                timestep: r.step.rolled,
                part: 0,
                name: "contact".into(),
            });
        }
    }
    if vtk {
        vtk::write_collection(&dir.join("transient.pvd"), &entries)?;
    }
    Ok(())
}

/// `step_NNNN.EXT`: four digits at least, so that the names sort in step order.
pub fn step_file(k: usize, ext: &str) -> String {
    format!("step_{k:04}.{ext}")
}

/// Writes transient.svg into `dir` ([`super::charts::transient`]): x is scaled by half the last
/// step's contact length, the force axis is Q/(μP) when μ > 0 (Q otherwise); `units` are the
/// case's length, stress and force-per-length units.
pub fn write_transient_svg(
    dir: &Path,
    records: &[StepRecord],
    friction: f64,
    title: &str,
    units: [&str; 3],
) -> Result<(), Error> {
    let last = &records[records.len() - 1].solution;
    let a = last
        .contact_extent()
        .map(|[x0, x1]| 0.5 * (x1 - x0))
        .filter(|a| *a > 0.0)
        .unwrap_or(1.0);
    let profiles = profiled_steps(records.len())
        .into_iter()
        .map(|k| {
            let s = &records[k].solution;
            Profile {
                step: k,
                rolled: number(records[k].step.rolled),
                x: s.x.iter().map(|x| x / a).collect(),
                pressure: s.pressure.clone(),
                shear: s.shear.clone(),
            }
        })
        .collect();
    let ratio = |s: &ContactSolution| {
        if friction > 0.0 && s.normal_force > 0.0 {
            s.tangential_force / (friction * s.normal_force)
        } else {
            s.tangential_force
        }
    };
    let picture = TransientPicture {
        title: title.to_string(),
        half_width: a,
        units: [units[0].to_string(), units[1].to_string()],
        force_label: if friction > 0.0 {
            "Q/μP [-]".into()
        } else {
            format!("Q [{}]", units[2])
        },
        profiles,
        force: records.iter().map(|r| (r.step.rolled, ratio(&r.solution))).collect(),
        creep: records
            .iter()
            .filter(|r| r.step.step.distance > 0.0)
            .map(|r| (r.step.rolled, r.solution.creep))
            .collect(),
    };
    super::charts::transient::write(&dir.join("transient.svg"), &picture)
}
