//! The half-space model's setup: an elastic cylinder of given material and profile radius,
//! built from the closed-form half-plane integrals on any grid.

use super::HalfSpace;
use crate::body::setup::{BodySetup, BuildContext, BuildError, SurfaceAt};
use crate::body::transfer::Transferred;
use crate::body::{Body, Side};
use crate::material::Elastic;

/// A `half_space` body of a scene.
#[derive(Debug, Clone)]
pub struct HalfSpaceSetup {
    /// Elastic constants.
    pub material: Elastic,
    /// Signed profile radius [length] (negative: concave; infinite for a flat profile).
    pub radius: f64,
}

impl BodySetup for HalfSpaceSetup {
    fn model_name(&self) -> &'static str {
        "half_space"
    }

    fn radius(&self) -> f64 {
        self.radius
    }

    fn hertz_material(&self) -> Option<Elastic> {
        Some(self.material)
    }

    fn idealises_as_half_plane(&self) -> bool {
        true
    }

    fn hertz_applies(&self) -> bool {
        true
    }

    /// Flat in its model: the contact frame keeps the global axes.
    fn surface_at(&self, _x: f64, _side: Side) -> Option<SurfaceAt> {
        None
    }

    /// On a grid of mapped (curved) elements, which the closed-form element integrals do not
    /// cover, the body is built on the straight grid between the same edges and carried over
    /// by [`Transferred`].
    fn build(&self, ctx: &BuildContext) -> Result<Box<dyn Body>, BuildError> {
        let body = HalfSpace::new(self.material, self.radius).in_pair(ctx.pair);
        Ok(Transferred::flat_model_on(Box::new(body), ctx.grid, ctx.side)?)
    }
}
