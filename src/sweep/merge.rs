//! `rollbem sweep --merge`: the shard tables of one sweep, from one folder or several, joined
//! into one sweep.csv and sweep.pvd; incomplete, mixed or malformed sets are refused.

use super::record::{read_record, write_record, SweepRecord};
use super::table::{header, parse_row, write_collection_atomically, write_rows};
use super::{lock_table, product, run_folder, sweep_err, RunRow, Shard, Vary};
use crate::error::Error;
use crate::output::folder::{self, Access, Claim, FileLock, FolderError, Kind};
use crate::output::vtk::CollectionEntry;
use std::path::{Path, PathBuf};

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
/// for every run it owns; an empty or malformed table is named with what is wrong. `out` must be
/// new, empty or a sweep folder, and no sweep may still be writing any of the folders.
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
    let count = first.record.shards.unwrap_or(1);
    check_shards_complete(&tables, count)?;
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
    let runs = product(&varies);
    let mut rows: Vec<RunRow> = Vec::new();
    for t in &tables {
        let mut shard_rows = read_table_strictly(t, &keys, &runs)?;
        for r in &mut shard_rows {
            r.has_vtk = t.dir.join(&r.folder).join("contact.vtu").is_file();
            r.folder = relative(&out_abs, &t.dir.join(&r.folder));
        }
        rows.extend(shard_rows);
    }
    rows.sort_by_key(|r| r.run);
    claim.create_in_place()?;
    let mut record = first.record.clone();
    record.shard = None;
    record.written_by = format!("rollbem {}", env!("CARGO_PKG_VERSION"));
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
        for name in &names {
            let Some((k, n, ext)) = folder::shard_file_name(name) else {
                continue;
            };
            let stem = format!("sweep_shard_{k}_of_{n}");
            let (csv, json) = (dir.join(format!("{stem}.csv")), dir.join(format!("{stem}.json")));
            if ext == "json" {
                if !csv.is_file() {
                    return Err(sweep_err(format!(
                        "{}: shard {k}/{n} has no table {stem}.csv (it was killed before its first run \
                         finished?): rerun it with --shard {k}/{n} --resume",
                        json.display()
                    )));
                }
                continue;
            }
            if !json.is_file() {
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
    for (i, a) in tables.iter().enumerate() {
        if let Some(b) = tables[i + 1..].iter().find(|b| b.record.shard == a.record.shard) {
            return Err(sweep_err(format!(
                "shard {}/{count} is given twice: {} and {}; merge one of them",
                a.record.shard.unwrap_or(0),
                a.csv.display(),
                b.csv.display()
            )));
        }
    }
    let missing: Vec<String> = (1..=count)
        .filter(|k| !tables.iter().any(|t| t.record.shard == Some(*k)))
        .map(|k| format!("{k}/{count}"))
        .collect();
    if missing.is_empty() {
        Ok(())
    } else {
        Err(sweep_err(format!(
            "the sweep is incomplete: shard(s) {} missing (no sweep_shard_K_of_{count}.csv in the merged \
             folders); run them with --shard K/{count}, or add their folders to --merge",
            missing.join(", ")
        )))
    }
}

/// The rows of one shard table, every one checked; a table that lacks some of its runs names
/// them.
fn read_table_strictly(t: &ShardTable, keys: &[String], runs: &[Vec<(String, String)>]) -> Result<Vec<RunRow>, Error> {
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
        if rows.iter().any(|r| r.run == row.run) {
            return Err(bad(format!("line {}: run {} appears twice", line + 2, row.run)));
        }
        rows.push(row);
    }
    let missing: Vec<String> = (0..runs.len())
        .filter(|&n| shard.owns(n) && !rows.iter().any(|r| r.run == n))
        .map(run_folder)
        .collect();
    if !missing.is_empty() {
        return Err(sweep_err(format!(
            "{shown}: shard {}/{} is incomplete, it lacks {} of its runs ({}): it was killed or is \
             still running; finish it with --shard {}/{} --resume",
            shard.index,
            shard.count,
            missing.len(),
            missing.join(", "),
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
