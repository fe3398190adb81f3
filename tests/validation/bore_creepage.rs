//! The creepage's error on the conformal bore of tests/data/bore_c30_tractive.yaml (roller R 30
//! in a ring bore R 30.6, μ 0.2, Q/μP 0.5; ξ ≈ 9.79e-4, two thirds of it the bore's free-rolling
//! part), against ξ = 9.788815e-4 from the same geometry meshed 4 times finer at tolerance 2e-5
//! (docs/validation.md, "The creepage in a bore: measured, a remedy tried and not kept"): the
//! estimate with the geometry's share (src/adapt/geometry_share.rs) within [1/3, 3] of the true
//! error (docs/validation.md, "The creepage's estimate in a bore: the geometry's share"), and
//! two ignored measurements of why the grid's bisection alone under-reads it (docs/validation.md,
//! "The creepage in a bore under bisection"), which print tables (about a minute each):
//! `cargo test --release --test validation bore_creepage -- --ignored --nocapture`.

use crate::adaptive::carter_errors_of;
use crate::stand_in::solved;
use rollbem::adapt::cells::DyadicGrid;
use rollbem::adapt::geometry_share::geometry_share;
use rollbem::post::ContactSolution;
use rollbem::scene::Scene;

/// The bore's creepage from the 4 times finer meshes at tolerance 2e-5.
const REFERENCE: f64 = 9.788815e-4;

fn bore_path() -> std::path::PathBuf {
    std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/data/bore_c30_tractive.yaml")
}

fn adapted(path: &std::path::Path, set: &[String]) -> (Scene, rollbem::adapt::Adapted) {
    let scene = Scene::from_case(&rollbem::case::load(path, set).expect("loads")).expect("scene");
    let a = rollbem::adapt::solve(&scene).expect("solved");
    (scene, a)
}

/// Carter's complete-slip creepage μa/R* of `scene` [-].
fn complete_slip_creepage(scene: &Scene) -> f64 {
    scene.friction() * scene.estimates.hertz_half_width / scene.estimates.effective_radius.abs()
}

/// The bore's creepage estimate against its true error at tolerances 1e-3 to 1e-4: within
/// [1/3, 3] (measured 0.80–1.24; the grid's bisection alone read 0.03–0.81, the runs ending on
/// the same grids; docs/validation.md, "The creepage's estimate in a bore: the geometry's
/// share"). The reference's own error, about 2e-6 (the shipped meshes
/// at 1e-5 and meshes half as fine at 2e-5 lie within 2.1e-6 of it), is a fortieth of the
/// smallest true error here, so the window is the estimate's alone.
#[test]
fn the_bore_s_creepage_estimate_is_within_3_times_its_true_error() {
    let mut effectivities = Vec::new();
    for tol in ["1e-3", "5e-4", "3e-4", "2e-4", "1e-4"] {
        let (_, a) = adapted(&bore_path(), &[format!("contact.grid.tolerance={tol}")]);
        let elements = a.problem.grid.n_elements();
        let e = a.adaptation.and_then(|a| a.estimate).expect("an estimate");
        let truth = (a.state.creep / REFERENCE - 1.0).abs();
        eprintln!(
            "bore at {tol}: {elements} elements, creepage estimate {:.2e}, true error {truth:.2e}, effectivity {:.2}",
            e.creep_rel,
            e.creep_rel / truth
        );
        assert!(
            truth > 2e-5,
            "the true error at {tol}, {truth:.2e}, is not far above the reference's own"
        );
        effectivities.push(e.creep_rel / truth);
    }
    assert!(
        effectivities.iter().all(|r| (1.0 / 3.0..=3.0).contains(r)),
        "{effectivities:?}"
    );
}

/// The geometry's share of the bore's creepage is that beyond Carter's, which the half-plane
/// twin solves: |ξ − ξ_C|/(|ξ − ξ_C| + ξ_C) with ξ_C = (μa/R*)(1 − √(1 − Q/μP)) = 3.4458e-4.
/// The twin's creepage is 4.2 % above ξ_C (w 0.6334 against 0.6480): the half-space model's gap
/// is the two circles', not Hertz's parabola, whose quartic term is 3a²/(4R²) ≈ 7 % of the gap
/// at the contact's ends here (a/R ≈ 0.3). The bound, 0.02, covers that and the twin's grid
/// (w moves by 0.0017 from the 52-element start grid to its double bisection); a scene of
/// half-planes has none.
#[test]
fn the_geometry_s_share_is_the_creepage_beyond_carter_s() {
    let scene = Scene::from_case(&rollbem::case::load(&bore_path(), &[]).expect("loads")).expect("scene");
    let carter = scene
        .carter_reference()
        .expect("a ratio")
        .creep(scene.estimates.effective_radius.abs())
        .abs();
    let load = scene.estimates.normal_force;
    let w = geometry_share(&scene, &scene.grid, REFERENCE, || load);
    let expected = (REFERENCE - carter) / REFERENCE;
    assert!(
        (w - expected).abs() < 0.02,
        "share {w} against {expected} (ξ_C {carter:.6e})"
    );
    let half_planes = crate::common::case_path("carter2d_contact");
    let scene = Scene::from_case(&rollbem::case::load(&half_planes, &[]).expect("loads")).expect("scene");
    assert_eq!(
        geometry_share(&scene, &scene.grid, 1e-3, || scene.estimates.normal_force),
        0.0
    );
}

/// The final grid at tolerance 1e-3 bisected uniformly three times: the creepage's error
/// changes sign (−2.65e-4, −1.43e-4, +1.73e-5, −1.93e-5), so a grid and its bisection can agree
/// by chance. Asserts the sign change, the finding the docs table rests on.
#[test]
#[ignore]
fn the_bore_s_creepage_error_changes_sign_under_bisection() {
    let (scene, a) = adapted(&bore_path(), &["contact.grid.tolerance=1e-3".to_string()]);
    let mut g = DyadicGrid::new(&a.problem.grid);
    let mut errors = Vec::new();
    for k in 0..4 {
        let grid = g.grid();
        let s = solved(&scene, &grid);
        let longest = grid.element_length();
        // The stick/slip point near x = −3.6, not the contact's trailing edge at −7.93.
        let transition = (1..s.x.len())
            .find(|&i| s.state[i - 1] != s.state[i] && s.x[i] < 0.0 && s.x[i] > -6.0)
            .map(|i| (s.x[i - 1], s.x[i]));
        let e = s.creep / REFERENCE - 1.0;
        eprintln!(
            "bisected {k}: {} elements, longest {longest:.3e}, stick/slip between {transition:.4?}, ξ {:.6e}, error {e:.2e}",
            grid.n_elements(),
            s.creep
        );
        errors.push(e);
        g = g.bisected();
    }
    assert!(
        errors.iter().any(|&e| e > 0.0) && errors.iter().any(|&e| e < 0.0),
        "{errors:?}"
    );
}

/// A candidate creepage estimate: the shear's estimate times μa/R* over |ξ| (the creepage a
/// shear error of that size over the contact would move). On the bore it lies within [1/3, 3] of
/// the true error at tolerances 1e-3 to 1e-4 (measured 1.24–1.97), where the bisection's reads
/// 0.03–0.81; on Carter's half-planes it over-reads 2 to 340 times, where the bisection's is
/// within 0.33–1.24 but for Q/μP 0.99 at 1e-5 (whose true error nearly cancels): not adopted
/// as it stands; the error control weights it by the share of ξ the bodies' true geometry sets,
/// zero on half-planes (src/adapt/geometry_share.rs), and the printed estimate now holds it.
/// Asserts the bore's window and Carter's over-reading, the two facts the docs quote.
#[test]
#[ignore]
fn a_creepage_estimate_from_the_shear_estimate_fits_the_bore_not_carter() {
    let mut bore = Vec::new();
    for tol in ["1e-3", "5e-4", "3e-4", "2e-4", "1e-4"] {
        let (scene, a) = adapted(&bore_path(), &[format!("contact.grid.tolerance={tol}")]);
        let e = a.adaptation.and_then(|a| a.estimate).expect("an estimate");
        let truth = (a.state.creep / REFERENCE - 1.0).abs();
        let candidate = e.shear_rms * complete_slip_creepage(&scene) / a.state.creep.abs();
        eprintln!(
            "bore at {tol}: estimate {:.2e} (effectivity {:.2}), candidate {candidate:.2e} ({:.2}), true {truth:.2e}",
            e.creep_rel,
            e.creep_rel / truth,
            candidate / truth
        );
        bore.push(candidate / truth);
    }
    let carter = crate::common::case_path("carter2d_contact");
    let mut largest = 0.0_f64;
    for ratio in ["0.05", "0.3", "0.64", "0.9"] {
        for tol in ["1e-3", "1e-4", "1e-5"] {
            let set = [
                format!("contact.grid.tolerance={tol}"),
                format!("load.tangential.ratio={ratio}"),
            ];
            let (scene, a) = adapted(&carter, &set);
            let e = a.adaptation.clone().and_then(|a| a.estimate).expect("an estimate");
            let sol = ContactSolution::from_state(&a.problem, &a.state);
            let [_, _, truth] = carter_errors_of(&a.scene, &sol);
            let scale = complete_slip_creepage(&scene);
            let candidate = e.shear_rms * scale / a.state.creep.abs().max(0.05 * scale);
            eprintln!(
                "carter {ratio} at {tol}: bisection {:.2e} ({:.2}), candidate {candidate:.2e} ({:.2}), true {truth:.2e}",
                e.creep_rel,
                e.creep_rel / truth,
                candidate / truth
            );
            largest = largest.max(candidate / truth);
        }
    }
    assert!(bore.iter().all(|r| (1.0 / 3.0..=3.0).contains(r)), "{bore:?}");
    assert!(largest > 10.0, "{largest}");
}
