//! One run of a sweep as a row of its table: the columns, a run done on its own (the case
//! loaded, solved and, when asked, written to its folder) and a row made from a run's summary.

use crate::app;
use crate::output::Summary;
use std::path::Path;

/// Summary columns of sweep.csv after `run`, `folder`, `status`, the varied keys and `message`.
pub const RESULT_COLUMNS: [&str; 22] = [
    "converged",
    "iterations",
    "residual",
    "normal_force",
    "tangential_force",
    "load_ratio",
    "overlap",
    "creep",
    "contact_x_min",
    "contact_x_max",
    "contact_centre",
    "half_width",
    "max_pressure",
    "slip_regime",
    "stick_zones",
    "slip_zones",
    "pressure_centre",
    "rolling_resistance",
    "assembly_s",
    "condense_s",
    "solve_s",
    "total_s",
];

/// Columns that hold wall-clock times (differ between otherwise identical sweeps).
pub const TIMING_COLUMNS: [&str; 4] = ["assembly_s", "condense_s", "solve_s", "total_s"];

/// Outcome of one run as a sweep.csv row.
#[derive(Debug, Clone)]
pub struct RunRow {
    /// Run number in the full product.
    pub run: usize,
    /// Sub-folder name.
    pub folder: String,
    /// `ok`, `not_converged` or `failed`.
    pub status: String,
    /// Varied values, in `--vary` order.
    pub values: Vec<String>,
    /// Error message of a failed run (empty otherwise).
    pub message: String,
    /// Values of [`RESULT_COLUMNS`] (empty strings for a failed run).
    pub results: Vec<String>,
    /// Whether the run folder has a contact.vtu.
    pub has_vtk: bool,
    /// Whether the run failed on an internal error (a caught panic: a bug, not bad input).
    pub internal_error: bool,
}

impl RunRow {
    /// The CSV record: `run, folder, status`, the values, `message`, the results.
    pub(super) fn record(&self) -> Vec<String> {
        let mut rec = vec![self.run.to_string(), self.folder.clone(), self.status.clone()];
        rec.extend(self.values.iter().cloned());
        rec.push(self.message.clone());
        rec.extend(self.results.iter().cloned());
        rec
    }
}

/// Runs `point` (one run of the sweep) with a panic in it caught and recorded as an internal
/// error of that run (the others go on).
pub(super) fn guarded(run: usize, overrides: &[(String, String)], point: impl FnOnce() -> RunRow) -> RunRow {
    let outcome = std::panic::catch_unwind(std::panic::AssertUnwindSafe(point));
    outcome.unwrap_or_else(|payload| {
        let what = payload
            .downcast_ref::<&str>()
            .map(|s| s.to_string())
            .or_else(|| payload.downcast_ref::<String>().cloned())
            .unwrap_or_else(|| "panic".into());
        RunRow {
            internal_error: true,
            ..failed_row(
                run,
                run_folder(run),
                overrides,
                format!("internal error — please report it: {what}"),
            )
        }
    })
}

/// Name of the folder of run `run`.
pub fn run_folder(run: usize) -> String {
    format!("run_{run:04}")
}

/// The row of a run that failed with `message`.
pub(super) fn failed_row(run: usize, folder: String, overrides: &[(String, String)], message: String) -> RunRow {
    RunRow {
        run,
        folder,
        status: "failed".into(),
        values: overrides.iter().map(|(_, v)| v.clone()).collect(),
        message: message.replace('\n', " "),
        results: vec![String::new(); RESULT_COLUMNS.len()],
        has_vtk: false,
        internal_error: false,
    }
}

/// Runs one point of the sweep on its own (its scene built and assembled for it): with
/// `per_run_files` into `out/run_NNNN` as `rollbem run` would, else in memory (the row's folder
/// empty).
pub(super) fn run_alone(
    case: &Path,
    base_set: &[String],
    out: &Path,
    per_run_files: bool,
    run: usize,
    overrides: &[(String, String)],
) -> RunRow {
    let mut set = base_set.to_vec();
    set.extend(overrides.iter().map(|(k, v)| format!("{k}={v}")));
    let folder = if per_run_files { run_folder(run) } else { String::new() };
    let summary = if per_run_files {
        app::run(case, &set, Some(&out.join(&folder))).map(|report| report.summary)
    } else {
        app::solve_case(case, &set).and_then(|solved| app::checked_summary(&solved))
    };
    match summary {
        Ok(s) => row_of_summary(run, folder, overrides, &s),
        Err(e) => failed_row(run, folder, overrides, e.to_string()),
    }
}

/// The row of a run from its summary (run `run`, folder `folder`, empty when the run wrote no
/// files).
pub(super) fn row_of_summary(run: usize, folder: String, overrides: &[(String, String)], s: &Summary) -> RunRow {
    let c = s.contact.as_ref();
    let r = s.rolling_resistance.as_ref();
    let f = crate::output::number;
    RunRow {
        run,
        status: if s.converged { "ok" } else { "not_converged" }.into(),
        values: overrides.iter().map(|(_, v)| v.clone()).collect(),
        message: String::new(),
        results: vec![
            s.converged.to_string(),
            s.iterations.to_string(),
            f(s.residual),
            f(s.normal_force),
            f(s.tangential_force),
            s.load_ratio.map_or(String::new(), f),
            f(s.overlap),
            f(s.creep),
            c.map_or(String::new(), |c| f(c.x_min)),
            c.map_or(String::new(), |c| f(c.x_max)),
            c.map_or(String::new(), |c| f(c.centre)),
            c.map_or(String::new(), |c| f(c.half_width)),
            f(s.max_pressure),
            s.slip_regime.to_string(),
            s.stick_zones.len().to_string(),
            s.slip_zones.len().to_string(),
            r.map_or(String::new(), |r| f(r.pressure_centre)),
            r.map_or(String::new(), |r| f(r.coefficient)),
            f(s.timings.assembly_s),
            f(s.timings.condense_s),
            f(s.timings.solve_s),
            f(s.timings.total_s),
        ],
        has_vtk: !folder.is_empty() && s.converged && s.vtk,
        folder,
        internal_error: false,
    }
}
