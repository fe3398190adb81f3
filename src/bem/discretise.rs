//! Field nodes (the BEM unknowns' locations) of an oriented boundary mesh.
//!
//! Every element carries three field nodes (start, end, mid; see [`super::element`]). At the
//! junction of two elements the end nodes are **shared** (continuous interpolation) only if
//! the junction is smooth (tangents within [`super::BemOptions::corner_angle_deg`]), both
//! elements belong to the same group, and that group is not a contact group. Otherwise both
//! ends are moved inside to ∓2/3 (partially discontinuous elements): at a corner the traction
//! is discontinuous and the normal undefined, and where the boundary condition changes the
//! known and unknown components change, so no node may sit there. Contact groups use fully
//! discontinuous elements (González & Abascal §5).
//!
//! Consequently every field node belongs to exactly one group, and has a well defined normal.

use super::element::{ElementGeometry, FieldInterpolation};
use crate::mesh::BoundaryMesh;

/// One field node: a collocation point carrying (u_x, u_y, t_x, t_y).
#[derive(Debug, Clone, PartialEq)]
pub struct FieldNode {
    /// Position [length].
    pub position: [f64; 2],
    /// Unit normal out of the material (averaged over the two elements at a shared node).
    pub normal: [f64; 2],
    /// Physical group (index into the mesh's groups).
    pub group: usize,
    /// An element carrying the node and its local index there (0 start, 1 end, 2 mid).
    pub element: (usize, usize),
}

/// The field nodes of a mesh and the element → node map.
#[derive(Debug, Clone)]
pub struct Discretisation {
    /// Geometry of each element.
    pub geometry: Vec<ElementGeometry>,
    /// Field interpolation of each element.
    pub interpolation: Vec<FieldInterpolation>,
    /// Global field-node indices of each element, order (start, end, mid).
    pub element_nodes: Vec<[usize; 3]>,
    /// The field nodes.
    pub nodes: Vec<FieldNode>,
}

impl Discretisation {
    /// Field nodes of an oriented `mesh` (see [`crate::mesh::validate_and_orient`]).
    /// `contact_group[g]` marks the groups with fully discontinuous elements;
    /// `corner_angle` [rad] is the largest tangent jump of a smooth junction.
    pub fn new(mesh: &BoundaryMesh, contact_group: &[bool], corner_angle: f64) -> Self {
        let ne = mesh.elements.len();
        let geometry: Vec<ElementGeometry> = (0..ne).map(|e| ElementGeometry::from_mesh(mesh, e)).collect();
        // In an oriented mesh each end node has one element ending and one starting there.
        let mut incoming = vec![usize::MAX; mesh.nodes.len()];
        let mut outgoing = vec![usize::MAX; mesh.nodes.len()];
        for (e, el) in mesh.elements.iter().enumerate() {
            incoming[el.nodes[1]] = e;
            outgoing[el.nodes[0]] = e;
        }
        let cos_corner = corner_angle.cos();
        let smooth = |before: usize, after: usize| -> bool {
            let (gb, ga) = (mesh.elements[before].group, mesh.elements[after].group);
            if gb != ga || contact_group[gb] {
                return false;
            }
            let t1 = geometry[before].tangent(1.0);
            let t2 = geometry[after].tangent(-1.0);
            let cos = (t1[0] * t2[0] + t1[1] * t2[1]) / (t1[0].hypot(t1[1]) * t2[0].hypot(t2[1]));
            cos >= cos_corner
        };
        let interpolation: Vec<FieldInterpolation> = (0..ne)
            .map(|e| {
                let el = &mesh.elements[e];
                if contact_group[el.group] {
                    return FieldInterpolation::DISCONTINUOUS;
                }
                let previous = incoming[el.nodes[0]];
                let next = outgoing[el.nodes[1]];
                let start_shared = previous != usize::MAX && smooth(previous, e);
                let end_shared = next != usize::MAX && smooth(e, next);
                FieldInterpolation::with_discontinuous_ends(!start_shared, !end_shared)
            })
            .collect();

        let mut nodes: Vec<FieldNode> = Vec::new();
        let mut shared_at_mesh_node = vec![usize::MAX; mesh.nodes.len()];
        let mut element_nodes = Vec::with_capacity(ne);
        for e in 0..ne {
            let el = &mesh.elements[e];
            let f = interpolation[e];
            let xs = f.node_coordinates();
            let mut ids = [0usize; 3];
            for (local, id) in ids.iter_mut().enumerate() {
                let shared_mesh_node = match local {
                    0 if f.start_is_shared() => Some(el.nodes[0]),
                    1 if f.end_is_shared() => Some(el.nodes[1]),
                    _ => None,
                };
                let normal = geometry[e].normal(xs[local]);
                if let Some(m) = shared_mesh_node {
                    if shared_at_mesh_node[m] != usize::MAX {
                        // Second element at a smooth junction: average the two normals.
                        let k = shared_at_mesh_node[m];
                        let n = &mut nodes[k].normal;
                        let (sx, sy) = (n[0] + normal[0], n[1] + normal[1]);
                        let len = sx.hypot(sy);
                        *n = [sx / len, sy / len];
                        *id = k;
                        continue;
                    }
                    shared_at_mesh_node[m] = nodes.len();
                }
                *id = nodes.len();
                nodes.push(FieldNode {
                    position: geometry[e].point(xs[local]),
                    normal,
                    group: el.group,
                    element: (e, local),
                });
            }
            element_nodes.push(ids);
        }
        Self {
            geometry,
            interpolation,
            element_nodes,
            nodes,
        }
    }

    /// Number of field nodes N (the system has 2N equations).
    pub fn n_nodes(&self) -> usize {
        self.nodes.len()
    }

    /// Field nodes of group `group`, in element order.
    pub fn nodes_of_group(&self, group: usize) -> Vec<usize> {
        (0..self.nodes.len())
            .filter(|&k| self.nodes[k].group == group)
            .collect()
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::mesh::build::rectangle;
    use crate::mesh::validate_and_orient;

    #[test]
    fn rectangle_corners_and_group_changes_get_discontinuous_ends() {
        // Bottom "a" (2 elements), right "b" (1), top "a" (2), left "a" (1). Sides of the
        // same group meet at corners, so every corner has moved nodes; inside a side the
        // elements share their end nodes.
        let mut mesh = rectangle([0.0, 0.0], 2.0, 1.0, [2, 1, 2, 1], ["a", "b", "a", "a"], true);
        validate_and_orient(&mut mesh).unwrap();
        let d = Discretisation::new(&mesh, &[false, false], 15f64.to_radians());
        // 6 elements × 3 nodes − 2 shared junctions (inside bottom and top).
        assert_eq!(d.n_nodes(), 16);
        let corners = [[0.0, 0.0], [2.0, 0.0], [2.0, 1.0], [0.0, 1.0]];
        for n in &d.nodes {
            for c in corners {
                assert!((n.position[0] - c[0]).hypot(n.position[1] - c[1]) > 1e-9);
            }
        }
        // With the contact flag every element is discontinuous.
        let d = Discretisation::new(&mesh, &[true, false], 15f64.to_radians());
        assert_eq!(d.n_nodes(), 18);
    }
}
