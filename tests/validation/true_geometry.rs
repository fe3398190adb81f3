//! BEM bodies in the contact problem: half-space blocks and true rollers on shafts
//! against Carter and against the analytic half-space model.

use crate::common::solve;
use rollbem::bem::BoundaryCondition;
use rollbem::body::{BodySetup, Side};
use rollbem::mesh::build::MeshBuilder;
use rollbem::mesh::{validate_and_orient, LoadedMesh};
use rollbem::post::norms::nodal_error_against;
use rollbem::post::NodeState;
use rollbem::scene::{BemSetup, Scene};
use std::sync::Arc;

/// Carter's shear, stick zone and creepage for the case's Hertz estimates.
fn carter_errors(name: &str) -> (f64, f64, f64) {
    let s = solve(name, &[]);
    // The BEM grid comes from the mesh; Carter from the case's Hertz estimates (a = 1 mm).
    let c = s.scene.carter_reference().unwrap();
    let mu_p0 = c.friction * c.peak_pressure;
    let max_q = nodal_error_against(&s.solution.x, &s.solution.shear, |x| c.shear(x), f64::INFINITY, mu_p0).max;
    let stick = s.solution.zones_of(NodeState::Stick);
    assert_eq!(stick.len(), 1, "{name}: stick zones {stick:?}");
    let [c0, c1] = c.stick_zone();
    let width_error = ((stick[0][1] - stick[0][0]) - (c1 - c0)).abs() / s.problem.grid.element_length();
    let creep_error = s.solution.creep / c.creep(s.scene.estimates.effective_radius) - 1.0;
    (max_q, width_error, creep_error)
}

/// Half-space blocks (paper Fig. 2) with the cylinders' profile: within 2 % of μp0 of Carter,
/// stick zone within one element, creepage within 1 % (measured 1.7 %, 0.1 element, 0.4 %).
#[test]
fn half_space_blocks_reproduce_carter() {
    let (q, w, xi) = carter_errors("carter_051_block");
    assert!(q < 0.02, "max |q − q_Carter| = {q} μp0");
    assert!(w < 1.0, "stick width off by {w} elements");
    assert!(xi.abs() < 0.01, "creep error {xi}");
}

/// True rollers R = 100 mm on rigid shafts: within 3 % of μp0 of Carter, stick zone within one
/// element (measured 2.2 %, 0.1 element). Carter is a half-space result, so the true geometry
/// is allowed to differ by its a/R effects.
#[test]
fn true_rollers_on_shafts_reproduce_carter() {
    let (q, w, xi) = carter_errors("carter_051_true");
    assert!(q < 0.03, "max |q − q_Carter| = {q} μp0");
    assert!(w < 1.0, "stick width off by {w} elements");
    assert!(xi.abs() < 0.02, "creep error {xi}");
}

/// The BEM block and the analytic half-space, on the same 21-element grid: tangential
/// tractions within 2 % of μp0.
#[test]
fn half_space_block_agrees_with_the_analytic_half_space() {
    let block = solve("carter_051_block", &[]);
    let analytic = solve("carter_051", &[]);
    let x = &analytic.solution.x;
    assert!(
        x.iter().zip(&block.solution.x).all(|(a, b)| (a - b).abs() < 1e-9),
        "grids differ"
    );
    let mu_p0 = 0.1 * analytic.scene.estimates.hertz_peak_pressure;
    let dq = analytic
        .solution
        .shear
        .iter()
        .zip(&block.solution.shear)
        .fold(0.0_f64, |m, (a, b)| m.max((a - b).abs()));
    assert!(dq / mu_p0 < 0.02, "max |q_block − q_half-space| = {} μp0", dq / mu_p0);
}

/// Paper Figs 14–15: half-space and true cylinders give nearly the same tractions and the same
/// zones; only the true geometry gives the approach of the shaft centres.
#[test]
fn fig14_half_space_and_true_cylinders_nearly_agree() {
    let hs = solve("fig14_half_space", &[]);
    let bem = solve("fig14_true_geometry", &[]);
    let p0 = hs.scene.estimates.hertz_peak_pressure;
    let mu = 0.2;
    let dq = hs
        .solution
        .shear
        .iter()
        .zip(&bem.solution.shear)
        .fold(0.0_f64, |m, (a, b)| m.max((a - b).abs()));
    assert!(dq / (mu * p0) < 0.05, "max |Δq| = {} μp0", dq / (mu * p0));
    assert!((hs.solution.creep / bem.solution.creep - 1.0).abs() < 0.03);
    assert_eq!(hs.regime, bem.regime);
    assert_eq!(hs.solution.slip_directions(), bem.solution.slip_directions());
    assert!(bem.solution.overlap > 0.0);
}

/// What only the true geometry gives: the approach of the shaft centres. Compared with the
/// closed form of an annulus on a rigid shaft under one Hertz contact (docs/references.md §6c,
/// summed over both rollers), at Q = 0. The formula itself is exact to O(a/R) (3e-4 relative at
/// a/R = 0.01, docs/references.md §6b); we allow 0.5 % for that and the BEM discretization.
#[test]
fn approach_of_the_shaft_centres_matches_the_annulus_on_shaft_formula() {
    use rollbem::analytic::shaft_roller_approach;
    use rollbem::material::Elastic;
    let steel = Elastic::new(210_000.0, 0.3);
    let al = Elastic::from_shear(23_000.0, 0.31);
    let steel_bj = Elastic::from_shear(82_000.0, 0.28);
    for (name, rollers) in [
        ("carter_051_true", [(100.0, 10.0, steel), (100.0, 10.0, steel)]),
        ("fig14_true_geometry", [(150.0, 15.0, al), (300.0, 30.0, steel_bj)]),
    ] {
        let s = solve(name, &["load.tangential.ratio=0.0"]);
        let (p, a) = (s.solution.normal_force, s.scene.estimates.hertz_half_width);
        let formula: f64 = rollers
            .iter()
            .map(|(r, rs, m)| shaft_roller_approach(p, *r, *rs, a, m))
            .sum();
        let rel = s.solution.overlap / formula - 1.0;
        println!(
            "{name}: δ0 BEM {:.6e}, formula {formula:.6e}, relative difference {rel:+.2e}",
            s.solution.overlap
        );
        assert!(rel.abs() < 5e-3, "{name}: δ0 {} vs {formula}", s.solution.overlap);
    }
}

/// Non-matching contact nodes: body B's 54 contact elements on |x| ≤ 1.5 mm are
/// carried to A's 21-element grid by interpolation. Against the node-to-node run: same zones,
/// pressure within 0.1 % of p0, shear within 5 % of μp0 and creepage within 3 % (measured 0.04 %,
/// 4.0 %, 2.3 %). The transfer costs tangential accuracy: the slip differentiates the
/// interpolated displacements (docs/validation.md; a body mesh of the grid's size but offset
/// nodes loses ~8 % of the creepage, so the shipped mesh is over twice as fine).
#[test]
fn non_matching_contact_nodes_are_transferred() {
    let matched = solve("carter_051_true", &[]);
    let moved = solve("carter_051_true_nonmatching", &[]);
    let p0 = matched.scene.estimates.hertz_peak_pressure;
    let diff = |a: &[f64], b: &[f64]| a.iter().zip(b).fold(0.0_f64, |m, (x, y)| m.max((x - y).abs()));
    assert!(diff(&matched.solution.pressure, &moved.solution.pressure) / p0 < 1e-3);
    assert!(diff(&matched.solution.shear, &moved.solution.shear) / (0.1 * p0) < 0.05);
    assert!((moved.solution.creep / matched.solution.creep - 1.0).abs() < 0.03);
    assert_eq!(
        matched.solution.zones_of(NodeState::Stick).len(),
        moved.solution.zones_of(NodeState::Stick).len()
    );
}

/// Non-matching BEM meshes under a tolerance: body B's contact elements end elsewhere than A's
/// (cases/carter_051_true_nonmatching.yaml: 54 on |x| ≤ 1.5 against the grid's 21 on
/// |x| ≤ 1.24), so each pass cuts B's mesh to the grid's elements inside the grid (src/mesh/cuts.rs), and the
/// passes and the results take the BEM bodies' stand-ins, as for matching meshes (before the
/// cuts conformed, B kept its own nodes, was carried over to the grid by interpolation and
/// solved with the full BEM in every pass, 4–5 times the time). At 1e-3 and 1e-4 its RMS
/// pressure and shear over the contact (on the matching run's grid) and its creepage agree
/// with the matching meshes' run at the same tolerance to within that tolerance (measured:
/// 1e-3 6.2e-7 p0, 1.2e-5 μp0, 9.8e-6; 1e-4 2.6e-7, 4.5e-6, 9.6e-6), on the same number of
/// elements, and its creepage with Carter's (μa/R*)(1 − √(1 − Q/μP)) within 0.5 % (the true
/// cylinders' own departure from the half-plane theory is 0.2 %).
#[test]
fn non_matching_meshes_follow_an_error_controlled_grid() {
    for tolerance in [1e-3, 1e-4] {
        let tol = format!("contact.grid.tolerance={tolerance:e}");
        let nonmatching = solve("carter_051_true_nonmatching", &[&tol]);
        let matching = solve("carter_051_true", &[&tol]);
        let (a, b) = (&nonmatching.solution, &matching.solution);
        let (ga, gb) = (
            nonmatching.adaptation.as_ref().expect("an error-controlled run"),
            matching.adaptation.as_ref().expect("an error-controlled run"),
        );
        agrees_with_matching("non-matching meshes", tolerance, &nonmatching, &matching);
        assert!(
            ga.results_from_stand_ins,
            "the stand-ins give the results at {tolerance:e}"
        );
        assert_eq!(
            nonmatching.problem.grid.n_elements(),
            matching.problem.grid.n_elements(),
            "the same grid at {tolerance:e}"
        );
        assert!(ga.refinements > 0 && gb.refinements > 0, "the grid was refined");
        let carter = 0.1 * 1.0 / 50.0 * (1.0 - (1.0f64 - 0.51).sqrt());
        assert!(
            (a.creep.abs() / carter - 1.0).abs() < 5e-3,
            "creepage {} against Carter {carter}",
            a.creep
        );
        assert!(b.creep.abs() > 0.0);
    }
}

/// A roller meshed on its own, coarser than the grid across the contact: body B of
/// cases/carter_051_true.yaml (R 100 on a rigid shaft of 10) rebuilt with 9 contact elements on
/// |x| ≤ 1.5 (ends every 1/3 mm, the grid's every 0.118 mm: all but the outer two inside grid
/// elements), its free circle graded from the contact (angles growing by 1.26) and 24 elements
/// on its shaft. Under a tolerance of 1e-3 each cut of its mesh takes the grid's elements inside
/// the grid, the stand-ins give the results, and they agree with the Gmsh meshes' matching run
/// within the tolerance (measured: 2.9e-6 p0, 3.3e-5 μp0, 1.9e-5 in the creepage).
#[test]
fn a_coarser_roller_meshed_on_its_own_follows_an_error_controlled_grid() {
    let tolerance = 1e-3;
    let (matching, case, generated) = carter_051_true_at(tolerance);
    let ends: Vec<f64> = (0..=9).map(|k| -1.5 + k as f64 / 3.0).collect();
    let own = steel_roller_on_a_shaft(&case, Side::B, &ends, "<roller meshed on its own>");
    let bodies: [Arc<dyn BodySetup>; 2] = [generated.bodies[0].clone(), Arc::new(own)];
    let run = rollbem::app::solve_scene(Scene::new(case, bodies), std::time::Instant::now())
        .expect("the roller meshed on its own meets the tolerance");
    let a = run.adaptation.as_ref().expect("an error-controlled run");
    assert!(a.results_from_stand_ins, "the stand-ins give the results");
    agrees_with_matching("roller meshed on its own", tolerance, &run, &matching);
}

/// cases/carter_051_true.yaml at `tolerance`: its run, the case and its scene (whose bodies the
/// tests replace one at a time).
fn carter_051_true_at(tolerance: f64) -> (rollbem::app::Solved, rollbem::case::LoadedCase, Scene) {
    let tol = format!("contact.grid.tolerance={tolerance:e}");
    let matching = solve("carter_051_true", &[&tol]);
    let case = rollbem::app::load_case(&crate::common::case_path("carter_051_true"), &[&tol]).unwrap();
    let generated = Scene::from_case(&case).unwrap();
    (matching, case, generated)
}

/// A steel roller of R 100 on a rigid shaft of 10 as body `side` of carter_051_true (A above
/// the contact, B below), meshed on its own: one contact element between each pair of
/// neighbouring `ends` (x, increasing), its free circle graded from the contact (angles growing
/// by 1.26 over 24 elements a side), 24 elements on its shaft.
fn steel_roller_on_a_shaft(case: &rollbem::case::LoadedCase, side: Side, ends: &[f64], label: &str) -> BemSetup {
    let (r, up) = (100.0, if side == Side::A { 1.0 } else { -1.0 });
    let centre = [0.0, up * r];
    let surface = |x: f64| [x, up * (r - (r * r - x * x).sqrt())];
    // Counter-clockwise: along +x at A's bottom, along −x at B's top.
    let order: Vec<f64> = match side {
        Side::A => ends.to_vec(),
        Side::B => ends.iter().rev().copied().collect(),
    };
    let mut b = MeshBuilder::new(true, label);
    b.move_to(surface(order[0]));
    for &x in &order[1..] {
        b.arc_to(centre, surface(x), 1, true, 1.0, "contact");
    }
    b.arc_to(centre, [0.0, 2.0 * centre[1]], 24, true, 1.26, "free");
    b.arc_to(centre, surface(order[0]), 24, true, 1.0 / 1.26, "free");
    b.circle(centre, 10.0, 24, "shaft");
    let mut mesh = b.finish();
    validate_and_orient(&mut mesh).expect("the roller mesh is valid");
    let loaded = LoadedMesh::new(label, mesh, Vec::new(), "contact").unwrap();
    let conditions = vec![
        ("free".to_string(), BoundaryCondition::Free),
        ("shaft".to_string(), BoundaryCondition::Fixed),
        ("contact".to_string(), BoundaryCondition::Contact),
    ];
    BemSetup::on_start_mesh(loaded, case.material("steel"), "contact".into(), conditions, None, None)
}

/// Asserts that `run`'s RMS pressure and shear over the contact (on `matching`'s grid) and its
/// creepage differ from `matching`'s within `tolerance`, printing them and both grids' sizes.
fn agrees_with_matching(label: &str, tolerance: f64, run: &rollbem::app::Solved, matching: &rollbem::app::Solved) {
    let errors = crate::adaptive::errors_against(matching, run);
    println!(
        "{label} against the matching meshes at {tolerance:e}: {} and {} elements, p, q, ξ {:.2e} {:.2e} {:.2e}",
        run.problem.grid.n_elements(),
        matching.problem.grid.n_elements(),
        errors.0,
        errors.1,
        errors.2
    );
    crate::adaptive::assert_true_errors_within(label, tolerance, errors);
}

/// A roller whose mesh has only four contact elements (on |x| ≤ 1.2, the run's start grid)
/// runs under a tolerance and agrees with the matching rollers of cases/carter_051_true.yaml
/// within it (measured 1.7e-4 p0, 2.4e-4 μp0, 1.2e-5 in the creepage: its free circle's long
/// elements next to the contact fail the stand-ins' own check, and the final grid is solved
/// with the full BEM). Its stand-in's series have the degree the coarsest level allows (5 on
/// 12 nodes) on every level; before, the start grid's fit took degree 5 and the next level's 8,
/// and their Richardson extrapolation panicked on the matrices' shapes.
#[test]
fn a_roller_with_four_contact_elements_runs_under_a_tolerance() {
    let tolerance = 1e-3;
    let (matching, case, generated) = carter_051_true_at(tolerance);
    let ends = [-1.2, -0.6, 0.0, 0.6, 1.2];
    let own = steel_roller_on_a_shaft(&case, Side::A, &ends, "<roller with four contact elements>");
    assert_eq!(own.mesh.contact_grid().n_elements(), 4);
    let bodies: [Arc<dyn BodySetup>; 2] = [Arc::new(own), generated.bodies[1].clone()];
    let run = rollbem::app::solve_scene(Scene::new(case, bodies), std::time::Instant::now())
        .expect("the roller with four contact elements meets the tolerance");
    agrees_with_matching("roller with four contact elements", tolerance, &run, &matching);
}
