//! `rollbem mesh`: the meshes of a case's `geometry:` bodies as Gmsh MSH 4.1 files, which
//! rollbem's reader reads back to the meshes `run` solves on.

use crate::common::{case_path, rollbem};
use rollbem::mesh::BoundaryMesh;

/// Each element as its group's name and its nodes' coordinates (bit for bit), sorted: the mesh
/// independent of the numbering of its nodes and elements.
fn canonical(mesh: &BoundaryMesh) -> Vec<(String, Vec<[u64; 2]>)> {
    let mut elements: Vec<(String, Vec<[u64; 2]>)> = mesh
        .elements
        .iter()
        .map(|e| {
            let nodes = e.nodes.iter().map(|&n| mesh.nodes[n].map(f64::to_bits)).collect();
            (mesh.groups[e.group].name.clone(), nodes)
        })
        .collect();
    elements.sort();
    elements
}

#[test]
fn mesh_writes_gmsh_files_that_read_back_to_the_generated_meshes() {
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("meshes");
    let case = case_path("fig14_geometry");
    let (code, stdout, stderr) = rollbem(&["mesh", case.to_str().unwrap(), "--out", out.to_str().unwrap()]);
    assert_eq!(code, 0, "{stderr}");
    assert!(stdout.contains("A.msh") && stdout.contains("B.msh"), "{stdout}");
    let loaded = rollbem::app::load_case(&case, &[] as &[&str]).unwrap();
    let generated = rollbem::scene::registry::generated_meshes(&loaded).unwrap();
    assert_eq!(generated.len(), 2);
    for (side, mesh) in &generated {
        let path = out.join(format!("{side}.msh"));
        let (read, notices) = rollbem::mesh::load(&path).unwrap();
        assert!(notices.is_empty(), "the loops are written oriented: {notices:?}");
        assert_eq!(read.nodes.len(), mesh.nodes.len(), "{side}");
        assert_eq!(read.group_names(), mesh.group_names(), "{side}");
        assert_eq!(canonical(&read), canonical(mesh), "{side}: the mesh read back differs");
    }
    // The folder is rollbem's: a second run replaces it.
    let (code, _, stderr) = rollbem(&["mesh", case.to_str().unwrap(), "--out", out.to_str().unwrap()]);
    assert_eq!(code, 0, "{stderr}");
}

#[test]
fn mesh_of_a_case_without_geometry_is_refused() {
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("meshes");
    let case = case_path("fig14_true_geometry");
    let (code, _, stderr) = rollbem(&["mesh", case.to_str().unwrap(), "--out", out.to_str().unwrap()]);
    assert_eq!(code, 1, "{stderr}");
    assert!(
        stderr.contains("bodies.A.geometry") && stderr.contains("no body is given by `geometry:`"),
        "{stderr}"
    );
    assert!(!out.exists());
}
