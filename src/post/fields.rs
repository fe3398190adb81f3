//! The fields a body model shows under the solved contact tractions: its whole boundary (for
//! VTK) and the interior grid of `output.interior`.

use super::solution::ContactSolution;
use crate::body::{Body, BoundaryField, ContactLoad, InteriorQuery, Side};
use crate::case::InteriorSpec;
use crate::contact::ContactFrame;
use crate::error::Error;
use crate::grid::ContactGrid;
use crate::interior::{grid_points, InteriorField, InteriorOptions};
use crate::scene::{BodyModels, Scene};

/// The whole-boundary fields of A and B under the solved tractions (None for a model without
/// a boundary: half-space, rigid).
///
/// Body models take their loads in global axes: the contact's p and q are turned into each
/// body's own (P, Q) by the contact frame first ([`ContactFrame::global_loads`]).
pub fn boundary_fields(
    models: &BodyModels,
    grid: &ContactGrid,
    frame: &ContactFrame,
    solution: &ContactSolution,
) -> Result<[Option<BoundaryField>; 2], Error> {
    let field = |m: &dyn Body, side: Side| {
        let (pressure, shear) = frame.global_loads(side, &solution.pressure, &solution.shear);
        let load = ContactLoad {
            grid,
            pressure: &pressure,
            shear: &shear,
        };
        m.boundary_field(&load)
            .transpose()
            .map_err(|e| Error::BoundaryField(Box::new(e)))
    };
    Ok([field(models[0].as_ref(), Side::A)?, field(models[1].as_ref(), Side::B)?])
}

/// The interior fields that `output.interior` asks for, from the body's own model (Somigliana
/// for a bem body, Flamant superposition for a half-space) under the solved contact tractions.
pub fn interior_field(
    scene: &Scene,
    spec: &InteriorSpec,
    models: &BodyModels,
    grid: &ContactGrid,
    frame: &ContactFrame,
    solution: &ContactSolution,
) -> Result<InteriorField, Error> {
    let (k, side) = if spec.body == "B" { (1, Side::B) } else { (0, Side::A) };
    let model = models[k].as_ref();
    let points = grid_points(spec.x, spec.y);
    let (pressure, shear) = frame.global_loads(side, &solution.pressure, &solution.shear);
    let query = InteriorQuery {
        side,
        load: ContactLoad {
            grid,
            pressure: &pressure,
            shear: &shear,
        },
        points: &points,
        options: InteriorOptions::default(),
    };
    let samples = model.interior(&query).map_err(|source| Error::Interior {
        case: scene.case.path.clone(),
        body: spec.body.clone(),
        source: Box::new(source),
    })?;
    let shape = [spec.x[2] as usize, spec.y[2] as usize];
    Ok(InteriorField::from_samples(
        &spec.body,
        model.model_name(),
        shape,
        points,
        &samples,
    ))
}

/// The notice for interior points that lie outside the body or in its boundary layer (not
/// evaluated), if there are any.
pub fn unevaluated_points_notice(f: &InteriorField) -> Option<String> {
    let [_, outside, boundary] = f.counts();
    (outside + boundary > 0).then(|| {
        format!(
            "output.interior: of {} points of body {}, {outside} lie outside the body and \
             {boundary} on its boundary (closer than {} element lengths); they are not \
             evaluated: status `outside`/`boundary`, fields written as 0",
            f.points.len(),
            f.body,
            InteriorOptions::default().boundary_layer
        )
    })
}
