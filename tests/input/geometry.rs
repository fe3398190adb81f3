//! Parametric bodies (`geometry:`) refused before anything is meshed or solved: both `mesh`
//! and `geometry`, neither, an unknown family or key, lengths out of order or negative, an
//! elastic core (no two-region BEM), a group the family does not have, a contact segment
//! wider than the body, and lengths or grids that would take billions of elements. Each is exit code 1 with the key named, and nothing written.

use crate::common::{case_path, rollbem};

/// Runs `check` and `run` on cases/fig14_geometry.yaml with the overrides; asserts exit 1,
/// every `needles` in the message, nothing written.
fn assert_refused(set: &[&str], needles: &[&str]) {
    let case = case_path("fig14_geometry");
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("out");
    for verb in ["check", "run", "mesh"] {
        let mut args = vec![verb, case.to_str().unwrap()];
        if verb != "check" {
            args.extend(["--out", out.to_str().unwrap()]);
        }
        for s in set {
            args.extend(["--set", s]);
        }
        let (code, _, stderr) = rollbem(&args);
        assert_eq!(code, 1, "{verb} {set:?}: {stderr}");
        for n in needles {
            assert!(stderr.contains(n), "{verb} {set:?}: does not say `{n}`: {stderr}");
        }
        assert!(!out.exists(), "{verb} {set:?} wrote {}", out.display());
    }
}

#[test]
fn both_mesh_and_geometry_are_refused() {
    assert_refused(
        &["bodies.A.mesh=../meshes/roller_r150_shaft15_A.msh"],
        &["bodies.A.geometry", "exactly one of `mesh`"],
    );
}

#[test]
fn neither_mesh_nor_geometry_is_refused() {
    assert_refused(&["bodies.B.geometry=null"], &["bodies.B.mesh", "`geometry`"]);
}

#[test]
fn a_shaft_as_large_as_the_roller_is_refused() {
    assert_refused(
        &["bodies.A.geometry.roller.shaft=150"],
        &["bodies.A.geometry.roller.shaft", "must be less than radius = 150"],
    );
}

#[test]
fn a_negative_cover_thickness_is_refused() {
    assert_refused(
        &[
            "bodies.B.geometry={covered_roller: {radius: 300, cover_thickness: -5}}",
            "bodies.B.boundaries={bonded: fixed}",
        ],
        &["bodies.B.geometry.covered_roller.cover_thickness", "positive"],
    );
}

#[test]
fn a_ring_whose_rim_is_inside_its_bore_is_refused() {
    assert_refused(
        &[
            "bodies.B.geometry={ring: {bore: 500, rim: 400}}",
            "bodies.B.boundaries={rim: fixed}",
        ],
        &["bodies.B.geometry.ring.rim", "must exceed bore"],
    );
}

#[test]
fn an_unknown_family_or_key_is_refused() {
    assert_refused(
        &["bodies.A.geometry={disc: {radius: 150}}"],
        &["bodies.A", "geometry: unknown name `disc`", "roller"],
    );
    assert_refused(
        &["bodies.A.geometry={roller: {radius: 150, shaft: 15, width: 3}}"],
        &["bodies.A", "geometry: unknown field `width`"],
    );
}

#[test]
fn an_elastic_core_is_refused_for_want_of_a_two_region_bem() {
    assert_refused(
        &[
            "bodies.B.geometry={covered_roller: {radius: 300, cover_thickness: 5, core: {material: steel_bj}}}",
            "bodies.B.boundaries={}",
        ],
        &["bodies.B.geometry.covered_roller.core", "two-region BEM"],
    );
}

#[test]
fn a_group_the_family_lacks_is_refused() {
    assert_refused(
        &["bodies.A.boundaries={rim: fixed}"],
        &["bodies.A.boundaries.rim", "a roller has no group `rim`"],
    );
}

#[test]
fn a_contact_segment_wider_than_the_body_is_refused() {
    assert_refused(
        &["load.normal.force=1e7"],
        &["bodies.A.geometry", "wider than the roller allows"],
    );
}

/// Lengths whose far field would take billions of elements are refused before anything is
/// meshed (the generator would otherwise run out of memory or time before the memory estimate).
#[test]
fn a_cover_too_thin_or_a_block_too_deep_for_its_width_is_refused() {
    assert_refused(
        &[
            "bodies.A.geometry={covered_roller: {radius: 150, cover_thickness: 1e-9}}",
            "bodies.A.boundaries={}",
        ],
        &["bodies.A.geometry.covered_roller", "too thin"],
    );
    assert_refused(
        &[
            "bodies.A.geometry={block: {width: 1e-3, depth: 1e9}}",
            "bodies.A.boundaries={}",
        ],
        &["bodies.A.geometry.block", "width and depth of similar size"],
    );
}

/// A contact grid of 1e8 elements is refused before it is meshed.
#[test]
fn a_huge_generated_contact_segment_is_refused_before_it_is_built() {
    assert_refused(
        &["contact.grid.elements=100000000"],
        &["contact.grid.elements", "at most 20000"],
    );
}

/// A profile radius that a `geometry:` body implies is blamed on the key the user wrote: a
/// ring bore smaller than the roller names `bodies.A.geometry`, not a `radius` the case does
/// not have; a radius refused on its own is not blamed again on the pair.
#[test]
fn radius_messages_name_the_keys_the_case_has() {
    let case = crate::common::case_path("fig14_geometry");
    let case = case.to_str().unwrap();
    let (code, _, stderr) = crate::common::rollbem(&[
        "check",
        case,
        "--set",
        "bodies.A.geometry={ring: {bore: 150, rim: 200}}",
        "--set",
        "bodies.A.boundaries={rim: fixed, bore: free}",
    ]);
    assert_eq!(code, 1, "{stderr}");
    assert!(
        stderr.contains("bodies.A.geometry, bodies.B.geometry: internal contact"),
        "{stderr}"
    );
    assert!(!stderr.contains("bodies.A.radius"), "{stderr}");
    let (code, _, stderr) = crate::common::rollbem(&[
        "check",
        case,
        "--set",
        "bodies.A.geometry={roller: {radius: -150, shaft: 15}}",
    ]);
    assert_eq!(code, 1, "{stderr}");
    assert!(
        stderr.contains("bodies.A.geometry.roller.radius") && !stderr.contains("internal contact"),
        "{stderr}"
    );
}

/// A generated contact segment is cut into `contact.grid.elements` like a uniform grid, so it
/// needs the same 3 elements at least (one or two passed `check`, then `run` blamed the grid's
/// extent).
#[test]
fn a_generated_contact_segment_of_one_element_is_refused() {
    assert_refused(&["contact.grid.elements=1"], &["contact.grid.elements", "at least 3"]);
}

/// Proportions the generated mesh cannot represent are refused by the geometry's key with the
/// reason (they were blamed on "duplicated points", "a boundary that crosses itself" or a
/// missing support): a shaft or rim at 1e-12 or 1e29 of the other circle, a wall of 1e-4 mm
/// under a 150 mm roller (with the covered roller that models it), a cover leaving a core of
/// 1e-6 of its radius.
#[test]
fn proportions_the_generated_mesh_cannot_represent_are_refused() {
    let key = "bodies.A.geometry.roller";
    assert_refused(
        &["bodies.A.geometry.roller.shaft=1e-12"],
        &[key, "below 1e-3 of the outer"],
    );
    assert_refused(
        &["bodies.A.geometry.roller.radius=1e30"],
        &[key, "below 1e-3 of the outer"],
    );
    // A roller of radius 1e5 on its shaft of 15 broke down in the solve (`pressure[52]` is inf);
    // a cover is no remedy for a small shaft, so none is offered.
    assert_refused(
        &["bodies.A.geometry.roller.radius=1e5"],
        &[key, "below 1e-3 of the outer"],
    );
    let case = case_path("fig14_geometry");
    let (_, _, stderr) = rollbem(&[
        "check",
        case.to_str().unwrap(),
        "--set",
        "bodies.A.geometry.roller.radius=1e5",
    ]);
    assert!(!stderr.contains("covered_roller"), "{stderr}");
    assert_refused(
        &["bodies.A.geometry.roller.shaft=149.9999"],
        &[key, "wall", "covered_roller: {radius: 150, cover_thickness: 0.0001"],
    );
    assert_refused(
        &[
            "bodies.A.geometry={ring: {bore: 400, rim: 1e29}}",
            "bodies.A.boundaries={rim: fixed, bore: free}",
        ],
        &["bodies.A.geometry.ring", "below 1e-3 of the outer"],
    );
    assert_refused(
        &[
            "bodies.B.geometry={covered_roller: {radius: 100, cover_thickness: 99.9999}}",
            "bodies.B.boundaries={bonded: fixed}",
        ],
        &["bodies.B.geometry.covered_roller", "below 1e-3 of the outer"],
    );
}

/// The thinnest wall accepted runs: a roller of 150 on a shaft of 148 (wall 2 mm, just above a
/// tenth of its 19.6 mm far elements) is meshed and passes `check`.
#[test]
fn a_wall_just_above_the_limit_is_accepted() {
    let case = case_path("fig14_geometry");
    let (code, _, stderr) = rollbem(&[
        "check",
        case.to_str().unwrap(),
        "--set",
        "bodies.A.geometry.roller.shaft=148",
    ]);
    assert_eq!(code, 0, "{stderr}");
}

/// A generated roller in a generated ring: the ring's contact nodes are carried to the grid by
/// interpolation, and `check` told the user to mesh its contact group finer (the transfer
/// "loses accuracy (about 8 % of the creepage)") — advice about a mesh rollbem makes itself,
/// for a transfer that costs nothing measurable (see the message). It says so instead.
#[test]
fn check_does_not_ask_to_remesh_a_generated_body() {
    let dir = tempfile::tempdir().unwrap();
    let case = dir.path().join("case.yaml");
    std::fs::write(
        &case,
        r#"
materials:
  steel: {E: 210000.0, nu: 0.3}
bodies:
  A:
    model: bem
    geometry: {roller: {radius: 40, shaft: 10}}
    material: steel
    boundaries: {shaft: fixed, free: free}
  B:
    model: bem
    geometry: {ring: {bore: 50, rim: 65}}
    material: steel
    boundaries: {rim: fixed, bore: free}
contact:
  friction: 0.2
load:
  normal: {force: 28999.316802}
  tangential: {ratio: 0.5}
output: {dir: out}
"#,
    )
    .unwrap();
    let (code, stdout, stderr) = rollbem(&["check", case.to_str().unwrap()]);
    assert_eq!(code, 0, "{stderr}");
    let line = stdout
        .lines()
        .find(|l| l.contains("B: contact nodes"))
        .unwrap_or_else(|| panic!("{stdout}"));
    assert!(line.contains("transferred to the grid by interpolation"), "{line}");
    assert!(
        !line.contains("loses accuracy") && !line.contains("mesh the contact group"),
        "{line}"
    );
    assert!(line.contains("meshed by rollbem"), "{line}");
}
