//! Gmsh MSH 4.1 reader: ASCII and binary files, physical names, loop orientation, bad input.
//!
//! The meshes under tests/data/msh/ are made from the `.geo` files next to them by
//! `python3 tests/data/msh/generate.py` (gmsh Python wheel).

use rollbem::mesh::{self, boundary_loops, BoundaryMesh, MeshError};
use std::path::{Path, PathBuf};

fn data(name: &str) -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/data/msh").join(name)
}

fn load(name: &str) -> (BoundaryMesh, Vec<String>) {
    mesh::load(&data(name)).unwrap_or_else(|e| panic!("{name}: {e}"))
}

fn group_count(m: &BoundaryMesh, name: &str) -> usize {
    m.count_in_group(m.group_index(name).unwrap())
}

/// Outward normal n = (t_y, −t_x) at the middle of element `e` (material on the left).
fn mid_normal(m: &BoundaryMesh, e: usize) -> ([f64; 2], [f64; 2]) {
    let el = &m.elements[e];
    let (a, b) = (m.nodes[el.nodes[0]], m.nodes[el.nodes[1]]);
    let t = [b[0] - a[0], b[1] - a[1]];
    let len = (t[0] * t[0] + t[1] * t[1]).sqrt();
    let mid = if el.nodes.len() == 3 {
        m.nodes[el.nodes[2]]
    } else {
        [0.5 * (a[0] + b[0]), 0.5 * (a[1] + b[1])]
    };
    (mid, [t[1] / len, -t[0] / len])
}

#[test]
fn ascii_and_binary_annulus_read_identically_with_names_and_quadratic_elements() {
    let (ascii, _) = load("annulus.msh");
    let (binary, _) = load("annulus_bin.msh");
    // ASCII files carry 16 significant digits, binary ones the exact doubles.
    assert_eq!(ascii.nodes.len(), binary.nodes.len());
    for (a, b) in ascii.nodes.iter().zip(&binary.nodes) {
        assert!((a[0] - b[0]).abs() < 1e-13 && (a[1] - b[1]).abs() < 1e-13);
    }
    assert_eq!(ascii.elements, binary.elements);
    assert_eq!(ascii.groups, binary.groups);
    assert_eq!(ascii.group_names(), vec!["inner", "outer"]);
    assert_eq!(ascii.groups[0].tag, 11);
    assert_eq!(group_count(&ascii, "inner"), 16);
    assert_eq!(group_count(&ascii, "outer"), 16);
    assert!(ascii.elements.iter().all(|e| e.nodes.len() == 3));
    // Only the boundary nodes are kept: 2 circles × 16 elements × 2 nodes.
    assert_eq!(ascii.nodes.len(), 64);
    for p in &ascii.nodes {
        let r = p[0].hypot(p[1]);
        assert!((r - 10.0).abs() < 1e-9 || (r - 20.0).abs() < 1e-9, "r = {r}");
    }
}

#[test]
fn annulus_loops_are_oriented_with_normals_out_of_the_material() {
    let (m, notices) = load("annulus.msh");
    // Gmsh draws both circles the same way round, so at least the hole had to be turned.
    assert!(!notices.is_empty());
    assert!(notices.iter().all(|n| n.contains("annulus.msh")), "{notices:?}");
    let loops = boundary_loops(&m).unwrap();
    assert_eq!(loops.len(), 2);
    assert_eq!(loops.iter().filter(|l| l.is_hole()).count(), 1);
    for l in &loops {
        // Quadratic arcs: the area of each disc within 1e-3 relative at 16 elements.
        let expected = if l.is_hole() { -100.0 } else { 400.0 } * std::f64::consts::PI;
        assert!(
            ((l.signed_area - expected) / expected).abs() < 1e-3,
            "{}",
            l.signed_area
        );
    }
    for e in 0..m.elements.len() {
        let (x, n) = mid_normal(&m, e);
        let radial = (x[0] * n[0] + x[1] * n[1]) / x[0].hypot(x[1]);
        let inner = m.groups[m.elements[e].group].name == "inner";
        // Out of the material: towards the centre on the hole, away from it outside.
        assert!(
            if inner { radial < -0.99 } else { radial > 0.99 },
            "element {e}: {radial}"
        );
    }
}

#[test]
fn plate_with_reversed_curves_and_a_hole_is_oriented_and_grouped() {
    let (m, notices) = load("plate.msh");
    let (mb, notices_b) = load("plate_bin.msh");
    assert_eq!(m.elements, mb.elements);
    assert_eq!(notices.len(), notices_b.len());
    assert!(!notices.is_empty());
    assert_eq!(m.group_names(), vec!["fixed", "free", "contact", "shaft"]);
    assert_eq!(group_count(&m, "fixed"), 8);
    assert_eq!(group_count(&m, "free"), 14);
    assert_eq!(group_count(&m, "contact"), 6);
    assert_eq!(group_count(&m, "shaft"), 8);
    for e in 0..m.elements.len() {
        let (x, n) = mid_normal(&m, e);
        let expected = match m.groups[m.elements[e].group].name.as_str() {
            "fixed" => [0.0, -1.0],
            "contact" => [0.0, 1.0],
            "shaft" => {
                let d = [20.0 - x[0], 10.0 - x[1]];
                let r = d[0].hypot(d[1]);
                [d[0] / r, d[1] / r]
            }
            _ if x[1] > 19.999 => [0.0, 1.0],
            _ if x[0] > 39.999 => [1.0, 0.0],
            _ => [-1.0, 0.0],
        };
        let dot = n[0] * expected[0] + n[1] * expected[1];
        assert!(dot > 0.99, "element {e} at {x:?}: n = {n:?}");
    }
}

#[test]
fn linear_elements_are_read() {
    let (m, _) = load("square_linear.msh");
    assert_eq!(m.elements.len(), 8);
    assert!(m.elements.iter().all(|e| e.nodes.len() == 2));
    assert_eq!(group_count(&m, "bottom"), 2);
    assert_eq!(group_count(&m, "sides"), 6);
    let loops = boundary_loops(&m).unwrap();
    assert!((loops[0].signed_area - 1.0).abs() < 1e-14);
}

fn load_err(name: &str) -> MeshError {
    match mesh::load(&data(name)) {
        Ok(_) => panic!("{name} should be rejected"),
        Err(e) => e,
    }
}

#[test]
fn bad_files_give_errors_that_name_the_file_and_the_culprit() {
    let err = load_err("annulus_v22.msh");
    assert!(matches!(err, MeshError::NotMsh4 { .. }), "{err}");
    assert!(err.to_string().contains("annulus_v22.msh") && err.to_string().contains("2.2"));

    let err = load_err("open_loop.msh");
    assert!(
        matches!(err, MeshError::OpenLoop { ref group, .. } if group == "free"),
        "{err}"
    );
    // An open loop may be a curve left out of every physical group (Gmsh then writes none of
    // its elements): the message says so and lists the groups the file has.
    let text = err.to_string();
    assert!(text.contains("in none") && text.contains("`free`"), "{text}");

    let err = load_err("unnamed_group.msh");
    assert!(matches!(err, MeshError::MissingPhysicalName { tag: 7, .. }), "{err}");

    let err = load_err("cubic.msh");
    assert!(matches!(err, MeshError::UnknownElementType { .. }), "{err}");
    assert!(err.to_string().contains("Lin4"), "{err}");

    let err = load_err("untagged.msh");
    assert!(matches!(err, MeshError::UntaggedCurve { curve: 4, .. }), "{err}");

    let err = load_err("zero_length.msh");
    assert!(
        matches!(err, MeshError::BadElement { ref group, element: 4, defect: rollbem::mesh::ElementDefect::ZeroLength, .. } if group == "free"),
        "{err}"
    );

    let err = load_err("no_such_file.msh");
    assert!(matches!(err, MeshError::NotFound { .. }), "{err}");
    assert!(err.to_string().contains("no_such_file.msh"));
}

#[test]
fn truncated_files_and_unknown_groups_are_reported() {
    let bytes = std::fs::read(data("annulus.msh")).unwrap();
    let cut = &bytes[..bytes.len() * 2 / 3];
    let err = mesh::parse_msh_bytes(cut, "cut.msh").unwrap_err();
    assert!(matches!(err, MeshError::Parse { .. }), "{err}");
    assert!(err.to_string().starts_with("cannot parse cut.msh"), "{err}");
    assert!(err.to_string().len() < 500, "no hex dump: {err}");

    let bytes = std::fs::read(data("plate_bin.msh")).unwrap();
    let cut = &bytes[..bytes.len() - 200];
    assert!(mesh::parse_msh_bytes(cut, "cut_bin.msh").is_err());

    let (m, _) = load("plate.msh");
    let err = m.group_index("contacts").unwrap_err();
    let text = err.to_string();
    assert!(text.contains("`contacts`") && text.contains("contact, shaft"), "{text}");
}

/// Nodes, elements and groups of two meshes are the same (the source label aside).
fn assert_same_mesh(a: &BoundaryMesh, b: &BoundaryMesh, what: &str) {
    assert_eq!(a.nodes, b.nodes, "{what}");
    assert_eq!(a.elements, b.elements, "{what}");
    assert_eq!(a.groups, b.groups, "{what}");
}

/// Files written by `meshio` (`meshio.write(..., file_format="gmsh")`, ASCII and binary) from
/// Gmsh's meshes read as those meshes: meshio writes 17 significant digits, so exactly.
#[test]
fn meshio_written_files_read_as_the_gmsh_originals() {
    for (original, copy) in [
        ("annulus.msh", "annulus_meshio.msh"),
        ("plate.msh", "plate_meshio_bin.msh"),
    ] {
        assert_same_mesh(&load(original).0, &load(copy).0, copy);
    }
}

/// A 2D mesh saved with everything (point elements, triangles of a physical surface,
/// parametric node coordinates) has the boundary of the 1D mesh of the same square.
#[test]
fn point_and_surface_elements_and_parametric_nodes_are_read_past() {
    let (line, _) = load("square_linear.msh");
    for name in ["square_surface.msh", "square_surface_bin.msh"] {
        let text = std::fs::read(data(name)).unwrap();
        // The file does hold what is to be read past.
        assert!(String::from_utf8_lossy(&text).contains("\"body\""), "{name}");
        assert_same_mesh(&line, &load(name).0, name);
    }
}

/// `bytes` with `insert` put in front of the first line that starts with `before`.
fn insert_before(bytes: &[u8], before: &[u8], insert: &[u8]) -> Vec<u8> {
    let at = bytes.windows(before.len()).position(|w| w == before).unwrap();
    [&bytes[..at], insert, &bytes[at..]].concat()
}

/// Sections rollbem does not read are skipped to their end marker, binary content and all.
#[test]
fn unknown_sections_are_skipped() {
    let comments = b"$Comments\nmade by hand; $EndComment is not its end\n$EndComments\n".as_slice();
    let ascii = std::fs::read(data("annulus.msh")).unwrap();
    let with = insert_before(&ascii, b"$Nodes", comments);
    let read = |bytes: &[u8]| mesh::parse_msh_bytes(bytes, "m.msh").unwrap();
    assert_same_mesh(&read(&ascii), &read(&with), "ASCII");

    let binary = std::fs::read(data("plate_bin.msh")).unwrap();
    let mut data_section = b"$NodeData\n".to_vec();
    data_section.extend((0..=255u8).chain(0..=255u8));
    data_section.extend(b"\n$EndNodeData\n");
    let with = insert_before(&binary, b"$Elements", &data_section);
    assert_same_mesh(&read(&binary), &read(&with), "binary");
}

/// A section without its end marker is named, in ASCII and binary files.
#[test]
fn a_missing_end_marker_names_the_section() {
    for name in ["annulus.msh", "annulus_bin.msh"] {
        let bytes = std::fs::read(data(name)).unwrap();
        let end = bytes.windows(12).rposition(|w| w == b"$EndElements").unwrap();
        let err = mesh::parse_msh_bytes(&bytes[..end], name).unwrap_err().to_string();
        assert!(
            err.contains("$Elements section") && err.contains("ends before $EndElements"),
            "{name}: {err}"
        );
    }
}

/// A count forged to more than the file can hold is refused (not allocated), naming the
/// section: the number of nodes of the binary $Nodes header, the number of elements of an
/// ASCII block.
#[test]
fn forged_counts_are_refused_before_anything_is_allocated() {
    let mut binary = std::fs::read(data("plate_bin.msh")).unwrap();
    let at = binary.windows(7).position(|w| w == b"$Nodes\n").unwrap() + 7 + 8;
    binary[at..at + 8].copy_from_slice(&(u64::MAX / 3).to_le_bytes());
    let err = mesh::parse_msh_bytes(&binary, "forged_bin.msh")
        .unwrap_err()
        .to_string();
    assert!(
        err.contains("$Nodes section") && err.contains("number of nodes = 6148914691236517205, more than the rest"),
        "{err}"
    );

    let ascii = std::fs::read_to_string(data("square_linear.msh")).unwrap();
    let forged = ascii.replacen("\n1 1 1 2\n", "\n1 1 1 2000000000000\n", 1);
    let err = mesh::parse_msh_bytes(forged.as_bytes(), "forged.msh")
        .unwrap_err()
        .to_string();
    assert!(
        err.contains("$Elements section: element block 1 of 4: number of elements in block = 2000000000000"),
        "{err}"
    );
}

/// Windows line ends (`\r\n`) read as `\n` ones.
#[test]
fn crlf_line_ends_read_the_same() {
    let text = std::fs::read_to_string(data("plate.msh")).unwrap();
    let crlf = text.replace('\n', "\r\n");
    let read = |t: &str| mesh::parse_msh_bytes(t.as_bytes(), "plate.msh").unwrap();
    assert_same_mesh(&read(&text), &read(&crlf), "CRLF");
}

/// Every mesh shipped in meshes/ (the ones the cases under cases/ read) is drawn with the
/// orientation rollbem wants: material on the left, outer contour counter-clockwise, holes
/// clockwise. Loading one then gives no "turned N element(s) round" notice, which every run of
/// a shipped case would otherwise print.
#[test]
fn shipped_meshes_are_oriented_and_load_without_notices() {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("meshes");
    let mut paths: Vec<PathBuf> = std::fs::read_dir(&dir)
        .unwrap()
        .map(|e| e.unwrap().path())
        .filter(|p| p.extension().is_some_and(|x| x == "msh"))
        .collect();
    paths.sort();
    assert!(paths.len() >= 10, "meshes/ holds {} .msh files", paths.len());
    let noisy: Vec<String> = paths
        .iter()
        .flat_map(|p| mesh::load(p).unwrap_or_else(|e| panic!("{}: {e}", p.display())).1)
        .collect();
    assert!(
        noisy.is_empty(),
        "shipped meshes turned round on loading:\n{}",
        noisy.join("\n")
    );
}
