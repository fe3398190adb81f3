//! Parameter sweeps: the Cartesian product of `--vary key=v1,v2,…` over a case, run in parallel
//! (rayon) with a progress bar (indicatif), one sub-folder per run, a `sweep.csv` with the varied
//! values and the summary numbers of every run, and a `sweep.pvd` that ParaView steps through.
//!
//! Runs are numbered in the order of the product (the first `--vary` varies slowest). Sharding
//! (`--shard K/N`) keeps the runs whose number n satisfies n mod N = K − 1, so N processes on N
//! machines (a Slurm job array, GNU parallel) split one sweep deterministically; each shard writes
//! `sweep_shard_K_of_N.csv`, and [`merge`] joins shard files (from one folder or several) into
//! one `sweep.csv` and `sweep.pvd`. A failed run is recorded as failed and does not stop the
//! others.

use crate::app;
use crate::error::Error;
use crate::output::folder::{self, Access, Claim, FileLock, FolderError, Kind, SweepEntry};
use crate::output::vtk::{write_collection, CollectionEntry};
use indicatif::{ProgressBar, ProgressStyle};
use rayon::prelude::*;
use serde::{Deserialize, Serialize};
use std::path::{Path, PathBuf};
use std::sync::Mutex;

/// One `--vary key=v1,v2,…` argument.
#[derive(Debug, Clone, PartialEq)]
pub struct Vary {
    /// Dotted case key.
    pub key: String,
    /// Values as written (each read as YAML, like `--set`).
    pub values: Vec<String>,
}

impl Vary {
    /// Parses `key=v1,v2,…`.
    pub fn parse(arg: &str) -> Result<Self, Error> {
        let bad = |m: &str| Error::Sweep {
            message: format!("--vary {arg}: {m}; write e.g. --vary contact.friction=0.1,0.2,0.4"),
        };
        let (key, list) = arg.split_once('=').ok_or_else(|| bad("expected key.path=v1,v2,..."))?;
        let values: Vec<String> = list.split(',').map(|v| v.trim().to_string()).collect();
        if key.is_empty() || values.iter().any(|v| v.is_empty()) {
            return Err(bad("empty key or value"));
        }
        Ok(Self {
            key: key.to_string(),
            values,
        })
    }
}

/// A shard K of N (1 ≤ K ≤ N).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Shard {
    /// 1-based shard index.
    pub index: usize,
    /// Number of shards.
    pub count: usize,
}

impl Shard {
    /// Parses `K/N`.
    pub fn parse(arg: &str) -> Result<Self, Error> {
        let bad = || Error::Sweep {
            message: format!("--shard {arg}: expected K/N with 1 <= K <= N, e.g. --shard 2/4"),
        };
        let (k, n) = arg.split_once('/').ok_or_else(bad)?;
        let (index, count) = (
            k.trim().parse().map_err(|_| bad())?,
            n.trim().parse().map_err(|_| bad())?,
        );
        if index == 0 || count == 0 || index > count {
            return Err(bad());
        }
        Ok(Self { index, count })
    }

    /// Whether run number `run` (0-based) belongs to this shard.
    pub fn owns(&self, run: usize) -> bool {
        run % self.count == self.index - 1
    }
}

/// The runs of a sweep: each is a list of (key, value) overrides.
pub fn product(varies: &[Vary]) -> Vec<Vec<(String, String)>> {
    varies.iter().fold(vec![Vec::new()], |acc, v| {
        acc.iter()
            .flat_map(|prefix| {
                v.values.iter().map(move |value| {
                    let mut run = prefix.clone();
                    run.push((v.key.clone(), value.clone()));
                    run
                })
            })
            .collect()
    })
}

/// Summary columns of sweep.csv after `run`, `folder`, `status`, the varied keys and `message`.
pub const RESULT_COLUMNS: [&str; 19] = [
    "converged",
    "iterations",
    "residual",
    "normal_force",
    "tangential_force",
    "load_ratio",
    "overlap",
    "creep",
    "contact_x_min",
    "contact_x_max",
    "half_width",
    "max_pressure",
    "slip_regime",
    "stick_zones",
    "slip_zones",
    "assembly_s",
    "condense_s",
    "solve_s",
    "total_s",
];

/// Columns that hold wall-clock times (differ between otherwise identical sweeps).
pub const TIMING_COLUMNS: [&str; 4] = ["assembly_s", "condense_s", "solve_s", "total_s"];

/// Outcome of one run as a sweep.csv row.
#[derive(Debug, Clone)]
pub struct RunRow {
    /// Run number in the full product.
    pub run: usize,
    /// Sub-folder name.
    pub folder: String,
    /// `ok`, `not_converged` or `failed`.
    pub status: String,
    /// Varied values, in `--vary` order.
    pub values: Vec<String>,
    /// Error message of a failed run (empty otherwise).
    pub message: String,
    /// Values of [`RESULT_COLUMNS`] (empty strings for a failed run).
    pub results: Vec<String>,
    /// Whether the run folder has a contact.vtu.
    pub has_vtk: bool,
    /// Whether the run failed on an internal error (a caught panic: a bug, not bad input).
    pub internal_error: bool,
}

impl RunRow {
    /// The CSV record: `run, folder, status`, the values, `message`, the results.
    fn record(&self) -> Vec<String> {
        let mut rec = vec![self.run.to_string(), self.folder.clone(), self.status.clone()];
        rec.extend(self.values.iter().cloned());
        rec.push(self.message.clone());
        rec.extend(self.results.iter().cloned());
        rec
    }
}

/// Runs one point of the sweep into `out/run_NNNN`; a panic in it is caught and recorded as an
/// internal error of that run (the others go on).
fn run_one(case: &Path, base_set: &[String], out: &Path, run: usize, overrides: &[(String, String)]) -> RunRow {
    let outcome = std::panic::catch_unwind(std::panic::AssertUnwindSafe(|| {
        run_one_unguarded(case, base_set, out, run, overrides)
    }));
    outcome.unwrap_or_else(|payload| {
        let what = payload
            .downcast_ref::<&str>()
            .map(|s| s.to_string())
            .or_else(|| payload.downcast_ref::<String>().cloned())
            .unwrap_or_else(|| "panic".into());
        RunRow {
            run,
            folder: run_folder(run),
            status: "failed".into(),
            values: overrides.iter().map(|(_, v)| v.clone()).collect(),
            message: format!("internal error — please report it: {}", what.replace('\n', " ")),
            results: vec![String::new(); RESULT_COLUMNS.len()],
            has_vtk: false,
            internal_error: true,
        }
    })
}

/// Name of the folder of run `run`.
pub fn run_folder(run: usize) -> String {
    format!("run_{run:04}")
}

fn run_one_unguarded(
    case: &Path,
    base_set: &[String],
    out: &Path,
    run: usize,
    overrides: &[(String, String)],
) -> RunRow {
    let folder = run_folder(run);
    let mut set = base_set.to_vec();
    set.extend(overrides.iter().map(|(k, v)| format!("{k}={v}")));
    let values = overrides.iter().map(|(_, v)| v.clone()).collect();
    match app::run(case, &set, Some(&out.join(&folder))) {
        Ok(report) => {
            let s = &report.summary;
            let c = s.contact.as_ref();
            let f = |v: f64| format!("{v:e}");
            RunRow {
                run,
                status: if s.converged { "ok" } else { "not_converged" }.into(),
                values,
                message: String::new(),
                results: vec![
                    s.converged.to_string(),
                    s.iterations.to_string(),
                    f(s.residual),
                    f(s.normal_force),
                    f(s.tangential_force),
                    s.load_ratio.map_or(String::new(), f),
                    f(s.overlap),
                    f(s.creep),
                    c.map_or(String::new(), |c| f(c.x_min)),
                    c.map_or(String::new(), |c| f(c.x_max)),
                    c.map_or(String::new(), |c| f(c.half_width)),
                    f(s.max_pressure),
                    s.slip_regime.to_string(),
                    s.stick_zones.len().to_string(),
                    s.slip_zones.len().to_string(),
                    f(s.timings.assembly_s),
                    f(s.timings.condense_s),
                    f(s.timings.solve_s),
                    f(s.timings.total_s),
                ],
                has_vtk: s.converged && s.vtk,
                folder,
                internal_error: false,
            }
        }
        Err(e) => RunRow {
            run,
            folder,
            status: "failed".into(),
            values,
            message: e.to_string().replace('\n', " "),
            results: vec![String::new(); RESULT_COLUMNS.len()],
            has_vtk: false,
            internal_error: false,
        },
    }
}

/// What a sweep did.
#[derive(Debug, Clone)]
pub struct SweepReport {
    /// Output folder.
    pub dir: PathBuf,
    /// Rows of the runs of this sweep (or shard), done now or kept by `--resume`.
    pub rows: Vec<RunRow>,
    /// Total runs in the full product.
    pub total_runs: usize,
    /// Runs kept from an earlier, interrupted sweep (`--resume`).
    pub resumed: usize,
    /// The CSV written (sweep.csv, or the shard file).
    pub csv: PathBuf,
}

/// What sweep a folder's table belongs to: written next to it as `sweep.json` or
/// `sweep_shard_K_of_N.json`, compared by `--resume`, by shards that share a folder and by
/// `--merge`, which refuse tables of another sweep.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct SweepRecord {
    /// `rollbem VERSION`.
    pub written_by: String,
    /// The case file as given (not compared: shards may run on machines that mount it elsewhere).
    pub case: String,
    /// FNV-1a 64-bit hash of the case file's bytes, `fnv1a64:` and 16 hex digits.
    pub case_hash: String,
    /// The `--set` overrides of every run, in order.
    pub set: Vec<String>,
    /// The `--vary` keys and values, in order.
    pub vary: Vec<VaryRecord>,
    /// Number of runs of the whole sweep.
    pub runs: usize,
    /// N of `--shard K/N` (a shard, or a sweep merged from N shards); null when unsharded.
    pub shards: Option<usize>,
    /// K of `--shard K/N` (null for sweep.json).
    pub shard: Option<usize>,
}

/// One `--vary` in a [`SweepRecord`].
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct VaryRecord {
    /// Dotted case key.
    pub key: String,
    /// Values as written.
    pub values: Vec<String>,
}

impl SweepRecord {
    /// The record of a sweep of `case` (read to hash it).
    pub fn new(case: &Path, set: &[String], varies: &[Vary], shard: Option<Shard>) -> Result<Self, Error> {
        let bytes = std::fs::read(case).map_err(|e| Error::Sweep {
            message: format!("{}: {e}", case.display()),
        })?;
        Ok(Self {
            written_by: format!("rollbem {}", env!("CARGO_PKG_VERSION")),
            case: case.display().to_string(),
            case_hash: format!("fnv1a64:{:016x}", fnv1a64(&bytes)),
            set: set.to_vec(),
            vary: varies
                .iter()
                .map(|v| VaryRecord {
                    key: v.key.clone(),
                    values: v.values.clone(),
                })
                .collect(),
            runs: product(varies).len(),
            shards: shard.map(|s| s.count),
            shard: shard.map(|s| s.index),
        })
    }

    /// How `other` differs from this record as a sweep (the shard index and the case path
    /// aside); `None` when both belong to the same sweep.
    pub fn difference(&self, other: &SweepRecord) -> Option<String> {
        if self.case_hash != other.case_hash {
            return Some(format!(
                "the case file differs ({} against {})",
                other.case_hash, self.case_hash
            ));
        }
        if self.vary != other.vary {
            let show = |r: &SweepRecord| {
                r.vary
                    .iter()
                    .map(|v| format!("--vary {}={}", v.key, v.values.join(",")))
                    .collect::<Vec<_>>()
                    .join(" ")
            };
            return Some(format!(
                "the varied values differ ({} against {})",
                show(other),
                show(self)
            ));
        }
        if self.set != other.set {
            return Some(format!(
                "the --set overrides differ ({:?} against {:?})",
                other.set, self.set
            ));
        }
        if self.shards != other.shards {
            let show = |n: Option<usize>| n.map_or("unsharded".to_string(), |n| format!("{n} shards"));
            return Some(format!(
                "the sharding differs ({} against {})",
                show(other.shards),
                show(self.shards)
            ));
        }
        (self.runs != other.runs).then(|| format!("the number of runs differs ({} against {})", other.runs, self.runs))
    }

    /// The file name of the table this record describes.
    fn csv_name(&self) -> String {
        match (self.shard, self.shards) {
            (Some(k), Some(n)) => format!("sweep_shard_{k}_of_{n}.csv"),
            _ => "sweep.csv".into(),
        }
    }
}

/// FNV-1a, 64 bits (Fowler, Noll, Vo): a fast content hash to tell case files apart (not a
/// cryptographic one: it guards against mistakes, not against forgery).
pub fn fnv1a64(bytes: &[u8]) -> u64 {
    bytes.iter().fold(0xcbf2_9ce4_8422_2325, |h, &b| {
        (h ^ u64::from(b)).wrapping_mul(0x0000_0100_0000_01b3)
    })
}

fn sweep_err(message: String) -> Error {
    Error::Sweep { message }
}

fn read_record(path: &Path) -> Result<SweepRecord, Error> {
    let text = std::fs::read_to_string(path).map_err(|e| sweep_err(format!("{}: {e}", path.display())))?;
    serde_json::from_str(&text).map_err(|e| {
        sweep_err(format!(
            "{}: not a sweep record written by rollbem ({e}); rerun that sweep or shard",
            path.display()
        ))
    })
}

fn write_record(dir: &Path, record: &SweepRecord) -> Result<(), Error> {
    let name = record.csv_name().replace(".csv", ".json");
    let json = serde_json::to_string_pretty(record).map_err(|e| Error::Output {
        path: dir.join(&name),
        message: e.to_string(),
    })?;
    Ok(folder::write_file_atomically(&dir.join(name), json.as_bytes())?)
}

/// Runs a sweep (or one shard of it) into `out`.
///
/// `out` must be new, empty or a sweep folder (see [`crate::output::folder`]): a folder holding
/// anything else is refused before any run. An unsharded sweep locks `out` for itself; the
/// shards of one sweep share it, each locking its own table. The runs' rows are appended to the
/// table as they finish (in the order they finish; rewritten in run order at the end), so a
/// killed sweep leaves the finished ones, and `resume` re-runs only the runs that are missing or
/// failed (the table must belong to the same sweep). Without `resume`, an unsharded sweep into
/// a folder of an earlier sweep replaces it atomically when complete; a shard re-runs its runs.
pub fn run(
    case: &Path,
    base_set: &[String],
    varies: &[Vary],
    shard: Option<Shard>,
    out: &Path,
    resume: bool,
) -> Result<SweepReport, Error> {
    if varies.is_empty() {
        return Err(sweep_err(
            "nothing to sweep: give at least one --vary key.path=v1,v2,...".into(),
        ));
    }
    // Fail fast on an unreadable case; value errors are per-run failures.
    crate::case::load(case, base_set)?;
    let record = SweepRecord::new(case, base_set, varies, shard)?;
    let access = if shard.is_some() {
        Access::Shared
    } else {
        Access::Exclusive
    };
    let claim = Claim::acquire(out, Kind::Sweep, access)?;
    let dir = claim.path().to_path_buf();
    let _shard_lock = match shard {
        Some(_) => Some(lock_table(&dir, &record)?),
        None => None,
    };
    check_other_records(&dir, &record, resume)?;
    let job = Job {
        case,
        base_set,
        varies,
        shard,
        record: &record,
    };
    let holds_sweep = folder::read_manifest(&dir).is_some();
    let (rows, resumed) = if shard.is_none() && holds_sweep && !resume {
        // Replace the earlier sweep atomically: run into a temporary sibling, renamed at the end.
        let mut done = None;
        claim.write(|tmp| {
            done = Some(job.run_in(tmp, false)?);
            Ok(())
        })?;
        done.unwrap_or_default()
    } else {
        claim.create_in_place()?;
        job.run_in(&dir, resume)?
    };
    Ok(SweepReport {
        csv: dir.join(record.csv_name()),
        dir,
        rows,
        total_runs: record.runs,
        resumed,
    })
}

/// Locks a shard's table in `dir` (two processes must not run the same shard).
fn lock_table(dir: &Path, record: &SweepRecord) -> Result<FileLock, Error> {
    let lock = dir.join(format!(".{}.rollbem-lock", record.csv_name()));
    std::fs::create_dir_all(dir).map_err(|e| Error::Output {
        path: dir.to_path_buf(),
        message: e.to_string(),
    })?;
    FileLock::try_acquire(&lock, Access::Exclusive)?.ok_or_else(|| {
        Error::Folder(FolderError::Busy {
            dir: dir.join(record.csv_name()),
            lock,
        })
    })
}

/// Refuses to mix sweeps in one folder: every record there (sweep.json, shard files) must
/// belong to the same sweep as `record`. An unsharded sweep without `resume` replaces the
/// folder, so only a resumed one is checked against sweep.json.
fn check_other_records(dir: &Path, record: &SweepRecord, resume: bool) -> Result<(), Error> {
    if record.shards.is_none() && !resume {
        return Ok(());
    }
    let Ok(names) = std::fs::read_dir(dir) else {
        return Ok(());
    };
    let mut names: Vec<String> = names
        .filter_map(|e| e.ok().map(|e| e.file_name().to_string_lossy().into_owned()))
        .filter(|n| n == "sweep.json" || folder::shard_file_name(n).is_some_and(|(_, _, ext)| ext == "json"))
        .collect();
    names.sort();
    for name in names {
        let path = dir.join(&name);
        let other = read_record(&path)?;
        if let Some(diff) = record.difference(&other) {
            let what = if record.shards.is_some() {
                "this shard"
            } else {
                "this sweep"
            };
            return Err(sweep_err(format!(
                "{} belongs to another sweep than {what}: {diff}. Sweeps are not mixed in one folder: \
                 give another --out",
                path.display()
            )));
        }
    }
    Ok(())
}

/// One sweep (or shard) to run.
struct Job<'a> {
    case: &'a Path,
    base_set: &'a [String],
    varies: &'a [Vary],
    shard: Option<Shard>,
    record: &'a SweepRecord,
}

impl Job<'_> {
    /// Runs the sweep in the folder `dir` (which the caller has claimed): record, stale
    /// temporaries removed, finished runs kept when resuming, the rest run in parallel with
    /// their rows appended to the table as they finish. Returns the rows and how many were kept.
    fn run_in(&self, dir: &Path, resume: bool) -> Result<(Vec<RunRow>, usize), Error> {
        let runs = product(self.varies);
        let mine = |n: usize| self.shard.is_none_or(|s| s.owns(n));
        let csv_name = self.record.csv_name();
        let mut tables = vec![csv_name.clone(), csv_name.replace(".csv", ".json")];
        if self.shard.is_none() {
            tables.extend(["sweep.pvd".to_string(), folder::MANIFEST.to_string()]);
        }
        clean_stale(dir, &mine, &tables);
        write_record(dir, self.record)?;
        let csv_path = dir.join(self.record.csv_name());
        let keys: Vec<String> = self.varies.iter().map(|v| v.key.clone()).collect();
        let kept: Vec<RunRow> = if resume {
            read_rows_leniently(&csv_path, &keys, &runs)
                .into_iter()
                .filter(|r| mine(r.run) && (r.status == "ok" || r.status == "not_converged"))
                .filter(|r| folder::read_manifest(&dir.join(&r.folder)).is_some())
                .collect()
        } else {
            Vec::new()
        };
        let done: std::collections::HashSet<usize> = kept.iter().map(|r| r.run).collect();
        let todo: Vec<(usize, &Vec<(String, String)>)> = runs
            .iter()
            .enumerate()
            .filter(|(n, _)| mine(*n) && !done.contains(n))
            .collect();
        write_rows(&csv_path, &keys, &kept)?;
        let table = Mutex::new(Appender::open(&csv_path)?);
        let bar = ProgressBar::new(todo.len() as u64);
        bar.set_style(
            ProgressStyle::with_template("{spinner} [{elapsed_precise}] {bar:40} {pos}/{len} runs, eta {eta} {msg}")
                .unwrap_or_else(|_| ProgressStyle::default_bar()),
        );
        let new_rows: Vec<Result<RunRow, Error>> = todo
            .par_iter()
            .map(|(n, overrides)| {
                let row = run_one(self.case, self.base_set, dir, *n, overrides);
                let appended = table
                    .lock()
                    .map_err(|_| sweep_err("the table writer failed in another thread".into()))
                    .and_then(|mut t| t.append(&row));
                bar.inc(1);
                appended.map(|()| row)
            })
            .collect();
        bar.finish_and_clear();
        drop(table);
        let resumed = kept.len();
        let mut rows = kept;
        for r in new_rows {
            rows.push(r?);
        }
        rows.sort_by_key(|r| r.run);
        write_rows(&csv_path, &keys, &rows)?;
        if self.shard.is_none() {
            write_pvd(&dir.join("sweep.pvd"), dir, &rows)?;
        }
        Ok((rows, resumed))
    }
}

/// Removes temporaries that killed writers left for this sweep's runs (`.run_NNNN.partial-PID`,
/// `.run_NNNN.old-PID`, unheld `.run_NNNN.rollbem-lock`) and for its own files (`tables`:
/// `.sweep.csv.partial-PID`, ...); the caller holds the sweep's (or the shard's) lock, so no live
/// writer owns them.
fn clean_stale(dir: &Path, mine: &dyn Fn(usize) -> bool, tables: &[String]) {
    let Ok(entries) = std::fs::read_dir(dir) else { return };
    for name in entries.filter_map(|e| e.ok().map(|e| e.file_name().to_string_lossy().into_owned())) {
        let Some(hidden) = name.strip_prefix('.') else { continue };
        let base = hidden
            .rsplit_once(".partial-")
            .or_else(|| hidden.rsplit_once(".old-"))
            .map_or(hidden.strip_suffix(".rollbem-lock").unwrap_or(""), |(b, _)| b);
        let ours = match base.strip_prefix("run_").map(str::parse::<usize>) {
            Some(Ok(n)) => mine(n),
            _ => tables.iter().any(|t| t == base),
        };
        let path = dir.join(&name);
        match folder::sweep_owns(&name) {
            Some(SweepEntry::Temporary) if ours && path.is_dir() => {
                let _ = folder::remove_owned(&path);
            }
            Some(SweepEntry::Temporary) if ours => {
                let _ = std::fs::remove_file(&path);
            }
            Some(SweepEntry::File) if ours && name.ends_with(".rollbem-lock") && base.starts_with("run_") => {
                // Taking the lock removes the file when it is released; a held one stays.
                if let Ok(lock) = FileLock::try_acquire(&path, Access::Exclusive) {
                    drop(lock);
                }
            }
            _ => {}
        }
    }
}

/// The header of sweep.csv (and of the shard files).
fn header(keys: &[String]) -> Vec<String> {
    let mut h: Vec<String> = ["run", "folder", "status"].map(String::from).to_vec();
    h.extend(keys.iter().cloned());
    h.push("message".into());
    h.extend(RESULT_COLUMNS.map(String::from));
    h
}

/// Writes the table (header and rows) atomically.
fn write_rows(path: &Path, keys: &[String], rows: &[RunRow]) -> Result<(), Error> {
    let io = |e: &dyn std::fmt::Display| Error::Output {
        path: path.to_path_buf(),
        message: e.to_string(),
    };
    let mut w = csv::Writer::from_writer(Vec::new());
    w.write_record(header(keys)).map_err(|e| io(&e))?;
    for r in rows {
        w.write_record(r.record()).map_err(|e| io(&e))?;
    }
    let bytes = w.into_inner().map_err(|e| io(&e))?;
    Ok(folder::write_file_atomically(path, &bytes)?)
}

/// Appends rows to a table as runs finish, each flushed at once (a killed sweep keeps them).
struct Appender {
    path: PathBuf,
    writer: csv::Writer<std::fs::File>,
}

impl Appender {
    fn open(path: &Path) -> Result<Self, Error> {
        let file = std::fs::OpenOptions::new()
            .append(true)
            .open(path)
            .map_err(|e| Error::Output {
                path: path.to_path_buf(),
                message: e.to_string(),
            })?;
        Ok(Self {
            path: path.to_path_buf(),
            writer: csv::Writer::from_writer(file),
        })
    }

    fn append(&mut self, row: &RunRow) -> Result<(), Error> {
        let io = |e: &dyn std::fmt::Display| Error::Output {
            path: self.path.clone(),
            message: e.to_string(),
        };
        self.writer.write_record(row.record()).map_err(|e| io(&e))?;
        self.writer.flush().map_err(|e| io(&e))
    }
}

/// Rows of a table written by a sweep that may have been killed: a row that does not parse (a
/// torn last line), does not fit the header or does not match its run's values is dropped, so
/// that its run is done again. A missing or unreadable table gives no rows.
fn read_rows_leniently(path: &Path, keys: &[String], runs: &[Vec<(String, String)>]) -> Vec<RunRow> {
    let Ok(mut reader) = csv::ReaderBuilder::new().flexible(true).from_path(path) else {
        return Vec::new();
    };
    let expected = header(keys);
    match reader.headers() {
        Ok(h) if h.iter().eq(expected.iter().map(String::as_str)) => {}
        _ => return Vec::new(),
    }
    reader
        .records()
        .filter_map(Result::ok)
        .filter_map(|rec| parse_row(&rec, keys.len(), runs).ok())
        .collect()
}

/// A table row as a [`RunRow`], checked against the sweep: field count, run number in range,
/// folder and values those of that run, a known status.
fn parse_row(rec: &csv::StringRecord, n_keys: usize, runs: &[Vec<(String, String)>]) -> Result<RunRow, String> {
    let width = 4 + n_keys + RESULT_COLUMNS.len();
    if rec.len() != width {
        return Err(format!("{} fields where the header has {width}", rec.len()));
    }
    let field = |i: usize| rec.get(i).unwrap_or_default().to_string();
    let run: usize = field(0)
        .parse()
        .map_err(|_| format!("run number `{}` is not a number", field(0)))?;
    let Some(overrides) = runs.get(run) else {
        return Err(format!("run {run} is not a run of this sweep (it has {})", runs.len()));
    };
    let values: Vec<String> = (0..n_keys).map(|i| field(3 + i)).collect();
    if values.iter().zip(overrides).any(|(v, (_, expected))| v != expected) {
        return Err(format!("the values of run {run} are not those of the sweep"));
    }
    let status = field(2);
    if !matches!(status.as_str(), "ok" | "not_converged" | "failed") {
        return Err(format!("unknown status `{status}` of run {run}"));
    }
    Ok(RunRow {
        run,
        folder: field(1),
        status,
        values,
        message: field(3 + n_keys),
        results: (0..RESULT_COLUMNS.len()).map(|i| field(4 + n_keys + i)).collect(),
        has_vtk: false,
        internal_error: false,
    })
}

/// sweep.pvd: each successful run's contact line as one time step (the run number), with file
/// paths relative to `dir`; written atomically.
fn write_pvd(path: &Path, dir: &Path, rows: &[RunRow]) -> Result<(), Error> {
    let entries: Vec<CollectionEntry> = rows
        .iter()
        .filter(|r| r.status == "ok" && (r.has_vtk || dir.join(&r.folder).join("contact.vtu").is_file()))
        .map(|r| {
            let file = Path::new(&r.folder).join("contact.vtu");
            let rel = pathdiff(dir, &file);
            CollectionEntry {
                file: rel,
                timestep: r.run as f64,
                part: 0,
                name: format!("contact {}", r.folder),
            }
        })
        .collect();
    write_collection_atomically(path, &entries)
}

fn write_collection_atomically(path: &Path, entries: &[CollectionEntry]) -> Result<(), Error> {
    let tmp = folder::temp_file_path(path);
    write_collection(&tmp, entries)?;
    std::fs::rename(&tmp, path).map_err(|e| {
        let _ = std::fs::remove_file(&tmp);
        Error::Output {
            path: path.to_path_buf(),
            message: e.to_string(),
        }
    })
}

/// `file` as written relative to `dir` (files given relative to dir stay as they are).
fn pathdiff(dir: &Path, file: &Path) -> String {
    file.strip_prefix(dir)
        .unwrap_or(file)
        .to_string_lossy()
        .replace('\\', "/")
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
fn relative(base: &Path, target: &Path) -> String {
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

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn product_order_and_shards_partition_the_runs() {
        let v = [Vary::parse("a=1,2,3").unwrap(), Vary::parse("b=x,y").unwrap()];
        let runs = product(&v);
        assert_eq!(runs.len(), 6);
        assert_eq!(runs[1], vec![("a".into(), "1".into()), ("b".into(), "y".into())]);
        let mut seen = [0; 6];
        for k in 1..=4 {
            let s = Shard::parse(&format!("{k}/4")).unwrap();
            (0..6).filter(|&n| s.owns(n)).for_each(|n| seen[n] += 1);
        }
        assert!(seen.iter().all(|&c| c == 1));
        assert!(Shard::parse("0/4").is_err() && Shard::parse("5/4").is_err() && Shard::parse("x").is_err());
        assert!(Vary::parse("a").is_err() && Vary::parse("a=1,,2").is_err());
    }

    #[test]
    fn relative_paths() {
        assert_eq!(relative(Path::new("/a/b"), Path::new("/a/b/c")), "c");
        assert_eq!(relative(Path::new("/a/b"), Path::new("/a/d/c")), "../d/c");
    }
}
