//! The scene of each body model of the accuracy study, built from the case's bodies: the
//! half-space model, BEM blocks standing in for the half-spaces, BEM rollers on rigid shafts.

use super::{study_error, SceneModel};
use crate::app;
use crate::bem::BoundaryCondition;
use crate::case::LoadedCase;
use crate::error::Error;
use crate::material::Elastic;
use crate::mesh::build::{half_space_block, ring_with_bore, roller_on_shaft, RingMeshSizes, RollerMeshSizes};
use crate::mesh::{validate_and_orient, BoundaryMesh};
use crate::post::ContactSolution;
use crate::scene::{registry, BemSetup, BodySetup, HalfSpaceSetup, LoadedMesh, RigidSetup, Scene};
use std::sync::Arc;
use std::time::Instant;

/// The elastic description of one body of the scene.
#[derive(Debug, Clone)]
pub(super) struct SceneBody {
    /// Elastic constants (None: rigid).
    pub(super) material: Option<Elastic>,
    /// Profile radius [length].
    pub(super) radius: f64,
}

/// The two bodies of the scene: materials and profile radii of the case's bodies.
pub(super) fn scene_bodies(case: &LoadedCase) -> Result<[SceneBody; 2], Error> {
    let body = |setup: &Arc<dyn BodySetup>| -> Result<SceneBody, Error> {
        if !setup.radius().is_finite() {
            return Err(study_error(
                "a body of the case has a flat profile (infinite radius): the study compares models of \
                 cylinders; give the body a radius",
            ));
        }
        Ok(SceneBody {
            material: setup.hertz_material(),
            radius: setup.radius(),
        })
    };
    let [a, b] = registry::setups_of_case(case)?;
    Ok([body(&a)?, body(&b)?])
}

/// The scene's bodies as half-spaces (rigid bodies stay rigid), on the case's uniform grid.
pub(super) fn half_space_scene(case: &LoadedCase, scene: &[SceneBody; 2]) -> Scene {
    let bodies = scene.clone().map(|b| -> Arc<dyn BodySetup> {
        match b.material {
            Some(material) => Arc::new(HalfSpaceSetup {
                material,
                radius: b.radius,
            }),
            None => Arc::new(RigidSetup { radius: b.radius }),
        }
    });
    Scene::new(case.clone(), bodies)
}

/// What one run of a scene produced.
#[derive(Debug, Clone)]
pub struct Outcome {
    /// The contact solution (the last iterate if not converged).
    pub solution: ContactSolution,
    /// Whether the contact solver converged.
    pub solution_converged: bool,
    /// Solver iterations.
    pub iterations: usize,
    /// Boundary elements of the larger BEM body (0 for the half-space model).
    pub boundary_elements: usize,
    /// Contact elements of the grid solved on.
    pub contact_elements: usize,
    /// Assembly and condensation time [s].
    pub build_s: f64,
    /// Contact solve time [s].
    pub solve_s: f64,
}

/// Solves the scene of `case` (its bodies' materials and radii, its load and friction) with
/// `model` at `n` contact elements; true-geometry rollers sit on shafts of `shaft_ratio` times
/// their radius, a concave body (negative radius) is a ring round its bore with its rim
/// ([`RIM_RATIO`] times the bore) fixed.
pub fn solve_model(case: &LoadedCase, model: SceneModel, n: usize, shaft_ratio: f64) -> Result<Outcome, Error> {
    solve_model_of(case, &scene_bodies(case)?, model, n, shaft_ratio)
}

/// [`solve_model`] with the case's bodies already resolved.
pub(super) fn solve_model_of(
    case: &LoadedCase,
    scene: &[SceneBody; 2],
    model: SceneModel,
    n: usize,
    shaft_ratio: f64,
) -> Result<Outcome, Error> {
    let start = Instant::now();
    let mut c = case.clone();
    c.case.contact.grid.elements = n;
    c.case.output.interior = None;
    c.case.output.strength = None;
    c.case.output.vtk = false;
    let mut run = half_space_scene(&c, scene);
    let mut boundary_elements = 0;
    if model != SceneModel::HalfSpace {
        // The grid of the half-space model sets the contact segment of the BEM meshes, so
        // that every model solves on the same nodes.
        let (a, half_length) = (run.estimates.hertz_half_width, run.estimates.grid_half_length);
        let mut bodies = run.bodies.clone();
        for (k, body) in scene.iter().enumerate() {
            let Some(material) = body.material else { continue };
            let above = k == 0;
            let bem = match model {
                SceneModel::HalfSpaceBlock => bem_body(
                    half_space_block(40.0 * a, 40.0 * a, half_length, n, 4.0 * a, above),
                    model,
                    material,
                    &[("far", BoundaryCondition::Fixed), ("free", BoundaryCondition::Free)],
                    body.radius,
                    Some(body.radius),
                )?,
                // A concave body is a ring round the other: its bore, its rim fixed.
                _ if body.radius < 0.0 => bem_body(
                    ring_with_bore(
                        -body.radius,
                        -RIM_RATIO * body.radius,
                        half_length,
                        ring_sizes(n),
                        above,
                    ),
                    model,
                    material,
                    &[("bore", BoundaryCondition::Free), ("rim", BoundaryCondition::Fixed)],
                    body.radius,
                    None,
                )?,
                _ => bem_body(
                    roller_on_shaft(
                        body.radius,
                        shaft_ratio * body.radius,
                        half_length,
                        roller_sizes(n),
                        above,
                    ),
                    model,
                    material,
                    &[("free", BoundaryCondition::Free), ("shaft", BoundaryCondition::Fixed)],
                    body.radius,
                    None,
                )?,
            };
            boundary_elements = boundary_elements.max(bem.mesh.mesh.elements.len());
            bodies[k] = Arc::new(bem);
        }
        run = Scene::new(c, bodies);
    }
    let solved = app::solve_scene(run, start)?;
    Ok(Outcome {
        solution_converged: solved.report.converged,
        iterations: solved.report.iterations,
        boundary_elements,
        contact_elements: solved.problem.grid.n_elements(),
        build_s: solved.timings.assembly_s + solved.timings.condense_s,
        solve_s: solved.timings.solve_s,
        solution: solved.solution,
    })
}

/// The half-space model of the scene of `case` on an error-controlled grid of `tolerance`
/// (its start grid the case's `contact.grid.elements`).
pub(super) fn solve_adaptive_of(case: &LoadedCase, scene: &[SceneBody; 2], tolerance: f64) -> Result<Outcome, Error> {
    let start = Instant::now();
    let mut c = case.clone();
    c.case.contact.grid.tolerance = Some(tolerance);
    c.case.output.interior = None;
    c.case.output.strength = None;
    c.case.output.vtk = false;
    let solved = app::solve_scene(half_space_scene(&c, scene), start)?;
    Ok(Outcome {
        solution_converged: solved.report.converged,
        iterations: solved.report.iterations,
        boundary_elements: 0,
        contact_elements: solved.problem.grid.n_elements(),
        build_s: solved.timings.assembly_s + solved.timings.condense_s,
        solve_s: solved.timings.solve_s,
        solution: solved.solution,
    })
}

/// Element counts of a true-geometry roller with n contact elements: the free arc gets n/2
/// (at least 32, at most 160) graded elements, the shaft 24 (the shaft's own error is below
/// 1e-4 at 24, docs/validation.md).
fn roller_sizes(n: usize) -> RollerMeshSizes {
    RollerMeshSizes {
        contact: n,
        free: (n / 2).clamp(32, 160),
        shaft: 24,
    }
}

/// Rim radius of a true-geometry ring over its bore radius (the issue scene's ring: bore 50 mm,
/// rim 65 mm, the rim fixed).
pub const RIM_RATIO: f64 = 1.3;

/// Element counts of a true-geometry ring with n contact elements: its bore like a roller's
/// free arc, the fixed rim 48 (smooth, far from the contact).
fn ring_sizes(n: usize) -> RingMeshSizes {
    RingMeshSizes {
        contact: n,
        bore: (n / 2).clamp(32, 160),
        rim: 48,
    }
}

/// A procedural mesh as a `bem` body with its `contact` group and the other groups' conditions
/// (in name order, as a case's boundaries).
fn bem_body(
    mut mesh: BoundaryMesh,
    model: SceneModel,
    material: Elastic,
    groups: &[(&str, BoundaryCondition)],
    radius: f64,
    profile_radius: Option<f64>,
) -> Result<BemSetup, Error> {
    let notices = validate_and_orient(&mut mesh)?;
    let mut conditions: Vec<(String, BoundaryCondition)> =
        groups.iter().map(|(g, c)| (g.to_string(), c.clone())).collect();
    conditions.push(("contact".to_string(), BoundaryCondition::Contact));
    let mesh = LoadedMesh::new(format!("<procedural {}>", model.name()), mesh, notices, "contact")?;
    Ok(BemSetup {
        radius,
        ..BemSetup::on_start_mesh(mesh, material, "contact".to_string(), conditions, profile_radius, None)
    })
}
