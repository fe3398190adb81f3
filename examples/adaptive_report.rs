//! Error-controlled grids against closed forms: for each requested tolerance, the grid reached,
//! the estimated errors and the true ones (against Hertz and Carter), and their ratio (the
//! effectivity of the estimate). The `docs` test compares the columns that are not times
//! with docs/validation.md.
//!
//! Run: `cargo run --release --example adaptive_report [case] [tolerances...]`
//! (default: carter2d_contact at 1e-2 … 1e-5).

pub mod common;

use common::{solve, Table};
use rollbem::analytic::hertz_pressure;
use rollbem::app::Solved;
use rollbem::post::norms::nodal_error_against;

/// The header of the table.
pub const HEADER: [&str; 12] = [
    "tolerance",
    "elements",
    "nodes",
    "passes",
    "est. p (p0)",
    "true p (p0)",
    "est. q (μp0)",
    "true q (μp0)",
    "est. ξ (rel)",
    "true ξ (rel)",
    "effectivity p, q",
    "time [s]",
];

/// True errors of a solved Carter case: RMS p/p0 against Hertz, RMS q/μp0 against Carter,
/// relative creepage error.
pub fn true_errors(s: &Solved) -> [f64; 3] {
    let c = s.scene.carter_reference().expect("the case prescribes Q/μP");
    let x = &s.solution.x;
    let p = nodal_error_against(
        x,
        &s.solution.pressure,
        |x| hertz_pressure(x, c.half_width, c.peak_pressure),
        c.half_width,
        c.peak_pressure,
    )
    .rms;
    let mu_p0 = c.friction * c.peak_pressure;
    let q = nodal_error_against(x, &s.solution.shear, |x| c.shear(x), c.half_width, mu_p0).rms;
    let xi = c.creep(s.scene.estimates.effective_radius);
    let creep = if xi == 0.0 {
        s.solution.creep.abs()
    } else {
        (s.solution.creep / xi - 1.0).abs()
    };
    [p, q, creep]
}

/// One row of the table for `case` at `tolerance` with extra overrides.
pub fn row(case: &str, tolerance: f64, extra: &[&str]) -> Vec<String> {
    let mut set = vec![format!("contact.grid.tolerance={tolerance:e}")];
    set.extend(extra.iter().map(|s| s.to_string()));
    let s = solve(case, &set);
    let a = s.adaptation.as_ref().expect("an error-controlled run");
    let e = a.estimate.expect("a converged run has an estimate");
    let [p, q, xi] = true_errors(&s);
    vec![
        format!("{tolerance:.0e}"),
        s.problem.grid.n_elements().to_string(),
        s.problem.n_nodes().to_string(),
        a.steps.len().to_string(),
        format!("{:.2e}", e.pressure_rms),
        format!("{p:.2e}"),
        format!("{:.2e}", e.shear_rms),
        format!("{q:.2e}"),
        format!("{:.1e}", e.creep_rel),
        format!("{xi:.1e}"),
        format!("{:.2}, {:.2}", e.pressure_rms / p, e.shear_rms / q),
        format!("{:.3}", s.timings.total_s),
    ]
}

fn main() {
    // Arguments: the case, then tolerances and `key=value` overrides in any order.
    let args: Vec<String> = std::env::args().skip(1).collect();
    let case = args.first().cloned().unwrap_or_else(|| "carter2d_contact".into());
    let rest = args.get(1..).unwrap_or_default();
    let set: Vec<&str> = rest.iter().filter(|a| a.contains('=')).map(String::as_str).collect();
    let mut tolerances: Vec<f64> = rest
        .iter()
        .filter(|a| !a.contains('='))
        .map(|t| t.parse().expect("a tolerance"))
        .collect();
    if tolerances.is_empty() {
        tolerances = vec![1e-2, 1e-3, 1e-4, 1e-5];
    }
    let mut t = Table::new(&HEADER);
    for tol in tolerances {
        t.push(row(&case, tol, &set));
    }
    print!("{}", t.markdown());
}
