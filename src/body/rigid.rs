//! The rigid body model: zero flexibility, circular profile.

use super::kind::Capabilities;
use super::setup::{BodySetup, BuildContext, BuildError, SurfaceAt};
use super::Body;
use super::{
    circle_profile, circle_profile_slope, BodyFields, BodyModel, FieldError, Flexibility, InteriorQuery,
    InteriorResult, Side, StrainOperator,
};
use crate::grid::ContactGrid;
use crate::material::Elastic;

/// What the checks of a case ask of the `rigid` model. A rigid body: no material, no deformation, no interior.
pub const CAPABILITIES: Capabilities = Capabilities {
    name: "rigid",
    deforms: false,
    accepts_viscoelastic: false,
    interior_fields: false,
    boundary_elements: false,
};

/// A rigid cylinder of the given signed radius [length] (negative: a concave bore).
#[derive(Debug, Clone)]
pub struct Rigid {
    /// Signed profile radius [length]: positive convex, negative concave.
    pub radius: f64,
}

impl BodyModel for Rigid {
    fn model_name(&self) -> &'static str {
        "rigid"
    }

    fn flexibility(&self, grid: &ContactGrid, _side: Side) -> Flexibility {
        Flexibility::zero(grid.n_nodes())
    }

    fn profile(&self, x: f64) -> f64 {
        circle_profile(self.radius, x)
    }

    fn profile_slope(&self, x: f64) -> f64 {
        circle_profile_slope(self.radius, x)
    }

    fn strain_operator(&self, grid: &ContactGrid, _side: Side) -> Option<StrainOperator> {
        let m = grid.n_nodes();
        Some(StrainOperator {
            p: faer::Mat::zeros(m, m),
            q: faer::Mat::zeros(m, m),
        })
    }

    fn strain_at(
        &self,
        grid: &ContactGrid,
        _side: Side,
        p: faer::MatRef<'_, f64>,
        _q: faer::MatRef<'_, f64>,
    ) -> Option<faer::Mat<f64>> {
        Some(faer::Mat::zeros(grid.n_nodes(), p.ncols()))
    }
}

/// A rigid body has neither a boundary solution nor interior fields.
impl BodyFields for Rigid {
    fn interior(&self, _query: &InteriorQuery) -> InteriorResult {
        Err(FieldError::NoInteriorField {
            model: self.model_name(),
        })
    }
}

/// A `rigid` body of a scene: a cylinder of the given signed radius [length] (given, or the
/// circle fitted to a mesh's contact group), which does not deform.
#[derive(Debug, Clone)]
pub struct RigidSetup {
    /// Signed profile radius [length]: positive convex, negative concave.
    pub radius: f64,
}

impl BodySetup for RigidSetup {
    fn model_name(&self) -> &'static str {
        "rigid"
    }

    fn radius(&self) -> f64 {
        self.radius
    }

    fn hertz_material(&self) -> Option<Elastic> {
        None
    }

    fn surface_at(&self, x: f64, side: Side) -> Option<SurfaceAt> {
        Some(SurfaceAt::of_circle(self.radius, x, side))
    }

    fn build(&self, _ctx: &BuildContext) -> Result<Box<dyn Body>, BuildError> {
        Ok(Box::new(Rigid { radius: self.radius }))
    }
}
