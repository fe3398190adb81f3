//! Time of `rollbem sweep --merge` against the number of rows: four shard tables of a sweep of
//! N runs (two `--vary` keys of 1000 and N/1000 values) are written into a temporary folder, then
//! merged into one sweep.csv, once per N. The rows are `failed` runs (they have no run folders
//! to check, so that a million rows fit on a small disk): the time is that of reading, checking
//! and joining the tables, which the merge once did in quadratic time (every row compared with
//! every other). Linear time shows as a constant time per row.
//!
//! Run: `cargo run --release --example merge_scale [N ...]` (default 10000 40000 200000 1000000).
//! Method and machine: docs/performance.md.

use rollbem::sweep::{merge, SweepRecord, VaryRecord, RESULT_COLUMNS};
use std::io::Write;
use std::path::Path;
use std::time::Instant;

const SHARDS: usize = 4;

/// Writes the four shard tables and records of an N-run sweep into `dir`.
fn write_shards(dir: &Path, n: usize) {
    let inner = n / 1000;
    let vary = vec![
        VaryRecord {
            key: "contact.friction".into(),
            values: (0..1000).map(|i| format!("0.{i:04}")).collect(),
        },
        VaryRecord {
            key: "load.tangential.ratio".into(),
            values: (0..inner).map(|j| format!("{j}")).collect(),
        },
    ];
    let mut header: Vec<String> = [
        "run",
        "folder",
        "status",
        "contact.friction",
        "load.tangential.ratio",
        "message",
    ]
    .map(String::from)
    .to_vec();
    header.extend(RESULT_COLUMNS.map(String::from));
    let empty = ",".repeat(RESULT_COLUMNS.len());
    for k in 1..=SHARDS {
        let record = SweepRecord {
            written_by: format!("rollbem {}", env!("CARGO_PKG_VERSION")),
            case: "case.yaml".into(),
            case_hash: "fnv1a64:0123456789abcdef".into(),
            set: Vec::new(),
            vary: vary.clone(),
            runs: n,
            shards: Some(SHARDS),
            shard: Some(k),
        };
        let stem = format!("sweep_shard_{k}_of_{SHARDS}");
        std::fs::write(
            dir.join(format!("{stem}.json")),
            serde_json::to_string(&record).unwrap(),
        )
        .unwrap();
        let mut csv = std::io::BufWriter::new(std::fs::File::create(dir.join(format!("{stem}.csv"))).unwrap());
        writeln!(csv, "{}", header.join(",")).unwrap();
        for run in (k - 1..n).step_by(SHARDS) {
            let (i, j) = (run / inner, run % inner);
            writeln!(
                csv,
                "{run},run_{run:04},failed,{},{},not solved{empty}",
                vary[0].values[i], vary[1].values[j]
            )
            .unwrap();
        }
    }
    std::fs::write(
        dir.join(".rollbem-manifest"),
        format!(
            "{{\"written_by\": \"rollbem {}\", \"kind\": \"sweep\", \"files\": []}}",
            env!("CARGO_PKG_VERSION")
        ),
    )
    .unwrap();
}

fn main() {
    let sizes: Vec<usize> = std::env::args()
        .skip(1)
        .map(|a| a.parse().expect("N: a number of rows"))
        .collect();
    let sizes = if sizes.is_empty() {
        vec![10_000, 40_000, 200_000, 1_000_000]
    } else {
        sizes
    };
    println!("| rows | merge [s] | per row [µs] |");
    println!("|---:|---:|---:|");
    for n in sizes {
        let n = n.max(1000) / 1000 * 1000;
        let tmp = tempfile::tempdir().unwrap();
        let shards = tmp.path().join("shards");
        std::fs::create_dir(&shards).unwrap();
        write_shards(&shards, n);
        let start = Instant::now();
        let out = merge(std::slice::from_ref(&shards), &tmp.path().join("merged")).expect("the merge succeeds");
        let t = start.elapsed().as_secs_f64();
        let lines = std::fs::read_to_string(&out).unwrap().lines().count();
        assert_eq!(lines, n + 1, "the merged table has every row");
        println!("| {n} | {t:.2} | {:.1} |", t / n as f64 * 1e6);
    }
}
