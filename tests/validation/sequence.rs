//! Sequences of runs on one assembly (src/sequence.rs) against the same runs solved cold, one
//! by one, through the public API: the tractions agree to the Newton tolerance, the shared
//! flexibilities are bit for bit the per-run ones, and the warm starts take fewer Newton
//! iterations than the cold ones.

use rollbem::post::Solved;
use rollbem::scene::Scene;
use rollbem::sequence::{SequenceError, Shared, Start};

/// The scene of a shipped case with overrides.
fn scene(name: &str, set: &[String]) -> Scene {
    let case = rollbem::case::load(&crate::common::case_path(name), set).expect("loads");
    Scene::from_case(&case).expect("scene")
}

/// Largest difference of the tractions of two solutions over the peak pressure [-].
fn traction_difference(a: &Solved, b: &Solved) -> f64 {
    let p0 = a.solution.pressure.iter().fold(0.0f64, |m, p| m.max(p.abs()));
    let d = |x: &[f64], y: &[f64]| x.iter().zip(y).fold(0.0f64, |m, (u, v)| m.max((u - v).abs()));
    d(&a.solution.pressure, &b.solution.pressure).max(d(&a.solution.shear, &b.solution.shear)) / p0
}

/// The runs of `key` = `values` on case `name` (with `set`), solved in one chain on the
/// assembly of the first and cold one by one: each pair's tractions agree within `tolerance`
/// of the peak pressure and their flexibilities are identical; returns the Newton iterations
/// (warm-chain total, cold total).
fn compare(name: &str, set: &[&str], key: &str, values: &[&str], tolerance: f64) -> (usize, usize) {
    let with = |v: &str| {
        let mut s: Vec<String> = set.iter().map(|s| s.to_string()).collect();
        s.push(format!("{key}={v}"));
        s
    };
    let shared = Shared::new(&scene(name, &with(values[0]))).expect("shared assembly");
    let mut chain = shared.chain();
    let (mut warm_iterations, mut cold_iterations) = (0, 0);
    for (k, v) in values.iter().enumerate() {
        let run = scene(name, &with(v));
        assert!(shared.shares(&run), "{name} {key}={v} shares the assembly");
        let run = shared.admit(run).expect("admitted");
        let (warm, start) = chain.solve(run).expect("warm run");
        assert_eq!(start, if k == 0 { Start::Cold } else { Start::Warm });
        let cold = rollbem::app::solve_case(crate::common::case_path(name).as_path(), &with(v)).expect("cold run");
        assert!(warm.report.converged && cold.report.converged, "{name} {key}={v}");
        let diff = traction_difference(&cold, &warm);
        assert!(diff <= tolerance, "{name} {key}={v}: tractions differ by {diff:e} p0");
        let (fw, fc) = (&warm.problem.flex, &cold.problem.flex);
        assert!(
            fw.hp == fc.hp && fw.hq == fc.hq && fw.wp == fc.wp && fw.wq == fc.wq && warm.problem.bp == cold.problem.bp,
            "{name} {key}={v}: the shared assembly is not the per-run one"
        );
        assert_eq!(warm.problem.h0, cold.problem.h0);
        eprintln!(
            "{name} {key}={v}: {} iterations warm, {} cold, tractions within {diff:.1e} p0",
            warm.report.iterations, cold.report.iterations
        );
        if k > 0 {
            warm_iterations += warm.report.iterations;
            cold_iterations += cold.report.iterations;
        }
    }
    (warm_iterations, cold_iterations)
}

/// Tractions of warm-started runs against cold ones: the Newton tolerance 1e-10 on the scaled
/// residual bounds both runs' tractions to about 1e-10 p0 of the exact discrete solution;
/// 1e-8 p0 leaves room for the conditioning of the Newton system.
const TOLERANCE: f64 = 1e-8;

#[test]
fn a_ratio_sweep_on_one_assembly_equals_the_cold_runs_in_fewer_iterations() {
    let values = ["0.0", "0.2", "0.4", "0.6", "0.64", "0.8", "0.95"];
    let (warm, cold) = compare("carter2d_contact", &[], "load.tangential.ratio", &values, TOLERANCE);
    assert!(warm < cold, "warm {warm} against cold {cold} iterations");
}

#[test]
fn friction_creepage_and_dissimilar_sweeps_equal_the_cold_runs() {
    let (warm, cold) = compare(
        "dissimilar_al_steel_075",
        &[],
        "contact.friction",
        &["0.1", "0.15", "0.2", "0.3"],
        TOLERANCE,
    );
    assert!(warm < cold, "friction: warm {warm} against cold {cold} iterations");
    let creep = ["-0.0002", "-0.00015", "-0.0001", "-0.00005"];
    let (warm, cold) = compare(
        "carter_051",
        &["load.tangential.ratio=null"],
        "load.tangential.creep",
        &creep,
        TOLERANCE,
    );
    assert!(warm < cold, "creepage: warm {warm} against cold {cold} iterations");
}

/// Under a falling friction law (cases/veldep_fric.yaml) the static coefficient and the speed
/// are part of the law: a chain that varies them must solve each run with its own law, not the
/// first run's (the tolerance of the law's fixed point, 1e-10 μ_s, and the Newton tolerance
/// bound both to about 1e-8 p0).
#[test]
fn a_falling_law_follows_the_friction_and_speed_of_each_run() {
    compare(
        "veldep_fric",
        &[],
        "contact.friction",
        &["0.3", "0.33", "0.36"],
        TOLERANCE,
    );
    compare(
        "veldep_fric",
        &[],
        "load.speed",
        &["45000", "30000", "60000"],
        TOLERANCE,
    );
}

#[test]
fn bem_bodies_share_their_condensation() {
    let (warm, cold) = compare(
        "carter_051_true",
        &["contact.grid.elements=16"],
        "load.tangential.ratio",
        &["0.4", "0.51", "0.6"],
        TOLERANCE,
    );
    assert!(warm < cold, "warm {warm} against cold {cold} iterations");
}

#[test]
fn grids_geometry_and_error_control_do_not_share() {
    let base = scene("carter2d_contact", &[]);
    let shared = Shared::new(&base).expect("shared");
    let other = |set: &str| shared.shares(&scene("carter2d_contact", &[set.to_string()]));
    assert!(other("load.tangential.ratio=0.3") && other("contact.friction=0.5") && other("solver.tolerance=1e-9"));
    // A normal load sizes the grid around its Hertz contact: another grid, another assembly.
    assert!(!other("load.normal.force=100.0"));
    assert!(!other("contact.grid.elements=40") && !other("bodies.A.radius=900.0"));
    assert!(!other("materials.steel.G=80000.0"));
    // With the grid's half-length fixed, the normal load shares.
    let fixed = |p: &str| {
        let set = [
            "contact.grid.half_length=1.5".to_string(),
            format!("load.normal.force={p}"),
        ];
        scene("carter2d_contact", &set)
    };
    assert!(Shared::new(&fixed("178.896248"))
        .expect("shared")
        .shares(&fixed("120.0")));
    let adaptive = scene("carter2d_contact", &["contact.grid.tolerance=1e-3".to_string()]);
    assert!(matches!(Shared::new(&adaptive), Err(SequenceError::AdaptiveGrid)));
}

/// Error-controlled runs in a chain (src/sequence.rs, "Error-controlled chains"): carter_051 at
/// the tolerance 1e-4 over Q/μP from 0.2 to 0.8, each run started warm from the last one's
/// solution, on its own start grid (the sweep's [`GridReuse::StartGrid`]) and on the last
/// one's final grid merged twice ([`GridReuse::LastGrid`]: the loop's entry from a given grid).
/// Every run of both chains meets the tolerance in the true RMS errors of p/p0 and q/(μp0)
/// against Hertz and Carter's closed form (the parabolic profile of Carter's solution departs
/// from the case's circles by (a/R)²/4 = 2.5e-5 p0, a quarter of the tolerance) and in its own
/// estimate, and agrees with the cold error-controlled run (every run alone, from the start
/// grid) within twice the tolerance: both are within it of the exact solution, on other grids.
/// (Measured, the run of Q/μP = 0.65 on the last grid: 1.08e-4 in q, each 4–5e-5 from Carter.)
/// On the start grid
/// the passes see the cold run's solutions to the Newton tolerance, so they refine to the
/// cold run's grids: the chained run is the cold one, its tractions within 1e-8 p0 (the
/// sequence's TOLERANCE), whatever run precedes it; a sweep's result does not depend on its
/// chains (its threads).
#[test]
fn error_controlled_chains_meet_the_tolerance_and_agree_with_the_cold_runs() {
    use crate::adaptive::{carter_errors, errors_against};
    use rollbem::sequence::{GridChain, GridReuse};
    let tolerance = 1e-4;
    let tol = format!("contact.grid.tolerance={tolerance:e}");
    let values = ["0.2", "0.35", "0.51", "0.65", "0.8"];
    let set = |v: &str| vec![tol.clone(), format!("load.tangential.ratio={v}")];
    let cold: Vec<Solved> = values
        .iter()
        .map(|v| rollbem::app::solve_case(crate::common::case_path("carter_051").as_path(), &set(v)).expect("cold"))
        .collect();
    for reuse in [GridReuse::StartGrid, GridReuse::LastGrid { merged: 2 }] {
        let mut chain = GridChain::new(reuse);
        for (k, v) in values.iter().enumerate() {
            assert_eq!(chain.is_warm(), k > 0, "{reuse:?}: the chain carries its last run");
            let run = chain
                .solve_with(scene("carter_051", &set(v)), std::time::Instant::now(), Clone::clone)
                .expect("chained run");
            let label = format!("carter_051 Q/μP = {v}, {reuse:?}");
            let estimate = run.adaptation.as_ref().and_then(|a| a.estimate).expect("an estimate");
            assert!(estimate.within(tolerance), "{label}: estimate {estimate:?}");
            let [p, q, xi] = carter_errors(&run);
            assert!(
                p <= tolerance && q <= tolerance && xi <= tolerance,
                "{label}: true errors p {p:.3e}, q {q:.3e}, creepage {xi:.3e}"
            );
            let (dp, dq, dxi) = errors_against(&cold[k], &run);
            let apart = 2.0 * tolerance;
            assert!(
                dp <= apart && dq <= apart && dxi <= apart,
                "{label}: against the cold run p {dp:.3e}, q {dq:.3e}, creepage {dxi:.3e}"
            );
            let (n, n_cold) = (run.problem.grid.n_elements(), cold[k].problem.grid.n_elements());
            let iterations = |s: &Solved| {
                let a = s.adaptation.as_ref().expect("passes");
                a.steps.iter().map(|p| p.iterations).sum::<usize>()
            };
            eprintln!(
                "{label}: {n} elements ({n_cold} cold), {} Newton iterations ({} cold), true errors \
                 p {p:.2e} q {q:.2e}, against cold p {dp:.1e} q {dq:.1e}",
                iterations(&run),
                iterations(&cold[k])
            );
            if reuse == GridReuse::StartGrid {
                assert_eq!(
                    run.problem.grid.edges, cold[k].problem.grid.edges,
                    "{label}: the cold run's grid"
                );
                let diff = traction_difference(&cold[k], &run);
                assert!(
                    diff <= TOLERANCE,
                    "{label}: tractions differ from the cold run's by {diff:e} p0"
                );
            }
        }
    }
}

/// An error-controlled chain under a prescribed creepage (carter_051, ξ from −2e-4 to −5e-5 at
/// 1e-4): the warm start takes the run's own creepage, not the last run's (the Newton method
/// keeps a prescribed unknown where it starts), so each run on its start grid is the cold run,
/// its grid and tractions (within the sequence's TOLERANCE of p0) and its creepage exactly.
#[test]
fn an_error_controlled_chain_under_a_prescribed_creepage_solves_each_run_at_its_own() {
    use rollbem::sequence::GridChain;
    let set = |xi: &str| {
        vec![
            "contact.grid.tolerance=1e-4".to_string(),
            "load.tangential.ratio=null".to_string(),
            format!("load.tangential.creep={xi}"),
        ]
    };
    let mut chain = GridChain::default();
    for xi in ["-0.0002", "-0.00015", "-0.0001", "-0.00005"] {
        let run = chain
            .solve_with(scene("carter_051", &set(xi)), std::time::Instant::now(), Clone::clone)
            .expect("chained run");
        let cold = rollbem::app::solve_case(crate::common::case_path("carter_051").as_path(), &set(xi)).expect("cold");
        assert_eq!(
            run.solution.creep,
            xi.parse::<f64>().unwrap(),
            "ξ = {xi}: its own creepage"
        );
        assert_eq!(
            run.problem.grid.edges, cold.problem.grid.edges,
            "ξ = {xi}: the cold run's grid"
        );
        let diff = traction_difference(&cold, &run);
        assert!(
            diff <= TOLERANCE,
            "ξ = {xi}: tractions differ from the cold run's by {diff:e} p0"
        );
    }
}

/// Every shipped steady case on a fixed grid, its friction coefficient swept in a chain of
/// three (μ, 1.02μ, 1.04μ: the third run starts from the secant extrapolation of the first
/// two) on one assembly: each warm run equals its cold run to [`TOLERANCE`] and shares its
/// flexibilities bit for bit (`compare`). Transient histories and error-controlled grids are
/// left to their own tests (tests/validation/transient.rs, the error-controlled chains above).
#[test]
fn every_shipped_steady_case_swept_in_a_chain_equals_its_cold_runs() {
    let mut swept = Vec::new();
    for name in crate::solver::shipped_cases() {
        let case = rollbem::case::load(&crate::common::case_path(&name), &[] as &[String]).expect("loads");
        if case.case.transient.is_some() || Scene::from_case(&case).expect("scene").grid_control.is_some() {
            continue;
        }
        let mu = case.case.contact.friction;
        let values: Vec<String> = [1.0, 1.02, 1.04].iter().map(|f| format!("{}", mu * f)).collect();
        let values: Vec<&str> = values.iter().map(String::as_str).collect();
        compare(&name, &[], "contact.friction", &values, TOLERANCE);
        swept.push(name);
    }
    assert!(swept.len() >= 30, "swept {} cases: {swept:?}", swept.len());
}
