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
    bore_with(&[])
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
/// bodies themselves on the same grid, within 0.05 mm of the end: within 5e-5 p0 at every node,
/// and no open node between the first and the last loaded one. Measured 2.1e-5 p0, smooth (the
/// stand-ins' own error). Before the cut bodies took their circle's slope on elements this short
/// ([`the_bodies_pressure_has_no_ripple_on_elements_of_1e_6`]) the bodies' pressure rippled
/// node to node by ±5e-4 p0 within 4e-5 mm of the end and the two differed by 6.2e-4 p0; with
/// the start mesh's kink in the stand-ins' contact frame they differed by 1.4 p0 there, with an
/// open node inside the contact.
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
    assert!(worst <= 5e-5, "the pressures differ by {worst:e} p0 at x = {at}");
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

/// The generated bore of [`bore`] with `extra` overrides on top.
fn bore_with(extra: &[&str]) -> Scene {
    let path = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/data/bore_c30_tractive.yaml");
    let mut overrides: Vec<String> = [
        "bodies.A.mesh=null",
        "bodies.A.geometry={roller: {radius: 30, shaft: 5}}",
        "bodies.B.mesh=null",
        "bodies.B.geometry={ring: {bore: 30.6, rim: 42}}",
        "contact.grid.tolerance=1e-5",
    ]
    .map(String::from)
    .to_vec();
    overrides.extend(extra.iter().map(|s| s.to_string()));
    Scene::from_case(&rollbem::case::load(&path, &overrides).expect("loads")).expect("scene")
}

/// The largest deviation of `v` from the straight line through its two neighbours, over the
/// nodes i (with both neighbours) whose x lies within `window` of `end`: a node-to-node ripple
/// shows at its full amplitude, a smooth field at v''·h²/8 for node spacing h.
fn kink(x: &[f64], v: &[f64], end: f64, window: f64) -> f64 {
    (1..x.len() - 1)
        .filter(|&i| (x[i] - end).abs() < window)
        .map(|i| {
            let (a, b) = (x[i] - x[i - 1], x[i + 1] - x[i]);
            (v[i] - (v[i - 1] * b + v[i + 1] * a) / (a + b)).abs()
        })
        .fold(0.0, f64::max)
}

/// The contact solution of `scene` on `grid`, or None when the solver does not converge.
fn solved_or_none(scene: &Scene, grid: &ContactGrid) -> Option<rollbem::post::ContactSolution> {
    let on = scene.on_grid(grid.clone());
    let (_, problem) = on.assemble().expect("assembles");
    let (state, report) = rollbem::contact::methods::solve(&problem, &on.solver);
    report
        .converged
        .then(|| rollbem::post::ContactSolution::from_state(&problem, &state))
}

/// The start grid of `scene` with the start element holding `x` halved `depth` times towards
/// `x` (a point inside it, away from its ends: a stick/slip point, say).
fn graded_at(scene: &Scene, x: f64, depth: u32) -> ContactGrid {
    let start = DyadicGrid::new(&scene.grid);
    let k = scene.grid.edges.partition_point(|&e| e <= x) - 1;
    let mut action = vec![Action::Keep; start.len()];
    action[k] = Action::GradeTowards(x, depth);
    start.refined(&action).grid()
}

/// On the start grid halved 20 times towards a point 0.3 mm inside the start element that
/// begins at x = −3.706 (elements of 1.0e-6 mm there), the bodies' contact pressure has no
/// node-to-node ripple: its largest kink ([`kink`]) within 0.05 mm of the point is 2.4e-6 p0,
/// the stand-ins' 2.1e-6 p0 (the smooth pressure's curvature over the window's coarser nodes),
/// within 1e-5 p0, the error-controlled run's tolerance that a ripple above it would stall.
/// Before the cut bodies took the circle's slope on their tiny elements, the round-off of those
/// elements' slopes (nodes 1e-6 mm apart, coordinates of a few mm) turned the contact frame
/// node to node and stepped the normal gap by tan ψ·w (w ≈ 2.3e-2 mm): a ripple of 0.15 p0.
#[test]
fn the_bodies_pressure_has_no_ripple_on_elements_of_1e_6() {
    let scene = bore();
    let passes = stand_ins(&scene);
    let p0 = scene.estimates.hertz_peak_pressure;
    let (end, _) = graded_at_end(&scene, 7, 0);
    let point = end + 0.3;
    let grid = graded_at(&scene, point, 20);
    let full = solved(&scene, &grid);
    let stand = solved(&passes, &grid);
    let relative = |p: &[f64]| p.iter().map(|v| v / p0).collect::<Vec<f64>>();
    let bodies = kink(&grid.nodes, &relative(&full.pressure), point, 0.05);
    let stand_ins = kink(&grid.nodes, &relative(&stand.pressure), point, 0.05);
    eprintln!(
        "graded 20 times towards x = {point:.4}: pressure kink bodies {bodies:.2e} p0, stand-ins {stand_ins:.2e} p0"
    );
    assert!(bodies <= 1e-5, "the bodies' pressure ripples by {bodies:e} p0");
}

/// The ripple of the bodies' own BEM near a point graded towards, against the depth of the
/// grading (shortest element 1.06·2^−depth mm), at the start element end x = −3.706 and at the
/// point 0.3 mm past it inside the element: for the bodies and the stand-ins, the largest kink
/// ([`kink`]) of the contact pressure within 0.05 mm of the point [p0]; and, without the contact
/// solver, of the normal and tangential surface displacements h and w (global axes) of each
/// body under one smooth load (the stand-ins' solution on that grid), within 64 shortest
/// elements of the point, for the body, its stand-in and their difference [mm]. `RIPPLE_DEPTHS`
/// (comma-separated) and `RIPPLE_SET` (overrides, `;`-separated) change the sweep. Ignored (a
/// measurement); `cargo test --release --test validation stand_in_surface::ripple -- --ignored
/// --nocapture`.
#[test]
#[ignore]
fn ripple_against_the_grading_depth() {
    let set = std::env::var("RIPPLE_SET").unwrap_or_default();
    let extra: Vec<&str> = set.split(';').filter(|s| !s.is_empty()).collect();
    let scene = bore_with(&extra);
    let passes = stand_ins(&scene);
    let p0 = scene.estimates.hertz_peak_pressure;
    let depths: Vec<u32> = std::env::var("RIPPLE_DEPTHS")
        .unwrap_or_else(|_| "12,16,20,24".to_string())
        .split(',')
        .map(|s| s.trim().parse().expect("a depth"))
        .collect();
    eprintln!("overrides {extra:?}; p0 {p0:.1}");
    for depth in depths {
        let (end, at_end) = graded_at_end(&scene, 7, depth);
        let inside = end + 0.3;
        for (label, point, grid) in [
            ("end", end, at_end),
            ("inside", inside, graded_at(&scene, inside, depth)),
        ] {
            ripple_on(&scene, &passes, p0, depth, label, point, &grid);
        }
    }
}

/// One line of [`ripple_against_the_grading_depth`].
fn ripple_on(scene: &Scene, passes: &Scene, p0: f64, depth: u32, label: &str, point: f64, grid: &ContactGrid) {
    let shortest = (0..grid.n_elements())
        .map(|e| grid.edges[e + 1] - grid.edges[e])
        .fold(f64::INFINITY, f64::min);
    let (on_bodies, on_stand) = (scene.on_grid(grid.clone()), passes.on_grid(grid.clone()));
    if on_bodies.grid.n_nodes() != grid.n_nodes() {
        eprintln!(
            "depth {depth:2} {label:6}: the cut bodies' grid has {} nodes, not {}: skipped",
            on_bodies.grid.n_nodes(),
            grid.n_nodes()
        );
        return;
    }
    let stand = solved_or_none(passes, grid).expect("the stand-ins solve");
    let x = &grid.nodes;
    let ps: Vec<f64> = stand.pressure.iter().map(|p| p / p0).collect();
    let full = solved_or_none(scene, grid);
    let (pb, diff) = match &full {
        Some(f) => {
            let pb: Vec<f64> = f.pressure.iter().map(|p| p / p0).collect();
            let d: Vec<f64> = pb.iter().zip(&ps).map(|(a, b)| a - b).collect();
            (kink(x, &pb, point, 0.05), kink(x, &d, point, 0.05))
        }
        None => (f64::NAN, f64::NAN),
    };
    eprintln!(
        "depth {depth:2} {label:6}: shortest {shortest:.2e} mm, {} elements; pressure kink within 0.05 mm: \
         bodies {pb:.2e} p0, stand-ins {:.2e} p0, bodies − stand-ins {diff:.2e} p0{}",
        grid.n_elements(),
        kink(x, &ps, point, 0.05),
        if full.is_none() {
            " (bodies did not converge)"
        } else {
            ""
        }
    );
    // The bodies' flexibility itself, under the stand-ins' smooth solution.
    let m = grid.n_nodes();
    let p = faer::Mat::from_fn(m, 1, |i, _| stand.pressure[i]);
    let q = faer::Mat::from_fn(m, 1, |i, _| stand.shear[i]);
    let (body_models, stand_models) = (
        on_bodies.body_models().expect("builds"),
        on_stand.body_models().expect("builds"),
    );
    let window = 64.0 * shortest;
    for (k, side) in [(0, Side::A), (1, Side::B)] {
        let [hb, wb] = body_models[k]
            .model()
            .displacements(&on_bodies.grid, side, p.as_ref(), q.as_ref());
        let [hs, ws] = stand_models[k]
            .model()
            .displacements(&on_stand.grid, side, p.as_ref(), q.as_ref());
        let col = |a: &faer::Mat<f64>| (0..m).map(|i| a[(i, 0)]).collect::<Vec<f64>>();
        let (hb, wb, hs, ws) = (col(&hb), col(&wb), col(&hs), col(&ws));
        let dh: Vec<f64> = hb.iter().zip(&hs).map(|(a, b)| a - b).collect();
        let dw: Vec<f64> = wb.iter().zip(&ws).map(|(a, b)| a - b).collect();
        let at = x.iter().position(|&v| v > point).expect("a node past the point");
        eprintln!(
            "    body {}: h {:.3e} w {:.3e} mm there; kink within {window:.1e} mm: h body {:.2e} stand-in {:.2e} \
             difference {:.2e}; w body {:.2e} stand-in {:.2e} difference {:.2e} mm",
            ["A", "B"][k],
            hb[at],
            wb[at],
            kink(x, &hb, point, window),
            kink(x, &hs, point, window),
            kink(x, &dh, point, window),
            kink(x, &wb, point, window),
            kink(x, &ws, point, window),
            kink(x, &dw, point, window),
        );
    }
}
