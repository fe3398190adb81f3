//! One body of the scene: the case's body spec resolved against the case (material, profile
//! radius, the loaded mesh of a `bem` body) and the body model it builds on a contact grid.

use super::loaded_mesh::LoadedMesh;
use crate::bem::{BemModel, BemOptions, BoundaryCondition};
use crate::body::bem::BemBody;
use crate::body::half_space::HalfSpace;
use crate::body::rigid::Rigid;
use crate::body::transfer::Transferred;
use crate::body::{Body, Side, WithCircularProfile};
use crate::case::{BodySpec, BoundaryKeyword, BoundarySpec, LoadedCase};
use crate::error::Error;
use crate::grid::ContactGrid;
use crate::material::Elastic;

/// One body of a scene, ready to build its model.
#[derive(Debug, Clone)]
pub enum BodySetup {
    /// Closed-form half-plane influence coefficients of an elastic cylinder.
    HalfSpace {
        /// Elastic constants.
        material: Elastic,
        /// Signed profile radius [length] (negative: concave; infinite for a flat profile).
        radius: f64,
    },
    /// A rigid cylinder.
    Rigid {
        /// Signed profile radius [length]: given, or the circle fitted to a mesh's contact
        /// group (negative: concave).
        radius: f64,
    },
    /// A body discretized by boundary elements (boxed: its mesh makes it large).
    Bem(Box<BemSetup>),
}

/// A `bem` body: its mesh, material and boundary conditions.
#[derive(Debug, Clone)]
pub struct BemSetup {
    /// The checked and oriented mesh.
    pub mesh: LoadedMesh,
    /// Elastic constants.
    pub material: Elastic,
    /// Name of the contact group.
    pub contact: String,
    /// Boundary condition of every group: the other groups in name order, the contact group
    /// last (the order numbers the unknowns).
    pub conditions: Vec<(String, BoundaryCondition)>,
    /// Profile radius [length]: `profile_radius` if given, else the circle fitted to the
    /// contact group (used for the Hertz estimates).
    pub radius: f64,
    /// A radius that replaces the mesh's own contact profile in the gap (a BEM block standing
    /// in for a cylinder, paper Fig. 2), if the case gives one.
    pub profile_radius: Option<f64>,
}

impl BodySetup {
    /// Resolves a body spec: loads and checks the mesh of a `bem` body (paths relative to the
    /// case) and fits the profile radius where the case gives a mesh instead of a radius.
    pub fn from_spec(case: &LoadedCase, spec: &BodySpec) -> Result<Self, Error> {
        Ok(match spec {
            BodySpec::HalfSpace { material, radius } => BodySetup::HalfSpace {
                material: case.material(material),
                radius: *radius,
            },
            BodySpec::Rigid { radius: Some(r), .. } => BodySetup::Rigid { radius: *r },
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
                BodySetup::Rigid {
                    radius: loaded.contact_radius(),
                }
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
                BodySetup::Bem(Box::new(BemSetup {
                    radius: radius.unwrap_or_else(|| loaded.contact_radius()),
                    mesh: loaded,
                    material: case.material(material),
                    contact: contact.clone(),
                    conditions,
                    profile_radius: *radius,
                }))
            }
        })
    }

    /// Both bodies of a case, A first. Radii fitted to meshes are checked as a pair like the
    /// case's own (two concave bodies, or a bore no larger than the roller, cannot touch).
    pub fn of_case(case: &LoadedCase) -> Result<[Self; 2], Error> {
        let bodies = [
            Self::from_spec(case, &case.case.bodies.a)?,
            Self::from_spec(case, &case.case.bodies.b)?,
        ];
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

    /// Elastic constants, None for a rigid body.
    pub fn material(&self) -> Option<Elastic> {
        match self {
            BodySetup::HalfSpace { material, .. } => Some(*material),
            BodySetup::Rigid { .. } => None,
            BodySetup::Bem(b) => Some(b.material),
        }
    }

    /// Signed profile radius [length]: positive convex, negative concave (infinite for a flat
    /// profile).
    pub fn radius(&self) -> f64 {
        match self {
            BodySetup::HalfSpace { radius, .. } | BodySetup::Rigid { radius } => *radius,
            BodySetup::Bem(b) => b.radius,
        }
    }

    /// The mesh of a `bem` body.
    pub fn mesh(&self) -> Option<&LoadedMesh> {
        match self {
            BodySetup::Bem(b) => Some(&b.mesh),
            _ => None,
        }
    }

    /// The model's name in outputs: `half_space`, `rigid` or `bem`.
    pub fn model_name(&self) -> &'static str {
        match self {
            BodySetup::HalfSpace { .. } => "half_space",
            BodySetup::Rigid { .. } => "rigid",
            BodySetup::Bem(_) => "bem",
        }
    }

    /// Builds the body model, seen on the contact `grid` from `side`.
    ///
    /// A `bem` body is condensed to its own contact nodes; if those differ from the grid's, its
    /// flexibility is carried over by [`Transferred`].
    /// A half-space body on a grid of mapped (curved) elements, which its closed-form element
    /// integrals do not cover, is built on the straight grid between the same edges and carried
    /// over by the same transfer.
    pub fn model(&self, grid: &ContactGrid, side: Side) -> Result<Box<dyn Body>, Error> {
        match self {
            BodySetup::HalfSpace { material, radius } => {
                let body = HalfSpace {
                    material: *material,
                    radius: *radius,
                };
                if grid.is_straight() {
                    return Ok(Box::new(body));
                }
                let t = Transferred {
                    inner: Box::new(body),
                    own_grid: grid.straightened(),
                    side,
                };
                t.check(grid)?;
                Ok(Box::new(t))
            }
            BodySetup::Rigid { radius } => Ok(Box::new(Rigid { radius: *radius })),
            BodySetup::Bem(b) => b.model(grid, side),
        }
    }

    /// Depth of a `bem` body's material under its contact when a fixed boundary lies closer
    /// below it than half the body's radius (a cover layer on a rigid core): the distance from
    /// the contact node nearest x = 0 to the nearest node of a `fixed` group [length].
    pub fn layer_thickness(&self) -> Option<f64> {
        let BodySetup::Bem(b) = self else { return None };
        let fixed: Vec<usize> = b
            .conditions
            .iter()
            .filter(|(_, c)| matches!(c, BoundaryCondition::Fixed))
            .filter_map(|(g, _)| b.mesh.mesh.group_index(g).ok())
            .collect();
        let depth = b.mesh.depth_below_contact(&fixed)?;
        (depth < 0.5 * b.radius.abs()).then_some(depth)
    }
}

impl BemSetup {
    fn model(&self, grid: &ContactGrid, side: Side) -> Result<Box<dyn Body>, Error> {
        let model = BemModel::new(
            self.mesh.mesh.clone(),
            self.material,
            self.conditions.clone(),
            BemOptions::default(),
        )?;
        let own = self.mesh.contact_grid();
        let body = BemBody::new(model, &self.contact, &own, side)?;
        let on_grid: Box<dyn Body> = if own.coincides_with(grid) {
            Box::new(body)
        } else {
            let t = Transferred {
                inner: Box::new(body),
                own_grid: own,
                side,
            };
            t.check(grid)?;
            Box::new(t)
        };
        Ok(match self.profile_radius {
            Some(r) => Box::new(WithCircularProfile {
                inner: on_grid,
                radius: r,
            }),
            None => on_grid,
        })
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
