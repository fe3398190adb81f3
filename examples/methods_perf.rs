//! Time per solve of each solution method on Carter's case (cases/carter_051.yaml, Q/μP = 0.51)
//! at several grid sizes: the contact problem is assembled once per size, then each method
//! solves it from the paper's start vector (Gauss–Seidel with the study's 20 000-sweep budget);
//! the best of 5 wall times of the solve alone (2 at 81 elements, 1 at 161) is reported with the
//! iteration count (the same on any machine) and the agreement with Newton. The `docs` test
//! compares the columns that are not times with docs/performance.md.
//!
//! Run: `cargo run --release --example methods_perf`. Method and machine: docs/performance.md.

pub mod common;

use common::{case_path, Table};
use rollbem::app;
use rollbem::contact::Formulation;
use rollbem::contact::{methods, Method, SolverSettings};
use rollbem::scene::Scene;

/// The method variants, each with its iteration budget.
const VARIANTS: [(&str, Method, Formulation, usize); 5] = [
    ("newton", Method::Newton, Formulation::Phi, 100),
    ("newton_psi", Method::Newton, Formulation::Psi, 100),
    ("newton_plain", Method::NewtonPlain, Formulation::Phi, 100),
    ("norm_tang", Method::NormTang, Formulation::Phi, 100),
    ("gauss_seidel", Method::GaussSeidel, Formulation::Phi, 20_000),
];

/// The table; `repeats(n)` solves of each method on the grid of n elements give the best
/// time (1: one solve, its time).
pub fn table(grids: &[usize], repeats: impl Fn(usize) -> usize) -> Table {
    let mut t = Table::new(&[
        "elements",
        "nodes",
        "method",
        "converged",
        "iterations",
        "solve [ms]",
        "max |Δq| vs newton (μp0)",
    ]);
    for &n in grids {
        let loaded =
            app::load_case(&case_path("carter_051"), &[format!("contact.grid.elements={n}")]).expect("case loads");
        let scene = Scene::from_case(&loaded).expect("scene");
        let (_, problem) = scene.assemble().expect("problem");
        let mu_p0 = scene.friction() * scene.estimates.hertz_peak_pressure;
        let mut reference: Option<Vec<f64>> = None;
        for (label, method, formulation, max_iterations) in VARIANTS {
            let mut settings = SolverSettings { method, ..scene.solver };
            settings.newton.formulation = formulation;
            settings.newton.max_iterations = max_iterations;
            let mut best = f64::INFINITY;
            let mut last = None;
            for _ in 0..repeats(n).max(1) {
                let (state, report) = methods::solve(&problem, &settings);
                best = best.min(report.wall_time_s);
                last = Some((state, report));
            }
            let (state, report) = last.expect("at least one solve");
            let diff = reference.as_ref().map_or(0.0, |q: &Vec<f64>| {
                q.iter()
                    .zip(&state.shear)
                    .fold(0.0_f64, |m, (a, b)| m.max((a - b).abs() / mu_p0))
            });
            if reference.is_none() {
                reference = Some(state.shear.clone());
            }
            t.push(vec![
                n.to_string(),
                problem.n_nodes().to_string(),
                label.to_string(),
                report.converged.to_string(),
                report.iterations.to_string(),
                format!("{:.2}", 1e3 * best),
                format!("{diff:.1e}"),
            ]);
        }
    }
    t
}

fn main() {
    // Best of 5 (of 2 at 81 elements, 1 at 161: the slow methods take seconds there).
    let repeats = |n: usize| match n {
        0..=41 => 5,
        42..=81 => 2,
        _ => 1,
    };
    print!("{}", table(&[21, 41, 81, 161], repeats).markdown());
}
