//! The viscoelastic half-space's setup: a standard linear solid of given profile radius, built
//! on any grid from the aged half-plane integrals with the scene's rolling speed and direction.

use super::aged_kernels::Ageing;
use super::ViscoelasticHalfSpace;
use crate::body::setup::{BodySetup, BuildContext, BuildError, SurfaceAt};
use crate::body::transfer::Transferred;
use crate::body::{Body, Side};
use crate::material::{Elastic, StandardLinearSolid};

/// A `half_space` body of a viscoelastic material.
#[derive(Debug, Clone)]
pub struct ViscoelasticHalfSpaceSetup {
    /// The standard linear solid.
    pub material: StandardLinearSolid,
    /// Signed profile radius [length].
    pub radius: f64,
}

impl ViscoelasticHalfSpaceSetup {
    /// The model on the kinematics of `ctx`: aged with L = V τc when the material creeps.
    /// The case's validation guarantees a speed V > 0 whenever τc > 0.
    fn model(&self, ctx: &BuildContext) -> ViscoelasticHalfSpace {
        let length = self.material.creep_time * ctx.rolling.speed.unwrap_or(0.0);
        ViscoelasticHalfSpace {
            material: self.material,
            radius: self.radius,
            ageing: (length > 0.0).then_some(Ageing {
                length,
                direction: ctx.rolling.direction,
            }),
            pair: None,
        }
    }
}

impl BodySetup for ViscoelasticHalfSpaceSetup {
    fn model_name(&self) -> &'static str {
        "viscoelastic_half_space"
    }

    fn radius(&self) -> f64 {
        self.radius
    }

    /// The rubbery constants: they give the widest contact (slow rolling), which the grid
    /// must cover.
    fn hertz_material(&self) -> Option<Elastic> {
        Some(self.material.rubbery())
    }

    fn idealises_as_half_plane(&self) -> bool {
        true
    }

    fn relaxation_layer(&self, speed: Option<f64>) -> Option<f64> {
        let layer = speed? * self.material.relaxation_time();
        (layer > 0.0).then_some(layer)
    }

    /// The BEM is elastic: no true-geometry model of a viscoelastic body.
    fn has_true_geometry_model(&self) -> bool {
        false
    }

    fn surface_at(&self, _x: f64, _side: Side) -> Option<SurfaceAt> {
        None
    }

    /// As the elastic half-space: on a grid of curved elements built on the straightened grid
    /// and carried over.
    fn build(&self, ctx: &BuildContext) -> Result<Box<dyn Body>, BuildError> {
        let body = self.model(ctx).in_pair(ctx.pair);
        Ok(Transferred::flat_model_on(Box::new(body), ctx.grid, ctx.side)?)
    }
}
