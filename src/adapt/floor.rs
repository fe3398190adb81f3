//! The refinement's floor: where refining the contact grid makes the estimate rise instead of
//! fall, the grid has reached a length below which the solution's own noise, not its
//! discretisation error, is what the estimate compares, and the loop stops there.
//!
//! On a grid that the loop refines (it only adds nodes, besides merging pieces of the open
//! region whose indicators are negligible) the discretisation error of a convergent method
//! falls, and so does the estimate: over every shipped half-space case at tolerances 1e-4 and
//! 1e-5 and every shipped BEM case at 1e-4 and 1e-5 the largest of the traction estimates
//! never rose above 1.5 times the best before it on the same scene (docs/validation.md, "The
//! refinement's floor"). Noise does not fall with the element length, and can grow as it
//! shrinks: the cut BEM bodies' contact frame once took its slope from elements 1e-6 mm long
//! whose tangent is round-off (~εR/h), a node-to-node pressure ripple ∝ 1/h² (0.15 p0 at 1e-6
//! mm, since removed: src/body/bem/surface.rs), which the bisection of such a grid read as
//! error and the marking graded towards, deeper every pass, while the estimate grew; left alone
//! a run chases such noise to `contact.grid.max_elements` and returns its worst solution. The
//! floor keeps whatever noise is left (round-off growing with the system's condition, a body
//! model's own) from doing that.
//!
//! The rule: the passes on one scene (the stand-ins', or the bodies' own once the loop solves
//! them) keep their best pass, the one with the smallest traction estimate (the larger of the
//! RMS estimates of p/p0 and q/(μp0); the creepage and overlap are integrals, in which a
//! node-to-node ripple cancels). A pass whose traction estimate exceeds [`RISE`] times the best
//! one, and the tolerance, ends the run: the best pass's grid is solved again (warm from its solution: the same
//! solution) and returned as the result with its estimate, not reaching the tolerance
//! (exit code 2), and the error names the element length at which the estimate rose.

use super::contribution::{Env, Held};
use super::{ended, solve_on, Adapted};
use crate::contact::residual::State;
use crate::error::Error;
use crate::grid::ContactGrid;
use crate::post::adaptation::{ErrorEstimate, RefinementFloor};
use crate::scene::Scene;

/// How many times the best pass's traction estimate a later pass's must exceed for the loop to
/// take the rise as noise [-]. The refinement aims each pass at 0.6 times the tolerance and a
/// pass that falls short of it still falls; a rise by 4 is far outside what the shipped cases
/// show (at most 1.5) and far inside the rises that noise gave (16 to 40 times a pass on the
/// Gmsh bore at 1e-5 before its contact frame's slope round-off was removed).
pub const RISE: f64 = 4.0;

/// The best pass on the scene the passes solve now.
#[derive(Debug, Clone)]
pub(super) struct Best {
    /// The grid of its result, H.
    pub grid: ContactGrid,
    /// Its result's solution on `grid`.
    pub state: State,
    /// Its traction estimate, the larger of the RMS estimates of p/p0 and q/(μp0) [-].
    pub traction: f64,
    /// Its whole estimate, as recorded for the pass.
    pub estimate: ErrorEstimate,
    /// Its number among the run's passes (1 the first).
    pub pass: usize,
}

impl Best {
    /// The pass whose result is `h`, with its traction estimate `traction`, its whole
    /// `estimate` and its number `pass`.
    pub(super) fn of(h: &Held, traction: f64, estimate: ErrorEstimate, pass: usize) -> Self {
        Best {
            grid: h.grid().clone(),
            state: h.state().clone(),
            traction,
            estimate,
            pass,
        }
    }
}

/// The passes' best so far, reset when the scene they solve changes.
#[derive(Debug, Default)]
pub(super) struct FloorWatch {
    best: Option<Best>,
}

/// The traction estimate of `e`: the larger of its RMS estimates of p/p0 and q/(μp0) [-].
pub(super) fn traction_estimate(e: &ErrorEstimate) -> f64 {
    e.pressure_rms.max(e.shear_rms)
}

impl FloorWatch {
    /// Forgets the best pass: the passes solve another scene from now on.
    pub(super) fn reset(&mut self) {
        self.best = None;
    }

    /// The best pass, when a pass whose traction estimate is `traction` rose above [`RISE`]
    /// times its estimate and above the `tolerance`. A rise that stays within the tolerance is
    /// no noise that matters: a first pass whose two grids agree by chance far below the
    /// tolerance, then refined by the a-priori length rule, shows its true error only on the
    /// next (the Winkler foundation of tests/validation/winkler.rs at 1e-4: 2.9e-8, then 6.2e-7).
    pub(super) fn risen(&self, traction: f64, tolerance: f64) -> Option<&Best> {
        self.best
            .as_ref()
            .filter(|b| traction > RISE * b.traction && traction > tolerance)
    }

    /// Keeps `pass` when it is the best so far (its traction estimate the smallest).
    pub(super) fn offer(&mut self, pass: Best) {
        if self.best.as_ref().is_none_or(|b| pass.traction < b.traction) {
            self.best = Some(pass);
        }
    }
}

/// The run's result when the pass `risen_h` (the bisected grid's solve), whose traction
/// estimate `risen` rose far above the `best` pass's on `pass_scene` (module docs): the best
/// pass's grid solved again, warm from its solution, returned with its estimate, not reaching
/// the tolerance.
pub(super) fn at_the_floor(
    pass_scene: &Scene,
    bodies: &Scene,
    best: Best,
    risen: f64,
    risen_h: Held,
    from_stand_ins: bool,
    mut env: Env<'_>,
) -> Result<Adapted, Error> {
    let risen_shortest = risen_h.grid().shortest_element();
    // The risen pass's matrices go before the best pass's are built again.
    drop(risen_h);
    let risen_pass = env.steps.len();
    log::warn!(
        "error control, pass {risen_pass}: the estimate rose to {risen:.2e} from {:.2e} at pass {} as the elements \
         reached {risen_shortest:.3e}: the solution's noise, not its discretisation error; the result is pass {}'s",
        best.traction,
        best.pass,
        best.pass
    );
    let mut s = solve_on(
        pass_scene.on_grid(best.grid.clone()),
        Some((&best.grid, &best.state)),
        false,
        Some(env.run),
        &mut env.timings,
        &mut env.ws,
    )?;
    s.from_stand_ins = from_stand_ins;
    let mut done = ended(s, bodies, env, false, None);
    if let Some(a) = done.adaptation.as_mut() {
        a.estimate = Some(best.estimate);
        a.floor = Some(RefinementFloor {
            best_pass: best.pass,
            best_estimate: best.traction,
            risen_pass,
            risen_estimate: risen,
            shortest_element: risen_shortest,
            best_shortest_element: best.grid.shortest_element(),
        });
    }
    Ok(done)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::grid::ElementKind;

    fn pass(traction: f64, number: usize) -> Best {
        let grid = ContactGrid::uniform(ElementKind::DiscontinuousQuadratic, 2, -1.0, 1.0);
        let n = grid.n_nodes();
        Best {
            state: State {
                gap: vec![0.0; n],
                slip: vec![0.0; n],
                pressure: vec![0.0; n],
                shear: vec![0.0; n],
                overlap: 0.0,
                creep: 0.0,
            },
            grid,
            traction,
            estimate: ErrorEstimate {
                pressure_rms: traction,
                shear_rms: 0.0,
                creep_rel: 0.0,
                overlap_rel: None,
                body_mesh: None,
            },
            pass: number,
        }
    }

    /// A falling or slowly wavering estimate is not a rise; a rise above RISE times the best
    /// pass's (not the last pass's) and above the tolerance is, and a reset forgets the best.
    #[test]
    fn only_a_rise_above_the_best_pass_by_the_factor_counts() {
        let mut w = FloorWatch::default();
        assert!(w.risen(1.0, 1e-6).is_none(), "no pass yet");
        w.offer(pass(1e-3, 1));
        w.offer(pass(1e-5, 2));
        w.offer(pass(3e-5, 3)); // rose 3 times: kept watching, not the best
        assert!(w.risen(3.9e-5, 1e-6).is_none());
        let best = w.risen(4.1e-5, 1e-6).expect("a rise above 4 times the best");
        assert_eq!(best.pass, 2);
        // Within the tolerance a rise does not count.
        assert!(w.risen(4.1e-5, 1e-4).is_none());
        w.reset();
        assert!(w.risen(1.0, 1e-6).is_none(), "forgotten");
    }
}
