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
use crate::output::vtk::{write_collection, CollectionEntry};
use indicatif::{ProgressBar, ProgressStyle};
use rayon::prelude::*;
use std::path::{Path, PathBuf};

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
}

fn run_one(case: &Path, base_set: &[String], out: &Path, run: usize, overrides: &[(String, String)]) -> RunRow {
    let folder = format!("run_{run:04}");
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
        },
    }
}

/// What a sweep did.
#[derive(Debug, Clone)]
pub struct SweepReport {
    /// Output folder.
    pub dir: PathBuf,
    /// Rows of the runs done here.
    pub rows: Vec<RunRow>,
    /// Total runs in the full product.
    pub total_runs: usize,
    /// The CSV written (sweep.csv, or the shard file).
    pub csv: PathBuf,
}

/// Runs a sweep (or one shard of it) into `out`.
pub fn run(
    case: &Path,
    base_set: &[String],
    varies: &[Vary],
    shard: Option<Shard>,
    out: &Path,
) -> Result<SweepReport, Error> {
    if varies.is_empty() {
        return Err(Error::Sweep {
            message: "nothing to sweep: give at least one --vary key.path=v1,v2,...".into(),
        });
    }
    // Fail fast on an unreadable case; value errors are per-run failures.
    crate::case::load(case, base_set)?;
    let runs = product(varies);
    let total_runs = runs.len();
    let mine: Vec<(usize, &Vec<(String, String)>)> = runs
        .iter()
        .enumerate()
        .filter(|(n, _)| shard.is_none_or(|s| s.owns(*n)))
        .collect();
    std::fs::create_dir_all(out).map_err(|e| Error::Output {
        path: out.to_path_buf(),
        message: e.to_string(),
    })?;
    let bar = ProgressBar::new(mine.len() as u64);
    bar.set_style(
        ProgressStyle::with_template("{spinner} [{elapsed_precise}] {bar:40} {pos}/{len} runs, eta {eta} {msg}")
            .unwrap_or_else(|_| ProgressStyle::default_bar()),
    );
    let mut rows: Vec<RunRow> = mine
        .par_iter()
        .map(|(n, overrides)| {
            let row = run_one(case, base_set, out, *n, overrides);
            bar.inc(1);
            row
        })
        .collect();
    bar.finish_and_clear();
    rows.sort_by_key(|r| r.run);
    let keys: Vec<String> = varies.iter().map(|v| v.key.clone()).collect();
    let csv = match shard {
        None => out.join("sweep.csv"),
        Some(s) => out.join(format!("sweep_shard_{}_of_{}.csv", s.index, s.count)),
    };
    write_rows(&csv, &keys, &rows)?;
    if shard.is_none() {
        write_pvd(&out.join("sweep.pvd"), out, &rows)?;
    }
    Ok(SweepReport {
        dir: out.to_path_buf(),
        rows,
        total_runs,
        csv,
    })
}

fn header(keys: &[String]) -> Vec<String> {
    let mut h: Vec<String> = ["run", "folder", "status"].map(String::from).to_vec();
    h.extend(keys.iter().cloned());
    h.push("message".into());
    h.extend(RESULT_COLUMNS.map(String::from));
    h
}

fn write_rows(path: &Path, keys: &[String], rows: &[RunRow]) -> Result<(), Error> {
    let io = |e: &dyn std::fmt::Display| Error::Output {
        path: path.to_path_buf(),
        message: e.to_string(),
    };
    let tmp = path.with_extension("csv.partial");
    let mut w = csv::Writer::from_path(&tmp).map_err(|e| io(&e))?;
    w.write_record(header(keys)).map_err(|e| io(&e))?;
    for r in rows {
        let mut rec = vec![r.run.to_string(), r.folder.clone(), r.status.clone()];
        rec.extend(r.values.iter().cloned());
        rec.push(r.message.clone());
        rec.extend(r.results.iter().cloned());
        w.write_record(rec).map_err(|e| io(&e))?;
    }
    w.flush().map_err(|e| io(&e))?;
    drop(w);
    std::fs::rename(&tmp, path).map_err(|e| io(&e))
}

/// sweep.pvd: each successful run's contact line as one time step (the run number), with file
/// paths relative to `dir`.
fn write_pvd(path: &Path, dir: &Path, rows: &[RunRow]) -> Result<(), Error> {
    let entries: Vec<CollectionEntry> = rows
        .iter()
        .filter(|r| r.has_vtk)
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
    write_collection(path, &entries)
}

/// `file` as written relative to `dir` (files given relative to dir stay as they are).
fn pathdiff(dir: &Path, file: &Path) -> String {
    file.strip_prefix(dir)
        .unwrap_or(file)
        .to_string_lossy()
        .replace('\\', "/")
}

/// Joins the shard CSV files found in `dirs` (or their `sweep.csv`) into `out/sweep.csv` and
/// `out/sweep.pvd`, rows ordered by run number. Run folders stay where they are; the `folder`
/// column and the .pvd point to them relative to `out`.
pub fn merge(dirs: &[PathBuf], out: &Path) -> Result<PathBuf, Error> {
    let mut header_row: Option<Vec<String>> = None;
    let mut rows: Vec<(usize, Vec<String>)> = Vec::new();
    std::fs::create_dir_all(out).map_err(|e| Error::Output {
        path: out.to_path_buf(),
        message: e.to_string(),
    })?;
    let out_abs = std::fs::canonicalize(out).unwrap_or_else(|_| out.to_path_buf());
    for dir in dirs {
        let mut files: Vec<PathBuf> = std::fs::read_dir(dir)
            .map_err(|e| Error::Sweep {
                message: format!("--merge {}: {e}", dir.display()),
            })?
            .filter_map(|e| e.ok().map(|e| e.path()))
            .filter(|p| {
                p.file_name()
                    .is_some_and(|n| n.to_string_lossy().starts_with("sweep_shard_"))
                    && p.extension().is_some_and(|e| e == "csv")
            })
            .collect();
        files.sort();
        if files.is_empty() {
            return Err(Error::Sweep {
                message: format!(
                    "--merge {}: no sweep_shard_K_of_N.csv files found; run `rollbem sweep --shard K/N` into it first",
                    dir.display()
                ),
            });
        }
        let dir_abs = std::fs::canonicalize(dir).unwrap_or_else(|_| dir.clone());
        for f in files {
            let mut r = csv::Reader::from_path(&f).map_err(|e| Error::Sweep {
                message: format!("{}: {e}", f.display()),
            })?;
            let h: Vec<String> = r
                .headers()
                .map_err(|e| Error::Sweep { message: e.to_string() })?
                .iter()
                .map(String::from)
                .collect();
            match &header_row {
                None => header_row = Some(h),
                Some(prev) if *prev != h => {
                    return Err(Error::Sweep {
                        message: format!(
                            "{}: columns differ from the other shards (different --vary?)",
                            f.display()
                        ),
                    })
                }
                _ => {}
            }
            for rec in r.records() {
                let rec = rec.map_err(|e| Error::Sweep { message: e.to_string() })?;
                let mut v: Vec<String> = rec.iter().map(String::from).collect();
                let run: usize = v[0].parse().map_err(|_| Error::Sweep {
                    message: format!("{}: bad run number {}", f.display(), v[0]),
                })?;
                // Folder relative to the merged output.
                let folder = dir_abs.join(&v[1]);
                v[1] = relative(&out_abs, &folder);
                rows.push((run, v));
            }
        }
    }
    rows.sort_by_key(|(run, _)| *run);
    if let Some(w) = rows.windows(2).find(|w| w[0].0 == w[1].0) {
        return Err(Error::Sweep {
            message: format!("run {} appears in two shards", w[0].0),
        });
    }
    let header_row = header_row.unwrap_or_default();
    let path = out.join("sweep.csv");
    let io = |e: &dyn std::fmt::Display| Error::Output {
        path: path.clone(),
        message: e.to_string(),
    };
    let mut w = csv::Writer::from_path(&path).map_err(|e| io(&e))?;
    w.write_record(&header_row).map_err(|e| io(&e))?;
    for (_, v) in &rows {
        w.write_record(v).map_err(|e| io(&e))?;
    }
    w.flush().map_err(|e| io(&e))?;
    let entries: Vec<CollectionEntry> = rows
        .iter()
        .filter(|(_, v)| v[2] == "ok")
        .map(|(run, v)| CollectionEntry {
            file: format!("{}/contact.vtu", v[1]),
            timestep: *run as f64,
            part: 0,
            name: format!("contact run_{run:04}"),
        })
        .filter(|e| out.join(&e.file).exists())
        .collect();
    write_collection(&out.join("sweep.pvd"), &entries)?;
    Ok(path)
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
