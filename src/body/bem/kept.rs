//! A BEM body condensed on one grid, kept for a later build on the same grid within the run.
//!
//! An error-controlled run condenses each BEM body on the finer of its stand-in's two grids
//! ([`super::stand_in`]) and, once the contact grid meets the tolerance, solves the bodies on
//! that same grid again to check their meshes (src/adapt/body_mesh.rs). The first condensation
//! is kept in the run's caches ([`crate::body::RunCaches`], found by the setup's
//! [`crate::body::BodyLineage`], its side and its own contact grid) and the second build takes
//! it: the same matrices, not a copy computed again. [`Kept`] is that body in a build.

use super::BemBody;
use crate::body::{
    BodyFields, BodyModel, BoundaryField, ContactLoad, FieldError, Flexibility, InteriorQuery, InteriorResult, Side,
    StrainOperator,
};
use crate::grid::ContactGrid;
use faer::{Mat, MatRef};
use std::sync::Arc;

/// A kept body in a build: the same model, and whether this build condensed it (then it
/// reports the body's times; a later build takes it without counting them again).
pub struct Kept(pub Arc<BemBody>, pub bool);

impl BodyModel for Kept {
    fn model_name(&self) -> &'static str {
        self.0.model_name()
    }

    fn flexibility(&self, grid: &ContactGrid, side: Side) -> Flexibility {
        self.0.flexibility(grid, side)
    }

    fn displacements(&self, grid: &ContactGrid, side: Side, p: MatRef<'_, f64>, q: MatRef<'_, f64>) -> [Mat<f64>; 2] {
        self.0.displacements(grid, side, p, q)
    }

    fn profile(&self, x: f64) -> f64 {
        self.0.profile(x)
    }

    fn profile_slope(&self, x: f64) -> f64 {
        self.0.profile_slope(x)
    }

    fn strain_operator(&self, grid: &ContactGrid, side: Side) -> Option<StrainOperator> {
        self.0.strain_operator(grid, side)
    }

    fn strain_at(&self, grid: &ContactGrid, side: Side, p: MatRef<'_, f64>, q: MatRef<'_, f64>) -> Option<Mat<f64>> {
        self.0.strain_at(grid, side, p, q)
    }

    /// The body's own times in the build that condensed it (the flag), zero in a later
    /// build: that build counted them.
    fn stage_seconds(&self) -> (f64, f64) {
        if self.1 {
            self.0.stage_seconds()
        } else {
            (0.0, 0.0)
        }
    }
}

impl BodyFields for Kept {
    fn boundary_field(&self, load: &ContactLoad) -> Option<Result<BoundaryField, FieldError>> {
        self.0.boundary_field(load)
    }

    fn interior(&self, query: &InteriorQuery) -> InteriorResult {
        self.0.interior(query)
    }

    fn field_surface(&self, x: f64) -> f64 {
        self.0.field_surface(x)
    }
}
