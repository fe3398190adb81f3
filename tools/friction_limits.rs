//! Newton steps of the default method at the friction limits: the ladder of
//! docs/performance.md ("Solver cost at the friction limits").
//!
//! ```sh
//! cargo run --release --example friction_limits                 # 41 … 481 elements (minutes)
//! cargo run --release --example friction_limits -- 41 81 161    # chosen element counts
//! ```
//!
//! For each element count and friction coefficient it solves free rolling of aluminium on steel
//! (cases/free_rolling_al_steel.yaml, Q = 0: complete slip as μ → 0, Bufler's no-slip limit as
//! μ → ∞) and Carter's case (cases/carter_051.yaml, Q/μP = 0.51), and prints one Markdown row
//! per run: Newton steps (every step of every attempt, NORM steps included), the restarts used,
//! the creepage and the solve time. Iteration counts are machine independent; the times are not.

use rollbem::{app, case};
use std::path::Path;

const FRICTIONS: [&str; 9] = ["1e-4", "3e-4", "1e-3", "1e-2", "0.1", "1", "10", "50", "1e3"];

fn main() {
    let args: Vec<usize> = std::env::args().skip(1).filter_map(|a| a.parse().ok()).collect();
    let elements = if args.is_empty() {
        vec![41, 81, 161, 321, 481]
    } else {
        args
    };
    let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("cases");
    println!("| case | elements | μ | Newton steps | restarts | creepage ξ | solve [s] |");
    println!("|---|---|---|---|---|---|---|");
    for name in ["free_rolling_al_steel", "carter_051"] {
        for &n in &elements {
            for mu in FRICTIONS {
                let set = vec![format!("contact.friction={mu}"), format!("contact.grid.elements={n}")];
                let solved = case::load(&root.join(format!("{name}.yaml")), &set)
                    .map_err(|e| e.to_string())
                    .and_then(|c| app::solve(&c).map_err(|e| e.to_string()));
                let row = match solved {
                    Ok(s) => format!(
                        "| {name} | {n} | {mu} | {}{} | {} | {:.10e} | {:.2} |",
                        s.report.iterations,
                        if s.report.converged { "" } else { " (not converged)" },
                        if s.report.fallbacks.is_empty() {
                            "–".to_string()
                        } else {
                            s.report.fallbacks.join(", ")
                        },
                        s.solution.creep,
                        s.timings.solve_s
                    ),
                    Err(e) => format!("| {name} | {n} | {mu} | error: {e} | | | |"),
                };
                println!("{row}");
            }
        }
    }
}
