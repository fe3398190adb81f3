//! The effectivity of the error estimate (estimate over true error) across a matrix of
//! error-controlled runs. Against closed forms, half-space runs: Carter's tractions and
//! creepage for similar bodies (cases/carter2d_contact.yaml varied in Q/μP, sign of Q, rolling
//! direction, μ, element kind and grid extent) and Hertz's pressure for a frictionless pair
//! (cases/hertz.yaml with radii of 10 m, where the circle's profile is Hertz's parabola to
//! (a/R)²/4 ≈ 2.5e-7 of p0), each at the tolerances 1e-3, 1e-4 and 1e-5. Against the same case
//! solved at a tolerance a hundred times smaller ([`REFERENCED`], no closed form): a dissimilar
//! pair in partial slip (cases/dissimilar_al_steel_075.yaml, aluminium on steel, Q/μP 0.75,
//! where the normal and tangential problems are coupled) and BEM rollers on shafts
//! (cases/carter_051_true.yaml, and the paper's Fig. 14 rollers of two radii). tests/validation
//! (`effectivity::`) asserts every effectivity within [1/3, 3] and the true errors within the
//! tolerance, and the `docs` test compares [`table`] with docs/validation.md.
//!
//! Run: `cargo run --release --example effectivity_matrix` (the table of docs/validation.md).

pub mod common;

use rollbem::adapt::estimate::CREEP_FLOOR;
use rollbem::analytic::{hertz_pressure, Carter};
use rollbem::app::{self, Solved};
use rollbem::contact::TangentialControl;
use rollbem::post::norms::{nodal_error, nodal_error_against};

/// The header of the table.
pub const HEADER: [&str; 12] = [
    "variant",
    "tolerance",
    "elements",
    "passes",
    "true p (p0)",
    "true q (μp0)",
    "true ξ (rel)",
    "effectivity p",
    "effectivity q",
    "effectivity ξ",
    "within tolerance",
    "time [s]",
];

/// One variant of the matrix: its label, its case and the overrides.
pub type Variant = (&'static str, &'static str, &'static [&'static str]);

/// cases/hertz.yaml with radii of 10 m and no friction (Hertz's pressure is then exact).
pub const HERTZ: &[&str] = &["bodies.A.radius=10000", "bodies.B.radius=10000", "contact.friction=0"];

/// The variants, each run at every one of [`TOLERANCES`].
pub const VARIANTS: [Variant; 14] = [
    ("carter2d, Q/μP 0.64", "carter2d_contact", &[]),
    ("Q/μP 0.05", "carter2d_contact", &["load.tangential.ratio=0.05"]),
    ("Q/μP 0.5", "carter2d_contact", &["load.tangential.ratio=0.5"]),
    ("Q/μP 0.95", "carter2d_contact", &["load.tangential.ratio=0.95"]),
    ("Q/μP 0.99", "carter2d_contact", &["load.tangential.ratio=0.99"]),
    (
        "braking, Q/μP −0.64",
        "carter2d_contact",
        &["load.tangential.ratio=-0.64"],
    ),
    ("rolling −x", "carter2d_contact", &["contact.rolling_direction=-x"]),
    (
        "creepage control, ξ 2.4e-4",
        "carter2d_contact",
        &["load.tangential={creep: 0.00024}"],
    ),
    ("μ 0.02", "carter2d_contact", &["contact.friction=0.02"]),
    ("μ 0.8", "carter2d_contact", &["contact.friction=0.8"]),
    (
        "continuous elements",
        "carter2d_contact",
        &["contact.grid.element=continuous_quadratic"],
    ),
    ("extent 1.05", "carter2d_contact", &["contact.grid.extent=1.05"]),
    ("extent 3", "carter2d_contact", &["contact.grid.extent=3"]),
    ("Hertz, μ 0", "hertz", HERTZ),
];

/// The tolerances of the matrix.
pub const TOLERANCES: [f64; 3] = [1e-3, 1e-4, 1e-5];

/// One run of the matrix: the solved case and its estimate and true errors (p, q, ξ).
pub struct Run {
    /// The solved case.
    pub solved: Solved,
    /// The estimate of p, q, ξ.
    pub estimate: [f64; 3],
    /// The true errors of p, q, ξ.
    pub truth: [f64; 3],
    /// Whether the error control met the tolerance (by its estimate).
    pub reached: bool,
}

/// Solves `variant` at `tolerance`; panics when the case is refused or a solve fails.
pub fn solve(variant: &Variant, tolerance: f64) -> Solved {
    let (label, case, set) = *variant;
    let mut overrides = vec![format!("contact.grid.tolerance={tolerance:e}")];
    overrides.extend(set.iter().map(|s| s.to_string()));
    let s = app::solve_case(&common::case_path(case), &overrides).unwrap_or_else(|e| panic!("{label}: {e}"));
    assert!(s.report.converged, "{label} at {tolerance:e}: a solve did not converge");
    s
}

/// Solves `variant` at `tolerance` and measures its true errors with `truth`.
pub fn run_with(variant: &Variant, tolerance: f64, truth: impl Fn(&Solved) -> [f64; 3]) -> Run {
    let s = solve(variant, tolerance);
    let a = s.adaptation.as_ref().expect("an error-controlled run");
    let e = a.estimate.expect("an estimate");
    Run {
        estimate: [e.pressure_rms, e.shear_rms, e.creep_rel],
        truth: truth(&s),
        reached: a.reached,
        solved: s,
    }
}

/// Solves `variant` at `tolerance` and measures its true errors against the closed forms.
pub fn run(variant: &Variant, tolerance: f64) -> Run {
    run_with(variant, tolerance, true_errors)
}

/// A variant without a closed form, measured against the same case solved at
/// `reference` (a tolerance a hundred times below the smallest of its `tolerances`).
pub struct Referenced {
    /// The variant.
    pub variant: Variant,
    /// The tolerances it is run at.
    pub tolerances: &'static [f64],
    /// The tolerance of its reference run.
    pub reference: f64,
}

/// The variants measured against a finer run of their own: the dissimilar pair in partial
/// slip (aluminium on steel, Q/μP 0.75: the normal and tangential problems are coupled, there
/// is no closed form) and the BEM rollers on shafts (the contact grid cuts the meshes, the
/// passes and the final grid solve the bodies' stand-ins).
pub const REFERENCED: [Referenced; 3] = [
    Referenced {
        variant: ("dissimilar Al/steel, Q/μP 0.75", "dissimilar_al_steel_075", &[]),
        tolerances: &[1e-3, 1e-4],
        reference: 1e-6,
    },
    Referenced {
        variant: ("BEM rollers, carter_051_true", "carter_051_true", &[]),
        tolerances: &[1e-3],
        reference: 1e-5,
    },
    Referenced {
        variant: ("BEM rollers, fig14_true_geometry", "fig14_true_geometry", &[]),
        tolerances: &[1e-3],
        reference: 1e-5,
    },
];

/// The errors of `run` against `reference`, in the estimate's measures: RMS p/p0 and q/(μp0)
/// over |x| < a (a and p0 of Hertz's estimates) at the run's nodes, the reference interpolated
/// by its shape functions, and the creepage's difference relative to the reference's |ξ|, or
/// to [`CREEP_FLOOR`]·μa/R* where that is smaller.
pub fn errors_against(reference: &Solved, run: &Solved) -> [f64; 3] {
    let est = &reference.scene.estimates;
    let floor = CREEP_FLOOR * reference.scene.friction() * est.hertz_half_width / est.effective_radius.abs();
    errors_against_with_creep_floor(reference, run, floor)
}

/// [`errors_against`] with the creepage's difference taken relative to max(|ξ_reference|,
/// `creep_floor`) [-] (0: relative to |ξ_reference| alone).
pub fn errors_against_with_creep_floor(reference: &Solved, run: &Solved, creep_floor: f64) -> [f64; 3] {
    let est = &reference.scene.estimates;
    let (a, p0, mu) = (
        est.hertz_half_width,
        est.hertz_peak_pressure,
        reference.scene.friction(),
    );
    let (x, g) = (&run.solution.x, &reference.problem.grid);
    let (rp, rq) = (&reference.solution.pressure, &reference.solution.shear);
    let p = nodal_error(x, a, |i| {
        (run.solution.pressure[i] - g.interpolate(rp, x[i])).abs() / p0
    })
    .rms;
    let q = nodal_error(x, a, |i| {
        (run.solution.shear[i] - g.interpolate(rq, x[i])).abs() / (mu * p0)
    })
    .rms;
    let xi = reference.solution.creep;
    [p, q, (run.solution.creep - xi).abs() / xi.abs().max(creep_floor)]
}

/// True errors: RMS p/p0 against Hertz, RMS q/μp0 against Carter (length-weighted over
/// |x| < a), relative creepage error against Carter's; 0 for q and ξ without friction.
pub fn true_errors(s: &Solved) -> [f64; 3] {
    let est = &s.scene.estimates;
    let carter = s.scene.carter_reference().or_else(|| carter_of_creepage(s));
    let Some(c) = carter.filter(|c| c.friction > 0.0) else {
        let (a, p0) = (est.hertz_half_width, est.hertz_peak_pressure);
        let x = &s.solution.x;
        let p = nodal_error_against(x, &s.solution.pressure, |x| hertz_pressure(x, a, p0), a, p0).rms;
        return [p, 0.0, 0.0];
    };
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
    // In the estimate's own measure: relative to |ξ|, or to the floor where ξ is smaller.
    if let TangentialControl::Creep(_) = s.scene.tangential {
        // A prescribed creepage has no error (and the estimate none).
        return [p, q, 0.0];
    }
    let xi = c.creep(est.effective_radius);
    let floor = CREEP_FLOOR * c.friction * c.half_width / est.effective_radius.abs();
    [p, q, (s.solution.creep - xi).abs() / xi.abs().max(floor)]
}

/// Carter's solution under a prescribed creepage ξ (and prescribed force): the load ratio from
/// ξ = sign·(μa/R*)(1 − √(1 − |Q|/(μP))) (docs/references.md §2).
fn carter_of_creepage(s: &Solved) -> Option<Carter> {
    let TangentialControl::Creep(xi) = s.scene.tangential else {
        return None;
    };
    let est = &s.scene.estimates;
    let mu = s.scene.friction();
    let (a, r) = (est.hertz_half_width, est.effective_radius);
    let root = 1.0 - xi.abs() * r / (mu * a);
    let sign = xi.signum() * s.scene.leading_edge_sign();
    (mu > 0.0 && root > 0.0).then(|| Carter {
        half_width: a,
        peak_pressure: est.hertz_peak_pressure,
        friction: mu,
        ratio: sign * (1.0 - root * root),
        leading_edge_sign: s.scene.leading_edge_sign(),
    })
}

/// The effectivities est/true of p, q, ξ (None where the true error is 0: nothing to estimate).
pub fn effectivities(r: &Run) -> [Option<f64>; 3] {
    std::array::from_fn(|k| (r.truth[k] > 0.0).then(|| r.estimate[k] / r.truth[k]))
}

/// One row of the table.
pub fn row(label: &str, tolerance: f64, r: &Run) -> Vec<String> {
    let eff = effectivities(r);
    let cell = |v: Option<f64>| v.map_or("-".to_string(), |v| format!("{v:.2}"));
    let within = r.reached && r.truth.iter().all(|&t| t <= tolerance);
    vec![
        label.to_string(),
        format!("{tolerance:.0e}"),
        r.solved.problem.grid.n_elements().to_string(),
        r.solved.adaptation.as_ref().map_or(0, |a| a.steps.len()).to_string(),
        format!("{:.2e}", r.truth[0]),
        format!("{:.2e}", r.truth[1]),
        format!("{:.2e}", r.truth[2]),
        cell(eff[0]),
        cell(eff[1]),
        cell(eff[2]),
        if within { "yes" } else { "no" }.to_string(),
        format!("{:.3}", r.solved.timings.total_s),
    ]
}

/// The rows of `referenced`: its reference solved once, then each of its tolerances.
pub fn referenced_rows(referenced: &Referenced) -> Vec<Vec<String>> {
    let reference = solve(&referenced.variant, referenced.reference);
    let truth = |s: &Solved| errors_against(&reference, s);
    let label = format!("{} (against {:.0e})", referenced.variant.0, referenced.reference);
    referenced
        .tolerances
        .iter()
        .map(|&tol| row(&label, tol, &run_with(&referenced.variant, tol, truth)))
        .collect()
}

/// The whole matrix: the variants against closed forms, then those against finer runs.
pub fn table() -> common::Table {
    let mut t = common::Table::new(&HEADER);
    for v in &VARIANTS {
        for tol in TOLERANCES {
            t.push(row(v.0, tol, &run(v, tol)));
        }
    }
    for r in &REFERENCED {
        for cells in referenced_rows(r) {
            t.push(cells);
        }
    }
    t
}

fn main() {
    print!("{}", table().markdown());
}
