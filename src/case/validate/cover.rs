//! The load against a cover's thickness: a rigid body pressed through a layer.

use super::shown;
use crate::case::schema::Bodies;

/// A cover (`model: layer`) on which the other body is rigid takes the whole overlap δ0: one
/// deeper than the cover is thick would press the surface through the core, a strain of order
/// δ0/b > 1 that linear elasticity (every model here) cannot describe. The solver would still
/// return a contact (p_max/E = 77 at δ0 = 57 b), so it is refused, naming the cover's thickness.
pub(super) fn overlap_through_a_cover(bodies: &Bodies, overlap: f64) -> Vec<(String, String)> {
    let mut out = Vec::new();
    for (side, body, other) in [("A", &bodies.a, &bodies.b), ("B", &bodies.b, &bodies.a)] {
        if let (Some(thickness), false) = (body.cover_thickness(), other.capabilities().deforms) {
            if overlap >= thickness && thickness.is_finite() && thickness > 0.0 {
                out.push((
                    format!("bodies.{side}.thickness"),
                    format!(
                        "the cover is {} thick but load.normal.overlap = {} presses the rigid body {} that deep into \
                         it ({:.3} times its thickness): linear elasticity describes compressions of a small \
                         fraction of the cover; give a thicker cover or a smaller overlap",
                        shown(thickness),
                        shown(overlap),
                        if side == "A" { "B" } else { "A" },
                        overlap / thickness
                    ),
                ));
            }
        }
    }
    out
}
