//! The check of the bodies' meshes ([`super::body_mesh`]) solves the bodies coarsened and
//! bisected outside the contact as corrections of the bodies as given, on the same grid.
//!
//! Condensed on the check grid, a changed body would be solved for every unit load of the m
//! contact nodes: on a bore's 312-node grid 624 right-hand sides, as many as the bisected
//! body's own unknowns, and as costly as its LU. The contact problem needs the changed
//! flexibility F' only applied to the few tractions its Newton iterations try, and F' differs
//! from the given bodies' F (whose problem the check has solved already) by E = F' − F, the
//! body meshes' own error: of relative size 1e-3 or less, or the check would not be asked. So
//! each changed body is factored only ([`crate::body::BuildContext::responses_only`]), and the
//! fixed point
//!
//! ```text
//! t_{k+1} = the solution of the given problem with F + M_k,   M_k t_k = E t_k
//! ```
//!
//! is iterated from the given solution. Its limit is the changed bodies' own solution
//! ((F + E) t = …), reached at the rate of E's relative size: two or three rounds, each one
//! solve of the factored bodies under the tractions t_k (one right-hand side each) and one
//! warm-started contact solve. M_k is the change of rank two that maps t_k onto E t_k (per
//! body, in its global axes: the left factor (δh, δw) = E t_k, the right one t_kᵀ/|t_k|² in the
//! rows of h and of w), added to the given problem in its place
//! ([`WithoutSlipBlocks::with_flexibility_changes`]) and taken back after: the
//! problem's undeformed gap and frame are the given bodies', whose contact groups the changed
//! ones share element for element.

use super::{condensation_share, solve_problem, WarmFrom};
use crate::body::{LowRankFlexibility, RunCaches, Side};
use crate::contact::residual::State;
use crate::contact::{SolverSettings, WithoutSlipBlocks, Workspace};
use crate::error::Error;
use crate::post::Timings;
use crate::scene::{BodyModels, Scene};
use faer::Mat;
use std::time::Instant;

/// Most rounds of the fixed point before the correction gives up (the caller then solves the
/// changed bodies condensed on the grid).
pub const MAX_ROUNDS: usize = 8;

/// The estimated distance of the last round's solution from the limit, in the estimate's
/// norms (RMS of p/p0 and q/(μp0), relative ξ and δ), below which the rounds stop: two orders
/// below the smallest body-mesh estimates the shipped cases report (1e-8), near the Newton
/// solves' own accuracy.
pub const ROUND_TOLERANCE: f64 = 1e-10;

/// A rate of the fixed point (each round's change over the one before) above which it is
/// taken not to converge: the body meshes' error that the check is asked to measure is far
/// smaller.
pub const SLOWEST_RATE: f64 = 0.3;

/// The bodies as given on the check grid: their contact problem and models, the base of the
/// corrections.
pub(super) struct GivenBodies<'a> {
    /// The given bodies' problem, without its slip blocks (changes are made in its place and
    /// taken back, with the slip blocks of the changed problem).
    pub problem: &'a mut WithoutSlipBlocks,
    /// The given bodies.
    pub models: &'a BodyModels,
    /// Their solution on the grid.
    pub state: &'a State,
}

impl GivenBodies<'_> {
    /// The solution of `changed` (the scene of the changed bodies on the given problem's grid)
    /// by corrections of the given problem (module docs), from the given solution, the changed
    /// bodies built for their responses only and their build time added to `timings`; None
    /// when a round does not converge or the rounds do not settle. `distance` measures two
    /// solutions apart in the estimate's norms (the rounds' changes).
    pub(super) fn solve_changed(
        &mut self,
        changed: &Scene,
        solver: &SolverSettings,
        distance: impl Fn(&State, &State) -> f64,
        run: Option<&RunCaches>,
        timings: &mut Timings,
        ws: &mut Workspace,
    ) -> Result<Option<State>, Error> {
        let t = Instant::now();
        let models = changed.body_models_for_responses(run)?;
        let built = t.elapsed().as_secs_f64();
        let condense_s = condensation_share(&models, built);
        timings.condense_s += condense_s;
        timings.assembly_s += built - condense_s;
        let mut z = self.state.clone();
        let mut last_step = f64::INFINITY;
        for _ in 0..MAX_ROUNDS {
            let t = Instant::now();
            let [a, b] = [Side::A, Side::B].map(|side| self.correction(side, &z, &models));
            timings.assembly_s += t.elapsed().as_secs_f64();
            let grid = self.problem.grid().clone();
            let (next, report) = self.problem.with_flexibility_changes([Some(&a), Some(&b)], |pb| {
                solve_problem(pb, solver, Some((&grid, &z)), WarmFrom::Pass, timings, ws)
            });
            if !report.converged {
                return Ok(None);
            }
            let step = distance(&z, &next);
            log::debug!("body-mesh check, correction round: change {step:.3e}");
            z = next;
            if step <= ROUND_TOLERANCE {
                return Ok(Some(z));
            }
            // From the second round on, the fixed point's rate is known (the first change is
            // the changed bodies' whole difference).
            if last_step.is_finite() {
                let rate = step / last_step;
                if rate > SLOWEST_RATE {
                    log::info!(
                        target: crate::logging::PROGRESS,
                        "error control: the corrections of the given bodies' problem do not settle \
                         (change {step:.2e} after {last_step:.2e})"
                    );
                    return Ok(None);
                }
                // The distance left to the limit of a fixed point converging at this rate.
                if step * rate / (1.0 - rate) <= ROUND_TOLERANCE {
                    return Ok(Some(z));
                }
            }
            last_step = step;
        }
        Ok(None)
    }

    /// The change of rank two of body `side`'s flexibility (global axes) that maps the state's
    /// loads on it, t = (P, Q), onto E t, the changed body's displacements less the given
    /// one's under them (module docs): left (δh, δw), right tᵀ/|t|² in the rows of h and of w.
    fn correction(&self, side: Side, z: &State, changed: &BodyModels) -> LowRankFlexibility {
        let k = match side {
            Side::A => 0,
            Side::B => 1,
        };
        let grid = self.problem.grid();
        let m = grid.n_nodes();
        let (p, q) = self.problem.frame().global_load_columns(side, &z.pressure, &z.shear);
        let [h, w] = changed[k].model().displacements(grid, side, p.as_ref(), q.as_ref());
        let [h0, w0] = self.models[k].model().displacements(grid, side, p.as_ref(), q.as_ref());
        let norm2 = p.squared_norm_l2() + q.squared_norm_l2();
        let scale = if norm2 > 0.0 { 1.0 / norm2 } else { 0.0 };
        let left = Mat::from_fn(m, 2, |i, c| {
            if c == 0 {
                h[(i, 0)] - h0[(i, 0)]
            } else {
                w[(i, 0)] - w0[(i, 0)]
            }
        });
        let row = |v: &Mat<f64>, at: usize| Mat::from_fn(2, m, |r, j| if r == at { scale * v[(j, 0)] } else { 0.0 });
        LowRankFlexibility {
            left,
            right: [row(&p, 0), row(&q, 0), row(&p, 1), row(&q, 1)],
        }
    }
}
