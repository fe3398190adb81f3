//! The Hertz contact that sets the units of a run's error estimate.

use super::estimate::Scales;
use super::geometry_share::geometry_share;
use crate::analytic::{hertz_half_width, hertz_peak_pressure};
use crate::contact::residual::State;
use crate::contact::{ContactProblem, NormalControl, TangentialControl};
use crate::post::ContactSolution;
use crate::scene::Scene;

/// The Hertz contact that sets the units of the error estimate (p0) and the a-priori element
/// lengths at the square-root points (a).
#[derive(Debug, Clone, Copy)]
pub struct HertzScales {
    /// Hertz peak pressure p0 [stress].
    pub peak_pressure: f64,
    /// Hertz half-width a [length].
    pub half_width: f64,
    /// The share of the creepage the bodies' true geometry sets [-] (src/adapt/geometry_share.rs).
    pub geometry_share: f64,
}

impl HertzScales {
    /// The case's estimates under force control. Under overlap control, Hertz's contact for the
    /// normal force of the first grid's solution: the force the case's estimates derive from the
    /// overlap (half-plane datums, only to size the grid) can be far off, by orders of magnitude
    /// for a thin layer, and would give the estimate meaningless units. (An overlap that leaves
    /// the bodies apart, P = 0, keeps the case's estimates.)
    pub fn of_run(scene: &Scene, problem: &ContactProblem, first: &State) -> Self {
        let est = &scene.estimates;
        let force = || ContactSolution::from_state(problem, first).normal_force;
        let geometry_share = geometry_share(scene, &problem.grid, first.creep, force);
        let of_estimates = Self {
            peak_pressure: est.hertz_peak_pressure,
            half_width: est.hertz_half_width,
            geometry_share,
        };
        // A body's own scales (a cover on its core) do not follow Hertz's law in the force.
        if matches!(scene.normal, NormalControl::Force(_)) || est.scales_from.is_some() {
            return of_estimates;
        }
        let force = force();
        if !(force > 0.0 && force.is_finite()) {
            return of_estimates;
        }
        let a = hertz_half_width(force, est.effective_radius, est.e_star);
        Self {
            peak_pressure: hertz_peak_pressure(force, a),
            half_width: a,
            geometry_share,
        }
    }

    /// The units of the error estimate of a run of `scene` with these scales.
    pub fn scales(&self, scene: &Scene) -> Scales {
        let complete_slip_creep = scene.friction() * self.half_width / scene.estimates.effective_radius.abs();
        Scales {
            peak_pressure: self.peak_pressure,
            friction: scene.friction(),
            creep_prescribed: matches!(scene.tangential, TangentialControl::Creep(_)),
            complete_slip_creep,
            geometry_share: self.geometry_share,
        }
    }
}
