//! What `rollbem run` and `rollbem check` refuse in `contact.falling_friction`
//! (src/contact/falling.rs, cases/README.md): a kinetic coefficient above the static one, a slip
//! velocity ≤ 0, a missing rolling speed, a method other than `newton`. Each is exit code 1 with
//! the key named and nothing written; a valid law passes `check` (also with a transient
//! history, which takes the law in its rolling steps).

use crate::common::rollbem;

const BASE: &str = r#"
title: "falling friction input validation"
materials:
  steel: {E: 210000.0, nu: 0.3}
bodies:
  A: {model: half_space, material: steel, radius: 100.0}
  B: {model: half_space, material: steel, radius: 100.0}
contact:
  friction: 0.3
  falling_friction: {kinetic: 0.1, slip_velocity: 0.3}
  grid: {elements: 21, extent: 1.3}
load:
  normal: {force: 1812.4573}
  tangential: {ratio: 0.5}
  speed: 100.0
output: {dir: out}
"#;

/// Runs `verb` on BASE with `--set` overrides: (exit code, stderr, whether the output exists).
fn run(verb: &str, set: &[&str]) -> (i32, String, bool) {
    let dir = tempfile::tempdir().unwrap();
    let case = dir.path().join("case.yaml");
    std::fs::write(&case, BASE).unwrap();
    let mut args = vec![verb, case.to_str().unwrap()];
    for s in set {
        args.push("--set");
        args.push(s);
    }
    let (code, _, stderr) = rollbem(&args);
    (code, stderr, dir.path().join("out").exists())
}

/// Exit 1 from `run` and `check`, `key` and every `also` named, nothing written.
fn assert_refused(set: &[&str], key: &str, also: &[&str]) {
    for verb in ["run", "check"] {
        let (code, stderr, written) = run(verb, set);
        assert_eq!(code, 1, "{verb} {set:?}: {stderr}");
        assert!(stderr.contains(key), "{verb} {set:?}: does not name `{key}`: {stderr}");
        for a in also {
            assert!(stderr.contains(a), "{verb} {set:?}: does not say `{a}`: {stderr}");
        }
        assert!(!stderr.contains("panicked"), "{stderr}");
        assert!(!written, "{verb} {set:?}: output written");
    }
}

#[test]
fn a_valid_falling_law_passes_check() {
    let (code, stderr, _) = run("check", &[]);
    assert_eq!(code, 0, "{stderr}");
    // μ_k = μ_s (constant friction written as a law) is valid too.
    let (code, stderr, _) = run("check", &["contact.falling_friction.kinetic=0.3"]);
    assert_eq!(code, 0, "{stderr}");
    // A second exponential.
    let (code, stderr, _) = run(
        "check",
        &["contact.falling_friction.second={share: 0.25, slip_velocity: 2000.0}"],
    );
    assert_eq!(code, 0, "{stderr}");
    // A transient history takes the law in its rolling steps.
    let (code, stderr, _) = run("check", &["transient={steps: 3}"]);
    assert_eq!(code, 0, "{stderr}");
}

#[test]
fn falling_friction_keys_are_checked() {
    assert_refused(
        &["contact.falling_friction.kinetic=0.4"],
        "contact.falling_friction.kinetic",
        &["[0, contact.friction = 0.3]"],
    );
    assert_refused(
        &["contact.falling_friction.kinetic=-0.1"],
        "contact.falling_friction.kinetic",
        &[],
    );
    for sh in ["0", "-1"] {
        assert_refused(
            &[&format!("contact.falling_friction.slip_velocity={sh}")],
            "contact.falling_friction.slip_velocity",
            &["> 0"],
        );
    }
    assert_refused(&["load.speed=null"], "load.speed", &["missing", "falling_friction"]);
    assert_refused(
        &["contact.falling_friction.second={share: 1.5, slip_velocity: 10.0}"],
        "contact.falling_friction.second.share",
        &["[0, 1]", "1.5"],
    );
    assert_refused(
        &["contact.falling_friction.second={share: 0.5, slip_velocity: 0}"],
        "contact.falling_friction.second.slip_velocity",
        &["> 0"],
    );
    for method in ["gauss_seidel", "norm_tang", "newton_plain"] {
        assert_refused(
            &[&format!("solver.method={method}")],
            "solver.method",
            &[method, "constant friction"],
        );
    }
    assert_refused(
        &["contact.falling_friction={kinetic: 0.1, slip_velocity: 0.3, shape: 2}"],
        "contact",
        &["shape"],
    );
}
