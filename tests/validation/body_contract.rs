//! What every body model must satisfy, whatever its physics: the contract of
//! `rollbem::body::BodySetup` (docs/architecture.md, "A new body model"). Each registered model
//! is checked on the shipped cases that use it; a new model adds its case to [`CASES`].
//!
//! * it builds on the scene's grid, with m × m flexibility blocks of finite numbers;
//! * the pair convention: a uniform pressure pushes a deformable body's surface into it
//!   (h > 0 at the centre node) and leaves a rigid one where it is (h = 0);
//! * its profile is zero at the touching point and keeps the sign of its radius (≥ 0 convex,
//!   ≤ 0 concave) over the grid;
//! * it follows a bisected grid (`follow_grid`, or unchanged) and builds there, and its
//!   compliance under the uniform pressure changes by less than 2 % at the centre (the grid
//!   error of a smooth load).

use rollbem::adapt::cells::DyadicGrid;
use rollbem::body::{Body, BodySetup, BuildContext, Side};
use rollbem::grid::ContactGrid;
use rollbem::scene::Scene;
use std::sync::Arc;

/// Shipped cases that use every model between them: half-spaces, a rigid roller on a BEM
/// layer, two BEM rollers on shafts, a BEM roller in a BEM ring's bore, two BEM rollers
/// that rollbem meshed itself (`geometry:`), viscoelastic half-spaces (a pair, and under a
/// rigid roller), an elastic layer under a rigid roller and a viscoelastic one under a
/// half-space.
const CASES: [&str; 9] = [
    "carter_051",
    "tyre_b05_compressible",
    "carter_051_true",
    "bore_a005_tractive",
    "fig14_geometry",
    "visc_cylindr_tc0009",
    "hunter_rigid_on_sls",
    "tyre_b05_layer",
    "covered_roller_v_peak",
];

/// The body built on `grid` from `side`.
fn build(setup: &Arc<dyn BodySetup>, grid: &ContactGrid, side: Side, scene: &Scene) -> Box<dyn Body> {
    let ctx = BuildContext {
        grid,
        side,
        rolling: scene.rolling(),
        pair: None,
        responses_only: false,
        run: None,
    };
    setup
        .build(&ctx)
        .unwrap_or_else(|e| panic!("{} builds: {e}", setup.model_name()))
}

/// Normal displacement into the body at the node nearest x = 0 under a uniform unit pressure.
fn centre_compliance(body: &dyn Body, grid: &ContactGrid, side: Side) -> f64 {
    let f = body.model().flexibility(grid, side);
    let m = grid.n_nodes();
    for block in [&f.hp, &f.hq, &f.wp, &f.wq] {
        assert_eq!((block.nrows(), block.ncols()), (m, m));
        for i in 0..m {
            for j in 0..m {
                assert!(
                    block[(i, j)].is_finite(),
                    "{}: a flexibility entry is not finite",
                    body.model_name()
                );
            }
        }
    }
    let h = f.normal(&vec![1.0; m], &vec![0.0; m]);
    let centre = (0..m)
        .min_by(|&a, &b| grid.nodes[a].abs().total_cmp(&grid.nodes[b].abs()))
        .unwrap();
    h[centre]
}

#[test]
fn every_body_model_keeps_the_contract() {
    for case in CASES {
        let loaded = rollbem::case::load(&crate::common::case_path(case), &[]).unwrap();
        let scene = Scene::from_case(&loaded).unwrap();
        let finer = DyadicGrid::new(&scene.grid).bisected().grid();
        for (k, side) in [Side::A, Side::B].into_iter().enumerate() {
            let setup = &scene.bodies[k];
            let label = format!("{case}, body {side:?} ({})", setup.model_name());
            let body = build(setup, &scene.grid, side, &scene);
            let h = centre_compliance(body.as_ref(), &scene.grid, side);
            if setup.hertz_material().is_some() {
                assert!(h > 0.0, "{label}: uniform pressure must push the surface in, h = {h}");
            } else {
                assert_eq!(h, 0.0, "{label}: a rigid body does not move");
            }
            let r = setup.radius();
            assert!(
                body.model().profile(0.0).abs() <= 1e-9 * r.abs().min(1.0),
                "{label}: profile at 0"
            );
            for &x in &scene.grid.nodes {
                let p = body.model().profile(x);
                assert!(
                    p * r.signum() >= -1e-12 * r.abs().min(1.0),
                    "{label}: profile {p} at x = {x}"
                );
            }
            // The bisected grid: followed (a mesh cut along it) or built on as it is.
            let followed = setup.follow_grid(&finer).unwrap_or_else(|| setup.clone());
            let own = followed.contact_mesh().map(|c| c.mesh.contact_grid());
            let grid = own.as_ref().unwrap_or(&finer);
            assert_eq!(grid.n_elements(), finer.n_elements(), "{label}: followed the grid");
            let fine_body = build(&followed, grid, side, &scene);
            let h_fine = centre_compliance(fine_body.as_ref(), grid, side);
            if h > 0.0 {
                assert!((h_fine / h - 1.0).abs() < 0.02, "{label}: compliance {h} then {h_fine}");
            }
        }
    }
}
