//! A `bem` body's mesh refined with its contact grid: each contact element cut where the cells
//! of the error-controlled grid end, the new nodes on the element's own quadratic geometry.
//!
//! A contact element spans one start element of the grid. Its pieces are new quadratic
//! elements whose end and mid nodes lie on the original element's curve at the x of the
//! cells' ends and mid points, so that the contact grid the refined mesh gives is the cells'
//! grid node for node, for the body the grid was built from and for a matching body across
//! the contact alike (the x of a point fixes it on either curve). Neighbouring pieces differ in
//! length by at most 2 ([`super::cells`]).
//!
//! The rest of the mesh is unchanged but for the two elements that meet the contact group at
//! its ends: where the grid's end element was cut much shorter than its neighbour outside the
//! group, that neighbour is halved towards the common node ([`graded_transition`]), so the
//! element lengths also change by at most 2 from the contact segment into the rest of the mesh
//! (or by no more than the start mesh had them change there).

use super::cells::{DyadicGrid, MAX_NEIGHBOUR_RATIO};
use crate::bem::element::ElementGeometry;
use crate::mesh::{BoundaryElement, BoundaryMesh};
use crate::scene::{BemSetup, LoadedMesh};
use std::collections::HashMap;

/// The setup with its contact elements cut along the cells of `cells` (module docs).
pub fn refined_setup(setup: &BemSetup, cells: &DyadicGrid) -> BemSetup {
    BemSetup {
        mesh: LoadedMesh {
            mesh: refined_mesh(&setup.mesh, cells),
            ..setup.mesh.clone()
        },
        ..setup.clone()
    }
}

/// The mesh with its contact elements cut along the cells of `cells` and their neighbours
/// graded into the rest (module docs). A contact element that spans no start element of the
/// grid is kept as it is.
pub fn refined_mesh(loaded: &LoadedMesh, cells: &DyadicGrid) -> BoundaryMesh {
    let mesh = &loaded.mesh;
    let group = loaded.contact_group;
    let root = cells.root();
    let tol = 1e-9 * mesh.size();
    // The cells of each start element: (x at the left end, at the right end, at the mid point).
    let mut pieces: Vec<Vec<[f64; 3]>> = vec![Vec::new(); root.n_elements()];
    for &c in cells.cells() {
        pieces[c.root].push([cells.end(c, false), cells.end(c, true), cells.mid(c)]);
    }
    let mut nodes = mesh.nodes.clone();
    let mut elements = Vec::with_capacity(mesh.elements.len());
    for (e, el) in mesh.elements.iter().enumerate() {
        if el.group != group {
            elements.push(el.clone());
            continue;
        }
        let geom = ElementGeometry::from_mesh(mesh, e);
        let (xa, xb) = (geom.nodes[0][0], geom.nodes[1][0]);
        let (lo, hi) = (xa.min(xb), xa.max(xb));
        let spanned = (0..root.n_elements())
            .find(|&r| (root.edges[r] - lo).abs() <= tol && (root.edges[r + 1] - hi).abs() <= tol);
        let Some(r) = spanned.filter(|&r| pieces[r].len() > 1) else {
            elements.push(el.clone());
            continue;
        };
        let increasing = xa <= xb;
        let (at_lo, at_hi) = if increasing {
            (el.nodes[0], el.nodes[1])
        } else {
            (el.nodes[1], el.nodes[0])
        };
        // The cut nodes in increasing x: the element's own end nodes at the ends.
        let p = &pieces[r];
        let mut cuts = vec![at_lo];
        for piece in &p[..p.len() - 1] {
            cuts.push(point_at_x(&geom, piece[1], &mut nodes));
        }
        cuts.push(at_hi);
        let mut children: Vec<BoundaryElement> = p
            .iter()
            .enumerate()
            .map(|(k, piece)| BoundaryElement {
                nodes: vec![cuts[k], cuts[k + 1], point_at_x(&geom, piece[2], &mut nodes)],
                group,
            })
            .collect();
        // Keep the element's walking direction (the orientation of its loop).
        if !increasing {
            children.reverse();
            for c in &mut children {
                c.nodes.swap(0, 1);
            }
        }
        elements.extend(children);
    }
    let elements = graded_transitions(mesh, &mut nodes, elements, group);
    BoundaryMesh::new(nodes, elements, mesh.groups.clone(), mesh.source.clone())
}

/// `elements` (the cut mesh's, on `nodes`) with every element outside contact group `group`
/// that shares an end node with it graded towards that node ([`graded_transition`]). `original`
/// is the mesh before the cuts: the contact element there at the common node sets the length
/// ratio the start mesh already had, which is kept where it exceeds [`MAX_NEIGHBOUR_RATIO`].
fn graded_transitions(
    original: &BoundaryMesh,
    nodes: &mut Vec<[f64; 2]>,
    elements: Vec<BoundaryElement>,
    group: usize,
) -> Vec<BoundaryElement> {
    let cut_ends = contact_end_lengths(&elements, nodes, group);
    let uncut_ends = contact_end_lengths(&original.elements, &original.nodes, group);
    let mut out = Vec::with_capacity(elements.len());
    for el in &elements {
        let touches = |v: usize| el.group != group && cut_ends.contains_key(&v);
        let shared = match (touches(el.nodes[0]), touches(el.nodes[1])) {
            (true, false) => el.nodes[0],
            (false, true) => el.nodes[1],
            // Not next to the contact group, or between two of its ends: kept as it is.
            _ => {
                out.push(el.clone());
                continue;
            }
        };
        let cut = cut_ends[&shared];
        let uncut = uncut_ends.get(&shared).copied().unwrap_or(cut);
        let own = ElementGeometry::of_element(el, nodes).length();
        // 10 % slack, as in the grid's balance: equal pieces in ξ are nearly equal in length.
        let allowed = (MAX_NEIGHBOUR_RATIO * 1.1).max(own / uncut);
        let halvings = (own / (cut * allowed)).log2().ceil().max(0.0) as u32;
        out.extend(graded_transition(el, shared == el.nodes[0], halvings, nodes));
    }
    out
}

/// The length of the contact group's element at each of its end nodes [length]; a node between
/// two contact elements gets the shorter (only the group's two ends meet other elements).
fn contact_end_lengths(elements: &[BoundaryElement], nodes: &[[f64; 2]], group: usize) -> HashMap<usize, f64> {
    let mut ends = HashMap::new();
    for el in elements.iter().filter(|e| e.group == group) {
        let l = ElementGeometry::of_element(el, nodes).length();
        for v in [el.nodes[0], el.nodes[1]] {
            let e = ends.entry(v).or_insert(l);
            *e = f64::min(*e, l);
        }
    }
    ends
}

/// `el` halved `halvings` times towards its start (`towards_start`) or its end, each time the
/// half at that end: `halvings + 1` pieces on the element's own curve, in its walking direction,
/// each at most [`MAX_NEIGHBOUR_RATIO`] times its neighbour (in ξ, exactly).
fn graded_transition(
    el: &BoundaryElement,
    towards_start: bool,
    halvings: u32,
    nodes: &mut Vec<[f64; 2]>,
) -> Vec<BoundaryElement> {
    if halvings == 0 {
        return vec![el.clone()];
    }
    let geom = ElementGeometry::of_element(el, nodes);
    // Fractions of the element from the graded end: 0, 2^-halvings, …, 1/2, 1.
    let mut fractions = vec![0.0];
    fractions.extend((0..halvings).rev().map(|k| 0.5f64.powi(k as i32 + 1)));
    fractions.push(1.0);
    let mut xi: Vec<f64> = fractions
        .iter()
        .map(|&t| if towards_start { -1.0 + 2.0 * t } else { 1.0 - 2.0 * t })
        .collect();
    if !towards_start {
        xi.reverse();
    }
    let mut ends = vec![el.nodes[0]];
    for &x in &xi[1..xi.len() - 1] {
        nodes.push(geom.point(x));
        ends.push(nodes.len() - 1);
    }
    ends.push(el.nodes[1]);
    (0..xi.len() - 1)
        .map(|k| {
            let mut piece = vec![ends[k], ends[k + 1]];
            if el.nodes.len() == 3 {
                nodes.push(geom.point(0.5 * (xi[k] + xi[k + 1])));
                piece.push(nodes.len() - 1);
            }
            BoundaryElement {
                nodes: piece,
                group: el.group,
            }
        })
        .collect()
}

/// A new node on the element's curve at abscissa x; its index.
fn point_at_x(geom: &ElementGeometry, x: f64, nodes: &mut Vec<[f64; 2]>) -> usize {
    let (xa, xb) = (geom.nodes[0][0], geom.nodes[1][0]);
    // x lies inside the element's x-range; the linear guess only guards round-off at its ends.
    let xi = geom
        .parameter_at_x(x)
        .unwrap_or_else(|| (2.0 * (x - xa) / (xb - xa) - 1.0).clamp(-1.0, 1.0));
    nodes.push(geom.point(xi));
    nodes.len() - 1
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::adapt::cells::Action;
    use crate::mesh::{boundary_loops, validate_and_orient};

    /// The shipped roller of radius 100 on a shaft of radius 10 (meshes/roller_r100_shaft10_A.msh):
    /// 17 contact elements on |x| ≤ 1.25, its free arc graded from there at ratio ≤ 1.04.
    fn roller() -> LoadedMesh {
        let path = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("meshes/roller_r100_shaft10_A.msh");
        let (mut mesh, _) = crate::mesh::load(&path).unwrap();
        validate_and_orient(&mut mesh).unwrap();
        let contact_group = mesh.group_index("contact").unwrap();
        LoadedMesh {
            path,
            mesh,
            notices: Vec::new(),
            contact_group,
        }
    }

    /// Length ratios of consecutive elements along every loop of `mesh`, largest first.
    fn neighbour_ratios(mesh: &BoundaryMesh) -> Vec<(f64, usize, usize)> {
        let length = |e: usize| ElementGeometry::from_mesh(mesh, e).length();
        let mut ratios = Vec::new();
        for lp in boundary_loops(mesh).unwrap() {
            let els = &lp.elements;
            for k in 0..els.len() {
                let (a, b) = (els[k], els[(k + 1) % els.len()]);
                let (la, lb) = (length(a), length(b));
                ratios.push((la.max(lb) / la.min(lb), a, b));
            }
        }
        ratios.sort_by(|x, y| y.0.total_cmp(&x.0));
        ratios
    }

    /// A grid graded 12 times towards each end of the contact segment (singular points at
    /// its ends) cuts the end contact elements to 1/4096 of their length; the free elements
    /// next to them are halved towards the contact until no two neighbours anywhere differ
    /// by more than the grid's 2 (+10 % slack), on the circle they were on, without a change
    /// of the boundary's length or of the mesh away from the contact's ends.
    #[test]
    fn cut_contact_ends_grade_their_neighbours_into_the_mesh() {
        let loaded = roller();
        let start = DyadicGrid::new(&loaded.contact_grid());
        let n = start.len();
        let (lo, hi) = (start.root().edges[0], start.root().edges[n]);
        let mut action = vec![Action::Keep; n];
        action[0] = Action::GradeTowards(lo, 12);
        action[n - 1] = Action::GradeTowards(hi, 12);
        let cells = start.refined(&action);
        let before = &loaded.mesh;
        let start_ratio = neighbour_ratios(before)[0].0;
        let after = refined_mesh(&loaded, &cells);

        let mut checked = after.clone();
        validate_and_orient(&mut checked).expect("the refined mesh is a valid boundary");
        let worst = neighbour_ratios(&after)[0];
        assert!(
            worst.0 <= (MAX_NEIGHBOUR_RATIO * 1.1).max(start_ratio),
            "elements {} and {} differ by {:.2} (start mesh: {start_ratio:.2})",
            worst.1,
            worst.2,
            worst.0
        );
        // Without the transition the worst ratio is the cut: the neighbour over 1/4096 of a
        // contact element (the test would not see a missing transition otherwise).
        let free = after.group_index("free").unwrap();
        let free_before = before.count_in_group(free);
        let free_after = after.count_in_group(free);
        assert!(
            free_after >= free_before + 2 * 10,
            "{free_before} -> {free_after} free elements"
        );
        // Every node of the free arc stays on the roller's circle (centre (0, 100), R 100).
        for el in after.elements.iter().filter(|e| e.group == free) {
            for &v in &el.nodes {
                let [x, y] = after.nodes[v];
                let r = (x * x + (y - 100.0).powi(2)).sqrt();
                assert!((r - 100.0).abs() < 1e-3, "node {v} at radius {r}");
            }
        }
        // The boundary's length is the same (the pieces lie on the elements' own curves; the
        // quadratic arcs through the new mid nodes differ from the original ones at O(h⁴)).
        let total = |m: &BoundaryMesh| -> f64 {
            (0..m.elements.len())
                .map(|e| ElementGeometry::from_mesh(m, e).length())
                .sum()
        };
        let (l0, l1) = (total(before), total(&after));
        assert!((l1 - l0).abs() < 1e-9 * l0, "length {l0} -> {l1}");
    }

    /// A grid that refines only inside the contact leaves every element outside the contact
    /// group as it was: the transition adds nothing where the cut is within the grid's ratio.
    #[test]
    fn interior_refinement_leaves_the_rest_of_the_mesh_alone() {
        let loaded = roller();
        let start = DyadicGrid::new(&loaded.contact_grid());
        let n = start.len();
        let mut action = vec![Action::Keep; n];
        action[n / 2] = Action::Split(3);
        let after = refined_mesh(&loaded, &start.refined(&action));
        let outside = |m: &BoundaryMesh| -> Vec<Vec<[f64; 2]>> {
            m.elements
                .iter()
                .filter(|e| e.group != loaded.contact_group)
                .map(|e| e.nodes.iter().map(|&v| m.nodes[v]).collect())
                .collect()
        };
        assert_eq!(outside(&after), outside(&loaded.mesh));
    }
}
