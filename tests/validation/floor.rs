//! The refinement's floor (src/adapt/floor.rs): a run whose estimate rises as its grid is
//! refined stops at its best pass, with exit code 2 naming the element length, rather than
//! chasing the rise to `contact.grid.max_elements`.
//!
//! The noise is put in by the estimator: CONTACT's Carter case (carter2d_contact.yaml) at
//! tolerance 1e-5, its solutions read with a node-to-node ripple on the pressure that grows as
//! ℓ/h where the node spacing h falls below ℓ — round-off that grows as the elements shrink, as
//! the BEM bodies' contact frame did on tiny cut elements before they took their circle's slope
//! there (docs/validation.md, "The bodies' ripple, measured" and "The refinement's floor"). Carter's closed form is the reference.

use crate::adaptive::carter_errors_of;
use rollbem::adapt::estimate::{compare, Comparison, ErrorEstimator, Pass};
use rollbem::contact::residual::State;
use rollbem::grid::ContactGrid;
use rollbem::post::ContactSolution;

/// The bisection estimate of solutions read with a ripple of `amplitude`·p0·(ℓ/h − 1) on the
/// pressure of every loaded node whose spacing h to its nearer neighbour is below ℓ = `below`
/// [mm], alternating in sign from node to node.
struct Rippled {
    amplitude: f64,
    below: f64,
}

impl Rippled {
    fn read(&self, grid: &ContactGrid, z: &State, p0: f64) -> State {
        let x = &grid.nodes;
        let mut z = z.clone();
        for i in 0..x.len() {
            let left = if i > 0 { x[i] - x[i - 1] } else { f64::INFINITY };
            let right = if i + 1 < x.len() {
                x[i + 1] - x[i]
            } else {
                f64::INFINITY
            };
            let h = left.min(right);
            if z.pressure[i] > 0.0 && h < self.below {
                let sign = if i % 2 == 0 { 1.0 } else { -1.0 };
                z.pressure[i] += sign * self.amplitude * p0 * (self.below / h - 1.0);
            }
        }
        z
    }
}

impl ErrorEstimator for Rippled {
    fn estimate(&mut self, pass: &Pass<'_>) -> Comparison {
        let p0 = pass.scales.peak_pressure;
        let coarse = self.read(pass.coarse_grid, pass.coarse, p0);
        let fine = self.read(pass.fine_grid, pass.fine, p0);
        compare(pass.coarse_grid, &coarse, pass.fine_grid, &fine, pass.scales)
    }
}

fn scene() -> rollbem::scene::Scene {
    let loaded = rollbem::app::load_case(
        &crate::common::case_path("carter2d_contact"),
        &["contact.grid.tolerance=1e-5", "contact.grid.max_elements=4000"],
    )
    .expect("the case");
    rollbem::scene::Scene::from_case(&loaded).expect("its scene")
}

/// With a ripple that grows as the grid grades below 1e-3 a, the estimate rises after the pass
/// that first reaches that spacing; the run stops there: not reached, its result the best pass's
/// solution (its grid, its estimate), whose true errors against Carter are within the
/// tolerance, and the floor named at an element length below the best pass's. Without the ripple
/// the same estimator (amplitude 0) meets the tolerance, so the stop is the ripple's.
#[test]
fn a_rising_estimate_stops_the_run_at_its_best_pass() {
    let scene = scene();
    let clean = rollbem::adapt::solve_with(
        &scene,
        &mut Rippled {
            amplitude: 0.0,
            below: 1e-3,
        },
    )
    .expect("solved");
    let a = clean.adaptation.expect("error-controlled");
    assert!(a.reached && a.floor.is_none(), "the clean run meets 1e-5");

    let noisy = rollbem::adapt::solve_with(
        &scene,
        &mut Rippled {
            amplitude: 1e-5,
            below: 1e-3,
        },
    )
    .expect("solved");
    let a = noisy.adaptation.as_ref().expect("error-controlled");
    let traction: Vec<f64> = a
        .steps
        .iter()
        .map(|s| s.estimate.pressure_rms.max(s.estimate.shear_rms))
        .collect();
    eprintln!(
        "passes: {:?}, floor {:?}",
        traction.iter().map(|t| format!("{t:.2e}")).collect::<Vec<_>>(),
        a.floor
    );
    let floor = a.floor.expect("the run stopped at the floor");
    assert!(!a.reached);
    let best = &a.steps[floor.best_pass - 1];
    assert_eq!(noisy.problem.grid.n_elements(), best.elements, "the best pass's grid");
    assert_eq!(a.estimate, Some(best.estimate), "with the best pass's estimate");
    assert!(floor.risen_estimate > rollbem::adapt::floor::RISE * floor.best_estimate);
    assert!(floor.shortest_element < floor.best_shortest_element);
    assert!(a.steps.len() < 12, "stopped within a few passes, not at max_elements");
    let sol = ContactSolution::from_state(&noisy.problem, &noisy.state);
    let [p, q, _] = carter_errors_of(&noisy.scene, &sol);
    let e = best.estimate;
    eprintln!(
        "best pass {}: {} elements, estimate p {:.2e} q {:.2e}; true p {p:.2e} q {q:.2e}",
        floor.best_pass, best.elements, e.pressure_rms, e.shear_rms
    );
    // The best pass's grid, solved again, carries the clean Carter solution of its pass: within
    // the tolerance although its estimate, read with the ripple, is not.
    assert!(p <= 1e-5 && q <= 1e-5, "true p {p:e}, q {q:e}");
}
