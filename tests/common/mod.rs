//! Helpers shared by the integration tests.
#![allow(dead_code)]

use rollbem::app::{self, Solved};
use std::path::{Path, PathBuf};
use std::process::Command;

/// Path of a shipped case by its stem.
pub fn case_path(name: &str) -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
        .join("cases")
        .join(format!("{name}.yaml"))
}

/// Loads a shipped case with `key=value` overrides and solves it (no files written); panics
/// with the residual history if it does not converge.
pub fn solve(name: &str, overrides: &[&str]) -> Solved {
    let solved = app::solve_case(&case_path(name), overrides).unwrap_or_else(|e| panic!("{name}: {e}"));
    assert!(
        solved.report.converged,
        "{name} {overrides:?} did not converge: {:?}",
        solved.report.history
    );
    solved
}

/// A fast half-space case (Carter, Q/μP = 0.51, 21 elements), without an output folder.
pub const CARTER_CASE: &str = r#"
title: "cli test"
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
"#;

/// Runs the `rollbem` binary: (exit code, stdout, stderr).
pub fn rollbem(args: &[&str]) -> (i32, String, String) {
    rollbem_with(None, &[], args)
}

/// Runs the `rollbem` binary in `cwd` (None: this process's folder) with extra environment
/// (the fault injection of the tests is cleared first): (exit code, stdout, stderr); -1 when
/// it was killed by a signal.
pub fn rollbem_with(cwd: Option<&Path>, env: &[(&str, &str)], args: &[&str]) -> (i32, String, String) {
    let mut cmd = Command::new(env!("CARGO_BIN_EXE_rollbem"));
    if let Some(dir) = cwd {
        cmd.current_dir(dir);
    }
    cmd.args(args).env_remove("ROLLBEM_TEST_FAULT");
    for (k, v) in env {
        cmd.env(k, v);
    }
    let out = cmd.output().unwrap();
    (
        out.status.code().unwrap_or(-1),
        String::from_utf8_lossy(&out.stdout).into_owned(),
        String::from_utf8_lossy(&out.stderr).into_owned(),
    )
}
pub mod lame;
pub mod patch;

/// Least-squares slope of ln(error) against ln(h), h ∝ 1/n (n elements).
pub fn fitted_rate(ns: &[usize], errors: &[f64]) -> f64 {
    let xs: Vec<f64> = ns.iter().map(|&n| (1.0 / n as f64).ln()).collect();
    let ys: Vec<f64> = errors.iter().map(|e| e.ln()).collect();
    let k = xs.len() as f64;
    let (mx, my) = (xs.iter().sum::<f64>() / k, ys.iter().sum::<f64>() / k);
    let sxy: f64 = xs.iter().zip(&ys).map(|(x, y)| (x - mx) * (y - my)).sum();
    let sxx: f64 = xs.iter().map(|x| (x - mx) * (x - mx)).sum();
    sxy / sxx
}

/// The other ways to load the scene of a solved force/ratio-controlled run `load`, each with the
/// values that run found, so that every one must reproduce it: (label, `--set` overrides). The
/// grid is pinned to the run's half-length (the estimates would otherwise follow the new load).
/// Labels: "P and Q", "P with ξ", "δ0 with Q", "δ0 and ξ".
pub fn equivalent_load_controls(load: &Solved) -> Vec<(&'static str, Vec<String>)> {
    let s = &load.solution;
    let half = format!(
        "contact.grid.half_length={:.17e}",
        load.scene.estimates.grid_half_length
    );
    let overlap = format!("load.normal.overlap={:.17e}", s.overlap);
    let creep = format!("load.tangential.creep={:.17e}", s.creep);
    let force = format!("load.normal.force={:.17e}", s.normal_force);
    let q = format!("load.tangential.force={:.17e}", s.tangential_force);
    let (no_force, no_ratio) = (
        "load.normal.force=null".to_string(),
        "load.tangential.ratio=null".to_string(),
    );
    vec![
        ("P and Q", vec![no_ratio.clone(), q.clone(), half.clone()]),
        ("P with ξ", vec![force, no_ratio.clone(), creep.clone(), half.clone()]),
        (
            "δ0 with Q",
            vec![no_force.clone(), overlap.clone(), no_ratio.clone(), q, half.clone()],
        ),
        ("δ0 and ξ", vec![no_force, overlap, no_ratio, creep, half]),
    ]
}

/// A frictionless run on a thin layer against docs/references.md §5's leading order: its
/// contact half-width a, normal force P and the largest difference of its pressure from the
/// thin-layer shape of the same a, P and centre — (3P/4a)(1 − x²/a²) compressible,
/// (15P/16a)(1 − x²/a²)² incompressible (ν = ½) — over its peak pressure.
pub fn thin_layer_fit(sol: &rollbem::post::ContactSolution, nu: f64) -> (f64, f64, f64) {
    let [x0, x1] = sol.contact_extent().expect("contact");
    let (a, centre, p_total) = (0.5 * (x1 - x0), 0.5 * (x0 + x1), sol.normal_force);
    let thin = |x: f64| {
        let t = (1.0 - ((x - centre) / a).powi(2)).max(0.0);
        if nu < 0.5 {
            0.75 * p_total / a * t
        } else {
            15.0 / 16.0 * p_total / a * t * t
        }
    };
    let p_max = sol.pressure.iter().fold(0.0_f64, |m, &p| m.max(p));
    let shape = sol
        .x
        .iter()
        .zip(&sol.pressure)
        .map(|(&x, &p)| (p - thin(x)).abs())
        .fold(0.0_f64, f64::max)
        / p_max;
    (a, p_total, shape)
}
