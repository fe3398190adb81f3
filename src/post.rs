//! Post-processing: what a solved contact means — the solution in user-facing terms, its
//! stick/slip zones and slip regime, the friction-law check of the boundary-integral slip, and
//! the fields each body model shows under the solved tractions (its boundary, its interior).
//!
//! Everything here is physics derived from the solver's state; [`crate::output`] only writes
//! it. [`process`] runs the whole stage and returns a [`Solved`] run.

pub mod adaptation;
pub mod fields;
pub mod finite;
pub mod friction_check;
pub mod norms;
pub mod regime;
pub mod rolling_resistance;
pub mod solution;
pub mod strength;
pub mod zones;

use crate::body::BoundaryField;
use crate::contact::residual::State;
use crate::contact::{ContactProblem, SolveReport};
use crate::error::Error;
use crate::interior::InteriorField;
use crate::scene::{BodyModels, Scene};
use friction_check::{check_friction_law, FrictionCheck, DEFAULT_THRESHOLD_FRACTION};
pub use regime::{slip_regime, traction_ripple};
use serde::Serialize;
pub use solution::ContactSolution;
use std::time::Instant;
pub use zones::{NodeState, SlipDirection, SlipRegime, Zone};

/// Wall-clock time of each stage [s].
#[derive(Debug, Clone, Copy, Default, Serialize)]
pub struct Timings {
    /// Influence coefficients / BEM assembly.
    pub assembly_s: f64,
    /// Condensation to the contact nodes (zero for closed-form models).
    pub condense_s: f64,
    /// Contact solve.
    pub solve_s: f64,
    /// Interior fields of `output.interior` (post-processing; 0 when not asked).
    pub interior_s: f64,
    /// First yield and shakedown of `output.strength` (post-processing; 0 when not asked).
    pub strength_s: f64,
    /// Whole run including output.
    pub total_s: f64,
}

impl Timings {
    /// The part [s] of `wall` [s] that went to a stage taking `part` [s] of `whole` [s] of
    /// work done side by side (two bodies built on a thread each): the stage's share of the
    /// wall time, so that the stages still add up to it. Zero when nothing was timed.
    pub fn share_of_wall(wall: f64, part: f64, whole: f64) -> f64 {
        if whole > 0.0 {
            (wall * part / whole).min(part)
        } else {
            0.0
        }
    }
}

/// A solved scene with everything post-processing derived from it, before anything is written.
#[derive(Debug, Clone)]
pub struct Solved {
    /// The scene that was solved (case, bodies, grid, estimates).
    pub scene: Scene,
    /// The assembled problem.
    pub problem: ContactProblem,
    /// The solution (for a non-converged run: the last iterate).
    pub solution: ContactSolution,
    /// Solver report (for every method).
    pub report: SolveReport,
    /// Stage timings (total excludes output).
    pub timings: Timings,
    /// Slip regime (González & Abascal §5.2).
    pub regime: SlipRegime,
    /// Where the boundary-integral slip contradicts the friction law (None without HBEM slip
    /// or friction).
    pub friction_check: Option<FrictionCheck>,
    /// Whole-boundary fields of A and B (bem bodies, when VTK output is on).
    pub boundary: [Option<BoundaryField>; 2],
    /// Interior displacements and stresses, when `output.interior` asks for them.
    pub interior: Option<InteriorField>,
    /// First yield and shakedown of the bodies `output.strength` assesses (empty when not
    /// asked).
    pub strength: Vec<strength::assess::BodyStrength>,
    /// Notices for the user (e.g. mesh loops turned round, interior points not evaluated).
    pub notices: Vec<String>,
    /// Where the inputs leave the models' validity ([`crate::scene::validity`]).
    pub warnings: Vec<String>,
    /// How an error-controlled grid was reached (`contact.grid.tolerance`), else none.
    pub adaptation: Option<adaptation::GridAdaptation>,
    /// The estimated error of a fixed grid's solution (`rollbem run` with
    /// `contact.grid.estimate`, src/adapt/fixed.rs), else none.
    pub fixed_grid_estimate: Option<adaptation::ErrorEstimate>,
}

/// Post-processes a solver state: the user-facing solution, its regime and friction check,
/// and (for a converged run) the boundary and interior fields the case's output asks for.
/// `timings` are those of the stages before; the interior time is added here.
pub fn process(
    scene: Scene,
    models: &BodyModels,
    problem: ContactProblem,
    state: &State,
    report: SolveReport,
    mut timings: Timings,
) -> Result<Solved, Error> {
    let solution = ContactSolution::from_state(&problem, state);
    let case_path = &scene.case.path;
    finite::check(case_path, "the solver's residual history", &report.history)?;
    finite::check(case_path, "the contact solution", &solution)?;
    if report.converged {
        check_grid_contains_contact(&scene, &solution)?;
    }
    let regime = slip_regime(&solution, scene.leading_edge_sign(), 1);
    let friction_check = check_friction_law(
        &solution,
        scene.friction(),
        DEFAULT_THRESHOLD_FRACTION,
        scene.estimates.hertz_half_width / scene.estimates.effective_radius.abs(),
    );
    let output = &scene.fields;
    let boundary = if report.converged && output.vtk {
        fields::boundary_fields(models, &problem.grid, &problem.frame, &solution)?
    } else {
        [None, None]
    };
    let mut notices = scene.notices();
    let t_interior = Instant::now();
    let interior = match (&output.interior, report.converged) {
        (Some(spec), true) => {
            log::info!(
                target: crate::logging::PROGRESS,
                "interior stresses of body {}: {} × {} points",
                spec.body,
                spec.x[2],
                spec.y[2]
            );
            Some(fields::interior_field(
                &scene,
                spec,
                models,
                &problem.grid,
                &problem.frame,
                &solution,
            )?)
        }
        _ => None,
    };
    timings.interior_s = t_interior.elapsed().as_secs_f64();
    finite::check_fields(&scene.case.path, interior.as_ref(), &boundary)?;
    notices.extend(interior.as_ref().and_then(fields::unevaluated_points_notice));
    let t_strength = Instant::now();
    let strength = match (&output.strength, report.converged) {
        (Some(spec), true) => {
            log::info!(target: crate::logging::PROGRESS, "strength: first yield and shakedown");
            strength::assess::assess(&scene, spec, models, &problem.grid, &problem.frame, &solution)?
        }
        _ => Vec::new(),
    };
    timings.strength_s = t_strength.elapsed().as_secs_f64();
    notices.extend(strength::assess::notices(
        &strength,
        &solution,
        scene.grid_control.is_some(),
    ));
    let solved_peak = solution.pressure.iter().fold(0.0_f64, |m, &p| m.max(p));
    let mut warnings = crate::scene::validity::warnings(&scene.bodies, &scene.estimates, Some(solved_peak));
    warnings.extend(crate::scene::validity::traction_axes_warning(
        &scene.case,
        &scene.bodies,
    ));
    Ok(Solved {
        scene,
        problem,
        solution,
        report,
        timings,
        regime,
        friction_check,
        boundary,
        interior,
        strength,
        notices,
        warnings,
        adaptation: None,
        fixed_grid_estimate: None,
    })
}

/// A converged contact must end inside the grid: a loaded end node means the grid cut it off.
fn check_grid_contains_contact(scene: &Scene, sol: &ContactSolution) -> Result<(), Error> {
    let m = sol.x.len();
    for (i, end) in [(0, "left"), (m - 1, "right")] {
        if sol.pressure[i] > 0.0 {
            return Err(Error::GridTooShort {
                case: scene.case.path.clone(),
                end,
                x: sol.x[i],
                extent: scene.grid_extent,
                advice: crate::scene::preflight::grid_too_short_advice(&scene.case, &scene.bodies),
            });
        }
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::Timings;

    /// Two builds of 1.5 s of work, 0.6 s of it condensation, overlapped in 1 s of wall time:
    /// 0.4 s is condensation. Never more than the stage's own time, zero with nothing timed.
    #[test]
    fn a_stage_of_overlapped_work_takes_its_share_of_the_wall_time() {
        assert!((Timings::share_of_wall(1.0, 0.6, 1.5) - 0.4).abs() < 1e-15);
        assert_eq!(Timings::share_of_wall(2.0, 0.5, 1.0), 0.5);
        assert_eq!(Timings::share_of_wall(1.0, 0.0, 0.0), 0.0);
    }
}
