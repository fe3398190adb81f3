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

/// The `rollbem check` output quoted in docs/choosing-a-model.md: each quoted row (continuation
/// lines joined, a trailing `...` standing for the rest of the row) begins a row that `check`
/// prints now, white space aside.
#[test]
fn choosing_a_model_quotes_what_check_prints() {
    let root = PathBuf::from(env!("CARGO_MANIFEST_DIR"));
    let page = std::fs::read_to_string(root.join("docs/choosing-a-model.md")).unwrap();
    let start = page.find("```text\n$ rollbem check").expect("the quoted check runs") + 8;
    let block = &page[start..start + page[start..].find("```").unwrap()];
    let squeeze = |s: &str| s.split_whitespace().collect::<Vec<_>>().join(" ");
    let mut runs: Vec<(Vec<String>, Vec<String>)> = Vec::new();
    for line in block.lines() {
        if let Some(command) = line.strip_prefix("$ rollbem ") {
            runs.push((command.split_whitespace().map(str::to_string).collect(), Vec::new()));
        } else if line.starts_with("                  ") {
            let rows = &mut runs.last_mut().unwrap().1;
            let last = rows.pop().unwrap();
            rows.push(format!("{last} {}", line.trim()));
        } else {
            runs.last_mut().unwrap().1.push(line.to_string());
        }
    }
    assert_eq!(runs.len(), 4);
    for (args, rows) in runs {
        let args: Vec<&str> = args.iter().map(String::as_str).collect();
        let (code, stdout, stderr) = rollbem_with(Some(&root), &[], &args);
        assert_eq!(code, 0, "{stderr}");
        let printed: Vec<String> = stdout.lines().map(squeeze).collect();
        for row in rows {
            let quoted = squeeze(&row);
            let prefix = quoted.trim_end_matches("...").trim_end();
            assert!(
                printed.iter().any(|p| p.starts_with(prefix)),
                "rollbem {}: no printed row begins with\n  {prefix}\nprinted:\n{stdout}",
                args.join(" ")
            );
        }
    }
}
