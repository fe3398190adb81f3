//! The share of the creepage that the bodies' true geometry sets, for the creepage's estimate.
//!
//! A grid and its bisection estimate the creepage's error faithfully on half-planes (Carter's
//! theory, dissimilar half-planes: docs/validation.md), but not in a conformal bore: there the
//! error oscillates in sign as the grid is refined, following where the discrete stick/slip
//! point falls between nodes, and a grid and its bisection can agree by chance (14 times low
//! at tolerance 1e-3, 30 times at 2e-4; docs/validation.md, "The creepage in a bore under
//! bisection"). Most of a bore's creepage is not Carter's: two thirds of it is the free-rolling
//! part the bodies' strain under the whole traction sets (docs/conformal.md), and its error
//! moves with the shear's: the shear's estimate times Carter's complete-slip creepage μa/R*
//! (the creepage a shear error of that size over the contact moves) reads the bore's error
//! within 0.8–1.3. On half-planes that product over-reads 7 to 450 times, so it is weighted
//! here by the share of ξ that the half-plane model of the same scene does not give:
//!
//! ```text
//! w = |ξ − ξ_hp| / (|ξ − ξ_hp| + |ξ_hp|)   ∈ [0, 1],
//! ```
//!
//! ξ_hp the creepage of the scene with every body of true geometry replaced by its half-plane
//! twin ([`crate::body::BodySetup::half_plane_twin`]), solved once per run on the first pass's
//! grid: w need hold only a digit (the Gmsh bore of tests/data/bore_c30_tractive.yaml has
//! w = 0.6318 on its 52-element start grid, 0.6334 on that grid bisected twice), and a finer
//! grid would cost the half-plane's dense matrices more memory than the pass itself holds.
//! Scenes without a body of true geometry have w = 0 and keep the bisection's estimate alone.

use crate::body::BodySetup;
use crate::contact::methods;
use crate::contact::{NormalControl, TangentialControl};
use crate::grid::ContactGrid;
use crate::scene::Scene;
use std::sync::Arc;

/// The share w ∈ [0, 1] (module docs) of the creepage `creep` [-] solved on `grid` for `scene`
/// under the normal force `normal_force()` [force/length] (asked only for a twin): 0 without a body of true geometry,
/// with a prescribed creepage or without friction; 1 (the candidate unweighted, on the safe
/// side) when the half-plane twin does not solve. The twin carries the solved normal force
/// whatever controls the scene's (an overlap's meaning depends on the bodies' datums).
pub fn geometry_share(scene: &Scene, grid: &ContactGrid, creep: f64, normal_force: impl FnOnce() -> f64) -> f64 {
    if matches!(scene.tangential, TangentialControl::Creep(_)) || scene.friction() == 0.0 {
        return 0.0;
    }
    let twins = scene.bodies.clone().map(|b| b.half_plane_twin());
    if twins.iter().all(Option::is_none) {
        return 0.0;
    }
    let normal_force = normal_force();
    if !(normal_force > 0.0 && normal_force.is_finite()) {
        return 1.0;
    }
    let bodies: [Arc<dyn BodySetup>; 2] = [0, 1].map(|k| twins[k].clone().unwrap_or_else(|| scene.bodies[k].clone()));
    let twin = Scene {
        bodies,
        normal: NormalControl::Force(normal_force),
        ..scene.clone()
    }
    .with_grid(grid.clone());
    let half_plane_creep = twin.assemble().ok().and_then(|(_, problem)| {
        let (state, report) = methods::solve(&problem, &twin.solver);
        (report.converged && state.creep.is_finite()).then_some(state.creep)
    });
    match half_plane_creep {
        Some(xi) => share_beyond(creep, xi),
        None => {
            log::warn!("the half-plane twin of the scene did not solve: the creepage's estimate takes the geometry's share as 1");
            1.0
        }
    }
}

/// |ξ − ξ_hp| / (|ξ − ξ_hp| + |ξ_hp|), 0 when both vanish.
fn share_beyond(creep: f64, half_plane_creep: f64) -> f64 {
    let beyond = (creep - half_plane_creep).abs();
    let total = beyond + half_plane_creep.abs();
    if total > 0.0 {
        beyond / total
    } else {
        0.0
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_share_is_that_of_the_creepage_beyond_the_half_plane_s() {
        // A bore: two thirds of ξ beyond Carter's.
        assert!((share_beyond(3e-3, 1e-3) - 2.0 / 3.0).abs() < 1e-15);
        // Braking in a bore: ξ nearly cancels, its two parts are each about 1e-3.
        assert!((share_beyond(-1e-5, -1e-3) - 0.99e-3 / 1.99e-3).abs() < 1e-15);
        // A half-plane model: nothing beyond.
        assert_eq!(share_beyond(1e-3, 1e-3), 0.0);
        assert_eq!(share_beyond(0.0, 0.0), 0.0);
    }
}
