//! The registry of body models: the one place that turns a case's body spec (its `model:` and
//! keys) into the [`BodySetup`] of that model. A new model adds its setup type in `src/body/`
//! and one arm here; nothing after the scene matches on body kinds.

use crate::bem::BoundaryCondition;
use crate::body::bem::setup::BemSetup;
use crate::body::half_space::setup::HalfSpaceSetup;
use crate::body::rigid::RigidSetup;
use crate::body::BodySetup;
use crate::case::{BodySpec, BoundaryKeyword, BoundarySpec, LoadedCase};
use crate::error::Error;
use crate::mesh::LoadedMesh;
use std::sync::Arc;

/// Both bodies of a scene, A first.
pub type BodySetups = [Arc<dyn BodySetup>; 2];

/// Resolves a body spec into its model's setup: loads and checks the mesh of a `bem` body (paths relative to the
/// case) and fits the profile radius where the case gives a mesh instead of a radius.
pub fn setup_of(case: &LoadedCase, spec: &BodySpec) -> Result<Arc<dyn BodySetup>, Error> {
    Ok(match spec {
        BodySpec::HalfSpace { material, radius } => Arc::new(HalfSpaceSetup {
            material: case.material(material),
            radius: *radius,
        }),
        BodySpec::Rigid { radius: Some(r), .. } => Arc::new(RigidSetup { radius: *r }),
        BodySpec::Rigid {
            radius: None,
            mesh,
            contact,
        } => {
            // Validated: a rigid body without a radius has a mesh. The mesh gives only the
            // profile radius; it does not set the contact grid.
            let path = case.base_dir().join(mesh.as_deref().unwrap_or_default());
            let (m, _) = crate::mesh::load(&path)?;
            let contact_group = m.group_index(contact)?;
            let loaded = LoadedMesh {
                path,
                mesh: m,
                notices: Vec::new(),
                contact_group,
            };
            Arc::new(RigidSetup {
                radius: loaded.contact_radius(),
            })
        }
        BodySpec::Bem {
            mesh,
            material,
            contact,
            boundaries,
            radius,
        } => {
            let path = case.base_dir().join(mesh);
            let (m, notices) = crate::mesh::load(&path)?;
            let contact_group = m.group_index(contact)?;
            for name in m.group_names() {
                if name != *contact && !boundaries.contains_key(&name) {
                    return Err(Error::MissingBoundary {
                        case: case.path.clone(),
                        mesh: path.clone(),
                        group: name,
                    });
                }
            }
            for name in boundaries.keys() {
                m.group_index(name)?;
            }
            let loaded = LoadedMesh {
                path,
                mesh: m,
                notices,
                contact_group,
            };
            let mut conditions: Vec<(String, BoundaryCondition)> = boundaries
                .iter()
                .map(|(g, b)| (g.clone(), boundary_condition(b)))
                .collect();
            conditions.push((contact.clone(), BoundaryCondition::Contact));
            Arc::new(BemSetup {
                radius: radius.unwrap_or_else(|| loaded.contact_radius()),
                mesh: loaded,
                material: case.material(material),
                contact: contact.clone(),
                conditions,
                profile_radius: *radius,
                start_mesh: None,
                far_field: Default::default(),
            })
        }
    })
}

/// Both bodies of a case, A first. Radii fitted to meshes are checked as a pair like the
/// case's own (two concave bodies, or a bore no larger than the roller, cannot touch).
pub fn setups_of_case(case: &LoadedCase) -> Result<BodySetups, Error> {
    let bodies = [
        setup_of(case, &case.case.bodies.a)?,
        setup_of(case, &case.case.bodies.b)?,
    ];
    for (side, spec, setup) in [
        ("A", &case.case.bodies.a, &bodies[0]),
        ("B", &case.case.bodies.b, &bodies[1]),
    ] {
        if let (BodySpec::Bem { radius: Some(r), .. }, Some(own)) = (spec, setup.contact_mesh()) {
            if let Some(message) = radius_contradicts_mesh(*r, own.mesh) {
                return Err(Error::Case(crate::case::CaseError::Invalid {
                    path: case.path.clone(),
                    violations: vec![crate::case::Violation {
                        key: format!("bodies.{side}.radius"),
                        message,
                    }],
                }));
            }
        }
    }
    if let Some(message) = crate::case::validate::radius_pair_problem(bodies[0].radius(), bodies[1].radius()) {
        return Err(Error::Case(crate::case::CaseError::Invalid {
            path: case.path.clone(),
            violations: vec![crate::case::Violation {
                key: "bodies.A, bodies.B (profile radii fitted to the meshes' contact groups)".into(),
                message,
            }],
        }));
    }
    Ok(bodies)
}

/// Why a profile radius given to a `bem` body contradicts its mesh: the contact group is
/// clearly curved (its fitted circle within 100 times the given radius) the other way (a ring's
/// concave bore given a positive radius would be solved as an external contact).
fn radius_contradicts_mesh(radius: f64, mesh: &LoadedMesh) -> Option<String> {
    let fitted = mesh.contact_radius();
    let curved = fitted.is_finite() && fitted.abs() < 100.0 * radius.abs();
    (curved && fitted.signum() != radius.signum()).then(|| {
        format!(
            "radius {radius} contradicts the mesh {}: its contact group is {} (the circle through it has \
             radius {fitted:.6}); give radius {} (negative: concave, a ring's bore), or leave radius out \
             to use the mesh's own profile",
            mesh.path.display(),
            if fitted < 0.0 { "concave" } else { "convex" },
            if radius < 0.0 { "> 0" } else { "< 0" }
        )
    })
}

/// How `rollbem check` describes a body: its model and the keys that define it, with the
/// values resolved (material constants, a fitted radius).
pub fn describe(case: &LoadedCase, spec: &BodySpec, setup: &dyn BodySetup) -> String {
    let (l, f) = (&case.case.units.length, &case.case.units.force);
    match spec {
        BodySpec::HalfSpace { material, radius } => {
            let m = case.material(material);
            format!(
                "half_space, R = {radius} {l}, material `{material}` (E = {:.6} {f}/{l}^2, G = {:.6} {f}/{l}^2, nu = {})",
                m.young,
                m.shear(),
                m.poisson
            )
        }
        BodySpec::Rigid { radius: Some(r), .. } => format!("rigid, R = {r} {l}"),
        BodySpec::Rigid { mesh, contact, .. } => format!(
            "rigid, R = {:.6} {l} (circle fitted to group `{contact}` of {})",
            setup.radius(),
            mesh.as_deref().unwrap_or("")
        ),
        BodySpec::Bem { mesh, material, .. } => {
            let m = case.material(material);
            format!(
                "bem, mesh {mesh}, material `{material}` (E = {:.6} {f}/{l}^2, G = {:.6} {f}/{l}^2, nu = {})",
                m.young,
                m.shear(),
                m.poisson
            )
        }
    }
}

/// The BEM boundary condition of a case's boundary spec.
fn boundary_condition(spec: &BoundarySpec) -> BoundaryCondition {
    match spec {
        BoundarySpec::Keyword(BoundaryKeyword::Fixed) => BoundaryCondition::Fixed,
        BoundarySpec::Keyword(BoundaryKeyword::Free) => BoundaryCondition::Free,
        BoundarySpec::Prescribed(p) => match (p.displacement, p.traction, p.pressure) {
            (Some(u), _, _) => BoundaryCondition::Displacement(u),
            (_, Some(t), _) => BoundaryCondition::Traction(t),
            (_, _, Some(pr)) => BoundaryCondition::Pressure(pr),
            _ => BoundaryCondition::Free,
        },
    }
}
