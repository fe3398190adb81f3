//! The registry of body models: the one place that turns a case's body spec (its `model:` and
//! keys) into the [`BodySetup`] of that model. A new model adds its setup type in `src/body/`
//! and one arm here; nothing after the scene matches on body kinds.

use crate::bem::BoundaryCondition;
use crate::body::bem::setup::BemSetup;
use crate::body::half_space::setup::HalfSpaceSetup;
use crate::body::layer::setup::LayerSetup;
use crate::body::rigid::RigidSetup;
use crate::body::viscoelastic::setup::ViscoelasticHalfSpaceSetup;
use crate::body::BodySetup;
use crate::case::{BodySpec, BoundaryKeyword, BoundarySpec, LoadedCase, Shape};
use crate::error::Error;
use crate::mesh::smooth::{contact_curve, kink_notice, ContactCurve};
use crate::mesh::LoadedMesh;
use std::sync::Arc;

/// Both bodies of a scene, A first.
pub type BodySetups = [Arc<dyn BodySetup>; 2];

/// Resolves a body spec into its model's setup: loads and checks the mesh of a `bem` body (paths relative to the
/// case) and fits the profile radius where the case gives a mesh instead of a radius. A
/// `geometry:` body is meshed with its contact elements ending at `edges` (ascending x; the
/// caller sizes them, [`setups_of_case`]); `side` is 0 for A, 1 for B.
fn setup_of(case: &LoadedCase, spec: &BodySpec, side: usize, edges: &[f64]) -> Result<Arc<dyn BodySetup>, Error> {
    Ok(match spec {
        BodySpec::HalfSpace { material, radius } => match case.viscoelastic_material(material) {
            Some(sls) => Arc::new(ViscoelasticHalfSpaceSetup {
                material: sls,
                radius: *radius,
            }),
            None => Arc::new(HalfSpaceSetup {
                material: case.material(material),
                radius: *radius,
            }),
        },
        BodySpec::Layer {
            material,
            radius,
            thickness,
        } => Arc::new(match case.viscoelastic_material(material) {
            Some(sls) => LayerSetup {
                material: sls,
                radius: *radius,
                thickness: *thickness,
            },
            None => LayerSetup::elastic(case.material(material), *radius, *thickness),
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
            let loaded = LoadedMesh::new(path, m, Vec::new(), contact)?;
            Arc::new(RigidSetup {
                radius: loaded.contact_radius(),
            })
        }
        BodySpec::Bem {
            geometry: Some(geometry),
            material,
            contact,
            boundaries,
            radius,
            ..
        } => {
            let shape = geometry.shape();
            let name = ["A", "B"][side];
            let label = format!("<geometry {} of body {name}>", shape.family());
            let mut m = shape.mesh(edges, contact, side == 0, &label);
            // The loops are drawn in a fixed turn and oriented here; that is no news to the
            // user, so the notices are dropped.
            crate::mesh::validate_and_orient(&mut m)?;
            let loaded = LoadedMesh::new(label, m, Vec::new(), contact)?;
            let mut conditions: Vec<(String, BoundaryCondition)> = shape
                .groups()
                .iter()
                .map(|(g, fixed)| {
                    let default = if *fixed {
                        BoundaryCondition::Fixed
                    } else {
                        BoundaryCondition::Free
                    };
                    (g.to_string(), boundaries.get(*g).map_or(default, boundary_condition))
                })
                .collect();
            conditions.sort_by(|a, b| a.0.cmp(&b.0));
            conditions.push((contact.clone(), BoundaryCondition::Contact));
            let contact_circle = exact_circle(&loaded, shape.profile_radius());
            bem_setup(case, loaded, material, contact, conditions, *radius, contact_circle)
        }
        BodySpec::Bem {
            mesh,
            material,
            contact,
            boundaries,
            radius,
            ..
        } => {
            // Validated: a bem body without a geometry has a mesh.
            let path = case.base_dir().join(mesh.as_deref().unwrap_or_default());
            let (m, notices) = crate::mesh::load(&path)?;
            // The contact group first: a mesh without it is refused before its other groups.
            m.group_index(contact)?;
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
            let mut loaded = LoadedMesh::new(path, m, notices, contact)?;
            let mut conditions: Vec<(String, BoundaryCondition)> = boundaries
                .iter()
                .map(|(g, b)| (g.clone(), boundary_condition(b)))
                .collect();
            conditions.push((contact.clone(), BoundaryCondition::Contact));
            // The cuts of an error-controlled grid go on the circle the contact nodes lie on,
            // as a generated body's do; a group on no circle keeps its elements' kinks, which
            // the user is told of when the grid will be cut (src/mesh/smooth.rs).
            let circle = match contact_curve(&loaded) {
                ContactCurve::Circle { circle, .. } => Some(circle),
                _ => None,
            };
            if circle.is_none() && case.case.contact.grid.tolerance.is_some() {
                let notice = kink_notice(&loaded, contact, &case.case.units.length);
                loaded.notices.extend(notice);
            }
            bem_setup(case, loaded, material, contact, conditions, *radius, circle)
        }
    })
}

/// Whether rollbem meshes the body itself (a `bem` body given by `geometry:`): its mesh is not
/// the user's to refine, and its contact nodes lie on the exact circle.
pub fn is_generated(spec: &BodySpec) -> bool {
    matches!(spec, BodySpec::Bem { geometry: Some(_), .. })
}

/// A `bem` body on its start mesh with the case's material and run options
/// (`contact.grid.reuse_far_field`).
fn bem_setup(
    case: &LoadedCase,
    loaded: LoadedMesh,
    material: &str,
    contact: &str,
    conditions: Vec<(String, BoundaryCondition)>,
    radius: Option<f64>,
    contact_circle: Option<crate::mesh::cuts::Circle>,
) -> Arc<dyn BodySetup> {
    Arc::new(
        BemSetup::on_start_mesh(
            loaded,
            case.material(material),
            contact.to_string(),
            conditions,
            radius,
            contact_circle,
        )
        .reusing_far_field(case.case.contact.grid.reuse_far_field),
    )
}

/// The circle of radius |`radius`| (the generated shape's) through a generated body's
/// outermost contact nodes, which lie on it exactly, on the side its other contact nodes bulge
/// to (None for a flat contact face). Its centre from the radius: a circle through three
/// points of a short arc would lose digits as ε/θ².
fn exact_circle(loaded: &LoadedMesh, radius: f64) -> Option<crate::mesh::cuts::Circle> {
    let r = radius.abs();
    if !r.is_finite() {
        return None;
    }
    let nodes: Vec<[f64; 2]> = loaded.contact_nodes().collect();
    let p = *nodes.iter().min_by(|a, b| a[0].total_cmp(&b[0]))?;
    let q = *nodes.iter().max_by(|a, b| a[0].total_cmp(&b[0]))?;
    let (dx, dy) = (q[0] - p[0], q[1] - p[1]);
    let d = (dx * dx + dy * dy).sqrt();
    if d == 0.0 || d > 2.0 * r {
        return None;
    }
    let h = (r * r - 0.25 * d * d).sqrt();
    let (mx, my) = (0.5 * (p[0] + q[0]), 0.5 * (p[1] + q[1]));
    let (nx, ny) = (-dy / d, dx / d);
    let middle = nodes[nodes.len() / 2];
    [1.0, -1.0]
        .map(|side| crate::mesh::cuts::Circle {
            centre: [mx + side * h * nx, my + side * h * ny],
            radius: r,
        })
        .into_iter()
        .min_by(|a, b| {
            let miss =
                |c: &crate::mesh::cuts::Circle| ((middle[0] - c.centre[0]).hypot(middle[1] - c.centre[1]) - r).abs();
            miss(a).total_cmp(&miss(b))
        })
}

/// The parametric shape of a body spec, if it is a `geometry:` body.
fn shape_of(spec: &BodySpec) -> Option<Shape> {
    match spec {
        BodySpec::Bem { geometry: Some(g), .. } => Some(g.shape()),
        _ => None,
    }
}

/// A case error of one key.
fn invalid(case: &LoadedCase, key: String, message: String) -> Error {
    Error::Case(crate::case::CaseError::Invalid {
        path: case.path.clone(),
        violations: vec![crate::case::Violation { key, message }],
    })
}

/// The contact element ends of the case's `geometry:` bodies (ascending x): those of the other
/// body's mesh file when it has one (so that the contact nodes pair up), else the uniform grid
/// the case's `contact.grid` builds around the Hertz contact (its `elements`, and its half-length
/// from `extent` or `half_length`), as the shipped meshes were made. The Hertz estimates need
/// the bodies' radii and materials only, so they are taken on the bodies meshed with a
/// provisional contact segment. Refuses a segment too wide for a body.
fn contact_edges(case: &LoadedCase, given: &[Option<Arc<dyn BodySetup>>; 2]) -> Result<Vec<f64>, Error> {
    let specs = [&case.case.bodies.a, &case.case.bodies.b];
    let from_mesh = given
        .iter()
        .flatten()
        .find_map(|b| b.contact_mesh().map(|own| own.mesh.contact_grid().edges.clone()));
    let (edges, source) = match from_mesh {
        Some(edges) => (edges, "the other body's mesh sets the contact elements".to_string()),
        None => {
            let n = case.case.contact.grid.elements.max(1);
            if n > MAX_GENERATED_CONTACT_ELEMENTS {
                // Checked before anything is built: the memory estimate comes after the meshes.
                return Err(invalid(
                    case,
                    "contact.grid.elements".into(),
                    format!(
                        "{n} contact elements for a `geometry:` body: at most \
                         {MAX_GENERATED_CONTACT_ELEMENTS} (their dense BEM matrices take tens of GB \
                         already); use contact.grid.tolerance to refine where it matters"
                    ),
                ));
            }
            let mut provisional = Vec::new();
            for (k, spec) in specs.iter().enumerate() {
                let setup = match (&given[k], shape_of(spec)) {
                    (Some(b), _) => b.clone(),
                    (None, Some(shape)) => {
                        let l = shape.provisional_half_length();
                        setup_of(case, spec, k, &uniform_edges(l, n))?
                    }
                    (None, None) => setup_of(case, spec, k, &[])?,
                };
                provisional.push(setup);
            }
            let bodies: BodySetups = [provisional[0].clone(), provisional[1].clone()];
            let estimates = crate::scene::Estimates::of(&case.case, &bodies);
            let l = estimates.grid_half_length;
            let why = format!(
                "Hertz half-width a = {:.6} and contact.grid (extent, half_length) give the contact \
                 segment |x| <= {l:.6}",
                estimates.hertz_half_width
            );
            (uniform_edges(l, n), why)
        }
    };
    let reach = edges.iter().fold(0.0_f64, |m, x| m.max(x.abs()));
    for (k, spec) in specs.iter().enumerate() {
        if let Some(shape) = shape_of(spec) {
            let max = shape.max_contact_half_length();
            if reach > max || reach.is_nan() {
                return Err(invalid(
                    case,
                    format!("bodies.{}.geometry", ["A", "B"][k]),
                    format!(
                        "{source}, wider than the {} allows (|x| <= {max:.6}, half its {}): lower the \
                         load, or make the body larger",
                        shape.family(),
                        if matches!(shape, Shape::Block { .. }) {
                            "half-width"
                        } else {
                            "radius"
                        }
                    ),
                ));
            }
        }
    }
    Ok(edges)
}

/// Most contact elements of a generated body: the memory estimate refuses far fewer (5000
/// need some 100 GB), but it comes after the meshes are built.
pub const MAX_GENERATED_CONTACT_ELEMENTS: usize = 20_000;

/// The ends of `n` equal elements on [−l, l].
fn uniform_edges(l: f64, n: usize) -> Vec<f64> {
    (0..=n).map(|i| -l + 2.0 * l * i as f64 / n as f64).collect()
}

/// Both bodies of a case, A first. Radii fitted to meshes are checked as a pair like the
/// case's own (two concave bodies, or a bore no larger than the roller, cannot touch). Bodies
/// with `geometry:` are meshed last, their contact segment sized by the others
/// ([`contact_edges`]).
pub fn setups_of_case(case: &LoadedCase) -> Result<BodySetups, Error> {
    let specs = [&case.case.bodies.a, &case.case.bodies.b];
    let mut given: [Option<Arc<dyn BodySetup>>; 2] = [None, None];
    for (k, spec) in specs.iter().enumerate() {
        if shape_of(spec).is_none() {
            given[k] = Some(setup_of(case, spec, k, &[])?);
        }
    }
    if given.iter().any(Option::is_none) {
        let edges = contact_edges(case, &given)?;
        for (k, spec) in specs.iter().enumerate() {
            if given[k].is_none() {
                given[k] = Some(setup_of(case, spec, k, &edges)?);
            }
        }
    }
    let [Some(a), Some(b)] = given else {
        unreachable!("every body has its setup")
    };
    let bodies = [a, b];
    for (side, spec, setup) in [
        ("A", &case.case.bodies.a, &bodies[0]),
        ("B", &case.case.bodies.b, &bodies[1]),
    ] {
        if let (BodySpec::Bem { radius: Some(r), .. }, Some(own)) = (spec, setup.contact_mesh()) {
            if let Some(message) = radius_contradicts_mesh(*r, own.mesh) {
                return Err(invalid(case, format!("bodies.{side}.radius"), message));
            }
        }
    }
    if let Some(message) = crate::case::validate::radius_pair_problem(bodies[0].radius(), bodies[1].radius()) {
        return Err(invalid(
            case,
            "bodies.A, bodies.B (profile radii fitted to the meshes' contact groups)".into(),
            message,
        ));
    }
    Ok(bodies)
}

/// The meshes rollbem generated for the case's `geometry:` bodies (checked and oriented), with
/// their side, "A" or "B": what `rollbem mesh` writes.
pub fn generated_meshes(case: &LoadedCase) -> Result<Vec<(&'static str, crate::mesh::BoundaryMesh)>, Error> {
    let bodies = setups_of_case(case)?;
    let specs = [&case.case.bodies.a, &case.case.bodies.b];
    Ok((0..2)
        .filter(|&k| shape_of(specs[k]).is_some())
        .filter_map(|k| Some((["A", "B"][k], bodies[k].contact_mesh()?.mesh.mesh.clone())))
        .collect())
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
            if let Some(sls) = case.viscoelastic_material(material) {
                let r = sls.rubbery();
                let t = &case.case.units.time;
                return format!(
                    "viscoelastic half_space, R = {radius} {l}, material `{material}` (standard linear solid: glassy \
                     E = {:.6} {f}/{l}^2, rubbery E = {:.6} {f}/{l}^2, G = {:.6} -> {:.6} {f}/{l}^2, nu = {}, creep time \
                     {} {t}, relaxation time {:.6} {t})",
                    m.young,
                    r.young,
                    m.shear(),
                    r.shear(),
                    m.poisson,
                    sls.creep_time,
                    sls.relaxation_time()
                );
            }
            format!(
                "half_space, R = {radius} {l}, material `{material}` (E = {:.6} {f}/{l}^2, G = {:.6} {f}/{l}^2, nu = {})",
                m.young,
                m.shear(),
                m.poisson
            )
        }
        BodySpec::Layer {
            material,
            radius,
            thickness,
        } => {
            let m = case.material(material);
            let kind = match case.viscoelastic_material(material) {
                Some(sls) => {
                    let t = &case.case.units.time;
                    format!(
                        "standard linear solid: G = {:.6} -> {:.6} {f}/{l}^2, nu = {}, creep time {} {t}",
                        m.shear(),
                        sls.rubbery().shear(),
                        m.poisson,
                        sls.creep_time
                    )
                }
                None => format!(
                    "E = {:.6} {f}/{l}^2, G = {:.6} {f}/{l}^2, nu = {}",
                    m.young,
                    m.shear(),
                    m.poisson
                ),
            };
            format!("layer, outer radius R = {radius} {l}, cover b = {thickness} {l} on a rigid core, material `{material}` ({kind})")
        }
        BodySpec::Rigid { radius: Some(r), .. } => format!("rigid, R = {r} {l}"),
        BodySpec::Rigid { mesh, contact, .. } => format!(
            "rigid, R = {:.6} {l} (circle fitted to group `{contact}` of {})",
            setup.radius(),
            mesh.as_deref().unwrap_or("")
        ),
        BodySpec::Bem {
            mesh,
            geometry,
            material,
            ..
        } => {
            let m = case.material(material);
            let source = match (geometry, setup.contact_mesh()) {
                (Some(g), Some(own)) => {
                    let shape = g.shape();
                    let lengths = match shape {
                        Shape::Roller { radius, shaft } => format!("radius {radius} {l}, shaft {shaft} {l}"),
                        Shape::Ring { bore, rim } => format!("bore {bore} {l}, rim {rim} {l}"),
                        Shape::CoveredRoller {
                            radius,
                            cover_thickness,
                        } => format!("radius {radius} {l}, cover {cover_thickness} {l} on a rigid core"),
                        Shape::Block { width, depth } => format!("width {width} {l}, depth {depth} {l}"),
                    };
                    let lm = own.mesh;
                    format!(
                        "geometry {} ({lengths}; meshed by rollbem: {} elements, {} on the contact)",
                        shape.family(),
                        lm.mesh.elements.len(),
                        lm.mesh.count_in_group(lm.contact_group)
                    )
                }
                _ => format!("mesh {}", mesh.as_deref().unwrap_or_default()),
            };
            format!(
                "bem, {source}, material `{material}` (E = {:.6} {f}/{l}^2, G = {:.6} {f}/{l}^2, nu = {})",
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
