//! A boundary mesh with the elements outside one group merged in pairs: the body's own mesh
//! coarsened once away from the contact, the cheap half of the body-mesh estimate
//! (`crate::adapt`'s body-mesh screen). Where [`super::bisect`] doubles the unknowns outside
//! the contact to see what a finer mesh changes, this halves them: the difference between the
//! mesh and its coarsening is (2^k − 1) times the mesh's own error for an error falling as h^k,
//! at a fraction of the bisected body's assembly.
//!
//! Neighbouring elements of the same group are paired along each chain of the boundary (the
//! elements that share a node, walked in the loop's direction). A pair (a → b, b → c) becomes
//! one element a → c; a quadratic pair's new mid node is the point halfway along the pair's
//! arc, on the old elements' own curves, so the merged element interpolates the old geometry at
//! its ends and middle (placing it at the shared node b instead would make a quarter-point
//! element of the coarse roller's pairs, whose lengths differ by 3, and a singular Jacobian).
//! An odd chain keeps one element as it is, near its middle (away from the contact, where a
//! chain starts at a contact end).

use super::geometry::ElementGeometry;
use super::{BoundaryElement, BoundaryMesh};
use std::collections::HashMap;

/// `mesh` with the elements outside group `keep` merged in pairs (module docs), or None when no
/// two neighbouring elements of one group lie outside `keep`. The elements of `keep` (the
/// contact group) are unchanged, in order, and unused nodes are dropped.
pub fn coarsen_outside_group(mesh: &BoundaryMesh, keep: usize) -> Option<BoundaryMesh> {
    let mut nodes = mesh.nodes.clone();
    let mut merged: Vec<Option<BoundaryElement>> = mesh.elements.iter().cloned().map(Some).collect();
    let mut any = false;
    for chain in chains(mesh, keep) {
        // An odd chain keeps one element: the even index nearest its middle, so that both
        // sides of it pair up.
        let skip = (chain.len() % 2 == 1).then_some((chain.len() / 2) & !1);
        let mut i = 0;
        while i + 1 < chain.len() {
            if Some(i) == skip {
                i += 1;
                continue;
            }
            let (e1, e2) = (chain[i], chain[i + 1]);
            merged[e1] = Some(merge_pair(mesh, e1, e2, &mut nodes));
            merged[e2] = None;
            any = true;
            i += 2;
        }
    }
    if !any {
        return None;
    }
    Some(compacted(nodes, merged.into_iter().flatten().collect(), mesh))
}

/// The chains of elements outside `keep`: maximal runs of elements of one group, each starting
/// where the one before ends, in walking order. A closed loop is one chain starting anywhere.
fn chains(mesh: &BoundaryMesh, keep: usize) -> Vec<Vec<usize>> {
    let free = |e: usize| mesh.elements[e].group != keep;
    // (start node, group) → element; a node where two elements of one group start is not a
    // chain (a mesh that does not pass validation), and the later wins: harmless, pairs only
    // join elements that do share a node.
    let starting: HashMap<(usize, usize), usize> = (0..mesh.elements.len())
        .filter(|&e| free(e))
        .map(|e| ((mesh.elements[e].ends().0, mesh.elements[e].group), e))
        .collect();
    let next = |e: usize| {
        let el = &mesh.elements[e];
        starting.get(&(el.ends().1, el.group)).copied()
    };
    let has_previous: Vec<bool> = {
        let mut p = vec![false; mesh.elements.len()];
        for e in (0..mesh.elements.len()).filter(|&e| free(e)) {
            if let Some(n) = next(e) {
                p[n] = true;
            }
        }
        p
    };
    let mut seen = vec![false; mesh.elements.len()];
    let mut out = Vec::new();
    // Open chains first (from an element nothing leads into), then the closed loops left.
    let starts: Vec<usize> = (0..mesh.elements.len())
        .filter(|&e| free(e) && !has_previous[e])
        .chain((0..mesh.elements.len()).filter(|&e| free(e)))
        .collect();
    for start in starts {
        if seen[start] {
            continue;
        }
        let mut chain = Vec::new();
        let mut e = start;
        while !seen[e] {
            seen[e] = true;
            chain.push(e);
            match next(e) {
                Some(n) => e = n,
                None => break,
            }
        }
        out.push(chain);
    }
    out
}

/// Elements `e1` (a → b) and `e2` (b → c) as one element a → c, its mid node (quadratic pairs)
/// appended to `nodes` halfway along the pair's arc.
fn merge_pair(mesh: &BoundaryMesh, e1: usize, e2: usize, nodes: &mut Vec<[f64; 2]>) -> BoundaryElement {
    let (first, second) = (&mesh.elements[e1], &mesh.elements[e2]);
    let (a, c) = (first.ends().0, second.ends().1);
    let mut merged = vec![a, c];
    if first.nodes.len() == 3 && second.nodes.len() == 3 {
        let (g1, g2) = (
            ElementGeometry::from_mesh(mesh, e1),
            ElementGeometry::from_mesh(mesh, e2),
        );
        let (l1, l2) = (g1.length(), g2.length());
        let half = 0.5 * (l1 + l2);
        let mid = if half <= l1 {
            g1.point(g1.parameter_at_length(half))
        } else {
            g2.point(g2.parameter_at_length(half - l1))
        };
        nodes.push(mid);
        merged.push(nodes.len() - 1);
    }
    BoundaryElement {
        nodes: merged,
        group: first.group,
    }
}

/// The mesh of `elements` with only the nodes they use, renumbered in order of first use.
fn compacted(nodes: Vec<[f64; 2]>, mut elements: Vec<BoundaryElement>, like: &BoundaryMesh) -> BoundaryMesh {
    let mut index = vec![usize::MAX; nodes.len()];
    let mut used = Vec::new();
    for el in &mut elements {
        for n in &mut el.nodes {
            if index[*n] == usize::MAX {
                index[*n] = used.len();
                used.push(nodes[*n]);
            }
            *n = index[*n];
        }
    }
    BoundaryMesh::new(used, elements, like.groups.clone(), like.source.clone())
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::mesh::bisect::bisect_outside_group;
    use crate::mesh::build::MeshBuilder;

    fn length(m: &BoundaryMesh) -> f64 {
        (0..m.elements.len())
            .map(|e| ElementGeometry::from_mesh(m, e).length())
            .sum()
    }

    /// A quadratic circle of 24 elements merged: 12 elements whose mid nodes lie on the
    /// circle (halfway along the old pairs' arcs, which lie within 1e-5 R of it) and whose
    /// length is that of the circle meshed with 12 elements directly.
    #[test]
    fn a_quadratic_circle_is_merged_in_pairs() {
        let mut b = MeshBuilder::new(true, "circle");
        b.circle([0.0, 0.0], 1.0, 24, "free");
        let mesh = b.finish();
        let out = coarsen_outside_group(&mesh, usize::MAX).expect("pairs to merge");
        assert_eq!(out.elements.len(), 12);
        assert_eq!(
            out.nodes.len(),
            24,
            "12 ends and 12 new mid nodes, the old ones dropped"
        );
        for p in &out.nodes {
            assert!(((p[0] * p[0] + p[1] * p[1]).sqrt() - 1.0).abs() < 1e-5, "{p:?}");
        }
        // The length of a circle meshed with 12 quadratic elements directly (4.8e-4 short of
        // 2π: the parabolas' own error), within the mid nodes' 1e-5 R off the circle.
        let mut b = MeshBuilder::new(true, "circle");
        b.circle([0.0, 0.0], 1.0, 12, "free");
        let direct = length(&b.finish());
        assert!((length(&out) - direct).abs() < 1e-5, "{} vs {direct}", length(&out));
        for w in out.elements.windows(2) {
            assert_eq!(w[0].nodes[1], w[1].nodes[0], "the loop stays closed");
        }
    }

    /// Coarsening undoes a bisection: the bisected circle merged again is the circle (the same
    /// ends, and mid nodes on the same quadratic curves at the same arc length).
    #[test]
    fn coarsening_a_bisection_gives_the_mesh_back() {
        let mut b = MeshBuilder::new(true, "circle");
        b.circle([0.0, 0.0], 1.0, 10, "free");
        let mesh = b.finish();
        let back = coarsen_outside_group(&bisect_outside_group(&mesh, usize::MAX), usize::MAX).expect("pairs");
        assert_eq!(back.elements.len(), mesh.elements.len());
        let g = |m: &BoundaryMesh, e| ElementGeometry::from_mesh(m, e).nodes;
        // The loop may start at another element: match by the start node.
        for e in 0..mesh.elements.len() {
            let start = g(&mesh, e)[0];
            let f = (0..back.elements.len())
                .find(|&f| {
                    let s = g(&back, f)[0];
                    (s[0] - start[0]).hypot(s[1] - start[1]) < 1e-14
                })
                .expect("the same start node");
            for (p, q) in g(&mesh, e).iter().zip(g(&back, f)) {
                assert!((p[0] - q[0]).hypot(p[1] - q[1]) < 1e-12, "{p:?} vs {q:?}");
            }
        }
    }

    /// The kept group's elements stay, an odd chain keeps one element, and groups are never
    /// merged across.
    #[test]
    fn the_contact_stays_and_odd_chains_keep_their_middle() {
        let mut b = MeshBuilder::new(true, "square");
        b.move_to([0.0, 0.0]);
        b.line_to([1.0, 0.0], 2, "contact");
        b.line_to([1.0, 1.0], 3, "free");
        b.line_to([0.0, 1.0], 2, "shaft");
        b.close(2, "free");
        let mesh = b.finish();
        let contact = mesh.group_index("contact").unwrap();
        let out = coarsen_outside_group(&mesh, contact).expect("pairs");
        let count = |m: &BoundaryMesh, g: &str| {
            let gi = m.group_index(g).unwrap();
            m.elements.iter().filter(|e| e.group == gi).count()
        };
        assert_eq!(count(&out, "contact"), 2);
        assert_eq!(count(&out, "shaft"), 1);
        // free: 3 on one side (one kept, two merged: 2 elements) and 2 on the other (1).
        assert_eq!(count(&out, "free"), 3);
        assert!((length(&out) - 4.0).abs() < 1e-12);
    }
}
