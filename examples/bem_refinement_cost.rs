//! The cost of an error-controlled grid on BEM bodies: the wall time of a run at a tolerance
//! over the same case's run on its fixed grid, with every pass on the full BEM (before: the
//! far field reused, `rollbem::bem::reuse`, the contact cut and condensed in every pass;
//! `contact.grid.stand_ins=false`) and with the passes on the BEM's stand-ins (after:
//! `rollbem::body::bem::stand_in`, the full BEM on the final grid only). Prints the table of
//! docs/performance.md ("Error-controlled grids on BEM bodies"). Each row's three runs (fixed,
//! before, after) follow each other in one process, so the ratios share the machine's load;
//! times are the library's whole solve (`app::solve_case`: case, scene, every pass,
//! post-processing; nothing written), best of `--repeat N` (default 1; the fixed run at least
//! five times). Both error-controlled
//! runs must meet the tolerance, and their creepages agree within it (they end on different
//! grids; each solution is the full BEM's on its own final grid).
//!
//! Run: `cargo run --release --example bem_refinement_cost [-- --repeat 3] [--after-only]`
//! (`--after-only` skips the "before" runs, which take most of the time: their cells print as
//! "-" and the creepages are not compared).

pub mod common;

use common::{solve, Table};
use rollbem::app::Solved;
use std::time::Instant;

/// The header of the table.
pub const HEADER: [&str; 11] = [
    "case",
    "tolerance",
    "elements before",
    "elements after",
    "fixed [s]",
    "before [s]",
    "after [s]",
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

/// Fewest runs of the fixed grid whose best time is taken.
const FIXED_REPEAT: usize = 5;

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

/// The relative difference of the creepages of two solutions.
fn creep_difference(a: &Solved, b: &Solved) -> f64 {
    let (xa, xb) = (a.solution.creep, b.solution.creep);
    (xa - xb).abs() / xa.abs().max(xb.abs())
}

/// The table: one row per entry of [`RUNS`].
pub fn table(repeat: usize) -> Table {
    table_of(repeat, true)
}

/// [`table`], with the "before" runs or without them (their cells "-").
pub fn table_of(repeat: usize, with_before: bool) -> Table {
    let mut t = Table::new(&HEADER);
    for (name, tolerance, target) in RUNS {
        // The fixed run, the ratios' denominator, is short and the most exposed to the load
        // of the moment: best of at least five.
        let (fixed, _) = timed(name, &[], repeat.max(FIXED_REPEAT));
        let set = vec![format!("contact.grid.tolerance={tolerance:e}")];
        let old = with_before.then(|| {
            let full_bem = [set.clone(), vec!["contact.grid.stand_ins=false".to_string()]].concat();
            timed(name, &full_bem, repeat)
        });
        let (after, new) = timed(name, &set, repeat);
        for run in old.iter().map(|(_, s)| s).chain([&new]) {
            let e = run.adaptation.as_ref().and_then(|a| a.estimate).expect("an estimate");
            assert!(e.within(tolerance), "{name} at {tolerance:e}: estimate {e:?}");
        }
        if let Some((_, old)) = &old {
            let diff = creep_difference(old, &new);
            assert!(
                diff <= 2.0 * tolerance,
                "{name} at {tolerance:e}: the creepages differ by {diff:.2e}"
            );
        }
        let ratio = after / fixed;
        let dash = || "-".to_string();
        t.push(vec![
            name.to_string(),
            format!("{tolerance:.0e}"),
            old.as_ref()
                .map_or_else(dash, |(_, s)| s.problem.grid.n_elements().to_string()),
            new.problem.grid.n_elements().to_string(),
            format!("{fixed:.2}"),
            old.as_ref().map_or_else(dash, |(b, _)| format!("{b:.2}")),
            format!("{after:.2}"),
            old.as_ref().map_or_else(dash, |(b, _)| format!("{:.1}", b / fixed)),
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
    let with_before = !args.iter().any(|a| a == "--after-only");
    print!("{}", table_of(repeat, with_before).markdown());
}
