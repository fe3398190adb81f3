//! The cost of a sweep of Q/μP on CONTACT's Carter scene (cases/carter2d_contact.yaml): every
//! run cold and alone (scene, assembly, Newton, as a sweep ran its runs before the sequence
//! solver; nothing written, and once more with each run's files written as `rollbem run` writes
//! them) against the sweep of `rollbem sweep` (src/sweep.rs: the runs ordered by value, one
//! chain per thread on one shared assembly, each warm-started from the last; its table and
//! record written, no per-run files), and against one cold run alone. Two sweeps: 100 values
//! (0, 0.01, …, 0.99) on 100 elements and 1001 values (0 to 0.999 in steps of 0.000999)
//! on 41 elements, each on all threads and on one. Best of `--repeat N` (default 3), all
//! measured one after the other in one process, so their ratios share the machine's load.
//!
//! Run: `cargo run --release --example sweep_cost [-- --repeat 5]`. The ratios are in
//! docs/performance.md ("Sweeps").

pub mod common;

use common::{case_path, Table};
use rayon::prelude::*;
use std::path::Path;
use std::time::Instant;

/// The values of Q/μP: `n` of them from 0 in steps of `step`.
fn ratios(n: usize, step: f64) -> Vec<String> {
    (0..n)
        .map(|k| format!("{}", (k as f64 * step * 1e6).round() / 1e6))
        .collect()
}

/// Every run cold and alone, in parallel; with `files`, each written to its own folder under
/// `dir`. Returns the wall time [s] and the Newton iterations.
fn cold(case: &Path, elements: &str, values: &[String], files: Option<&Path>) -> (f64, usize) {
    let t = Instant::now();
    let iterations: usize = values
        .par_iter()
        .enumerate()
        .map(|(k, v)| {
            let set = [elements.to_string(), format!("load.tangential.ratio={v}")];
            match files {
                Some(dir) => {
                    let r = rollbem::app::run(case, &set, Some(&dir.join(format!("run_{k:04}")))).expect("run");
                    r.report.iterations
                }
                None => rollbem::app::solve_case(case, &set).expect("solves").report.iterations,
            }
        })
        .sum();
    (t.elapsed().as_secs_f64(), iterations)
}

/// The sweep as `rollbem sweep` runs it (table and record only) into `dir`. Returns the wall
/// time [s] and the Newton iterations.
fn swept(case: &Path, elements: &str, values: &[String], dir: &Path) -> (f64, usize) {
    let vary = rollbem::sweep::Vary {
        key: "load.tangential.ratio".into(),
        values: values.to_vec(),
    };
    let t = Instant::now();
    let report = rollbem::sweep::run(case, &[elements.to_string()], &[vary], None, dir, false, false).expect("sweep");
    let wall = t.elapsed().as_secs_f64();
    assert!(report.rows.iter().all(|r| r.status == "ok"), "every run converges");
    let iterations = report.rows.iter().map(|r| r.results[1].parse::<usize>().unwrap()).sum();
    (wall, iterations)
}

/// Best of `repeat` of `f`'s (time, iterations).
fn best(repeat: usize, mut f: impl FnMut() -> (f64, usize)) -> (f64, usize) {
    (0..repeat)
        .map(|_| f())
        .fold((f64::INFINITY, 0), |b, r| if r.0 < b.0 { r } else { b })
}

fn main() {
    let args: Vec<String> = std::env::args().collect();
    let repeat = args
        .iter()
        .position(|a| a == "--repeat")
        .and_then(|i| args.get(i + 1))
        .and_then(|v| v.parse().ok())
        .unwrap_or(3);
    let case = case_path("carter2d_contact");
    let tmp = tempfile::tempdir().expect("a temporary folder");
    let mut table = Table::new(&[
        "sweep",
        "threads",
        "one cold run [s]",
        "cold runs, files [s]",
        "cold runs [s]",
        "shared + warm [s]",
        "cold / shared",
        "shared / one run",
        "iterations a run cold / warm",
    ]);
    let one = rayon::ThreadPoolBuilder::new().num_threads(1).build().expect("a pool");
    for (n, step, elements) in [(100, 0.01, 100), (1001, 0.000999, 41)] {
        let values = ratios(n, step);
        let el = format!("contact.grid.elements={elements}");
        for threads in [rayon::current_num_threads(), 1] {
            let run = || {
                let single = best(repeat, || cold(&case, &el, &values[40..41], None));
                let files = if n <= 100 {
                    let dir = tmp.path().join(format!("files_{n}_{threads}"));
                    Some(best(1, || cold(&case, &el, &values, Some(&dir))))
                } else {
                    None
                };
                let c = best(repeat, || cold(&case, &el, &values, None));
                let mut k = 0;
                let s = best(repeat, || {
                    k += 1;
                    swept(
                        &case,
                        &el,
                        &values,
                        &tmp.path().join(format!("sweep_{n}_{threads}_{k}")),
                    )
                });
                (single, files, c, s)
            };
            let (single, files, c, s) = if threads == 1 { one.install(run) } else { run() };
            table.push(vec![
                format!("{n} values, {elements} elements"),
                threads.to_string(),
                format!("{:.4}", single.0),
                files.map_or("—".into(), |f| format!("{:.3}", f.0)),
                format!("{:.3}", c.0),
                format!("{:.3}", s.0),
                format!("{:.1}", c.0 / s.0),
                format!("{:.1}", s.0 / single.0),
                format!("{:.2} / {:.2}", c.1 as f64 / n as f64, s.1 as f64 / n as f64),
            ]);
        }
    }
    print!("{}", table.markdown());
}
