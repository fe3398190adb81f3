//! The runs of a sweep: the `--vary` options, their Cartesian product generated one run at a
//! time, and the shards that split it.

use super::sweep_err;
use crate::error::Error;

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

    /// The run numbers of this shard among `total` runs, in order (without visiting the others).
    pub fn runs(&self, total: usize) -> impl Iterator<Item = usize> {
        (self.index - 1..total).step_by(self.count)
    }
}

/// Most runs one sweep may have: a sweep's table, its run numbers and `--merge` hold a row per
/// run; beyond this a typo (three `--vary` of 1000 values) is far likelier than intent.
pub const MAX_RUNS: usize = 10_000_000;

/// The runs of a sweep, generated one at a time (never the whole product in memory): run n's
/// values are the digits of n in the mixed radix of the value counts, the last `--vary` varying
/// fastest.
#[derive(Debug, Clone, Copy)]
pub struct Runs<'a> {
    varies: &'a [Vary],
    count: usize,
}

impl<'a> Runs<'a> {
    /// The runs of `varies`; more than [`MAX_RUNS`] (or more than a `usize` counts) is refused
    /// with the count.
    pub fn new(varies: &'a [Vary]) -> Result<Self, Error> {
        let count = varies
            .iter()
            .try_fold(1usize, |n, v| n.checked_mul(v.values.len()))
            .filter(|&n| n <= MAX_RUNS);
        match count {
            Some(count) => Ok(Self { varies, count }),
            None => {
                let shown = varies
                    .iter()
                    .map(|v| v.values.len().to_string())
                    .collect::<Vec<_>>()
                    .join(" × ");
                let total: f64 = varies.iter().map(|v| v.values.len() as f64).product();
                Err(sweep_err(format!(
                    "the --vary options make {shown} = {total:.3e} runs; a sweep may have at most \
                     {MAX_RUNS} runs: vary fewer keys or values (or split the study into several sweeps)"
                )))
            }
        }
    }

    /// Number of runs.
    pub fn count(&self) -> usize {
        self.count
    }

    /// Index of run `run`'s value of `--vary` number `key` (`run` < [`Self::count`]).
    fn index(&self, run: usize, key: usize) -> usize {
        let inner: usize = self.varies[key + 1..].iter().map(|v| v.values.len()).product();
        (run / inner) % self.varies[key].values.len()
    }

    /// Run `run`'s value of `--vary` number `key`.
    pub fn value(&self, run: usize, key: usize) -> &'a str {
        &self.varies[key].values[self.index(run, key)]
    }

    /// Run `run`'s overrides: (key, value) per `--vary`, in order.
    pub fn overrides(&self, run: usize) -> Vec<(String, String)> {
        (0..self.varies.len())
            .map(|k| (self.varies[k].key.clone(), self.value(run, k).to_string()))
            .collect()
    }
}

/// The runs of a sweep, all at once: each is a list of (key, value) overrides (for small sweeps;
/// [`Runs`] generates them one at a time). Refused like [`Runs::new`] beyond [`MAX_RUNS`] runs.
pub fn product(varies: &[Vary]) -> Result<Vec<Vec<(String, String)>>, Error> {
    let runs = Runs::new(varies)?;
    Ok((0..runs.count()).map(|n| runs.overrides(n)).collect())
}
