//! The body mesh's error estimate (`error_estimate.body_mesh`) against the truth: a roller on
//! a rigid shaft meshed deliberately coarsely outside the contact (12 quadratic elements on the
//! free circle, graded from the contact as Gmsh's size field grades; 6 on the shaft), rolling
//! on a rigid cylinder, its error-controlled run's estimate against the difference from the
//! same geometry meshed 8 times finer outside the contact, solved on the same final contact
//! grid (the contact elements of both are the grid's); and the cheaper comparison with the
//! roller's mesh coarsened outside the contact (elements merged in pairs) against the same
//! truth. The shipped Gmsh meshes of
//! cases/fig14_true_geometry.yaml report their estimate too.
//!
//! Prints the table of docs/validation.md, "The body mesh's error"; tests/docs compares the two
//! and tests/validation/body_mesh.rs checks the bounds.
//!
//! Run: cargo run --release --example body_mesh_report

mod common;

use common::Table;
use rollbem::adapt::body_mesh::{difference, estimate};
use rollbem::adapt::estimate::Scales;
use rollbem::app::{self, Solved};
use rollbem::bem::BoundaryCondition;
use rollbem::body::setup::ChangedFor;
use rollbem::body::BodySetup;
use rollbem::contact::residual::State;
use rollbem::mesh::build::MeshBuilder;
use rollbem::mesh::{validate_and_orient, LoadedMesh};
use rollbem::post::adaptation::BodyMeshComparison;
use rollbem::post::adaptation::BodyMeshError;
use rollbem::scene::{BemSetup, Scene};
use std::sync::Arc;

/// The coarse roller's tolerance: above its body mesh's error, so that the run reports the
/// estimate of the mesh as given (no bisection adopted).
pub const TOLERANCE: f64 = 1e-2;

/// Elements of each half of the coarse roller's free circle.
pub const HALF_CIRCLE_ELEMENTS: usize = 6;

/// Elements of the coarse roller's shaft.
pub const SHAFT_ELEMENTS: usize = 6;

/// Growth of neighbouring element angles on the coarse roller's free circle, from the contact.
pub const GROWTH: f64 = 3.0;

/// How much finer the reference mesh is outside the contact.
pub const FINER: usize = 8;

/// The scene: the aluminium roller R 150 on a shaft of 15 of cases/fig14_geometry.yaml (body A)
/// on a rigid cylinder R 300 (body B), with `overrides` after those.
pub fn overrides(extra: &[&str]) -> Vec<String> {
    let mut o = vec!["bodies.B={model: rigid, radius: 300}".to_string()];
    o.extend(extra.iter().map(|s| s.to_string()));
    o
}

/// The roller R on a shaft of radius `shaft` above the contact (centre (0, R)): one contact
/// element between neighbouring `edges`, the free circle in two arcs of `n` elements each
/// whose angles grow by `growth` away from the contact, the shaft a circle of `shaft_n`.
pub fn roller_mesh(edges: &[f64], r: f64, shaft: f64, n: usize, growth: f64, shaft_n: usize) -> LoadedMesh {
    let centre = [0.0, r];
    let surface = |x: f64| [x, r - (r * r - x * x).sqrt()];
    let mut b = MeshBuilder::new(true, "coarse roller");
    b.move_to(surface(edges[0]));
    for &x in &edges[1..] {
        b.arc_to(centre, surface(x), 1, true, 1.0, "contact");
    }
    b.arc_to(centre, [0.0, 2.0 * r], n, true, growth, "free");
    b.arc_to(centre, surface(edges[0]), n, true, 1.0 / growth, "free");
    b.circle(centre, shaft, shaft_n, "shaft");
    let mut mesh = b.finish();
    validate_and_orient(&mut mesh).expect("the roller mesh is valid");
    LoadedMesh::new(
        format!("<coarse roller, {} elements on the free circle>", 2 * n),
        mesh,
        Vec::new(),
        "contact",
    )
    .expect("a contact group")
}

/// Body A of the case's scene replaced by the roller of `2·half` elements on its free circle
/// and `shaft` on its shaft, meshed `fineness` times finer outside the contact, on the
/// generated roller's contact elements.
pub fn scene_with_roller(extra: &[&str], half: usize, shaft: usize, fineness: usize) -> Scene {
    scene_with_graded_roller(extra, half, GROWTH, shaft, fineness)
}

/// [`scene_with_roller`] with the free circle's element angles growing by `growth`.
pub fn scene_with_graded_roller(extra: &[&str], half: usize, growth: f64, shaft: usize, fineness: usize) -> Scene {
    let case = app::load_case(&common::case_path("fig14_geometry"), &overrides(extra)).expect("the case loads");
    let generated = Scene::from_case(&case).expect("the scene builds");
    let edges = generated.bodies[0]
        .contact_mesh()
        .expect("a bem roller")
        .mesh
        .contact_grid()
        .edges;
    let k = fineness as f64;
    let mesh = roller_mesh(
        &edges,
        150.0,
        15.0,
        half * fineness,
        growth.powf(1.0 / k),
        shaft * fineness,
    );
    let conditions = vec![
        ("free".to_string(), BoundaryCondition::Free),
        ("shaft".to_string(), BoundaryCondition::Fixed),
        ("contact".to_string(), BoundaryCondition::Contact),
    ];
    let a = BemSetup::on_start_mesh(
        mesh,
        case.material("aluminium"),
        "contact".into(),
        conditions,
        None,
        None,
    );
    let bodies: [Arc<dyn BodySetup>; 2] = [Arc::new(a), generated.bodies[1].clone()];
    Scene::new(case, bodies)
}

/// The state of a solved run (its solution's fields).
fn state(s: &Solved) -> State {
    let sol = &s.solution;
    State {
        gap: sol.gap.clone(),
        slip: sol.slip.clone(),
        pressure: sol.pressure.clone(),
        shear: sol.shear.clone(),
        overlap: sol.overlap,
        creep: sol.creep,
    }
}

/// The coarse roller's error-controlled run and what its body mesh's estimates are measured
/// against.
pub struct CoarseRoller {
    /// The run at [`TOLERANCE`].
    pub run: Solved,
    /// The true error of its body mesh: on the run's final grid, the difference between the
    /// roller as meshed and the roller meshed [`FINER`] times finer outside the contact, both
    /// solved with the full BEM (the run's results may be its stand-ins', whose own error the
    /// run estimates apart), in the estimate's norms.
    pub truth: BodyMeshError,
    /// The coarsened comparison's estimate on the same grid: the roller as meshed against its
    /// mesh coarsened outside the contact (elements merged in pairs), a third of the difference.
    pub coarsened: BodyMeshError,
}

/// The coarse roller's run at [`TOLERANCE`], its body mesh's true error and the coarsened
/// comparison's estimate ([`CoarseRoller`]).
pub fn coarse_roller() -> CoarseRoller {
    let tol = format!("contact.grid.tolerance={TOLERANCE:e}");
    let run = app::solve_scene(
        scene_with_roller(&[&tol], HALF_CIRCLE_ELEMENTS, SHAFT_ELEMENTS, 1),
        std::time::Instant::now(),
    )
    .expect("the coarse roller's run meets the tolerance");
    let on_run_grid = |s: Scene, body: Arc<dyn BodySetup>| {
        let followed = body
            .follow_grid(&run.problem.grid)
            .expect("a bem body follows the grid");
        let s = Scene::new(s.case.clone(), [followed, s.bodies[1].clone()]);
        assert!(s.grid.coincides_with(&run.problem.grid), "the same contact grid");
        app::solve_scene(s, std::time::Instant::now()).expect("the roller solves on the run's grid")
    };
    let meshed = |fineness: usize| {
        let s = scene_with_roller(&[], HALF_CIRCLE_ELEMENTS, SHAFT_ELEMENTS, fineness);
        let body = s.bodies[0].clone();
        on_run_grid(s, body)
    };
    let given = meshed(1);
    let reference = meshed(FINER);
    let coarse = {
        let s = scene_with_roller(&[], HALF_CIRCLE_ELEMENTS, SHAFT_ELEMENTS, 1);
        let body = s.bodies[0]
            .with_free_boundary_coarsened(ChangedFor::Check)
            .expect("a bem body coarsens");
        on_run_grid(s, body)
    };
    let est = &run.scene.estimates;
    let mu = run.scene.friction();
    let scales = Scales {
        peak_pressure: est.hertz_peak_pressure,
        friction: mu,
        creep_prescribed: false,
        complete_slip_creep: mu * est.hertz_half_width / est.effective_radius.abs(),
        // The body meshes' differences read the creepage's difference alone.
        geometry_share: 0.0,
    };
    let grid = &run.problem.grid;
    // The plain difference: the reference stands for the exact body.
    let truth = difference(grid, &state(&given), &state(&reference), scales, true);
    let coarsened = estimate(
        BodyMeshComparison::Coarsened,
        grid,
        &state(&given),
        &state(&coarse),
        scales,
        true,
    );
    CoarseRoller { run, truth, coarsened }
}

/// The body mesh's estimate of an error-controlled run.
pub fn body_mesh_estimate(s: &Solved) -> BodyMeshError {
    s.adaptation
        .as_ref()
        .and_then(|a| a.estimate)
        .and_then(|e| e.body_mesh)
        .expect("an error-controlled run of a bem body reports its body mesh's estimate")
}

/// The estimate against the truth for the coarse roller, and the shipped fig14 meshes'
/// estimate at 1e-3.
pub fn body_mesh() -> Table {
    let mut t = Table::new(&["run", "quantity", "estimate", "true error", "estimate / true"]);
    let CoarseRoller { run, truth, coarsened } = coarse_roller();
    let e = body_mesh_estimate(&run);
    let quantities = |b: &BodyMeshError| {
        [
            ("pressure (RMS, p0)", b.pressure),
            ("shear (RMS, μp0)", b.shear),
            ("creepage (relative)", b.creepage_rel),
            ("overlap (relative)", b.overlap_rel.unwrap_or(f64::NAN)),
        ]
    };
    let roller = format!("coarse roller, {} free elements", 2 * HALF_CIRCLE_ELEMENTS);
    let label = format!(
        "{roller}, tolerance {TOLERANCE:.0e}, meshes {}",
        e.compared_with.as_str()
    );
    let coarsened_label = format!("{roller}, meshes coarsened (on the run's final grid)");
    for (label, estimate) in [(&label, &e), (&coarsened_label, &coarsened)] {
        for ((q, est), (_, tr)) in quantities(estimate).into_iter().zip(quantities(&truth)) {
            t.push(vec![
                label.clone(),
                q.into(),
                format!("{est:.2e}"),
                format!("{tr:.2e}"),
                format!("{:.2}", est / tr),
            ]);
        }
    }
    let fig14 = common::solve("fig14_true_geometry", &["contact.grid.tolerance=1e-3"]);
    let grid = fig14.adaptation.as_ref().and_then(|a| a.estimate);
    let e = body_mesh_estimate(&fig14);
    let overlap = grid.and_then(|g| g.overlap_rel).unwrap_or(f64::NAN);
    let rows = quantities(&e)
        .into_iter()
        .chain([("overlap, contact grid's estimate (relative)", overlap)]);
    for (q, est) in rows {
        t.push(vec![
            format!(
                "cases/fig14_true_geometry.yaml, tolerance 1e-3, meshes {}",
                e.compared_with.as_str()
            ),
            q.into(),
            format!("{est:.2e}"),
            "-".into(),
            "-".into(),
        ]);
    }
    t
}

fn main() {
    println!(
        "## The body mesh's error estimate against the truth\n\n{}",
        body_mesh().markdown()
    );
}
