//! Stall detection (src/contact/stall.rs): a tolerance below the round-off of the residual, with
//! a huge iteration budget, must end on the stall test of every method — quickly, with exit 2,
//! `converged: false` and the residual history in summary.json — instead of running through the
//! budget (before: 100 000 NORM/TANG pairs in about 5 minutes, 100 000 plain Newton steps or
//! Gauss–Seidel sweeps). The message says that the tolerance is below round-off, not that more
//! iterations are needed.

use crate::common::{case_path, rollbem};
use rollbem::contact::stall::{GAUSS_SEIDEL_STALL, NORM_TANG_STALL, ROUNDOFF_STALL};
use std::path::Path;

const CARTER: &str = r#"
title: "stall test: Carter, Q/(mu P) = 0.51"
materials:
  steel: {E: 210000.0, nu: 0.3}
bodies:
  A: {model: half_space, material: steel, radius: 100.0}
  B: {model: half_space, material: steel, radius: 100.0}
contact:
  friction: 0.1
  grid: {elements: 21, extent: 1.3}
load:
  normal: {force: 1812.4573}
  tangential: {ratio: 0.51}
output: {dir: out}
"#;

/// Runs the case with an unreachable tolerance; returns summary.json.
fn run_unreachable(dir: &Path, method: &str) -> serde_json::Value {
    let case = dir.join(format!("{method}.yaml"));
    std::fs::write(&case, CARTER).unwrap();
    let out = dir.join(method);
    let (code, _, stderr) = rollbem(&[
        "run",
        case.to_str().unwrap(),
        "--out",
        out.to_str().unwrap(),
        "--set",
        "solver.max_iterations=100000",
        "--set",
        "solver.tolerance=1e-300",
        "--set",
        &format!("solver.method={method}"),
    ]);
    assert_eq!(code, 2, "{method}: {stderr}");
    assert!(stderr.contains("did not converge"), "{method}: {stderr}");
    // The budget of 100 000 was not spent: the message must not send the user for more, but
    // say that the tolerance is below round-off.
    assert!(
        stderr.contains("below what double precision gives") && !stderr.contains("give more solver.max_iterations"),
        "{method}: {stderr}"
    );
    serde_json::from_str(&std::fs::read_to_string(out.join("summary.json")).unwrap()).unwrap()
}

#[test]
fn an_unreachable_tolerance_ends_on_the_stall_test_of_every_method() {
    let dir = tempfile::tempdir().unwrap();
    // Upper bounds on the iterations before the stall test ends the run: the residual reaches
    // round-off (about 1e-14) within the counts a converging run needs (5 Newton steps, 1 pair,
    // about 1 100 sweeps), then the patience of the rule runs out: for the Newton methods the
    // round-off rule (no halving in 3 steps) and no restart; round-off fluctuations may pass the
    // 10 % margin a few more times in the long Gauss–Seidel runs.
    // Measured: 8, 8, 11, 6 080 (before the round-off rule: 110 with 8 restarts, 111, 11, 6 080;
    // before the stall tests: 81, 100 000, 100 000, 100 000).
    let bounds = [
        ("newton", 10 + ROUNDOFF_STALL.patience),
        ("newton_plain", 10 + ROUNDOFF_STALL.patience),
        ("norm_tang", 5 + NORM_TANG_STALL.patience),
        ("gauss_seidel", 4 * GAUSS_SEIDEL_STALL.patience),
    ];
    for (method, bound) in bounds {
        let s = run_unreachable(dir.path(), method);
        assert_eq!(s["converged"], false, "{method}");
        let iterations = s["iterations"].as_u64().unwrap() as usize;
        let history = s["solver"]["history"].as_array().unwrap();
        assert!(iterations <= bound, "{method}: {iterations} iterations (bound {bound})");
        assert_eq!(history.len(), iterations, "{method}: one history record per iteration");
        // It stalled at round-off, not on a wrong answer.
        let residual = s["residual"].as_f64().unwrap();
        assert!(residual < 1e-12, "{method}: residual {residual}");
        assert!(history.iter().all(|h| h["residual"].as_f64().unwrap().is_finite()));
    }
}

/// Carter's shipped case at `solver.tolerance=1e-20` reaches round-off (about 1e-14) in 5 Newton
/// steps. Before the round-off rule it spent 110 steps over 8 restarts and exited 2 advising
/// more `solver.max_iterations`; now it stops after a few steps at round-off, restarts nothing,
/// and says that the tolerance is below what double precision gives, naming the smallest
/// residual reached and a tolerance that converges (checked here too).
#[test]
fn a_tolerance_below_round_off_stops_at_round_off_and_says_so() {
    let dir = tempfile::tempdir().unwrap();
    let case = case_path("carter_051");
    let run = |tolerance: &str, out: &str| {
        let out = dir.path().join(out);
        let set = format!("solver.tolerance={tolerance}");
        let (code, _, stderr) = rollbem(&[
            "run",
            case.to_str().unwrap(),
            "--out",
            out.to_str().unwrap(),
            "--set",
            &set,
        ]);
        let summary: serde_json::Value =
            serde_json::from_str(&std::fs::read_to_string(out.join("summary.json")).unwrap()).unwrap();
        (code, stderr, summary)
    };
    let (code, stderr, s) = run("1e-20", "tiny");
    assert_eq!(code, 2, "{stderr}");
    assert!(
        stderr.contains("round-off") && stderr.contains("below what double precision gives"),
        "{stderr}"
    );
    assert!(!stderr.contains("give more solver.max_iterations"), "{stderr}");
    assert!(!stderr.contains("restarted"), "no restart at round-off: {stderr}");
    assert_eq!(s["solver"]["fallbacks"].as_array().unwrap().len(), 0);
    let iterations = s["iterations"].as_u64().unwrap() as usize;
    assert!(iterations <= 10 + ROUNDOFF_STALL.patience, "{iterations} iterations");
    // The smallest residual reached is named, and the advised tolerance is 10 × it, rounded up
    // to a power of ten.
    let history = s["solver"]["history"].as_array().unwrap();
    let smallest = history
        .iter()
        .map(|h| h["residual"].as_f64().unwrap())
        .fold(s["residual"].as_f64().unwrap(), f64::min);
    assert!(smallest < 1e-13, "smallest residual {smallest:e}");
    assert!(stderr.contains(&format!("{smallest:.2e}")), "{stderr}");
    let advised = 10f64.powf((10.0 * smallest).log10().ceil());
    let advised = format!("{advised:.0e}");
    assert!(
        stderr.contains(&format!("set solver.tolerance to {advised} or more")),
        "{stderr}"
    );
    // The advice holds: that tolerance converges.
    let (code, stderr, s) = run(&advised, "advised");
    assert_eq!(code, 0, "solver.tolerance={advised}: {stderr}");
    assert_eq!(s["converged"], true);
}
