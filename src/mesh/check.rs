//! Mesh checks and loop orientation.
//!
//! [`validate_and_orient`] checks every element (node indices, zero length, distorted 3-node
//! elements), traces the closed boundary loops, and turns elements round so that the material
//! lies on the left of every element (outer contour counter-clockwise, holes clockwise; normals
//! out of the material, see [`crate::mesh`]). Holes are told from outer contours by nesting:
//! a loop inside an odd number of other loops is a hole.
//!
//! A mesh must describe one body: loops that do not cross each other or themselves (checked on
//! the polygon through every node, mid nodes included), exactly one outer contour, and holes
//! directly inside it. A bow-tie outline, a hole that crosses the outer contour or a loop outside
//! the body is refused with the groups concerned named.

use super::{BoundaryMesh, ElementDefect, MeshError};
use crate::quadrature::gauss_legendre;

/// One closed loop of the boundary.
#[derive(Debug, Clone, PartialEq)]
pub struct BoundaryLoop {
    /// Element indices in walking order: each element's end node is the next one's start node.
    pub elements: Vec<usize>,
    /// Area enclosed by the loop's (exact quadratic) geometry [length²], positive when the loop
    /// runs counter-clockwise.
    pub signed_area: f64,
    /// Nesting depth: 0 for an outer contour, 1 for a hole in it, 2 for an island in the hole…
    pub depth: usize,
}

impl BoundaryLoop {
    /// Whether the loop bounds a hole (odd nesting depth).
    pub fn is_hole(&self) -> bool {
        self.depth % 2 == 1
    }
}

/// Checks `mesh` and orients its loops in place so that the material lies on the left of every
/// element. Returns one notice per loop in which elements were turned round.
pub fn validate_and_orient(mesh: &mut BoundaryMesh) -> Result<Vec<String>, MeshError> {
    check_elements(mesh)?;
    let traced = trace_loops(mesh)?;
    let loops = loop_geometry(mesh, &traced);
    check_one_simple_body(mesh, &traced, &loops)?;
    let mut notices = Vec::new();
    for (k, (tl, lp)) in traced.iter().zip(&loops).enumerate() {
        // Outer contours must run counter-clockwise (positive area), holes clockwise.
        let flip_all = (lp.signed_area > 0.0) == lp.is_hole();
        let mut turned = 0;
        for (&e, &rev) in tl.elements.iter().zip(&tl.reversed) {
            if rev != flip_all {
                mesh.elements[e].reverse();
                turned += 1;
            }
        }
        if turned > 0 {
            let mut groups: Vec<&str> = tl
                .elements
                .iter()
                .map(|&e| mesh.groups[mesh.elements[e].group].name.as_str())
                .collect();
            groups.sort_unstable();
            groups.dedup();
            notices.push(format!(
                "{}: loop {k} ({}, groups {}; {} elements): turned {turned} element(s) round so \
                 that the material lies on their left and the normals point out of the material \
                 (harmless: Gmsh orients a curve as the .geo draws it, and rollbem orients every \
                 loop itself)",
                mesh.source,
                if lp.is_hole() { "hole" } else { "outer contour" },
                groups.join(", "),
                tl.elements.len()
            ));
        }
    }
    Ok(notices)
}

/// The closed loops of a mesh, in walking order of its elements as they stand.
///
/// Fails like [`validate_and_orient`] on a bad mesh; on a mesh that
/// [`validate_and_orient`] has processed, every loop has the orientation of the module docs.
pub fn boundary_loops(mesh: &BoundaryMesh) -> Result<Vec<BoundaryLoop>, MeshError> {
    check_elements(mesh)?;
    let traced = trace_loops(mesh)?;
    let loops = loop_geometry(mesh, &traced);
    check_one_simple_body(mesh, &traced, &loops)?;
    Ok(loops)
}

/// A traced loop: elements in walking order and whether each is walked against its node order.
struct TracedLoop {
    elements: Vec<usize>,
    reversed: Vec<bool>,
}

/// An element of `mesh` no longer than this [length] has zero length (a duplicated point):
/// 1e-10 of the mesh's size, far above its coordinates' round-off.
pub fn zero_length_tolerance(mesh: &BoundaryMesh) -> f64 {
    1e-10 * mesh.size()
}

/// Per-element checks: node counts and indices, group index, zero length, distortion, one
/// order (2 or 3 nodes) for all (the loops' polygons, the contact grid and the BEM take one).
fn check_elements(mesh: &BoundaryMesh) -> Result<(), MeshError> {
    let path = || mesh.source.clone();
    let tolerance = zero_length_tolerance(mesh);
    for (i, el) in mesh.elements.iter().enumerate() {
        if el.nodes.len() != 2 && el.nodes.len() != 3 {
            return Err(MeshError::MalformedElement {
                path: path(),
                element: i,
                problem: format!("{} nodes (expected 2 or 3)", el.nodes.len()),
            });
        }
        if el.group >= mesh.groups.len() {
            return Err(MeshError::MalformedElement {
                path: path(),
                element: i,
                problem: format!("group index {} but the mesh has {} groups", el.group, mesh.groups.len()),
            });
        }
        if let Some(&node) = el.nodes.iter().find(|&&n| n >= mesh.nodes.len()) {
            return Err(MeshError::NodeOutOfRange {
                path: path(),
                element: i,
                node,
                count: mesh.nodes.len(),
            });
        }
        let first = mesh.elements[0].nodes.len();
        let [x0, y0] = mesh.nodes[el.nodes[0]];
        let bad = |defect| MeshError::BadElement {
            path: path(),
            group: mesh.groups[el.group].name.clone(),
            element: i,
            x: x0,
            y: y0,
            defect,
        };
        if el.nodes.len() != first {
            return Err(bad(ElementDefect::MixedOrder {
                nodes: el.nodes.len(),
                first,
            }));
        }
        let [x1, y1] = mesh.nodes[el.nodes[1]];
        let chord = [x1 - x0, y1 - y0];
        let length2 = chord[0] * chord[0] + chord[1] * chord[1];
        if length2.sqrt() <= tolerance {
            return Err(bad(ElementDefect::ZeroLength));
        }
        if el.nodes.len() == 3 {
            // The Jacobian along the chord is |c|²(1/2 + ξ(1 − 2s)), with s the mid node's
            // position along the chord: it stays positive on [−1, 1] iff 1/4 < s < 3/4.
            let [xm, ym] = mesh.nodes[el.nodes[2]];
            let s = ((xm - x0) * chord[0] + (ym - y0) * chord[1]) / length2;
            if !(0.25 < s && s < 0.75) {
                return Err(bad(ElementDefect::Distorted));
            }
        }
    }
    Ok(())
}

/// Follows the elements from node to node into closed loops.
fn trace_loops(mesh: &BoundaryMesh) -> Result<Vec<TracedLoop>, MeshError> {
    let mut incident: Vec<Vec<usize>> = vec![Vec::new(); mesh.nodes.len()];
    for (i, el) in mesh.elements.iter().enumerate() {
        incident[el.nodes[0]].push(i);
        incident[el.nodes[1]].push(i);
    }
    for (node, list) in incident.iter().enumerate() {
        match list.len() {
            0 | 2 => {}
            1 => {
                let el = list[0];
                let groups: Vec<String> = mesh.groups.iter().map(|g| format!("`{}`", g.name)).collect();
                return Err(MeshError::OpenLoop {
                    path: mesh.source.clone(),
                    groups: groups.join(", "),
                    group: mesh.groups[mesh.elements[el].group].name.clone(),
                    element: el,
                    node,
                    x: mesh.nodes[node][0],
                    y: mesh.nodes[node][1],
                });
            }
            count => {
                let mut groups: Vec<&str> = list
                    .iter()
                    .map(|&e| mesh.groups[mesh.elements[e].group].name.as_str())
                    .collect();
                groups.sort_unstable();
                groups.dedup();
                return Err(MeshError::BranchingBoundary {
                    path: mesh.source.clone(),
                    node,
                    count,
                    x: mesh.nodes[node][0],
                    y: mesh.nodes[node][1],
                    groups: groups.join(", "),
                });
            }
        }
    }
    let mut visited = vec![false; mesh.elements.len()];
    let mut loops = Vec::new();
    for first in 0..mesh.elements.len() {
        if visited[first] {
            continue;
        }
        visited[first] = true;
        let (start, mut node) = mesh.elements[first].ends();
        let mut current = first;
        let mut traced = TracedLoop {
            elements: vec![first],
            reversed: vec![false],
        };
        while node != start {
            // Every node has exactly two incident elements (checked above).
            let list = &incident[node];
            let next = if list[0] == current { list[1] } else { list[0] };
            let (a, b) = mesh.elements[next].ends();
            let reversed = a != node;
            node = if reversed { a } else { b };
            visited[next] = true;
            traced.elements.push(next);
            traced.reversed.push(reversed);
            current = next;
        }
        loops.push(traced);
    }
    Ok(loops)
}

/// Names of the groups of a loop's elements, sorted, without repeats.
fn loop_groups(mesh: &BoundaryMesh, elements: &[usize]) -> String {
    let mut groups: Vec<&str> = elements
        .iter()
        .map(|&e| mesh.groups[mesh.elements[e].group].name.as_str())
        .collect();
    groups.sort_unstable();
    groups.dedup();
    groups.join(", ")
}

/// Refuses crossing loops, a second outer contour and islands: the mesh must bound one body.
fn check_one_simple_body(mesh: &BoundaryMesh, traced: &[TracedLoop], loops: &[BoundaryLoop]) -> Result<(), MeshError> {
    check_no_crossings(mesh, traced)?;
    let outer = (0..loops.len())
        .filter(|&k| loops[k].depth == 0)
        .max_by(|&i, &j| loops[i].signed_area.abs().total_cmp(&loops[j].signed_area.abs()));
    for (k, lp) in loops.iter().enumerate() {
        if lp.depth == 1 || Some(k) == outer {
            continue;
        }
        let [x, y] = polygon(mesh, &traced[k])[0];
        return Err(MeshError::LoopOutsideBody {
            path: mesh.source.clone(),
            groups: loop_groups(mesh, &lp.elements),
            outer: outer.map_or_else(String::new, |o| loop_groups(mesh, &loops[o].elements)),
            x,
            y,
            island: lp.depth > 1,
        });
    }
    Ok(())
}

/// One straight piece of a loop's polygon (end node to mid node to end node).
struct Segment {
    a: [f64; 2],
    b: [f64; 2],
    /// Loop index and position of the segment along its polygon.
    at: (usize, usize),
    /// Element the segment belongs to.
    element: usize,
}

/// Refuses any two non-adjacent segments of the loops' polygons that touch or cross: a sweep in
/// x over the segments sorted by their left end, so only those overlapping in x are compared.
fn check_no_crossings(mesh: &BoundaryMesh, traced: &[TracedLoop]) -> Result<(), MeshError> {
    let mut segments = Vec::new();
    let mut lengths = Vec::with_capacity(traced.len());
    for (k, t) in traced.iter().enumerate() {
        let points = polygon(mesh, t);
        // The element each polygon point starts a segment of (one or two points per element).
        let owners = t
            .elements
            .iter()
            .flat_map(|&e| std::iter::repeat_n(e, mesh.elements[e].nodes.len() - 1));
        for (i, element) in owners.enumerate() {
            segments.push(Segment {
                a: points[i],
                b: points[(i + 1) % points.len()],
                at: (k, i),
                element,
            });
        }
        lengths.push(points.len());
    }
    let left = |s: &Segment| s.a[0].min(s.b[0]);
    let right = |s: &Segment| s.a[0].max(s.b[0]);
    segments.sort_by(|s, t| left(s).total_cmp(&left(t)));
    let adjacent = |s: &Segment, t: &Segment| {
        let ((ks, is), (kt, it)) = (s.at, t.at);
        let n = lengths[ks];
        ks == kt && (is.abs_diff(it) <= 1 || is.abs_diff(it) == n - 1)
    };
    for (i, s) in segments.iter().enumerate() {
        for t in segments[i + 1..].iter().take_while(|t| left(t) <= right(s)) {
            if adjacent(s, t) || !segments_meet(s.a, s.b, t.a, t.b) {
                continue;
            }
            let group = |e: usize| mesh.groups[mesh.elements[e].group].name.clone();
            let (x, y) = crossing_point(s, t);
            return Err(MeshError::CrossingBoundary {
                path: mesh.source.clone(),
                first: group(s.element),
                second: group(t.element),
                x,
                y,
            });
        }
    }
    Ok(())
}

/// Where two meeting segments meet (the intersection of their lines, or a shared point when
/// they are parallel), for the message.
fn crossing_point(s: &Segment, t: &Segment) -> (f64, f64) {
    let d1 = [s.b[0] - s.a[0], s.b[1] - s.a[1]];
    let d2 = [t.b[0] - t.a[0], t.b[1] - t.a[1]];
    let den = d1[0] * d2[1] - d1[1] * d2[0];
    if den != 0.0 {
        let u = ((t.a[0] - s.a[0]) * d2[1] - (t.a[1] - s.a[1]) * d2[0]) / den;
        let u = u.clamp(0.0, 1.0);
        (s.a[0] + u * d1[0], s.a[1] + u * d1[1])
    } else {
        (t.a[0], t.a[1])
    }
}

/// Whether the closed segments pq and rs share a point (orientation tests; a touch counts).
fn segments_meet(p: [f64; 2], q: [f64; 2], r: [f64; 2], s: [f64; 2]) -> bool {
    let orient = |a: [f64; 2], b: [f64; 2], c: [f64; 2]| {
        let v = (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]);
        if v > 0.0 {
            1
        } else if v < 0.0 {
            -1
        } else {
            0
        }
    };
    let on = |a: [f64; 2], b: [f64; 2], c: [f64; 2]| {
        c[0] >= a[0].min(b[0]) && c[0] <= a[0].max(b[0]) && c[1] >= a[1].min(b[1]) && c[1] <= a[1].max(b[1])
    };
    let (o1, o2, o3, o4) = (orient(p, q, r), orient(p, q, s), orient(r, s, p), orient(r, s, q));
    if o1 != o2 && o3 != o4 {
        return true;
    }
    (o1 == 0 && on(p, q, r)) || (o2 == 0 && on(p, q, s)) || (o3 == 0 && on(r, s, p)) || (o4 == 0 && on(r, s, q))
}

/// Area and nesting depth of every traced loop.
fn loop_geometry(mesh: &BoundaryMesh, traced: &[TracedLoop]) -> Vec<BoundaryLoop> {
    let polygons: Vec<Vec<[f64; 2]>> = traced.iter().map(|t| polygon(mesh, t)).collect();
    traced
        .iter()
        .enumerate()
        .map(|(k, t)| {
            let probe = polygons[k][0];
            let depth = polygons
                .iter()
                .enumerate()
                .filter(|&(j, poly)| j != k && point_in_polygon(probe, poly))
                .count();
            BoundaryLoop {
                elements: t.elements.clone(),
                signed_area: signed_area(mesh, t),
                depth,
            }
        })
        .collect()
}

/// Nodes of a loop in walking order (mid nodes included), as a closed polygon.
fn polygon(mesh: &BoundaryMesh, t: &TracedLoop) -> Vec<[f64; 2]> {
    let mut points = Vec::with_capacity(2 * t.elements.len());
    for (&e, &rev) in t.elements.iter().zip(&t.reversed) {
        let el = &mesh.elements[e];
        points.push(mesh.nodes[if rev { el.nodes[1] } else { el.nodes[0] }]);
        if el.nodes.len() == 3 {
            points.push(mesh.nodes[el.nodes[2]]);
        }
    }
    points
}

/// Signed area ½∮(x dy − y dx) over the exact element geometry (degree ≤ 3 in ξ for quadratic
/// elements, so the 2-point Gauss rule is exact).
fn signed_area(mesh: &BoundaryMesh, t: &TracedLoop) -> f64 {
    let (xi, w) = gauss_legendre(2);
    let mut area = 0.0;
    for (&e, &rev) in t.elements.iter().zip(&t.reversed) {
        let el = &mesh.elements[e];
        let sign = if rev { -1.0 } else { 1.0 };
        for (&s, &wk) in xi.iter().zip(&w) {
            let (x, dx) = element_point(mesh, el, s);
            area += sign * wk * 0.5 * (x[0] * dx[1] - x[1] * dx[0]);
        }
    }
    area
}

/// Position and derivative dx/dξ of an element at ξ (node order [end0, end1, mid]).
fn element_point(mesh: &BoundaryMesh, el: &super::BoundaryElement, xi: f64) -> ([f64; 2], [f64; 2]) {
    let (n, dn): (Vec<f64>, Vec<f64>) = if el.nodes.len() == 3 {
        (
            vec![0.5 * xi * (xi - 1.0), 0.5 * xi * (xi + 1.0), 1.0 - xi * xi],
            vec![xi - 0.5, xi + 0.5, -2.0 * xi],
        )
    } else {
        (vec![0.5 * (1.0 - xi), 0.5 * (1.0 + xi)], vec![-0.5, 0.5])
    };
    let mut x = [0.0; 2];
    let mut dx = [0.0; 2];
    for (a, &node) in el.nodes.iter().enumerate() {
        for k in 0..2 {
            x[k] += n[a] * mesh.nodes[node][k];
            dx[k] += dn[a] * mesh.nodes[node][k];
        }
    }
    (x, dx)
}

/// Even–odd ray casting: whether `p` lies inside the closed polygon `poly`.
fn point_in_polygon(p: [f64; 2], poly: &[[f64; 2]]) -> bool {
    let mut inside = false;
    let n = poly.len();
    for i in 0..n {
        let a = poly[i];
        let b = poly[(i + 1) % n];
        if (a[1] > p[1]) != (b[1] > p[1]) {
            let x_cross = a[0] + (p[1] - a[1]) / (b[1] - a[1]) * (b[0] - a[0]);
            if p[0] < x_cross {
                inside = !inside;
            }
        }
    }
    inside
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::mesh::{BoundaryElement, PhysicalGroup};

    /// Unit square of four line2 elements, in the given node order per element.
    fn square(elements: [[usize; 2]; 4]) -> BoundaryMesh {
        BoundaryMesh::new(
            vec![[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0]],
            elements
                .iter()
                .map(|n| BoundaryElement {
                    nodes: n.to_vec(),
                    group: 0,
                })
                .collect(),
            vec![PhysicalGroup {
                tag: 1,
                name: "free".into(),
            }],
            "square",
        )
    }

    #[test]
    fn a_clockwise_square_with_a_mixed_element_is_turned_counter_clockwise() {
        let mut mesh = square([[1, 0], [2, 1], [2, 3], [0, 3]]);
        let notices = validate_and_orient(&mut mesh).unwrap();
        assert_eq!(notices.len(), 1, "{notices:?}");
        let loops = boundary_loops(&mesh).unwrap();
        assert_eq!(loops.len(), 1);
        assert!((loops[0].signed_area - 1.0).abs() < 1e-14);
        assert_eq!(loops[0].depth, 0);
        // Already oriented: nothing more to do.
        assert!(validate_and_orient(&mut mesh).unwrap().is_empty());
    }

    #[test]
    fn open_and_branching_boundaries_are_reported() {
        let mut mesh = square([[0, 1], [1, 2], [2, 3], [3, 0]]);
        mesh.elements.pop();
        let err = validate_and_orient(&mut mesh).unwrap_err();
        assert!(matches!(err, MeshError::OpenLoop { .. }), "{err}");
        let mut mesh = square([[0, 1], [1, 2], [2, 3], [3, 0]]);
        mesh.elements.push(BoundaryElement {
            nodes: vec![0, 2],
            group: 0,
        });
        let err = validate_and_orient(&mut mesh).unwrap_err();
        assert!(matches!(err, MeshError::BranchingBoundary { count: 3, .. }), "{err}");
    }

    #[test]
    fn zero_length_and_distorted_elements_are_reported() {
        let mut mesh = square([[0, 1], [1, 2], [2, 3], [3, 0]]);
        mesh.nodes.push([0.0, 0.0]);
        mesh.elements[3].nodes[1] = 4;
        mesh.elements.push(BoundaryElement {
            nodes: vec![4, 0],
            group: 0,
        });
        let err = validate_and_orient(&mut mesh).unwrap_err();
        assert!(
            matches!(
                err,
                MeshError::BadElement {
                    element: 4,
                    defect: ElementDefect::ZeroLength,
                    ..
                }
            ),
            "{err}"
        );

        let mut mesh = square([[0, 1], [1, 2], [2, 3], [3, 0]]);
        mesh.nodes.push([0.9, 0.0]);
        mesh.elements[0].nodes.push(4);
        let err = validate_and_orient(&mut mesh).unwrap_err();
        assert!(
            matches!(
                err,
                MeshError::BadElement {
                    element: 0,
                    defect: ElementDefect::Distorted,
                    ..
                }
            ),
            "{err}"
        );
    }

    #[test]
    fn point_in_polygon_handles_a_concave_outline() {
        let l_shape = [[0.0, 0.0], [2.0, 0.0], [2.0, 1.0], [1.0, 1.0], [1.0, 2.0], [0.0, 2.0]];
        assert!(point_in_polygon([0.5, 1.5], &l_shape));
        assert!(!point_in_polygon([1.5, 1.5], &l_shape));
        assert!(point_in_polygon([1.5, 0.5], &l_shape));
    }
}
