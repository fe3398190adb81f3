//! The refusals that hang on a body's kind, asked of its capabilities (whether it deforms,
//! takes a viscoelastic material, gives interior fields, is a boundary element model, brings
//! its own contact elements, is a cover): each message whole, so that the checks keep saying
//! exactly what they said when they named the kinds themselves.

use crate::common::{self, rollbem};

const BASE: &str = r#"
title: "body kinds"
materials:
  steel: {E: 210000.0, nu: 0.3}
bodies:
  A: {model: half_space, material: steel, radius: 100.0}
  B: {model: layer, material: steel, radius: 100.0, thickness: 2}
contact:
  friction: 0.1
  grid: {elements: 21, extent: 1.3}
load:
  normal: {force: 1812.4573}
  tangential: {ratio: 0.51}
output: {dir: out}
"#;

/// `rollbem check` of `case` (BASE when None) with `--set` overrides: (exit code, stderr).
fn check(case: Option<&std::path::Path>, set: &[&str]) -> (i32, String) {
    let dir = tempfile::tempdir().unwrap();
    let path = match case {
        Some(p) => p.to_path_buf(),
        None => {
            let p = dir.path().join("case.yaml");
            std::fs::write(&p, BASE).unwrap();
            p
        }
    };
    let mut args = vec!["check".to_string(), path.to_string_lossy().into_owned()];
    for s in set {
        args.extend(["--set".to_string(), s.to_string()]);
    }
    let args: Vec<&str> = args.iter().map(String::as_str).collect();
    let (code, _, stderr) = rollbem(&args);
    (code, stderr)
}

/// Asserts exit 1 with every line of `lines` in the message.
fn assert_says(case: Option<&std::path::Path>, set: &[&str], lines: &[&str]) {
    let (code, stderr) = check(case, set);
    assert_eq!(code, 1, "{set:?}: {stderr}");
    for l in lines {
        assert!(stderr.contains(l), "{set:?}: does not say\n{l}\nbut\n{stderr}");
    }
}

#[test]
fn a_layer_has_no_interior_and_nothing_to_assess() {
    assert_says(
        None,
        &[
            "output.interior={body: B, x: [-1, 1, 5], y: [-1, -0.1, 3]}",
            "output.strength={bodies: [B]}",
        ],
        &[
            "output.interior.body: body B is a layer, whose model gives its surface only; ask for the other \
             body, or model the cover by `bem` (geometry: covered_roller)",
            "output.strength.bodies: body B is a layer, whose model gives its surface tractions only, not the \
             stresses inside the cover; model the cover by `bem` (geometry: covered_roller), or leave it out \
             of `bodies`",
        ],
    );
}

#[test]
fn a_rigid_body_has_no_interior_nothing_to_assess_and_presses_through_a_cover() {
    assert_says(
        None,
        &[
            "bodies.A={model: rigid, radius: 100}",
            "load.normal={overlap: 3}",
            "output.interior={body: A, x: [-1, 1, 5], y: [0.1, 1, 3]}",
            "output.strength={bodies: [A]}",
        ],
        &[
            "bodies.B.thickness: the cover is 2 thick but load.normal.overlap = 3 presses the rigid body A that \
             deep into it (1.500 times its thickness): linear elasticity describes compressions of a small \
             fraction of the cover; give a thicker cover or a smaller overlap",
            "output.interior.body: body A is rigid: it does not deform and has no interior stresses; ask for \
             a half_space or bem body",
            "output.strength.bodies: body A is rigid: it does not deform and has no stresses to assess; leave \
             it out of `bodies`",
        ],
    );
}

#[test]
fn two_rigid_bodies_are_refused_and_a_rigid_mesh_sets_no_grid() {
    assert_says(
        None,
        &[
            "bodies.A={model: rigid, radius: 100}",
            "bodies.B={model: rigid, mesh: m.msh}",
            "contact.grid.elements=2",
        ],
        &[
            "bodies: both bodies are rigid: at least one must be elastic",
            "contact.grid.elements: need at least 3 elements (value = 2)",
        ],
    );
    // A viscoelastic material on no deforming body asks for no speed.
    let (_, stderr) = check(
        None,
        &[
            "bodies.A={model: rigid, radius: 100}",
            "bodies.B={model: rigid, radius: 100}",
            "materials.steel.viscoelastic={E_rubbery: 100000, creep_time: 1}",
        ],
    );
    assert!(!stderr.contains("load.speed"), "{stderr}");
}

#[test]
fn a_viscoelastic_half_space_or_layer_needs_a_speed_and_friction_is_free_without_bem() {
    assert_says(
        None,
        &["materials.steel.viscoelastic={E_rubbery: 100000, creep_time: 1}"],
        &["load.speed: missing: a viscoelastic material with creep_time > 0 needs the rolling speed"],
    );
    let (code, stderr) = check(None, &["contact.friction=20", "contact.grid.element=constant"]);
    assert_eq!(code, 0, "{stderr}");
}

#[test]
fn a_bem_body_is_elastic_on_quadratic_elements_under_a_bounded_friction_and_sets_the_grid() {
    let case = common::case_path("fig14_true_geometry");
    assert_says(
        Some(&case),
        &[
            "materials.aluminium.viscoelastic={G_rubbery: 10000, creep_time: 0}",
            "contact.friction=20",
            "load.tangential={ratio: 0.5}",
            "contact.grid.element=constant",
        ],
        &[
            "bodies.A.material: material `aluminium` is viscoelastic, which rollbem models on `half_space` and \
             `layer` bodies only (the aged kernels); give this bem body an elastic material or model it as a \
             half_space (a cover on a rigid core: a layer)",
            "contact.grid.element: constant elements cannot be used with a bem body",
            "contact.friction: a friction coefficient of 20 with load.tangential.ratio = 0.5 asks a tangential \
             force Q = ratio·mu·P of 10 times the normal load, which the bem bodies cannot carry",
        ],
    );
    // Its mesh's contact elements are the grid: `elements` below the uniform grid's least is no fault.
    let (code, stderr) = check(Some(&case), &["contact.grid.elements=2"]);
    assert_eq!(code, 0, "{stderr}");
}
