//! A boundary mesh with every element outside one group bisected: the body's own mesh refined
//! once away from the contact, to estimate what its coarseness costs the contact's solution
//! (`crate::adapt`'s body-mesh estimate).
//!
//! Each element is halved at its parameter ξ = 0 (its mid node, which becomes an end node of
//! both halves); a quadratic element's halves take new mid nodes at ξ = ±½ on the element's
//! own quadratic curve, as [`super::cuts`] places its cut nodes, so the bisected mesh has the
//! same geometry and only its boundary fields gain resolution. A linear element's halves are
//! linear, the new end node at the mid point. Nodes shared between elements stay shared, so
//! the loops stay closed and keep their orientation.

use super::geometry::ElementGeometry;
use super::{BoundaryElement, BoundaryMesh};

/// `mesh` with every element outside group `keep` bisected (module docs); the elements of
/// `keep` (the contact group) are unchanged, in order, so its contact grid is the same.
pub fn bisect_outside_group(mesh: &BoundaryMesh, keep: usize) -> BoundaryMesh {
    let mut nodes = mesh.nodes.clone();
    let mut elements = Vec::with_capacity(2 * mesh.elements.len());
    for (e, el) in mesh.elements.iter().enumerate() {
        if el.group == keep {
            elements.push(el.clone());
            continue;
        }
        let geom = ElementGeometry::from_mesh(mesh, e);
        let (a, b) = el.ends();
        let mid = if el.nodes.len() == 3 {
            el.nodes[2]
        } else {
            nodes.push(geom.point(0.0));
            nodes.len() - 1
        };
        let halves = [(a, mid, -0.5), (mid, b, 0.5)];
        for (start, end, centre) in halves {
            let mut n = vec![start, end];
            if el.nodes.len() == 3 {
                nodes.push(geom.point(centre));
                n.push(nodes.len() - 1);
            }
            elements.push(BoundaryElement {
                nodes: n,
                group: el.group,
            });
        }
    }
    BoundaryMesh::new(nodes, elements, mesh.groups.clone(), mesh.source.clone())
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::mesh::build::MeshBuilder;

    /// A quadratic circle of 12 elements bisected: 24 elements whose every node lies on the
    /// old elements' quadratic curves, within the quadratic's own distance from the circle,
    /// and whose total length is the old one's (the same curve, cut in two).
    #[test]
    fn a_quadratic_circle_is_halved_on_its_own_curves() {
        let mut b = MeshBuilder::new(true, "circle");
        b.circle([0.0, 0.0], 1.0, 12, "free");
        let mesh = b.finish();
        let out = bisect_outside_group(&mesh, usize::MAX);
        assert_eq!(out.elements.len(), 24);
        let length = |m: &BoundaryMesh| -> f64 {
            (0..m.elements.len())
                .map(|e| ElementGeometry::from_mesh(m, e).length())
                .sum()
        };
        assert!((length(&out) - length(&mesh)).abs() < 1e-12 * length(&mesh));
        // The quadratic's own departure from a 30° arc (2.2e-4 R at ξ = ±½) bounds the new
        // nodes' distance from the circle; the chord's midpoint of a half (1 − cos 7.5° =
        // 8.6e-3 R) would not meet it.
        for p in &out.nodes {
            assert!(((p[0] * p[0] + p[1] * p[1]).sqrt() - 1.0).abs() < 5e-4, "{p:?}");
        }
        // Consecutive halves share their nodes: the loop stays closed.
        for w in out.elements.windows(2) {
            assert_eq!(w[0].nodes[1], w[1].nodes[0]);
        }
    }

    /// The kept group's elements stay as they were.
    #[test]
    fn the_kept_group_is_unchanged() {
        let mut b = MeshBuilder::new(true, "circle");
        b.circle([0.0, 0.0], 1.0, 8, "free");
        let mesh = b.finish();
        let group = mesh.elements[0].group;
        let out = bisect_outside_group(&mesh, group);
        assert_eq!(out, mesh);
    }
}
