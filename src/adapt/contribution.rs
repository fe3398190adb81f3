//! The error contributions of the error-control loop (src/adapt.rs): each part of a run's error
//! that the loop controls is one implementation of [`ErrorContribution`], and says what it
//! found as one value, a [`Contribution`].
//!
//! The loop solves a pass (a grid G and its bisection H), asks the contributions in order, and
//! acts on the first whose [`Verdict`] is not [`Verdict::Met`]: it marks and refines the contact
//! grid ([`Verdict::Refine`]), solves the passes again on other bodies from this pass's grid
//! ([`Verdict::Rebuild`]), or stops ([`Verdict::Ended`]); with every contribution met, H's
//! solution (or the one a contribution put in its place) is the result. The contributions a
//! pass always collects come first (the contact grid's, the overlap's: cheap, from G's and H's
//! solutions); those that solve other problems ([`ErrorContribution::checks_the_result`]: the
//! stand-ins', the bodies' meshes') are asked only once all before them are met.
//!
//! The loop knows nothing of the bodies: a contribution that offers a cheaper scene for the
//! passes (the BEM bodies' stand-ins) returns it from [`ErrorContribution::start`], and one
//! with nothing to check (no stand-ins, no meshes of the bodies' own: half-space scenes) is
//! met. Adding a contribution: implement the trait, and add it to the list of
//! [`super::solve_with`] (the order is the order it is asked in).

use super::a_priori::{resolved, APriori};
use super::cells::DyadicGrid;
use super::estimate::{Comparison, ErrorEstimator, Pass, Scales};
use super::Solve;
use crate::body::RunCaches;
use crate::contact::{WithoutSlipBlocks, Workspace};
use crate::error::Error;
use crate::post::adaptation::{AdaptationStep, ErrorEstimate};
use crate::post::Timings;
use crate::scene::Scene;

/// What one contribution found on a pass.
#[derive(Debug)]
pub struct Contribution {
    /// The contribution's name (for the log).
    pub name: &'static str,
    /// Its largest estimated relative error [-] (RMS of p/p0 and q/(μp0), relative creepage or
    /// overlap), None where it estimated nothing.
    pub estimate: Option<f64>,
    /// What the loop is to do.
    pub verdict: Verdict,
}

/// What a contribution asks of the loop.
#[derive(Debug)]
pub enum Verdict {
    /// Within the tolerance, or nothing to check.
    Met,
    /// The contact grid is to be refined: the loop marks its elements by the contact grid's
    /// indicators and the pass's estimate.
    Refine,
    /// The passes are to be solved again, from this pass's grid G and from the result's
    /// solution.
    Rebuild(Rebuild),
    /// The loop stops with the result as it is: `reached` false when the tolerance is out of
    /// reach (then the run ends with exit code 2); `too_coarse` names the bodies whose meshes
    /// were too coarse for it, if that is why.
    Ended {
        /// Whether the result is as good as the loop can make it (a solve that did not
        /// converge ends the loop with `reached` true: the report says why).
        reached: bool,
        /// The bodies whose own meshes stayed too coarse (`Error::BodyMeshTooCoarse`).
        too_coarse: Option<String>,
    },
}

/// On what the passes are solved again ([`Verdict::Rebuild`]).
#[derive(Debug)]
pub enum Rebuild {
    /// The bodies themselves, no longer a cheaper scene that stood in for them.
    Bodies,
    /// These bodies in place of the run's (the result is of them): every contribution is
    /// started on them again ([`ErrorContribution::start`]).
    New(Box<Scene>),
}

/// One part of the error the loop controls (module docs).
pub trait ErrorContribution {
    /// The name in the log.
    fn name(&self) -> &'static str;

    /// Whether it is asked only once every contribution before it is met (it solves other
    /// problems than the pass's), rather than on every pass.
    fn checks_the_result(&self) -> bool {
        false
    }

    /// The run's bodies `bodies`, told at the start and after each [`Rebuild::New`], with the
    /// grid `start` the passes start from: a contribution may return a cheaper scene that the
    /// passes solve in their place (the BEM bodies' stand-ins).
    fn start(&mut self, bodies: &Scene, start: &DyadicGrid, env: &mut Env<'_>) -> Result<Option<Scene>, Error> {
        let _ = (bodies, start, env);
        Ok(None)
    }

    /// What it finds on the pass `round`.
    fn assess(&mut self, round: &mut Round<'_, '_>) -> Result<Contribution, Error>;
}

/// What every solve of the run shares: the run's caches, its times, its workspace, its passes.
pub struct Env<'a> {
    /// The caches of the run's body builds.
    pub(super) run: &'a RunCaches,
    /// The times of the stages, summed over the run.
    pub(super) timings: Timings,
    /// The solver's workspace.
    pub(super) ws: Workspace,
    /// The passes so far.
    pub(super) steps: Vec<AdaptationStep>,
    /// The tolerance.
    pub(super) tolerance: f64,
}

/// The solution of H as the loop holds it: whole, or waiting for its outputs without its slip
/// blocks while a check solves other problems.
pub(super) enum Held {
    Whole(Solve),
    Waiting(Solve<WithoutSlipBlocks>),
}

impl Held {
    /// Its grid and solution, the warm start of the next solve.
    pub(super) fn into_warm(self) -> (crate::grid::ContactGrid, crate::contact::residual::State) {
        match self {
            Held::Whole(s) => (s.problem.grid, s.state),
            Held::Waiting(s) => (s.problem.grid().clone(), s.state),
        }
    }

    /// Its grid.
    pub(super) fn grid(&self) -> &crate::grid::ContactGrid {
        match self {
            Held::Whole(s) => &s.problem.grid,
            Held::Waiting(s) => s.problem.grid(),
        }
    }

    /// Its solution.
    pub(super) fn state(&self) -> &crate::contact::residual::State {
        match self {
            Held::Whole(s) => &s.state,
            Held::Waiting(s) => &s.state,
        }
    }

    /// The solve, whole.
    pub(super) fn whole(self) -> Solve {
        match self {
            Held::Whole(s) => s,
            Held::Waiting(s) => s.with_slip_blocks(),
        }
    }
}

/// One pass as the contributions see it: the bodies, the two grids' solutions, the units of
/// the errors, and the pass's estimate (which the contributions complete).
pub struct Round<'a, 'e> {
    /// The run's bodies (the result is of them).
    pub(super) bodies: &'a Scene,
    /// The pass's grid G.
    pub(super) coarse: &'a DyadicGrid,
    /// The solve on G (None once a check has taken it).
    pub(super) g: Option<Solve>,
    /// The solve on H: the result, unless a contribution puts another in its place.
    pub(super) h: Option<Held>,
    /// The units of the errors.
    pub(super) scales: Scales,
    /// Where H's tractions have square-root points [length].
    pub(super) singular: Vec<f64>,
    /// The a-priori lengths at those points.
    pub(super) lengths: APriori,
    /// The contact grid's comparison, whose indicators the loop marks by.
    pub(super) comparison: Option<Comparison>,
    /// The pass's estimate, as the contributions complete it.
    pub(super) estimate: ErrorEstimate,
    /// What the solves share.
    pub(super) env: &'a mut Env<'e>,
}

impl Round<'_, '_> {
    /// The run's tolerance [-].
    pub fn tolerance(&self) -> f64 {
        self.env.tolerance
    }

    /// The run's bodies.
    pub fn bodies(&self) -> &Scene {
        self.bodies
    }

    /// The elements of the pass's bisected grid H.
    pub fn elements(&self) -> usize {
        2 * self.coarse.len()
    }

    /// The pass's estimate so far.
    pub fn estimate(&self) -> &ErrorEstimate {
        &self.estimate
    }

    /// The result's solve taken out of the round, waiting without its slip blocks (made so if
    /// it was whole); whoever takes it puts the result back (`h`).
    pub(super) fn take_waiting(&mut self) -> Solve<WithoutSlipBlocks> {
        match self.h.take().expect("the pass's result") {
            Held::Whole(s) => s.without_slip_blocks(),
            Held::Waiting(s) => s,
        }
    }
}

/// The contact grid's contribution: the estimate of H's error from the comparison of G's and
/// H's solutions by an [`ErrorEstimator`], met when it (without the overlap, which has its own
/// contribution) is within the tolerance and every square-root point lies in an element of
/// at most its a-priori length.
pub struct ContactGrid<'e> {
    /// The estimator.
    pub estimator: &'e mut dyn ErrorEstimator,
}

impl ErrorContribution for ContactGrid<'_> {
    fn name(&self) -> &'static str {
        "contact grid"
    }

    fn assess(&mut self, round: &mut Round<'_, '_>) -> Result<Contribution, Error> {
        let g = round.g.as_ref().expect("the pass's solve on G");
        let Some(Held::Whole(h)) = round.h.as_ref() else {
            unreachable!("the contact grid is assessed first, on the pass's solve")
        };
        let cmp = self.estimator.estimate(&Pass {
            coarse_grid: &g.problem.grid,
            coarse: &g.state,
            fine_grid: &h.problem.grid,
            fine: &h.state,
            singular: &round.singular,
            scales: round.scales,
        });
        round.estimate = cmp.estimate;
        let largest = cmp.estimate.largest();
        let met = largest <= round.tolerance() && resolved(&h.problem.grid, &round.singular, &round.lengths);
        round.comparison = Some(cmp);
        Ok(Contribution {
            name: self.name(),
            estimate: Some(largest),
            verdict: if met { Verdict::Met } else { Verdict::Refine },
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::adapt::estimate::BisectionEstimator;
    use crate::adapt::{controlled, overlap};

    /// A contribution of a test: asks for one rebuild on the bodies, then is met; counts how
    /// often it is asked and on how many elements.
    struct OneRebuild {
        asked: Vec<usize>,
    }

    impl ErrorContribution for OneRebuild {
        fn name(&self) -> &'static str {
            "one rebuild"
        }

        fn checks_the_result(&self) -> bool {
            true
        }

        fn assess(&mut self, round: &mut Round<'_, '_>) -> Result<Contribution, Error> {
            self.asked.push(round.elements());
            let verdict = match self.asked.len() {
                1 => Verdict::Rebuild(Rebuild::Bodies),
                _ => Verdict::Met,
            };
            Ok(Contribution {
                name: self.name(),
                estimate: None,
                verdict,
            })
        }
    }

    /// The extension point: a contribution added to the loop's list drives it. On
    /// cases/carter2d_contact.yaml at 1e-3 the loop without it stops on the first pass whose
    /// contact grid meets the tolerance; with it, it is asked there (and only there: a check of
    /// the result is asked once the grid is met), the loop solves that pass's grid again, the
    /// contribution is asked again on the same grid, is met, and the run ends one pass later
    /// on the same grid with the tolerance met.
    #[test]
    fn a_contribution_of_its_own_drives_the_loop() {
        let case = crate::case::load(
            &crate::case::shipped("carter2d_contact.yaml"),
            &["contact.grid.tolerance=1e-3".to_string()],
        )
        .unwrap();
        let scene = Scene::from_case(&case).unwrap();
        let run = |toy: Option<&mut OneRebuild>| {
            let mut estimator = BisectionEstimator;
            let mut list: Vec<Box<dyn ErrorContribution + '_>> = vec![
                Box::new(ContactGrid {
                    estimator: &mut estimator,
                }),
                Box::new(overlap::Overlap),
            ];
            if let Some(toy) = toy {
                list.push(Box::new(ToyRef(toy)));
            }
            controlled(&scene, &mut list, None)
                .unwrap()
                .adaptation
                .expect("an error-controlled run")
        };
        let plain = run(None);
        let mut toy = OneRebuild { asked: Vec::new() };
        let driven = run(Some(&mut toy));
        assert!(plain.reached && driven.reached);
        let last = |a: &crate::post::adaptation::GridAdaptation| a.steps.last().unwrap().elements;
        assert_eq!(driven.steps.len(), plain.steps.len() + 1, "{:?}", toy.asked);
        assert_eq!(toy.asked, vec![last(&plain), last(&plain)]);
        assert_eq!(last(&driven), last(&plain));
        assert!(driven.estimate.unwrap().within(1e-3));
    }

    /// A borrowed contribution in the loop's list (the test reads it after the run).
    struct ToyRef<'t>(&'t mut OneRebuild);

    impl ErrorContribution for ToyRef<'_> {
        fn name(&self) -> &'static str {
            self.0.name()
        }

        fn checks_the_result(&self) -> bool {
            self.0.checks_the_result()
        }

        fn assess(&mut self, round: &mut Round<'_, '_>) -> Result<Contribution, Error> {
            self.0.assess(round)
        }
    }
}
