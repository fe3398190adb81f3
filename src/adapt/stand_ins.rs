//! The BEM bodies' pass stand-ins in the error control: the grids they are fitted on and the
//! estimate of their own error on the final grid (src/body/bem/stand_in.rs).

use super::body_mesh;
use super::estimate::Scales;
use super::{carried, solve_on, solve_problem, Solve};
use crate::adapt::cells::DyadicGrid;
use crate::body::{FlexibilityChange, Side};
use crate::contact::report::SolveReport;
use crate::contact::residual::State;
use crate::contact::{ContactProblem, Workspace};
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

/// How often [`level`] bisects the start grid.
fn bisections(tolerance: f64) -> usize {
    if tolerance >= 3e-4 {
        0
    } else if tolerance >= 3e-5 {
        1
    } else {
        2
    }
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

/// The factor of the difference between the stand-ins' solution and their check's on the
/// final grid that estimates the stand-ins' error (src/body/bem/stand_in.rs). Fitted on three
/// levels, the check is the Richardson remainder of the two coarser: with the remainder's error
/// c₁h + c₂h², Richardson leaves c₂h²/2 from the two coarser levels and a quarter of that from
/// the two finer, so the finer's is the difference / 3 (Richardson's own error estimate for a
/// second-order term; measured on fig14_true_geometry at 1e-4 and 1e-5: effectivities 0.7–1.2).
/// Fitted on two, the check is the finer level's remainder alone, with the first-order error the
/// extrapolation removes, and the whole difference stands for the result's.
pub(super) fn check_factor(levels: usize) -> f64 {
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
/// ([`ContactProblem::with_flexibility_changes`]): the half-plane blocks, the larger part of a
/// stand-in's assembly, are the same in both, and are not made again.
#[allow(clippy::too_many_arguments)]
pub(super) fn check_difference(
    check: &Scene,
    changes: Option<&Changes>,
    g: &Solve,
    h: &Solve,
    scales: Scales,
    overlap_controlled: bool,
    timings: &mut Timings,
    ws: &mut Workspace,
) -> Result<Option<(BodyMeshError, usize)>, Error> {
    let (g_grid, h_grid) = (&g.problem.grid, &h.problem.grid);
    let solve = |on: &Solve, warm: &State, timings: &mut Timings, ws: &mut Workspace| match changes {
        Some(c) => Ok(solve_changed(&on.problem, c, check, warm, timings, ws)),
        None => solve_on(
            check.on_grid(on.problem.grid.clone()),
            Some((&on.problem.grid, warm)),
            false,
            timings,
            ws,
        )
        .map(|s| (s.state, s.report)),
    };
    // Only its solution is needed: its matrices go before H's are made.
    let (on_g, g_report) = solve(g, &g.state, timings, ws)?;
    let warm = g_report
        .converged
        .then(|| moved_by(&h.problem, &h.state, g_grid, &g.state, &on_g));
    let (on_h, h_report) = solve(h, warm.as_ref().unwrap_or(&h.state), timings, ws)?;
    if !h_report.converged {
        return Ok(None);
    }
    let d = body_mesh::difference(h_grid, &on_h, &h.state, scales, overlap_controlled);
    Ok(Some((d, g_report.iterations + h_report.iterations)))
}

/// How the check's bodies differ from the passes' stand-ins (A's, B's; None: the same body).
pub(super) type Changes = [Option<Arc<dyn FlexibilityChange>>; 2];

/// The check solved on `base`'s grid, its problem `base` (the passes' problem there) plus
/// `changes`, from `warm` (a solution on that grid); the times added to `timings`.
fn solve_changed(
    base: &ContactProblem,
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
    let grid = &base.grid;
    let [a, b] = [(0, Side::A), (1, Side::B)].map(|(k, side)| changes[k].as_ref().map(|c| c.on_grid(grid, side)));
    let pb = base.with_flexibility_changes([a.as_ref(), b.as_ref()]);
    timings.assembly_s += t.elapsed().as_secs_f64();
    solve_problem(&pb, &check.solver, Some((grid, warm)), timings, ws)
}

/// `z` (a solution on `pb`'s grid) moved by the change from `from` to `to` (two solutions on the
/// grid `coarse`), carried to `pb`'s grid: the warm start of a solve whose solution differs
/// from `z` as `to` from `from`. Pressure and gap stay ≥ 0.
fn moved_by(pb: &ContactProblem, z: &State, coarse: &ContactGrid, from: &State, to: &State) -> State {
    let (a, b) = (carried(pb, coarse, to), carried(pb, coarse, from));
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
        let same = moved_by(&pb, &z, &coarse, &from, &from);
        assert_eq!(
            (same.pressure.clone(), same.shear.clone(), same.creep),
            (z.pressure.clone(), z.shear.clone(), z.creep)
        );
        let to = uniform_state(n, 9.0, 1.5e-4);
        let moved = moved_by(&pb, &z, &coarse, &from, &to);
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
