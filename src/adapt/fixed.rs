//! The error estimate of a fixed grid's solution: the run's grid is solved once more with every
//! element halved, and the two solutions are compared as a pass of the error control compares
//! them ([`super::estimate::compare`]).
//!
//! The comparison gives the RMS difference d of the two solutions at the halved grid's nodes
//! (G's solution interpolated by its shape functions) and the difference of the creepages. For
//! a scalar whose error falls at first order, as the creepage's does (its stick zone ends at a
//! square-root point inside an element), e_G = 2d exactly in the limit. The tractions' RMS
//! difference does not cancel so: the halved grid's nodes are not G's, and the errors of the two
//! grids sit at different places of the square-root points, so d is itself 1.2–3 times e_G
//! (measured on Carter's and Hertz's problems on 21–81 elements, where e_G falls at first order).
//! The tractions' factors below are therefore calibrated, not derived: they keep the estimate
//! above the true error on those problems and on the shipped cases of docs/validation.md's
//! table (effectivities 1.7–6.3 for p, 1.2–5.8 for q; the creepage's 0.7–2.8, within 3 % of 1
//! on Carter's problem and a little low for the BEM rollers on shafts). The cost is one solve on twice
//! the elements (for a `bem` body, one more condensation on the halved grid): 1.5–4 times the
//! run on the shipped cases, which `contact.grid.estimate: false` skips.

use super::estimate::{self, PRESSURE_ESTIMATE_FACTOR, SHEAR_ESTIMATE_FACTOR};
use super::{cells::DyadicGrid, overlap, solve_on, HertzScales};
use crate::contact::residual::State;
use crate::contact::{ContactProblem, Workspace};
use crate::error::Error;
use crate::post::adaptation::ErrorEstimate;
use crate::post::Timings;
use crate::scene::Scene;

/// The pressure's estimated error on G in units of the RMS difference d of the two solutions
/// (calibrated: module docs).
pub const FIXED_PRESSURE_FACTOR: f64 = 4.0 / 3.0;

/// The shear's, the creepage's and the overlap's estimated error on G in units of their
/// differences d: 2, exact for a scalar converging at first order (module docs).
pub const FIXED_SHEAR_FACTOR: f64 = 2.0;

/// The estimated error of `state`, the solution of `problem` on the fixed grid of `scene`
/// (module docs); None for an error-controlled scene (its passes estimate it) or when the
/// halved grid's solve does not converge. The time of that solve is added to `timings`.
pub fn fixed_grid_estimate(
    scene: &Scene,
    problem: &ContactProblem,
    state: &State,
    timings: &mut Timings,
) -> Result<Option<ErrorEstimate>, Error> {
    if scene.grid_control.is_some() {
        return Ok(None);
    }
    let halved = DyadicGrid::new(&problem.grid).bisected().grid();
    log::info!(
        target: crate::logging::PROGRESS,
        "error estimate of the fixed grid: solving once more on it halved, {} elements \
         (contact.grid.estimate: false skips this)",
        halved.n_elements()
    );
    let mut ws = Workspace::new();
    let fine = solve_on(
        scene.on_grid(halved),
        Some((&problem.grid, state)),
        false,
        None,
        timings,
        &mut ws,
    )?;
    if !fine.report.converged {
        log::warn!("the error estimate of the fixed grid was skipped: the solve on its halved grid did not converge");
        return Ok(None);
    }
    let scales = HertzScales::of_run(scene, problem, state).scales(scene);
    let d = estimate::compare(&problem.grid, state, &fine.problem.grid, &fine.state, scales).estimate;
    Ok(Some(ErrorEstimate {
        pressure_rms: FIXED_PRESSURE_FACTOR * d.pressure_rms / PRESSURE_ESTIMATE_FACTOR,
        shear_rms: FIXED_SHEAR_FACTOR * d.shear_rms / SHEAR_ESTIMATE_FACTOR,
        creep_rel: FIXED_SHEAR_FACTOR * d.creep_rel,
        overlap_rel: overlap::controlled(scene)
            .then(|| FIXED_SHEAR_FACTOR * overlap::relative_error(state.overlap, fine.state.overlap)),
        body_mesh: None,
    }))
}
