//! The alternative solution methods: where they converge they solve the same
//! discrete problem as the default Newton, and they handle every load control.

use crate::common::{case_path, solve};
use rollbem::app;
use rollbem::case;
use rollbem::contact::Formulation;
use rollbem::contact::{methods, Method, SolverSettings};

/// Solves a shipped case with a method (Gauss–Seidel gets its sweep budget); panics with the
/// history if it does not converge.
fn solve_with(name: &str, method: &str, overrides: &[&str]) -> app::Solved {
    let mut set = vec![format!("solver.method={method}")];
    if method == "gauss_seidel" {
        set.push("solver.max_iterations=20000".into());
    }
    set.extend(overrides.iter().map(|s| s.to_string()));
    let refs: Vec<&str> = set.iter().map(String::as_str).collect();
    solve(name, &refs)
}

/// Largest nodal difference of two traction fields relative to `scale`.
fn max_diff(a: &[f64], b: &[f64], scale: f64) -> f64 {
    a.iter().zip(b).fold(0.0_f64, |m, (x, y)| m.max((x - y).abs() / scale))
}

const ALTERNATIVES: [&str; 3] = ["newton_plain", "norm_tang", "gauss_seidel"];

/// On Carter (Q/μP = 0.51) every method converges to Newton's tractions and creepage to 1e-8 of
/// p0 (they all stop at the common scaled residual 1e-10), and so to Carter's closed form as
/// closely as Newton does: creepage within 1 %, shear within 2 % of μp0 away from the zone edges.
#[test]
fn every_method_gives_newtons_solution_on_carter() {
    let reference = solve("carter_051", &[]);
    let p0 = reference.scene.estimates.hertz_peak_pressure;
    let carter = reference.scene.carter_reference().expect("ratio-controlled");
    let exact_creep = carter.creep(reference.scene.estimates.effective_radius);
    for method in ALTERNATIVES {
        for formulation in ["phi", "psi"] {
            let f = format!("solver.formulation={formulation}");
            let s = solve_with("carter_051", method, &[&f]);
            let (sol, r) = (&s.solution, &reference.solution);
            assert!(
                max_diff(&sol.pressure, &r.pressure, p0) < 1e-8,
                "{method}/{formulation}: pressure"
            );
            assert!(
                max_diff(&sol.shear, &r.shear, p0) < 1e-8,
                "{method}/{formulation}: shear"
            );
            assert!(
                (sol.creep / r.creep - 1.0).abs() < 1e-8,
                "{method}/{formulation}: creep {} vs {}",
                sol.creep,
                r.creep
            );
            assert!(
                (sol.creep / exact_creep - 1.0).abs() < 0.01,
                "{method}: creep vs Carter"
            );
            let mu_p0 = carter.friction * carter.peak_pressure;
            let [x0, x1] = carter.stick_zone();
            for (x, q) in sol.x.iter().zip(&sol.shear) {
                let far = (x - x0).abs() > 0.1 && (x - x1).abs() > 0.1 && x.abs() < 0.9;
                if far {
                    assert!((q - carter.shear(*x)).abs() < 0.02 * mu_p0, "{method}: q({x})");
                }
            }
            assert_eq!(s.report.method.name(), method);
        }
    }
}

/// Similar bodies: the normal and tangential problems do not interact (H_q = B_p = 0), so one
/// NORM/TANG alternation is the exact solution. Dissimilar bodies (β = 0.288) need several.
#[test]
fn norm_tang_needs_one_alternation_for_similar_bodies_and_more_for_dissimilar_ones() {
    let similar = solve_with("carter_051", "norm_tang", &[]);
    assert_eq!(similar.report.iterations, 1, "{:?}", similar.report.history);
    let dissimilar = solve_with("dissimilar_beta0288_004", "norm_tang", &[]);
    assert!(dissimilar.report.iterations > 2, "{:?}", dissimilar.report.history);
}

/// Every load control reaches every method: force control (δ0 and ξ unknown, Lagrange-type rows),
/// mixed, and kinematic control (δ0, ξ given); each method matches Newton's solution of the same
/// control to 1e-7 of p0. On Carter's case for every method; on the dissimilar regime-4 case for
/// the two that converge there without a line search (the full Newton step of `newton_plain`
/// overshoots there with ξ prescribed: docs/stability.md).
#[test]
fn every_method_handles_every_load_control() {
    for (name, methods) in [
        ("carter_051", &ALTERNATIVES[..]),
        ("dissimilar_beta0288_004", &ALTERNATIVES[1..]),
    ] {
        let load = solve(name, &[]);
        // P and Q/μP (the shipped control) against the other four.
        let mut controls = crate::common::equivalent_load_controls(&load);
        controls.insert(0, ("P and Q/μP", vec![]));
        let p0 = load.scene.estimates.hertz_peak_pressure;
        for (label, set) in controls {
            let set: Vec<&str> = set.iter().map(String::as_str).collect();
            let newton = solve(name, &set);
            for method in methods {
                let other = solve_with(name, method, &set);
                let (a, b) = (&other.solution, &newton.solution);
                assert!(
                    max_diff(&a.pressure, &b.pressure, p0) < 1e-7 && max_diff(&a.shear, &b.shear, p0) < 1e-7,
                    "{name} {method} with {label}: tractions differ from Newton's"
                );
                assert!(
                    (a.creep - b.creep).abs() < 1e-7 * b.creep.abs(),
                    "{name} {method} with {label}: ξ"
                );
                assert!(
                    (a.overlap - b.overlap).abs() < 1e-7 * b.overlap.abs(),
                    "{name} {method} with {label}: δ0"
                );
            }
        }
    }
}

/// Every method reports in the same form: the common measure below the tolerance, its own
/// iteration count, a history of that length, a wall time.
#[test]
fn every_method_reports_in_the_same_form() {
    let loaded = case::load(&case_path("carter_051"), &[]).unwrap();
    let scene = rollbem::scene::Scene::from_case(&loaded).unwrap();
    let (_, problem) = scene.assemble().unwrap();
    for method in Method::ALL {
        let mut settings = SolverSettings { method, ..scene.solver };
        settings.newton.max_iterations = if method == Method::GaussSeidel { 20_000 } else { 100 };
        let (state, report) = methods::solve(&problem, &settings);
        let measure = rollbem::contact::residual::ConvergenceMeasure::new(&problem);
        assert!(report.converged, "{method:?}");
        assert!(report.residual <= 1e-10 && (measure.of(&state) - report.residual).abs() < 1e-12);
        assert_eq!(report.history.len(), report.iterations, "{method:?}");
        assert!(report.wall_time_s > 0.0 && report.method == method);
        assert_eq!(report.formulation, Formulation::Phi);
    }
}

/// A Gauss–Seidel relaxation beyond 2 makes the local normal update overshoot: the sweeps
/// diverge and the method reports it (not converged, a finite residual in the report).
#[test]
fn gauss_seidel_over_relaxed_beyond_two_fails_and_says_so() {
    let set = [
        "solver.method=gauss_seidel",
        "solver.penalty=3",
        "solver.max_iterations=2000",
    ];
    let s = app::solve_case(&case_path("carter_051"), &set).unwrap();
    assert!(!s.report.converged);
    assert!(
        s.report.residual.is_finite() && s.report.residual > 1e-3,
        "{}",
        s.report.residual
    );
}

/// Hertz with continuous quadratic elements: a and p0 within 1 % (the element type of the
/// ripple study solves the same problem).
#[test]
fn continuous_quadratic_elements_reproduce_hertz() {
    let s = solve(
        "hertz",
        &["contact.grid.element=continuous_quadratic", "contact.grid.elements=41"],
    );
    let e = &s.scene.estimates;
    let [x0, x1] = s.solution.contact_extent().unwrap();
    assert!(
        (0.5 * (x1 - x0) / e.hertz_half_width - 1.0).abs() < 0.01,
        "a = {}",
        0.5 * (x1 - x0)
    );
    let pmax = s.solution.pressure.iter().fold(0.0_f64, |m, &p| m.max(p));
    assert!((pmax / e.hertz_peak_pressure - 1.0).abs() < 0.01, "p0 = {pmax}");
    assert_eq!(s.problem.n_nodes(), 2 * 41 + 1);
    assert!(s.solution.slip_strain.is_none());
}
