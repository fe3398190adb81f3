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
        // Cumulative fractions of a geometric sequence of element lengths.
        let lengths: Vec<f64> = (0..n).map(|k| grading.powi(k as i32)).collect();
        let total: f64 = lengths.iter().sum();
        let point = |f: f64| [p0[0] + f * (p1[0] - p0[0]), p0[1] + f * (p1[1] - p0[1])];
        let mut prev = start;
        let mut f0 = 0.0;
        for (k, len) in lengths.iter().enumerate() {
            let f1 = if k + 1 == n { 1.0 } else { f0 + len / total };
            let next = match (k + 1 == n, end_node) {
                (true, Some(s)) => s,
                _ => self.add_node(point(f1)),
            };
            let mut nodes = vec![prev, next];
            if self.quadratic {
                nodes.push(self.add_node(point(0.5 * (f0 + f1))));
            }
            self.mesh.elements.push(BoundaryElement { nodes, group: g });
            prev = next;
            f0 = f1;
        }
        self.pen = Some(prev);
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
    let y = if above { h } else { -h };
    let mut b = MeshBuilder::new(true, "half-plane block");
    b.move_to([-w, 0.0])
        .graded_line_to([-l, 0.0], n_face, 1.0 / growth, "free")
        .line_to([l, 0.0], contact_elements, "contact")
        .graded_line_to([w, 0.0], n_face, growth, "free")
        .line_to([w, y], side_elements, "free")
        .line_to([-w, y], 2 * side_elements, "far")
        .close(side_elements, "free");
    b.finish()
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
