//! The cost of an error-controlled grid on BEM bodies: the wall time of a run at a tolerance
//! over the same case's run on its fixed grid, with the far-field reuse of `rollbem::bem::reuse`
//! (after) and without it (before, `set_reuse_enabled(false)`, the assembly from scratch in
//! every pass). Prints the table of docs/performance.md ("Error-controlled grids on BEM
//! bodies"). Each row's three runs (fixed, before, after) follow each other in one process, so
//! the ratios share the machine's load; times are the library's whole solve
//! (`app::solve_case`: case, scene, every pass, post-processing; nothing written), best of
//! `--repeat N` (default 1), and the BEM assembly's share of it (both bodies, every pass:
//! `timings.assembly_s`, the stage the reuse acts on). The before and after runs must give the same solution: the
//! program checks the contact pressure and shear node by node (relative 1e-10 of their peak).
//!
//! Run: `cargo run --release --example bem_refinement_cost [-- --repeat 3]`.

pub mod common;

use common::{solve, Table};
use rollbem::app::Solved;
use rollbem::bem::reuse::set_reuse_enabled;
use std::time::Instant;

/// The header of the table.
pub const HEADER: [&str; 12] = [
    "case",
    "tolerance",
    "elements",
    "fixed [s]",
    "before [s]",
    "after [s]",
    "assembly before [s]",
    "assembly after [s]",
    "before / fixed",
    "after / fixed",
    "target",
    "met",
];

/// The rows: case, tolerance, target ratio (tolerance run / fixed run).
pub const RUNS: [(&str, f64, f64); 5] = [
    ("fig14_true_geometry", 1e-4, 4.0),
    ("carter_051_true", 1e-4, 4.0),
    ("bore_a020_tractive", 1e-3, 4.0),
    ("bore_a020_braking", 1e-3, 10.0),
    ("fig14_true_geometry", 1e-5, 15.0),
];

/// The wall time of solving `name` with `overrides` [s] (best of `repeat`) and the solution.
fn timed(name: &str, overrides: &[String], repeat: usize) -> (f64, Solved) {
    let mut best = f64::INFINITY;
    let mut last = None;
    for _ in 0..repeat.max(1) {
        let t0 = Instant::now();
        let s = solve(name, overrides);
        best = best.min(t0.elapsed().as_secs_f64());
        last = Some(s);
    }
    (best, last.expect("at least one run"))
}

/// The largest difference of the nodal pressure and shear of two solutions on the same grid,
/// relative to the peak pressure.
fn difference(a: &Solved, b: &Solved) -> f64 {
    let (sa, sb) = (&a.solution, &b.solution);
    assert_eq!(sa.x.len(), sb.x.len(), "the same grid");
    let peak = sa.pressure.iter().fold(0.0f64, |m, p| m.max(p.abs()));
    let d = |u: &[f64], v: &[f64]| u.iter().zip(v).fold(0.0f64, |m, (x, y)| m.max((x - y).abs()));
    d(&sa.pressure, &sb.pressure).max(d(&sa.shear, &sb.shear)) / peak
}

/// The table: one row per entry of [`RUNS`].
pub fn table(repeat: usize) -> Table {
    let mut t = Table::new(&HEADER);
    for (name, tolerance, target) in RUNS {
        let (fixed, _) = timed(name, &[], repeat);
        let set = vec![format!("contact.grid.tolerance={tolerance:e}")];
        set_reuse_enabled(false);
        let (before, old) = timed(name, &set, repeat);
        set_reuse_enabled(true);
        let (after, new) = timed(name, &set, repeat);
        let diff = difference(&old, &new);
        assert!(
            diff <= 1e-10,
            "{name} at {tolerance:e}: the reuse changed the solution by {diff:.2e} p0"
        );
        let ratio = after / fixed;
        t.push(vec![
            name.to_string(),
            format!("{tolerance:.0e}"),
            new.problem.grid.n_elements().to_string(),
            format!("{fixed:.2}"),
            format!("{before:.2}"),
            format!("{after:.2}"),
            format!("{:.2}", old.timings.assembly_s),
            format!("{:.2}", new.timings.assembly_s),
            format!("{:.1}", before / fixed),
            format!("{ratio:.1}"),
            format!("≤ {target:.0}"),
            if ratio <= target { "yes" } else { "no" }.to_string(),
        ]);
    }
    t
}

fn main() {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let repeat = args
        .iter()
        .position(|a| a == "--repeat")
        .and_then(|i| args.get(i + 1))
        .map_or(1, |n| n.parse().expect("--repeat N: a count"));
    print!("{}", table(repeat).markdown());
}
