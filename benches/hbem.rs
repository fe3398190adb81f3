//! Criterion benchmarks of the hypersingular (HBEM) boundary strains on the roller meshes of
//! cases/carter_051_true.yaml (R = 100 mm on a 10 mm shaft, 21 contact elements) and of its
//! non-matching body B (54 contact elements):
//!
//! * `rows_one_point`: the integration rows of u_i,k at one contact node (every element
//!   integrated once, the singular one by Guiggiani's direct method);
//! * `surface_strain`: the HBEM surface strain of all m contact nodes for 2m boundary
//!   responses, the work [`rollbem::bem::condense`] adds to the condensation to give a bem body
//!   its strain operator;
//! * `condense`: the whole condensation (assembly, LU, 1 + 2m solves, HBEM strain) for scale.
//!
//! Run: `cargo bench --bench hbem`. Method and machine: docs/performance.md.

use criterion::{criterion_group, criterion_main, BenchmarkId, Criterion};
use rollbem::bem::condense::surface_strain;
use rollbem::bem::hypersingular::{GradientEvaluator, GradientPoint};
use rollbem::bem::{condense, BemModel, BemOptions, BemSolution, BoundaryCondition};
use rollbem::material::Elastic;
use std::path::PathBuf;
use std::time::Duration;

fn roller(mesh: &str) -> BemModel {
    let path = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("meshes").join(mesh);
    let (mesh, _) = rollbem::mesh::load(&path).expect("roller mesh loads");
    BemModel::new(
        mesh,
        Elastic::new(210_000.0, 0.3),
        vec![
            ("shaft".into(), BoundaryCondition::Fixed),
            ("free".into(), BoundaryCondition::Free),
            ("contact".into(), BoundaryCondition::Contact),
        ],
        BemOptions::default(),
    )
    .expect("roller model")
}

fn hbem(c: &mut Criterion) {
    let mut group = c.benchmark_group("hbem");
    group
        .sample_size(10)
        .measurement_time(Duration::from_secs(4))
        .warm_up_time(Duration::from_millis(500));
    for mesh in ["roller_r100_shaft10_A.msh", "roller_r100_shaft10_B_nonmatching.msh"] {
        let mut model = roller(mesh);
        let nodes = model.group_nodes("contact").expect("contact group");
        let m = nodes.len();
        eprintln!(
            "{mesh}: {} elements, {} field nodes, {m} contact nodes",
            model.mesh.elements.len(),
            model.field_nodes().len()
        );
        let label = format!("{m}_of_{}", model.field_nodes().len());
        let (element, local) = model.field_nodes()[nodes[m / 2]].element;
        let xi = model.discretisation.interpolation[element].node_coordinates()[local];
        let evaluator = GradientEvaluator::new(&model);
        group.bench_with_input(BenchmarkId::new("rows_one_point", &label), &label, |b, _| {
            b.iter(|| evaluator.rows(GradientPoint::Boundary { element, xi }).unwrap())
        });
        // 2m responses: the cost does not depend on their values (one traction-loaded solve).
        let contact = model.mesh.group_index("contact").unwrap();
        let loaded = model.clone();
        model.conditions[contact] = BoundaryCondition::Pressure(100.0);
        let solution: BemSolution = model.solve().expect("pressure-loaded roller solves");
        let responses = vec![solution; 2 * m];
        group.bench_with_input(BenchmarkId::new("surface_strain", &label), &label, |b, _| {
            b.iter(|| surface_strain(&loaded, &nodes, &responses).unwrap())
        });
        group.bench_with_input(BenchmarkId::new("condense", &label), &label, |b, _| {
            b.iter(|| condense(&loaded, "contact").unwrap())
        });
    }
    group.finish();
}

criterion_group!(benches, hbem);
criterion_main!(benches);
