//! Speed against accuracy on CONTACT's carter2d problem (cases/carter2d_contact.yaml):
//! per-size iterations, per-iteration cost, time split, whole-process wall time of the
//! `rollbem run` binary (best of 5), RMS shear error against Carter (μp0) and creepage error.
//! The `docs` test compares the columns that are not times with docs/performance.md.
//!
//! Run: `cargo build --release && cargo run --release --example perf_report`.

pub mod common;

use common::{case_path, root, solve, Table};
use rollbem::app::Solved;
use rollbem::post::norms::nodal_error_against;
use std::process::Command;
use std::time::Instant;

/// The header of the table; the columns with a unit of time are measured, the others are
/// the same on any machine.
pub const HEADER: [&str; 11] = [
    "elements",
    "nodes",
    "iterations",
    "largest system",
    "assembly [ms]",
    "solve [ms]",
    "per iteration [ms]",
    "whole process [s]",
    "RMS q error (μp0)",
    "creep error",
    "CONTACT creep error 0.24Δx/a",
];

/// The grids of the table.
pub const ELEMENTS: [usize; 5] = [21, 41, 81, 161, 321];

/// The overrides of one grid.
fn overrides(n: usize, derivative: &str) -> Vec<String> {
    vec![
        format!("contact.grid.elements={n}"),
        format!("contact.slip_derivative={derivative}"),
    ]
}

/// One row; `process_s` is the whole-process time (None: not measured, written `-`).
pub fn row(n: usize, s: &Solved, process_s: Option<f64>) -> Vec<String> {
    let c = s.scene.carter_reference().expect("carter2d prescribes Q/μP");
    let mu_p0 = c.friction * c.peak_pressure;
    let rms = nodal_error_against(&s.solution.x, &s.solution.shear, |x| c.shear(x), c.half_width, mu_p0).rms;
    let xi = c.creep(s.scene.estimates.effective_radius);
    let largest = s.report.history.iter().map(|h| h.system_size).max().unwrap_or(0);
    vec![
        n.to_string(),
        s.problem.n_nodes().to_string(),
        s.report.iterations.to_string(),
        largest.to_string(),
        format!("{:.1}", 1e3 * s.timings.assembly_s),
        format!("{:.1}", 1e3 * s.timings.solve_s),
        format!("{:.2}", 1e3 * s.timings.solve_s / s.report.iterations as f64),
        process_s.map_or("-".into(), |t| format!("{t:.3}")),
        format!("{rms:.2e}"),
        format!("{:+.2e}", s.solution.creep / xi - 1.0),
        format!("{:.2e}", 0.24 * s.problem.grid.element_length() / c.half_width),
    ]
}

/// The solve of one grid (second-order slip derivative unless `derivative` says otherwise).
pub fn solve_grid(n: usize, derivative: &str) -> Solved {
    solve("carter2d_contact", &overrides(n, derivative))
}

/// Best of 5 wall times of `rollbem run` on one grid [s].
fn process_time(n: usize, derivative: &str) -> f64 {
    let exe = root().join("target/release/rollbem");
    let out = std::env::temp_dir().join("rollbem_perf");
    let mut args = vec![
        "run".to_string(),
        case_path("carter2d_contact").to_string_lossy().into_owned(),
        "--out".into(),
        out.to_string_lossy().into_owned(),
    ];
    for v in overrides(n, derivative) {
        args.push("--set".into());
        args.push(v);
    }
    let mut best = f64::INFINITY;
    for _ in 0..5 {
        let t = Instant::now();
        let status = Command::new(&exe)
            .args(&args)
            .output()
            .expect("run the release binary (cargo build --release first)");
        assert!(status.status.success());
        best = best.min(t.elapsed().as_secs_f64());
    }
    best
}

fn main() {
    let derivative = std::env::args().nth(1).unwrap_or_else(|| "second_order".into());
    let mut t = Table::new(&HEADER);
    for n in ELEMENTS {
        let s = solve_grid(n, &derivative);
        t.push(row(n, &s, Some(process_time(n, &derivative))));
    }
    print!("{}", t.markdown());
}
