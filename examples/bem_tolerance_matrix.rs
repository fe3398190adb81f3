//! Every shipped case with a `bem` body at the tolerances 1e-3, 1e-4, 3e-5 and 1e-5, with
//! `contact.grid.max_elements` capped at [`MAX_ELEMENTS`]: each run either meets its tolerance
//! (exit code 0) or stops at the cap with its estimate (exit code 2); none may end in an error
//! (a cut of the body's mesh along a grid that does not fit it, a refusal of its own grid).
//! Prints the table of docs/validation.md ("Every BEM case at every tolerance") and asserts
//! the outcome of each run; tests/validation/bem_tolerances.rs runs the cheap rows.
//!
//! Run: `cargo run --release --example bem_tolerance_matrix [-- NAME]` (NAME: only the cases
//! whose name contains it).

mod common;

use common::{case_path, shipped_cases, Table};
use rollbem::app::{self, Solved};
use rollbem::error::Error;
use std::time::Instant;

/// The tolerances of the matrix.
pub const TOLERANCES: [f64; 4] = [1e-3, 1e-4, 3e-5, 1e-5];

/// The cap on the grid's elements: above it a run stops with exit code 2 (3 nodes an element;
/// a grid of 600 elements keeps a bore's condensation within about 2 GB).
pub const MAX_ELEMENTS: usize = 600;

/// How a run ended.
#[derive(Debug, Clone, PartialEq)]
pub enum Outcome {
    /// The estimate met the tolerance: elements, the estimate's largest relative quantity, the
    /// body meshes' (None without an estimate of theirs), and whether the results are the BEM
    /// bodies' stand-ins' (`grid.results_from_stand_ins`).
    Met(usize, f64, Option<f64>, bool),
    /// The grid reached the cap first (exit code 2): elements, the last estimate's largest.
    Capped(usize, f64),
    /// The contact grid met the tolerance, but a body's mesh outside the contact stayed too
    /// coarse after the error control's bisections of it (exit code 2): the body meshes'
    /// estimate (largest).
    BodyMeshTooCoarse(f64),
    /// Anything else: the message.
    Failed(String),
}

/// The shipped steady cases with a `bem` body, sorted (a transient history keeps one grid and
/// refuses a tolerance).
pub fn bem_cases() -> Vec<String> {
    shipped_cases()
        .into_iter()
        .filter(|name| {
            std::fs::read_to_string(case_path(name))
                .map(|text| text.contains("model: bem") && !text.contains("\ntransient:"))
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
        Outcome::Met(
            elements,
            e.largest(),
            e.body_mesh.map(|b| b.largest()),
            a.results_from_stand_ins,
        )
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
        Err(Error::ToleranceNotReached {
            elements,
            pressure,
            shear,
            creep,
            ..
        }) => Outcome::Capped(elements, pressure.max(shear).max(creep)),
        Err(Error::BodyMeshTooCoarse {
            pressure, shear, creep, ..
        }) => Outcome::BodyMeshTooCoarse(pressure.max(shear).max(creep)),
        Err(e) => Outcome::Failed(e.to_string()),
    };
    (outcome, t0.elapsed().as_secs_f64())
}

/// The runs of the table the tests repeat (tests/validation/bem_tolerances.rs checks their
/// outcomes, tests/docs their rows of docs/validation.md): short ones, among them the runs
/// whose own cuts were once refused (fig14_true_geometry at 1e-4, carter_051_true at 3e-5),
/// non-matching meshes, and a run that stops at the element limit.
pub const TESTED: [(&str, f64); 4] = [
    ("fig14_true_geometry", 1e-4),
    ("carter_051_true", 3e-5),
    ("carter_051_true_nonmatching", 1e-3),
    ("bore_a020_braking", 3e-5),
];

/// The header of the table.
pub const HEADER: [&str; 8] = [
    "case",
    "tolerance",
    "outcome",
    "elements",
    "estimate (largest)",
    "body mesh (largest)",
    "results from",
    "time [s]",
];

/// The table's row of one run.
pub fn row(name: &str, tolerance: f64) -> Vec<String> {
    let (outcome, seconds) = run(name, tolerance);
    eprintln!("{name} {tolerance:e}: {outcome:?} in {seconds:.1} s");
    let e = |v: f64| format!("{v:.1e}");
    let (what, elements, estimate, body, from) = match &outcome {
        Outcome::Met(n, x, b, stand_ins) => (
            "met",
            n.to_string(),
            e(*x),
            b.map_or("-".to_string(), e),
            if *stand_ins { "stand-ins" } else { "bodies" },
        ),
        Outcome::Capped(n, x) => ("max_elements (exit 2)", n.to_string(), e(*x), "-".to_string(), "-"),
        Outcome::BodyMeshTooCoarse(b) => ("body mesh too coarse (exit 2)", "-".into(), "-".into(), e(*b), "-"),
        Outcome::Failed(message) => panic!("{name} at {tolerance:e}: {message}"),
    };
    let row = vec![
        name.to_string(),
        format!("{tolerance:.0e}"),
        what.to_string(),
        elements,
        estimate,
        body,
        from.to_string(),
        format!("{seconds:.1}"),
    ];
    eprintln!("| {} |", row.join(" | "));
    row
}

/// The table of `runs`.
pub fn table_of(runs: &[(String, f64)]) -> Table {
    let mut t = Table::new(&HEADER);
    for (name, tolerance) in runs {
        t.push(row(name, *tolerance));
    }
    t
}

/// The whole table: every case with a `bem` body at every tolerance.
pub fn table(only: Option<&str>) -> Table {
    let runs: Vec<(String, f64)> = bem_cases()
        .into_iter()
        .filter(|name| only.is_none_or(|o| name.contains(o)))
        .flat_map(|name| TOLERANCES.map(|t| (name.clone(), t)))
        .collect();
    table_of(&runs)
}

#[allow(dead_code)]
fn main() {
    let only = std::env::args().nth(1);
    println!("{}", table(only.as_deref()).markdown());
}
