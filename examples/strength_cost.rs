//! What a strength assessment (`output.strength`) costs: the wall time of a run with it
//! against the same run without it, on a 100-element contact with a 200 × 100 interior grid
//! (the half-space Carter scene and the BEM rollers of fig14_true_geometry), median of 5.
//! docs/performance.md records the ratios.
//!
//! Run: cargo run --release --example strength_cost

mod common;

use common::case_path;
use std::time::Instant;

/// Median wall time [s] of `reps` solves of `case` with `overrides`.
fn median_time(case: &str, overrides: &[&str], reps: usize) -> f64 {
    let mut t: Vec<f64> = (0..reps)
        .map(|_| {
            let t0 = Instant::now();
            let s = rollbem::app::solve_case(&case_path(case), overrides).expect("solves");
            assert!(s.report.converged);
            t0.elapsed().as_secs_f64()
        })
        .collect();
    t.sort_by(f64::total_cmp);
    t[reps / 2]
}

fn main() {
    println!("| case | without strength [s] | with strength [s] | ratio |");
    println!("|---|---|---|---|");
    for case in ["carter_051", "fig14_true_geometry"] {
        let base = ["contact.grid.elements=100", "output.interior=null"];
        let mut without = base.to_vec();
        without.push("output.strength=null");
        let mut with = base.to_vec();
        with.push("output.strength.grid=[200, 100]");
        let (a, b) = (median_time(case, &without, 5), median_time(case, &with, 5));
        println!("| {case} | {a:.4} | {b:.4} | {:.1} |", b / a);
    }
}
