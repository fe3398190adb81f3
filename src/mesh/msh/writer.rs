//! Writer of a [`BoundaryMesh`] as a Gmsh MSH 4.1 ASCII file (Gmsh reference manual, "MSH file
//! format version 4.1"): `$MeshFormat`, `$PhysicalNames`, `$Entities` (one curve per physical
//! group, carrying its tag), `$Nodes` and `$Elements` (one block per curve). Gmsh opens it, and
//! rollbem's reader ([`super::parse_msh_bytes`]) reads it back to the same nodes, elements and
//! groups: coordinates are written with the shortest decimal that reads back to the same double.

use crate::mesh::BoundaryMesh;
use std::fmt::Write;

/// The MSH 4.1 ASCII text of `mesh`. Node tags are the node indices plus one, element tags
/// the element indices plus one; each group is curve entity `k + 1` with physical tag
/// `tag` (its own), and each node is listed once, in the block of the first element that uses it.
pub fn write_msh41_ascii(mesh: &BoundaryMesh) -> String {
    let mut s = String::new();
    let groups = &mesh.groups;
    // `write!` into a String cannot fail.
    let _ = writeln!(s, "$MeshFormat\n4.1 0 8\n$EndMeshFormat");
    let _ = writeln!(s, "$PhysicalNames\n{}", groups.len());
    for g in groups {
        let _ = writeln!(s, "1 {} \"{}\"", g.tag, g.name.replace('"', "'"));
    }
    let _ = writeln!(s, "$EndPhysicalNames");

    // Each node's curve: the group of the first element that uses it.
    let mut owner = vec![usize::MAX; mesh.nodes.len()];
    for e in &mesh.elements {
        for &n in &e.nodes {
            if owner[n] == usize::MAX {
                owner[n] = e.group;
            }
        }
    }
    let _ = writeln!(s, "$Entities\n0 {} 0 0", groups.len());
    for (k, g) in groups.iter().enumerate() {
        let mut lo = [f64::INFINITY; 2];
        let mut hi = [f64::NEG_INFINITY; 2];
        for e in mesh.elements.iter().filter(|e| e.group == k) {
            for &n in &e.nodes {
                for d in 0..2 {
                    lo[d] = lo[d].min(mesh.nodes[n][d]);
                    hi[d] = hi[d].max(mesh.nodes[n][d]);
                }
            }
        }
        if lo[0] > hi[0] {
            lo = [0.0; 2];
            hi = [0.0; 2];
        }
        let _ = writeln!(
            s,
            "{} {:?} {:?} 0 {:?} {:?} 0 1 {} 0",
            k + 1,
            lo[0],
            lo[1],
            hi[0],
            hi[1],
            g.tag
        );
    }
    let _ = writeln!(s, "$EndEntities");

    let used = owner.iter().filter(|&&o| o != usize::MAX).count();
    let _ = writeln!(s, "$Nodes\n{} {} 1 {}", groups.len(), used, mesh.nodes.len());
    for k in 0..groups.len() {
        let nodes: Vec<usize> = (0..mesh.nodes.len()).filter(|&n| owner[n] == k).collect();
        let _ = writeln!(s, "1 {} 0 {}", k + 1, nodes.len());
        for &n in &nodes {
            let _ = writeln!(s, "{}", n + 1);
        }
        for &n in &nodes {
            let p = mesh.nodes[n];
            let _ = writeln!(s, "{:?} {:?} 0", p[0], p[1]);
        }
    }
    let _ = writeln!(s, "$EndNodes");

    let _ = writeln!(
        s,
        "$Elements\n{} {} 1 {}",
        groups.len(),
        mesh.elements.len(),
        mesh.elements.len()
    );
    for k in 0..groups.len() {
        let elements: Vec<usize> = (0..mesh.elements.len())
            .filter(|&e| mesh.elements[e].group == k)
            .collect();
        let kind = match elements.first().map(|&e| mesh.elements[e].nodes.len()) {
            Some(2) => 1,
            _ => 8,
        };
        let _ = writeln!(s, "1 {} {kind} {}", k + 1, elements.len());
        for &e in &elements {
            let _ = write!(s, "{}", e + 1);
            for &n in &mesh.elements[e].nodes {
                let _ = write!(s, " {}", n + 1);
            }
            let _ = writeln!(s);
        }
    }
    let _ = writeln!(s, "$EndElements");
    s
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::mesh::build::rectangle;
    use crate::mesh::{parse_msh_bytes, validate_and_orient};

    /// Linear and quadratic meshes read back to the same nodes (bit for bit), elements and
    /// groups: the writer numbers nodes by index and the reader keeps the file's order.
    #[test]
    fn written_meshes_read_back_identical() {
        for quadratic in [false, true] {
            let mut mesh = rectangle(
                [0.1, -0.3],
                2.0 / 3.0,
                1e-7,
                [3, 1, 2, 1],
                ["a", "b", "a", "c"],
                quadratic,
            );
            validate_and_orient(&mut mesh).unwrap();
            let text = write_msh41_ascii(&mesh);
            let read = parse_msh_bytes(text.as_bytes(), "written").unwrap();
            assert_eq!(read.group_names(), mesh.group_names());
            assert_eq!(read.elements.len(), mesh.elements.len());
            let coords = |m: &BoundaryMesh| {
                let mut e: Vec<(String, Vec<[u64; 2]>)> = m
                    .elements
                    .iter()
                    .map(|e| {
                        let nodes = e.nodes.iter().map(|&n| m.nodes[n].map(f64::to_bits)).collect();
                        (m.groups[e.group].name.clone(), nodes)
                    })
                    .collect();
                e.sort();
                e
            };
            assert_eq!(coords(&read), coords(&mesh), "quadratic = {quadratic}");
        }
    }
}
