//! Studies: many solves of one scene, in parallel, with a progress bar, summarised in a CSV and
//! SVG charts written atomically (issue 6).
//!
//! This module holds what every study needs (the parallel runner, one solve of an overridden
//! case, the atomic output folder); each study is a submodule that builds its jobs and reads
//! the results:
//!
//! * [`accuracy`] — `rollbem study accuracy`: each body model the scene allows at a ladder of
//!   discretizations, its error against the reference and its wall time (accuracy.csv/.svg).
//! * [`stability`] — `rollbem study stability`: where each solution method converges.

pub mod accuracy;
pub mod heatmap;
pub mod stability;

use crate::app::{self, Solved};
use crate::case::{self, LoadedCase};
use crate::error::Error;
use indicatif::{ProgressBar, ProgressStyle};
use rayon::prelude::*;
use std::path::Path;

/// Runs `f` on every job in parallel (rayon, in the current thread pool) with a progress bar on
/// stderr when `progress` (indicatif hides it when stderr is not a terminal); results in job
/// order.
pub fn run_parallel<J: Sync, T: Send>(jobs: &[J], unit: &str, progress: bool, f: impl Fn(&J) -> T + Sync) -> Vec<T> {
    let bar = if progress {
        ProgressBar::new(jobs.len() as u64)
    } else {
        ProgressBar::hidden()
    };
    let template = format!("{{spinner}} [{{elapsed_precise}}] {{bar:40}} {{pos}}/{{len}} {unit}, eta {{eta}}");
    bar.set_style(ProgressStyle::with_template(&template).unwrap_or_else(|_| ProgressStyle::default_bar()));
    let out = jobs
        .par_iter()
        .map(|job| {
            let result = f(job);
            bar.inc(1);
            result
        })
        .collect();
    bar.finish_and_clear();
    out
}

/// Loads `case_path` with the base overrides followed by `overrides` and solves it (nothing is
/// written). Input errors (a value out of range, an unknown key) come back as `Err`.
pub fn solve_overridden(
    case_path: &Path,
    base_set: &[String],
    overrides: &[String],
) -> Result<(LoadedCase, Solved), Error> {
    let mut set = base_set.to_vec();
    set.extend(overrides.iter().cloned());
    let case = case::load(case_path, &set)?;
    let solved = app::solve(&case)?;
    Ok((case, solved))
}
