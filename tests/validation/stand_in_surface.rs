//! The surface a BEM body's pass stand-in gives the contact (its profile, its slope and so the
//! contact frame) at the ends of its start mesh's contact elements, against the body itself
//! cut along a grid graded towards such an end (src/body/bem/stand_in.rs, `surface`). The
//! scene is the generated twin of tests/data/bore_c30_tractive.yaml: a roller R 30 on a shaft
//! of 5 in a ring bore R 30.6 (rim 42), whose contact elements (1.06 mm) end inside the
//! contact. The start mesh's quadratics change slope at their ends; the body cut along a fine
//! grid has its contact nodes on the circle and no such kink. A stand-in that kept the start
//! mesh's kink turned the contact frame there and stepped the normal gap: on a grid graded
//! towards an element's end the passes found a spurious opening and a pressure spike (17.5 p0
//! at 8.4e-8 mm spacing), and the error-controlled run at 1e-5 stalled near 8e-5 p0
//! (docs/validation.md, "Stand-ins at the start mesh's element ends").

use crate::stand_in::solved;
use rollbem::adapt::cells::{Action, DyadicGrid};
use rollbem::body::Side;
use rollbem::grid::ContactGrid;
use rollbem::scene::Scene;

/// The generated bore at `contact.grid.tolerance` = 1e-5 (three stand-in levels).
fn bore() -> Scene {
    let path = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/data/bore_c30_tractive.yaml");
    let overrides: Vec<String> = [
        "bodies.A.mesh=null",
        "bodies.A.geometry={roller: {radius: 30, shaft: 5}}",
        "bodies.B.mesh=null",
        "bodies.B.geometry={ring: {bore: 30.6, rim: 42}}",
        "contact.grid.tolerance=1e-5",
    ]
    .map(String::from)
    .to_vec();
    Scene::from_case(&rollbem::case::load(&path, &overrides).expect("loads")).expect("scene")
}

/// The stand-ins' scene of `scene`, fitted on its start grid bisected once, twice and three
/// times (the levels of a run at 1e-5).
fn stand_ins(scene: &Scene) -> Scene {
    let start = DyadicGrid::new(&scene.grid);
    let levels: Vec<ContactGrid> = (1..=3)
        .map(|t| (0..t).fold(start.clone(), |g, _| g.bisected()).grid())
        .collect();
    let refs: Vec<&ContactGrid> = levels.iter().collect();
    scene
        .with_pass_stand_ins(&refs, None)
        .expect("builds")
        .expect("BEM bodies offer a stand-in")
        .passes
}

/// The start element end `k` of `scene`'s grid and the start grid with its two neighbouring
/// elements halved `depth` times towards it.
fn graded_at_end(scene: &Scene, k: usize, depth: u32) -> (f64, ContactGrid) {
    let start = DyadicGrid::new(&scene.grid);
    let end = scene.grid.edges[k];
    let mut action = vec![Action::Keep; start.len()];
    let nudge = 1e-12 * scene.grid.length();
    action[k - 1] = Action::GradeTowards(end - nudge, depth);
    action[k] = Action::GradeTowards(end + nudge, depth);
    (end, start.refined(&action).grid())
}

/// Near the end of a start element inside the contact (x = −3.706, 0.09 mm behind the
/// stick/slip point), the stand-ins' surface slope and profile are those of the bodies cut
/// along a grid graded to 1.6e-5 mm there, whose contact nodes lie on the exact circles:
/// within 1e-9 rad and 1e-11 mm (measured below); the start mesh's own slope differs from
/// them by 1.4e-6 rad there, which a stand-in on the start mesh's elements kept.
#[test]
fn the_stand_ins_surface_is_the_cut_bodies_at_a_start_element_end() {
    let scene = bore();
    let passes = stand_ins(&scene);
    let (end, grid) = graded_at_end(&scene, 7, 16);
    let cut = scene.on_grid(grid.clone());
    let (mut slope, mut profile, mut start_mesh) = (0.0_f64, 0.0_f64, 0.0_f64);
    for (k, side) in [(0, Side::A), (1, Side::B)] {
        for &x in grid.nodes.iter().filter(|&&x| (x - end).abs() < 1e-3) {
            let s = passes.bodies[k].surface_at(x, side).expect("a surface");
            let c = cut.bodies[k].surface_at(x, side).expect("a surface");
            let m = scene.bodies[k].surface_at(x, side).expect("a surface");
            slope = slope.max((s.slope_angle - c.slope_angle).abs());
            profile = profile.max((s.profile - c.profile).abs());
            start_mesh = start_mesh.max((m.slope_angle - c.slope_angle).abs());
        }
    }
    eprintln!(
        "within 1e-3 of x = {end:.4}: stand-in − cut bodies: slope {slope:.2e} rad, profile {profile:.2e}; \
         start mesh − cut bodies: slope {start_mesh:.2e} rad"
    );
    assert!(slope <= 1e-9, "the stand-in's slope differs by {slope:e} rad");
    assert!(profile <= 1e-11, "the stand-in's profile differs by {profile:e}");
    // The check can fail: the start mesh's elements differ from the cut bodies' here.
    assert!(start_mesh > 1e3 * slope.max(1e-12), "start mesh {start_mesh:e}");
}

/// On the grid graded to 1.6e-5 mm at that element end, the stand-ins' pressure against the
/// bodies themselves on the same grid, within 0.05 mm of the end: within 1e-3 p0 at every node,
/// and no open node between the first and the last loaded one. Measured 6.2e-4 p0: the
/// difference is 1.6e-5 p0 and smooth down to 4e-5 mm from the end, and there the bodies'
/// own BEM on cut elements of 1.6e-5 mm carries a node-to-node ripple of ±5e-4 p0 that the
/// stand-ins (the half-plane's closed forms near the nodes) do not have, which sets the bound.
/// With the start mesh's kink in the stand-ins' contact frame the two differed by 1.4 p0 there,
/// with an open node inside the contact.
#[test]
fn the_stand_ins_pressure_has_no_step_at_a_start_element_end() {
    let scene = bore();
    let passes = stand_ins(&scene);
    let (end, grid) = graded_at_end(&scene, 7, 16);
    let full = solved(&scene, &grid);
    let stand = solved(&passes, &grid);
    let p0 = scene.estimates.hertz_peak_pressure;
    let (mut worst, mut at) = (0.0_f64, 0.0);
    for i in (0..grid.n_nodes()).filter(|&i| (grid.nodes[i] - end).abs() < 0.05) {
        let d = (stand.pressure[i] - full.pressure[i]).abs() / p0;
        if d > worst {
            (worst, at) = (d, grid.nodes[i]);
        }
    }
    let loaded: Vec<usize> = (0..grid.n_nodes()).filter(|&i| stand.pressure[i] > 0.0).collect();
    let (first, last) = (loaded[0], loaded[loaded.len() - 1]);
    let open_inside = (first..=last).filter(|&i| stand.pressure[i] <= 0.0).count();
    eprintln!(
        "graded at x = {end:.4} ({} elements): stand-ins − bodies up to {worst:.2e} p0 at x = {at:.6}; \
         {open_inside} open nodes inside the contact",
        grid.n_elements()
    );
    assert_eq!(open_inside, 0, "a spurious opening inside the contact");
    assert!(worst <= 1e-3, "the pressures differ by {worst:e} p0 at x = {at}");
}

/// The generated bore at `contact.grid.tolerance` = 1e-5 meets the tolerance (measured: 7 passes
/// to 1456 elements, the contact grid's estimate falling every pass from 2.9e-5 p0 at pass 2 to
/// 9.1e-9 p0 at pass 6; with the stand-ins' own error p 3.1e-6 p0, q 4.7e-6 μp0, creepage 5.1e-6;
/// before, it stalled near 8e-5 p0 and rose to 1.4e-4 p0 at 1254 elements). With
/// `max_elements` 1300 the run stops one pass short (creepage 1.02e-5 at 1108 elements), hence
/// 2600 here. Ignored: 316 s in release, 1.8 GB;
/// `cargo test --release --test validation stand_in_surface -- --ignored --nocapture`.
#[test]
#[ignore]
fn the_generated_bore_meets_1e_5() {
    let path = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/data/bore_c30_tractive.yaml");
    let s = rollbem::app::solve_case(
        path.as_path(),
        &[
            "bodies.A.mesh=null",
            "bodies.A.geometry={roller: {radius: 30, shaft: 5}}",
            "bodies.B.mesh=null",
            "bodies.B.geometry={ring: {bore: 30.6, rim: 42}}",
            "contact.grid.tolerance=1e-5",
            "contact.grid.max_elements=2600",
        ],
    )
    .expect("meets the tolerance");
    let a = s.adaptation.expect("an error-controlled run");
    eprintln!(
        "passes: {:?}; estimate {:?}",
        a.steps.iter().map(|p| p.elements).collect::<Vec<_>>(),
        a.estimate
    );
    assert!(a.reached && a.estimate.expect("an estimate").within(1e-5));
    // Before, the passes chased the stand-ins' spurious step to max_elements (12 passes).
    assert!(a.steps.len() <= 8, "{} passes", a.steps.len());
}
