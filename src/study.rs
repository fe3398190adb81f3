//! Studies: many solves of one scene, in parallel, with a progress bar, summarised in a CSV and
//! SVG charts written atomically.
//!
//! This module holds the parallel runner every study uses; each study is a submodule that
//! builds its jobs, solves them through [`crate::app`] and reads the results:
//!
//! * [`accuracy`] — `rollbem study accuracy`: each body model the scene allows at a ladder of
//!   discretizations, its error against the reference and its wall time (accuracy.csv/.svg).
//! * [`stability`] — `rollbem study stability`: where each solution method converges.
//! * [`shakedown`] — `rollbem study shakedown`: Johnson's shakedown map with the case's points.

pub mod accuracy;
pub mod shakedown;
pub mod stability;

use indicatif::{ProgressBar, ProgressStyle};
use rayon::prelude::*;

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
