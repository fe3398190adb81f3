//! `rollbem sweep`: 15-run product, failure isolation, sharding and merging (issue 5).

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

fn pvd_entries(path: &Path) -> usize {
    std::fs::read_to_string(path).unwrap().matches("<DataSet").count()
}

const MU: &str = "contact.friction=0.1,0.2,0.3,0.4,0.8";
const RATIO: &str = "load.tangential.ratio=0.2,0.5,0.75";

/// The 15-run sweep (5 μ × 3 Q/μP) into `out`.
fn full_sweep(out: &Path) -> (i32, String, String) {
    rollbem(&[
        "sweep",
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
    assert_eq!(rows(&merged.join("sweep.csv")), rows(&whole.join("sweep.csv")));
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
