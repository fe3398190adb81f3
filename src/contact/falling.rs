//! Friction falling with the local slip velocity, solved by an outer fixed point on the nodal
//! friction coefficients.
//!
//! **The law** (the single exponential of Vollebregt & Schuttelaars, J. Sound Vib. 331
//! (2012) 2141–2155, Eq. 2, and of CONTACT's velocity-dependent friction with one term):
//!
//! μ(v) = μ_k + (μ_s − μ_k) exp(−|v| / s_h),   v = V s,
//!
//! with V the rolling speed (`load.speed`, [length/time]), s the dimensionless slip of the
//! paper's Eq. 19 at the node (so V s is the local slip velocity [length/time]), μ_s the static
//! coefficient (`contact.friction`), μ_k ≤ μ_s the kinetic one and s_h > 0 the slip velocity of
//! the decay [length/time]. At a sticking node s = 0 and μ = μ_s; μ_k = μ_s is Coulomb's
//! constant friction.
//!
//! **The scheme.** The generalized Newton method of [`super::restart`] solves the problem with
//! the nodal μ_i frozen ([`ContactProblem::nodal_friction`], the bound μ_i p̂_i of the paper's
//! Eq. 43/44 node by node); μ_i is then set from the slip found, and the next solve starts from
//! the last solution (warm), until no μ_i changes by more than [`FIXED_POINT_TOLERANCE`] μ_s.
//! The first solve freezes μ_i = μ_s (or the law at a warm start's slip). An outer fixed point
//! keeps the Newton direction of [`super::direction`] as it is (μ inside the residual would add
//! a dμ/ds column to every slipping row, which its reduction does not have); its cost is a few
//! warm solves. When the change of μ grows from one solve to the next, the update is relaxed
//! (halved, down to 1/16): a falling law makes the slip more sensitive to μ the steeper it is.
//!
//! **Uniqueness.** With a falling law the discrete problem can have several solutions
//! (Vollebregt & Schuttelaars 2012, §3): which one the fixed point finds depends on where it
//! starts, μ_s everywhere from a cold start, the neighbour's slip from a warm one. The run
//! reports the branch it found (its creepage and forces); a continuation in the creepage from
//! below and from above can find different ones for the same load.

use super::newton::NewtonInputs;
use super::report::{NewtonSettings, SolveReport};
use super::residual::{ConvergenceMeasure, State};
use super::workspace::Workspace;
use super::{restart, ContactProblem};
use serde::{Deserialize, Serialize};

/// Largest change of any nodal μ_i, relative to μ_s, at which the fixed point stops: below the
/// Newton tolerance's effect on the slip (‖G‖/p_ref ≤ 1e-10 moves s by about that much).
pub const FIXED_POINT_TOLERANCE: f64 = 1e-10;

/// Most solves of the outer fixed point before the run is reported not converged.
pub const MAX_FIXED_POINT_SOLVES: usize = 200;

/// Smallest relaxation of the μ update (1/16).
const MIN_RELAXATION: f64 = 1.0 / 16.0;

/// The keys of `contact.falling_friction`: the friction coefficient falls from the static
/// `contact.friction` μ_s to `kinetic` μ_k as the local slip velocity grows (module docs).
#[derive(Debug, Clone, Copy, PartialEq, Deserialize, Serialize)]
#[serde(deny_unknown_fields)]
pub struct FallingFriction {
    /// Kinetic friction coefficient μ_k, 0 ≤ μ_k ≤ μ_s [-]: the limit at large slip velocity.
    pub kinetic: f64,
    /// Slip velocity s_h > 0 [length/time] over which μ falls by the factor e from μ_s towards
    /// μ_k (the case's length and time units, as `load.speed`).
    pub slip_velocity: f64,
}

/// A falling law with what it needs from the case: the static coefficient and the speed.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct FallingLaw {
    /// The law's keys.
    pub law: FallingFriction,
    /// Static friction coefficient μ_s [-] (`contact.friction`).
    pub static_friction: f64,
    /// Rolling speed V > 0 [length/time] (`load.speed`): slip velocity = V × slip.
    pub speed: f64,
}

impl FallingLaw {
    /// μ(V s) for the dimensionless slip `slip` at a node [-] (module docs); μ_s exactly when
    /// μ_k = μ_s (the factor of the exponential is then zero).
    pub fn coefficient(&self, slip: f64) -> f64 {
        let v = self.speed * slip.abs();
        let (mu_s, mu_k) = (self.static_friction, self.law.kinetic);
        mu_k + (mu_s - mu_k) * (-v / self.law.slip_velocity).exp()
    }

    /// μ at every node of the slip `slip` [-].
    pub fn nodal(&self, slip: &[f64]) -> Vec<f64> {
        slip.iter().map(|&s| self.coefficient(s)).collect()
    }
}

/// Solves `pb` under the falling law `law` by the outer fixed point of the module docs, each
/// solve the line-search Newton of [`restart`] stopping on the measure of its frozen problem (from `warm` when given, else cold first), the
/// Newton systems in the memory of `ws`. The report sums the iterations of every solve; it is
/// not converged when a solve fails or the nodal μ_i do not settle within
/// [`MAX_FIXED_POINT_SOLVES`] solves.
pub fn solve(
    pb: &ContactProblem,
    law: &FallingLaw,
    settings: &NewtonSettings,
    warm: Option<State>,
    ws: &mut Workspace,
) -> (State, SolveReport) {
    let mut own = pb.clone();
    own.falling = None;
    let m = pb.n_nodes();
    let mut mu = match &warm {
        Some(z) => law.nodal(&z.slip),
        None => vec![law.static_friction; m],
    };
    let mut start = warm;
    let (mut relaxation, mut last_change) = (1.0_f64, f64::INFINITY);
    let (mut iterations, mut inner, mut history) = (0, 0, Vec::new());
    let scale = law.static_friction.max(f64::MIN_POSITIVE);
    let mut solve = 0;
    loop {
        solve += 1;
        own.nodal_friction = Some(mu.clone());
        // The measure of this pass's problem: its friction rows bound by the frozen μ_i (one of
        // the unfrozen problem would see the constant μ_s and accept a Ψ iterate that has it).
        let measure = ConvergenceMeasure::new(&own);
        let (state, mut report) = match start.take() {
            Some(w) => restart::solve_warm(&own, settings, &measure, w, ws),
            None => restart::solve(NewtonInputs::new(&own, settings, &measure), ws),
        };
        iterations += report.iterations;
        inner += report.inner_iterations;
        history.append(&mut report.history);
        let target = law.nodal(&state.slip);
        // Only where the bound μ_i p̂_i can act: out of contact μ_i bounds nothing.
        let change = (0..m)
            .filter(|&i| state.pressure[i] > 0.0)
            .fold(0.0_f64, |a, i| a.max((target[i] - mu[i]).abs()));
        let settled = change <= FIXED_POINT_TOLERANCE * scale;
        if !report.converged || settled || solve == MAX_FIXED_POINT_SOLVES {
            report.converged &= settled;
            report.iterations = iterations;
            report.inner_iterations = inner;
            report.history = history;
            // A settled run's count goes to the log (not a fallback: nothing stalled).
            match settled {
                true => log::info!(
                    target: crate::logging::PROGRESS,
                    "falling friction: {solve} solve(s) with the nodal mu frozen, last change {change:.1e}"
                ),
                false => report.fallbacks.push(format!(
                    "falling friction: the nodal mu did not settle in {solve} solve(s) (last change {change:.1e})"
                )),
            }
            return (state, report);
        }
        if change > last_change {
            relaxation = (relaxation * 0.5).max(MIN_RELAXATION);
        }
        last_change = change;
        for (u, t) in mu.iter_mut().zip(&target) {
            *u += relaxation * (t - *u);
        }
        start = Some(state);
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn law(kinetic: f64) -> FallingLaw {
        FallingLaw {
            law: FallingFriction {
                kinetic,
                slip_velocity: 0.5,
            },
            static_friction: 0.3,
            speed: 100.0,
        }
    }

    /// μ_s at zero slip, μ_k + (μ_s − μ_k)/e at V|s| = s_h, even in s, exactly μ_s when μ_k = μ_s.
    #[test]
    fn the_law_falls_from_static_to_kinetic() {
        let l = law(0.1);
        assert_eq!(l.coefficient(0.0), 0.3);
        let at_sh = 0.1 + 0.2 * (-1.0_f64).exp();
        assert!((l.coefficient(0.005) - at_sh).abs() < 1e-15);
        assert_eq!(l.coefficient(-0.005), l.coefficient(0.005));
        assert!((l.coefficient(10.0) - 0.1).abs() < 1e-15);
        let flat = law(0.3);
        for s in [0.0, 1e-6, 0.005, -3.0] {
            assert_eq!(flat.coefficient(s), 0.3);
        }
    }
}
