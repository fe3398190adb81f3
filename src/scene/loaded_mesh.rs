//! A boundary mesh read for a body of the scene, with what the scene needs from its contact
//! group: the x-range, the fitted profile radius and the contact grid of its own elements.

use crate::grid::{ContactGrid, ElementKind};
use crate::mesh::BoundaryMesh;
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

    /// Radius of the contact segment's profile [length]: the algebraic least-squares circle
    /// (Kåsa fit: x² + y² + Dx + Ey + F = 0), exact for nodes on a circle; infinite when the
    /// segment is straight (the fit's centre then runs away: R > 1e6 times the segment length).
    pub fn contact_radius(&self) -> f64 {
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
        match a.lu().solve(&b) {
            Some(s) => {
                let r2 = 0.25 * (s[0] * s[0] + s[1] * s[1]) - s[2];
                let r = r2.max(0.0).sqrt();
                if r.is_finite() && r < 1e6 * span {
                    r
                } else {
                    f64::INFINITY
                }
            }
            None => f64::INFINITY,
        }
    }

    /// The contact grid of the mesh's own contact elements: their end points in x, with
    /// discontinuous quadratic interpolation (the BEM contact elements' field nodes).
    pub fn contact_grid(&self) -> ContactGrid {
        let mut edges: Vec<f64> = self
            .mesh
            .elements
            .iter()
            .filter(|e| e.group == self.contact_group)
            .flat_map(|e| {
                let (a, b) = e.ends();
                [self.mesh.nodes[a][0], self.mesh.nodes[b][0]]
            })
            .collect();
        edges.sort_by(f64::total_cmp);
        let tol = 1e-9 * self.mesh.size();
        edges.dedup_by(|a, b| (*a - *b).abs() <= tol);
        ContactGrid::from_edges(ElementKind::DiscontinuousQuadratic, edges)
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
