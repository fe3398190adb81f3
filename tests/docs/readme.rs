//! README's worked example is what `rollbem run cases/carter_051.yaml` prints now, line by line:
//! every label and every number, but the times (machine and load), the results folder (the
//! test writes elsewhere) and the residual's digits below the tolerance (round-off, which
//! differs between processors).

use crate::common::rollbem_with;
use std::path::PathBuf;

/// The lines of README's ```text block that starts with the `$ cargo run` of the example.
fn quoted_run() -> Vec<String> {
    let root = PathBuf::from(env!("CARGO_MANIFEST_DIR"));
    let readme = std::fs::read_to_string(root.join("README.md")).unwrap();
    let start = "```text\n$ cargo run --release -- run cases/carter_051.yaml\n";
    let at = readme.find(start).expect("README's worked example") + start.len();
    let end = readme[at..].find("```").unwrap();
    readme[at..at + end].lines().map(str::to_string).collect()
}

/// (label, value) of a table row; the whole line otherwise.
fn split(line: &str) -> (String, String) {
    match line.strip_prefix("  ").and_then(|l| l.split_once("  ")) {
        Some((k, v)) => (k.trim().to_string(), v.trim().to_string()),
        None => (line.to_string(), String::new()),
    }
}

/// The solver row with its residual taken out: (text, residual).
fn residual(value: &str) -> (String, f64) {
    let (text, r) = value.rsplit_once("residual ").expect("a residual");
    (text.to_string(), r.parse().expect("a number"))
}

#[test]
fn readme_worked_example_is_what_the_run_prints() {
    let root = PathBuf::from(env!("CARGO_MANIFEST_DIR"));
    let out = tempfile::tempdir().unwrap();
    let (code, stdout, stderr) = rollbem_with(
        Some(&root),
        &[],
        &["run", "cases/carter_051.yaml", "--out", out.path().to_str().unwrap()],
    );
    assert_eq!(code, 0, "{stderr}");
    let printed: Vec<&str> = stdout.lines().collect();
    let quoted = quoted_run();
    assert_eq!(
        quoted.len(),
        printed.len(),
        "README quotes {} lines, the run prints {}:\n{stdout}",
        quoted.len(),
        printed.len()
    );
    for (q, p) in quoted.iter().zip(&printed) {
        let ((qk, qv), (pk, pv)) = (split(q), split(p));
        assert_eq!(qk, pk, "README's row `{q}` against the printed `{p}`");
        match qk.as_str() {
            "time [s]" | "results" => {}
            "solver" => {
                let ((qt, qr), (pt, pr)) = (residual(&qv), residual(&pv));
                assert_eq!(qt, pt, "README's solver row `{q}` against `{p}`");
                assert!(qr < 1e-12 && pr < 1e-12, "residuals at round-off: {qr:e}, {pr:e}");
            }
            _ => assert_eq!(qv, pv, "README's row `{q}` against the printed `{p}`"),
        }
    }
}
