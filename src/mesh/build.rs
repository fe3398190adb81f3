//! Procedural boundary meshes (rectangles, half-plane blocks with a refined contact segment,
//! annuli), for tests, benchmarks and quick studies without Gmsh.
//!
//! A [`MeshBuilder`] draws loops like a pen: [`MeshBuilder::move_to`] starts a loop,
//! [`MeshBuilder::line_to`] adds a straight run of elements, [`MeshBuilder::close`] returns to
//! the loop's start, [`MeshBuilder::circle`] adds a whole circular loop. Mid nodes of 3-node
//! elements lie on the exact line or circle. The builder does not orient the loops: pass the
//! result through [`super::validate_and_orient`] (the BEM does).

use super::{BoundaryElement, BoundaryMesh, PhysicalGroup};

/// Pen-style builder of a [`BoundaryMesh`].
#[derive(Debug, Clone)]
pub struct MeshBuilder {
    mesh: BoundaryMesh,
    quadratic: bool,
    loop_start: Option<usize>,
    pen: Option<usize>,
}

impl MeshBuilder {
    /// A builder of 3-node (`quadratic = true`) or 2-node elements; `label` names the mesh in
    /// messages.
    pub fn new(quadratic: bool, label: &str) -> Self {
        Self {
            mesh: BoundaryMesh::new(Vec::new(), Vec::new(), Vec::new(), label),
            quadratic,
            loop_start: None,
            pen: None,
        }
    }

    /// Starts a new loop at `p` [length].
    pub fn move_to(&mut self, p: [f64; 2]) -> &mut Self {
        let node = self.add_node(p);
        self.loop_start = Some(node);
        self.pen = Some(node);
        self
    }

    /// Adds `n` equal straight elements of group `group` from the pen to `p`.
    pub fn line_to(&mut self, p: [f64; 2], n: usize, group: &str) -> &mut Self {
        self.graded_line_to(p, n, 1.0, group)
    }

    /// Adds `n` straight elements from the pen to `p` whose lengths grow by the factor `grading`
    /// from one element to the next (grading < 1 shrinks them towards `p`).
    pub fn graded_line_to(&mut self, p: [f64; 2], n: usize, grading: f64, group: &str) -> &mut Self {
        let start = self.pen.expect("move_to before line_to");
        self.run_to(start, Some(p), n, grading, group);
        self
    }

    /// Closes the current loop with `n` equal straight elements back to its start.
    pub fn close(&mut self, n: usize, group: &str) -> &mut Self {
        let start = self.pen.expect("move_to before close");
        self.run_to(start, None, n, 1.0, group);
        self.pen = None;
        self.loop_start = None;
        self
    }

    /// Adds a whole circle of `n` elements (counter-clockwise) as its own loop.
    pub fn circle(&mut self, centre: [f64; 2], radius: f64, n: usize, group: &str) -> &mut Self {
        let g = self.group(group);
        let at = |t: f64| {
            let a = 2.0 * std::f64::consts::PI * t;
            [centre[0] + radius * a.cos(), centre[1] + radius * a.sin()]
        };
        let first = self.add_node(at(0.0));
        let mut prev = first;
        for k in 0..n {
            let next = if k + 1 == n {
                first
            } else {
                self.add_node(at((k + 1) as f64 / n as f64))
            };
            let mut nodes = vec![prev, next];
            if self.quadratic {
                nodes.push(self.add_node(at((k as f64 + 0.5) / n as f64)));
            }
            self.mesh.elements.push(BoundaryElement { nodes, group: g });
            prev = next;
        }
        self
    }

    /// Adds `n` circular-arc elements of group `group` from the pen to `p` around `centre`,
    /// counter-clockwise if `counter_clockwise`, with element angles growing by the factor
    /// `grading` from one element to the next. `p` must lie on the pen's circle (its radius is
    /// taken from the pen); mid nodes sit at the mid-angle of each element, as Gmsh puts them.
    pub fn arc_to(
        &mut self,
        centre: [f64; 2],
        p: [f64; 2],
        n: usize,
        counter_clockwise: bool,
        grading: f64,
        group: &str,
    ) -> &mut Self {
        let g = self.group(group);
        let start = self.pen.expect("move_to before arc_to");
        let p0 = self.mesh.nodes[start];
        let radius = (p0[0] - centre[0]).hypot(p0[1] - centre[1]);
        let a0 = (p0[1] - centre[1]).atan2(p0[0] - centre[0]);
        let a1 = (p[1] - centre[1]).atan2(p[0] - centre[0]);
        let tau = 2.0 * std::f64::consts::PI;
        let mut sweep = if counter_clockwise { a1 - a0 } else { a0 - a1 };
        sweep = sweep.rem_euclid(tau);
        if sweep == 0.0 {
            sweep = tau;
        }
        let dir = if counter_clockwise { 1.0 } else { -1.0 };
        let at = |f: f64| {
            let a = a0 + dir * f * sweep;
            [centre[0] + radius * a.cos(), centre[1] + radius * a.sin()]
        };
        let closes = self.loop_start.filter(|&s| {
            let q = self.mesh.nodes[s];
            (q[0] - p[0]).hypot(q[1] - p[1]) <= 1e-12 * radius
        });
        let last = self.chain(start, n, grading, g, &at, closes, Some(p));
        self.pen = Some(last);
        if closes.is_some() {
            self.pen = None;
            self.loop_start = None;
        }
        self
    }

    /// The finished mesh.
    pub fn finish(self) -> BoundaryMesh {
        self.mesh
    }

    fn run_to(&mut self, start: usize, end: Option<[f64; 2]>, n: usize, grading: f64, group: &str) {
        let g = self.group(group);
        let p0 = self.mesh.nodes[start];
        let (p1, end_node) = match end {
            Some(p) => (p, None),
            None => {
                let s = self.loop_start.expect("move_to before close");
                (self.mesh.nodes[s], Some(s))
            }
        };
        let point = |f: f64| [p0[0] + f * (p1[0] - p0[0]), p0[1] + f * (p1[1] - p0[1])];
        let last = self.chain(start, n, grading, g, &point, end_node, None);
        self.pen = Some(last);
    }

    /// Adds `n` elements of group `g` from node `start` along the curve `at(f)`, f ∈ [0, 1],
    /// with lengths (in f) growing by `grading`; the last node is `end_node` if given, else a
    /// new node at `end_point` (or at(1)). Mid nodes sit at the mid-parameter. Returns the last
    /// node.
    #[allow(clippy::too_many_arguments)]
    fn chain(
        &mut self,
        start: usize,
        n: usize,
        grading: f64,
        g: usize,
        at: &dyn Fn(f64) -> [f64; 2],
        end_node: Option<usize>,
        end_point: Option<[f64; 2]>,
    ) -> usize {
        // Cumulative fractions of a geometric sequence of element lengths.
        let lengths: Vec<f64> = (0..n).map(|k| grading.powi(k as i32)).collect();
        let total: f64 = lengths.iter().sum();
        let mut prev = start;
        let mut f0 = 0.0;
        for (k, len) in lengths.iter().enumerate() {
            let last = k + 1 == n;
            let f1 = if last { 1.0 } else { f0 + len / total };
            let next = match (last, end_node) {
                (true, Some(s)) => s,
                (true, None) => self.add_node(end_point.unwrap_or_else(|| at(1.0))),
                _ => self.add_node(at(f1)),
            };
            let mut nodes = vec![prev, next];
            if self.quadratic {
                nodes.push(self.add_node(at(0.5 * (f0 + f1))));
            }
            self.mesh.elements.push(BoundaryElement { nodes, group: g });
            prev = next;
            f0 = f1;
        }
        prev
    }

    fn add_node(&mut self, p: [f64; 2]) -> usize {
        self.mesh.nodes.push(p);
        self.mesh.nodes.len() - 1
    }

    fn group(&mut self, name: &str) -> usize {
        if let Some(i) = self.mesh.groups.iter().position(|g| g.name == name) {
            return i;
        }
        self.mesh.groups.push(PhysicalGroup {
            tag: self.mesh.groups.len() as i32 + 1,
            name: name.to_string(),
        });
        self.mesh.groups.len() - 1
    }
}

/// Axis-parallel rectangle [x0, x0 + width] × [y0, y0 + height] with `n[k]` equal elements
/// on side k and group `groups[k]`; sides in the order bottom, right, top, left.
pub fn rectangle(
    origin: [f64; 2],
    width: f64,
    height: f64,
    n: [usize; 4],
    groups: [&str; 4],
    quadratic: bool,
) -> BoundaryMesh {
    let [x0, y0] = origin;
    let mut b = MeshBuilder::new(quadratic, "rectangle");
    b.move_to([x0, y0])
        .line_to([x0 + width, y0], n[0], groups[0])
        .line_to([x0 + width, y0 + height], n[1], groups[1])
        .line_to([x0, y0 + height], n[2], groups[2])
        .close(n[3], groups[3]);
    b.finish()
}

/// Annulus r_inner ≤ r ≤ r_outer centred at the origin: a circle of `n_inner` elements in
/// group `inner` (the hole) and one of `n_outer` elements in group `outer`.
pub fn annulus(
    r_inner: f64,
    r_outer: f64,
    n_inner: usize,
    n_outer: usize,
    groups: [&str; 2],
    quadratic: bool,
) -> BoundaryMesh {
    let mut b = MeshBuilder::new(quadratic, "annulus");
    b.circle([0.0, 0.0], r_outer, n_outer, groups[1]);
    b.circle([0.0, 0.0], r_inner, n_inner, groups[0]);
    b.finish()
}

/// A circle through the contact segment |x| ≤ `half_length` at the origin: `contact` elements
/// with equal-x ends (group `contact`), then the rest of the circle back to the start, the long
/// way round, in two halves of `rest` elements graded from the contact elements' size towards
/// the far size (each half by the factor that takes the one to the other).
struct ContactCircle {
    centre: [f64; 2],
    radius: f64,
    half_length: f64,
    contact: usize,
    rest: usize,
    counter_clockwise: bool,
}

impl ContactCircle {
    /// Draws the circle into `b`; `surface(x)` is its point above or below x on the contact
    /// side, and the rest of it goes to `group`.
    fn draw(&self, b: &mut MeshBuilder, surface: &dyn Fn(f64) -> [f64; 2], group: &str) {
        let (centre, turn, n, l) = (self.centre, self.counter_clockwise, self.contact, self.half_length);
        b.move_to(surface(-l));
        for i in 1..=n {
            let x = -l + 2.0 * l * i as f64 / n as f64;
            b.arc_to(centre, surface(x), 1, turn, 1.0, "contact");
        }
        let far_size = 2.0 * std::f64::consts::PI * self.radius / (self.rest.max(2) as f64);
        let contact_size = 2.0 * l / n.max(1) as f64;
        let half = (self.rest / 2).max(1);
        let grading = (far_size / contact_size)
            .max(1.0)
            .powf(1.0 / (half as f64 - 1.0).max(1.0));
        // The point opposite the contact.
        let top = [centre[0], 2.0 * centre[1]];
        b.arc_to(centre, top, half, turn, grading, group);
        b.arc_to(centre, surface(-l), self.rest.max(2) - half, turn, 1.0 / grading, group);
    }
}

/// Mesh sizes of a [`roller_on_shaft`].
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct RollerMeshSizes {
    /// Elements on the contact segment (their ends at x = −L + 2L·i/n).
    pub contact: usize,
    /// Elements on the rest of the outer circle, graded from the contact size to the far size.
    pub free: usize,
    /// Elements on the shaft hole.
    pub shaft: usize,
}

/// A roller of radius `radius` on a rigid shaft of radius `shaft_radius` (groups `contact`,
/// `free`, `shaft`), the procedural twin of `meshes/roller_r100_shaft10_A.geo`: body A (above
/// the contact, centre at y = +R) if `above`, else body B (centre at y = −R). The contact
/// segment |x| ≤ `half_length` carries equal-x elements, so two rollers built with the same
/// `half_length` and contact count pair node to node; the free arc is graded (each half by the
/// factor that takes the element from the contact size towards the far size).
pub fn roller_on_shaft(
    radius: f64,
    shaft_radius: f64,
    half_length: f64,
    sizes: RollerMeshSizes,
    above: bool,
) -> BoundaryMesh {
    let s = if above { 1.0 } else { -1.0 };
    let centre = [0.0, s * radius];
    let surface = |x: f64| [x, s * (radius - (radius * radius - x * x).sqrt())];
    let mut b = MeshBuilder::new(true, "roller");
    // Walking the contact in +x is counter-clockwise round A's centre (the contact is A's
    // bottom) and clockwise round B's; the loop goes on the same way round.
    let arc = ContactCircle {
        centre,
        radius,
        half_length,
        contact: sizes.contact,
        rest: sizes.free,
        counter_clockwise: above,
    };
    arc.draw(&mut b, &surface, "free");
    b.circle(centre, shaft_radius, sizes.shaft, "shaft");
    b.finish()
}

/// Mesh sizes of a [`ring_with_bore`].
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct RingMeshSizes {
    /// Elements on the contact segment of the bore (their ends at x = −L + 2L·i/n).
    pub contact: usize,
    /// Elements on the rest of the bore, graded from the contact size to the far size.
    pub bore: usize,
    /// Elements on the outer rim.
    pub rim: usize,
}

/// A ring whose bore of radius `bore_radius` holds a roller (internal contact), with its outer
/// rim at `rim_radius` (groups `contact`, `bore`, `rim`): the bore touches the contact at the
/// origin, its centre on the roller's side, so the ring is body B (material below the contact,
/// centre at y = +R) if not `above`, else body A (centre at y = −R). The contact segment
/// |x| ≤ `half_length` of the bore carries equal-x elements like [`roller_on_shaft`]'s, so a
/// roller and a ring built with the same `half_length` and count have contact elements with the
/// same end abscissae (their mid nodes differ with the radius: the ring's contact nodes are
/// carried over to the roller's grid by the transfer). Counterpart of `meshes/bore_ring.inc`.
pub fn ring_with_bore(
    bore_radius: f64,
    rim_radius: f64,
    half_length: f64,
    sizes: RingMeshSizes,
    above: bool,
) -> BoundaryMesh {
    // The bore's centre lies across the contact from the ring's material.
    let s = if above { -1.0 } else { 1.0 };
    let r = bore_radius;
    let centre = [0.0, s * r];
    let surface = |x: f64| [x, s * (r - (r * r - x * x).sqrt())];
    let mut b = MeshBuilder::new(true, "ring");
    // Walking the bore's bottom in +x is counter-clockwise round a centre above it.
    let arc = ContactCircle {
        centre,
        radius: r,
        half_length,
        contact: sizes.contact,
        rest: sizes.bore,
        counter_clockwise: !above,
    };
    arc.draw(&mut b, &surface, "bore");
    b.circle(centre, rim_radius, sizes.rim, "rim");
    b.finish()
}

/// (elements, growth factor) of a straight run of length `run` whose elements grow by at most
/// 1.2 from `first` (the neighbouring contact element) towards `far_size`: geometric growth
/// while it needs fewer elements than `far_size` would, equal elements otherwise.
fn graded_run(run: f64, first: f64, far_size: f64) -> (usize, f64) {
    let grading: f64 = 1.2;
    let n_graded = ((1.0 + run * (grading - 1.0) / first).ln() / grading.ln())
        .ceil()
        .max(1.0) as usize;
    let n_equal = ((run / far_size).ceil() as usize).max(1);
    if n_graded >= n_equal {
        (n_graded, grading)
    } else {
        (n_equal, 1.0)
    }
}

/// A rectangular block standing in for a half-space (paper Fig. 2; the procedural twin of
/// `meshes/halfspace_block_A.geo`): width 2·`half_width`, depth `depth`, its contact face on
/// y = 0 (groups `contact` on |x| ≤ `half_length` with `n_contact` equal elements, `free` on the
/// rest of that face and the sides, `far` on the opposite face). Above y = 0 (body A) if
/// `above`, else below. Elements grow geometrically by at most 1.2 from the contact size to
/// `far_size` along the contact face.
pub fn half_space_block(
    half_width: f64,
    depth: f64,
    half_length: f64,
    n_contact: usize,
    far_size: f64,
    above: bool,
) -> BoundaryMesh {
    let (n_free, g) = graded_run(
        half_width - half_length,
        2.0 * half_length / n_contact.max(1) as f64,
        far_size,
    );
    let n_side = ((depth / far_size).ceil() as usize).max(2);
    let n_far = ((2.0 * half_width / far_size).ceil() as usize).max(2);
    let faces = BlockFaces {
        n_free,
        growth: g,
        n_side,
        n_far,
    };
    block(half_width, depth, half_length, n_contact, faces, above)
}

/// Element counts of a block's faces other than its contact segment.
struct BlockFaces {
    /// Elements on each free part of the contact face, growing by `growth` away from contact.
    n_free: usize,
    growth: f64,
    /// Elements on each side face.
    n_side: usize,
    /// Elements on the far face.
    n_far: usize,
}

/// The rectangle [−w, w] × [0, ±h] of [`half_space_block`] and [`half_plane_block`].
fn block(w: f64, h: f64, half_length: f64, n_contact: usize, faces: BlockFaces, above: bool) -> BoundaryMesh {
    let y = if above { h } else { -h };
    let (l, g) = (half_length, faces.growth);
    let mut b = MeshBuilder::new(true, "block");
    b.move_to([-w, 0.0])
        .graded_line_to([-l, 0.0], faces.n_free, 1.0 / g, "free")
        .line_to([l, 0.0], n_contact, "contact")
        .graded_line_to([w, 0.0], faces.n_free, g, "free")
        .line_to([w, y], faces.n_side, "free")
        .line_to([-w, y], faces.n_far, "far")
        .close(faces.n_side, "free");
    b.finish()
}

/// A flat layer of thickness `thickness` below y = 0 (body B), the procedural twin of
/// `meshes/tyre_layer_strip.inc`: groups `contact` (|x| ≤ `half_length`, `n_contact` equal
/// elements), `free` (the rest of the top face), `ends` (x = ±`half_width`) and `bonded`
/// (y = −thickness). Far elements are about `far_size` long; the bonded face under the contact
/// segment has the contact's elements (a thin layer carries its load straight through to the
/// core, whose traction varies there as fast as the contact's) and grades out like the top face.
pub fn layer_strip(thickness: f64, half_width: f64, half_length: f64, n_contact: usize, far_size: f64) -> BoundaryMesh {
    let (n_free, g) = graded_run(
        half_width - half_length,
        2.0 * half_length / n_contact.max(1) as f64,
        far_size,
    );
    let (w, l, t) = (half_width, half_length, thickness);
    let mut b = MeshBuilder::new(true, "layer");
    b.move_to([-w, 0.0])
        .graded_line_to([-l, 0.0], n_free, 1.0 / g, "free")
        .line_to([l, 0.0], n_contact, "contact")
        .graded_line_to([w, 0.0], n_free, g, "free")
        .line_to([w, -t], 2, "ends")
        .graded_line_to([l, -t], n_free, 1.0 / g, "bonded")
        .line_to([-l, -t], n_contact, "bonded")
        .graded_line_to([-w, -t], n_free, g, "bonded")
        .close(2, "ends");
    b.finish()
}

/// A rectangular block standing in for a half-plane (the paper's Fig. 2 block): [−w, w] × [0, h]
/// for a body above the contact (`above`, body A) or [−w, w] × [−h, 0] below it (body B).
/// Its face y = 0 carries `contact_elements` equal elements on |x| ≤ `contact_half_length`
/// (group `contact`), then elements growing geometrically by `growth` towards the corners,
/// starting from the contact elements' length (group `free`); the sides have `side_elements`
/// equal elements each (group `free`), the far face 2·`side_elements` (group `far`).
/// Lengths in the case's unit.
pub fn half_plane_block(
    w: f64,
    h: f64,
    contact_half_length: f64,
    contact_elements: usize,
    growth: f64,
    side_elements: usize,
    above: bool,
) -> BoundaryMesh {
    let l = contact_half_length;
    let first = 2.0 * l / contact_elements as f64;
    // First + first·g + … + first·g^(n−1) ≈ w − l.
    let n_face = if growth > 1.0 {
        ((1.0 + (w - l) * (growth - 1.0) / first).ln() / growth.ln()).round() as usize
    } else {
        ((w - l) / first).round() as usize
    }
    .max(1);
    let faces = BlockFaces {
        n_free: n_face,
        growth,
        n_side: side_elements,
        n_far: 2 * side_elements,
    };
    block(w, h, l, contact_elements, faces, above)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::mesh::{boundary_loops, validate_and_orient};

    #[test]
    fn annulus_hole_is_turned_clockwise_and_areas_are_exact_for_quadratic_arcs() {
        let mut mesh = annulus(1.0, 2.0, 16, 16, ["inner", "outer"], true);
        let notices = validate_and_orient(&mut mesh).unwrap();
        // Both circles are drawn counter-clockwise: only the hole is turned round.
        assert_eq!(notices.len(), 1, "{notices:?}");
        assert!(notices[0].contains("hole") && notices[0].contains("inner"));
        let loops = boundary_loops(&mesh).unwrap();
        let (outer, hole) = if loops[0].is_hole() {
            (&loops[1], &loops[0])
        } else {
            (&loops[0], &loops[1])
        };
        // Quadratic interpolation of a circle: area error O(h^4) ≈ 1e-4 relative at 16 elements.
        assert!((outer.signed_area - std::f64::consts::PI * 4.0).abs() < 2e-3);
        assert!((hole.signed_area + std::f64::consts::PI).abs() < 5e-4);
    }

    /// The procedural roller is one closed outer loop and the shaft hole, its contact nodes at
    /// the equal-x stations on the circle, all nodes on the two circles.
    #[test]
    fn roller_on_shaft_has_its_contact_nodes_at_equal_x_on_the_circle() {
        for above in [true, false] {
            let sizes = RollerMeshSizes {
                contact: 21,
                free: 40,
                shaft: 24,
            };
            let mut mesh = roller_on_shaft(100.0, 10.0, 1.3, sizes, above);
            validate_and_orient(&mut mesh).unwrap();
            let loops = boundary_loops(&mesh).unwrap();
            assert_eq!(loops.len(), 2);
            let cy = if above { 100.0 } else { -100.0 };
            for p in &mesh.nodes {
                let r = p[0].hypot(p[1] - cy);
                assert!(
                    (r - 100.0).abs() < 1e-9 || (r - 10.0).abs() < 1e-9,
                    "node {p:?} at r = {r}"
                );
            }
            let contact = mesh.group_index("contact").unwrap();
            let xs = mesh.group_end_abscissae(contact, 1e-12);
            assert_eq!(xs.len(), 22);
            for (i, x) in xs.iter().enumerate() {
                assert!((x - (-1.3 + 2.6 * i as f64 / 21.0)).abs() < 1e-12);
            }
            // Contact nodes face the other body.
            for e in mesh.elements.iter().filter(|e| e.group == contact) {
                let y = mesh.nodes[e.nodes[2]][1];
                assert!(y.abs() < 0.01, "contact mid node at y = {y}");
            }
        }
    }

    #[test]
    fn graded_line_reaches_its_end_with_growing_elements() {
        let mut b = MeshBuilder::new(false, "t");
        b.move_to([0.0, 0.0]).graded_line_to([10.0, 0.0], 4, 2.0, "a");
        let m = b.finish();
        let xs: Vec<f64> = m.nodes.iter().map(|p| p[0]).collect();
        assert_eq!(xs.len(), 5);
        assert!((xs[4] - 10.0).abs() < 1e-14);
        assert!(((xs[2] - xs[1]) / (xs[1] - xs[0]) - 2.0).abs() < 1e-12);
    }
}
