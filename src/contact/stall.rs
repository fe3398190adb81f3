//! Stall detection shared by every solution method: an iteration that has not produced a new
//! best residual, by a relative margin, for a bounded number of its own iterations has stopped
//! making progress and is ended (the default method may then restart, [`super::restart`]).
//!
//! Why a best-so-far test and not the change from one iteration to the next: the line-search
//! Newton decreases its merit ½‖G‖² monotonically but not the measure ‖G‖∞, the plain Newton and
//! Gauss–Seidel are not monotone at all, and a run that converges does so by passing below its
//! best residual again and again. What stalls looks alike in every method: a tolerance below the
//! round-off of the residual (the residual then wanders at 10⁻¹⁴–10⁻¹⁵ for ever), an iterate
//! trapped against a kink of G (a Newton line search that only accepts ever shorter steps), a
//! cycle between active sets (plain Newton, Gauss–Seidel), a divergent alternation (NORM/TANG).
//! Without the test such a run spends its whole `max_iterations` (docs/stability.md).

/// Relative margin and patience of a stall test.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct StallRule {
    /// A residual counts as progress when it is below (1 − margin) × the best so far [-].
    pub margin: f64,
    /// Iterations without progress after which the run has stalled.
    pub patience: usize,
}

impl StallRule {
    /// The rule of every method's stall test: no 10 % gain on the best residual in `patience`
    /// iterations (a converging run gains a decade within a few; the methods differ in how long
    /// they may hover before that, not in what counts as progress).
    pub const fn tenth_gain_in(patience: usize) -> Self {
        StallRule { margin: 0.1, patience }
    }
}

/// A line-search Newton attempt (the default method's attempts from the paper's start vector and
/// after restarts, the creepage iteration's solves, the NORM and TANG solves): no 10 % gain of
/// ‖G‖₂ in 50 steps. Its Armijo search decreases ‖G‖₂ at every accepted step, so what this ends
/// is an attempt creeping along a kink of G with ever shorter steps, or wandering at round-off.
/// Hard attempts can spend 20–30 steps at one level before they escape and converge (measured on
/// the stability map, docs/stability.md): the patience is half the default budget.
pub const NEWTON_STALL: StallRule = StallRule::tenth_gain_in(50);

/// An attempt from the normal start ([`super::start`]): no 10 % gain in 5 steps. From that start
/// a converging attempt gains a decade in one or two steps; one that creeps is trapped against
/// the kink of an edge node's friction bound (at μ ≥ 200, gaining < 1 % per step while its step
/// length halves towards 10⁻¹²), and the other formulation from the same start follows at once
/// (docs/performance.md, "Solver cost at the friction limits").
pub const NORMAL_START_STALL: StallRule = StallRule::tenth_gain_in(5);

/// The plain Newton (`newton_plain`, every step in full): no 10 % gain in 100 steps, the default
/// budget. Without a line search the residual is not monotone: on the stability map converging
/// runs hover for up to 77 steps before the active sets settle (docs/stability.md), so only a
/// budget far above the default meets this test (a tolerance below round-off).
pub const PLAIN_NEWTON_STALL: StallRule = StallRule::tenth_gain_in(100);

/// NORM/TANG pairs: no 10 % gain in 10 pairs (a converging alternation gains a decade in one to
/// three pairs: at most 2 pairs without a 10 % gain on the stability map).
pub const NORM_TANG_STALL: StallRule = StallRule::tenth_gain_in(10);

/// Gauss–Seidel sweeps: no 10 % gain in 2 500 sweeps (converging runs on the stability map go
/// up to 1 950 sweeps without one, in bursts around a flipping node).
pub const GAUSS_SEIDEL_STALL: StallRule = StallRule::tenth_gain_in(2_500);

/// The scaled residual (the common measure ‖G‖∞/p_ref) that double precision reaches on a grid of
/// `nodes` contact nodes, with a margin: 10 ε max(m, 100) (2.2e-13 up to 100 nodes, 2.1e-12 at
/// 963). Each row of G sums m products H_ij p_j (and B_ij q_j), whose rounding errors grow like
/// m ε times the traction scale, and the Newton step solves a system whose condition grows with
/// m too. Measured on Carter's case (carter_051) with `solver.tolerance=1e-20`, the smallest
/// residual the Newton iteration reaches is 8.9e-15, 2.0e-13 and 5.7e-13 at m = 63, 483 and 963
/// (0.6, 1.8 and 2.7 m ε): this level is 4–15 times above them, and below every tolerance a
/// converging run needs (the default is 1e-10).
pub fn roundoff_level(nodes: usize) -> f64 {
    10.0 * f64::EPSILON * nodes.max(100) as f64
}

/// Whether a run that did not converge ended with its residual at round-off: at or below
/// [`roundoff_level`], where no iteration can do better, however many it is given.
pub fn at_roundoff(residual: f64, nodes: usize) -> bool {
    residual <= roundoff_level(nodes)
}

/// Newton steps at round-off ([`roundoff_level`]): no halving of the best residual in 3 steps.
/// Newton converges quadratically, so above round-off a step gains far more than a factor 2;
/// at round-off the residual wanders within a factor of about 2 of its floor (measured on
/// Carter's case at tolerance 1e-20: 1.5e-14, 1.2e-14, 1.2e-14, 8.9e-15, 8.9e-15, ...).
pub const ROUNDOFF_STALL: StallRule = StallRule {
    margin: 0.5,
    patience: 3,
};

/// The advice when a run ended at round-off ([`at_roundoff`]), `smallest` being the smallest
/// scaled residual it reached: the tolerance asks for more than double precision gives, and a
/// tolerance of at least 10 × `smallest` (rounded up to a power of ten) is reachable.
pub fn roundoff_advice(smallest: f64, tolerance: Option<f64>) -> String {
    let reachable = 10f64.powf((10.0 * smallest).log10().ceil());
    let asked = tolerance.map_or(String::new(), |t| format!(" ({t:e})"));
    format!(
        "the residual reached round-off: solver.tolerance{asked} is below what double precision \
         gives on this grid (the smallest scaled residual reached is {smallest:.2e}); more iterations \
         or restarts will not help: set solver.tolerance to {reachable:.0e} or more"
    )
}

/// The running state of a stall test.
#[derive(Debug, Clone, Copy)]
pub struct Progress {
    rule: StallRule,
    best: f64,
    since_best: usize,
}

impl Progress {
    /// A test with `rule` for a run whose residual is `initial` before its first iteration.
    pub fn new(rule: StallRule, initial: f64) -> Self {
        Self {
            rule,
            best: initial,
            since_best: 0,
        }
    }

    /// Records the residual after an iteration; returns whether the run has stalled. A
    /// non-finite residual is never progress.
    pub fn record(&mut self, residual: f64) -> bool {
        if residual < (1.0 - self.rule.margin) * self.best || !self.best.is_finite() && residual.is_finite() {
            self.best = residual;
            self.since_best = 0;
        } else {
            self.since_best += 1;
        }
        self.stalled()
    }

    /// Whether the run has gone `patience` iterations without progress.
    pub fn stalled(&self) -> bool {
        self.since_best >= self.rule.patience
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_roundoff_level_grows_with_the_grid_and_the_advice_rounds_up() {
        assert_eq!(roundoff_level(10), roundoff_level(100));
        assert!((roundoff_level(100) - 1e3 * f64::EPSILON).abs() < 1e-28);
        assert_eq!(roundoff_level(1000), 10.0 * roundoff_level(100));
        assert!(at_roundoff(1e-14, 63) && !at_roundoff(1e-12, 63) && at_roundoff(1e-12, 963));
        // 10 × 8.9e-15 = 8.9e-14, rounded up to 1e-13; 10 × 5.7e-13 → 1e-11.
        let advice = roundoff_advice(8.926e-15, Some(1e-20));
        assert!(advice.contains("(1e-20)") && advice.contains("8.93e-15"), "{advice}");
        assert!(advice.contains("set solver.tolerance to 1e-13 or more"), "{advice}");
        assert!(roundoff_advice(5.7e-13, None).contains("to 1e-11 or more"));
    }

    #[test]
    fn a_run_that_keeps_gaining_never_stalls() {
        // Linear convergence at 20 % per iteration, the slowest that passes the 10 % margin
        // every time: never stalled however long.
        let mut p = Progress::new(NORMAL_START_STALL, 1.0);
        let mut r = 1.0;
        for _ in 0..1000 {
            r *= 0.8;
            assert!(!p.record(r));
        }
    }

    #[test]
    fn a_plateau_stalls_after_the_patience() {
        let mut p = Progress::new(NORMAL_START_STALL, 1.0);
        assert!(!p.record(0.5));
        // Within 10 % of the best: no progress.
        for k in 1..NORMAL_START_STALL.patience {
            assert!(!p.record(0.46), "stalled after {k}");
        }
        assert!(p.record(0.46));
    }

    #[test]
    fn bursts_above_the_best_do_not_reset_the_count_and_a_new_best_does() {
        let mut p = Progress::new(
            StallRule {
                margin: 0.1,
                patience: 3,
            },
            1.0,
        );
        assert!(!p.record(5.0));
        assert!(!p.record(0.95));
        assert!(!p.record(0.5)); // new best
        assert!(!p.record(2.0));
        assert!(!p.record(0.46));
        assert!(p.record(f64::NAN));
    }
}
