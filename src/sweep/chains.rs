//! The runs of a sweep in chains of neighbours: ordered so that each run follows the one
//! nearest to it in the varied values, split into one contiguous chain per worker thread, and
//! solved on one shared assembly with warm starts ([`crate::sequence`]) where the varied keys
//! allow it, or, on an error-controlled grid, each warm-started from the last run's solution
//! ([`GridChain`]); every other run is done on its own.

use super::row::{failed_row, guarded, row_of_summary, run_alone, run_folder, RunRow};
use super::{Runs, Vary};
use crate::case::LoadedCase;
use crate::scene::Scene;
use crate::sequence::{Chain, GridChain, SequenceError, Shared};
use rayon::prelude::*;
use std::path::Path;
use std::time::Instant;

/// Whether a varied key leaves the assembly of the bodies as it is: loads, creepage and speed
/// (`load.*`), the friction coefficient and the solver settings. Whether a run then shares it
/// is decided on its scene ([`Shared::shares`]: a normal load may resize the grid).
pub(super) fn may_share(key: &str) -> bool {
    key.starts_with("load.") || key == "contact.friction" || key.starts_with("solver.")
}

/// The ranks of a `--vary`'s values in increasing order: numerically when every value is a
/// number, else in the order given.
fn value_ranks(vary: &Vary) -> Vec<usize> {
    let numbers: Option<Vec<f64>> = vary.values.iter().map(|v| v.parse::<f64>().ok()).collect();
    let Some(numbers) = numbers else {
        return (0..vary.values.len()).collect();
    };
    let mut order: Vec<usize> = (0..numbers.len()).collect();
    order.sort_by(|&a, &b| numbers[a].total_cmp(&numbers[b]));
    let mut ranks = vec![0; numbers.len()];
    for (rank, &k) in order.iter().enumerate() {
        ranks[k] = rank;
    }
    ranks
}

/// `todo` ordered so that neighbours follow each other: by the values' ranks, the first
/// `--vary` slowest, each inner key's direction turned at every step of the outer ones (a
/// boustrophedon), so that consecutive runs differ in one value by one step.
pub(super) fn neighbour_order(runs: &Runs, varies: &[Vary], mut todo: Vec<usize>) -> Vec<usize> {
    let ranks: Vec<Vec<usize>> = varies.iter().map(value_ranks).collect();
    let position = |n: usize| {
        let mut pos = 0usize;
        for (k, v) in varies.iter().enumerate() {
            let index = v.values.iter().position(|x| x == runs.value(n, k)).unwrap_or(0);
            let rank = ranks[k][index];
            let len = v.values.len();
            let step = if pos % 2 == 1 { len - 1 - rank } else { rank };
            pos = pos * len + step;
        }
        pos
    };
    todo.sort_by_key(|&n| position(n));
    todo
}

/// `order` cut into at most `workers` contiguous chains of near-equal length.
pub(super) fn contiguous_chains(order: &[usize], workers: usize) -> Vec<&[usize]> {
    if order.is_empty() {
        return Vec::new();
    }
    let count = workers.clamp(1, order.len());
    let size = order.len().div_ceil(count);
    order.chunks(size).collect()
}

/// What one chain of a sweep carries from a run to the next.
pub(super) enum Link<'a> {
    /// Nothing: every run is done on its own.
    Alone,
    /// The shared assembly and the last run's solution (fixed grids).
    Shared(Box<Chain<'a>>),
    /// The last run's solution, the next run's warm start (error-controlled grids).
    Grids(Box<GridChain>),
}

/// Solves the runs `order` (already in [`neighbour_order`]) of the case text `text` in
/// contiguous chains, one per thread of the current rayon pool ([`contiguous_chains`]), on one
/// shared assembly when the varied keys allow it, or warm from the last run on an
/// error-controlled grid ([`Points::share`]); `each` solves run `n` with the points and its
/// chain's link. The results come back in `order`'s order.
pub(super) fn solve_in_chains<R: Send>(
    mut points: Points<'_>,
    runs: &Runs,
    varies: &[Vary],
    order: &[usize],
    each: impl Fn(&Points, &mut Link, usize) -> R + Sync,
) -> Vec<R> {
    points.share(varies, order.first().map(|&n| runs.overrides(n)).as_deref());
    let points = &points;
    contiguous_chains(order, rayon::current_num_threads())
        .par_iter()
        .flat_map_iter(|runs_of_chain| {
            let mut link = match (&points.shared, points.grids) {
                (Some(s), _) => Link::Shared(Box::new(s.chain())),
                (None, true) => Link::Grids(Box::default()),
                (None, false) => Link::Alone,
            };
            runs_of_chain
                .iter()
                .map(|&n| each(points, &mut link, n))
                .collect::<Vec<_>>()
        })
        .collect()
}

/// What every run of a sweep shares: the case, the overrides, the folder and the assembly.
pub(super) struct Points<'a> {
    /// The case file.
    pub case: &'a Path,
    /// Its text, read and parsed once.
    pub parsed: crate::case::ParsedCase,
    /// The `--set` overrides.
    pub base_set: &'a [String],
    /// The sweep's folder.
    pub out: &'a Path,
    /// Whether each run writes its own folder.
    pub per_run_files: bool,
    /// The shared assembly, when the varied keys allow one.
    pub shared: Option<Shared>,
    /// Whether the runs are error-controlled and the varied keys leave the bodies as they
    /// are: each then starts warm from the last run of its chain ([`GridChain`]).
    pub grids: bool,
}

impl Points<'_> {
    /// The case of one run: the `--set` overrides, then the run's.
    fn case_of(&self, overrides: &[(String, String)]) -> Result<LoadedCase, crate::error::Error> {
        let mut set = self.base_set.to_vec();
        set.extend(overrides.iter().map(|(k, v)| format!("{k}={v}")));
        Ok(self.parsed.with_overrides(&set)?)
    }

    /// The assembly the runs share: that of the scene of `first` (a run of the sweep), when
    /// every varied key [`may_share`] and that scene can start a sequence; None otherwise (each
    /// run then builds its own). An error-controlled scene shares no assembly: its runs are
    /// chained by their solutions instead ([`Self::grids`]).
    pub fn share(&mut self, varies: &[Vary], first: Option<&[(String, String)]>) {
        let Some(first) = first.filter(|_| varies.iter().all(|v| may_share(&v.key))) else {
            return;
        };
        let scene = self.case_of(first).and_then(|c| Scene::from_case(&c));
        self.shared = match scene.map(|s| Shared::new(&s)) {
            Ok(Ok(shared)) => Some(shared),
            Ok(Err(SequenceError::AdaptiveGrid)) => {
                self.grids = true;
                None
            }
            Ok(Err(e)) => {
                log::info!("the runs build their own assemblies: {e}");
                None
            }
            Err(_) => None,
        };
    }

    /// Runs one point: on the chain's shared assembly when its scene shares it, warm from the
    /// chain's last run on an error-controlled grid, else on its own.
    pub fn run(&self, link: &mut Link, run: usize, overrides: &[(String, String)]) -> RunRow {
        guarded(run, overrides, || {
            let start = Instant::now();
            let chain = match (link, self.shared.as_ref()) {
                (Link::Shared(chain), Some(shared)) => (chain, shared),
                (Link::Grids(chain), _) => return self.run_warm(chain, run, overrides, start),
                _ => return self.alone(run, overrides),
            };
            let (chain, shared) = chain;
            let scene = match self.case_of(overrides).and_then(|c| shared.scene_of(c)) {
                Ok(Some(scene)) => scene,
                Ok(None) => return self.alone(run, overrides),
                Err(e) => return failed_row(run, self.folder(run), overrides, e.to_string()),
            };
            let folder = self.folder(run);
            let dir = self.out.join(&folder);
            let summary = chain.solve_with(scene, start, |solved| {
                if self.per_run_files {
                    crate::app::write_solved(solved, &dir, start)
                } else {
                    crate::app::checked_summary(solved)
                }
            });
            match summary {
                Ok((Ok(s), _)) => row_of_summary(run, folder, overrides, &s),
                Ok((Err(e), _)) | Err(e) => failed_row(run, folder, overrides, e.to_string()),
            }
        })
    }

    /// An error-controlled run warm from `chain`'s last run ([`GridChain`]), written to its
    /// folder with per-run files.
    fn run_warm(&self, chain: &mut GridChain, run: usize, overrides: &[(String, String)], start: Instant) -> RunRow {
        let folder = self.folder(run);
        let dir = self.out.join(&folder);
        let summary = self
            .case_of(overrides)
            .and_then(|c| Scene::from_case(&c))
            .and_then(|scene| {
                chain.solve_with(scene, start, |solved| {
                    if self.per_run_files {
                        crate::app::write_solved(solved, &dir, start)
                    } else {
                        crate::app::checked_summary(solved)
                    }
                })
            });
        match summary {
            Ok(Ok(s)) => row_of_summary(run, folder, overrides, &s),
            Ok(Err(e)) | Err(e) => {
                chain.restart_cold();
                failed_row(run, folder, overrides, e.to_string())
            }
        }
    }

    /// The summary of one point, nothing written (the library's [`super::summaries`]): on the
    /// chain's shared assembly when its scene shares it, warm from the chain's last run on an
    /// error-controlled grid, else solved on its own.
    pub fn summary(
        &self,
        link: &mut Link,
        overrides: &[(String, String)],
    ) -> Result<crate::output::Summary, crate::error::Error> {
        let start = Instant::now();
        match (link, self.shared.as_ref()) {
            (Link::Shared(chain), Some(shared)) => {
                if let Some(scene) = shared.scene_of(self.case_of(overrides)?)? {
                    return chain.solve_with(scene, start, crate::app::checked_summary)?.0;
                }
            }
            (Link::Grids(chain), _) => {
                let scene = Scene::from_case(&self.case_of(overrides)?)?;
                return chain.solve_with(scene, start, crate::app::checked_summary)?;
            }
            _ => {}
        }
        crate::app::solve(&self.case_of(overrides)?).and_then(|s| crate::app::checked_summary(&s))
    }

    fn alone(&self, run: usize, overrides: &[(String, String)]) -> RunRow {
        run_alone(self.case, self.base_set, self.out, self.per_run_files, run, overrides)
    }

    /// The folder column of run `run`: its folder with per-run files, else empty.
    fn folder(&self, run: usize) -> String {
        if self.per_run_files {
            run_folder(run)
        } else {
            String::new()
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn neighbours_follow_each_other_in_a_boustrophedon() {
        let v = [Vary::parse("a=2,1").unwrap(), Vary::parse("b=0.3,0.1,0.2").unwrap()];
        let runs = Runs::new(&v).unwrap();
        let order = neighbour_order(&runs, &v, (0..6).collect());
        let values: Vec<(String, String)> = order
            .iter()
            .map(|&n| (runs.value(n, 0).to_string(), runs.value(n, 1).to_string()))
            .collect();
        let expected = [
            ("1", "0.1"),
            ("1", "0.2"),
            ("1", "0.3"),
            ("2", "0.3"),
            ("2", "0.2"),
            ("2", "0.1"),
        ];
        assert_eq!(values, expected.map(|(a, b)| (a.to_string(), b.to_string())));
        let chains = contiguous_chains(&order, 4);
        assert_eq!(chains.iter().map(|c| c.len()).sum::<usize>(), 6);
        assert!(chains.len() <= 4 && contiguous_chains(&[], 2).is_empty());
        assert!(may_share("load.tangential.ratio") && may_share("contact.friction"));
        assert!(!may_share("contact.grid.elements") && !may_share("bodies.A.radius"));
    }
}
