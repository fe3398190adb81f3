//! What `rollbem run` and `rollbem check` refuse before solving, and what never reaches an output:
//! finite values whose derived quantities overflow, NaN and infinities in any key, YAML tags,
//! grids too coarse to hold the contact, loads beyond the radius, cases that do not fit in
//! memory, and contact segments that do not cover the grid. Each refusal is exit code 1 with the
//! file and the key (or mesh) named, and writes nothing.

use std::path::{Path, PathBuf};

use crate::common::{self, rollbem};

const BASE: &str = r#"
title: "input validation"
materials:
  steel: {E: 210000.0, nu: 0.3}
bodies:
  A: {model: half_space, material: steel, radius: 100.0}
  B: {model: half_space, material: steel, radius: 100.0}
contact:
  friction: 0.1
  grid: {elements: 21, extent: 1.3}
load:
  normal: {force: 1812.4573}
  tangential: {ratio: 0.51}
output: {dir: out}
"#;

fn write_case(dir: &Path, text: &str) -> PathBuf {
    let path = dir.join("case.yaml");
    std::fs::write(&path, text).unwrap();
    path
}

/// Runs `verb` on BASE (with `replace` applied) and `--set` overrides: (exit code, stderr, whether
/// the output folder exists).
fn run_base(verb: &str, replace: Option<(&str, &str)>, set: &[&str]) -> (i32, String, bool) {
    let dir = tempfile::tempdir().unwrap();
    let text = match replace {
        Some((from, to)) => {
            assert!(BASE.contains(from), "BASE lacks {from}");
            BASE.replacen(from, to, 1)
        }
        None => BASE.to_string(),
    };
    let case = write_case(dir.path(), &text);
    let mut args = vec![verb, case.to_str().unwrap()];
    for s in set {
        args.push("--set");
        args.push(s);
    }
    let (code, _, stderr) = rollbem(&args);
    (code, stderr, dir.path().join("out").exists())
}

/// Asserts exit 1 from `run` and `check`, the key and every `also` named, nothing written.
fn assert_refused(set: &[&str], key: &str, also: &[&str]) {
    for verb in ["run", "check"] {
        let (code, stderr, written) = run_base(verb, None, set);
        assert_eq!(code, 1, "{verb} {set:?}: {stderr}");
        assert!(stderr.contains(key), "{verb} {set:?}: does not name `{key}`: {stderr}");
        assert!(
            stderr.contains("case.yaml"),
            "{verb} {set:?}: does not name the file: {stderr}"
        );
        for a in also {
            assert!(stderr.contains(a), "{verb} {set:?}: does not say `{a}`: {stderr}");
        }
        assert!(!stderr.contains("panicked"), "{stderr}");
        assert!(!written, "{verb} {set:?}: output written");
    }
}

/// Finite values that passed validation and then panicked on NaN grid edges (exit 101).
#[test]
fn finite_values_whose_derived_quantities_overflow_are_refused_by_key() {
    assert_refused(
        &["materials.steel.E=1.7976931348623157e308"],
        "materials.steel.E",
        &["1e30"],
    );
    assert_refused(&["bodies.B.radius=5e-324"], "bodies.B.radius", &["5e-324"]);
    assert_refused(&["contact.grid.extent=1.79e308"], "contact.grid.extent", &["1.79e308"]);
    assert_refused(&["load.normal.force=1.79e308"], "load.normal.force", &[]);
    assert_refused(
        &["contact.grid.half_length=1e29"],
        "contact.grid.half_length",
        &["node spacing"],
    );
    assert_refused(
        &["load.normal={overlap: 60}"],
        "load.normal.overlap",
        &["effective radius"],
    );
    assert_refused(&["solver.tolerance=.nan"], "solver.tolerance", &[]);
}

/// `elements = 1 or 2` and a > R used to end in "increase contact.grid.extent", which cannot help.
#[test]
fn coarse_grids_and_loads_beyond_the_radius_get_the_right_advice() {
    for n in ["1", "2"] {
        let set = format!("contact.grid.elements={n}");
        assert_refused(&[set.as_str()], "contact.grid.elements", &["at least 3"]);
        let (_, stderr, _) = run_base("run", None, &[set.as_str()]);
        assert!(!stderr.contains("Increase contact.grid.extent"), "{stderr}");
    }
    assert_refused(
        &["load.normal.force=1e9"],
        "load.normal.force",
        &["effective radius", "a/R"],
    );
    let (_, stderr, _) = run_base("run", None, &["load.normal.force=1e9"]);
    assert!(!stderr.contains("extent"), "{stderr}");
}

#[test]
fn nan_and_infinity_are_refused_in_any_key() {
    let overlap = "load.normal={overlap: 0.01}";
    assert_refused(
        &[overlap, "load.tangential={force: .nan}"],
        "load.tangential.force",
        &["finite"],
    );
    assert_refused(
        &[overlap, "load.tangential={force: .inf}"],
        "load.tangential.force",
        &["finite"],
    );
    assert_refused(
        &["output.interior={body: A, x: [-.inf, .inf, 5], y: [0.1, 1, 3]}"],
        "output.interior.x[0]",
        &["finite"],
    );
    assert_refused(&["materials.steel.nu=.nan"], "materials.steel.nu", &["finite"]);
    // In the file itself as well as through --set.
    let (code, stderr, written) = run_base("run", Some(("friction: 0.1", "friction: .nan")), &[]);
    assert_eq!(code, 1, "{stderr}");
    assert!(
        stderr.contains("contact.friction") && stderr.contains("finite"),
        "{stderr}"
    );
    assert!(!written);
}

/// `friction: !weird 0.1` was read as 0.1 with the tag silently dropped.
#[test]
fn yaml_tags_are_refused() {
    let (code, stderr, written) = run_base("run", Some(("friction: 0.1", "friction: !weird 0.1")), &[]);
    assert_eq!(code, 1, "{stderr}");
    assert!(
        stderr.contains("contact.friction") && stderr.contains("`!weird`"),
        "{stderr}"
    );
    assert!(!written);
    assert_refused(&["solver.penalty=!auto 1"], "solver.penalty", &["tag"]);
}

/// 100 000 elements ask for about 25 TB of dense matrices: refused before anything is
/// allocated, naming the key and the estimate; so is a 10 000 x 10 000 interior grid.
#[test]
fn cases_beyond_the_memory_are_refused_before_allocating() {
    assert_refused(
        &["contact.grid.elements=100000"],
        "contact.grid.elements",
        &["TB", "available", "now 100000"],
    );
    assert_refused(
        &["output.interior={body: A, x: [-2, 2, 10000], y: [0.05, 3, 10000]}"],
        "output.interior",
        &["GB", "available", "100000000"],
    );
    let dir = tempfile::tempdir().unwrap();
    let case = write_case(dir.path(), BASE);
    let (code, stdout, stderr) = rollbem(&["check", case.to_str().unwrap()]);
    assert_eq!(code, 0, "{stderr}");
    assert!(stdout.contains("memory estimate"), "{stdout}");
}

/// Degenerate but finite inputs: whatever the exit code, no output holds NaN, and summary.json
/// holds no `null` where a number belongs (a NaN residual used to be written as `null`).
#[test]
fn degenerate_inputs_never_leave_nan_or_null_in_outputs() {
    for set in [
        "load.normal.force=1e-300",
        "materials.steel.E=1e-300",
        "contact.grid.half_length=1e-300",
        "contact.grid.half_length=1e300",
        "load.normal={overlap: 1e-300}",
        "load.normal={overlap: 1e300}",
    ] {
        let dir = tempfile::tempdir().unwrap();
        let case = write_case(dir.path(), BASE);
        let (code, _, stderr) = rollbem(&["run", case.to_str().unwrap(), "--set", set]);
        assert!([0, 1, 2].contains(&code), "{set}: exit {code}: {stderr}");
        let out = dir.path().join("out");
        if let Ok(text) = std::fs::read_to_string(out.join("summary.json")) {
            let summary: serde_json::Value = serde_json::from_str(&text).unwrap();
            for key in [
                "residual",
                "normal_force",
                "tangential_force",
                "overlap",
                "creep",
                "max_pressure",
            ] {
                assert!(
                    summary[key].is_number(),
                    "{set}: summary.json `{key}` = {}",
                    summary[key]
                );
            }
            for (i, record) in summary["solver"]["history"].as_array().unwrap().iter().enumerate() {
                assert!(record["residual"].is_number(), "{set}: history[{i}] = {record}");
            }
        }
        if let Ok(csv) = std::fs::read_to_string(out.join("contact.csv")) {
            assert!(
                !csv.to_lowercase().contains("nan") && !csv.contains("inf"),
                "{set}: {csv}"
            );
        }
    }
}

/// Two bem bodies whose contact groups differ: the second must cover the grid the first gives.
/// The message used to name neither the case nor the meshes.
#[test]
fn a_contact_segment_shorter_than_the_grid_names_the_case_and_the_meshes() {
    let dir = tempfile::tempdir().unwrap();
    let case = common::case_path("carter_051_true_nonmatching");
    let out = dir.path().join("out");
    for verb in ["check", "run"] {
        let mut args = vec![verb, case.to_str().unwrap()];
        if verb == "run" {
            args.extend(["--out", out.to_str().unwrap()]);
        }
        // A's contact group (x in ±1.5) is now longer than B's (±1.235).
        args.extend([
            "--set",
            "bodies.A.mesh=../meshes/roller_r100_shaft10_B_nonmatching.msh",
            "--set",
            "bodies.B.mesh=../meshes/roller_r100_shaft10_B.msh",
        ]);
        let (code, _, stderr) = rollbem(&args);
        assert_eq!(code, 1, "{verb}: {stderr}");
        for part in [
            "carter_051_true_nonmatching.yaml",
            "bodies.B.mesh",
            "roller_r100_shaft10_B_nonmatching.msh",
            "roller_r100_shaft10_B.msh",
            "covers only",
        ] {
            assert!(stderr.contains(part), "{verb}: does not say `{part}`: {stderr}");
        }
        assert!(!out.exists());
    }
}

/// With a bem body the grid is the mesh's contact group: the advice is to lengthen that group
/// (or lower the load), not to change contact.grid keys that are not used.
#[test]
fn a_contact_beyond_a_bem_grid_names_the_mesh() {
    let dir = tempfile::tempdir().unwrap();
    let case = common::case_path("carter_051_true");
    let (code, _, stderr) = rollbem(&[
        "run",
        case.to_str().unwrap(),
        "--out",
        dir.path().join("out").to_str().unwrap(),
        "--set",
        "load.normal.force=4500",
    ]);
    assert_eq!(code, 1, "{stderr}");
    assert!(
        stderr.contains("roller_r100_shaft10_A.msh") && stderr.contains("group `contact`"),
        "{stderr}"
    );
    assert!(!stderr.contains("contact.grid.extent"), "{stderr}");
}

#[test]
fn error_controlled_grid_keys_are_checked() {
    assert_refused(
        &["contact.grid.tolerance=0"],
        "contact.grid.tolerance",
        &["1e-4 is typical"],
    );
    assert_refused(&["contact.grid.tolerance=2"], "contact.grid.tolerance", &[]);
    assert_refused(
        &["contact.grid.tolerance=1e-3", "contact.grid.max_elements=30"],
        "contact.grid.max_elements",
        &["twice"],
    );
}

/// The run ends with exit code 2 and the estimate; what it writes (the best grid's summary,
/// marked not converged) is tested in tests/cli/validity.rs.
#[test]
fn an_unreachable_tolerance_exits_2_with_the_estimate() {
    let (code, stderr, written) = run_base(
        "run",
        None,
        &["contact.grid.tolerance=1e-6", "contact.grid.max_elements=60"],
    );
    assert_eq!(code, 2, "{stderr}");
    for s in ["contact.grid.max_elements = 60", "estimates are", "mu p0"] {
        assert!(stderr.contains(s), "does not say `{s}`: {stderr}");
    }
    assert!(written, "the best grid's summary.json is written");
}

#[test]
fn check_describes_the_error_controlled_grid() {
    let case = crate::common::case_path("carter2d_contact");
    let (code, stdout, stderr) = rollbem(&["check", case.to_str().unwrap(), "--set", "contact.grid.tolerance=1e-4"]);
    assert_eq!(code, 0, "{stderr}");
    assert!(
        stdout.contains("contact.grid.tolerance 1e-4") && stdout.contains("at most 1000 elements"),
        "{stdout}"
    );
    assert!(stdout.contains("for the start grid"), "{stdout}");
}

/// A `--set` value the key cannot take is blamed on the `--set` option (not on the case file)
/// in words, not Rust's type names; `--set KEY=null` removes the key, so a body's model can be
/// switched; a null enum in the file says what to write.
#[test]
fn set_errors_name_the_option_in_words_and_null_removes_a_key() {
    for (set, says) in [
        ("contact.friction=abc", "expected a number"),
        ("contact.grid.elements=2.5", "expected a whole number"),
    ] {
        for verb in ["run", "check"] {
            let (code, stderr, written) = run_base(verb, None, &[set]);
            assert_eq!(code, 1, "{verb} {set}: {stderr}");
            assert!(
                stderr.contains(&format!("--set {set}")) && stderr.contains(says),
                "{verb} {set}: {stderr}"
            );
            assert!(
                !stderr.contains("case.yaml") && !stderr.contains("f64") && !stderr.contains("usize"),
                "{verb} {set}: {stderr}"
            );
            assert!(!written);
        }
    }
    let (code, stderr, _) = run_base("check", None, &["bodies.A.model=rigid"]);
    assert_eq!(code, 1, "{stderr}");
    assert!(stderr.contains("unknown field `material`"), "{stderr}");
    let (code, stderr, _) = run_base("check", None, &["bodies.A.model=rigid", "bodies.A.material=null"]);
    assert_eq!(code, 0, "{stderr}");
    // Removing a key that is not there changes nothing.
    let (code, stderr, _) = run_base("check", None, &["output.interior=null", "units=null"]);
    assert_eq!(code, 0, "{stderr}");
    let (code, stderr, _) = run_base(
        "check",
        Some(("  friction: 0.1\n", "  friction: 0.1\n  traction_axes: null\n")),
        &[],
    );
    assert_eq!(code, 1, "{stderr}");
    assert!(
        stderr.contains("contact.traction_axes") && stderr.contains("leave the key out") && !stderr.contains("Value::"),
        "{stderr}"
    );
}

/// A standard linear solid's keys: a rubbery modulus above the glassy one, a negative creep
/// time, the other kind of modulus than the glassy one, a missing or non-positive rolling
/// speed, and a viscoelastic material on a `bem` body are each refused by key.
#[test]
fn viscoelastic_keys_are_checked() {
    let sls = |rubbery: &str, time: &str| format!("materials.steel.viscoelastic={{{rubbery}, creep_time: {time}}}");
    assert_refused(
        &[&sls("E_rubbery: 300000", "1"), "load.speed=10"],
        "materials.steel.viscoelastic.E_rubbery",
        &["exceeds the glassy"],
    );
    assert_refused(
        &[&sls("E_rubbery: 100000", "-1"), "load.speed=10"],
        "materials.steel.viscoelastic.creep_time",
        &["must be >= 0"],
    );
    assert_refused(
        &[&sls("G_rubbery: 30000", "1"), "load.speed=10"],
        "materials.steel.viscoelastic.E_rubbery",
        &["same kind"],
    );
    assert_refused(
        &[&sls("E_rubbery: 100000", "1")],
        "load.speed",
        &["missing", "creep_time > 0"],
    );
    assert_refused(
        &[&sls("E_rubbery: 100000", "1"), "load.speed=0"],
        "load.speed",
        &["> 0"],
    );
    // Beyond the physical range the ageing's exponentials underflow or overflow (a run of
    // either used to end with exit 2 and a NaN): refused by key.
    for time in ["1e-300", "1e300"] {
        assert_refused(
            &[&sls("E_rubbery: 100000", time), "load.speed=10"],
            "materials.steel.viscoelastic.creep_time",
            &["lies outside", "check the units"],
        );
    }
    for speed in ["1e-300", "1e300"] {
        assert_refused(
            &[&sls("E_rubbery: 100000", "1"), &format!("load.speed={speed}")],
            "load.speed",
            &["lies outside", "check the units"],
        );
    }
    // τc = 0 (the rubbery elastic material) needs no speed.
    let (code, stderr, _) = run_base("check", None, &[&sls("E_rubbery: 100000", "0")]);
    assert_eq!(code, 0, "{stderr}");
    // A bem body cannot take a viscoelastic material.
    let case = common::case_path("fig14_true_geometry");
    let (code, _, stderr) = rollbem(&[
        "check",
        case.to_str().unwrap(),
        "--set",
        "materials.aluminium.viscoelastic={G_rubbery: 10000, creep_time: 1}",
        "--set",
        "load.speed=3",
    ]);
    assert_eq!(code, 1, "{stderr}");
    assert!(
        stderr.contains("bodies.A.material") && stderr.contains("`half_space` and `layer` bodies"),
        "{stderr}"
    );
    // Nor does the advice send a viscoelastic body to bem.
    let case = common::case_path("visc_cylindr_tc0009");
    let (code, stdout, _) = rollbem(&["check", case.to_str().unwrap()]);
    assert_eq!(code, 0);
    assert!(
        !stdout.contains("use bem") && !stdout.contains("model the bodies with `model: bem`"),
        "{stdout}"
    );
    assert!(
        stdout.contains("bem is elastic") && stdout.contains("elastic only"),
        "{stdout}"
    );
}

/// A `layer` body's keys: a thickness that is not positive or not below half its radius, an
/// undefined material, a viscoelastic cover without a rolling speed, and an interior grid asked
/// of it are each refused by key; a valid one passes `check`.
#[test]
fn layer_keys_are_checked() {
    let layer =
        |thickness: &str| format!("bodies.B={{model: layer, material: steel, radius: 100.0, thickness: {thickness}}}");
    assert_refused(&[&layer("0")], "bodies.B.thickness", &["must be positive"]);
    assert_refused(&[&layer("60")], "bodies.B.thickness", &["below R/2", "covered_roller"]);
    assert_refused(
        &["bodies.B={model: layer, material: rubber, radius: 100.0, thickness: 2}"],
        "bodies.B.material",
        &["not defined"],
    );
    assert_refused(
        &[
            &layer("2"),
            "materials.steel.viscoelastic={E_rubbery: 100000, creep_time: 1}",
        ],
        "load.speed",
        &["missing"],
    );
    assert_refused(
        &[
            &layer("2"),
            "output.interior={body: B, x: [-1, 1, 5], y: [-1, -0.1, 3]}",
        ],
        "output.interior.body",
        &["surface only"],
    );
    let (code, stderr, _) = run_base("check", None, &[&layer("2")]);
    assert_eq!(code, 0, "{stderr}");
}

/// Constant elements with a tolerance are refused up front with the reason (their estimate
/// overstates the error tenfold, so the grid would refine to its limit).
#[test]
fn constant_elements_with_a_tolerance_are_refused() {
    assert_refused(
        &["contact.grid.element=constant", "contact.grid.tolerance=1e-4"],
        "contact.grid.element",
        &["quadratic elements", "discontinuous_quadratic"],
    );
    let (code, stderr, _) = run_base("check", None, &["contact.grid.element=constant"]);
    assert_eq!(code, 0, "a fixed grid of constant elements stays allowed: {stderr}");
}

/// A friction coefficient far beyond Coulomb's law under a tangential load given as Q/(μP):
/// the force asked, Q = ratio·μ·P, is hundreds of times the normal load, and the solution broke
/// down (exit 2, nothing written: an infinite residual for the rubber tyre at μ = 1e3, `slip[0]`
/// = −inf at 1e5, an infinite residual for the true-geometry rollers at 1e6). Refused by key
/// before solving; a large μ still stands in for a stuck contact under Q = 0 (the free rolling
/// of the reference checks), a force or a creepage, and for the closed-form models.
#[test]
fn a_large_friction_under_a_tangential_ratio_is_refused() {
    for (name, mu) in [
        ("tyre_b05_compressible", "1e3"),
        ("tyre_b05_compressible", "1e5"),
        ("fig14_true_geometry", "1e6"),
        ("fig14_true_geometry", "11"),
    ] {
        let case = common::case_path(name);
        let set = format!("contact.friction={mu}");
        for verb in ["check", "run"] {
            let dir = tempfile::tempdir().unwrap();
            let out = dir.path().join("out");
            let mut args = vec![verb, case.to_str().unwrap(), "--set", set.as_str()];
            if verb == "run" {
                args.extend(["--out", out.to_str().unwrap()]);
            }
            let (code, _, stderr) = rollbem(&args);
            assert_eq!(code, 1, "{verb} {name} {set}: {stderr}");
            assert!(
                stderr.contains("contact.friction") && stderr.contains("load.tangential.ratio"),
                "{stderr}"
            );
            assert!(!out.exists(), "{verb} {name} {set}: output written");
        }
    }
    // The half-spaces of Carter's case solve under a ratio at any friction (docs/performance.md).
    for set in [
        ["contact.friction=1e3", "load.tangential={ratio: 0.51}"],
        ["contact.friction=1e3", "load.tangential={ratio: 0}"],
        ["contact.friction=1e3", "load.tangential={force: 100}"],
        ["contact.friction=10", "load.tangential={ratio: 0.51}"],
    ] {
        let (code, stderr, _) = run_base("check", None, &set);
        assert_eq!(code, 0, "{set:?}: {stderr}");
    }
}
