//! `rollbem sweep --merge`: the shard tables of one sweep, from one folder or several, joined
//! into one sweep.csv and sweep.pvd; incomplete, mixed or malformed sets are refused.
//!
//! Linear in the number of rows and shards (hash sets, no pairwise comparisons): a million rows
//! merge in seconds (docs/performance.md, `cargo run --release --example merge_scale`).

use super::record::{read_record, write_record, SweepRecord};
use super::table::{header, parse_row, write_collection_atomically, write_rows};
use super::{lock_table, run_folder, sweep_err, RunRow, Runs, Shard, Vary};
use crate::error::Error;
use crate::output::folder::{self, Access, Claim, FileLock, FolderError, Kind, SweepEntry};
use crate::output::vtk::CollectionEntry;
use std::collections::{HashMap, HashSet};
use std::path::{Path, PathBuf};

/// How many items a message lists before it gives only their number.
const SHOWN: usize = 5;

/// `items` for a message: all of them when few, else the first [`SHOWN`] and how many in all.
pub(super) fn summarise(items: &[String]) -> String {
    if items.len() <= SHOWN {
        items.join(", ")
    } else {
        format!("{}, … ({} in all)", items[..SHOWN].join(", "), items.len())
    }
}

/// One shard table found by [`merge`].
struct ShardTable {
    csv: PathBuf,
    dir: PathBuf,
    record: SweepRecord,
}

/// Joins the shard tables (`sweep_shard_K_of_N.csv` with their `.json` records) found in `dirs`
/// into `out/sweep.csv`, `out/sweep.json` and `out/sweep.pvd`, rows ordered by run number. Run
/// folders stay where they are; the `folder` column and the .pvd point to them relative to
/// `out`.
///
/// Refused (nothing written) unless the tables make exactly one complete sweep: every shard 1..N
/// present once, all of one sweep (same case content, `--set`, `--vary`, N), each holding a row
/// for every run it owns, each run recorded as done with its folder whole; an empty or malformed
/// table is named with what is wrong. `out` must be new, empty, a shard folder of this sweep or
/// its earlier merge: a folder that holds another sweep (its sweep.json differs, or run folders
/// that no shard table names) is refused. No sweep may still be writing any of the folders.
/// Shards written by different rollbem versions merge with a warning.
pub fn merge(dirs: &[PathBuf], out: &Path) -> Result<PathBuf, Error> {
    let claim = Claim::acquire(out, Kind::Sweep, Access::Exclusive)?;
    let out_abs = claim.path().to_path_buf();
    let mut inputs: Vec<PathBuf> = Vec::new();
    for dir in dirs {
        let abs = folder::resolve(dir)?;
        if !abs.is_dir() {
            return Err(sweep_err(format!("--merge {}: no such folder", dir.display())));
        }
        if !inputs.contains(&abs) {
            inputs.push(abs);
        }
    }
    // No sweep may be writing what is merged (the output's lock is the claim's).
    let mut locks = Vec::new();
    for dir in inputs.iter().filter(|d| **d != out_abs) {
        let lock = folder::lock_path(dir);
        match FileLock::try_acquire(&lock, Access::Exclusive)? {
            Some(l) => locks.push(l),
            None => return Err(FolderError::Busy { dir: dir.clone(), lock }.into()),
        }
    }
    let tables = find_tables(&inputs)?;
    for t in &tables {
        locks.push(lock_table(&t.dir, &t.record)?);
    }
    let first = &tables[0];
    for t in &tables[1..] {
        if let Some(diff) = first.record.difference(&t.record) {
            return Err(sweep_err(format!(
                "{} and {} belong to different sweeps: {diff}; merge the shards of one sweep",
                first.csv.display(),
                t.csv.display()
            )));
        }
    }
    warn_of_versions(&tables);
    let count = first.record.shards.unwrap_or(1);
    check_shards_complete(&tables, count)?;
    let mut record = first.record.clone();
    record.shard = None;
    record.written_by = format!("rollbem {}", env!("CARGO_PKG_VERSION"));
    check_output_folder(&out_abs, &record)?;
    let keys: Vec<String> = first.record.vary.iter().map(|v| v.key.clone()).collect();
    let varies: Vec<Vary> = first
        .record
        .vary
        .iter()
        .map(|v| Vary {
            key: v.key.clone(),
            values: v.values.clone(),
        })
        .collect();
    let runs = Runs::new(&varies)?;
    let mut rows: Vec<RunRow> = Vec::with_capacity(runs.count());
    for t in &tables {
        let mut shard_rows = read_table_strictly(t, &keys, &runs)?;
        for r in shard_rows.iter_mut().filter(|r| !r.folder.is_empty()) {
            let dir = t.dir.join(&r.folder);
            r.has_vtk = r.status == "ok" && dir.join("contact.vtu").is_file();
            r.folder = relative(&out_abs, &dir);
        }
        rows.extend(shard_rows);
    }
    rows.sort_by_key(|r| r.run);
    check_no_foreign_runs(&out_abs, &rows)?;
    claim.create_in_place()?;
    write_record(&out_abs, &record)?;
    let path = out_abs.join("sweep.csv");
    write_rows(&path, &keys, &rows)?;
    let entries: Vec<CollectionEntry> = rows
        .iter()
        .filter(|r| r.status == "ok" && r.has_vtk)
        .map(|r| CollectionEntry {
            file: format!("{}/contact.vtu", r.folder),
            timestep: r.run as f64,
            part: 0,
            name: format!("contact {}", run_folder(r.run)),
        })
        .collect();
    write_collection_atomically(&out_abs.join("sweep.pvd"), &entries)?;
    drop(locks);
    Ok(path)
}

/// A warning when the shards were written by more than one rollbem version: their tables have
/// one layout (the header is checked), but their numbers may differ in the last digits.
fn warn_of_versions(tables: &[ShardTable]) {
    let mut versions: Vec<(&str, usize)> = Vec::new();
    for t in tables {
        match versions.iter_mut().find(|(v, _)| *v == t.record.written_by) {
            Some((_, n)) => *n += 1,
            None => versions.push((&t.record.written_by, 1)),
        }
    }
    if versions.len() > 1 {
        let shown: Vec<String> = versions
            .iter()
            .map(|(v, n)| format!("{v} ({n} shard{})", if *n == 1 { "" } else { "s" }))
            .collect();
        log::warn!(
            "the shards were written by different rollbem versions: {}; their results may differ \
             in ways the merged table does not show (rerun the shards with one version to be sure)",
            shown.join(", ")
        );
    }
}

/// Refuses to merge into a folder that holds another sweep's table: a sweep.json of another
/// sweep (or a sweep.csv without one). The same sweep's earlier merge is replaced.
fn check_output_folder(out: &Path, record: &SweepRecord) -> Result<(), Error> {
    let (json, csv) = (out.join("sweep.json"), out.join("sweep.csv"));
    if json.exists() {
        let other = read_record(&json)?;
        if let Some(diff) = record.difference(&other) {
            return Err(sweep_err(format!(
                "--out {}: it holds another sweep ({} differs from the merged one: {diff}); the merge \
                 does not replace it: give another --out",
                out.display(),
                json.display()
            )));
        }
    } else if csv.exists() {
        return Err(sweep_err(format!(
            "--out {}: it holds a sweep.csv without the record sweep.json that says what sweep it \
             is; the merge does not replace it: give another --out",
            out.display()
        )));
    }
    Ok(())
}

/// Refuses an output folder holding run folders that the merged table does not name (another
/// sweep's runs, which the merged sweep.csv would leave beside it as if they were its own).
fn check_no_foreign_runs(out: &Path, rows: &[RunRow]) -> Result<(), Error> {
    let Ok(entries) = std::fs::read_dir(out) else {
        return Ok(());
    };
    let named: HashSet<&str> = rows.iter().map(|r| r.folder.as_str()).collect();
    let mut foreign: Vec<String> = entries
        .filter_map(|e| e.ok().map(|e| e.file_name().to_string_lossy().into_owned()))
        .filter(|n| folder::sweep_owns(n) == Some(SweepEntry::Run) && !named.contains(n.as_str()))
        .collect();
    if foreign.is_empty() {
        return Ok(());
    }
    foreign.sort();
    Err(sweep_err(format!(
        "--out {}: it holds run folders that no merged shard table names ({}): they belong to \
         another sweep, and the merge does not replace it: give another --out",
        out.display(),
        summarise(&foreign)
    )))
}

/// The shard tables in `dirs`, each with its record; a table without a record, a record without
/// a table, an empty table or a folder without tables is an error that names it.
fn find_tables(dirs: &[PathBuf]) -> Result<Vec<ShardTable>, Error> {
    let mut tables = Vec::new();
    for dir in dirs {
        let mut names: Vec<String> = std::fs::read_dir(dir)
            .map_err(|e| sweep_err(format!("--merge {}: {e}", dir.display())))?
            .filter_map(|e| e.ok().map(|e| e.file_name().to_string_lossy().into_owned()))
            .filter(|n| folder::shard_file_name(n).is_some())
            .collect();
        names.sort();
        if names.is_empty() {
            return Err(sweep_err(format!(
                "--merge {}: no sweep_shard_K_of_N.csv files found; run `rollbem sweep --shard K/N` into it first",
                dir.display()
            )));
        }
        let present: HashSet<&str> = names.iter().map(String::as_str).collect();
        for name in &names {
            let Some((k, n, ext)) = folder::shard_file_name(name) else {
                continue;
            };
            let stem = format!("sweep_shard_{k}_of_{n}");
            let (csv, json) = (dir.join(format!("{stem}.csv")), dir.join(format!("{stem}.json")));
            if ext == "json" {
                if !present.contains(format!("{stem}.csv").as_str()) || !csv.is_file() {
                    return Err(sweep_err(format!(
                        "{}: shard {k}/{n} has no table {stem}.csv (it was killed before its first run \
                         finished?): rerun it with --shard {k}/{n} --resume",
                        json.display()
                    )));
                }
                continue;
            }
            if !present.contains(format!("{stem}.json").as_str()) || !json.is_file() {
                return Err(sweep_err(format!(
                    "{}: no record {stem}.json says what sweep this table belongs to (written by an \
                     older rollbem, or copied without it): rerun the shard with --shard {k}/{n}",
                    csv.display()
                )));
            }
            if std::fs::metadata(&csv).is_ok_and(|m| m.len() == 0) {
                return Err(sweep_err(format!(
                    "{} is empty: shard {k}/{n} wrote nothing; rerun it with --shard {k}/{n} --resume",
                    csv.display()
                )));
            }
            let record = read_record(&json)?;
            if record.shard != Some(k) || record.shards != Some(n) {
                return Err(sweep_err(format!(
                    "{}: the record is not that of shard {k}/{n}",
                    json.display()
                )));
            }
            tables.push(ShardTable {
                csv,
                dir: dir.clone(),
                record,
            });
        }
    }
    Ok(tables)
}

/// Every shard 1..=count exactly once.
fn check_shards_complete(tables: &[ShardTable], count: usize) -> Result<(), Error> {
    let mut seen: HashMap<usize, &ShardTable> = HashMap::with_capacity(tables.len());
    for t in tables {
        let k = t.record.shard.unwrap_or(0);
        if let Some(earlier) = seen.insert(k, t) {
            return Err(sweep_err(format!(
                "shard {k}/{count} is given twice: {} and {}; merge one of them",
                earlier.csv.display(),
                t.csv.display()
            )));
        }
    }
    let missing: Vec<String> = (1..=count)
        .filter(|k| !seen.contains_key(k))
        .map(|k| format!("{k}/{count}"))
        .collect();
    if missing.is_empty() {
        Ok(())
    } else {
        Err(sweep_err(format!(
            "the sweep is incomplete: shard(s) {} missing (no sweep_shard_K_of_{count}.csv in the merged \
             folders); run them with --shard K/{count}, or add their folders to --merge",
            summarise(&missing)
        )))
    }
}

/// The rows of one shard table, every one checked: its runs all there, once, and each run
/// recorded as done (`ok`, `not_converged`) with its own folder whole (or with no folder, when
/// the shard wrote no per-run files). A table that lacks some of
/// its runs names them.
fn read_table_strictly(t: &ShardTable, keys: &[String], runs: &Runs) -> Result<Vec<RunRow>, Error> {
    let shown = t.csv.display();
    let bad = |m: String| {
        sweep_err(format!(
            "{shown}: {m}; rerun the shard (--resume keeps its finished runs)"
        ))
    };
    let mut reader = csv::ReaderBuilder::new()
        .flexible(true)
        .from_path(&t.csv)
        .map_err(|e| bad(e.to_string()))?;
    let expected = header(keys);
    let found: Vec<String> = reader
        .headers()
        .map_err(|e| bad(e.to_string()))?
        .iter()
        .map(String::from)
        .collect();
    if found != expected {
        return Err(bad(format!(
            "the header is `{}`, not that of this sweep (`{}`)",
            found.join(","),
            expected.join(",")
        )));
    }
    let shard = Shard {
        index: t.record.shard.unwrap_or(1),
        count: t.record.shards.unwrap_or(1),
    };
    let mut rows: Vec<RunRow> = Vec::new();
    let mut seen: HashSet<usize> = HashSet::new();
    for (line, rec) in reader.records().enumerate() {
        let rec = rec.map_err(|e| bad(e.to_string()))?;
        // Line 1 is the header.
        let row = parse_row(&rec, keys.len(), runs).map_err(|m| bad(format!("line {}: {m}", line + 2)))?;
        if !shard.owns(row.run) {
            return Err(bad(format!(
                "line {}: run {} does not belong to shard {}/{}",
                line + 2,
                row.run,
                shard.index,
                shard.count
            )));
        }
        if !seen.insert(row.run) {
            return Err(bad(format!("line {}: run {} appears twice", line + 2, row.run)));
        }
        // A run that wrote no files (a sweep without --per-run-files) has its row as its record.
        if row.status != "failed" && !row.folder.is_empty() {
            let whole = if row.folder == run_folder(row.run) {
                folder::check_run_folder(&t.dir.join(&row.folder))
            } else {
                Err(format!("its folder column names `{}`", row.folder))
            };
            if let Err(why) = whole {
                return Err(bad(format!(
                    "line {}: {} is recorded {} but {why}",
                    line + 2,
                    run_folder(row.run),
                    row.status
                )));
            }
        }
        rows.push(row);
    }
    let missing: Vec<String> = shard
        .runs(runs.count())
        .filter(|n| !seen.contains(n))
        .map(run_folder)
        .collect();
    if !missing.is_empty() {
        return Err(sweep_err(format!(
            "{shown}: shard {}/{} is incomplete, it lacks {} of its runs ({}): it was killed or is \
             still running; finish it with --shard {}/{} --resume",
            shard.index,
            shard.count,
            missing.len(),
            summarise(&missing),
            shard.index,
            shard.count
        )));
    }
    Ok(rows)
}

/// Path of `target` relative to `base` (both absolute), with `..` as needed.
pub(super) fn relative(base: &Path, target: &Path) -> String {
    let b: Vec<_> = base.components().collect();
    let t: Vec<_> = target.components().collect();
    let common = b.iter().zip(&t).take_while(|(x, y)| x == y).count();
    let mut parts: Vec<String> = vec!["..".to_string(); b.len() - common];
    parts.extend(t[common..].iter().map(|c| c.as_os_str().to_string_lossy().into_owned()));
    if parts.is_empty() {
        ".".into()
    } else {
        parts.join("/")
    }
}
