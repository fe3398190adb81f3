//! Prints docs/validation.md's table of fixed-grid error estimates (summary.json
//! `error_estimate` of a run on a fixed grid, src/adapt/fixed.rs) against the true errors of
//! shipped cases on their own grids, the truth being each case's error-controlled run at
//! tolerance 1e-4 (its own error about 1e-4, a tenth of the smallest error tabulated or less).
//!
//! Run: `cargo run --release --example fixed_grid_report` (about half a minute).

pub mod common;

use common::{case_path, Table};
use rollbem::adapt::estimate::CREEP_FLOOR;
use rollbem::app::{self, CaseSource, Solved};
use rollbem::post::adaptation::ErrorEstimate;
use rollbem::post::norms::nodal_error;

/// The shipped cases of the table: every body model, the paper's grids.
pub const CASES: [&str; 12] = [
    "hertz",
    "carter_051",
    "carter2d_contact",
    "dissimilar_al_steel_075",
    "dissimilar_beta0288_m083",
    "fig14_half_space",
    "fig14_true_geometry",
    "carter_051_true",
    "bore_a020_tractive",
    "tyre_b05_layer",
    "visc_cylindr_tc0009",
    "covered_roller_v_peak",
];

/// A shipped case run as `rollbem run` solves it (with its fixed grid's estimate).
pub fn run(name: &str, overrides: &[&str]) -> (Solved, ErrorEstimate) {
    let overrides: Vec<String> = overrides.iter().map(|s| s.to_string()).collect();
    let path = case_path(name);
    let case = app::load_case(CaseSource::File(&path), &overrides).unwrap_or_else(|e| panic!("{name}: {e}"));
    let s = app::solve_run(&case).unwrap_or_else(|e| panic!("{name}: {e}"));
    assert!(s.report.converged, "{name} did not converge");
    let e = s
        .fixed_grid_estimate
        .unwrap_or_else(|| panic!("{name}: a fixed grid's estimate"));
    (s, e)
}

/// The errors of `run` against `reference` in the estimate's norms: RMS p/p0 and q/(μp0) over
/// the reference's contact at the run's nodes (the reference interpolated by its shape
/// functions), and the creepage's difference relative to |ξ| or, where smaller, to 5 % of μa/R*.
pub fn errors_against(reference: &Solved, run: &Solved) -> [f64; 3] {
    let est = &reference.scene.estimates;
    let (p0, mu) = (est.hertz_peak_pressure, reference.scene.friction());
    let [x0, x1] = reference.solution.contact_extent().expect("in contact");
    let (c, a) = (0.5 * (x0 + x1), 0.5 * (x1 - x0));
    let g = &reference.problem.grid;
    let x: Vec<f64> = run.solution.x.iter().map(|x| x - c).collect();
    let rms = |values: &[f64], truth: &[f64], scale: f64| {
        nodal_error(&x, a, |i| (values[i] - g.interpolate(truth, x[i] + c)).abs() / scale).rms
    };
    let p = rms(&run.solution.pressure, &reference.solution.pressure, p0);
    if mu == 0.0 {
        return [p, 0.0, 0.0];
    }
    let q = rms(&run.solution.shear, &reference.solution.shear, mu * p0);
    let floor = CREEP_FLOOR * mu * est.hertz_half_width / est.effective_radius.abs();
    let xi = reference.solution.creep;
    [p, q, (run.solution.creep - xi).abs() / xi.abs().max(floor)]
}

/// Each case of [`CASES`] on its own fixed grid: the estimate against the true error.
pub fn table() -> Table {
    let mut t = Table::new(&[
        "case",
        "elements",
        "p estimate",
        "p true",
        "q estimate",
        "q true",
        "ξ estimate",
        "ξ true",
    ]);
    for name in CASES {
        let (s, e) = run(name, &[]);
        let reference = common::solve(name, &["contact.grid.tolerance=1e-4"]);
        let [p, q, xi] = errors_against(&reference, &s);
        let cell = |v: f64| format!("{v:.1e}");
        t.push(vec![
            name.to_string(),
            s.problem.grid.n_elements().to_string(),
            cell(e.pressure_rms),
            cell(p),
            cell(e.shear_rms),
            cell(q),
            cell(e.creep_rel),
            cell(xi),
        ]);
    }
    t
}

fn main() {
    println!("{}", table().markdown());
}
