//! What `rollbem run` refuses in a case's `transient:` section (cases/README.md, "Transient
//! rolling"): each bad value by its key, exit code 1, nothing written.

use crate::common::rollbem;

const BASE: &str = r#"
title: "transient input validation"
materials:
  steel: {E: 210000.0, nu: 0.3}
  rubber: {E: 10.0, nu: 0.45, viscoelastic: {E_rubbery: 5.0, creep_time: 0.01}}
bodies:
  A: {model: half_space, material: steel, radius: 100.0}
  B: {model: half_space, material: steel, radius: 100.0}
contact:
  friction: 0.3
  grid: {elements: 21, extent: 1.3}
load:
  normal: {force: 1812.4573}
  tangential: {ratio: 0.6}
transient:
  steps: 5
output: {dir: out}
"#;

/// Runs BASE with `--set` overrides: (exit code, stderr, whether the output folder exists).
fn run(set: &[&str]) -> (i32, String, bool) {
    let dir = tempfile::tempdir().unwrap();
    let case = dir.path().join("case.yaml");
    std::fs::write(&case, BASE).unwrap();
    let mut args = vec!["run", case.to_str().unwrap()];
    for s in set {
        args.extend(["--set", s]);
    }
    let (code, _, stderr) = rollbem(&args);
    (code, stderr, dir.path().join("out").exists())
}

/// Asserts exit 1, the key and every `also` named, nothing written.
fn assert_refused(set: &[&str], key: &str, also: &[&str]) {
    let (code, stderr, written) = run(set);
    assert_eq!(code, 1, "{set:?}: {stderr}");
    assert!(stderr.contains(key), "{set:?}: does not name `{key}`: {stderr}");
    for a in also {
        assert!(stderr.contains(a), "{set:?}: does not say `{a}`: {stderr}");
    }
    assert!(!stderr.contains("panicked"), "{stderr}");
    assert!(!written, "{set:?}: output written");
}

#[test]
fn a_history_with_good_keys_runs() {
    let (code, stderr, written) = run(&[
        "transient.shift={ratio: 0.6}",
        "transient.tangential={ratio: [0.1, 0.2, 0.3, 0.4, 0.5]}",
    ]);
    assert_eq!(code, 0, "{stderr}");
    assert!(written);
    let (code, stderr, _) = run(&[
        "transient.tangential={creep: [[0, 0], [0.1, 0.001]]}",
        "transient.step=0.02",
    ]);
    assert_eq!(code, 0, "{stderr}");
    let (code, stderr, _) = run(&[
        "load.speed=1000",
        "transient.time_step=2e-5",
        "transient.normal={overlap: 0.05}",
    ]);
    assert_eq!(code, 0, "{stderr}");
    let (code, stderr, _) = run(&[
        "transient.normal={force: {sine: {mean: 1812.4573, amplitude: 181.2, wavelength: 0.5, phase: 0.3}}}",
        "transient.tangential={creep: 0.001}",
    ]);
    assert_eq!(code, 0, "{stderr}");
}

#[test]
fn bad_steps_are_refused_by_key() {
    assert_refused(&["transient.steps=0"], "transient.steps", &["1..="]);
    assert_refused(&["transient.write_every=0"], "transient.write_every", &[">= 1"]);
    assert_refused(&["transient.step=-0.01"], "transient.step", &["positive"]);
    assert_refused(&["transient.step=0"], "transient.step", &["positive"]);
    assert_refused(&["transient.step=5"], "transient.step", &["contact"]);
    assert_refused(&["transient.time_step=1e-5"], "transient.time_step", &["load.speed"]);
    assert_refused(
        &["transient.step=0.01", "transient.time_step=1e-5", "load.speed=1000"],
        "transient.step",
        &["not both"],
    );
}

#[test]
fn bad_controls_are_refused_by_key() {
    assert_refused(
        &["transient.tangential={ratio: 1.2}"],
        "transient.tangential.ratio",
        &["< 1"],
    );
    assert_refused(
        &["transient.tangential={ratio: 0.5, creep: 0.001}"],
        "transient.tangential",
        &["exactly one"],
    );
    assert_refused(
        &["transient.tangential={ratio: [0.1, 0.2]}"],
        "transient.tangential.ratio",
        &["5"],
    );
    assert_refused(
        &["transient.tangential={ratio: [[0, 0.1], [0, 0.2]]}"],
        "transient.tangential.ratio",
        &["increase"],
    );
    assert_refused(
        &["transient.normal={force: [[0, 100], [1, -5]]}"],
        "transient.normal.force",
        &["positive"],
    );
    assert_refused(
        &["transient.tangential={ratio: abc}"],
        "transient.tangential.ratio",
        &["a list of numbers"],
    );
    assert_refused(&["transient.shift={ratio: -1}"], "transient.shift.ratio", &["< 1"]);
    assert_refused(
        &["transient.normal={force: {sine: {mean: 1800, amplitude: 180, wavelength: 0}}}"],
        "transient.normal.force",
        &["wavelength", "positive"],
    );
    assert_refused(
        &["transient.normal={force: {sine: {mean: 100, amplitude: 150, wavelength: 5}}}"],
        "transient.normal.force",
        &["positive"],
    );
    assert_refused(
        &["transient.tangential={ratio: {sine: {mean: 0.5, amplitude: 0.6, wavelength: 5}}}"],
        "transient.tangential.ratio",
        &["< 1"],
    );
    assert_refused(
        &["transient.normal={force: {sine: {mean: 1800, amplitude: 180}}}"],
        "transient.normal.force",
        &["sine"],
    );
    assert_refused(&["transient.shift={}"], "transient.shift", &["exactly one"]);
}

#[test]
fn what_a_history_cannot_follow_is_refused_by_key() {
    assert_refused(
        &["contact.grid.tolerance=1e-3"],
        "contact.grid.tolerance",
        &["one grid"],
    );
    assert_refused(
        &[
            "bodies.B={model: half_space, material: rubber, radius: 100.0}",
            "load.speed=100",
        ],
        "bodies.B.material",
        &["viscoelastic"],
    );
}
