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

/// A case whose body A reads a mesh that an earlier `rollbem mesh` wrote into `--out M`, and
/// whose body B is `geometry:`: meshing it into M again deleted M/A.msh (exit 0), the mesh the
/// case reads. A folder holding an input of the case is refused, `--force` or not, naming the
/// file; another `--out` is written.
#[test]
fn mesh_never_removes_a_mesh_the_case_reads() {
    let dir = tempfile::tempdir().unwrap();
    let case = case_path("fig14_geometry");
    let m = dir.path().join("M");
    let (code, _, stderr) = rollbem(&["mesh", case.to_str().unwrap(), "--out", m.to_str().unwrap()]);
    assert_eq!(code, 0, "{stderr}");
    let text = std::fs::read_to_string(&case).unwrap();
    let geometry_a = "geometry: {roller: {radius: 150, shaft: 15}}";
    assert!(text.contains(geometry_a));
    let mixed = dir.path().join("mixed.yaml");
    std::fs::write(&mixed, text.replacen(geometry_a, "mesh: M/A.msh", 1)).unwrap();
    let a_msh = std::fs::read(m.join("A.msh")).unwrap();
    for force in [&[][..], &["--force"][..]] {
        let mut args = vec!["mesh", mixed.to_str().unwrap(), "--out", m.to_str().unwrap()];
        args.extend(force);
        let (code, _, stderr) = rollbem(&args);
        assert_eq!(code, 1, "{args:?}: {stderr}");
        assert!(
            stderr.contains("A.msh is an input of the case") && stderr.contains("--out NEW_FOLDER"),
            "{stderr}"
        );
        assert_eq!(std::fs::read(m.join("A.msh")).unwrap(), a_msh);
        assert!(m.join("B.msh").is_file());
    }
    let other = dir.path().join("other");
    let (code, stdout, stderr) = rollbem(&["mesh", mixed.to_str().unwrap(), "--out", other.to_str().unwrap()]);
    assert_eq!(code, 0, "{stderr}");
    assert!(stdout.contains("B.msh") && !stdout.contains("A.msh"), "{stdout}");
}

/// A mesh edited since rollbem wrote it was replaced without a word; now the write stops,
/// naming it, and keeps it; `--force` replaces it.
#[test]
fn an_edited_mesh_is_kept_unless_forced() {
    let dir = tempfile::tempdir().unwrap();
    let case = case_path("fig14_geometry");
    let e = dir.path().join("e");
    let args = ["mesh", case.to_str().unwrap(), "--out", e.to_str().unwrap()];
    let (code, _, stderr) = rollbem(&args);
    assert_eq!(code, 0, "{stderr}");
    let written = std::fs::read_to_string(e.join("A.msh")).unwrap();
    let edited = format!("{written}// my edits\n");
    std::fs::write(e.join("A.msh"), &edited).unwrap();
    let (code, _, stderr) = rollbem(&args);
    assert_eq!(code, 1, "{stderr}");
    assert!(
        stderr.contains("A.msh was changed since rollbem wrote it") && stderr.contains("--force"),
        "{stderr}"
    );
    assert_eq!(std::fs::read_to_string(e.join("A.msh")).unwrap(), edited);
    let (code, _, stderr) = rollbem(&[&args[..], &["--force"]].concat());
    assert_eq!(code, 0, "{stderr}");
    assert_eq!(std::fs::read_to_string(e.join("A.msh")).unwrap(), written);
}
