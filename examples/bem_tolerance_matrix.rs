//! Every shipped case with a `bem` body at the tolerances 1e-3, 1e-4, 3e-5 and 1e-5, with
//! `contact.grid.max_elements` capped at [`MAX_ELEMENTS`]: each run either meets its tolerance
//! (exit code 0) or stops at the cap with its estimate (exit code 2); none may end in an error
//! (a cut of the body's mesh along a grid that does not fit it, a refusal of its own grid).
//! Prints the table of docs/validation.md ("Every BEM case at every tolerance") and asserts
//! the outcome of each run; tests/validation/bem_tolerances.rs runs the cheap rows.
//!
//! Run: `cargo run --release --example bem_tolerance_matrix`.

pub mod common;

use common::{case_path, shipped_cases, Table};
use rollbem::app::{self, Solved};
use std::time::Instant;

/// The tolerances of the matrix.
pub const TOLERANCES: [f64; 4] = [1e-3, 1e-4, 3e-5, 1e-5];

/// The cap on the grid's elements: above it a run stops with exit code 2 (3 nodes an element;
/// a grid of 600 elements keeps a bore's condensation within about 2 GB).
pub const MAX_ELEMENTS: usize = 600;

/// How a run ended.
#[derive(Debug, Clone, PartialEq)]
pub enum Outcome {
    /// The estimate met the tolerance: elements, the estimate's largest relative quantity and
    /// the body meshes' (None without an estimate of theirs).
    Met(usize, f64, Option<f64>),
    /// The grid reached the cap first (exit code 2): elements, the last estimate's largest.
    Capped(usize, f64),
    /// Anything else: the message.
    Failed(String),
}

/// The shipped cases with a `bem` body, sorted.
pub fn bem_cases() -> Vec<String> {
    shipped_cases()
        .into_iter()
        .filter(|name| {
            std::fs::read_to_string(case_path(name))
                .map(|text| text.contains("model: bem"))
                .unwrap_or(false)
        })
        .collect()
}

/// The outcome of a solved run at `tolerance`.
fn outcome_of(s: &Solved) -> Outcome {
    let Some(a) = s.adaptation.as_ref() else {
        return Outcome::Failed("no error control".into());
    };
    let Some(e) = a.estimate else {
        return Outcome::Failed("no estimate".into());
    };
    let elements = s.problem.grid.n_elements();
    if !s.report.converged {
        return Outcome::Failed(format!("the solver did not converge on {elements} elements"));
    }
    if a.reached {
        Outcome::Met(elements, e.largest(), e.body_mesh.map(|b| b.largest()))
    } else {
        Outcome::Capped(elements, e.largest())
    }
}

/// Runs `name` at `tolerance` (capped at [`MAX_ELEMENTS`]): its outcome and wall time [s].
pub fn run(name: &str, tolerance: f64) -> (Outcome, f64) {
    let set = [
        format!("contact.grid.tolerance={tolerance:e}"),
        format!("contact.grid.max_elements={MAX_ELEMENTS}"),
    ];
    let t0 = Instant::now();
    let outcome = match app::solve_case(&case_path(name), &set) {
        Ok(s) => outcome_of(&s),
        Err(e) => Outcome::Failed(e.to_string()),
    };
    (outcome, t0.elapsed().as_secs_f64())
}

/// The table: one row per case and tolerance.
pub fn table() -> Table {
    let mut t = Table::new(&[
        "case",
        "tolerance",
        "outcome",
        "elements",
        "estimate (largest)",
        "body mesh (largest)",
        "time [s]",
    ]);
    for name in bem_cases() {
        for tolerance in TOLERANCES {
            let (outcome, seconds) = run(&name, tolerance);
            eprintln!("{name} {tolerance:e}: {outcome:?} in {seconds:.1} s");
            let (what, elements, estimate, body) = match &outcome {
                Outcome::Met(n, e, b) => ("met", *n, *e, *b),
                Outcome::Capped(n, e) => ("max_elements (exit 2)", *n, *e, None),
                Outcome::Failed(message) => panic!("{name} at {tolerance:e}: {message}"),
            };
            t.push(vec![
                name.clone(),
                format!("{tolerance:.0e}"),
                what.to_string(),
                elements.to_string(),
                format!("{estimate:.1e}"),
                body.map_or("-".to_string(), |b| format!("{b:.1e}")),
                format!("{seconds:.1}"),
            ]);
        }
    }
    t
}

#[allow(dead_code)]
fn main() {
    println!("{}", table().markdown());
}
