//! Meshes with one defect each (tests/data/msh/, made by `python3 tests/data/msh/make_defects.py`):
//! node tags read by tag, duplicate and missing tags, NaN coordinates, self-crossing outlines,
//! holes that cross the outer contour or lie outside it, and non-regular files. Each is refused
//! with a message that names the file and the culprit, by `rollbem check` and `rollbem run` alike.

use rollbem::mesh::{self, MeshError};
use std::path::{Path, PathBuf};
use std::time::{Duration, Instant};

use crate::common::{self, rollbem};

fn data(name: &str) -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/data/msh").join(name)
}

fn load_err(name: &str) -> MeshError {
    match mesh::load(&data(name)) {
        Ok(_) => panic!("{name} should be refused"),
        Err(e) => e,
    }
}

/// The roller of cases/carter_051_true.yaml with node tags 24 and 54 swapped in $Nodes and
/// $Elements is the same mesh: the same elements through the same points, and the same run.
#[test]
fn a_relabelled_mesh_is_the_same_mesh() {
    let original = Path::new(env!("CARGO_MANIFEST_DIR")).join("meshes/roller_r100_shaft10_A.msh");
    let (a, _) = mesh::load(&original).unwrap();
    let (b, _) = mesh::load(&data("roller_relabelled.msh")).unwrap();
    let points = |m: &mesh::BoundaryMesh| {
        let mut p: Vec<Vec<[u64; 2]>> = m
            .elements
            .iter()
            .map(|e| e.nodes.iter().map(|&n| m.nodes[n].map(f64::to_bits)).collect())
            .collect();
        p.sort();
        p
    };
    assert_eq!(points(&a), points(&b));

    let creep = |mesh: &Path| {
        let dir = tempfile::tempdir().unwrap();
        let case = common::case_path("carter_051_true");
        let (code, _, stderr) = rollbem(&[
            "run",
            case.to_str().unwrap(),
            "--out",
            dir.path().to_str().unwrap(),
            "--set",
            &format!("bodies.A.mesh={}", mesh.display()),
            "--set",
            "output.vtk=false",
        ]);
        assert_eq!(code, 0, "{stderr}");
        let summary: serde_json::Value =
            serde_json::from_str(&std::fs::read_to_string(dir.path().join("summary.json")).unwrap()).unwrap();
        summary["creep"].as_f64().unwrap()
    };
    let (xi_original, xi_relabelled) = (creep(&original), creep(&data("roller_relabelled.msh")));
    // The same mesh gives the same equations in the same order: equal to round-off.
    assert!(
        (xi_relabelled - xi_original).abs() <= 1e-9 * xi_original.abs(),
        "creepage {xi_relabelled:e} with relabelled tags, {xi_original:e} without"
    );
}

#[test]
fn duplicate_and_missing_node_tags_are_refused() {
    let err = load_err("duplicate_tag.msh");
    assert!(matches!(err, MeshError::DuplicateNode { node: 5, .. }), "{err}");
    let text = err.to_string();
    assert!(
        text.contains("duplicate_tag.msh") && text.contains("node tag 5 is defined twice"),
        "{text}"
    );

    let err = load_err("missing_tag.msh");
    assert!(matches!(err, MeshError::UnknownNode { node: 99, .. }), "{err}");
    assert!(err.to_string().contains("missing_tag.msh"), "{err}");
}

#[test]
fn nan_coordinates_are_refused_in_ascii_and_binary_files() {
    for name in ["nan_node.msh", "nan_node_bin.msh"] {
        let err = load_err(name);
        let text = err.to_string();
        assert!(
            matches!(err, MeshError::NonFiniteNode { .. }) || matches!(err, MeshError::Parse { .. }),
            "{name}: {text}"
        );
        assert!(text.contains(name), "{text}");
    }
    let err = load_err("nan_node_bin.msh");
    assert!(matches!(err, MeshError::NonFiniteNode { node: 1, .. }), "{err}");
}

#[test]
fn crossing_outlines_and_holes_are_refused_with_the_groups_named() {
    let err = load_err("bowtie.msh");
    assert!(matches!(err, MeshError::CrossingBoundary { .. }), "{err}");
    assert!(err.to_string().contains("`sides`"), "{err}");

    let err = load_err("hole_crossing.msh");
    match &err {
        MeshError::CrossingBoundary { first, second, .. } => {
            let mut g = [first.as_str(), second.as_str()];
            g.sort_unstable();
            assert_eq!(g, ["inner", "outer"], "{err}");
        }
        other => panic!("expected a crossing: {other}"),
    }

    let err = load_err("hole_outside.msh");
    assert!(
        matches!(err, MeshError::LoopOutsideBody { ref groups, island: false, .. } if groups == "inner"),
        "{err}"
    );
    assert!(err.to_string().contains("outside the body"), "{err}");
}

/// A case of one bem body on a mesh of tests/data/msh, with every group free but `bottom`.
fn mesh_case(dir: &Path, mesh: &Path, groups: &str) -> PathBuf {
    let text = format!(
        "materials:\n  steel: {{E: 210000.0, nu: 0.3}}\nbodies:\n  A: {{model: half_space, material: steel, radius: 100.0}}\n  \
         B: {{model: bem, mesh: '{}', material: steel, contact: bottom, boundaries: {{{groups}}}, radius: 100.0}}\n\
         contact: {{friction: 0.1}}\nload: {{normal: {{force: 10.0}}}}\noutput: {{dir: out}}\n",
        mesh.display()
    );
    let path = dir.join("case.yaml");
    std::fs::write(&path, text).unwrap();
    path
}

/// `check` and `run` refuse the same broken meshes, naming the file, and write nothing.
#[test]
fn check_and_run_refuse_broken_meshes_alike() {
    for (name, culprit) in [
        ("nan_node.msh", "nan_node.msh"),
        ("duplicate_tag.msh", "defined twice"),
        ("missing_tag.msh", "node 99"),
        ("bowtie.msh", "crosses itself"),
    ] {
        let dir = tempfile::tempdir().unwrap();
        let case = mesh_case(dir.path(), &data(name), "sides: fixed");
        for verb in ["check", "run"] {
            let (code, _, stderr) = rollbem(&[verb, case.to_str().unwrap()]);
            assert_eq!(code, 1, "{verb} {name}: {stderr}");
            assert!(
                stderr.contains(name) && stderr.contains(culprit),
                "{verb} {name}: {stderr}"
            );
            assert!(!dir.path().join("out").exists(), "{verb} {name}: output written");
        }
    }
}

/// A boundary that mixes line2 and line3 elements (plate.msh with one contact element made a
/// 2-node line) is refused by `check` and `run` with exit code 1, naming the element and what to
/// do; it crashed the crossing check (one point count per element assumed) with exit code 3.
#[test]
fn a_loop_of_mixed_element_orders_is_refused_naming_the_element() {
    let err = load_err("mixed_order.msh");
    assert!(
        matches!(
            err,
            MeshError::BadElement {
                ref group,
                defect: mesh::ElementDefect::MixedOrder { nodes: 2, first: 3 },
                ..
            } if group == "contact"
        ),
        "{err}"
    );
    let dir = tempfile::tempdir().unwrap();
    let text = format!(
        "materials:\n  steel: {{E: 210000.0, nu: 0.3}}\nbodies:\n  A: {{model: half_space, material: steel, radius: 100.0}}\n  \
         B: {{model: bem, mesh: '{}', material: steel, contact: contact, boundaries: {{fixed: fixed}}, radius: 100.0}}\n\
         contact: {{friction: 0.1}}\nload: {{normal: {{force: 10.0}}}}\noutput: {{dir: out}}\n",
        data("mixed_order.msh").display()
    );
    let case = dir.path().join("case.yaml");
    std::fs::write(&case, text).unwrap();
    for verb in ["check", "run"] {
        let (code, _, stderr) = rollbem(&[verb, case.to_str().unwrap()]);
        assert_eq!(code, 1, "{verb}: {stderr}");
        assert!(
            stderr.contains("mixed_order.msh") && stderr.contains("`contact`") && stderr.contains("has 2 nodes"),
            "{verb}: {stderr}"
        );
        assert!(!dir.path().join("out").exists(), "{verb}: output written");
    }
}

/// Every element of the shipped and test meshes turned into the other order in turn (a line3
/// element losing its mid node, a line2 element gaining one at its middle): each mixed mesh is
/// refused with that element named, never a panic. Returns how many meshes were tried.
#[test]
fn every_element_of_another_order_is_refused() {
    let mut tried = 0;
    let mut files: Vec<PathBuf> = ["plate.msh", "annulus.msh", "square_linear.msh", "plate_bin.msh"]
        .iter()
        .map(|n| data(n))
        .collect();
    files.push(Path::new(env!("CARGO_MANIFEST_DIR")).join("meshes/roller_r100_shaft10_A.msh"));
    for file in files {
        let (valid, _) = mesh::load(&file).unwrap();
        for i in 0..valid.elements.len() {
            let mut m = valid.clone();
            let el = &mut m.elements[i];
            if el.nodes.len() == 3 {
                el.nodes.truncate(2);
            } else {
                let ([x0, y0], [x1, y1]) = (m.nodes[el.nodes[0]], m.nodes[el.nodes[1]]);
                el.nodes.push(m.nodes.len());
                m.nodes.push([0.5 * (x0 + x1), 0.5 * (y0 + y1)]);
            }
            // The first element sets the order: turning it makes the second one differ.
            let culprit = if i == 0 { 1 } else { i };
            match mesh::validate_and_orient(&mut m) {
                Err(MeshError::BadElement {
                    element,
                    defect: mesh::ElementDefect::MixedOrder { .. },
                    ..
                }) => assert_eq!(element, culprit, "{}", file.display()),
                other => panic!("{} element {i}: {other:?}", file.display()),
            }
            tried += 1;
        }
    }
    // The number docs/reliability.md quotes: the elements of the five meshes.
    assert_eq!(tried, 295);
}

/// Runs rollbem and kills it if it has not finished in `limit` (a FIFO would block it for ever).
fn rollbem_within(args: &[&str], limit: Duration) -> Option<(i32, String)> {
    let mut child = std::process::Command::new(env!("CARGO_BIN_EXE_rollbem"))
        .args(args)
        .stdout(std::process::Stdio::null())
        .stderr(std::process::Stdio::piped())
        .spawn()
        .unwrap();
    let start = Instant::now();
    while start.elapsed() < limit {
        if let Some(status) = child.try_wait().unwrap() {
            let mut stderr = String::new();
            std::io::Read::read_to_string(child.stderr.as_mut().unwrap(), &mut stderr).unwrap();
            return Some((status.code().unwrap_or(-1), stderr));
        }
        std::thread::sleep(Duration::from_millis(20));
    }
    child.kill().unwrap();
    child.wait().unwrap();
    None
}

/// A FIFO, a folder or a device given as a mesh or case path is refused before it is opened.
#[cfg(unix)]
#[test]
fn non_regular_files_are_refused_before_opening() {
    let dir = tempfile::tempdir().unwrap();
    let fifo = dir.path().join("pipe.msh");
    let made = std::process::Command::new("mkfifo").arg(&fifo).status().unwrap();
    assert!(made.success());
    for (mesh, what) in [
        (fifo.as_path(), "FIFO"),
        (dir.path(), "folder"),
        (Path::new("/dev/zero"), "device"),
    ] {
        let case = mesh_case(dir.path(), mesh, "sides: fixed");
        for verb in ["check", "run"] {
            let (code, stderr) = rollbem_within(&[verb, case.to_str().unwrap()], Duration::from_secs(30))
                .unwrap_or_else(|| panic!("{verb} blocked on {}", mesh.display()));
            assert_eq!(code, 1, "{verb}: {stderr}");
            assert!(
                stderr.contains(&mesh.display().to_string()) && stderr.contains(what),
                "{verb}: {stderr}"
            );
        }
    }
    // The case file itself.
    let (code, stderr) = rollbem_within(&["check", fifo.to_str().unwrap()], Duration::from_secs(30))
        .expect("check blocked on a FIFO case file");
    assert_eq!(code, 1, "{stderr}");
    assert!(stderr.contains("FIFO"), "{stderr}");
}

/// Inputs on which `cargo fuzz` found a panic, kept as regression tests (tests/data/msh/fuzz/:
/// the sections after the `$MeshFormat` header, which the fuzz targets fix). Each must be
/// refused with a message that names the problem.
#[test]
fn fuzz_findings_are_refused_cleanly() {
    let ascii = b"$MeshFormat\n4.1 0 8\n$EndMeshFormat\n".as_slice();
    let binary = b"$MeshFormat\n4.1 1 8\n\x01\x00\x00\x00\n$EndMeshFormat\n".as_slice();
    for (name, header, expected) in [
        // `8 0 1 2` in $Nodes: no nodes; mshio computed 0 - 1 in unsigned arithmetic.
        ("empty_node_section_ascii.sections", ascii, "announces no nodes"),
        ("empty_node_section_binary.sections", binary, "announces no nodes"),
        // A second $Elements section whose header says 0 elements (mshio parses every section
        // before it refuses a second one).
        (
            "second_empty_element_section_binary.sections",
            binary,
            "announces no elements",
        ),
    ] {
        let mut bytes = header.to_vec();
        bytes.extend(std::fs::read(data("fuzz").join(name)).unwrap());
        let err = mesh::parse_msh_bytes(&bytes, name).unwrap_err();
        assert!(err.to_string().contains(expected), "{name}: {err}");
    }
    // Read, then refused by the checks: a loop of line3 elements and one line2 element (the
    // crossing check indexed its elements by one point count for all and went out of bounds).
    let name = "mixed_order_loop_ascii.sections";
    let mut bytes = ascii.to_vec();
    bytes.extend(std::fs::read(data("fuzz").join(name)).unwrap());
    let mut read = mesh::parse_msh_bytes(&bytes, name).unwrap();
    let err = mesh::validate_and_orient(&mut read).unwrap_err();
    assert!(err.to_string().contains("has 2 nodes where"), "{name}: {err}");
}
