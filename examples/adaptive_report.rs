//! Error-controlled grids against closed forms: for each requested tolerance, the grid reached,
//! the estimated errors and the true ones (against Hertz and Carter), and their ratio (the
//! effectivity of the estimate). The `docs` test compares the columns that are not times
//! with docs/validation.md.
//!
//! Run: `cargo run --release --example adaptive_report` (the table of docs/validation.md), or
//! `… -- CASE TOLERANCE… [key=value…]` for other runs of a case that prescribes Q/μP.

pub mod common;

use common::{solve, Table};
use rollbem::analytic::hertz_pressure;
use rollbem::app::Solved;
use rollbem::post::norms::nodal_error_against;

/// The header of the table.
pub const HEADER: [&str; 13] = [
    "case",
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

/// The runs of docs/validation.md: (label, case, overrides, tolerance).
pub const RUNS: [(&str, &str, &[&str], f64); 10] = [
    ("carter2d", "carter2d_contact", &[], 1e-2),
    ("carter2d", "carter2d_contact", &[], 1e-3),
    ("carter2d", "carter2d_contact", &[], 1e-4),
    ("carter2d", "carter2d_contact", &[], 1e-5),
    (
        "braking, Q/μP −0.64",
        "carter2d_contact",
        &["load.tangential.ratio=-0.64"],
        1e-4,
    ),
    (
        "rolling −x",
        "carter2d_contact",
        &["contact.rolling_direction=-x"],
        1e-4,
    ),
    ("Q/μP 0.1", "carter2d_contact", &["load.tangential.ratio=0.1"], 1e-4),
    ("Q/μP 0.95", "carter2d_contact", &["load.tangential.ratio=0.95"], 1e-4),
    ("Hertz, R 10 m", "hertz", &HERTZ_FLAT, 1e-4),
    ("Hertz, R 10 m", "hertz", &HERTZ_FLAT, 1e-5),
];

/// cases/hertz.yaml with radii of 10 m: there the circle's profile departs from Hertz's parabola
/// by (a/R)²/4 ≈ 2.5e-7 of p0 (at R = 100 mm by 2.5e-5, a floor under the true error).
pub const HERTZ_FLAT: [&str; 2] = ["bodies.A.radius=10000", "bodies.B.radius=10000"];

/// The table of [`RUNS`].
pub fn table() -> Table {
    let mut t = Table::new(&HEADER);
    for (label, case, set, tol) in RUNS {
        t.push(row(label, case, tol, set));
    }
    t
}

/// One row of the table for `case` at `tolerance` with extra overrides.
pub fn row(label: &str, case: &str, tolerance: f64, extra: &[&str]) -> Vec<String> {
    let mut set = vec![format!("contact.grid.tolerance={tolerance:e}")];
    set.extend(extra.iter().map(|s| s.to_string()));
    let s = solve(case, &set);
    let a = s.adaptation.as_ref().expect("an error-controlled run");
    let e = a.estimate.expect("a converged run has an estimate");
    let [p, q, xi] = true_errors(&s);
    let ratio = |est: f64, truth: f64| {
        if truth > 0.0 {
            format!("{:.2}", est / truth)
        } else {
            "-".into()
        }
    };
    vec![
        label.to_string(),
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
        format!("{}, {}", ratio(e.pressure_rms, p), ratio(e.shear_rms, q)),
        format!("{:.3}", s.timings.total_s),
    ]
}

fn main() {
    // Arguments: the case, then tolerances and `key=value` overrides in any order.
    let args: Vec<String> = std::env::args().skip(1).collect();
    let Some(case) = args.first() else {
        print!("{}", table().markdown());
        println!();
        print!("{}", true_geometry_table().markdown());
        return;
    };
    let rest = &args[1..];
    let set: Vec<&str> = rest.iter().filter(|a| a.contains('=')).map(String::as_str).collect();
    let mut t = Table::new(&HEADER);
    for tol in rest.iter().filter(|a| !a.contains('=')) {
        t.push(row(case, case, tol.parse().expect("a tolerance"), &set));
    }
    print!("{}", t.markdown());
}

/// The header of the true-geometry table.
pub const TRUE_GEOMETRY_HEADER: [&str; 7] = [
    "grid",
    "contact elements",
    "p error (p0)",
    "q error (μp0)",
    "ξ error (rel)",
    "estimate p, q, ξ",
    "time [s]",
];

/// cases/carter_051_true.yaml (BEM rollers on shafts, 21 contact elements per mesh): the
/// error-controlled runs and the shipped mesh cut uniformly (every contact element halved k
/// times), against the run at tolerance 1e-4 (RMS over |x| < a at each run's nodes, the
/// reference interpolated by its own shape functions). Times are the library's run.
pub fn true_geometry_table() -> Table {
    use rollbem::adapt::cells::DyadicGrid;
    use rollbem::scene::Scene;
    let case = "carter_051_true";
    let fine = solve(case, &["contact.grid.tolerance=1e-4"]);
    let est = &fine.scene.estimates;
    let (a, p0, mu) = (est.hertz_half_width, est.hertz_peak_pressure, fine.scene.friction());
    let mut t = Table::new(&TRUE_GEOMETRY_HEADER);
    let mut push = |label: String, s: &Solved| {
        let x = &s.solution.x;
        let g = &fine.problem.grid;
        let err = |v: &[f64], r: &[f64], scale: f64| {
            rollbem::post::norms::nodal_error(x, a, |i| (v[i] - g.interpolate(r, x[i])).abs() / scale).rms
        };
        let p = err(&s.solution.pressure, &fine.solution.pressure, p0);
        let q = err(&s.solution.shear, &fine.solution.shear, mu * p0);
        let xi = (s.solution.creep / fine.solution.creep - 1.0).abs();
        let e = s.adaptation.as_ref().and_then(|a| a.estimate);
        t.push(vec![
            label,
            s.problem.grid.n_elements().to_string(),
            format!("{p:.2e}"),
            format!("{q:.2e}"),
            format!("{xi:.2e}"),
            e.map_or("-".into(), |e| {
                format!("{:.1e}, {:.1e}, {:.1e}", e.pressure_rms, e.shear_rms, e.creep_rel)
            }),
            format!("{:.2}", s.timings.total_s),
        ]);
    };
    let loaded = rollbem::app::load_case(&common::case_path(case), &[] as &[&str]).expect("the case");
    let shipped = Scene::from_case(&loaded).expect("its scene");
    for k in 0..4 {
        let mut cells = DyadicGrid::new(&shipped.grid);
        for _ in 0..k {
            cells = cells.bisected();
        }
        let s = rollbem::app::solve_scene(shipped.on_grid(cells.grid()), std::time::Instant::now())
            .expect("a uniformly cut mesh");
        push(format!("uniform, mesh cut {k}×"), &s);
    }
    for tol in ["3e-3", "1e-3", "3e-4"] {
        let s = solve(case, &[format!("contact.grid.tolerance={tol}")]);
        push(format!("tolerance {tol}"), &s);
    }
    t
}
