//! Criterion benchmark of the interior post-processing of a BEM body (Somigliana's identity,
//! `rollbem::bem::somigliana`): a 100 × 100 grid of points in a steel block of about 1000
//! boundary nodes (an 80 × 40 mm half-plane block with 21 contact elements of 0.118 mm),
//! loaded by a Hertz pressure (a = 1 mm) with q = 0.2p through its contact nodes, as
//! `rollbem run` does with `output.interior`. Two grids:
//! * `subsurface` — the sub-surface map under the contact, |x| ≤ 1.5 mm, 0.02 ≤ y ≤ 2 mm (the
//!   case files' usual request: every point within 17 contact elements of the surface, many
//!   within one, so most element integrals are nearly singular);
//! * `whole_body` — the whole block, |x| ≤ 39.6 mm, 0.2 ≤ y ≤ 39.6 mm.
//!
//! Run: `cargo bench --bench interior`. Method and machine: docs/performance.md.

use criterion::{criterion_group, criterion_main, Criterion};
use rollbem::bem::{BemModel, BemOptions, BoundaryCondition};
use rollbem::body::bem::BemBody;
use rollbem::body::{BodyFields, ContactLoad, InteriorQuery, Side};
use rollbem::grid::{ContactGrid, ElementKind};
use rollbem::interior::{grid_points, InteriorOptions, InteriorSample};
use rollbem::material::Elastic;
use rollbem::mesh::build::half_plane_block;
use std::time::Duration;

fn block() -> (BemBody, ContactGrid) {
    let l = 21.0 / 17.0;
    let mesh = half_plane_block(40.0, 40.0, l, 21, 1.04, 80, true);
    let model = BemModel::new(
        mesh,
        Elastic::new(210_000.0, 0.3),
        vec![
            ("contact".into(), BoundaryCondition::Contact),
            ("free".into(), BoundaryCondition::Free),
            ("far".into(), BoundaryCondition::Fixed),
        ],
        BemOptions::default(),
    )
    .expect("block model");
    let grid = ContactGrid::uniform(ElementKind::DiscontinuousQuadratic, 21, -l, l);
    let body = BemBody::new(model, "contact", &grid, Side::A).expect("block body");
    (body, grid)
}

fn interior(c: &mut Criterion) {
    let (body, grid) = block();
    let p: Vec<f64> = grid
        .nodes
        .iter()
        .map(|x| 1000.0 * (1.0 - x * x).max(0.0).sqrt())
        .collect();
    let q: Vec<f64> = p.iter().map(|v| 0.2 * v).collect();
    let options = InteriorOptions::default();
    let load = ContactLoad {
        grid: &grid,
        pressure: &p,
        shear: &q,
    };
    eprintln!(
        "interior benchmark: {} boundary nodes, {} elements, {} threads",
        body.model.field_nodes().len(),
        body.model.mesh.elements.len(),
        rayon::current_num_threads()
    );
    let mut group = c.benchmark_group("interior");
    group
        .sample_size(10)
        .measurement_time(Duration::from_secs(10))
        .warm_up_time(Duration::from_secs(1));
    for (name, x, y) in [
        ("subsurface_100x100", [-1.5, 1.5, 100.0], [0.02, 2.0, 100.0]),
        ("whole_body_100x100", [-39.6, 39.6, 100.0], [0.2, 39.6, 100.0]),
    ] {
        let points = grid_points(x, y);
        let query = InteriorQuery {
            side: Side::A,
            load,
            points: &points,
            options,
        };
        let samples = body.interior(&query).expect("interior");
        let inside = samples
            .iter()
            .filter(|s| matches!(s, InteriorSample::Inside(_)))
            .count();
        eprintln!("{name}: {inside} of {} points evaluated", points.len());
        group.bench_function(name, |b| b.iter(|| body.interior(&query).expect("interior")));
    }
    group.finish();
}

criterion_group!(benches, interior);
criterion_main!(benches);
