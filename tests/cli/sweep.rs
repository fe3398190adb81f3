//! `rollbem sweep`: 15-run product, failure isolation, sharding and merging.

use crate::common::rollbem;
use std::path::Path;
use std::process::Command;

fn case() -> String {
    format!("{}/cases/dissimilar_beta0288_075.yaml", env!("CARGO_MANIFEST_DIR"))
}

/// Rows of sweep.csv without the wall-clock and folder columns.
fn rows(path: &Path) -> Vec<Vec<String>> {
    let mut r = csv::Reader::from_path(path).unwrap();
    let header: Vec<String> = r.headers().unwrap().iter().map(String::from).collect();
    let keep: Vec<usize> = (0..header.len())
        .filter(|&i| !header[i].ends_with("_s") && header[i] != "folder")
        .collect();
    r.records()
        .map(|rec| keep.iter().map(|&i| rec.as_ref().unwrap()[i].to_string()).collect())
        .collect()
}

/// Asserts that two sweep tables hold the same results: the same runs, statuses, values,
/// regimes and zone counts, and numbers within 1e-7 of their column's largest magnitude. The
/// runs of a sweep start from their neighbours' solutions, and a sweep's shards or a resumed
/// sweep chain its runs otherwise: the results agree to the Newton tolerance (1e-10 on the
/// scaled residual), the iteration counts and residuals differ.
fn assert_same_results(a: &Path, b: &Path) {
    assert_same_results_except(a, b, &[]);
}

/// [`assert_same_results`] without the columns `skip`.
fn assert_same_results_except(a: &Path, b: &Path, skip: &[&str]) {
    let (ra, rb) = (rows(a), rows(b));
    let mut r = csv::Reader::from_path(a).unwrap();
    let header: Vec<String> = r
        .headers()
        .unwrap()
        .iter()
        .filter(|h| !h.ends_with("_s") && *h != "folder")
        .map(String::from)
        .collect();
    assert_eq!(ra.len(), rb.len(), "{} against {}", a.display(), b.display());
    for (c, name) in header.iter().enumerate() {
        if name == "iterations" || name == "residual" || skip.contains(&name.as_str()) {
            continue;
        }
        let scale = ra
            .iter()
            .filter_map(|row| row[c].parse::<f64>().ok())
            .fold(0.0f64, |m, v| m.max(v.abs()));
        for (x, y) in ra.iter().zip(&rb) {
            match (x[c].parse::<f64>(), y[c].parse::<f64>()) {
                (Ok(u), Ok(v)) => assert!((u - v).abs() <= 1e-7 * scale, "{name}: {x:?} against {y:?}"),
                _ => assert_eq!(x[c], y[c], "{name}"),
            }
        }
    }
}

fn pvd_entries(path: &Path) -> usize {
    std::fs::read_to_string(path).unwrap().matches("<DataSet").count()
}

const MU: &str = "contact.friction=0.1,0.2,0.3,0.4,0.8";
const RATIO: &str = "load.tangential.ratio=0.2,0.5,0.75";

/// The 15-run sweep (5 μ × 3 Q/μP) into `out`.
fn full_sweep(out: &Path) -> (i32, String, String) {
    rollbem(&[
        "sweep",
        "--per-run-files",
        &case(),
        "--vary",
        MU,
        "--vary",
        RATIO,
        "--out",
        out.to_str().unwrap(),
    ])
}

#[test]
fn fifteen_runs_write_fifteen_rows_and_pvd_entries() {
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("sw");
    let (code, stdout, stderr) = full_sweep(&out);
    assert_eq!(code, 0, "{stdout}{stderr}");
    let r = rows(&out.join("sweep.csv"));
    assert_eq!(r.len(), 15);
    assert!(r.iter().all(|row| row[1] == "ok"));
    assert_eq!(pvd_entries(&out.join("sweep.pvd")), 15);
    for k in 0..15 {
        assert!(out.join(format!("run_{k:04}/contact.vtu")).exists());
    }
    // The varied values are in the table, first --vary slowest.
    assert_eq!((r[1][2].as_str(), r[1][3].as_str()), ("0.1", "0.5"));
}

#[test]
fn a_failing_run_is_recorded_and_the_others_complete() {
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("sw");
    // Q = 0.06 P is full sliding only for μ = 0.05: exactly one of the 15 runs fails.
    let p = 470.805575;
    let q = format!("load.tangential.force={},{},{}", 0.01 * p, 0.03 * p, 0.06 * p);
    let (code, _, stderr) = rollbem(&[
        "sweep",
        "--per-run-files",
        &case(),
        "--set",
        "load.tangential.ratio=null",
        "--vary",
        "contact.friction=0.05,0.2,0.3,0.4,0.8",
        "--vary",
        &q,
        "--out",
        out.to_str().unwrap(),
    ]);
    assert_eq!(code, 2, "{stderr}");
    let r = rows(&out.join("sweep.csv"));
    assert_eq!(r.len(), 15);
    let failed: Vec<_> = r.iter().filter(|row| row[1] == "failed").collect();
    assert_eq!(failed.len(), 1, "{r:?}");
    assert!(failed[0][4].contains("load.tangential.force"), "{:?}", failed[0]);
    assert_eq!(pvd_entries(&out.join("sweep.pvd")), 14);
    assert!(stderr.contains("run_0002"), "{stderr}");
}

#[test]
fn four_shards_merged_equal_the_unsharded_sweep() {
    let dir = tempfile::tempdir().unwrap();
    let whole = dir.path().join("whole");
    let (code, _, stderr) = full_sweep(&whole);
    assert_eq!(code, 0, "{stderr}");
    // Four separate processes, each into its own folder (as on four machines).
    let children: Vec<_> = (1..=4)
        .map(|k| {
            let out = dir.path().join(format!("shard{k}"));
            Command::new(env!("CARGO_BIN_EXE_rollbem"))
                .args([
                    "sweep",
                    "--per-run-files",
                    &case(),
                    "--vary",
                    MU,
                    "--vary",
                    RATIO,
                    "--shard",
                    &format!("{k}/4"),
                    "--out",
                ])
                .arg(&out)
                .spawn()
                .unwrap()
        })
        .collect();
    for mut c in children {
        assert!(c.wait().unwrap().success());
    }
    let merged = dir.path().join("merged");
    let shard_dirs: Vec<String> = (1..=4)
        .map(|k| dir.path().join(format!("shard{k}")).to_string_lossy().into_owned())
        .collect();
    let mut args = vec!["sweep", "--merge"];
    args.extend(shard_dirs.iter().map(String::as_str));
    args.extend(["--out", merged.to_str().unwrap()]);
    let (code, _, stderr) = rollbem(&args);
    assert_eq!(code, 0, "{stderr}");
    assert_same_results(&merged.join("sweep.csv"), &whole.join("sweep.csv"));
    assert_eq!(pvd_entries(&merged.join("sweep.pvd")), 15);
    // The merged .pvd points at the shards' run folders.
    let pvd = std::fs::read_to_string(merged.join("sweep.pvd")).unwrap();
    assert!(pvd.contains("../shard2/run_0001/contact.vtu"), "{pvd}");
}

#[test]
fn bad_sweep_arguments_are_input_errors() {
    let (code, _, stderr) = rollbem(&["sweep", &case(), "--vary", "contact.friction"]);
    assert_eq!(code, 1);
    assert!(stderr.contains("--vary contact.friction"), "{stderr}");
    let (code, _, stderr) = rollbem(&["sweep", &case(), "--vary", MU, "--shard", "5/4"]);
    assert_eq!(code, 1);
    assert!(stderr.contains("--shard 5/4"), "{stderr}");
}

/// As [`rollbem`], with extra environment (the fault injection of the tests).
fn rollbem_env(env: &[(&str, &str)], args: &[&str]) -> (i32, String, String) {
    crate::common::rollbem_with(None, env, args)
}

/// Hidden entries of a folder (locks, temporaries).
fn hidden(dir: &Path) -> Vec<String> {
    let mut names: Vec<String> = std::fs::read_dir(dir)
        .unwrap()
        .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
        .filter(|n| n.starts_with('.') && n != ".rollbem-manifest")
        .collect();
    names.sort();
    names
}

#[test]
fn a_killed_sweep_keeps_its_finished_runs_and_resume_runs_only_the_rest() {
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("sw");
    let args = [
        "sweep",
        "--per-run-files",
        &case(),
        "--vary",
        MU,
        "--vary",
        RATIO,
        "--out",
        out.to_str().unwrap(),
    ];
    // Killed (abort: no cleanup) while writing the last run, which every thread reaches last.
    let (code, _, _) = rollbem_env(&[("ROLLBEM_TEST_FAULT", "abort@run_0014")], &args);
    assert_ne!(code, 0);
    assert_ne!(code, 2);
    // The table holds the runs that finished, as they finished; run 14's temporary folder stays.
    let done = rows(&out.join("sweep.csv"));
    assert!((1..15).contains(&done.len()), "{} rows", done.len());
    assert!(done.iter().all(|r| r[1] == "ok"), "{done:?}");
    assert!(
        hidden(&out).iter().any(|n| n.starts_with(".run_0014.partial-")),
        "{:?}",
        hidden(&out)
    );
    let (code, stdout, stderr) = rollbem(&[&args[..], &["--resume"]].concat());
    assert_eq!(code, 0, "{stdout}{stderr}");
    assert!(
        stdout.contains(&format!("({} kept from the interrupted sweep)", done.len())),
        "{stdout}"
    );
    // Complete, in run order, equal to an uninterrupted sweep; no temporaries or locks left.
    let whole = dir.path().join("whole");
    let (code, _, stderr) = full_sweep(&whole);
    assert_eq!(code, 0, "{stderr}");
    assert_same_results(&out.join("sweep.csv"), &whole.join("sweep.csv"));
    assert_eq!(pvd_entries(&out.join("sweep.pvd")), 15);
    assert!(hidden(&out).is_empty(), "{:?}", hidden(&out));
    assert!(hidden(dir.path()).is_empty(), "{:?}", hidden(dir.path()));
    // --resume of another sweep into this folder is refused, naming the difference.
    let (code, _, stderr) = rollbem(&[
        "sweep",
        "--per-run-files",
        &case(),
        "--vary",
        "contact.friction=0.1,0.2",
        "--out",
        out.to_str().unwrap(),
        "--resume",
    ]);
    assert_eq!(code, 1);
    assert!(
        stderr.contains("belongs to another sweep") && stderr.contains("varied values differ"),
        "{stderr}"
    );
    // Without --resume a new sweep replaces the earlier one whole.
    let (code, _, stderr) = rollbem(&[
        "sweep",
        "--per-run-files",
        &case(),
        "--vary",
        "contact.friction=0.1,0.2",
        "--out",
        out.to_str().unwrap(),
    ]);
    assert_eq!(code, 0, "{stderr}");
    assert_eq!(rows(&out.join("sweep.csv")).len(), 2);
    assert!(!out.join("run_0002").exists());
}

#[test]
fn a_panicking_run_is_recorded_as_an_internal_error_and_the_sweep_exits_3() {
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("sw");
    let (code, _, stderr) = rollbem_env(
        &[("ROLLBEM_TEST_FAULT", "panic@run_0002")],
        &[
            "sweep",
            "--per-run-files",
            &case(),
            "--vary",
            MU,
            "--out",
            out.to_str().unwrap(),
        ],
    );
    assert_eq!(code, 3, "{stderr}");
    let r = rows(&out.join("sweep.csv"));
    assert_eq!(r.len(), 5);
    assert_eq!(r[2][1], "failed");
    assert!(r[2][3].contains("internal error — please report"), "{:?}", r[2]);
    assert!(r.iter().enumerate().all(|(i, row)| i == 2 || row[1] == "ok"));
    assert!(!out.join("run_0002").exists());
    assert!(hidden(&out).is_empty(), "{:?}", hidden(&out));
}

/// Runs shard K of N of the 5-run friction sweep (`values` as the friction list) into `out`.
fn shard(values: &str, k: usize, n: usize, out: &Path) -> (i32, String, String) {
    rollbem(&[
        "sweep",
        "--per-run-files",
        &case(),
        "--vary",
        values,
        "--shard",
        &format!("{k}/{n}"),
        "--out",
        out.to_str().unwrap(),
    ])
}

#[test]
fn merge_refuses_incomplete_mixed_malformed_and_empty_shard_sets() {
    let dir = tempfile::tempdir().unwrap();
    let (a, b, other) = (dir.path().join("a"), dir.path().join("b"), dir.path().join("other"));
    assert_eq!(shard(MU, 1, 2, &a).0, 0);
    assert_eq!(shard(MU, 2, 2, &b).0, 0);
    // The same keys, other values: shard 2 of another sweep.
    assert_eq!(shard("contact.friction=0.1,0.2,0.3,0.4,0.9", 2, 2, &other).0, 0);
    let merged = dir.path().join("merged");
    let merge = |dirs: &[&Path]| {
        let mut args: Vec<String> = vec!["sweep".into(), "--merge".into()];
        args.extend(dirs.iter().map(|d| d.to_string_lossy().into_owned()));
        args.extend(["--out".into(), merged.to_string_lossy().into_owned()]);
        rollbem(&args.iter().map(String::as_str).collect::<Vec<_>>())
    };
    let refused = |dirs: &[&Path], says: &[&str]| {
        let (code, stdout, stderr) = merge(dirs);
        assert_eq!(code, 1, "{says:?}: {stdout}{stderr}");
        for s in says {
            assert!(stderr.contains(s), "expected `{s}` in: {stderr}");
        }
        assert!(!merged.join("sweep.csv").exists());
    };
    refused(&[&a], &["incomplete", "2/2 missing"]);
    refused(&[&a, &other], &["different sweeps", "varied values differ"]);
    // The same shard twice (a copy of b's table and record).
    let copy = dir.path().join("copy");
    std::fs::create_dir(&copy).unwrap();
    for f in ["sweep_shard_2_of_2.csv", "sweep_shard_2_of_2.json"] {
        std::fs::copy(b.join(f), copy.join(f)).unwrap();
    }
    refused(&[&a, &b, &copy], &["shard 2/2 is given twice"]);
    let table = b.join("sweep_shard_2_of_2.csv");
    let good = std::fs::read_to_string(&table).unwrap();
    // A shard that was killed after one of its two runs.
    let mut lines: Vec<&str> = good.lines().collect();
    lines.pop();
    std::fs::write(&table, lines.join("\n") + "\n").unwrap();
    refused(&[&a, &b], &["shard 2/2 is incomplete", "run_0003"]);
    // Malformed tables are named, never a panic.
    for text in ["run\n0\n", "run,folder\n0,x\n"] {
        std::fs::write(&table, text).unwrap();
        refused(&[&a, &b], &["sweep_shard_2_of_2.csv", "header"]);
    }
    std::fs::write(&table, good.replacen("\n1,", "\nx,", 1)).unwrap();
    refused(&[&a, &b], &["line 2", "not a number"]);
    std::fs::write(&table, "").unwrap();
    refused(&[&a, &b], &["sweep_shard_2_of_2.csv is empty"]);
    std::fs::write(&table, &good).unwrap();
    std::fs::remove_file(b.join("sweep_shard_2_of_2.json")).unwrap();
    refused(&[&a, &b], &["no record sweep_shard_2_of_2.json"]);
    // Rerun, the set merges.
    assert_eq!(shard(MU, 2, 2, &b).0, 0);
    let (code, _, stderr) = merge(&[&a, &b]);
    assert_eq!(code, 0, "{stderr}");
    assert_eq!(rows(&merged.join("sweep.csv")).len(), 5);
}

#[test]
fn shards_share_a_folder_and_a_second_writer_is_refused() {
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("shared");
    // Three shards at once into one folder.
    let children: Vec<_> = (1..=3)
        .map(|k| {
            Command::new(env!("CARGO_BIN_EXE_rollbem"))
                .args([
                    "sweep",
                    "--per-run-files",
                    &case(),
                    "--vary",
                    MU,
                    "--vary",
                    RATIO,
                    "--shard",
                    &format!("{k}/3"),
                    "--out",
                ])
                .arg(&out)
                .env_remove("ROLLBEM_TEST_FAULT")
                .output()
                .unwrap()
        })
        .collect();
    for c in &children {
        assert!(c.status.success(), "{}", String::from_utf8_lossy(&c.stderr));
    }
    let (code, _, stderr) = rollbem(&["sweep", "--merge", out.to_str().unwrap()]);
    assert_eq!(code, 0, "{stderr}");
    assert_eq!(rows(&out.join("sweep.csv")).len(), 15);
    // A shard of another split into that folder is refused.
    let (code, _, stderr) = shard(MU, 1, 2, &out);
    assert_eq!(code, 1);
    assert!(stderr.contains("belongs to another sweep"), "{stderr}");
    // A second sweep while one writes the folder: refused at once; the first one's runs are all
    // valid (a lost race must never mark a run failed).
    let busy = dir.path().join("busy");
    let many = "contact.friction=0.1,0.12,0.14,0.16,0.18,0.2,0.25,0.3,0.35,0.4,0.5,0.6,0.7,0.8";
    let mut first = Command::new(env!("CARGO_BIN_EXE_rollbem"))
        .args([
            "sweep",
            "--per-run-files",
            &case(),
            "--vary",
            many,
            "--vary",
            RATIO,
            "--out",
        ])
        .arg(&busy)
        .env_remove("ROLLBEM_TEST_FAULT")
        .stdout(std::process::Stdio::null())
        .stderr(std::process::Stdio::null())
        .spawn()
        .unwrap();
    let start = std::time::Instant::now();
    while !busy.join("sweep.json").exists() && start.elapsed().as_secs() < 60 {
        std::thread::sleep(std::time::Duration::from_millis(2));
    }
    let (code, _, stderr) = rollbem(&[
        "sweep",
        "--per-run-files",
        &case(),
        "--vary",
        many,
        "--vary",
        RATIO,
        "--out",
        busy.to_str().unwrap(),
    ]);
    let first_code = first.wait().unwrap().code();
    assert_eq!(first_code, Some(0));
    let r = rows(&busy.join("sweep.csv"));
    assert_eq!(r.len(), 42);
    assert!(r.iter().all(|row| row[1] == "ok"));
    // The second one started while the first held the folder (it writes sweep.json first and
    // runs 42 solves after it).
    assert_eq!(code, 1, "{stderr}");
    assert!(stderr.contains("being written by another rollbem process"), "{stderr}");
}

/// Every `--vary` key and value is applied to the case once before the first run: a misspelt
/// key, a value of the wrong type or a key varied twice is exit 1 with nothing written (each run
/// used to fail alike, exit 2, a folder written); a `--vary` of a `--set` key is a warning.
#[test]
fn vary_keys_are_checked_before_any_run() {
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("sw");
    let o = out.to_str().unwrap();
    for (args, says) in [
        (
            vec!["--vary", "contact.frictio=0.1,0.2"],
            vec!["--vary contact.frictio", "unknown field `frictio`"],
        ),
        (
            vec![
                "--vary",
                "contact.friction=0.1,0.2",
                "--vary",
                "contact.grid.elements=21,2.5",
            ],
            vec!["--vary contact.grid.elements", "`2.5`", "expected a whole number"],
        ),
        (
            vec!["--vary", "contact.friction=0.1,0.2", "--vary", "contact.friction=0.3"],
            vec!["--vary contact.friction is given twice"],
        ),
    ] {
        let mut all = vec!["sweep", case_str(), "--out", o];
        all.extend(&args);
        let (code, stdout, stderr) = rollbem(&all);
        assert_eq!(code, 1, "{args:?}: {stdout}{stderr}");
        for s in &says {
            assert!(stderr.contains(s), "{args:?}: expected `{s}` in {stderr}");
        }
        assert!(!out.exists(), "{args:?}: a folder was written");
        assert_eq!(std::fs::read_dir(dir.path()).unwrap().count(), 0, "{args:?}");
    }
    let (code, _, stderr) = rollbem(&[
        "sweep",
        "--per-run-files",
        case_str(),
        "--set",
        "contact.friction=0.9",
        "--vary",
        "contact.friction=0.3,0.4",
        "--out",
        o,
    ]);
    assert_eq!(code, 0, "{stderr}");
    assert!(
        stderr.contains("--vary contact.friction overrides --set contact.friction=0.9"),
        "{stderr}"
    );
    let r = rows(&out.join("sweep.csv"));
    assert_eq!((r[0][2].as_str(), r[1][2].as_str()), ("0.3", "0.4"));
}

/// The case as a `&'static str` (for argument lists).
fn case_str() -> &'static str {
    Box::leak(case().into_boxed_str())
}

/// Runs rollbem under `ulimit -v` (KiB of address space) through `sh -c`.
fn rollbem_limited(kib: u64, args: &[&str]) -> (i32, String, String) {
    let mut cmd = Command::new("sh");
    cmd.arg("-c")
        .arg(format!("ulimit -v {kib} && exec \"$0\" \"$@\""))
        .arg(env!("CARGO_BIN_EXE_rollbem"))
        .args(args)
        .env_remove("ROLLBEM_TEST_FAULT");
    let out = cmd.output().unwrap();
    (
        out.status.code().unwrap_or(-1),
        String::from_utf8_lossy(&out.stdout).into_owned(),
        String::from_utf8_lossy(&out.stderr).into_owned(),
    )
}

/// `KEY=v0,v1,…` with `n` values `start + i·step`.
fn values(key: &str, n: usize, start: f64, step: f64) -> String {
    let v: Vec<String> = (0..n).map(|i| format!("{}", start + i as f64 * step)).collect();
    format!("{key}={}", v.join(","))
}

/// The runs are counted with overflow checks and generated one at a time: 10⁹ runs are refused
/// at once with the count and the limit (the whole product was built first and aborted under
/// 4 GiB), and one shard of an 8-million-run sweep runs its one run under 2 GiB.
#[test]
fn huge_sweeps_are_refused_and_a_shard_of_a_large_one_costs_its_slice() {
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("sw");
    let (mu, ratio, extent) = (
        values("contact.friction", 1000, 0.1, 1e-4),
        values("load.tangential.ratio", 1000, 0.2, 1e-4),
        values("contact.grid.extent", 1000, 1.3, 1e-3),
    );
    let (code, stdout, stderr) = rollbem_limited(
        4 << 20,
        &[
            "sweep",
            "--per-run-files",
            &case(),
            "--vary",
            &mu,
            "--vary",
            &ratio,
            "--vary",
            &extent,
            "--shard",
            "1/1000000000",
            "--out",
            out.to_str().unwrap(),
        ],
    );
    assert_eq!(code, 1, "{stdout}{stderr}");
    assert!(
        stderr.contains("1000 × 1000 × 1000") && stderr.contains("at most 10000000 runs"),
        "{stderr}"
    );
    assert!(!out.exists());
    let (mu, ratio, extent) = (
        values("contact.friction", 200, 0.1, 1e-4),
        values("load.tangential.ratio", 200, 0.2, 1e-4),
        values("contact.grid.extent", 200, 1.3, 1e-3),
    );
    let (code, stdout, stderr) = rollbem_limited(
        2 << 20,
        &[
            "sweep",
            "--per-run-files",
            &case(),
            "--vary",
            &mu,
            "--vary",
            &ratio,
            "--vary",
            &extent,
            "--shard",
            "1/8000000",
            "--out",
            out.to_str().unwrap(),
        ],
    );
    assert_eq!(code, 0, "{stdout}{stderr}");
    assert!(stdout.contains("1 of 8000000 runs"), "{stdout}");
    let r = rows(&out.join("sweep_shard_1_of_8000000.csv"));
    assert_eq!(r.len(), 1);
    assert_eq!((r[0][0].as_str(), r[0][1].as_str()), ("0", "ok"));
}

/// `--resume` trusts a table only with its record: without sweep.json it cannot tell the table
/// from another sweep's (it kept another case's runs, exit 0).
#[test]
fn resume_refuses_a_table_without_its_record() {
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("sw");
    let o = out.to_str().unwrap();
    let (code, _, stderr) = rollbem(&[
        "sweep",
        "--per-run-files",
        &case(),
        "--vary",
        "contact.friction=0.1,0.2",
        "--out",
        o,
    ]);
    assert_eq!(code, 0, "{stderr}");
    std::fs::remove_file(out.join("sweep.json")).unwrap();
    let before = std::fs::read_to_string(out.join("sweep.csv")).unwrap();
    let other = format!("{}/cases/carter_051.yaml", env!("CARGO_MANIFEST_DIR"));
    let (code, _, stderr) = rollbem(&[
        "sweep",
        "--per-run-files",
        &other,
        "--vary",
        "contact.friction=0.1,0.2",
        "--out",
        o,
        "--resume",
    ]);
    assert_eq!(code, 1, "{stderr}");
    assert!(stderr.contains("no record sweep.json"), "{stderr}");
    assert_eq!(std::fs::read_to_string(out.join("sweep.csv")).unwrap(), before);
    assert!(!out.join("sweep.json").exists());
    // A shard's table without its record alike.
    let sh = dir.path().join("sh");
    assert_eq!(shard(MU, 1, 2, &sh).0, 0);
    std::fs::remove_file(sh.join("sweep_shard_1_of_2.json")).unwrap();
    let (code, _, stderr) = rollbem(&[
        "sweep",
        "--per-run-files",
        &case(),
        "--vary",
        MU,
        "--shard",
        "1/2",
        "--out",
        sh.to_str().unwrap(),
        "--resume",
    ]);
    assert_eq!(code, 1, "{stderr}");
    assert!(stderr.contains("no record sweep_shard_1_of_2.json"), "{stderr}");
}

/// `--merge` takes no case, `--set` or `--vary` (the shards' records say what sweep they are),
/// and does not write over another sweep's folder; a run recorded done whose folder is gone or
/// incomplete is refused by `--merge` and run again by `--resume`.
#[test]
fn merge_checks_its_arguments_the_output_folder_and_the_run_folders() {
    let dir = tempfile::tempdir().unwrap();
    let (a, b) = (dir.path().join("a"), dir.path().join("b"));
    assert_eq!(shard(MU, 1, 2, &a).0, 0);
    assert_eq!(shard(MU, 2, 2, &b).0, 0);
    let (sa, sb) = (a.to_str().unwrap(), b.to_str().unwrap());
    for extra in [
        vec![case()],
        vec!["--set".to_string(), "contact.friction=0.2".to_string()],
        vec!["--vary".to_string(), MU.to_string()],
    ] {
        let mut args = vec!["sweep"];
        args.extend(extra.iter().map(String::as_str));
        args.extend(["--merge", sa, sb]);
        let (code, _, stderr) = rollbem(&args);
        assert_eq!(code, 1, "{extra:?}: {stderr}");
        assert!(stderr.contains("cannot be used with"), "{extra:?}: {stderr}");
        assert!(!a.join("sweep.csv").exists());
    }
    // A complete sweep of other values in --out: left as it was.
    let other = dir.path().join("other");
    let (code, _, stderr) = rollbem(&[
        "sweep",
        "--per-run-files",
        &case(),
        "--vary",
        "contact.friction=0.1,0.2",
        "--out",
        other.to_str().unwrap(),
    ]);
    assert_eq!(code, 0, "{stderr}");
    let before = std::fs::read_to_string(other.join("sweep.csv")).unwrap();
    let (code, _, stderr) = rollbem(&["sweep", "--merge", sa, sb, "--out", other.to_str().unwrap()]);
    assert_eq!(code, 1, "{stderr}");
    assert!(stderr.contains("holds another sweep"), "{stderr}");
    assert_eq!(std::fs::read_to_string(other.join("sweep.csv")).unwrap(), before);
    // Its table and record gone, its run folders still refuse it.
    std::fs::remove_file(other.join("sweep.csv")).unwrap();
    std::fs::remove_file(other.join("sweep.json")).unwrap();
    std::fs::remove_file(other.join("sweep.pvd")).unwrap();
    let (code, _, stderr) = rollbem(&["sweep", "--merge", sa, sb, "--out", other.to_str().unwrap()]);
    assert_eq!(code, 1, "{stderr}");
    assert!(
        stderr.contains("run folders that no merged shard table names (run_0000, run_0001)"),
        "{stderr}"
    );
    // A run folder deleted after its shard finished.
    let gone = b.join("run_0003");
    std::fs::rename(&gone, dir.path().join("moved")).unwrap();
    let merged = dir.path().join("merged");
    let (code, _, stderr) = rollbem(&["sweep", "--merge", sa, sb, "--out", merged.to_str().unwrap()]);
    assert_eq!(code, 1, "{stderr}");
    assert!(
        stderr.contains("run_0003 is recorded ok but its folder") && stderr.contains("is missing"),
        "{stderr}"
    );
    std::fs::rename(dir.path().join("moved"), &gone).unwrap();
    // A file of a run's manifest gone: --merge refuses, --resume runs it again.
    std::fs::remove_file(gone.join("summary.json")).unwrap();
    let (code, _, stderr) = rollbem(&["sweep", "--merge", sa, sb, "--out", merged.to_str().unwrap()]);
    assert_eq!(code, 1, "{stderr}");
    assert!(stderr.contains("lacks summary.json"), "{stderr}");
    // The folder column of run 1 naming run 3's folder.
    let table = b.join("sweep_shard_2_of_2.csv");
    let text = std::fs::read_to_string(&table).unwrap();
    std::fs::write(&table, text.replacen("\n1,run_0001,", "\n1,run_0003,", 1)).unwrap();
    let (code, stdout, stderr) = rollbem(&[
        "sweep",
        "--per-run-files",
        &case(),
        "--vary",
        MU,
        "--shard",
        "2/2",
        "--out",
        sb,
        "--resume",
    ]);
    assert_eq!(code, 0, "{stderr}");
    assert!(stdout.contains("2 of 5 runs here"), "{stdout}");
    assert!(!stdout.contains("kept from"), "{stdout}");
    assert!(gone.join("summary.json").is_file());
    let (code, _, stderr) = rollbem(&["sweep", "--merge", sa, sb, "--out", merged.to_str().unwrap()]);
    assert_eq!(code, 0, "{stderr}");
}

/// sweep.csv has the contact's centre (the middle of x_min and x_max, as in summary.json), and
/// every number in the shortest form that reads back to the same double (as contact.csv).
#[test]
fn the_table_has_the_contact_centre_and_shortest_numbers() {
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("sw");
    let (code, _, stderr) = rollbem(&[
        "sweep",
        "--per-run-files",
        &case(),
        "--vary",
        "load.tangential.ratio=-0.74,0.05,0.41",
        "--out",
        out.to_str().unwrap(),
    ]);
    assert_eq!(code, 0, "{stderr}");
    let mut r = csv::Reader::from_path(out.join("sweep.csv")).unwrap();
    let header: Vec<String> = r.headers().unwrap().iter().map(String::from).collect();
    let col = |name: &str| header.iter().position(|h| h == name).unwrap();
    let (lo, hi, centre) = (col("contact_x_min"), col("contact_x_max"), col("contact_centre"));
    for rec in r.records() {
        let rec = rec.unwrap();
        let num = |i: usize| rec[i].parse::<f64>().unwrap();
        let (a, b, c) = (num(lo), num(hi), num(centre));
        assert!((c - 0.5 * (a + b)).abs() <= 1e-12 * (a.abs() + b.abs()), "{a} {b} {c}");
        let summary: serde_json::Value =
            serde_json::from_str(&std::fs::read_to_string(out.join(&rec[1]).join("summary.json")).unwrap()).unwrap();
        // summary.json holds the centre in the case's units, converted: equal to round-off.
        let json = summary["contact"]["centre"].as_f64().unwrap();
        assert!((json - c).abs() <= 1e-12 * (a.abs() + b.abs()), "{json} {c}");
        for (i, cell) in rec.iter().enumerate().skip(col("message") + 1) {
            if let Ok(v) = cell.parse::<f64>() {
                let shortest = if (1e-4..1e16).contains(&v.abs()) || v == 0.0 {
                    format!("{v}")
                } else {
                    format!("{v:e}")
                };
                assert_eq!(cell, shortest, "column {}", header[i]);
            }
        }
    }
}

/// A merge of shards written by different rollbem versions warns; the error for one shard of
/// 100 000 lists the first few missing shards and their number, not all 99 999.
#[test]
fn merge_warns_of_mixed_versions_and_summarises_long_lists() {
    let dir = tempfile::tempdir().unwrap();
    let (a, b) = (dir.path().join("a"), dir.path().join("b"));
    assert_eq!(shard(MU, 1, 2, &a).0, 0);
    assert_eq!(shard(MU, 2, 2, &b).0, 0);
    let record = b.join("sweep_shard_2_of_2.json");
    let text = std::fs::read_to_string(&record).unwrap();
    let older = text.replace(&format!("rollbem {}", env!("CARGO_PKG_VERSION")), "rollbem 0.0.1");
    assert_ne!(older, text);
    std::fs::write(&record, older).unwrap();
    let merged = dir.path().join("merged");
    let (code, _, stderr) = rollbem(&[
        "sweep",
        "--merge",
        a.to_str().unwrap(),
        b.to_str().unwrap(),
        "--out",
        merged.to_str().unwrap(),
    ]);
    assert_eq!(code, 0, "{stderr}");
    assert!(
        stderr.contains("different rollbem versions") && stderr.contains("rollbem 0.0.1 (1 shard)"),
        "{stderr}"
    );
    let one = dir.path().join("one");
    assert_eq!(shard(MU, 1, 100_000, &one).0, 0);
    let (code, _, stderr) = rollbem(&["sweep", "--merge", one.to_str().unwrap()]);
    assert_eq!(code, 1, "{stderr}");
    assert!(
        stderr.contains("2/100000, 3/100000, 4/100000, 5/100000, 6/100000, … (99999 in all)"),
        "{stderr}"
    );
    assert!(stderr.len() < 1000, "{} bytes", stderr.len());
}

/// A sweep writes its table and record only, unless --per-run-files asks for the run folders;
/// its runs, solved on one assembly from their neighbours' solutions, give the forces and
/// creepages of the same runs done alone by `rollbem run` (a cold start each) to the Newton
/// tolerance.
#[test]
fn a_sweep_writes_only_its_table_and_its_runs_equal_runs_alone() {
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("sw");
    let (code, _, stderr) = rollbem(&[
        "sweep",
        &case(),
        "--vary",
        MU,
        "--vary",
        RATIO,
        "--out",
        out.to_str().unwrap(),
    ]);
    assert_eq!(code, 0, "{stderr}");
    let mut names: Vec<String> = std::fs::read_dir(&out)
        .unwrap()
        .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
        .filter(|n| !n.starts_with('.'))
        .collect();
    names.sort();
    assert_eq!(names, ["sweep.csv", "sweep.json"]);
    let mut table = csv::Reader::from_path(out.join("sweep.csv")).unwrap();
    let header: Vec<String> = table.headers().unwrap().iter().map(String::from).collect();
    let col = |name: &str| header.iter().position(|h| h == name).unwrap();
    let records: Vec<csv::StringRecord> = table.records().map(Result::unwrap).collect();
    assert_eq!(records.len(), 15);
    assert!(records
        .iter()
        .all(|r| r[col("folder")].is_empty() && &r[col("status")] == "ok"));
    for k in [4, 13] {
        let rec = &records[k];
        let alone = dir.path().join(format!("alone{k}"));
        let mu = format!("contact.friction={}", &rec[col("contact.friction")]);
        let ratio = format!("load.tangential.ratio={}", &rec[col("load.tangential.ratio")]);
        let args = [
            "run",
            &case(),
            "--set",
            &mu,
            "--set",
            &ratio,
            "--out",
            alone.to_str().unwrap(),
        ];
        let (code, _, stderr) = rollbem(&args);
        assert_eq!(code, 0, "{stderr}");
        let summary: serde_json::Value =
            serde_json::from_str(&std::fs::read_to_string(alone.join("summary.json")).unwrap()).unwrap();
        for key in ["tangential_force", "creep", "max_pressure"] {
            let (swept, cold): (f64, f64) = (rec[col(key)].parse().unwrap(), summary[key].as_f64().unwrap());
            assert!(
                (swept - cold).abs() <= 1e-8 * cold.abs(),
                "run {k} {key}: {swept} against {cold}"
            );
        }
    }
}

/// Without run folders the table is the record of the finished runs: a sweep killed after some
/// rows (its table cut to them) resumes with those kept and the rest run, to the same results
/// as a whole sweep.
#[test]
fn resume_keeps_the_rows_of_a_sweep_without_run_folders() {
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("sw");
    let args = [
        "sweep",
        &case(),
        "--vary",
        MU,
        "--vary",
        RATIO,
        "--out",
        out.to_str().unwrap(),
    ];
    let (code, _, stderr) = rollbem(&args);
    assert_eq!(code, 0, "{stderr}");
    let whole = dir.path().join("whole.csv");
    std::fs::copy(out.join("sweep.csv"), &whole).unwrap();
    let text = std::fs::read_to_string(out.join("sweep.csv")).unwrap();
    // The header, four rows and a torn fifth, as a kill leaves them.
    let cut: Vec<&str> = text.lines().take(6).collect();
    let torn = format!("{}\n{}", cut[..5].join("\n"), &cut[5][..cut[5].len() / 2]);
    std::fs::write(out.join("sweep.csv"), torn).unwrap();
    let (code, stdout, stderr) = rollbem(&[&args[..], &["--resume"]].concat());
    assert_eq!(code, 0, "{stdout}{stderr}");
    assert!(stdout.contains("(4 kept from the interrupted sweep)"), "{stdout}");
    assert!(
        stdout.contains("11 of 15 runs here") || stdout.contains("15 of 15"),
        "{stdout}"
    );
    assert_same_results(&out.join("sweep.csv"), &whole);
    // Asked for run folders, a resumed sweep redoes the rows that have none.
    let (code, stdout, stderr) = rollbem(&[&args[..], &["--resume", "--per-run-files"]].concat());
    assert_eq!(code, 0, "{stdout}{stderr}");
    assert!(!stdout.contains("kept from the interrupted sweep"), "{stdout}");
    assert!(out.join("run_0014/summary.json").is_file());
    assert_same_results(&out.join("sweep.csv"), &whole);
}

/// `--jobs`: a count beyond the machine's cores runs on the cores with a warning; a count
/// beyond 1024 (or beyond a whole number of 64 bits) is refused with exit 1 naming `--jobs`,
/// nothing written. (`rollbem sweep` had no `--jobs`: exit 1 as an unknown flag.)
#[test]
fn jobs_beyond_the_cores_are_capped_and_absurd_counts_refused() {
    let dir = tempfile::tempdir().unwrap();
    let case = crate::common::case_path("carter_051");
    let case = case.to_str().unwrap();
    let out = dir.path().join("capped");
    let args = |jobs: &'static str, out: &Path| -> Vec<String> {
        [
            "sweep",
            case,
            "--vary",
            "contact.friction=0.1,0.2",
            "--jobs",
            jobs,
            "--out",
        ]
        .iter()
        .map(|s| s.to_string())
        .chain([out.to_str().unwrap().to_string()])
        .collect()
    };
    let a = args("100000000", &out);
    let (code, _, stderr) = rollbem(&a.iter().map(String::as_str).collect::<Vec<_>>());
    assert_eq!(code, 1, "{stderr}");
    assert!(
        stderr.contains("--jobs 100000000") && stderr.contains("at most 1024"),
        "{stderr}"
    );
    assert!(!out.exists());
    let a = args("1000000000000000000000000000000", &out);
    let (code, _, stderr) = rollbem(&a.iter().map(String::as_str).collect::<Vec<_>>());
    assert_eq!(code, 1, "{stderr}");
    assert!(stderr.contains("--jobs"), "{stderr}");
    assert!(!out.exists());
    let a = args("1024", &out);
    let (code, _, stderr) = rollbem(&a.iter().map(String::as_str).collect::<Vec<_>>());
    assert_eq!(code, 0, "{stderr}");
    let cores = std::thread::available_parallelism().map_or(1, |n| n.get());
    if cores < 1024 {
        assert!(
            stderr.contains(&format!("warning: --jobs 1024 exceeds the {cores} cores")),
            "{stderr}"
        );
    }
    assert!(out.join("sweep.csv").is_file());
}

/// An error-controlled sweep (`contact.grid.tolerance`; src/sequence.rs, "Error-controlled
/// chains"): carter_051 at 1e-4 over five values of Q/μP, on one thread (one chain, every run
/// after the first warm from the last) and on three (other chains, other neighbours). Every
/// run converges and its summary's error estimate meets the tolerance; each run starts its
/// passes on its own start grid, so its grids and result are the cold run's whatever its
/// chain: the two tables agree to the Newton tolerance, as the fixed-grid sweeps do. (The
/// first run of a chain starts cold: with one thread four runs are warm, with three two.)
#[test]
fn an_error_controlled_sweep_meets_its_tolerance_whatever_its_chains() {
    let dir = tempfile::tempdir().unwrap();
    let case = format!("{}/cases/carter_051.yaml", env!("CARGO_MANIFEST_DIR"));
    let sweep = |jobs: &str, name: &str| {
        let out = dir.path().join(name);
        let (code, stdout, stderr) = rollbem(&[
            "sweep",
            "--per-run-files",
            &case,
            "--set",
            "contact.grid.tolerance=1e-4",
            "--vary",
            "load.tangential.ratio=0.2,0.35,0.51,0.65,0.8",
            "--jobs",
            jobs,
            "--out",
            out.to_str().unwrap(),
        ]);
        assert_eq!(code, 0, "{stdout}{stderr}");
        out
    };
    let (one, three) = (sweep("1", "one"), sweep("3", "three"));
    let r = rows(&one.join("sweep.csv"));
    assert_eq!(r.len(), 5);
    assert!(r.iter().all(|row| row[1] == "ok"), "{r:?}");
    for k in 0..5 {
        let text = std::fs::read_to_string(one.join(format!("run_{k:04}/summary.json"))).unwrap();
        let s: serde_json::Value = serde_json::from_str(&text).unwrap();
        let e = &s["error_estimate"];
        for key in ["pressure_rms", "shear_rms", "creep_rel"] {
            let v = e[key].as_f64().unwrap_or_else(|| panic!("run {k}: {key} in {e}"));
            assert!(v <= 1e-4, "run {k}: {key} {v:e} above the tolerance");
        }
    }
    // Carter's pressure is symmetric: its centre and the rolling resistance are round-off
    // (6e-10 a, 1e-11), which a comparison relative to their own column reads as noise.
    assert_same_results_except(
        &one.join("sweep.csv"),
        &three.join("sweep.csv"),
        &["pressure_centre", "rolling_resistance"],
    );
}
