//! The rigid body model: zero flexibility, circular profile.

use super::{
    circle_profile, BodyFields, BodyModel, FieldError, Flexibility, InteriorQuery, InteriorResult, Side, StrainOperator,
};
use crate::grid::ContactGrid;

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

    fn strain_operator(&self, grid: &ContactGrid, _side: Side) -> Option<StrainOperator> {
        let m = grid.n_nodes();
        Some(StrainOperator {
            p: faer::Mat::zeros(m, m),
            q: faer::Mat::zeros(m, m),
        })
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
