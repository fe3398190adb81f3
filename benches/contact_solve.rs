//! Criterion benchmarks of the contact pipeline on CONTACT's carter2d problem
//! (cases/carter2d_contact.yaml) at 21–321 elements: influence-coefficient assembly and the
//! generalized Newton solve. Iteration counts (machine independent) are printed once per size.
//!
//! Run: `cargo bench --bench contact_solve`. Method and machine: docs/performance.md.

use criterion::{criterion_group, criterion_main, BenchmarkId, Criterion};
use rollbem::app;
use rollbem::case::LoadedCase;
use rollbem::contact::{methods, Method, SolverSettings};
use rollbem::scene::Scene;
use std::path::PathBuf;
use std::time::Duration;

fn load(n: usize) -> LoadedCase {
    let path = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("cases/carter2d_contact.yaml");
    app::load_case(&path, &[format!("contact.grid.elements={n}")]).expect("benchmark case loads")
}

fn contact_pipeline(c: &mut Criterion) {
    let mut group = c.benchmark_group("carter2d");
    group
        .sample_size(10)
        .measurement_time(Duration::from_secs(4))
        .warm_up_time(Duration::from_millis(500));
    for n in [21, 41, 81, 161, 321] {
        let case = load(n);
        let scene = Scene::from_case(&case).expect("scene");
        let (_, problem) = scene.assemble().expect("problem");
        let settings = SolverSettings {
            method: Method::Newton,
            ..scene.solver
        };
        let (_, report) = methods::solve(&problem, &settings);
        eprintln!(
            "carter2d {n} elements: {} Newton iterations, converged {}",
            report.iterations, report.converged
        );
        group.bench_with_input(BenchmarkId::new("assembly", n), &n, |b, _| b.iter(|| scene.assemble()));
        group.bench_with_input(BenchmarkId::new("newton_solve", n), &n, |b, _| {
            b.iter(|| methods::solve(&problem, &settings))
        });
    }
    group.finish();
}

criterion_group!(benches, contact_pipeline);
criterion_main!(benches);
