//! A boundary mesh read for a body of the scene, with what the scene needs from its contact
//! group: the x-range, the fitted profile radius and the contact grid of its own elements.

use super::geometry::ElementGeometry;
use super::BoundaryMesh;
use crate::grid::{ContactGrid, ElementKind};
use std::path::PathBuf;

/// A boundary mesh loaded for a `bem` body.
#[derive(Debug, Clone)]
pub struct LoadedMesh {
    /// The mesh file (or `<procedural …>` for a mesh built in memory).
    pub path: PathBuf,
    /// The checked and oriented mesh.
    pub mesh: BoundaryMesh,
    /// One notice per loop that was turned round.
    pub notices: Vec<String>,
    /// Index of the contact group.
    pub contact_group: usize,
}

impl LoadedMesh {
    /// `mesh` read from `path` (or built in memory under that label) with its contact group
    /// `contact` looked up by name, and the notices its checks gave; an error naming the
    /// mesh's groups when it has no group of that name.
    pub fn new(
        path: impl Into<PathBuf>,
        mesh: BoundaryMesh,
        notices: Vec<String>,
        contact: &str,
    ) -> Result<Self, super::MeshError> {
        let contact_group = mesh.group_index(contact)?;
        Ok(Self {
            path: path.into(),
            mesh,
            notices,
            contact_group,
        })
    }

    /// x-range [x_min, x_max] of the contact segment [length].
    pub fn contact_range(&self) -> [f64; 2] {
        let xs = self.contact_nodes().map(|p| p[0]);
        xs.fold([f64::INFINITY, f64::NEG_INFINITY], |[lo, hi], x| [lo.min(x), hi.max(x)])
    }

    /// The nodes of the contact group's elements [length].
    pub fn contact_nodes(&self) -> impl Iterator<Item = [f64; 2]> + '_ {
        self.mesh
            .elements
            .iter()
            .filter(|e| e.group == self.contact_group)
            .flat_map(|e| e.nodes.iter().map(|&n| self.mesh.nodes[n]))
    }

    /// Signed radius of the contact segment's profile [length]: the algebraic least-squares
    /// circle (Kåsa fit: x² + y² + Dx + Ey + F = 0), exact for nodes on a circle; positive when
    /// the circle's centre lies inside the body (a convex roller), negative when it lies outside
    /// (a concave bore: the segment's outward normal points towards the centre); infinite when
    /// the segment is straight (the fit's centre then runs away: |R| > 1e6 times the segment
    /// length).
    pub fn contact_radius(&self) -> f64 {
        match self.contact_circle() {
            Some((centre, r)) => r * self.convexity(centre),
            None => f64::INFINITY,
        }
    }

    /// Centre and (unsigned) radius of the circle fitted to the contact nodes, None when the
    /// segment is straight (see [`Self::contact_radius`]).
    pub fn contact_circle(&self) -> Option<([f64; 2], f64)> {
        let pts: Vec<[f64; 2]> = self.contact_nodes().collect();
        // Normal equations of min Σ (D x + E y + F + x² + y²)², centred for conditioning.
        let n = pts.len() as f64;
        let (cx, cy) = (
            pts.iter().map(|p| p[0]).sum::<f64>() / n,
            pts.iter().map(|p| p[1]).sum::<f64>() / n,
        );
        let mut a = nalgebra::Matrix3::<f64>::zeros();
        let mut b = nalgebra::Vector3::<f64>::zeros();
        for p in &pts {
            let (x, y) = (p[0] - cx, p[1] - cy);
            let row = nalgebra::Vector3::new(x, y, 1.0);
            a += row * row.transpose();
            b -= row * (x * x + y * y);
        }
        let [x0, x1] = self.contact_range();
        let span = (x1 - x0).max(f64::MIN_POSITIVE);
        let s = a.lu().solve(&b)?;
        let r2 = 0.25 * (s[0] * s[0] + s[1] * s[1]) - s[2];
        let r = r2.max(0.0).sqrt();
        (r.is_finite() && r < 1e6 * span).then_some(([cx - 0.5 * s[0], cy - 0.5 * s[1]], r))
    }

    /// +1 if `centre` lies inside the body behind its contact segment (convex), −1 if on the
    /// side its outward normal points to (concave), judged at the contact element nearest x = 0.
    fn convexity(&self, centre: [f64; 2]) -> f64 {
        let Some(e) = self
            .mesh
            .elements
            .iter()
            .enumerate()
            .filter(|(_, e)| e.group == self.contact_group)
            .min_by(|(a, _), (b, _)| {
                let x = |e: usize| ElementGeometry::from_mesh(&self.mesh, e).point(0.0)[0].abs();
                x(*a).total_cmp(&x(*b))
            })
            .map(|(e, _)| e)
        else {
            return 1.0;
        };
        let g = ElementGeometry::from_mesh(&self.mesh, e);
        let (p, n) = (g.point(0.0), g.normal(0.0));
        if (centre[0] - p[0]) * n[0] + (centre[1] - p[1]) * n[1] > 0.0 {
            -1.0
        } else {
            1.0
        }
    }

    /// The contact grid of the mesh's own contact elements: their end points in x and their
    /// quadratic geometry (the mid node's x), with discontinuous quadratic interpolation, so its
    /// nodes are the x of the BEM contact elements' field nodes however curved the arc
    /// ([`ContactGrid::from_mapped_edges`]).
    pub fn contact_grid(&self) -> ContactGrid {
        let mut pieces: Vec<[f64; 3]> = self
            .contact_elements()
            .map(|g| {
                let [a, b, m] = g.nodes;
                let (x0, x1) = if a[0] <= b[0] { (a[0], b[0]) } else { (b[0], a[0]) };
                [x0, x1, m[0]]
            })
            .collect();
        // Ends closer than this are one edge: the mesh's round-off, but never as much as a
        // share of its shortest contact element (an error-controlled grid grades elements
        // below 1e-9 of the mesh's size, whose ends a size-relative distance would merge).
        let shortest = pieces.iter().map(|p| p[1] - p[0]).fold(f64::INFINITY, f64::min);
        let tol = (1e-9 * self.mesh.size()).min(1e-3 * shortest);
        pieces.sort_by(|p, q| p[0].total_cmp(&q[0]));
        let mut edges: Vec<f64> = pieces.iter().flat_map(|p| [p[0], p[1]]).collect();
        edges.sort_by(f64::total_cmp);
        edges.dedup_by(|a, b| (*a - *b).abs() <= tol);
        // Each grid element takes the mid point of the mesh element between its edges (the
        // centre where the contact group has a gap).
        let mids = edges
            .windows(2)
            .map(|w| {
                pieces
                    .iter()
                    .find(|p| (p[0] - w[0]).abs() <= tol && (p[1] - w[1]).abs() <= tol)
                    .map_or(0.5 * (w[0] + w[1]), |p| p[2])
            })
            .collect();
        ContactGrid::from_mapped_edges(ElementKind::DiscontinuousQuadratic, edges, mids)
    }

    /// The geometry of the contact group's elements.
    pub fn contact_elements(&self) -> impl Iterator<Item = ElementGeometry> + '_ {
        self.mesh
            .elements
            .iter()
            .enumerate()
            .filter(|(_, e)| e.group == self.contact_group)
            .map(|(e, _)| ElementGeometry::from_mesh(&self.mesh, e))
    }

    /// The contact surface above x: its point's y and its slope dy/dx [length, -], from the
    /// contact element whose x-range holds x (None beyond the contact group).
    pub fn surface_at(&self, x: f64) -> Option<(f64, f64)> {
        let (g, xi) = self.contact_element_at(x)?;
        Some(g.height_and_slope(xi))
    }

    /// The contact element whose x-range holds x and the ξ at which it reaches x (None beyond
    /// the contact group).
    pub fn contact_element_at(&self, x: f64) -> Option<(ElementGeometry, f64)> {
        self.contact_elements()
            .find_map(|g| g.parameter_at_x(x).map(|xi| (g, xi)))
    }

    /// Total length of the elements of a group (polyline through end, mid, end nodes) [length].
    pub fn group_length(&self, group: usize) -> f64 {
        let d = |a: [f64; 2], b: [f64; 2]| ((a[0] - b[0]).powi(2) + (a[1] - b[1]).powi(2)).sqrt();
        self.mesh
            .elements
            .iter()
            .filter(|e| e.group == group)
            .map(|e| match e.nodes.as_slice() {
                [a, b, m] => d(self.mesh.nodes[*a], self.mesh.nodes[*m]) + d(self.mesh.nodes[*m], self.mesh.nodes[*b]),
                [a, b] => d(self.mesh.nodes[*a], self.mesh.nodes[*b]),
                _ => 0.0,
            })
            .sum()
    }

    /// Distance from the contact node nearest x = 0 to the nearest node of the given groups
    /// [length] (infinite when the groups have no node).
    pub fn depth_below_contact(&self, groups: &[usize]) -> Option<f64> {
        let m = &self.mesh;
        let centre = self.contact_nodes().min_by(|p, q| p[0].abs().total_cmp(&q[0].abs()))?;
        Some(
            m.elements
                .iter()
                .filter(|e| groups.contains(&e.group))
                .flat_map(|e| e.nodes.iter().map(|&n| m.nodes[n]))
                .map(|p| (p[0] - centre[0]).hypot(p[1] - centre[1]))
                .fold(f64::INFINITY, f64::min),
        )
    }
}
