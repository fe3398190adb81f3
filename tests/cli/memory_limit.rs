//! Runs under an address-space limit (`ulimit -v`), as batch schedulers set one: a case that
//! fits runs (faer's matrix-multiply kernel reserved a buffer of twice the L3 size the system
//! reports per thread — 960 MiB on the development machine — and aborted every solve under
//! 1 GB; vendor/README.md), and a case that does not fit is refused by the memory estimate,
//! naming the key to lower, instead of failing an allocation inside the solver.

use crate::common::case_path;
use std::process::Command;

/// `rollbem args…` under `ulimit -v kb`: exit code, stdout, stderr.
fn rollbem_limited(kb: u64, args: &[&str]) -> (i32, String, String) {
    let out = Command::new("bash")
        .arg("-c")
        .arg(format!("ulimit -v {kb} && exec \"$0\" \"$@\""))
        .arg(env!("CARGO_BIN_EXE_rollbem"))
        .args(args)
        .output()
        .expect("bash runs");
    (
        out.status.code().unwrap_or(-1),
        String::from_utf8_lossy(&out.stdout).into_owned(),
        String::from_utf8_lossy(&out.stderr).into_owned(),
    )
}

#[cfg(target_os = "linux")]
#[test]
fn a_case_that_fits_runs_under_an_address_space_limit_of_1_gb() {
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("hertz");
    let case = case_path("hertz");
    let (code, stdout, stderr) = rollbem_limited(
        1_000_000,
        &["run", case.to_str().unwrap(), "--out", out.to_str().unwrap()],
    );
    assert_eq!(code, 0, "stdout:\n{stdout}\nstderr:\n{stderr}");
    assert!(out.join("contact.csv").is_file());
}

#[cfg(target_os = "linux")]
#[test]
fn a_case_larger_than_the_address_space_limit_is_refused_by_its_estimate() {
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("large");
    let case = case_path("carter_051");
    let (code, _, stderr) = rollbem_limited(
        2_000_000,
        &[
            "run",
            case.to_str().unwrap(),
            "--set",
            "contact.grid.elements=2000",
            "--out",
            out.to_str().unwrap(),
        ],
    );
    assert_eq!(code, 1, "stderr:\n{stderr}");
    assert!(
        stderr.contains("memory") && stderr.contains("contact.grid.elements"),
        "{stderr}"
    );
    assert!(
        !stderr.contains("internal error") && !stderr.contains("panicked"),
        "{stderr}"
    );
    assert!(!out.join("contact.csv").exists(), "nothing is written");
}

/// An error-controlled BEM run is estimated on the grid its tolerance is expected to need, not
/// on its element limit: carter_051_true at 1e-4 (a peak of about 100 MB) runs under 1 GB. (It
/// was estimated at 3.4 GB for max_elements and refused.)
#[cfg(target_os = "linux")]
#[test]
fn an_error_controlled_bem_run_is_estimated_for_its_tolerance_and_runs_under_1_gb() {
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("true");
    let case = case_path("carter_051_true");
    let args = [
        "run",
        case.to_str().unwrap(),
        "--set",
        "contact.grid.tolerance=1e-4",
        "--out",
        out.to_str().unwrap(),
    ];
    let (code, stdout, stderr) = rollbem_limited(1_000_000, &args);
    assert_eq!(code, 0, "stdout:\n{stdout}\nstderr:\n{stderr}");
}

/// What the run asks before each finer grid: a grid whose matrices fit, and one that never
/// could (a million elements: about 10^15 bytes of contact matrices).
#[test]
fn a_finer_grid_is_asked_whether_it_fits_in_memory() {
    let loaded = rollbem::case::load(&case_path("carter_051_true"), &[]).unwrap();
    let scene = rollbem::scene::Scene::from_case(&loaded).unwrap();
    let fits = |n| rollbem::scene::preflight::grid_fits_in_memory(&scene.case, &scene.bodies, n);
    assert!(fits(42));
    assert!(!fits(1_000_000));
}

/// The measured peak [MB] that docs/reliability.md records for an error-controlled case (its
/// table of error-controlled runs: `| NAME at TOL | expected | estimate | grid | peak | … |`).
fn documented_peak_mb(row: &str) -> f64 {
    let docs = std::fs::read_to_string(concat!(env!("CARGO_MANIFEST_DIR"), "/docs/reliability.md")).unwrap();
    let line = docs
        .lines()
        .find(|l| l.starts_with(&format!("| {row} |")))
        .unwrap_or_else(|| panic!("docs/reliability.md has no row `{row}`"));
    let cells: Vec<&str> = line.split('|').map(str::trim).collect();
    cells[5].parse().unwrap_or_else(|_| panic!("no peak in `{line}`"))
}

/// The estimate of an error-controlled BEM run is that of the peak its tolerance needs: within
/// a factor 2 of the peak docs/reliability.md records for carter_051_true at 1e-4 (110 MB;
/// the estimate was 410 MB, sized as if the rollers' meshes followed the final grid with every
/// transition and the bisected check at their largest).
#[test]
fn the_estimate_of_carter_051_true_at_1e_4_is_within_twice_its_documented_peak() {
    let set = ["contact.grid.tolerance=1e-4".to_string()];
    let loaded = rollbem::case::load(&case_path("carter_051_true"), &set).unwrap();
    let bodies = rollbem::scene::registry::setups_of_case(&loaded).unwrap();
    let sizes = rollbem::scene::preflight::problem_sizes(&loaded, &bodies);
    let estimate = rollbem::limits::MemoryEstimate::of(&sizes).bytes() / 1e6;
    let peak = documented_peak_mb("carter_051_true at 1e-4");
    assert!(
        (0.5 * peak..=2.0 * peak).contains(&estimate),
        "estimate {estimate:.0} MB against the documented peak {peak:.0} MB"
    );
}
