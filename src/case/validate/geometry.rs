//! The checks of a body generated from its geometry (`geometry:`): its lengths, their order,
//! its keys.

use super::{positive_quantity, shown, Violation};
use crate::case::schema::*;

/// The broken rules of a `geometry:` body: its lengths, their order, its keys.
pub(in crate::case) fn geometry_violations(
    side: &str,
    g: &GeometrySpec,
    contact: &str,
    boundaries: &std::collections::BTreeMap<String, BoundarySpec>,
    radius: Option<f64>,
) -> Vec<Violation> {
    let mut out = Vec::new();
    let mut bad = |key: String, message: String| out.push(Violation { key, message });
    let (family, lengths): (&str, Vec<(&str, f64)>) = match g {
        GeometrySpec::Roller(r) => ("roller", vec![("radius", r.radius), ("shaft", r.shaft)]),
        GeometrySpec::Ring(r) => ("ring", vec![("bore", r.bore), ("rim", r.rim)]),
        GeometrySpec::CoveredRoller(c) => (
            "covered_roller",
            vec![("radius", c.radius), ("cover_thickness", c.cover_thickness)],
        ),
        GeometrySpec::Block(b) => ("block", vec![("width", b.width), ("depth", b.depth)]),
    };
    let key = |k: &str| format!("bodies.{side}.geometry.{family}.{k}");
    let mut all_positive = true;
    for (k, v) in &lengths {
        if let Some(why) = positive_quantity(*v) {
            bad(key(k), format!("{k} {why}"));
            all_positive = false;
        }
    }
    let mut ordered = all_positive;
    if all_positive {
        let (outer, inner) = (lengths[0], lengths[1]);
        let misordered = match g {
            GeometrySpec::Roller(_) | GeometrySpec::CoveredRoller(_) if inner.1 >= outer.1 => Some((
                key(inner.0),
                format!(
                    "{} = {} must be less than radius = {}: the {} lies inside the roller",
                    inner.0,
                    shown(inner.1),
                    shown(outer.1),
                    if inner.0 == "shaft" { "shaft" } else { "cover" }
                ),
            )),
            GeometrySpec::Ring(_) if inner.1 <= outer.1 => Some((
                key("rim"),
                format!(
                    "rim = {} must exceed bore = {}: the rim is the ring's outer circle",
                    shown(inner.1),
                    shown(outer.1)
                ),
            )),
            _ => None,
        };
        if let Some((k, message)) = misordered {
            bad(k, message);
            ordered = false;
        }
    }
    if let Some(problem) = g.shape().proportion_problem().filter(|_| ordered) {
        use crate::mesh::parametric::ProportionProblem;
        let (why, remedy) = match (&problem, g) {
            (ProportionProblem::WallTooThin(why), GeometrySpec::Roller(r)) => (
                why,
                format!(
                    "; a thin wall on a rigid shaft is a cover: `geometry: {{covered_roller: {{radius: {}, \
                 cover_thickness: {}, core: rigid}}}}` grades its elements to the thickness",
                    shown(r.radius),
                    shown(r.radius - r.shaft)
                ),
            ),
            (ProportionProblem::WallTooThin(why) | ProportionProblem::InnerTooSmall(why), _) => (why, String::new()),
        };
        bad(format!("bodies.{side}.geometry.{family}"), format!("{why}{remedy}"));
        ordered = false;
    }
    let far = g.shape().far_elements();
    if ordered && (far > crate::mesh::parametric::MAX_FAR_ELEMENTS || far.is_nan()) {
        bad(
            format!("bodies.{side}.geometry.{family}"),
            format!(
                "these lengths would need about {far:.3e} elements away from the contact (at most {:e}): {}",
                crate::mesh::parametric::MAX_FAR_ELEMENTS,
                if matches!(g, GeometrySpec::Block(_)) {
                    "give the block a width and depth of similar size (it stands in for a half-space)"
                } else {
                    "the cover is too thin for its radius (its elements are at most 10 thicknesses long); \
                     model a thin cover as a flat strip mesh (meshes/tyre_layer_strip.inc)"
                }
            ),
        );
    }
    if let GeometrySpec::CoveredRoller(c) = g {
        if let CoreSpec::Elastic { material } = &c.core {
            bad(
                key("core"),
                format!(
                    "an elastic core (material `{material}`) needs a two-region BEM (the cover and the core \
                     coupled along their bond), which rollbem does not have; give `core: rigid` (the cover \
                     bonded to a rigid core), or model the whole roller in one material with \
                     `geometry: {{roller: ...}}`"
                ),
            );
        }
    }
    if radius.is_some() && !matches!(g, GeometrySpec::Block(_)) {
        bad(
            format!("bodies.{side}.radius"),
            format!("the {family}'s own circle gives the profile radius: remove `radius` (it is for a block)"),
        );
    }
    if contact != "contact" {
        bad(
            format!("bodies.{side}.contact"),
            format!("a generated body's contact group is called `contact` (value = {contact}); remove the key"),
        );
    }
    let groups = g.shape().groups();
    for name in boundaries.keys() {
        if name != contact && !groups.iter().any(|(gname, _)| gname == name) {
            bad(
                format!("bodies.{side}.boundaries.{name}"),
                format!(
                    "a {family} has no group `{name}`; its groups are {} (besides `contact`)",
                    groups.map(|(n, _)| format!("`{n}`")).join(" and ")
                ),
            );
        }
    }
    out
}
