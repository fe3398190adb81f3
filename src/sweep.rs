//! Parameter sweeps: the Cartesian product of `--vary key=v1,v2,…` over a case, run in parallel
//! (rayon) with a progress bar (indicatif), a `sweep.csv` with the varied values and the summary
//! numbers of every run and its record `sweep.json`; with `--per-run-files` also one sub-folder
//! per run and a `sweep.pvd` that ParaView steps through.
//!
//! The runs are ordered so that neighbours in the varied values follow each other and cut into
//! one contiguous chain per worker thread ([`chains`]); where the varied keys leave the bodies
//! and the grid as they are, a chain's runs share one assembly and start from the last run's
//! solution ([`crate::sequence`]), so a run's iteration count (not its result, beyond the Newton
//! tolerance) depends on its neighbours. Error-controlled runs share no assembly; each starts
//! warm from the last run of its chain ([`crate::sequence::GridChain`]).
//!
//! Runs are numbered in the order of the product (the first `--vary` varies slowest). Sharding
//! (`--shard K/N`) keeps the runs whose number n satisfies n mod N = K − 1, so N processes on N
//! machines (a Slurm job array, GNU parallel) split one sweep deterministically; each shard writes
//! `sweep_shard_K_of_N.csv`, and [`merge`] joins shard files (from one folder or several) into
//! one `sweep.csv` and `sweep.pvd`. A failed run is recorded as failed and does not stop the
//! others.

/// Most threads `rollbem sweep --jobs` takes: more than any machine's cores by far; a larger
/// count is a mistake (a typo, a product of numbers) and is refused.
pub const MAX_JOBS: usize = 1024;

/// The threads a sweep runs on for `--jobs jobs` (0: one per core) on a machine of `cores`
/// cores, and a warning when the count asked was capped to them: each run is one thread's
/// work, so more threads than cores only add switching (and memory per thread). A count above
/// [`MAX_JOBS`] is refused, naming `--jobs`.
pub fn threads_for(jobs: usize, cores: usize) -> Result<(usize, Option<String>), Error> {
    let cores = cores.max(1);
    if jobs > MAX_JOBS {
        return Err(Error::Sweep {
            message: format!(
                "--jobs {jobs} is more threads than any machine has cores: give at most {MAX_JOBS}, \
                 or leave --jobs out for one thread per core ({cores} here)"
            ),
        });
    }
    Ok(match jobs {
        0 => (cores, None),
        n if n > cores => (
            cores,
            Some(format!(
                "--jobs {n} exceeds the {cores} cores of this machine; running on {cores} threads"
            )),
        ),
        n => (n, None),
    })
}

mod chains;
mod merge;
mod record;
mod row;
mod runs;
mod table;

use crate::error::Error;
use crate::output::folder::{self, Access, Claim, FileLock, FolderError, Kind, SweepEntry};
use indicatif::{ProgressBar, ProgressStyle};
pub use merge::merge;
pub use record::{fnv1a64, SweepRecord, VaryRecord};
use record::{read_record, write_record};
pub use row::{run_folder, RunRow, RESULT_COLUMNS, TIMING_COLUMNS};
pub use runs::{product, Runs, Shard, Vary, MAX_RUNS};
use std::path::{Path, PathBuf};
use std::sync::Mutex;
use table::{read_rows_leniently, write_pvd, write_rows, Appender};

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
fn sweep_err(message: String) -> Error {
    Error::Sweep { message }
}

/// Runs a sweep (or one shard of it) into `out`.
///
/// `out` must be new, empty or a sweep folder (see [`crate::output::folder`]): a folder holding
/// anything else is refused before any run. An unsharded sweep locks `out` for itself; the
/// shards of one sweep share it, each locking its own table. The runs' rows are appended to the
/// table as they finish (in the order they finish; rewritten in run order at the end), so a
/// killed sweep leaves the finished ones, and `resume` re-runs only the runs that are missing or
/// failed (the table must belong to the same sweep; with `per_run_files` also those whose folder
/// is missing or incomplete). With `per_run_files` each run also writes its folder `run_NNNN`
/// (what `rollbem run` writes) and the sweep a `sweep.pvd`. Without `resume`, an unsharded sweep into
/// a folder of an earlier sweep replaces it atomically when complete; a shard re-runs its runs.
pub fn run(
    case: &Path,
    base_set: &[String],
    varies: &[Vary],
    shard: Option<Shard>,
    out: &Path,
    resume: bool,
    per_run_files: bool,
) -> Result<SweepReport, Error> {
    if varies.is_empty() {
        return Err(sweep_err(
            "nothing to sweep: give at least one --vary key.path=v1,v2,...".into(),
        ));
    }
    // Fail fast on an unreadable case or a --set or --vary key that no run could take; value
    // errors (out of range, or only in some combinations) are per-run failures.
    Runs::new(varies)?;
    crate::case::load(case, base_set)?.steady_only("`rollbem sweep`")?;
    check_keys(case, base_set, varies)?;
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
        per_run_files,
    };
    let holds_sweep = folder::read_manifest(&dir).is_some();
    let (rows, resumed) = if shard.is_none() && holds_sweep && !resume {
        // Replace the earlier sweep atomically: run into a temporary sibling, renamed at the end;
        // a file of its runs edited since stops it before anything runs.
        claim.check_unchanged()?;
        let mut done = None;
        claim.write(|tmp| {
            done = Some(job.run_in(tmp, false)?);
            Ok::<(), Error>(())
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

/// Refuses, before anything is written, a `--vary` that every run with one of its values would
/// fail alike: a key given in two `--vary` options, or a key (or value) that the case cannot
/// take at all (a misspelt key, a value that is not of the key's type: what `--set` would refuse).
/// Each value is applied once to the case with the `--set` overrides. A `--vary` of a key that a
/// `--set` also sets wins over it: said in a warning.
fn check_keys(case: &Path, base_set: &[String], varies: &[Vary]) -> Result<(), Error> {
    for (i, v) in varies.iter().enumerate() {
        if varies[..i].iter().any(|w| w.key == v.key) {
            return Err(sweep_err(format!(
                "--vary {} is given twice; give all its values in one --vary {}=v1,v2,... (nothing was run \
                 or written)",
                v.key, v.key
            )));
        }
        for set in base_set {
            if set.split_once('=').is_some_and(|(k, _)| k == v.key) {
                log::warn!(
                    "--vary {} overrides --set {set}: the runs take the varied values",
                    v.key
                );
            }
        }
    }
    let text = std::fs::read_to_string(case).map_err(|e| sweep_err(format!("{}: {e}", case.display())))?;
    let parsed = crate::case::ParsedCase::new(&text, case);
    for v in varies {
        let mut seen = std::collections::HashSet::new();
        for value in v.values.iter().filter(|x| seen.insert(x.as_str())) {
            let argument = format!("{}={value}", v.key);
            let mut set = base_set.to_vec();
            set.push(argument.clone());
            if let Err(crate::case::CaseError::Override {
                argument: blamed,
                message,
            }) = parsed.with_overrides(&set)
            {
                if blamed == argument {
                    return Err(sweep_err(format!(
                        "--vary {}: the value `{value}` cannot be used: {message}; nothing was run or written",
                        v.key
                    )));
                }
            }
        }
    }
    Ok(())
}

/// The summaries of the runs of a sweep of `varies` over the case `source` with the overrides
/// `base_set`, nothing written (the Python module's `sweep`): solved as `rollbem sweep` solves
/// them, in chains of neighbours on one shared assembly where the varied keys allow it, each
/// warm-started from the run before it, one chain per thread of the current rayon pool. Each
/// run's solve is handed to `guard` (the caller's cancellation or panic guard), whose results
/// come back in run order. A case that cannot be read is an error before any run.
pub fn summaries<R: Send>(
    source: crate::app::CaseSource<'_>,
    base_set: &[String],
    varies: &[Vary],
    guard: impl Fn(&mut dyn FnMut() -> Result<crate::output::Summary, Error>) -> R + Sync,
) -> Result<Vec<R>, Error> {
    let (path, text) = match source {
        crate::app::CaseSource::File(path) => (
            path,
            std::fs::read_to_string(path).map_err(|e| sweep_err(format!("{}: {e}", path.display())))?,
        ),
        crate::app::CaseSource::Text { text, path } => (path, text.to_string()),
    };
    let runs = Runs::new(varies)?;
    let order = chains::neighbour_order(&runs, varies, (0..runs.count()).collect());
    let points = chains::Points {
        case: path,
        parsed: crate::case::ParsedCase::new(&text, path),
        base_set,
        out: Path::new(""),
        per_run_files: false,
        shared: None,
        grids: false,
    };
    let mut solved = chains::solve_in_chains(points, &runs, varies, &order, |points, link, n| {
        let overrides = runs.overrides(n);
        (n, guard(&mut || points.summary(link, &overrides)))
    });
    solved.sort_by_key(|(n, _)| *n);
    Ok(solved.into_iter().map(|(_, r)| r).collect())
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
    let table = dir.join(record.csv_name());
    let own = dir.join(record.csv_name().replace(".csv", ".json"));
    if resume && table.exists() && !own.exists() {
        return Err(sweep_err(format!(
            "{}: no record {} says what sweep this table belongs to (deleted, or copied without \
             it), so --resume cannot tell its runs from another sweep's: run without --resume (a \
             sweep replaces the folder's, a shard reruns its runs), or give another --out",
            table.display(),
            own.file_name()
                .map_or_else(String::new, |n| n.to_string_lossy().into_owned())
        )));
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
    /// Whether each run writes its own folder (`--per-run-files`).
    per_run_files: bool,
}

impl Job<'_> {
    /// Runs the sweep in the folder `dir` (which the caller has claimed): record, stale
    /// temporaries removed, finished runs kept when resuming, the rest run in parallel with
    /// their rows appended to the table as they finish. Returns the rows and how many were kept.
    fn run_in(&self, dir: &Path, resume: bool) -> Result<(Vec<RunRow>, usize), Error> {
        let runs = Runs::new(self.varies)?;
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
                .filter(|r| self.finished(dir, r))
                .collect()
        } else {
            Vec::new()
        };
        let done: std::collections::HashSet<usize> = kept.iter().map(|r| r.run).collect();
        let shard = self.shard.unwrap_or(Shard { index: 1, count: 1 });
        let todo: Vec<usize> = shard.runs(runs.count()).filter(|n| !done.contains(n)).collect();
        write_rows(&csv_path, &keys, &kept)?;
        let table = Mutex::new(Appender::open(&csv_path)?);
        let new_rows = self.run_chains(dir, &runs, todo, &table)?;
        drop(table);
        let resumed = kept.len();
        let mut rows = kept;
        rows.extend(new_rows);
        rows.sort_by_key(|r| r.run);
        write_rows(&csv_path, &keys, &rows)?;
        if self.shard.is_none() && self.per_run_files {
            write_pvd(&dir.join("sweep.pvd"), dir, &rows)?;
        }
        Ok((rows, resumed))
    }

    /// Whether a row that an earlier sweep recorded as done is kept on `--resume`: a row
    /// without a folder (a run that wrote no files) when no files are asked for, the table
    /// being its record; a row with its own run's folder only with that folder whole (every
    /// file its manifest lists). Any other is done again.
    fn finished(&self, dir: &Path, r: &RunRow) -> bool {
        if r.folder.is_empty() {
            return !self.per_run_files;
        }
        r.folder == run_folder(r.run) && folder::check_run_folder(&dir.join(&r.folder)).is_ok()
    }

    /// Runs `todo` in chains of neighbours (one per worker thread, [`chains`]), their rows
    /// appended to `table` as they finish.
    fn run_chains(
        &self,
        dir: &Path,
        runs: &Runs,
        todo: Vec<usize>,
        table: &Mutex<Appender>,
    ) -> Result<Vec<RunRow>, Error> {
        let order = chains::neighbour_order(runs, self.varies, todo);
        let text =
            std::fs::read_to_string(self.case).map_err(|e| sweep_err(format!("{}: {e}", self.case.display())))?;
        let points = chains::Points {
            case: self.case,
            parsed: crate::case::ParsedCase::new(&text, self.case),
            base_set: self.base_set,
            out: dir,
            per_run_files: self.per_run_files,
            shared: None,
            grids: false,
        };
        let bar = ProgressBar::new(order.len() as u64);
        bar.set_style(
            ProgressStyle::with_template("{spinner} [{elapsed_precise}] {bar:40} {pos}/{len} runs, eta {eta} {msg}")
                .unwrap_or_else(|_| ProgressStyle::default_bar()),
        );
        let rows = chains::solve_in_chains(points, runs, self.varies, &order, |points, chain, n| {
            let row = points.run(chain, n, &runs.overrides(n));
            let appended = table
                .lock()
                .map_err(|_| sweep_err("the table writer failed in another thread".into()))
                .and_then(|mut t| t.append(&row));
            bar.inc(1);
            appended.map(|()| row)
        });
        bar.finish_and_clear();
        rows.into_iter().collect()
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

#[cfg(test)]
mod tests {
    use super::merge::relative;
    use super::*;

    #[test]
    fn product_order_and_shards_partition_the_runs() {
        let v = [Vary::parse("a=1,2,3").unwrap(), Vary::parse("b=x,y").unwrap()];
        let runs = product(&v).unwrap();
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
    fn runs_are_generated_one_at_a_time_and_counted_without_overflow() {
        let v = [
            Vary::parse("a=1,2,3").unwrap(),
            Vary::parse("b=x,y").unwrap(),
            Vary::parse("c=p,q,r,s").unwrap(),
        ];
        let runs = Runs::new(&v).unwrap();
        assert_eq!(runs.count(), 24);
        let all = product(&v).unwrap();
        for (n, run) in all.iter().enumerate() {
            assert_eq!(&runs.overrides(n), run);
        }
        // The first --vary varies slowest, the last fastest.
        assert_eq!(
            all[5],
            [("a", "1"), ("b", "y"), ("c", "q")].map(|(k, v)| (k.to_string(), v.to_string()))
        );
        let shard = Shard { index: 3, count: 5 };
        assert_eq!(shard.runs(24).collect::<Vec<_>>(), [2, 7, 12, 17, 22]);
        // 2^64 runs overflow a usize count: refused like any count above the limit.
        let wide = Vary {
            key: "k".into(),
            values: vec!["0".into(); 1 << 16],
        };
        let huge = [wide.clone(), wide.clone(), wide.clone(), wide];
        let err = Runs::new(&huge).unwrap_err().to_string();
        assert!(
            err.contains("65536 × 65536 × 65536 × 65536") && err.contains("at most"),
            "{err}"
        );
        // 3163² = 10 004 569 runs: just above the limit; 3162² just below.
        let side = |n: usize| Vary {
            key: "k".into(),
            values: vec!["0".into(); n],
        };
        assert!(Runs::new(&[side(3163), side(3163)]).is_err());
        assert_eq!(Runs::new(&[side(3162), side(3162)]).unwrap().count(), 3162 * 3162);
    }

    #[test]
    fn long_lists_are_summarised() {
        let few: Vec<String> = (1..=5).map(|k| k.to_string()).collect();
        assert_eq!(super::merge::summarise(&few), "1, 2, 3, 4, 5");
        let many: Vec<String> = (1..=100_000).map(|k| k.to_string()).collect();
        assert_eq!(super::merge::summarise(&many), "1, 2, 3, 4, 5, … (100000 in all)");
    }

    #[test]
    fn relative_paths() {
        assert_eq!(relative(Path::new("/a/b"), Path::new("/a/b/c")), "c");
        assert_eq!(relative(Path::new("/a/b"), Path::new("/a/d/c")), "../d/c");
    }
}
