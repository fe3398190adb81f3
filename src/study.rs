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
use std::path::{Path, PathBuf};

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

/// Creates a temporary sibling of `dir`, lets `write` fill it, then renames it onto `dir`
/// (replacing an older result); on failure the temporary folder is removed and `dir` is left
/// as it was (DESIGN §5: nothing half-written).
pub fn write_atomically(dir: &Path, write: impl FnOnce(&Path) -> Result<(), Error>) -> Result<(), Error> {
    let err = |path: &Path, e: &dyn std::fmt::Display| Error::Output {
        path: path.to_path_buf(),
        message: e.to_string(),
    };
    let name = dir
        .file_name()
        .map_or("study".into(), |n| n.to_string_lossy().into_owned());
    let tmp: PathBuf = dir.with_file_name(format!(".{name}.partial-{}", std::process::id()));
    if let Some(parent) = tmp.parent().filter(|p| !p.as_os_str().is_empty()) {
        std::fs::create_dir_all(parent).map_err(|e| err(parent, &e))?;
    }
    if tmp.exists() {
        std::fs::remove_dir_all(&tmp).map_err(|e| err(&tmp, &e))?;
    }
    std::fs::create_dir(&tmp).map_err(|e| err(&tmp, &e))?;
    let result = write(&tmp).and_then(|()| {
        if dir.exists() {
            std::fs::remove_dir_all(dir).map_err(|e| err(dir, &e))?;
        }
        std::fs::rename(&tmp, dir).map_err(|e| err(dir, &e))
    });
    if result.is_err() {
        let _ = std::fs::remove_dir_all(&tmp);
    }
    result
}
