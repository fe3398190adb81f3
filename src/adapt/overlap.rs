//! The overlap δ among the quantities an error-controlled grid controls.
//!
//! Under force control the overlap (the approach of the bodies' datums: the centres of rollers
//! on rigid shafts, a rigid body's centre) is an output, and its relative change from a grid
//! G to its bisection H is estimated like the creepage's: the plain difference, relative to
//! |δ_H|. Like ξ, δ is one number the tractions fix through the whole body's flexibility, an
//! average that converges at least as fast as the tractions (order k ≥ 1 under bisection), so
//! H's error d/(2^k − 1) is at most the difference d: the factor is 1, on the safe side.
//!
//! A half-plane's approach is relative to a datum at a depth the model chooses (the ln(4R_b/a)
//! of the half-space and Flamant models), so its relative error says nothing of the solution:
//! with either body idealised as a half-plane the overlap is not controlled (absent). Under
//! overlap control δ is prescribed: absent too.

use super::contribution::{Contribution, ErrorContribution, Round, Verdict};
use crate::contact::NormalControl;
use crate::error::Error;
use crate::scene::Scene;

/// The factor of the overlap's relative difference between G and H (module docs).
pub const OVERLAP_ESTIMATE_FACTOR: f64 = 1.0;

/// Whether the scene's overlap is an output the error control estimates (module docs).
pub fn controlled(scene: &Scene) -> bool {
    matches!(scene.normal, NormalControl::Force(_)) && scene.bodies.iter().all(|b| !b.idealises_as_half_plane())
}

/// The estimated relative error of `fine`'s overlap from the coarser grid's `coarse` [-]
/// (relative to |δ_fine|; 0 where the two agree).
pub fn relative_error(coarse: f64, fine: f64) -> f64 {
    if coarse == fine {
        0.0
    } else {
        OVERLAP_ESTIMATE_FACTOR * (fine - coarse).abs() / fine.abs().max(f64::MIN_POSITIVE)
    }
}

/// The overlap's contribution: its relative change from G to H where [`controlled`] (it joins
/// the pass's estimate), met where not controlled.
pub struct Overlap;

impl ErrorContribution for Overlap {
    fn name(&self) -> &'static str {
        "overlap"
    }

    fn assess(&mut self, round: &mut Round<'_, '_>) -> Result<Contribution, Error> {
        let (Some(g), Some(h)) = (round.g.as_ref(), round.h.as_ref()) else {
            unreachable!("the overlap is assessed on the pass's solves")
        };
        let estimate = controlled(round.bodies).then(|| relative_error(g.state.overlap, h.state().overlap));
        if estimate.is_some() {
            round.estimate.overlap_rel = estimate;
        }
        let met = estimate.is_none_or(|e| e <= round.env.tolerance);
        Ok(Contribution {
            name: self.name(),
            estimate,
            verdict: if met { Verdict::Met } else { Verdict::Refine },
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_relative_error_is_the_difference_over_the_finer_overlap() {
        assert!((relative_error(1.01e-2, 1.0e-2) - 0.01).abs() < 1e-12);
        assert_eq!(relative_error(3e-3, 3e-3), 0.0);
    }
}
