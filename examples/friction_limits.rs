//! Newton steps of the default method at the friction limits: the ladder of
//! docs/performance.md ("Solver cost at the friction limits").
//!
//! For each element count and friction coefficient it solves free rolling of aluminium on steel
//! (cases/free_rolling_al_steel.yaml, Q = 0: complete slip as μ → 0, Bufler's no-slip limit as
//! μ → ∞) and Carter's case (cases/carter_051.yaml, Q/μP = 0.51), and prints per run the Newton
//! steps (every step of every attempt, NORM steps included), the restarts used, the creepage and
//! the solve time. Iteration counts are the same on any machine; the times are not. The first
//! table (41 and 81 elements) is compared with the page by the `docs` test; the second (161 to
//! 481 elements, several minutes) only by running this program.
//!
//! Run: `cargo run --release --example friction_limits`.

pub mod common;

use common::{solve, Table};

/// The friction coefficients of the ladder.
pub const FRICTIONS: [&str; 9] = ["1e-4", "3e-4", "1e-3", "1e-2", "0.1", "1", "10", "50", "1e3"];

/// The two cases of the ladder.
pub const CASES: [&str; 2] = ["free_rolling_al_steel", "carter_051"];

/// The ladder on `grids` (element counts); `first` is the header's first cell, which tells the
/// page's two tables apart.
pub fn table(first: &str, grids: &[usize]) -> Table {
    let mut t = Table::new(&[
        first,
        "elements",
        "μ",
        "Newton steps",
        "restarts",
        "creepage ξ",
        "solve [s]",
    ]);
    for name in CASES {
        for &n in grids {
            for mu in FRICTIONS {
                let s = solve(
                    name,
                    &[format!("contact.friction={mu}"), format!("contact.grid.elements={n}")],
                );
                let restarts = if s.report.fallbacks.is_empty() {
                    "–".to_string()
                } else {
                    s.report.fallbacks.join(", ")
                };
                t.push(vec![
                    name.to_string(),
                    n.to_string(),
                    mu.to_string(),
                    s.report.iterations.to_string(),
                    restarts,
                    format!("{:.6e}", s.solution.creep),
                    format!("{:.2}", s.timings.solve_s),
                ]);
            }
        }
    }
    t
}

fn main() {
    print!("{}", table("case", &[41, 81]).markdown());
    println!();
    print!("{}", table("case (larger grids)", &[161, 321, 481]).markdown());
}
