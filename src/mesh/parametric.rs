//! Parametric bodies: the boundary meshes of rollers, rings, covered rollers and blocks that
//! rollbem builds itself from a few lengths (a case's `geometry:` key), instead of reading a
//! Gmsh file.
//!
//! Each family is the twin of the shipped Gmsh geometries and uses their group names, so a
//! case's `boundaries:` keys mean the same:
//!
//! | family | groups (besides `contact`) | Gmsh twin |
//! |---|---|---|
//! | roller | `free` (rest of the outer circle), `shaft` (inner circle) | `meshes/roller_r150_shaft15_A.geo` |
//! | ring | `bore` (rest of the bore), `rim` (outer circle) | `meshes/bore_ring.inc` |
//! | covered roller | `free` (rest of the outer circle), `bonded` (the cover's inner circle, on the core) | `meshes/tyre_layer_strip.inc` (flat) |
//! | block | `free` (rest of the contact face and the sides), `far` (the opposite face) | `meshes/halfspace_block_A.geo` |
//!
//! Every element is quadratic (`line3`), its three nodes on the exact circle or line (mid
//! nodes at the mid-angle, as Gmsh puts them). The contact segment carries one element between
//! each pair of neighbouring abscissae of `edges` (the contact grid's element ends), so a body
//! built on a grid has that grid's contact nodes; beyond it the elements grow by
//! [`GROWTH`] per element from the last contact element's length up to the family's far size
//! (the size Gmsh's shipped geometries give their far points), as Gmsh's size field grades
//! between a small and a large point size. Lengths are in the case's unit.

use super::build::MeshBuilder;
use super::BoundaryMesh;
use std::f64::consts::PI;

/// Growth of neighbouring element lengths away from the contact: gentle enough that the
/// quadratic elements' error stays that of the far size (Gmsh's linear size field between a
/// contact point of 0.12 mm and a far point of 20 mm a quarter circle away grows by 1.08).
pub const GROWTH: f64 = 1.15;

/// Most elements a generated body's far field may take ([`Shape::far_elements`]): far more
/// than the dense BEM matrices of any machine hold, so that the memory estimate refuses such a
/// body with its sizes, and the generator is never asked for billions of elements.
pub const MAX_FAR_ELEMENTS: f64 = 1e5;

/// Largest half-length of the contact segment as a fraction of the radius of a curved
/// family (or of the half-width of a block): the contact stays a small arc of the body.
pub const MAX_CONTACT_FRACTION: f64 = 0.5;

/// A body given by its family and lengths [length].
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Shape {
    /// A solid disc of outer radius `radius` on a shaft: an inner circle of radius `shaft`.
    Roller {
        /// Outer radius R.
        radius: f64,
        /// Shaft radius (< R).
        shaft: f64,
    },
    /// A ring whose concave bore of radius `bore` holds the other body; outer rim of radius
    /// `rim`.
    Ring {
        /// Bore radius.
        bore: f64,
        /// Rim radius (> bore).
        rim: f64,
    },
    /// A cover of thickness `cover_thickness` on a core: outer radius `radius`, inner circle
    /// (the bond to the core) of radius `radius − cover_thickness`.
    CoveredRoller {
        /// Outer radius R.
        radius: f64,
        /// Cover thickness b (< R).
        cover_thickness: f64,
    },
    /// A rectangle of width `width` and depth `depth`, its contact face on y = 0 (a block
    /// standing in for a half-space, paper Fig. 2).
    Block {
        /// Full width (the contact face's length).
        width: f64,
        /// Depth below the contact face.
        depth: f64,
    },
}

impl Shape {
    /// The family's name as the case writes it.
    pub fn family(&self) -> &'static str {
        match self {
            Shape::Roller { .. } => "roller",
            Shape::Ring { .. } => "ring",
            Shape::CoveredRoller { .. } => "covered_roller",
            Shape::Block { .. } => "block",
        }
    }

    /// The groups other than the contact, each with whether it is held fixed by default (the
    /// shaft, rim, bond or far face: `true`) or free of traction (`false`), as the shipped
    /// cases give them.
    pub fn groups(&self) -> [(&'static str, bool); 2] {
        match self {
            Shape::Roller { .. } => [("free", false), ("shaft", true)],
            Shape::Ring { .. } => [("bore", false), ("rim", true)],
            Shape::CoveredRoller { .. } => [("free", false), ("bonded", true)],
            Shape::Block { .. } => [("free", false), ("far", true)],
        }
    }

    /// Signed profile radius of the contact surface [length]: positive convex, negative for a
    /// ring's bore, infinite for a block.
    pub fn profile_radius(&self) -> f64 {
        match *self {
            Shape::Roller { radius, .. } | Shape::CoveredRoller { radius, .. } => radius,
            Shape::Ring { bore, .. } => -bore,
            Shape::Block { .. } => f64::INFINITY,
        }
    }

    /// The largest half-length of a contact segment the body takes [length]
    /// ([`MAX_CONTACT_FRACTION`] of its radius or half-width).
    pub fn max_contact_half_length(&self) -> f64 {
        MAX_CONTACT_FRACTION
            * match *self {
                Shape::Block { width, .. } => 0.5 * width,
                _ => self.profile_radius().abs(),
            }
    }

    /// About how many elements the body's far field takes (away from the contact, where the
    /// elements have their far size), before any is built: the lengths' ratios set it (a thin
    /// cover's circumference over ten thicknesses, a deep narrow block's depth over its width).
    pub fn far_elements(&self) -> f64 {
        match *self {
            Shape::Roller { .. } => 48.0 + 24.0,
            Shape::Ring { .. } => 48.0 + 48.0,
            Shape::CoveredRoller {
                radius,
                cover_thickness: t,
            } => {
                let circle = |r: f64| 2.0 * PI * r / (2.0 * PI * r / 48.0).min(10.0 * t);
                circle(radius) + circle(radius - t)
            }
            Shape::Block { width, depth } => {
                let far = (width / 20.0).min(depth / 10.0);
                (2.0 * width + 2.0 * depth) / far
            }
        }
    }

    /// Why the generated mesh cannot represent these lengths, if it cannot: a roller's or a
    /// ring's wall thinner than [`MIN_WALL_PER_ELEMENT`] of its far elements (their two sides'
    /// integrals would be nearly singular over a whole element, and the polygon of the inner
    /// circle may cross the outer one), or an inner circle below [`MIN_INNER_FRACTION`] of the
    /// outer one (a covered roller's core too). A cover grades its elements to its thickness and a block
    /// has no inner circle.
    pub fn proportion_problem(&self) -> Option<ProportionProblem> {
        let (outer, inner, far) = match *self {
            Shape::Roller { radius, shaft } => (radius, shaft, far_size(radius)),
            Shape::Ring { bore, rim } => (rim, bore, far_size(rim)),
            // A cover's elements follow its thickness: only its core can be too small.
            Shape::CoveredRoller {
                radius,
                cover_thickness,
            } => (radius, radius - cover_thickness, 0.0),
            Shape::Block { .. } => return None,
        };
        let wall = outer - inner;
        if inner < MIN_INNER_FRACTION * outer {
            Some(ProportionProblem::InnerTooSmall(format!(
                "the inner circle ({inner:.4e}) is below {MIN_INNER_FRACTION:e} of the outer one ({outer:.4e}): \
                 too small for the generated mesh to hold the body's rotation or to resolve"
            )))
        } else if wall < MIN_WALL_PER_ELEMENT * far {
            Some(ProportionProblem::WallTooThin(format!(
                "the wall between the circles ({wall:.4e}) is thinner than {MIN_WALL_PER_ELEMENT} of the \
                 generated elements away from the contact ({far:.4e} long): the mesh cannot represent it"
            )))
        } else {
            None
        }
    }

    /// A contact half-length for a body whose contact is not sized yet (a small arc), used
    /// only to build a mesh for the Hertz estimates that size the real one.
    pub fn provisional_half_length(&self) -> f64 {
        0.1 * self.max_contact_half_length()
    }

    /// The body's mesh: the contact group (named `contact`) has one element between each pair
    /// of neighbouring abscissae of `edges` (ascending, |x| ≤ [`Self::max_contact_half_length`]),
    /// the body lies above the contact (y > 0, body A) if `above`, else below. `label` names
    /// the mesh in messages. The loops are not oriented yet: pass the mesh through
    /// [`super::validate_and_orient`].
    pub fn mesh(&self, edges: &[f64], contact: &str, above: bool, label: &str) -> BoundaryMesh {
        self.mesh_refined(edges, contact, above, label, 1)
    }

    /// [`Self::mesh`] with the elements away from the contact `fineness` times finer: far
    /// sizes divided by it, circles of fixed counts multiplied by it, and the growth
    /// [`GROWTH`]`^(1/fineness)` (the contact elements stay those of `edges`). Measures the
    /// discretisation error of the far field (docs/validation.md, "Parametric bodies").
    pub fn mesh_refined(
        &self,
        edges: &[f64],
        contact: &str,
        above: bool,
        label: &str,
        fineness: usize,
    ) -> BoundaryMesh {
        let k = fineness.max(1);
        let fine = Grading {
            growth: GROWTH.powf(1.0 / k as f64),
            scale: k as f64,
        };
        let mut b = MeshBuilder::new(true, label);
        let s = if above { 1.0 } else { -1.0 };
        match *self {
            Shape::Roller { radius, shaft } => {
                let centre = [0.0, s * radius];
                let far = far_size(radius) / fine.scale;
                outer_circle(&mut b, centre, radius, edges, above, [contact, "free"], far, fine);
                b.circle(centre, shaft, 24 * k, "shaft");
            }
            Shape::Ring { bore, rim } => {
                // The bore's centre lies across the contact from the ring's material.
                let centre = [0.0, -s * bore];
                let far = far_size(bore) / fine.scale;
                outer_circle(&mut b, centre, bore, edges, !above, [contact, "bore"], far, fine);
                b.circle(centre, rim, 48 * k, "rim");
            }
            Shape::CoveredRoller {
                radius,
                cover_thickness: t,
            } => {
                let centre = [0.0, s * radius];
                // Elements at most ten thicknesses long, as meshes/tyre_layer_strip.inc's far
                // elements: the nearly singular integration copes with elements much longer
                // than the cover is thick, and the field decays within some thicknesses of the
                // contact (from 4 to 10 thicknesses, a cover of b = 0.5 under a rigid roller
                // R = 100 changed its creepage by 4e-5).
                let far = far_size(radius).min(10.0 * t) / fine.scale;
                outer_circle(&mut b, centre, radius, edges, above, [contact, "free"], far, fine);
                let core = radius - t;
                let core_far = (2.0 * PI * core / 24.0).min(10.0 * t) / fine.scale;
                // The bond's elements facing the contact subtend the contact elements' angle:
                // under a thin cover its tractions vary as fast as the contact's (elements of
                // one thickness there cost 3e-3 of a thin cover's creepage,
                // tests/validation/parametric.rs); under a thick one they vary on the scale of
                // the thickness, so not below a tenth of it.
                let near = ((edges[1] - edges[0]) * core / radius).max(0.1 * t).min(core_far);
                let lengths = two_sided(2.0 * PI * core, near, core_far, fine.growth);
                // Smallest elements facing the contact.
                let start = if above { -0.5 * PI } else { 0.5 * PI };
                let at = |a: f64| [centre[0] + core * a.cos(), centre[1] + core * a.sin()];
                b.move_to(at(start));
                let mut angle = start;
                for (k, l) in lengths.iter().enumerate() {
                    angle += l / core;
                    let p = if k + 1 == lengths.len() { at(start) } else { at(angle) };
                    b.arc_to(centre, p, 1, true, 1.0, "bonded");
                }
            }
            Shape::Block { width, depth } => {
                let (w, y) = (0.5 * width, s * depth);
                let far = (width / 20.0).min(depth / 10.0) / fine.scale;
                let (x0, x1) = (edges[0], edges[edges.len() - 1]);
                let first = edges[1] - edges[0];
                let last = edges[edges.len() - 1] - edges[edges.len() - 2];
                b.move_to([-w, 0.0]);
                let left = one_sided(x0 + w, first, far, fine.growth);
                let mut x = -w;
                for (k, l) in left.iter().rev().enumerate() {
                    x += l;
                    let xe = if k + 1 == left.len() { x0 } else { x };
                    b.line_to([xe, 0.0], 1, "free");
                }
                for &xe in &edges[1..] {
                    b.line_to([xe, 0.0], 1, contact);
                }
                let right = one_sided(w - x1, last, far, fine.growth);
                let mut x = x1;
                for (k, l) in right.iter().enumerate() {
                    x += l;
                    let xe = if k + 1 == right.len() { w } else { x };
                    b.line_to([xe, 0.0], 1, "free");
                }
                let n_side = ((depth / far).ceil() as usize).max(2);
                let n_far = ((width / far).ceil() as usize).max(2);
                b.line_to([w, y], n_side, "free")
                    .line_to([-w, y], n_far, "far")
                    .close(n_side, "free");
            }
        }
        b.finish()
    }
}

/// How the elements grow away from the contact: by `growth` per element, to far sizes
/// divided by `scale`.
#[derive(Debug, Clone, Copy)]
struct Grading {
    growth: f64,
    scale: f64,
}

/// Why a generated body's lengths cannot be meshed ([`Shape::proportion_problem`]), in words.
#[derive(Debug, Clone, PartialEq)]
pub enum ProportionProblem {
    /// The inner circle (shaft, bore, core) is below [`MIN_INNER_FRACTION`] of the outer one.
    InnerTooSmall(String),
    /// The wall between the circles is thinner than [`MIN_WALL_PER_ELEMENT`] of the far
    /// elements.
    WallTooThin(String),
}

/// Thinnest wall of a roller or ring, as a fraction of its far element length: a cover's
/// elements are at most 10 thicknesses long ([`Shape::far_elements`]), the same ratio.
pub const MIN_WALL_PER_ELEMENT: f64 = 0.1;

/// Smallest inner circle (shaft, bore, core) of a roller or ring as a fraction of its outer one.
/// A fixed inner circle of radius r holds the body's rotation by about (r/R)² of its
/// translations: the support check of the BEM (src/bem/assemble.rs, 1e-10) fails near
/// r/R = 2e-5, where the message blamed a missing support; a thousandth keeps a margin of 400
/// in that ratio and is far below any roller, ring or cover built.
pub const MIN_INNER_FRACTION: f64 = 1e-3;

/// Far element size of a circle of radius r: a 48th of its circumference, as the shipped
/// Gmsh geometries give their far points.
fn far_size(r: f64) -> f64 {
    2.0 * PI * r / 48.0
}

/// A circle of radius `r` about `centre` touching the contact at the origin: the contact
/// elements (ends at x = `edges`, on the circle's side facing the contact), then the rest of
/// the circle back to the start (group `groups[1]`; the contact's is `groups[0]`), graded
/// from the end contact elements' lengths to `far`. `centre_above`: the centre lies at y > 0
/// (the contact at the circle's bottom).
#[allow(clippy::too_many_arguments)]
fn outer_circle(
    b: &mut MeshBuilder,
    centre: [f64; 2],
    r: f64,
    edges: &[f64],
    centre_above: bool,
    groups: [&str; 2],
    far: f64,
    fine: Grading,
) {
    let [contact, group] = groups;
    let s = if centre_above { 1.0 } else { -1.0 };
    let surface = |x: f64| [x, centre[1] - s * (r * r - x * x).sqrt()];
    // Walking the contact in +x is counter-clockwise round a centre above it.
    let ccw = centre_above;
    b.move_to(surface(edges[0]));
    for &x in &edges[1..] {
        b.arc_to(centre, surface(x), 1, ccw, 1.0, contact);
    }
    let angle = |p: [f64; 2]| (p[1] - centre[1]).atan2(p[0] - centre[0]);
    let (a0, a1) = (angle(surface(edges[edges.len() - 1])), angle(surface(edges[0])));
    let dir = if ccw { 1.0 } else { -1.0 };
    let sweep = (dir * (a1 - a0)).rem_euclid(2.0 * PI);
    // The contact end elements' arc lengths start the grading on each side.
    let arc = |x0: f64, x1: f64| r * (angle(surface(x1)) - angle(surface(x0))).abs();
    let n = edges.len();
    let (h_end, h_start) = (arc(edges[n - 2], edges[n - 1]), arc(edges[0], edges[1]));
    let half = 0.5 * sweep * r;
    let mut lengths = one_sided(half, h_end, far, fine.growth);
    let mut back = one_sided(half, h_start, far, fine.growth);
    back.reverse();
    lengths.extend(back);
    let mut a = a0;
    for (k, l) in lengths.iter().enumerate() {
        a += dir * l / r;
        let p = if k + 1 == lengths.len() {
            surface(edges[0])
        } else {
            [centre[0] + r * a.cos(), centre[1] + r * a.sin()]
        };
        b.arc_to(centre, p, 1, ccw, 1.0, group);
    }
}

/// Element lengths of a run of length `run` starting next to an element of length `first`:
/// each `growth` times the one before, up to `far`, scaled so that they fill the run exactly.
fn one_sided(run: f64, first: f64, far: f64, growth: f64) -> Vec<f64> {
    let far = far.max(first);
    let mut lengths = Vec::new();
    let (mut h, mut total) = (first, 0.0);
    while total < run {
        h = (h * growth).min(far);
        // The last element is merged into the others when less than half of it is left.
        if total + 0.5 * h >= run && !lengths.is_empty() {
            break;
        }
        lengths.push(h);
        total += h;
    }
    if lengths.is_empty() {
        lengths.push(run);
        total = run;
    }
    let scale = run / total;
    lengths.iter().map(|l| l * scale).collect()
}

/// Element lengths of a closed run of length `run` whose both ends meet an element of
/// length `near`: [`one_sided`] over each half.
fn two_sided(run: f64, near: f64, far: f64, growth: f64) -> Vec<f64> {
    let mut lengths = one_sided(0.5 * run, near / growth, far, growth);
    let back: Vec<f64> = lengths.iter().rev().copied().collect();
    lengths.extend(back);
    lengths
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::mesh::{boundary_loops, validate_and_orient};

    fn uniform(l: f64, n: usize) -> Vec<f64> {
        (0..=n).map(|i| -l + 2.0 * l * i as f64 / n as f64).collect()
    }

    /// Every family, on either side, is a valid body: closed loops that neither cross nor
    /// fold, its nodes on the exact circles or lines, the contact element ends at the edges.
    #[test]
    fn every_family_builds_a_valid_body_with_its_nodes_on_the_exact_geometry() {
        let shapes = [
            Shape::Roller {
                radius: 150.0,
                shaft: 15.0,
            },
            Shape::Ring { bore: 50.0, rim: 65.0 },
            Shape::CoveredRoller {
                radius: 100.0,
                cover_thickness: 0.5,
            },
            Shape::Block {
                width: 80.0,
                depth: 40.0,
            },
        ];
        let edges = uniform(21.0 / 17.0, 21);
        for shape in shapes {
            for above in [true, false] {
                let mut mesh = shape.mesh(&edges, "contact", above, "test");
                validate_and_orient(&mut mesh).unwrap_or_else(|e| panic!("{shape:?} {above}: {e}"));
                let loops = boundary_loops(&mesh).unwrap();
                let expected = if matches!(shape, Shape::Block { .. }) { 1 } else { 2 };
                assert_eq!(loops.len(), expected, "{shape:?}");
                let contact = mesh.group_index("contact").unwrap();
                assert_eq!(mesh.count_in_group(contact), 21);
                let xs = mesh.group_end_abscissae(contact, 0.0);
                assert_eq!(xs, edges, "{shape:?}");
                let s = if above { 1.0 } else { -1.0 };
                for p in &mesh.nodes {
                    let on = match shape {
                        Shape::Roller { radius, shaft } => {
                            let r = p[0].hypot(p[1] - s * radius);
                            (r - radius).abs() < 1e-9 || (r - shaft).abs() < 1e-9
                        }
                        Shape::Ring { bore, rim } => {
                            let r = p[0].hypot(p[1] + s * bore);
                            (r - bore).abs() < 1e-9 || (r - rim).abs() < 1e-9
                        }
                        Shape::CoveredRoller {
                            radius,
                            cover_thickness,
                        } => {
                            let r = p[0].hypot(p[1] - s * radius);
                            (r - radius).abs() < 1e-9 || (r - radius + cover_thickness).abs() < 1e-9
                        }
                        Shape::Block { width, depth } => {
                            p[1].abs() < 1e-12
                                || (p[1] - s * depth).abs() < 1e-12
                                || (p[0].abs() - 0.5 * width).abs() < 1e-12
                        }
                    };
                    assert!(on, "{shape:?}: node {p:?} off the geometry");
                }
            }
        }
    }

    /// Away from the contact the elements grow by at most the grading factor (and a little
    /// for the final fit) up to the far size.
    #[test]
    fn graded_runs_fill_their_length_and_grow_gently() {
        let l = one_sided(235.0, 0.1176, 19.6, GROWTH);
        assert!((l.iter().sum::<f64>() - 235.0).abs() < 1e-9);
        assert!(l[0] < 0.1176 * GROWTH * 1.01);
        for w in l.windows(2) {
            assert!(w[1] / w[0] < GROWTH * 1.0001, "{w:?}");
        }
        assert!(*l.last().unwrap() < 19.6 * 1.01);
        assert_eq!(one_sided(0.01, 1.0, 2.0, GROWTH), vec![0.01]);
    }
}
