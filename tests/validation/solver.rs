//! Acceptance tests of the contact solver on the shipped half-space cases.

use crate::common::{case_path, solve};
use rollbem::analytic;
use rollbem::post::traction_ripple;

pub(crate) fn shipped_cases() -> Vec<String> {
    let mut names: Vec<String> = std::fs::read_dir(case_path("x").parent().unwrap())
        .unwrap()
        .filter_map(|e| e.ok().map(|e| e.path()))
        .filter(|p| p.extension().is_some_and(|e| e == "yaml"))
        .map(|p| p.file_stem().unwrap().to_string_lossy().into_owned())
        .collect();
    names.sort();
    assert!(names.len() >= 13, "shipped cases: {names:?}");
    names
}

/// Every shipped case converges from the paper's start vector (Eq. 74) with its own settings,
/// reproduces its prescribed P or δ0 (and Q) to 1e-10, and Φ and Ψ agree to better than 3 significant
/// figures (paper §4.4; we measure agreement to ~1e-13 because both converge to the same exact
/// solution of the discrete problem).
///
/// The cases whose inputs leave a model's validity (summary.json `warnings`) are the ones
/// docs/reliability.md lists.
#[test]
fn every_shipped_case_converges_balances_its_loads_and_phi_equals_psi() {
    let mut warned = Vec::new();
    for name in shipped_cases() {
        let phi = solve(&name, &["solver.formulation=phi"]);
        let psi = solve(&name, &["solver.formulation=psi"]);
        if !phi.warnings.is_empty() {
            eprintln!("{name}: {} warning(s): {:?}", phi.warnings.len(), phi.warnings);
            warned.push(name.clone());
        }
        let sol = &phi.solution;
        // Overlap-controlled cases (the tyre) prescribe δ0; their P is the computed one.
        let p_target = match phi.scene.case.case.load.normal_keys.force {
            Some(p) => p,
            None => {
                let d = phi.scene.case.case.load.normal_keys.overlap.expect("force or overlap");
                assert!((sol.overlap - d).abs() <= 1e-12 * d, "{name}: δ0 = {}", sol.overlap);
                sol.normal_force
            }
        };
        assert!(
            (sol.normal_force / p_target - 1.0).abs() < 1e-10,
            "{name}: P = {}",
            sol.normal_force
        );
        let mu = phi.scene.friction();
        let q_target = match phi.scene.case.case.load.tangential() {
            rollbem::case::TangentialSpec::Ratio(r) => Some(r * mu * p_target),
            rollbem::case::TangentialSpec::Force(q) => Some(q),
            // A prescribed creepage (cases/veldep_fric.yaml): Q is an output, ξ is held.
            rollbem::case::TangentialSpec::Creep(xi) => {
                assert!((sol.creep - xi).abs() <= 1e-12 * xi.abs(), "{name}: ξ = {}", sol.creep);
                None
            }
        };
        if let Some(q_target) = q_target {
            assert!(
                (sol.tangential_force - q_target).abs() < 1e-10 * p_target,
                "{name}: Q = {} vs {q_target}",
                sol.tangential_force
            );
        }
        let rel = |a: f64, b: f64, scale: f64| (a - b).abs() / scale;
        let pmax = sol.pressure.iter().fold(0.0_f64, |m, &p| m.max(p));
        for (a, b) in sol.pressure.iter().zip(&psi.solution.pressure) {
            assert!(rel(*a, *b, pmax) < 1e-4, "{name}: Φ and Ψ pressures differ");
        }
        // A frictionless case has no shear to compare (|q| ≤ μp = 0 up to round-off).
        for (a, b) in sol.shear.iter().zip(&psi.solution.shear).filter(|_| mu > 0.0) {
            assert!(rel(*a, *b, mu * pmax) < 1e-4, "{name}: Φ and Ψ shears differ");
        }
        assert!(
            rel(sol.creep, psi.solution.creep, sol.creep.abs().max(1e-300)) < 1e-4,
            "{name}: creep"
        );
    }
    let page = std::fs::read_to_string(case_path("x").parent().unwrap().join("../docs/reliability.md")).unwrap();
    let listed = page
        .split("The shipped cases that warn")
        .nth(1)
        .and_then(|rest| rest.split("checks the\nlist").next())
        .expect("docs/reliability.md lists the shipped cases that warn");
    let documented: Vec<String> = listed
        .split('`')
        .skip(1)
        .step_by(2)
        .filter(|n| !n.contains(' '))
        .map(String::from)
        .collect();
    assert_eq!(
        warned, documented,
        "the shipped cases that warn, against docs/reliability.md"
    );
}

/// A kinematic run fed with the δ0 and ξ of a load-controlled run returns its P and Q to 1e-8;
/// the mixed controls (P with ξ; δ0 with Q) and force control (P and Q) return the missing
/// quantities too.
#[test]
fn kinematic_and_mixed_control_reproduce_the_load_controlled_run() {
    for name in ["carter_051", "dissimilar_beta0288_004"] {
        let load = solve(name, &[]);
        let s = &load.solution;
        for (label, set) in crate::common::equivalent_load_controls(&load) {
            let set: Vec<&str> = set.iter().map(String::as_str).collect();
            let k = solve(name, &set);
            let p_err = (k.solution.normal_force - s.normal_force).abs() / s.normal_force;
            let q_err = (k.solution.tangential_force - s.tangential_force).abs() / s.normal_force;
            assert!(
                p_err < 1e-8 && q_err < 1e-8,
                "{name} {label}: P err {p_err:e}, Q err {q_err:e} (relative to P)"
            );
            assert!(
                (k.solution.overlap - s.overlap).abs() < 1e-8 * s.overlap.abs(),
                "{name} {label}: δ0"
            );
            assert!(
                (k.solution.creep - s.creep).abs() < 1e-8 * s.creep.abs(),
                "{name} {label}: ξ"
            );
        }
    }
}

/// Dundurs β/μ = 2.88 (reading B): the paper's three load ratios give regimes 2, 3 and 4, with
/// our default rolling direction (+x) and Q with the paper's sign. Checked at 21 and 81 elements.
#[test]
fn dissimilar_regimes_of_the_paper_with_dundurs_beta_over_mu_2_88() {
    for n in [21, 81] {
        let grid = format!("contact.grid.elements={n}");
        for (name, regime, directions) in [
            ("dissimilar_beta0288_075", 2, vec![-1, -1]),
            ("dissimilar_beta0288_m083", 3, vec![1, -1]),
            ("dissimilar_beta0288_004", 4, vec![-1, 1, -1]),
        ] {
            let s = solve(name, &[&grid]);
            assert_eq!(s.regime.number(), regime, "{name}/{n}: zones {:?}", s.solution.zones);
            let signs: Vec<i8> = s.solution.slip_directions().iter().map(|d| d.sign()).collect();
            assert_eq!(signs, directions, "{name}/{n}");
        }
    }
    // Reading A (aluminium on steel, β_D/μ = 1.44): Q/μP = 0.04 gives regime 2, not 4
    // (docs/references.md §4.3).
    let s = solve("dissimilar_al_steel_004", &["contact.grid.elements=81"]);
    assert_eq!(s.regime.number(), 2, "zones {:?}", s.solution.zones);
}

/// Free rolling of aluminium on steel: ξ → 0.914772 β a/R as μ → 0 and ξ → 2εa/R with
/// p(0) → cosh(πε)E*a/(2R) as μ → ∞ (docs/references.md §4.4), within 1 % at 321 elements.
#[test]
fn free_rolling_creepage_limits() {
    let slip = solve(
        "free_rolling_al_steel",
        &["contact.friction=1e-4", "contact.grid.elements=321"],
    );
    let e = &slip.scene.estimates;
    let limit = analytic::free_rolling_creep_complete_slip(e.dundurs_beta, e.hertz_half_width, e.effective_radius);
    assert!(
        (slip.solution.creep / limit - 1.0).abs() < 0.01,
        "complete slip: ξ = {} vs {limit}",
        slip.solution.creep
    );

    let stick = solve(
        "free_rolling_al_steel",
        &["contact.friction=1e3", "contact.grid.elements=321"],
    );
    let (limit, _, p_centre) =
        analytic::free_rolling_no_slip(e.dundurs_beta, e.normal_force, e.effective_radius, e.e_star);
    assert!(
        (stick.solution.creep / limit - 1.0).abs() < 0.01,
        "no slip: ξ = {} vs {limit}",
        stick.solution.creep
    );
    let p0 = stick.problem.grid.interpolate(&stick.solution.pressure, 0.0);
    assert!((p0 / p_centre - 1.0).abs() < 1e-3, "no slip: p(0) = {p0} vs {p_centre}");
    // Bufler's p(0) exceeds Hertz: the coupling is really in the solution.
    assert!(p0 > 1.003 * e.hertz_peak_pressure);
}

/// Variable friction (paper Figs 7–9): converged, smooth tractions at every μ (zig-zag ripple
/// below 1 % of μp0; a node-to-node oscillation of amplitude A would give about 4A).
#[test]
fn variable_friction_cases_have_smooth_tractions() {
    for name in ["variable_mu_qp_0075", "variable_mu_qp_m0083", "variable_mu_qp_0004"] {
        for mu in [0.1, 0.2, 0.3, 0.4, 0.8] {
            let s = solve(name, &[&format!("contact.friction={mu}")]);
            let ripple = traction_ripple(&s.solution) / (mu * s.scene.estimates.hertz_peak_pressure);
            assert!(ripple < 0.01, "{name} μ={mu}: ripple {ripple}");
        }
    }
}

/// Interior stresses of half-space bodies: under the Hertz pressure
/// the maximum shear is 0.300283 p0 at depth 0.786 a in both bodies (docs/references.md §7);
/// within 2 % and one grid step (0.02 a) on a 161-element contact grid.
#[test]
fn interior_maximum_shear_under_hertz_in_both_bodies() {
    for (body, y) in [("A", "[0.02, 1.6, 80]"), ("B", "[-1.6, -0.02, 80]")] {
        let interior = format!("output.interior={{body: {body}, x: [-0.5, 0.5, 11], y: {y}}}");
        let s = solve("hertz", &["contact.grid.elements=161", &interior]);
        let f = s.interior.expect("interior field");
        let p0 = s.scene.estimates.hertz_peak_pressure;
        let (k, t) = f
            .stress
            .iter()
            .map(|st| rollbem::interior::invariants(st).1)
            .enumerate()
            .max_by(|a, b| a.1.total_cmp(&b.1))
            .unwrap();
        let [x, y] = f.points[k];
        assert!((t / p0 / 0.300283 - 1.0).abs() < 0.02, "{body}: τ1 = {} p0", t / p0);
        assert!(
            x.abs() < 1e-9 && (y.abs() - 0.786151).abs() < 0.025,
            "{body}: at ({x}, {y})"
        );
    }
}

/// The interior of a bem body whose contact nodes are transferred to the grid: body B
/// of the non-matching rollers (2× finer contact mesh, tractions carried to its own nodes by the
/// grid's interpolation) against the paired rollers, under the same Carter case. The two B
/// meshes differ, so the fields differ by their discretisations: measured 3e-5 p0 on the
/// maximum shear (0.30291 p0 against 0.30294 p0) and 2.7e-3 p0 pointwise over the 31 × 40
/// grid under the contact; asserted 1e-3 and 1e-2 p0.
#[test]
fn interior_of_a_transferred_bem_body_matches_the_paired_one() {
    let interior = "output.interior={body: B, x: [-1.5, 1.5, 31], y: [-2.0, -0.05, 40]}";
    let paired = solve("carter_051_true", &[interior]);
    let moved = solve("carter_051_true_nonmatching", &[interior]);
    let (a, b) = (paired.interior.unwrap(), moved.interior.unwrap());
    let p0 = paired.scene.estimates.hertz_peak_pressure;
    assert!(a.counts()[0] == a.points.len() && b.counts()[0] == b.points.len());
    let pointwise = a
        .stress
        .iter()
        .zip(&b.stress)
        .flat_map(|(s, t)| s.iter().zip(t).map(|(x, y)| (x - y).abs()))
        .fold(0.0f64, f64::max)
        / p0;
    let (ma, mb) = (a.summary().max_shear.unwrap(), b.summary().max_shear.unwrap());
    println!(
        "max shear paired {:.6} p0, transferred {:.6} p0; pointwise stress difference {pointwise:.2e} p0",
        ma.value / p0,
        mb.value / p0
    );
    assert!(
        (ma.value - mb.value).abs() < 1e-3 * p0 && pointwise < 1e-2,
        "{ma:?} {mb:?} {pointwise}"
    );
}
