//! Time per solve of each solution method on Carter's case (cases/carter_051.yaml, Q/μP = 0.51)
//! at several grid sizes: the contact problem is assembled once per size, then each method
//! solves it from the paper's start vector (Gauss–Seidel with the study's 20 000-sweep budget);
//! the best of 5 wall times of the solve alone (2 at 81 elements, 1 at 161) is reported with the
//! iteration count (the same on any machine) and the agreement with Newton.
//!
//! Run: `cargo run --release --example methods_perf`. Method and machine: docs/performance.md.

use rollbem::app;
use rollbem::case;
use rollbem::contact::Formulation;
use rollbem::contact::{methods, Method, SolverSettings};
use std::path::PathBuf;

fn main() {
    let path = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("cases/carter_051.yaml");
    let variants = [
        ("newton", Method::Newton, Formulation::Phi, 100),
        ("newton_psi", Method::Newton, Formulation::Psi, 100),
        ("newton_plain", Method::NewtonPlain, Formulation::Phi, 100),
        ("norm_tang", Method::NormTang, Formulation::Phi, 100),
        ("gauss_seidel", Method::GaussSeidel, Formulation::Phi, 20_000),
    ];
    println!("| elements | nodes | method | converged | iterations | solve [ms] | max |Δq| vs newton (μp0) |");
    println!("|---|---|---|---|---|---|---|");
    for n in [21usize, 41, 81, 161] {
        let loaded = case::load(&path, &[format!("contact.grid.elements={n}")]).expect("case loads");
        let bodies = app::prepare_bodies(&loaded).expect("bodies");
        let est = app::estimates(&loaded, &bodies);
        let (_, _, problem) = app::build_problem(&loaded, &est, &bodies).expect("problem");
        let mu_p0 = loaded.case.contact.friction * est.hertz_peak_pressure;
        let mut reference: Option<Vec<f64>> = None;
        for (label, method, formulation, max_iterations) in variants {
            let mut settings = SolverSettings {
                method,
                ..app::solver_settings(&loaded)
            };
            settings.newton.formulation = formulation;
            settings.newton.max_iterations = max_iterations;
            let mut best = f64::INFINITY;
            let mut last = None;
            // Best of 5 (of 2 at 81 elements, 1 at 161: the slow methods take seconds there).
            let repeats = match n {
                0..=41 => 5,
                42..=81 => 2,
                _ => 1,
            };
            for _ in 0..repeats {
                let (state, report) = methods::solve(&problem, &settings);
                best = best.min(report.wall_time_s);
                last = Some((state, report));
            }
            let (state, report) = last.expect("five runs");
            let diff = reference.as_ref().map_or(0.0, |q: &Vec<f64>| {
                q.iter()
                    .zip(&state.shear)
                    .fold(0.0_f64, |m, (a, b)| m.max((a - b).abs() / mu_p0))
            });
            if reference.is_none() {
                reference = Some(state.shear.clone());
            }
            println!(
                "| {n} | {} | {label} | {} | {} | {:.2} | {diff:.1e} |",
                problem.n_nodes(),
                report.converged,
                report.iterations,
                1e3 * best
            );
        }
    }
}
