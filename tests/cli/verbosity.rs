//! A run that talks: quiet when quick, its progress when long, every Newton step with `-v`, the
//! solver's restarts as a warning, nothing but errors with `-q`.

use crate::common::{rollbem, rollbem_with};
use std::path::{Path, PathBuf};

fn carter(dir: &Path) -> (PathBuf, PathBuf) {
    let case = dir.join("case.yaml");
    std::fs::write(&case, crate::common::CARTER_CASE).unwrap();
    (case, dir.join("out"))
}

fn summary(out: &Path) -> serde_json::Value {
    serde_json::from_str(&std::fs::read_to_string(out.join("summary.json")).unwrap()).unwrap()
}

#[test]
fn a_quick_run_prints_only_its_table() {
    let dir = tempfile::tempdir().unwrap();
    let (case, out) = carter(dir.path());
    let (code, stdout, stderr) = rollbem(&["run", case.to_str().unwrap(), "--out", out.to_str().unwrap()]);
    assert_eq!(code, 0, "{stderr}");
    assert!(stdout.contains("normal force P"), "{stdout}");
    assert_eq!(stderr, "", "a run of milliseconds says nothing on stderr");
}

#[test]
fn verbose_prints_every_newton_step_with_its_residual() {
    let dir = tempfile::tempdir().unwrap();
    let (case, out) = carter(dir.path());
    let (code, _, stderr) = rollbem(&["run", case.to_str().unwrap(), "--out", out.to_str().unwrap(), "-v"]);
    assert_eq!(code, 0, "{stderr}");
    let s = summary(&out);
    let history = s["solver"]["history"].as_array().unwrap();
    // The run's own steps come before the fixed grid's error estimate solves on its halving.
    let run_lines = stderr.split("error estimate of the fixed grid").next().unwrap();
    assert!(stderr.contains("error estimate of the fixed grid"), "{stderr}");
    let steps: Vec<&str> = run_lines.lines().filter(|l| l.contains("Newton step")).collect();
    assert_eq!(steps.len(), history.len(), "one line per Newton step:\n{stderr}");
    // Each line carries the residual after its step: the last one is the run's.
    let last = steps.last().unwrap();
    let printed = format!("scaled residual {:.2e}", s["residual"].as_f64().unwrap());
    assert!(last.contains(&printed), "`{last}` should say {printed}");
    assert!(stderr.contains("solving: newton, 63 contact nodes"), "{stderr}");
    assert!(stderr.lines().all(|l| l.starts_with("info: [")), "{stderr}");
}

#[test]
fn a_long_run_shows_its_progress_and_a_sweep_does_not() {
    let dir = tempfile::tempdir().unwrap();
    let (case, out) = carter(dir.path());
    // Progress appears once a run has taken longer than ROLLBEM_PROGRESS_AFTER seconds (default
    // 1): with 0 this quick run counts as long. stderr is a pipe here: plain lines.
    let (code, _, stderr) = rollbem_with(
        None,
        &[("ROLLBEM_PROGRESS_AFTER", "0")],
        &["run", case.to_str().unwrap(), "--out", out.to_str().unwrap()],
    );
    assert_eq!(code, 0, "{stderr}");
    assert!(stderr.starts_with("progress: ["), "{stderr}");
    // A sweep runs in parallel: no progress line of its runs.
    let sweep = dir.path().join("sweep");
    let (code, _, stderr) = rollbem_with(
        None,
        &[("ROLLBEM_PROGRESS_AFTER", "0")],
        &[
            "sweep",
            case.to_str().unwrap(),
            "--vary",
            "contact.friction=0.1,0.2",
            "--out",
            sweep.to_str().unwrap(),
        ],
    );
    assert_eq!(code, 0, "{stderr}");
    assert!(!stderr.contains("progress:"), "{stderr}");
}

/// Penalties 10⁴ times the automatic ones with 10 steps per attempt stall every attempt (each
/// spends its budget): each restart of the default method is tried and the warning names them
/// all, as summary.json does. (An unreachable tolerance no longer does: the run stops at
/// round-off without restarts, tests/cli/stall.rs.)
#[test]
fn restarts_are_warnings_and_quiet_keeps_only_the_error() {
    let dir = tempfile::tempdir().unwrap();
    let (case, out) = carter(dir.path());
    let args = [
        "run",
        case.to_str().unwrap(),
        "--out",
        out.to_str().unwrap(),
        "--set",
        "solver.penalty=1e4",
        "--set",
        "solver.max_iterations=10",
    ];
    let (code, stdout, stderr) = rollbem(&args);
    assert_eq!(code, 2, "{stderr}");
    let fallbacks: Vec<String> = summary(&out)["solver"]["fallbacks"]
        .as_array()
        .unwrap()
        .iter()
        .map(|f| f.as_str().unwrap().to_string())
        .collect();
    assert!(!fallbacks.is_empty());
    let warning = stderr
        .lines()
        .find(|l| l.starts_with("warning: the Newton method stalled and restarted"))
        .unwrap_or_else(|| panic!("no warning of the restarts:\n{stderr}"));
    for f in &fallbacks {
        assert!(warning.contains(f.as_str()), "`{warning}` lacks `{f}`");
    }
    let restarts = format!("after {} restart", fallbacks.len());
    assert!(
        stdout.contains(&restarts),
        "the table's solver row says {restarts}:\n{stdout}"
    );

    let mut quiet = args.to_vec();
    quiet.push("-q");
    let (code, _, stderr) = rollbem(&quiet);
    assert_eq!(code, 2);
    assert!(
        stderr.lines().all(|l| l.starts_with("error: ")),
        "-q prints errors only:\n{stderr}"
    );
}

/// `check` estimates time and memory for the grid the case asks for (not a fixed one).
#[test]
fn check_estimates_the_cost_of_the_cases_own_grid() {
    let dir = tempfile::tempdir().unwrap();
    let (case, _) = carter(dir.path());
    let cost = |elements: &str| {
        let set = format!("contact.grid.elements={elements}");
        // The grid's own cost, without the error estimate's solve on its halving.
        let no_estimate = "contact.grid.estimate=false";
        let (code, stdout, stderr) = rollbem(&["check", case.to_str().unwrap(), "--set", &set, "--set", no_estimate]);
        assert_eq!(code, 0, "{stderr}");
        stdout
            .lines()
            .find(|l| l.trim_start().starts_with("cost of this run"))
            .unwrap_or_else(|| panic!("no cost line:\n{stdout}"))
            .to_string()
    };
    let small = cost("21");
    assert!(small.contains("(63 contact nodes"), "{small}");
    assert!(small.contains(" ms, "), "{small}");
    // The run of 2001 elements took about 3 minutes and ~10 GB.
    let large = cost("2001");
    assert!(large.contains("(6003 contact nodes"), "{large}");
    assert!(large.contains(" min, ") && large.contains(" GB"), "{large}");
}

/// `-q` prints nothing on stderr but errors, as its help says, also for a run whose inputs
/// leave a model's validity (a rubber cover strained to half its modulus): the warning stays in
/// summary.json; without `-q` it is printed.
#[test]
fn quiet_runs_keep_their_warnings_in_the_summary() {
    let dir = tempfile::tempdir().unwrap();
    let case = crate::common::case_path("covered_roller_v_peak");
    let out = dir.path().join("q");
    let (code, _, stderr) = rollbem(&["run", case.to_str().unwrap(), "--out", out.to_str().unwrap(), "-q"]);
    assert_eq!(code, 0, "{stderr}");
    assert!(stderr.trim().is_empty(), "-q printed:\n{stderr}");
    let summary: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(out.join("summary.json")).unwrap()).unwrap();
    assert!(
        !summary["warnings"].as_array().unwrap().is_empty(),
        "the warning is in summary.json"
    );
    let loud = dir.path().join("loud");
    let (code, _, stderr) = rollbem(&["run", case.to_str().unwrap(), "--out", loud.to_str().unwrap()]);
    assert_eq!(code, 0);
    assert!(stderr.contains("warning: body B"), "{stderr}");
}
