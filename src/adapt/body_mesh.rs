//! The error of the bodies' own meshes outside the contact (a BEM body's free boundary, shaft,
//! rim), estimated once the contact grid meets the tolerance.
//!
//! The contact grid's estimate compares a grid with its bisection, each body's mesh cut along
//! the grid; the rest of a BEM body's mesh stays as the user (or the generator) made it, and its
//! error is invisible to that comparison. Here the solution M of the bodies as given is
//! compared with the solution M' of the bodies with every element outside the contact bisected
//! ([`crate::body::setup::BodySetup::with_free_boundary_bisected`]: new nodes on each
//! element's own curve): the RMS differences of p/p0 and q/(μp0) over the contact, the
//! relative differences of ξ and (where [`super::overlap::controlled`]) δ. With the body
//! mesh's error falling as h^k under bisection, M's error is the difference times
//! 2^k/(2^k − 1); the quadratic elements' boundary tractions converge at least at k = 2, so
//! the factor [`BODY_MESH_ESTIMATE_FACTOR`] is 4/3 (7/6 of the factor 8/7 of k = 3).
//!
//! **The coarsened comparison first.** The bisected bodies cost more than everything else of a
//! run whose meshes are fine already (fig14_true_geometry at 1e-4: 1.15 s of 2.5 s; its roller
//! A has 877 nodes bisected, 539 as given, cut along the check grid). So the meshes are first
//! compared with their coarsening ([`crate::body::setup::BodySetup::with_free_boundary_coarsened`]:
//! the elements outside the contact merged in pairs; 371 nodes). For an error falling as h^k the
//! difference C − M is (2^k − 1) times M's error, so [`COARSENED_ESTIMATE_FACTOR`] = 1/3
//! (k = 2). It is the estimate when it lies [`COARSENED_MARGIN`] times below the tolerance:
//! the coarsened mesh is further from the asymptotic range than the bisected one, and its
//! estimate spreads more. Against the bisection's estimate it measured 1.1–4.3 times on the
//! shipped roller meshes and 10–15 on the bores' (whose graded free boundaries, merged, are
//! far coarser next to the contact); against the true error of the coarse roller of
//! docs/validation.md 1.8–2.1, but 0.34 for the creepage, which the margin covers. Otherwise
//! (and for bodies that cannot be coarsened) the bisection decides, as above.
//!
//! Both are solved on a check grid coarser than the final one (src/adapt.rs chooses it: the
//! finer of the grids the BEM's stand-ins are fitted on): the bisection changes a body's
//! flexibility by a smooth remainder, and the solution's response to it needs the contact's
//! size and zones resolved, not its square-root points (the coarse roller's estimate of
//! docs/validation.md moves by under 2 % from the final grid to the check grid). The changed
//! bodies' element integrals are accurate to
//! [`crate::body::setup::CHECK_QUADRATURE_TOLERANCE`] (1e-9, against 1e-12): the differences the
//! check measures matter from a fifth of the tolerance, and the looser rule takes a sixth off
//! the bisected bodies' assembly, which is most of the check's cost.
//!
//! Above the tolerance, the bisected bodies are adopted (src/adapt.rs refines the contact
//! grid again on them) and estimated in turn, at most [`MAX_BODY_MESH_BISECTIONS`] times; a
//! body mesh still too coarse then ends the run with exit code 2 and a message naming the body,
//! its mesh and its groups (`Error::BodyMeshTooCoarse`).

use super::contribution::{Contribution, ErrorContribution, Held, Rebuild, Round, Verdict};
use super::corrections::GivenBodies;
use super::estimate::Scales;
use super::{overlap, solve_on};
use crate::body::setup::ChangedFor;
use crate::body::{BodySetup, RunCaches};
use crate::contact::residual::State;
use crate::contact::Workspace;
use crate::error::Error;
use crate::grid::ContactGrid;
use crate::post::adaptation::{BodyMeshComparison, BodyMeshError};
use crate::post::norms::node_lengths;
use crate::post::Timings;
use crate::scene::Scene;
use std::sync::Arc;

/// The factor of the difference between the body meshes and their bisection (module docs).
pub const BODY_MESH_ESTIMATE_FACTOR: f64 = 4.0 / 3.0;

/// The factor of the difference between the body meshes coarsened outside the contact and as
/// given (module docs: 1/(2^k − 1) for k = 2).
pub const COARSENED_ESTIMATE_FACTOR: f64 = 1.0 / 3.0;

/// How far below the tolerance the coarsened comparison's estimate must lie to be the
/// estimate (module docs): with its lowest measured effectivity, 0.34, the true error is then
/// under 0.6 of the tolerance.
pub const COARSENED_MARGIN: f64 = 5.0;

/// Most times the error control bisects the bodies' meshes outside the contact before it
/// stops with exit code 2 (each bisection doubles their elements there).
pub const MAX_BODY_MESH_BISECTIONS: usize = 2;

/// What the body-mesh check found.
pub(super) struct Checked {
    /// The estimate of the bodies' meshes' error ([`estimate`]: against the bisected meshes,
    /// or the coarsened ones when that comparison bounded it below the tolerance).
    pub estimate: BodyMeshError,
    /// The scene with its bodies bisected outside the contact, to adopt when the estimate
    /// exceeds the tolerance; None when the coarsened comparison sufficed.
    pub bisected: Option<Scene>,
}

/// The scene with every body that has a mesh of its own bisected outside the contact, None
/// when no body has one.
pub(super) fn bisected(scene: &Scene, changed_for: ChangedFor) -> Option<Scene> {
    with_bodies(scene, |b| b.with_free_boundary_bisected(changed_for))
}

/// The scene with every body that has a mesh of its own coarsened outside the contact
/// (elements merged in pairs), None when no body has one.
pub(super) fn coarsened(scene: &Scene) -> Option<Scene> {
    with_bodies(scene, |b| b.with_free_boundary_coarsened(ChangedFor::Check))
}

/// The scene with each body replaced by `change(body)` where that is Some; None when no body
/// changed.
fn with_bodies(scene: &Scene, change: impl Fn(&Arc<dyn BodySetup>) -> Option<Arc<dyn BodySetup>>) -> Option<Scene> {
    let mut any = false;
    let bodies = scene.bodies.clone().map(|b| match change(&b) {
        Some(changed) => {
            any = true;
            changed
        }
        None => b,
    });
    any.then(|| Scene::new(scene.case.clone(), bodies))
}

/// The bodies with meshes of their own, for messages: `body A (path, groups free, shaft)`.
pub(super) fn meshed_bodies(scene: &Scene) -> String {
    scene
        .bodies
        .iter()
        .zip(["A", "B"])
        .filter_map(|(b, name)| b.free_boundary_label().map(|l| format!("body {name} ({l})")))
        .collect::<Vec<_>>()
        .join(" and ")
}

/// The bodies' meshes' contribution: once the contact grid meets the tolerance, the bodies'
/// own meshes outside the contact checked on `grid` ([`check_on`], the module docs), and
/// bisected ([`Rebuild::New`]) while their estimate exceeds the tolerance, at most
/// [`MAX_BODY_MESH_BISECTIONS`] times; met when no body has a mesh of its own.
pub(super) struct BodyMeshes {
    /// The grid the check solves on (coarser than the final one: module docs).
    pub(super) grid: ContactGrid,
    /// How often the bodies' meshes were bisected so far.
    pub(super) bisections: usize,
}

impl ErrorContribution for BodyMeshes {
    fn name(&self) -> &'static str {
        "body meshes"
    }

    fn checks_the_result(&self) -> bool {
        true
    }

    fn assess(&mut self, round: &mut Round<'_, '_>) -> Result<Contribution, Error> {
        let tolerance = round.env.tolerance;
        // The result waits for its outputs without its slip blocks: two m × m blocks fewer
        // beside the check's bodies (the braking bore's: 31 MB). The check solves on a coarser
        // grid than the final one: the final grid's Newton matrix goes before the check's
        // condensations are made (the braking bore's: 25 MB).
        let met = round.take_waiting();
        let env = &mut *round.env;
        env.ws = Workspace::new();
        let checked = check_on(
            round.bodies,
            &self.grid,
            (met.problem.grid(), &met.state),
            round.scales,
            tolerance,
            self.bisections == 0,
            env.run,
            &mut env.timings,
            &mut env.ws,
        );
        round.h = Some(Held::Waiting(met));
        let contribution = |estimate: Option<f64>, verdict: Verdict| Contribution {
            name: "body meshes",
            estimate,
            verdict,
        };
        let Some(checked) = checked? else {
            return Ok(contribution(None, Verdict::Met));
        };
        let mut e = checked.estimate;
        e.bisections = self.bisections;
        if let Some(last) = round.env.steps.last_mut() {
            last.estimate.body_mesh = Some(e);
        }
        if e.largest() <= tolerance {
            return Ok(contribution(Some(e.largest()), Verdict::Met));
        }
        let Some(bisected) = checked.bisected.filter(|_| self.bisections < MAX_BODY_MESH_BISECTIONS) else {
            let ended = Verdict::Ended {
                reached: false,
                too_coarse: Some(meshed_bodies(round.bodies)),
            };
            return Ok(contribution(Some(e.largest()), ended));
        };
        // The bisected bodies are adopted: the contact grid is refined again on them from the
        // last pass's grid, warm from its solution (the bisection outside the contact moves the
        // square-root points only within the grid's tolerance; starting over from the start
        // grid repeated every pass: bore_a001 at 1e-5, about 67 s).
        log::info!(
            target: crate::logging::PROGRESS,
            "error control: the bodies' meshes outside the contact are too coarse for the tolerance; \
             solving again with them bisected"
        );
        self.bisections += 1;
        Ok(contribution(
            Some(e.largest()),
            Verdict::Rebuild(Rebuild::New(Box::new(bisected))),
        ))
    }
}

/// Checks the meshes of `scene`'s bodies (as given, before any cut along a grid) on `grid`,
/// each solve from `warm` (the final grid's solution carried): first, with `try_coarsened`,
/// the scene against the scene with its bodies coarsened outside the contact
/// ([`estimate`]), which is cheap and, when it lies [`COARSENED_MARGIN`] times below
/// `tolerance`, the estimate; else against the bodies bisected there. None when
/// no body has a mesh of its own, or when a solve does not converge (logged: the result stays
/// unestimated).
///
/// The changed bodies are solved as corrections of the given bodies' problem
/// ([`super::corrections`]: factored, not solved for every unit load), or where the
/// corrections do not settle, condensed on the grid.
///
/// After an adoption the caller passes `try_coarsened` false: the bisected bodies' coarsening
/// is the bodies checked before, whose estimate was above the tolerance, so a third of their
/// difference cannot lie five times below it.
///
/// The bodies are built with the run's caches `run`: the given bodies take the condensation
/// their stand-ins made on `grid`, and the bodies bisected for the run
/// ([`ChangedFor::Run`]) keep theirs for the next stand-ins and check.
#[allow(clippy::too_many_arguments)]
pub(super) fn check_on(
    scene: &Scene,
    grid: &ContactGrid,
    warm: (&ContactGrid, &State),
    scales: Scales,
    tolerance: f64,
    try_coarsened: bool,
    run: &RunCaches,
    timings: &mut Timings,
    ws: &mut Workspace,
) -> Result<Option<Checked>, Error> {
    // Solved with integrals to the check's accuracy; the bodies adopted (`Checked::bisected`)
    // are bisected again with the run's.
    let Some(fine_scene) = bisected(scene, ChangedFor::Check) else {
        return Ok(None);
    };
    let controlled = overlap::controlled(scene);
    // The given bodies' problem is the base of the changed bodies' problems, whose slip blocks
    // are made in place of its own (`GivenBodies`).
    let mut given =
        solve_on(scene.on_grid(grid.clone()), Some(warm), false, Some(run), timings, ws)?.without_slip_blocks();
    if !given.report.converged {
        return Ok(unestimated());
    }
    let given_state = given.state.clone();
    let mut base = GivenBodies {
        problem: &mut given.problem,
        models: &given.models,
        state: &given_state,
    };
    let mut solve = |changed: &Scene, timings: &mut Timings, ws: &mut Workspace| -> Result<Option<State>, Error> {
        let on = changed.on_grid(grid.clone());
        let distance = |a: &State, b: &State| difference(grid, a, b, scales, controlled).largest();
        if let Some(z) = base.solve_changed(&on, &scene.solver, distance, Some(run), timings, ws)? {
            return Ok(Some(z));
        }
        let full = solve_on(on, Some((grid, &given_state)), false, Some(run), timings, ws)?;
        Ok(full.report.converged.then_some(full.state))
    };
    if let Some(coarse_scene) = coarsened(scene).filter(|_| try_coarsened) {
        log::info!(
            target: crate::logging::PROGRESS,
            "error control: the bodies' meshes checked on a grid of {} elements, as given and coarsened \
             outside the contact",
            grid.n_elements()
        );
        // Merging a coarse mesh's elements in pairs can give a boundary that crosses itself
        // (a pair spanning more than a half circle): the bisected comparison still applies.
        match solve(&coarse_scene, timings, ws) {
            Ok(Some(coarse)) => {
                let estimate = estimate(
                    BodyMeshComparison::Coarsened,
                    grid,
                    &given_state,
                    &coarse,
                    scales,
                    controlled,
                );
                log_estimate("coarsened", &estimate);
                if estimate.largest() * COARSENED_MARGIN <= tolerance {
                    return Ok(Some(Checked {
                        estimate,
                        bisected: None,
                    }));
                }
            }
            Ok(None) => log::info!(
                target: crate::logging::PROGRESS,
                "error control: the coarsened bodies' solve did not converge"
            ),
            Err(e) => log::info!(
                target: crate::logging::PROGRESS,
                "error control: the bodies' meshes do not coarsen ({e})"
            ),
        }
    }
    log::info!(
        target: crate::logging::PROGRESS,
        "error control: the bodies' meshes checked on a grid of {} elements, as given and bisected \
         outside the contact",
        grid.n_elements()
    );
    let Some(fine) = solve(&fine_scene, timings, ws)? else {
        return Ok(unestimated());
    };
    let estimate = estimate(
        BodyMeshComparison::Bisected,
        grid,
        &given_state,
        &fine,
        scales,
        controlled,
    );
    log_estimate("bisected", &estimate);
    Ok(Some(Checked {
        estimate,
        bisected: bisected(scene, ChangedFor::Run),
    }))
}

/// A check whose solve did not converge: logged, no estimate.
fn unestimated() -> Option<Checked> {
    log::warn!(
        "a solve of the check of the bodies' meshes outside the contact did not converge: \
         their error is not estimated"
    );
    None
}

fn log_estimate(against: &str, e: &BodyMeshError) {
    log::info!(
        target: crate::logging::PROGRESS,
        "error control, body meshes (against {against}): estimated error: pressure {:.2e} p0, \
         shear {:.2e} mu p0, creepage {:.2e}",
        e.pressure,
        e.shear,
        e.creepage_rel
    );
}

/// `d` times `f`.
fn scaled(d: BodyMeshError, f: f64) -> BodyMeshError {
    BodyMeshError {
        creepage_rel: f * d.creepage_rel,
        overlap_rel: d.overlap_rel.map(|o| f * o),
        pressure: f * d.pressure,
        shear: f * d.shear,
        ..d
    }
}

/// The estimate of the body meshes' error from the solution `given` (the bodies as given) and
/// `other` on the same `grid` (module docs): `other` has the bodies bisected outside the contact
/// (the difference times [`BODY_MESH_ESTIMATE_FACTOR`]) or coarsened there (times
/// [`COARSENED_ESTIMATE_FACTOR`]), as `against` says.
pub fn estimate(
    against: BodyMeshComparison,
    grid: &ContactGrid,
    given: &State,
    other: &State,
    scales: Scales,
    overlap_controlled: bool,
) -> BodyMeshError {
    let (d, factor) = match against {
        BodyMeshComparison::Bisected => (
            difference(grid, given, other, scales, overlap_controlled),
            BODY_MESH_ESTIMATE_FACTOR,
        ),
        BodyMeshComparison::Coarsened => (
            difference(grid, other, given, scales, overlap_controlled),
            COARSENED_ESTIMATE_FACTOR,
        ),
    };
    BodyMeshError {
        compared_with: against,
        ..scaled(d, factor)
    }
}

/// The differences of two solutions on the same `grid` in the estimate's norms, with no factor:
/// the RMS of p/p0 and q/(μp0) over the contact (from the first to the last node loaded in
/// either), the relative differences of ξ (of at least the creepage floor) and, where
/// controlled, δ.
pub fn difference(
    grid: &ContactGrid,
    coarse: &State,
    fine: &State,
    scales: Scales,
    overlap_controlled: bool,
) -> BodyMeshError {
    let x = &grid.nodes;
    let w = node_lengths(x);
    // The contact: from the first to the last node loaded in either solution.
    let loaded = |i: &usize| fine.pressure[*i] > 0.0 || coarse.pressure[*i] > 0.0;
    let first = (0..x.len()).find(loaded);
    let last = (0..x.len()).rev().find(loaded);
    let rms = |scale: f64, d: &dyn Fn(usize) -> f64| -> f64 {
        let (Some(a), Some(b)) = (first, last) else {
            return 0.0;
        };
        let length: f64 = (a..=b).map(|i| w[i]).sum();
        if !(length > 0.0 && scale > 0.0) {
            return 0.0;
        }
        let sum: f64 = (a..=b).map(|i| w[i] * (d(i) / scale).powi(2)).sum();
        (sum / length).sqrt()
    };
    let pressure = rms(scales.peak_pressure, &|i| fine.pressure[i] - coarse.pressure[i]);
    let shear = rms(scales.friction * scales.peak_pressure, &|i| {
        fine.shear[i] - coarse.shear[i]
    });
    let creepage_rel = if scales.creep_prescribed || scales.friction == 0.0 || fine.creep == coarse.creep {
        0.0
    } else {
        (fine.creep - coarse.creep).abs() / fine.creep.abs().max(scales.creep_floor()).max(f64::MIN_POSITIVE)
    };
    BodyMeshError {
        creepage_rel,
        overlap_rel: overlap_controlled.then(|| overlap::relative_error(coarse.overlap, fine.overlap)),
        pressure,
        shear,
        bisections: 0,
        compared_with: BodyMeshComparison::Bisected,
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::adapt::cells::DyadicGrid;
    use crate::adapt::corrections::GivenBodies;
    use crate::contact::Workspace;
    use crate::grid::ElementKind;

    fn state(grid: &ContactGrid, p: f64, q: f64, creep: f64, overlap: f64) -> State {
        let m = grid.n_nodes();
        State {
            gap: vec![0.0; m],
            slip: vec![0.0; m],
            pressure: vec![p; m],
            shear: vec![q; m],
            overlap,
            creep,
        }
    }

    /// A known uniform difference gives the factor times its scaled size.
    #[test]
    fn a_known_difference_gives_the_factor_times_its_scaled_size() {
        let grid = ContactGrid::uniform(ElementKind::DiscontinuousQuadratic, 5, -1.0, 1.0);
        let scales = Scales {
            peak_pressure: 2.0,
            friction: 0.25,
            creep_prescribed: false,
            complete_slip_creep: 0.0,
            geometry_share: 0.0,
        };
        let (given, other) = (
            state(&grid, 1.0, 0.1, 1e-3, 2e-2),
            state(&grid, 1.02, 0.105, 1.1e-3, 2.2e-2),
        );
        let e = estimate(BodyMeshComparison::Bisected, &grid, &given, &other, scales, true);
        let f = BODY_MESH_ESTIMATE_FACTOR;
        assert!((e.pressure - f * 0.01).abs() < 1e-12, "{e:?}");
        assert!((e.shear - f * 0.01).abs() < 1e-12, "{e:?}");
        assert!((e.creepage_rel - f * 0.1 / 1.1).abs() < 1e-12, "{e:?}");
        assert!((e.overlap_rel.unwrap() - f * 0.1 / 1.1).abs() < 1e-12, "{e:?}");
        assert_eq!(e.compared_with, BodyMeshComparison::Bisected);
        // Against the coarsened meshes the given solution is the finer one: the creepage is
        // relative to its own.
        let e = estimate(BodyMeshComparison::Coarsened, &grid, &given, &other, scales, true);
        let f = COARSENED_ESTIMATE_FACTOR;
        assert!((e.pressure - f * 0.01).abs() < 1e-12, "{e:?}");
        assert!((e.creepage_rel - f * 0.1).abs() < 1e-12, "{e:?}");
        assert_eq!(e.compared_with, BodyMeshComparison::Coarsened);
        let e = estimate(
            BodyMeshComparison::Bisected,
            &grid,
            &given,
            &state(&grid, 1.0, 0.1, 1e-3, 2.2e-2),
            scales,
            false,
        );
        assert_eq!(e.overlap_rel, None);
        assert_eq!(e.largest(), 0.0);
    }

    /// The changed bodies solved as corrections of the given bodies' problem are the changed
    /// bodies condensed on the grid and solved (the fixed point's limit, module docs): for the
    /// roller and ring of cases/bore_a020_tractive.yaml coarsened and bisected outside the
    /// contact, on the start grid's bisection (the check grid of a run at 1e-3), within 1e-9 in
    /// the estimate's norms, while the changed bodies' solutions lie 1e-5 and more from the
    /// given one (what the check measures).
    #[test]
    fn the_corrections_reach_the_changed_bodies_own_solution() {
        let case = crate::case::load(&crate::case::shipped("bore_a020_tractive.yaml"), &[]).unwrap();
        let scene = Scene::from_case(&case).unwrap();
        let grid = DyadicGrid::new(&scene.grid).bisected().grid();
        let (mut timings, mut ws) = (Timings::default(), Workspace::new());
        let mut given = solve_on(scene.on_grid(grid.clone()), None, false, None, &mut timings, &mut ws)
            .unwrap()
            .without_slip_blocks();
        assert!(given.report.converged);
        let scales = Scales {
            peak_pressure: scene.estimates.hertz_peak_pressure,
            friction: scene.friction(),
            creep_prescribed: false,
            complete_slip_creep: 0.0,
            geometry_share: 0.0,
        };
        let state = given.state.clone();
        for changed in [coarsened(&scene).unwrap(), bisected(&scene, ChangedFor::Check).unwrap()] {
            let on = changed.on_grid(grid.clone());
            let mut base = GivenBodies {
                problem: &mut given.problem,
                models: &given.models,
                state: &state,
            };
            let corrected = base
                .solve_changed(
                    &on,
                    &scene.solver,
                    |a, b| difference(&grid, a, b, scales, false).largest(),
                    None,
                    &mut timings,
                    &mut ws,
                )
                .unwrap()
                .expect("the corrections settle");
            let full = solve_on(on, Some((&grid, &state)), false, None, &mut timings, &mut ws).unwrap();
            assert!(full.report.converged);
            let apart = difference(&grid, &state, &full.state, scales, false).largest();
            let off = difference(&grid, &corrected, &full.state, scales, false).largest();
            assert!(
                apart > 1e-5,
                "the changed bodies differ from the given ones: {apart:.2e}"
            );
            assert!(
                off <= 1e-9,
                "corrections {off:.2e} from the condensed bodies' solution ({apart:.2e} apart)"
            );
        }
    }
}
