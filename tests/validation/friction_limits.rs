//! Solver cost at the friction limits of free rolling (aluminium on steel, Q = 0) and of Carter's
//! case: near complete slip (μ → 0) the coupled Newton meets a staircase Q(ξ) and stalls; the
//! creepage iteration (src/contact/creep_secant.rs) must then finish the job; at large μ the
//! normal start (src/contact/start.rs) must keep the count low. Every answer must be the solution
//! of the problem (the same scene with ξ prescribed gives Q = 0) and approach the complete-slip
//! limit ξ = 0.914772 β a/R (Bentall & Johnson 1967) or Bufler's no-slip limit ξ = 2εa/R. The
//! 481-element ladder of docs/performance.md is `cargo run --release --example friction_limits`.

use crate::common::solve;
use rollbem::analytic;

/// Newton steps of the default method on a shipped case with μ and the element count set; the
/// run must converge. Every step of every attempt counts (NORM steps and restarts included).
fn newton_steps(case: &str, mu: &str, n: usize, extra: &[&str]) -> (usize, Vec<String>) {
    let mut set = vec![format!("contact.friction={mu}"), format!("contact.grid.elements={n}")];
    set.extend(extra.iter().map(|s| s.to_string()));
    let refs: Vec<&str> = set.iter().map(String::as_str).collect();
    let s = solve(case, &refs);
    (s.report.iterations, s.report.fallbacks.clone())
}

/// At most 30 Newton steps (every step of every attempt) on the free-rolling limits, μ = 1e-4 …
/// 1e3, at 41 and 81 elements. Measured: at most 20 (μ = 3e-4, 41 elements, with the creepage
/// iteration); before the normal start and the complete-slip predictor 34 (μ = 1e-4) and, at
/// larger grids, 84–530 (μ = 10; docs/performance.md).
#[test]
fn free_rolling_friction_limits_need_at_most_30_newton_steps() {
    for mu in ["1e-4", "3e-4", "1e-3", "1e-2", "0.1", "1", "10", "50", "1e3"] {
        for n in [41, 81] {
            let (steps, fallbacks) = newton_steps("free_rolling_al_steel", mu, n, &[]);
            assert!(
                fallbacks.iter().all(|f| f == "creep iteration"),
                "μ = {mu}, {n} elements: fallbacks {fallbacks:?}"
            );
            assert!(steps <= 30, "μ = {mu}, {n} elements: {steps} Newton steps");
        }
    }
}

/// At 161 elements and μ ≥ 200 an edge node whose pressure is nearly zero traps Φ's line search
/// against the kink of its augmented friction bound: the stall test ends that attempt and Ψ from
/// the same normal start finishes. Measured: 24 steps (μ = 1e3), 11 (μ = 10), 9 (μ = 1e-4);
/// before: 35, 32 and 9.
#[test]
fn large_friction_edge_kink_is_left_for_psi_within_30_steps() {
    let (steps, fallbacks) = newton_steps("free_rolling_al_steel", "1e3", 161, &[]);
    assert_eq!(fallbacks, ["psi"], "this scene exercises the formulation restart");
    assert!(steps <= 30, "μ = 1e3, 161 elements: {steps} Newton steps");
    for mu in ["1e-4", "10"] {
        let (steps, _) = newton_steps("free_rolling_al_steel", mu, 161, &[]);
        assert!(steps <= 30, "μ = {mu}, 161 elements: {steps} Newton steps");
    }
}

/// Carter's case (Q/μP = 0.51) with μ up to 1e3: at most 30 Newton steps (measured 8 for μ ≤ 1,
/// 13–14 above; before 278–408 steps and four restarts at μ = 50 and 1e3).
#[test]
fn carter_at_large_friction_needs_at_most_30_newton_steps() {
    for mu in ["1e-4", "1", "10", "50", "1e3"] {
        for n in [41, 81] {
            let (steps, fallbacks) = newton_steps("carter_051", mu, n, &[]);
            assert!(fallbacks.is_empty(), "μ = {mu}, {n} elements: fallbacks {fallbacks:?}");
            assert!(steps <= 30, "μ = {mu}, {n} elements: {steps} Newton steps");
        }
    }
}

/// The answer of the normal start and of the Ψ restart solves the problem: prescribing its ξ
/// reproduces Q = 0 and the same tractions, and ξ is within 1 % of Bufler's no-slip limit
/// ξ = 2εa/R.
#[test]
fn large_friction_answer_is_the_solution() {
    let set = ["contact.friction=1e3", "contact.grid.elements=161"];
    let load = solve("free_rolling_al_steel", &set);
    let half = format!(
        "contact.grid.half_length={:.17e}",
        load.scene.estimates.grid_half_length
    );
    let creep = format!("load.tangential.creep={:.17e}", load.solution.creep);
    let kin = solve(
        "free_rolling_al_steel",
        &[set[0], set[1], "load.tangential.ratio=null", &creep, &half],
    );
    let p_max = load.solution.pressure.iter().fold(0.0_f64, |a, &p| a.max(p));
    assert!(
        kin.solution.tangential_force.abs() < 1e-8 * load.solution.normal_force,
        "Q = {}",
        kin.solution.tangential_force
    );
    for (a, b) in load.solution.shear.iter().zip(&kin.solution.shear) {
        assert!((a - b).abs() < 1e-8 * p_max, "shear {a} vs {b}");
    }
    let e = &load.scene.estimates;
    let (limit, _, _) = analytic::free_rolling_no_slip(e.dundurs_beta, e.normal_force, e.effective_radius, e.e_star);
    assert!(
        (load.solution.creep / limit - 1.0).abs() < 0.01,
        "ξ = {} vs {limit}",
        load.solution.creep
    );
}

/// The creepage iteration's answer solves the problem: prescribing its ξ reproduces Q = 0 and
/// the same tractions, and ξ is within the discretisation error of the complete-slip limit.
#[test]
fn creep_iteration_answer_is_the_solution() {
    let load = solve(
        "free_rolling_al_steel",
        &["contact.friction=1e-4", "contact.grid.elements=81"],
    );
    assert_eq!(
        load.report.fallbacks,
        ["creep iteration"],
        "this scene exercises the creepage iteration"
    );
    let half = format!(
        "contact.grid.half_length={:.17e}",
        load.scene.estimates.grid_half_length
    );
    let creep = format!("load.tangential.creep={:.17e}", load.solution.creep);
    let kin = solve(
        "free_rolling_al_steel",
        &[
            "contact.friction=1e-4",
            "contact.grid.elements=81",
            "load.tangential.ratio=null",
            &creep,
            &half,
        ],
    );
    assert!(kin.report.fallbacks.is_empty());
    let mu_p = 1e-4 * load.solution.normal_force;
    assert!(
        kin.solution.tangential_force.abs() < 1e-6 * mu_p,
        "Q = {}",
        kin.solution.tangential_force
    );
    let q_max = load.solution.pressure.iter().fold(0.0_f64, |a, &p| a.max(p)) * 1e-4;
    for (a, b) in load.solution.shear.iter().zip(&kin.solution.shear) {
        assert!((a - b).abs() < 1e-6 * q_max, "shear {a} vs {b}");
    }
    let e = &load.scene.estimates;
    let limit = analytic::free_rolling_creep_complete_slip(e.dundurs_beta, e.hertz_half_width, e.effective_radius);
    // 81 elements: −0.11 % (the 321-element run of tests/validation/solver.rs is within 1 %).
    assert!(
        (load.solution.creep / limit - 1.0).abs() < 0.005,
        "ξ = {} vs {limit}",
        load.solution.creep
    );
}
