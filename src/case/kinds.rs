//! The questions the case asks of a body's kind, answered per kind: the one place in the case
//! that names the variants of [`BodySpec`]. The checks of `validate` and the readers of a case
//! ask these, so that a new body model is one arm in each answer here (its capabilities are
//! declared in its own module under `src/body/`) and none in the checks.

use super::schema::BodySpec;
use super::validate::{geometry_violations, layer_thickness_problems, prescribed_boundary_problems, Problems};
use crate::body::Capabilities;
use crate::case::schema::Case;

/// The profile radius a body's keys give, for the checks of radii.
#[derive(Debug, Clone, PartialEq)]
pub(super) struct GivenRadius {
    /// The value whose range is checked [length] (1 where a mesh gives the radius, or the keys
    /// that would give it are refused already: nothing more to say).
    pub checked: f64,
    /// The radius the case gives [length], for the rule on the pair; None where a mesh gives it.
    pub given: Option<f64>,
    /// Whether the body's `geometry:` gives it rather than a `radius` key (the key the pair
    /// rule then names).
    pub from_geometry: bool,
}

impl BodySpec {
    /// What the body's model can be asked for (its `model:` name, whether it deforms, takes a
    /// viscoelastic material, has interior fields, is a boundary element model).
    pub fn capabilities(&self) -> Capabilities {
        match self {
            BodySpec::HalfSpace { .. } => crate::body::half_space::CAPABILITIES,
            BodySpec::Layer { .. } => crate::body::layer::CAPABILITIES,
            BodySpec::Rigid { .. } => crate::body::rigid::CAPABILITIES,
            BodySpec::Bem { .. } => crate::body::bem::CAPABILITIES,
        }
    }

    /// The name of the body's material under `materials`, None for a body that has none (rigid).
    pub fn material_name(&self) -> Option<&str> {
        match self {
            BodySpec::HalfSpace { material, .. }
            | BodySpec::Bem { material, .. }
            | BodySpec::Layer { material, .. } => Some(material),
            BodySpec::Rigid { .. } => None,
        }
    }

    /// The Gmsh mesh the body reads (`mesh:` of a `bem` or `rigid` body), relative to the case
    /// file; None for a body given by its keys alone.
    pub fn mesh_file(&self) -> Option<&str> {
        match self {
            BodySpec::Bem { mesh, .. } | BodySpec::Rigid { mesh, .. } => mesh.as_deref(),
            BodySpec::HalfSpace { .. } | BodySpec::Layer { .. } => None,
        }
    }

    /// Whether the body brings its own contact elements, which the contact grid then follows:
    /// a `bem` body meshed in Gmsh. A generated (`geometry:`) body's contact is cut like a
    /// uniform grid, and a rigid body's mesh gives its profile radius only.
    pub fn has_own_contact_elements(&self) -> bool {
        match self {
            BodySpec::Bem { mesh, .. } => mesh.is_some(),
            BodySpec::HalfSpace { .. } | BodySpec::Layer { .. } | BodySpec::Rigid { .. } => false,
        }
    }

    /// Thickness b [length] of a cover on a rigid core (`model: layer`), None for a body
    /// that is no cover.
    pub fn cover_thickness(&self) -> Option<f64> {
        match self {
            BodySpec::Layer { thickness, .. } => Some(*thickness),
            BodySpec::HalfSpace { .. } | BodySpec::Rigid { .. } | BodySpec::Bem { .. } => None,
        }
    }

    /// Checks the keys of body `side` (A or B) that its model takes, beyond its material's
    /// name, recording what is wrong in `found`; returns the profile radius they give.
    pub(super) fn key_problems(&self, case: &Case, side: &str, found: &mut Problems) -> GivenRadius {
        let given = |r: f64| GivenRadius {
            checked: r,
            given: Some(r),
            from_geometry: false,
        };
        match self {
            BodySpec::HalfSpace { radius, .. } => given(*radius),
            BodySpec::Layer {
                material,
                radius,
                thickness,
            } => {
                layer_thickness_problems(case, side, material, *radius, *thickness, found);
                given(*radius)
            }
            BodySpec::Rigid { radius, mesh, .. } => match (radius, mesh) {
                (Some(r), None) => given(*r),
                (None, Some(_)) => GivenRadius {
                    checked: 1.0,
                    given: None,
                    from_geometry: false,
                },
                _ => {
                    found.bad(
                        format!("bodies.{side}"),
                        "a rigid body takes exactly one of `radius` (the profile radius) or `mesh` \
                         (a Gmsh mesh whose contact group's circle gives it)"
                            .into(),
                    );
                    GivenRadius {
                        checked: 1.0,
                        given: None,
                        from_geometry: false,
                    }
                }
            },
            BodySpec::Bem {
                boundaries,
                radius,
                contact,
                mesh,
                geometry,
                ..
            } => {
                match (mesh, geometry) {
                    (Some(_), Some(_)) => found.bad(
                        format!("bodies.{side}.geometry"),
                        "a bem body takes exactly one of `mesh` (a Gmsh file) or `geometry` (a parametric \
                         body rollbem meshes itself): remove one of the two"
                            .into(),
                    ),
                    (None, None) => found.bad(
                        format!("bodies.{side}.mesh"),
                        "missing: give `mesh` (a Gmsh .msh file) or `geometry` (e.g. {roller: {radius: 150, \
                         shaft: 15}}; cases/README.md lists the families)"
                            .into(),
                    ),
                    (None, Some(g)) => {
                        for v in geometry_violations(side, g, contact, boundaries, *radius) {
                            found.bad(v.key, v.message);
                        }
                    }
                    (Some(_), None) => {}
                }
                if boundaries.contains_key(contact) {
                    found.bad(
                        format!("bodies.{side}.boundaries.{contact}"),
                        "the contact group takes the contact tractions; do not give it a boundary condition".into(),
                    );
                }
                prescribed_boundary_problems(side, boundaries, found);
                GivenRadius {
                    checked: radius.unwrap_or(1.0),
                    given: radius.or_else(|| {
                        geometry
                            .as_ref()
                            .map(|g| g.shape().profile_radius())
                            .filter(|r| r.is_finite() && *r != 0.0)
                    }),
                    from_geometry: radius.is_none() && geometry.is_some(),
                }
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::BodySpec;

    fn half_space() -> BodySpec {
        BodySpec::HalfSpace {
            material: "steel".into(),
            radius: 40.0,
        }
    }

    fn layer() -> BodySpec {
        BodySpec::Layer {
            material: "rubber".into(),
            radius: 100.0,
            thickness: 5.0,
        }
    }

    fn rigid(mesh: Option<&str>) -> BodySpec {
        BodySpec::Rigid {
            radius: mesh.is_none().then_some(40.0),
            mesh: mesh.map(String::from),
            contact: "contact".into(),
        }
    }

    fn bem(mesh: Option<&str>) -> BodySpec {
        BodySpec::Bem {
            mesh: mesh.map(String::from),
            geometry: None,
            material: "steel".into(),
            contact: "contact".into(),
            boundaries: Default::default(),
            radius: None,
        }
    }

    #[test]
    fn each_kind_names_its_model() {
        let names = [half_space(), layer(), rigid(None), bem(Some("r.msh"))].map(|b| b.capabilities().name);
        assert_eq!(names, ["half_space", "layer", "rigid", "bem"]);
    }

    #[test]
    fn only_a_rigid_body_does_not_deform_and_has_no_material() {
        for b in [half_space(), layer(), bem(Some("r.msh"))] {
            assert!(b.capabilities().deforms, "{b:?}");
            assert!(b.material_name().is_some(), "{b:?}");
        }
        assert!(!rigid(None).capabilities().deforms);
        assert_eq!(rigid(None).material_name(), None);
    }

    #[test]
    fn viscoelastic_materials_go_on_the_models_with_aged_kernels_only() {
        let accepts =
            [half_space(), layer(), rigid(None), bem(Some("r.msh"))].map(|b| b.capabilities().accepts_viscoelastic);
        assert_eq!(accepts, [true, true, false, false]);
    }

    #[test]
    fn interior_fields_come_from_the_half_space_and_the_bem_body() {
        let interior =
            [half_space(), layer(), rigid(None), bem(Some("r.msh"))].map(|b| b.capabilities().interior_fields);
        assert_eq!(interior, [true, false, false, true]);
    }

    #[test]
    fn the_bem_body_alone_is_a_boundary_element_model() {
        let bem_model = [half_space(), layer(), rigid(None), bem(None)].map(|b| b.capabilities().boundary_elements);
        assert_eq!(bem_model, [false, false, false, true]);
    }

    #[test]
    fn meshes_are_read_by_meshed_bem_and_rigid_bodies() {
        assert_eq!(bem(Some("r.msh")).mesh_file(), Some("r.msh"));
        assert_eq!(rigid(Some("s.msh")).mesh_file(), Some("s.msh"));
        for b in [half_space(), layer(), rigid(None), bem(None)] {
            assert_eq!(b.mesh_file(), None, "{b:?}");
        }
    }

    #[test]
    fn only_a_meshed_bem_body_brings_its_contact_elements() {
        assert!(bem(Some("r.msh")).has_own_contact_elements());
        // A rigid body's mesh gives its profile radius only.
        for b in [half_space(), layer(), rigid(Some("s.msh")), bem(None)] {
            assert!(!b.has_own_contact_elements(), "{b:?}");
        }
    }

    #[test]
    fn only_a_layer_is_a_cover() {
        assert_eq!(layer().cover_thickness(), Some(5.0));
        for b in [half_space(), rigid(None), bem(Some("r.msh"))] {
            assert_eq!(b.cover_thickness(), None, "{b:?}");
        }
    }
}
