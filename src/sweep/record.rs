//! What sweep a table belongs to: the record written next to it and compared on `--resume`,
//! by shards that share a folder, and by `--merge`.

use super::{sweep_err, Runs, Shard, Vary};
use crate::error::Error;
use crate::output::folder;
use serde::{Deserialize, Serialize};
use std::path::Path;

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
            runs: Runs::new(varies)?.count(),
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
    pub(super) fn csv_name(&self) -> String {
        match (self.shard, self.shards) {
            (Some(k), Some(n)) => format!("sweep_shard_{k}_of_{n}.csv"),
            _ => "sweep.csv".into(),
        }
    }
}

pub use crate::files::fnv1a64;

pub(super) fn read_record(path: &Path) -> Result<SweepRecord, Error> {
    let text = std::fs::read_to_string(path).map_err(|e| sweep_err(format!("{}: {e}", path.display())))?;
    serde_json::from_str(&text).map_err(|e| {
        sweep_err(format!(
            "{}: not a sweep record written by rollbem ({e}); rerun that sweep or shard",
            path.display()
        ))
    })
}

pub(super) fn write_record(dir: &Path, record: &SweepRecord) -> Result<(), Error> {
    let name = record.csv_name().replace(".csv", ".json");
    let json = serde_json::to_string_pretty(record).map_err(|e| Error::Output {
        path: dir.join(&name),
        message: e.to_string(),
    })?;
    Ok(folder::write_file_atomically(&dir.join(name), json.as_bytes())?)
}
