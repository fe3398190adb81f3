//! Parametric bodies (`geometry:`) against their Gmsh twins: each family solved on the scene
//! of a shipped case whose bodies are Gmsh meshes of the same geometry, and on its own mesh with
//! the far field twice as fine. The contact elements of all three are the same (the grid's), so
//! the difference from the twin is the far-field meshes' difference, and the refined run
//! measures the generated mesh's own far-field discretisation error.
//!
//! Prints the table of docs/validation.md, "Parametric bodies"; tests/docs compares the two and
//! tests/validation/parametric.rs checks the bounds.
//!
//! Run: cargo run --release --example parametric_report

mod common;

use common::{case_path, Table};
use rollbem::app::{self, Solved};
use rollbem::bem::BoundaryCondition;
use rollbem::body::BodySetup;
use rollbem::case::{BodySpec, BoundaryKeyword, BoundarySpec, LoadedCase};
use rollbem::mesh::{validate_and_orient, LoadedMesh};
use rollbem::scene::{BemSetup, Scene};
use std::sync::Arc;

/// One family and its twin: the family, the shipped case of Gmsh meshes and the overrides that
/// give the same bodies by `geometry:` (the case stem of the generated scene when it is shipped).
pub struct Twin {
    /// The `geometry:` family.
    pub family: &'static str,
    /// The shipped case whose bodies are the Gmsh twins.
    pub twin: &'static str,
    /// The case of the generated bodies: a shipped case, or the twin with overrides.
    pub generated: &'static str,
    /// Overrides of `generated`.
    pub overrides: Vec<String>,
}

fn geometry_of(side: &str, geometry: &str, boundaries: &str) -> Vec<String> {
    vec![
        format!("bodies.{side}.mesh=null"),
        format!("bodies.{side}.geometry={geometry}"),
        format!("bodies.{side}.boundaries={boundaries}"),
    ]
}

/// The four families and their twins.
pub fn twins() -> Vec<Twin> {
    let both = |a: (&str, &str), b: (&str, &str)| {
        let mut o = geometry_of("A", a.0, a.1);
        o.extend(geometry_of("B", b.0, b.1));
        o
    };
    let mut ring = both(
        ("{roller: {radius: 40, shaft: 5}}", "{shaft: fixed, free: free}"),
        ("{ring: {bore: 50, rim: 65}}", "{rim: fixed, bore: free}"),
    );
    // The shipped meshes' contact segment: 52 elements on |x| <= 1.3a.
    ring.extend([
        "contact.grid.elements=52".into(),
        "contact.grid.align_edges=false".into(),
    ]);
    let block = "{block: {width: 80, depth: 40}}";
    let cover = "{covered_roller: {radius: 100, cover_thickness: 90}}";
    vec![
        Twin {
            family: "roller",
            twin: "fig14_true_geometry",
            generated: "fig14_geometry",
            overrides: Vec::new(),
        },
        Twin {
            family: "ring",
            twin: "bore_a020_tractive",
            generated: "bore_a020_tractive",
            overrides: ring,
        },
        Twin {
            family: "block",
            twin: "carter_051_block",
            generated: "carter_051_block",
            overrides: both((block, "{far: fixed, free: free}"), (block, "{far: fixed, free: free}")),
        },
        Twin {
            family: "covered_roller",
            twin: "carter_051_true",
            generated: "carter_051_true",
            overrides: both(
                (cover, "{bonded: fixed, free: free}"),
                (cover, "{bonded: fixed, free: free}"),
            ),
        },
    ]
}

/// Creepage, overlap and peak pressure of a solution.
pub fn numbers(s: &Solved) -> [f64; 3] {
    let p_max = s.solution.pressure.iter().fold(0.0_f64, |m, &p| m.max(p));
    [s.solution.creep, s.solution.overlap, p_max]
}

/// Boundary elements of the scene's two bodies.
fn elements(s: &Solved) -> usize {
    s.scene
        .bodies
        .iter()
        .filter_map(|b| b.contact_mesh())
        .map(|m| m.mesh.mesh.elements.len())
        .sum()
}

/// A body's setup with its `geometry:` meshed `fineness` times finer away from the contact,
/// on the contact elements of `setup` (the case's own mesh of it).
fn refined_body(
    case: &LoadedCase,
    spec: &BodySpec,
    setup: &Arc<dyn BodySetup>,
    side: usize,
    fineness: usize,
) -> Arc<dyn BodySetup> {
    let BodySpec::Bem {
        geometry: Some(g),
        material,
        boundaries,
        radius,
        ..
    } = spec
    else {
        return setup.clone();
    };
    let own = setup.contact_mesh().expect("a bem body has its mesh");
    let edges = own.mesh.contact_grid().edges.clone();
    let shape = g.shape();
    let mut mesh = shape.mesh_refined(&edges, "contact", side == 0, "refined", fineness);
    validate_and_orient(&mut mesh).expect("the refined mesh is valid");
    let loaded = LoadedMesh::new("refined", mesh, Vec::new(), "contact").expect("a contact group");
    let mut conditions: Vec<(String, BoundaryCondition)> = shape
        .groups()
        .iter()
        .map(|(name, fixed)| {
            let fixed = match boundaries.get(*name) {
                Some(BoundarySpec::Keyword(k)) => *k == BoundaryKeyword::Fixed,
                _ => *fixed,
            };
            let c = if fixed {
                BoundaryCondition::Fixed
            } else {
                BoundaryCondition::Free
            };
            (name.to_string(), c)
        })
        .collect();
    conditions.sort_by(|a, b| a.0.cmp(&b.0));
    conditions.push(("contact".into(), BoundaryCondition::Contact));
    Arc::new(BemSetup::on_start_mesh(
        loaded,
        case.material(material),
        "contact".into(),
        conditions,
        *radius,
        None,
    ))
}

/// The generated scene of `twin` with its far field `fineness` times finer (1: as `run`
/// solves it).
pub fn solve_generated(twin: &Twin, fineness: usize) -> Solved {
    let case = app::load_case(&case_path(twin.generated), &twin.overrides).expect("the generated case loads");
    let scene = Scene::from_case(&case).expect("the generated scene builds");
    if fineness == 1 {
        return app::solve_scene(scene, std::time::Instant::now()).expect("the generated scene solves");
    }
    let specs = [&case.case.bodies.a, &case.case.bodies.b];
    let bodies = [0, 1].map(|k| refined_body(&case, specs[k], &scene.bodies[k], k, fineness));
    let s = app::solve_scene(Scene::new(case, bodies), std::time::Instant::now()).expect("the refined scene solves");
    assert!(
        s.report.converged,
        "{}: the refined scene did not converge",
        twin.family
    );
    s
}

/// |a/b − 1| for each of the three numbers.
pub fn relative(a: [f64; 3], b: [f64; 3]) -> [f64; 3] {
    [0, 1, 2].map(|k| (a[k] / b[k] - 1.0).abs())
}

/// Each family against its Gmsh twin and against its own far field twice as fine.
pub fn parametric() -> Table {
    let mut t = Table::new(&[
        "family",
        "Gmsh twin",
        "elements (generated, twin)",
        "ξ: twin",
        "ξ: refined",
        "δ0: twin",
        "δ0: refined",
        "p_max: twin",
        "p_max: refined",
    ]);
    for twin in twins() {
        let gmsh = common::solve(twin.twin, &[] as &[&str]);
        let generated = solve_generated(&twin, 1);
        let refined = solve_generated(&twin, 2);
        let d_twin = relative(numbers(&generated), numbers(&gmsh));
        let d_ref = relative(numbers(&generated), numbers(&refined));
        let e = |v: f64| format!("{v:.1e}");
        t.push(vec![
            twin.family.into(),
            format!("cases/{}.yaml", twin.twin),
            format!("{}, {}", elements(&generated), elements(&gmsh)),
            e(d_twin[0]),
            e(d_ref[0]),
            e(d_twin[1]),
            e(d_ref[1]),
            e(d_twin[2]),
            e(d_ref[2]),
        ]);
    }
    t
}

fn main() {
    println!(
        "## Parametric bodies against their Gmsh twins (relative differences)\n\n{}",
        parametric().markdown()
    );
}
