//! The BEM bodies' pass stand-ins in the error control: the grids they are fitted on and the
//! estimate of their own error on the final grid (src/body/bem/stand_in.rs).

use super::body_mesh;
use super::cells::DyadicGrid;
use super::contribution::{Contribution, Env, ErrorContribution, Held, Rebuild, Round, Verdict};
use super::estimate::Scales;
use super::{carried, solve_on, solve_problem, Solve, WarmFrom};
use crate::body::{FlexibilityChange, RunCaches, Side};
use crate::contact::report::SolveReport;
use crate::contact::residual::State;
use crate::contact::{WithoutSlipBlocks, Workspace};
use crate::error::Error;
use crate::grid::ContactGrid;
use crate::post::adaptation::BodyMeshError;
use crate::post::Timings;
use crate::scene::Scene;
use std::sync::Arc;
use std::time::Instant;

/// The coarser of the two grids the pass stand-ins' result is extrapolated from (their
/// remainder's error falls as the grid's spacing, and Richardson's extrapolation from a grid
/// and its bisection removes most of it): the start grid for tolerances down to 3e-4, bisected
/// once down to 3e-5, twice below (measured on fig14_true_geometry, whose remainder converges
/// slowest of the shipped cases: from the start grid its solution differs from the full BEM's
/// by up to 1.1e-4, from the first bisection by 1e-5).
pub(super) fn level(start: &DyadicGrid, tolerance: f64) -> DyadicGrid {
    bisected_times(start, bisections(tolerance))
}

/// How often [`level`] bisects the start grid ([`crate::body::bem::stand_in::level_bisections`]).
fn bisections(tolerance: f64) -> usize {
    crate::body::bem::stand_in::level_bisections(tolerance)
}

/// `start` bisected `times` times.
fn bisected_times(start: &DyadicGrid, times: usize) -> DyadicGrid {
    (0..times).fold(start.clone(), |g, _| g.bisected())
}

/// The grids the stand-ins are fitted on, coarsest first: [`level`] and its bisection,
/// preceded by the level before when there is one (the start grid cannot be coarsened), which
/// the check of the stand-ins' own error extrapolates from (src/body/bem/stand_in.rs).
pub(super) fn levels(start: &DyadicGrid, tolerance: f64) -> Vec<ContactGrid> {
    let k = bisections(tolerance);
    (k.saturating_sub(1)..=k + 1)
        .map(|times| bisected_times(start, times).grid())
        .collect()
}

/// The stand-ins' contribution: a run's pass stand-ins, whose scene the passes solve (bodies
/// that offer a cheaper stand-in, a BEM body's half-plane plus its smooth remainder, replaced by
/// it), and the check that estimates the stand-ins' own error on the final grid. With no body
/// offering one, or once the passes go on with the bodies themselves, it is met.
#[derive(Default)]
pub(super) struct StandIns {
    /// Whether the passes solve the stand-ins.
    stood_in: bool,
    /// The scene of the stand-ins known less well (None: the final grid is solved with the
    /// bodies themselves).
    check: Option<Scene>,
    /// How the check's bodies differ from the passes' stand-ins, where they offer it.
    changes: Option<Changes>,
    /// [`check_factor`] of the levels the stand-ins were fitted on.
    check_factor: f64,
}

impl ErrorContribution for StandIns {
    fn name(&self) -> &'static str {
        "stand-ins"
    }

    fn checks_the_result(&self) -> bool {
        true
    }

    /// The stand-ins of `bodies`, fitted on the [`levels`] of `start` for the run's tolerance,
    /// their build time added to the run's: the passes' scene, None when no body offers one.
    fn start(&mut self, bodies: &Scene, start: &DyadicGrid, env: &mut Env<'_>) -> Result<Option<Scene>, Error> {
        let t = Instant::now();
        let levels = levels(start, env.tolerance);
        let level_refs: Vec<&ContactGrid> = levels.iter().collect();
        let built = bodies.with_pass_stand_ins(&level_refs, Some(env.run))?;
        let (passes, condense_s) = match built {
            // The two bodies' builds may have overlapped: the condensation's share of the wall time.
            Some(s) => {
                *self = Self {
                    stood_in: true,
                    check: s.check,
                    changes: s.check_changes,
                    check_factor: check_factor(levels.len()),
                };
                (
                    Some(s.passes),
                    Timings::share_of_wall(t.elapsed().as_secs_f64(), s.condense_s, s.build_s),
                )
            }
            None => {
                *self = Self {
                    check_factor: 1.0,
                    ..Self::default()
                };
                (None, 0.0)
            }
        };
        env.timings.assembly_s += t.elapsed().as_secs_f64() - condense_s;
        env.timings.condense_s += condense_s;
        Ok(passes)
    }

    /// The passes' grids G and H, solved on the stand-ins, meet the tolerance with the pass's
    /// estimate: H's solution is the result when the stand-ins' own estimated error
    /// ([`check_difference`] times the check factor) leaves the sum within the tolerance; else
    /// H's grid is solved with the bodies themselves, whose difference from the stand-ins'
    /// solution joins the estimate: met, or the passes go on with the bodies
    /// ([`Rebuild::Bodies`]). The final estimate and the iterations go to the pass's step.
    fn assess(&mut self, round: &mut Round<'_, '_>) -> Result<Contribution, Error> {
        // H's slip blocks go before the check's are made: its problem is the base of the
        // check's changed problems, and its solution waits for its outputs.
        let mut h = round.take_waiting();
        let e = round.estimate;
        let (scene, scales, tolerance) = (round.bodies, round.scales, round.env.tolerance);
        let contribution = |estimate: Option<f64>, verdict: Verdict| Contribution {
            name: "stand-ins",
            estimate,
            verdict,
        };
        if !self.stood_in {
            round.h = Some(Held::Waiting(h));
            return Ok(contribution(None, Verdict::Met));
        }
        let env = &mut *round.env;
        let overlap = e.overlap_rel.is_some();
        if let Some(check) = self.check.as_ref().filter(|_| !asks_interior_fields(scene)) {
            let g = round.g.take().expect("the pass's solve on G");
            let checked = check_difference(
                check,
                self.changes.as_ref(),
                g,
                &mut h,
                scales,
                overlap,
                env.run,
                &mut env.timings,
                &mut env.ws,
            )?;
            if let Some((d, iterations)) = checked {
                let total = e.plus(&d, self.check_factor);
                log::info!(
                    target: crate::logging::PROGRESS,
                    "error control: the stand-ins' own estimated error on the final grid: pressure {:.2e} p0, \
                     shear {:.2e} mu p0, creepage {:.2e}",
                    self.check_factor * d.pressure,
                    self.check_factor * d.shear,
                    self.check_factor * d.creepage_rel
                );
                if total.within(tolerance) {
                    if let Some(last) = env.steps.last_mut() {
                        last.estimate = total;
                        last.iterations += iterations;
                    }
                    round.h = Some(Held::Waiting(h));
                    return Ok(contribution(Some(total.largest()), Verdict::Met));
                }
            }
            // The stand-ins are not known well enough for this tolerance: the final grid is
            // solved with the bodies themselves.
            self.check = None;
        }
        let full = solve_on(
            scene.on_grid(h.problem.grid().clone()),
            Some((h.problem.grid(), &h.state)),
            false,
            Some(env.run),
            &mut env.timings,
            &mut env.ws,
        )?;
        if !full.report.converged {
            drop(h);
            round.h = Some(Held::Whole(full));
            let ended = Verdict::Ended {
                reached: true,
                too_coarse: None,
            };
            return Ok(contribution(None, ended));
        }
        // The bodies themselves differ from their stand-ins by this much on the final grid; the
        // estimate of their solution is the stand-in's plus the difference.
        let d = body_mesh::difference(&full.problem.grid, &h.state, &full.state, scales, overlap);
        drop(h);
        let total = e.plus(&d, 1.0);
        log::info!(
            target: crate::logging::PROGRESS,
            "error control: the bodies themselves on the final grid differ from their pass stand-ins by \
             pressure {:.2e} p0, shear {:.2e} mu p0, creepage {:.2e}",
            d.pressure,
            d.shear,
            d.creepage_rel
        );
        if let Some(last) = env.steps.last_mut() {
            last.estimate = total;
            last.iterations += full.report.iterations;
        }
        if total.within(tolerance) {
            round.h = Some(Held::Waiting(full.without_slip_blocks()));
            return Ok(contribution(Some(total.largest()), Verdict::Met));
        }
        // Not close enough at this tolerance: the passes go on with the bodies themselves, from
        // this grid.
        log::info!(
            target: crate::logging::PROGRESS,
            "error control: the pass stand-ins are not accurate enough at this tolerance; refining \
             with the full bodies"
        );
        self.stood_in = false;
        round.h = Some(Held::Whole(full));
        Ok(contribution(Some(total.largest()), Verdict::Rebuild(Rebuild::Bodies)))
    }
}

/// The factor of the difference between the stand-ins' solution and their check's on the
/// final grid that estimates the stand-ins' error (src/body/bem/stand_in.rs). Fitted on three
/// levels, the check is the Richardson remainder of the two coarser: with the remainder's error
/// c₁h + c₂h², Richardson leaves c₂h²/2 from the two coarser levels and a quarter of that from
/// the two finer, so the finer's is the difference / 3 (Richardson's own error estimate for a
/// second-order term; measured on fig14_true_geometry at 1e-4 and 1e-5: effectivities 0.7–1.2).
/// Fitted on two, the check is the finer level's remainder alone, with the first-order error the
/// extrapolation removes, and the whole difference stands for the result's.
fn check_factor(levels: usize) -> f64 {
    if levels == 3 {
        1.0 / 3.0
    } else {
        1.0
    }
}

/// The stand-ins' check (`check`, the scene of the stand-ins known less well) solved on the final
/// grid H of `h`, and the difference of its solution from `h`'s in the estimate's norms,
/// unscaled, with the Newton iterations the check took; None when a solve does not converge.
/// H's solve starts from `h`'s solution moved by the check's change on the grid G of `g`, solved
/// first (an eighth of a Newton step on H): where the two stand-ins' active sets differ, `h`'s
/// solution alone cost up to seven Newton steps on H (bore_a020_braking at 1e-3), the moved one
/// two.
///
/// With `changes` (how each check body differs from its stand-in, a low-rank change of its
/// flexibility), the check's problems are `g`'s and `h`'s plus the changes
/// ([`WithoutSlipBlocks::with_flexibility_changes`]): the half-plane blocks, the larger part of a
/// stand-in's assembly, are the same in both, and are not made again.
#[allow(clippy::too_many_arguments)]
fn check_difference(
    check: &Scene,
    changes: Option<&Changes>,
    g: Solve,
    h: &mut Solve<WithoutSlipBlocks>,
    scales: Scales,
    overlap_controlled: bool,
    run: &RunCaches,
    timings: &mut Timings,
    ws: &mut Workspace,
) -> Result<Option<(BodyMeshError, usize)>, Error> {
    let solve =
        |on: &mut Solve<WithoutSlipBlocks>, warm: &State, timings: &mut Timings, ws: &mut Workspace| match changes {
            Some(c) => Ok(solve_changed(&mut on.problem, c, check, warm, timings, ws)),
            None => solve_on(
                check.on_grid(on.problem.grid().clone()),
                Some((on.problem.grid(), warm)),
                false,
                Some(run),
                timings,
                ws,
            )
            .map(|s| (s.state, s.report)),
        };
    // Only its solution is needed: its matrices, and the passes' problem on G with its
    // models, go before H's are made.
    let mut g = g.without_slip_blocks();
    let g_start = g.state.clone();
    let (on_g, g_report) = solve(&mut g, &g_start, timings, ws)?;
    let Solve {
        problem: g_problem,
        state: g_state,
        ..
    } = g;
    let g_grid = g_problem.grid().clone();
    drop(g_problem);
    let h_start = match g_report.converged {
        true => moved_by(h.problem.grid(), &h.state, &g_grid, &g_state, &on_g),
        false => h.state.clone(),
    };
    let (on_h, h_report) = solve(h, &h_start, timings, ws)?;
    if !h_report.converged {
        return Ok(None);
    }
    let d = body_mesh::difference(h.problem.grid(), &on_h, &h.state, scales, overlap_controlled);
    Ok(Some((d, g_report.iterations + h_report.iterations)))
}

/// How the check's bodies differ from the passes' stand-ins (A's, B's; None: the same body).
pub(super) type Changes = [Option<Arc<dyn FlexibilityChange>>; 2];

/// The check solved on `base`'s grid, its problem `base` (the passes' problem there) plus
/// `changes`, from `warm` (a solution on that grid); the times added to `timings`.
fn solve_changed(
    base: &mut WithoutSlipBlocks,
    changes: &Changes,
    check: &Scene,
    warm: &State,
    timings: &mut Timings,
    ws: &mut Workspace,
) -> (State, SolveReport) {
    let t = Instant::now();
    log::info!(
        target: crate::logging::PROGRESS,
        "assembling the contact problem: {} contact nodes (the passes' problem with the check's change)",
        base.n_nodes()
    );
    let [a, b] =
        [(0, Side::A), (1, Side::B)].map(|(k, side)| changes[k].as_ref().map(|c| c.on_grid(base.grid(), side)));
    base.with_flexibility_changes([a.as_ref(), b.as_ref()], |pb| {
        timings.assembly_s += t.elapsed().as_secs_f64();
        solve_problem(pb, &check.solver, Some((&pb.grid, warm)), WarmFrom::Pass, timings, ws)
    })
}

/// `z` (a solution on `grid`) moved by the change from `from` to `to` (two solutions on the
/// grid `coarse`), carried to `grid`: the warm start of a solve whose solution differs
/// from `z` as `to` from `from`. Pressure and gap stay ≥ 0.
fn moved_by(grid: &ContactGrid, z: &State, coarse: &ContactGrid, from: &State, to: &State) -> State {
    let (a, b) = (carried(grid, coarse, to), carried(grid, coarse, from));
    let shift = |z: &[f64], a: &[f64], b: &[f64], floor: f64| -> Vec<f64> {
        z.iter()
            .zip(a)
            .zip(b)
            .map(|((z, a), b)| (z + (a - b)).max(floor))
            .collect()
    };
    State {
        gap: shift(&z.gap, &a.gap, &b.gap, 0.0),
        slip: shift(&z.slip, &a.slip, &b.slip, f64::NEG_INFINITY),
        pressure: shift(&z.pressure, &a.pressure, &b.pressure, 0.0),
        shear: shift(&z.shear, &a.shear, &b.shear, f64::NEG_INFINITY),
        overlap: z.overlap + (to.overlap - from.overlap),
        creep: z.creep + (to.creep - from.creep),
    }
}

/// The grid the bodies' meshes are checked on ([`body_mesh::check_on`]): the finer of the
/// stand-ins' two grids. Bisecting a body's mesh outside the contact changes its flexibility by
/// a smooth remainder, like the true geometry's against the half-plane, and the solution's
/// response to that change is set by the contact's size and zones, which this grid resolves
/// to a few percent; the check costs two condensations on it instead of two on the final grid.
/// (The coarser stand-in grid is too coarse: on the coarse roller of docs/validation.md the
/// creepage's estimate fell to 2 % of its true error there.)
pub(super) fn body_mesh_check_grid(start: &DyadicGrid, tolerance: f64) -> ContactGrid {
    level(start, tolerance).bisected().grid()
}

/// Whether the case asks for interior fields (`output.interior`, or the stresses of
/// `output.strength`), which only the bodies themselves give.
fn asks_interior_fields(scene: &Scene) -> bool {
    scene.case.case.output.interior.is_some() || scene.case.case.output.strength.is_some()
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A state of `n` nodes: pressure `p` and shear `p/10` everywhere, gap and slip zero.
    fn uniform_state(n: usize, p: f64, creep: f64) -> State {
        State {
            gap: vec![0.0; n],
            slip: vec![0.0; n],
            pressure: vec![p; n],
            shear: vec![0.1 * p; n],
            overlap: 1e-3,
            creep,
        }
    }

    /// The check's warm start: a solution on the bisected grid moved by the change of two
    /// solutions on the coarse grid, node for node (a uniform change moves every node by it),
    /// with the pressure kept ≥ 0; no change leaves it as it was.
    #[test]
    fn a_fine_solution_is_moved_by_the_coarse_change() {
        let path = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("cases/carter2d_contact.yaml");
        let scene = Scene::from_case(&crate::case::load(&path, &[]).unwrap()).unwrap();
        let coarse = scene.grid.clone();
        let fine = scene.on_grid(DyadicGrid::new(&coarse).bisected().grid());
        let (_, pb) = fine.assemble().unwrap();
        let (n, m) = (coarse.n_nodes(), pb.n_nodes());
        let mut z = uniform_state(m, 5.0, 2e-4);
        z.pressure[0] = 0.5;
        let from = uniform_state(n, 10.0, 1e-4);
        let same = moved_by(&pb.grid, &z, &coarse, &from, &from);
        assert_eq!(
            (same.pressure.clone(), same.shear.clone(), same.creep),
            (z.pressure.clone(), z.shear.clone(), z.creep)
        );
        let to = uniform_state(n, 9.0, 1.5e-4);
        let moved = moved_by(&pb.grid, &z, &coarse, &from, &to);
        assert_eq!(moved.pressure[0], 0.0, "a pressure moved below zero stays at zero");
        for i in 1..m {
            assert!(
                (moved.pressure[i] - 4.0).abs() < 1e-12,
                "node {i}: {}",
                moved.pressure[i]
            );
            assert!((moved.shear[i] - 0.4).abs() < 1e-12, "node {i}: {}", moved.shear[i]);
        }
        assert!((moved.creep - 2.5e-4).abs() < 1e-18 && moved.overlap == z.overlap);
    }
}
