//! Solver cost at the friction limits of free rolling (aluminium on steel, Q = 0): near complete
//! slip (μ → 0) the coupled Newton meets a staircase Q(ξ) and stalls; the creepage iteration
//! (src/contact/creep_secant.rs) must then finish the job in a few dozen Newton steps, without
//! the Gauss–Seidel fallback, and its answer must be the solution of the problem (the same
//! scene with ξ prescribed gives Q = 0) and approach the complete-slip limit
//! ξ = 0.914772 β a/R (Bentall & Johnson 1967).

use crate::common::solve;
use rollbem::analytic;

/// The default method's Newton steps on the free-rolling limits, μ = 1e-4 … 1e3.
#[test]
fn free_rolling_friction_limits_converge_in_few_newton_steps() {
    for mu in ["1e-4", "3e-4", "1e-3", "0.1", "1e3"] {
        for n in [41, 81] {
            let s = solve(
                "free_rolling_al_steel",
                &[&format!("contact.friction={mu}"), &format!("contact.grid.elements={n}")],
            );
            let r = &s.report;
            assert!(
                r.fallbacks.iter().all(|f| f == "creep iteration"),
                "μ = {mu}, {n} elements: fallbacks {:?}",
                r.fallbacks
            );
            // Measured: at most 34 (μ = 1e-4, 81 elements; 401 before the creepage iteration).
            assert!(
                r.iterations <= 40,
                "μ = {mu}, {n} elements: {} iterations",
                r.iterations
            );
        }
    }
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
