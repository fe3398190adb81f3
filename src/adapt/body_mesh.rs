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
//! Both are solved on a check grid coarser than the final one (src/adapt.rs chooses it: the
//! finer of the grids the BEM's stand-ins are fitted on): the bisection changes a body's
//! flexibility by a smooth remainder, and the solution's response to it needs the contact's
//! size and zones resolved, not its square-root points (the coarse roller's estimate of
//! docs/validation.md moves by under 2 % from the final grid to the check grid).
//!
//! Above the tolerance, the bisected bodies are adopted (src/adapt.rs refines the contact
//! grid again on them) and estimated in turn, at most [`MAX_BODY_MESH_BISECTIONS`] times; a
//! body mesh still too coarse then ends the run with exit code 2 and a message naming the body,
//! its mesh and its groups (`Error::BodyMeshTooCoarse`).

use super::estimate::Scales;
use super::{overlap, solve_on};
use crate::contact::residual::State;
use crate::contact::Workspace;
use crate::error::Error;
use crate::grid::ContactGrid;
use crate::post::adaptation::BodyMeshError;
use crate::post::norms::node_lengths;
use crate::post::Timings;
use crate::scene::Scene;

/// The factor of the difference between the body meshes and their bisection (module docs).
pub const BODY_MESH_ESTIMATE_FACTOR: f64 = 4.0 / 3.0;

/// Most times the error control bisects the bodies' meshes outside the contact before it
/// stops with exit code 2 (each bisection doubles their elements there).
pub const MAX_BODY_MESH_BISECTIONS: usize = 2;

/// What the body-mesh check found.
pub(super) struct Checked {
    /// The estimate of the bodies' meshes' error ([`compare`]).
    pub estimate: BodyMeshError,
    /// The scene with its bodies bisected outside the contact, to adopt when the estimate
    /// exceeds the tolerance.
    pub bisected: Scene,
}

/// The scene with every body that has a mesh of its own bisected outside the contact, None
/// when no body has one.
fn bisected(scene: &Scene) -> Option<Scene> {
    let mut any = false;
    let bodies = scene.bodies.clone().map(|b| match b.with_free_boundary_bisected() {
        Some(fine) => {
            any = true;
            fine
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

/// Checks the meshes of `scene`'s bodies (as given, before any cut along a grid) on `grid`:
/// the scene and the scene with its bodies bisected outside the contact, each solved on `grid`
/// from `warm` (the final grid's solution carried), compared by [`compare`]. None when no body
/// has a mesh of its own, or when a solve does not converge (logged: the result stays
/// unestimated).
pub(super) fn check_on(
    scene: &Scene,
    grid: &ContactGrid,
    warm: (&ContactGrid, &State),
    scales: Scales,
    timings: &mut Timings,
    ws: &mut Workspace,
) -> Result<Option<Checked>, Error> {
    let Some(fine_scene) = bisected(scene) else {
        return Ok(None);
    };
    log::info!(
        target: crate::logging::PROGRESS,
        "error control: the bodies' meshes checked on a grid of {} elements, as given and bisected \
         outside the contact",
        grid.n_elements()
    );
    let given = solve_on(scene.on_grid(grid.clone()), Some(warm), timings, ws)?;
    let fine = solve_on(
        fine_scene.on_grid(grid.clone()),
        Some((&given.problem.grid, &given.state)),
        timings,
        ws,
    )?;
    if !(given.report.converged && fine.report.converged) {
        log::warn!(
            "a solve of the check of the bodies' meshes outside the contact did not converge: \
             their error is not estimated"
        );
        return Ok(None);
    }
    let estimate = compare(grid, &given.state, &fine.state, scales, overlap::controlled(scene));
    log::info!(
        target: crate::logging::PROGRESS,
        "error control, body meshes: estimated error: pressure {:.2e} p0, shear {:.2e} mu p0, \
         creepage {:.2e}",
        estimate.pressure,
        estimate.shear,
        estimate.creepage_rel
    );
    Ok(Some(Checked {
        estimate,
        bisected: fine_scene,
    }))
}

/// The estimate of the body meshes' error from the solution `coarse` and `fine` (the bodies
/// bisected outside the contact) on the same `grid` (module docs): the difference times
/// [`BODY_MESH_ESTIMATE_FACTOR`].
pub fn compare(
    grid: &ContactGrid,
    coarse: &State,
    fine: &State,
    scales: Scales,
    overlap_controlled: bool,
) -> BodyMeshError {
    let d = difference(grid, coarse, fine, scales, overlap_controlled);
    let f = BODY_MESH_ESTIMATE_FACTOR;
    BodyMeshError {
        creepage_rel: f * d.creepage_rel,
        overlap_rel: d.overlap_rel.map(|o| f * o),
        pressure: f * d.pressure,
        shear: f * d.shear,
        bisections: 0,
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
        (fine.creep - coarse.creep).abs() / fine.creep.abs().max(scales.creep_floor).max(f64::MIN_POSITIVE)
    };
    BodyMeshError {
        creepage_rel,
        overlap_rel: overlap_controlled.then(|| overlap::relative_error(coarse.overlap, fine.overlap)),
        pressure,
        shear,
        bisections: 0,
    }
}

#[cfg(test)]
mod tests {
    use super::*;
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
            creep_floor: 0.0,
        };
        let e = compare(
            &grid,
            &state(&grid, 1.0, 0.1, 1e-3, 2e-2),
            &state(&grid, 1.02, 0.105, 1.1e-3, 2.2e-2),
            scales,
            true,
        );
        let f = BODY_MESH_ESTIMATE_FACTOR;
        assert!((e.pressure - f * 0.01).abs() < 1e-12, "{e:?}");
        assert!((e.shear - f * 0.01).abs() < 1e-12, "{e:?}");
        assert!((e.creepage_rel - f * 0.1 / 1.1).abs() < 1e-12, "{e:?}");
        assert!((e.overlap_rel.unwrap() - f * 0.1 / 1.1).abs() < 1e-12, "{e:?}");
        let e = compare(
            &grid,
            &state(&grid, 1.0, 0.1, 1e-3, 2e-2),
            &state(&grid, 1.0, 0.1, 1e-3, 2.2e-2),
            scales,
            false,
        );
        assert_eq!(e.overlap_rel, None);
        assert_eq!(e.largest(), 0.0);
    }
}
