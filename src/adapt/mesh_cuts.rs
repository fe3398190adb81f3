//! A `bem` body's mesh refined with its contact grid: each contact element cut where the cells
//! of the error-controlled grid end, the new nodes on the element's own quadratic geometry.
//!
//! A contact element spans one start element of the grid. Its pieces are new quadratic
//! elements whose end and mid nodes lie on the original element's curve at the x of the
//! cells' ends and mid points, so that the contact grid the refined mesh gives is the cells'
//! grid node for node, for the body the grid was built from and for a matching body across
//! the contact alike (the x of a point fixes it on either curve). The rest of the mesh is
//! unchanged; the contact group's elements outside the contact stay as long as the start
//! grid's and neighbouring pieces differ in length by at most 2 ([`super::cells`]).

use super::cells::DyadicGrid;
use crate::bem::element::ElementGeometry;
use crate::mesh::{BoundaryElement, BoundaryMesh};
use crate::scene::{BemSetup, LoadedMesh};

/// The setup with its contact elements cut along the cells of `cells` (module docs). A
/// contact element that spans no start element of the grid is kept as it is.
pub fn refined_setup(setup: &BemSetup, cells: &DyadicGrid) -> BemSetup {
    let mesh = &setup.mesh.mesh;
    let group = setup.mesh.contact_group;
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
    BemSetup {
        mesh: LoadedMesh {
            mesh: BoundaryMesh::new(nodes, elements, mesh.groups.clone(), mesh.source.clone()),
            ..setup.mesh.clone()
        },
        ..setup.clone()
    }
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
