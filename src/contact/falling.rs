//! Friction falling with the local slip velocity, solved by an outer fixed point on the nodal
//! friction coefficients.
//!
//! **The law** (the single exponential of Vollebregt & Schuttelaars, J. Sound Vib. 331
//! (2012) 2141–2155, Eq. 2, and of CONTACT's velocity-dependent friction with one term):
//!
//! μ(v) = μ_k + (μ_s − μ_k) exp(−|v| / s_h),   v = V s,
//!
//! with V the rolling speed (`load.speed`, [length/time]), s the dimensionless slip of the
//! paper's Eq. 19 at the node (so V s is the local slip velocity [length/time]), μ_s the static
//! coefficient (`contact.friction`), μ_k ≤ μ_s the kinetic one and s_h > 0 the slip velocity of
//! the decay [length/time]. At a sticking node s = 0 and μ = μ_s; μ_k = μ_s is Coulomb's
//! constant friction.
//!
//! **The scheme.** Two methods, combined ([`solve`]). (1) The generalized Newton method with
//! the law inside the residual: μ_i = μ(V s_i) of the iterate, whose slope dμ/ds gives each
//! slipping node a row of its own in the Newton direction ([`super::direction`]); quadratic
//! near a solution, but from a cold start it can stall on the nonsmooth, nonconvex merit.
//! (2) An outer fixed point: the Newton method of [`super::restart`] solves the problem with the
//! nodal μ_i frozen ([`ContactProblem::nodal_friction`]); μ_i is then set from the slip found,
//! and the next solve starts from the last solution, until no μ_i changes by more than
//! [`FIXED_POINT_TOLERANCE`] μ_s. The plain iteration μ ← μ(s(μ)) contracts only linearly, and
//! slowly where the law is steep (cases/veldep_fric.yaml at μ_s = 0.4: by 0.905 a solve), so the
//! update is Anderson's mixing of the last [`ANDERSON_DEPTH`] iterates (D.G. Anderson, J. ACM 12
//! (1965) 547–560; H.F. Walker & P. Ni, SIAM J. Numer. Anal. 49 (2011) 1715–1735, Eq. 2.2);
//! when the change grows the history is dropped and the mixing weight halved (down to 1/16).
//! The mixed μ_i are kept within [μ_k, μ_s]. A warm start goes to (1) first; otherwise, or when
//! that fails, (2) runs and hands over to (1) once its change is below [`FINISH_CHANGE`] μ_s:
//! veldep_fric at μ_s = 0.5, where (2) alone never settles, then converges in 5 Newton
//! iterations from its iterate. When (2) ends unsettled, (3) a continuation in the law's
//! amplitude from Coulomb's solution at μ_s and, where that branch folds, (4) a start from above
//! (Coulomb at μ_k, then (1)) follow ([`continuation`]): a transient step of a steep law whose
//! last step's branch no longer exists (a slip event) is solved by one of them.
//!
//! **Uniqueness.** With a falling law the discrete problem can have several solutions
//! (Vollebregt & Schuttelaars 2012, §3): which one the fixed point finds depends on where it
//! starts, μ_s everywhere from a cold start, the neighbour's slip from a warm one. The run
//! reports the branch it found (its creepage and forces); a continuation in the creepage from
//! below and from above can find different ones for the same load.

mod continuation;

pub use continuation::{at_amplitude, solve_from_side, InitialSlip};

use super::newton::NewtonInputs;
use super::report::{NewtonSettings, SolveReport};
use super::residual::{ConvergenceMeasure, State};
use super::workspace::Workspace;
use super::{restart, ContactProblem};
use serde::{Deserialize, Serialize};

/// Largest change of any nodal μ_i, relative to μ_s, at which the fixed point stops: below the
/// Newton tolerance's effect on the slip (‖G‖/p_ref ≤ 1e-10 moves s by about that much).
pub const FIXED_POINT_TOLERANCE: f64 = 1e-10;

/// Most solves of the outer fixed point before the run is reported not converged.
pub const MAX_FIXED_POINT_SOLVES: usize = 200;

/// How the fallback of a fixed point that did not settle begins (the CLI's advice keys on it).
pub const UNSETTLED: &str = "falling friction: the nodal mu did not settle";

/// Whether a report's fallback is a restart of the Newton method (not the note of a falling
/// law's fixed point that did not settle, [`UNSETTLED`]).
pub fn is_restart(fallback: &str) -> bool {
    !fallback.starts_with(UNSETTLED)
}

/// Smallest relaxation of the μ update (1/16).
const MIN_RELAXATION: f64 = 1.0 / 16.0;

/// How many past iterates Anderson's mixing combines (module docs): 5 is the usual choice
/// (Walker & Ni 2011, §5), enough to capture the few slowly contracting modes here.
pub const ANDERSON_DEPTH: usize = 5;

/// The keys of `contact.falling_friction`: the friction coefficient falls from the static
/// `contact.friction` μ_s to `kinetic` μ_k as the local slip velocity grows (module docs).
#[derive(Debug, Clone, Copy, PartialEq, Deserialize, Serialize)]
#[serde(deny_unknown_fields)]
pub struct FallingFriction {
    /// Kinetic friction coefficient μ_k, 0 ≤ μ_k ≤ μ_s [-]: the limit at large slip velocity.
    pub kinetic: f64,
    /// Slip velocity s_h > 0 [length/time] over which μ falls by the factor e from μ_s towards
    /// μ_k (the case's length and time units, as `load.speed`).
    pub slip_velocity: f64,
    /// A second exponential, taking the share w of the fall μ_s − μ_k (CONTACT's law with two
    /// exponential terms; [`FallingLaw::coefficient`]). None: one exponential.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub second: Option<SecondExponential>,
}

/// The second exponential of a falling law: μ = μ_k + (μ_s − μ_k)[(1 − w) e^(−|v|/s_h) +
/// w e^(−|v|/s_h2)]. CONTACT's μ = FKIN + FEXP1 e^(−ln 2 |v|/SABSH1) + FEXP2 e^(−ln 2 |v|/SABSH2)
/// (each term halved at its SABSH) with FEXP1, FEXP2 ≥ 0 is μ_s = FKIN + FEXP1 + FEXP2,
/// μ_k = FKIN, s_h = SABSH1/ln 2, w = FEXP2/(FEXP1 + FEXP2), s_h2 = SABSH2/ln 2.
#[derive(Debug, Clone, Copy, PartialEq, Deserialize, Serialize)]
#[serde(deny_unknown_fields)]
pub struct SecondExponential {
    /// The share w ∈ [0, 1] of the fall μ_s − μ_k that the second exponential carries [-].
    pub share: f64,
    /// Its slip velocity s_h2 > 0 [length/time].
    pub slip_velocity: f64,
}

/// A falling law with the speed it needs from the case. The static coefficient μ_s is the
/// problem's own `friction` ([`ContactProblem::friction`]), passed to each evaluation, so that
/// a run that changes μ (a sweep's) cannot leave the law with another.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct FallingLaw {
    /// The law's keys.
    pub law: FallingFriction,
    /// Rolling speed V > 0 [length/time] (`load.speed`): slip velocity = V × slip.
    pub speed: f64,
}

impl FallingLaw {
    /// μ(V s) for the static coefficient `mu_s` [-] and the dimensionless slip `slip` at a node
    /// [-] (module docs); μ_s exactly when μ_k = μ_s (the factor of the exponential is then
    /// zero).
    pub fn coefficient(&self, mu_s: f64, slip: f64) -> f64 {
        let v = self.speed * slip.abs();
        let mu_k = self.law.kinetic;
        let first = (-v / self.law.slip_velocity).exp();
        let decay = match self.law.second {
            None => first,
            Some(two) => (1.0 - two.share) * first + two.share * (-v / two.slip_velocity).exp(),
        };
        mu_k + (mu_s - mu_k) * decay
    }

    /// dμ/ds at the dimensionless slip `slip` [-] for the static coefficient `mu_s` [-]:
    /// −(μ_s − μ_k)(V/s_h) exp(−V|s|/s_h) sgn s, zero at s = 0 and wherever μ_k = μ_s (the row
    /// of the Newton direction of a slipping node, [`super::direction`]).
    pub fn slope(&self, mu_s: f64, slip: f64) -> f64 {
        if slip == 0.0 {
            return 0.0;
        }
        // d/ds of the decay of `coefficient`: each exponential e^(−V|s|/s_h) gives −(V/s_h)·itself.
        let rate = |s_h: f64| self.speed / s_h;
        let term = |s_h: f64| rate(s_h) * (-rate(s_h) * slip.abs()).exp();
        let first = term(self.law.slip_velocity);
        let decay = match self.law.second {
            None => first,
            Some(two) => (1.0 - two.share) * first + two.share * term(two.slip_velocity),
        };
        -(mu_s - self.law.kinetic) * decay * slip.signum()
    }

    /// μ at every node of the slip `slip` [-], for the static coefficient `mu_s` [-].
    pub fn nodal(&self, mu_s: f64, slip: &[f64]) -> Vec<f64> {
        slip.iter().map(|&s| self.coefficient(mu_s, s)).collect()
    }
}

/// Solves `pb` under the falling law `law` (module docs): from `warm`, when given, first the
/// Newton method with the law inside (its slope in the direction) for at most
/// [`FINISH_BUDGET`] iterations; else, or when that does not converge, the outer fixed point,
/// each solve the line-search Newton of [`restart`] on the frozen problem, handing over to the
/// Newton with the law once the largest change of μ_i is below [`FINISH_CHANGE`] μ_s (and
/// again each time it has fallen ten times further, and when the fixed point ends unsettled).
/// The Newton systems in the memory of `ws`. The report sums the iterations of every solve and
/// attempt; it is not converged when a solve fails or neither the fixed point settles within
/// [`MAX_FIXED_POINT_SOLVES`] solves nor the Newton finishes.
pub fn solve(
    pb: &ContactProblem,
    law: &FallingLaw,
    settings: &NewtonSettings,
    warm: Option<State>,
    ws: &mut Workspace,
) -> (State, SolveReport) {
    // The measure of the problem with the law inside: the one every result is judged by.
    let full = ConvergenceMeasure::new(pb);
    let mut tally = Tally::default();
    if let Some(w) = &warm {
        if let Some(done) = finish(pb, settings, &full, w.clone(), &mut tally, ws) {
            return done;
        }
    }
    let mu = match &warm {
        Some(z) => law.nodal(pb.friction, &z.slip),
        None => vec![pb.friction; pb.n_nodes()],
    };
    fixed_point(pb, law, settings, warm, mu, true, tally, ws)
}

/// The outer fixed point of [`solve`] from the nodal coefficients `mu` and the start `warm`
/// (the iterations so far in `tally`); when it does not settle and `stages`, the continuation
/// and the start from above of [`continuation`] follow.
#[allow(clippy::too_many_arguments)]
fn fixed_point(
    pb: &ContactProblem,
    law: &FallingLaw,
    settings: &NewtonSettings,
    warm: Option<State>,
    mut mu: Vec<f64>,
    stages: bool,
    mut tally: Tally,
    ws: &mut Workspace,
) -> (State, SolveReport) {
    let full = ConvergenceMeasure::new(pb);
    let mut own = pb.clone();
    let mu_s = pb.friction;
    own.falling = None;
    let m = pb.n_nodes();
    // The continuation's start when both stages fail (the fixed point moves `start` on).
    let origin = warm.clone();
    let mut start = warm;
    let (mut relaxation, mut last_change) = (1.0_f64, f64::INFINITY);
    let scale = mu_s.max(f64::MIN_POSITIVE);
    let mut next_finish = FINISH_CHANGE * scale;
    let mut solve = 0;
    let mut mixing = Anderson::new(ANDERSON_DEPTH);
    loop {
        solve += 1;
        own.nodal_friction = Some(mu.clone());
        // The measure of this pass's problem: its friction rows bound by the frozen μ_i (one of
        // the unfrozen problem would see the constant μ_s and accept a Ψ iterate that has it).
        let measure = ConvergenceMeasure::new(&own);
        let (state, mut report) = match start.take() {
            Some(w) => restart::solve_warm(&own, settings, &measure, w, ws),
            None => restart::solve(NewtonInputs::new(&own, settings, &measure), ws),
        };
        tally.add(&mut report);
        let target = law.nodal(mu_s, &state.slip);
        // Only where the bound μ_i p̂_i can act: out of contact μ_i bounds nothing.
        let change = (0..m)
            .filter(|&i| state.pressure[i] > 0.0)
            .fold(0.0_f64, |a, i| a.max((target[i] - mu[i]).abs()));
        let settled = change <= FIXED_POINT_TOLERANCE * scale;
        let ends = !report.converged || settled || solve == MAX_FIXED_POINT_SOLVES;
        if report.converged && !settled && (change <= next_finish || ends) {
            if let Some(done) = finish(pb, settings, &full, state.clone(), &mut tally, ws) {
                log::info!(
                    target: crate::logging::PROGRESS,
                    "falling friction: {solve} solve(s) with the nodal mu frozen (last change {change:.1e}), \
                     finished by the Newton method with the law's slope"
                );
                return done;
            }
            next_finish = change / 10.0;
        }
        if ends && !settled && stages {
            // Third the branch from below by a continuation in the law's amplitude, fourth,
            // where that branch folds, the start from above (continuation.rs).
            let found = continuation::solve(pb, law, settings, origin.clone(), &mut tally, ws)
                .or_else(|| continuation::from_above(pb, law, settings, origin.clone(), &mut tally, ws));
            if let Some(done) = found {
                log::info!(
                    target: crate::logging::PROGRESS,
                    "falling friction: {solve} solve(s) with the nodal mu frozen did not settle (last change \
                     {change:.1e}); solved by {}",
                    done.1.fallbacks.last().map_or("", String::as_str)
                );
                return done;
            }
        }
        if ends {
            report.converged &= settled;
            if !settled {
                // The residual of the problem with the law, not of the last frozen one.
                report.residual = full.of(&state);
            }
            tally.total(&mut report);
            // A settled run's count goes to the log (not a fallback: nothing stalled).
            match settled {
                true => log::info!(
                    target: crate::logging::PROGRESS,
                    "falling friction: {solve} solve(s) with the nodal mu frozen, last change {change:.1e}"
                ),
                false => report
                    .fallbacks
                    .push(format!("{UNSETTLED} in {solve} solve(s) (last change {change:.1e})")),
            }
            return (state, report);
        }
        if change > last_change {
            relaxation = (relaxation * 0.5).max(MIN_RELAXATION);
            mixing.clear();
        }
        last_change = change;
        mu = mixing.next(&mu, &target, relaxation);
        let (lo, hi) = (law.law.kinetic.min(mu_s), mu_s);
        mu.iter_mut().for_each(|u| *u = u.clamp(lo, hi));
        start = Some(state);
    }
}

/// Most iterations of one attempt of the Newton method with the law inside ([`solve`]): from
/// a start near the solution it converges quadratically, in 5–20 iterations on
/// cases/veldep_fric.yaml (μ_s 0.3–0.5).
pub const FINISH_BUDGET: usize = 30;

/// The largest change of the nodal μ_i, relative to μ_s, below which the fixed point hands
/// over to the Newton method with the law inside ([`solve`]): from fixed-point iterates whose
/// measure was still 1e-2, that Newton converged in 5 iterations on cases/veldep_fric.yaml at
/// μ_s 0.5, where the fixed point alone does not settle.
pub const FINISH_CHANGE: f64 = 1e-2;

/// The iterations of a falling-law solve's inner solves and attempts, summed into its report.
#[derive(Default)]
struct Tally {
    iterations: usize,
    inner: usize,
    history: Vec<super::report::IterationRecord>,
}

impl Tally {
    /// Adds a solve's or attempt's iterations (its history moves here).
    fn add(&mut self, report: &mut SolveReport) {
        self.iterations += report.iterations;
        self.inner += report.inner_iterations;
        self.history.append(&mut report.history);
    }

    /// Puts the sums into the last report.
    fn total(&mut self, report: &mut SolveReport) {
        report.iterations = self.iterations;
        report.inner_iterations = self.inner;
        report.history = std::mem::take(&mut self.history);
    }
}

/// The Newton method with the law inside from `from` ([`FINISH_BUDGET`] iterations, judged by
/// `full`, the measure of the problem with the law): its state and report (with the iterations
/// of `tally`) when it converged, else None, its iterations added to `tally`.
fn finish(
    pb: &ContactProblem,
    settings: &NewtonSettings,
    full: &ConvergenceMeasure,
    from: State,
    tally: &mut Tally,
    ws: &mut Workspace,
) -> Option<(State, SolveReport)> {
    let (state, mut report) = restart::attempt_warm(pb, settings, full, from, FINISH_BUDGET, ws);
    tally.add(&mut report);
    report.converged.then(|| {
        tally.total(&mut report);
        (state, report)
    })
}

/// Anderson's mixing of a fixed point x = g(x) (module docs): the last iterates' differences
/// ΔX and residual differences ΔF, at most `depth` of each.
struct Anderson {
    depth: usize,
    last: Option<(Vec<f64>, Vec<f64>)>,
    dx: Vec<Vec<f64>>,
    df: Vec<Vec<f64>>,
}

impl Anderson {
    fn new(depth: usize) -> Self {
        Self {
            depth,
            last: None,
            dx: Vec::new(),
            df: Vec::new(),
        }
    }

    /// Forgets the history (the next step is a relaxed plain step).
    fn clear(&mut self) {
        self.last = None;
        self.dx.clear();
        self.df.clear();
    }

    /// The next iterate from x and g(x) (Walker & Ni 2011, Eq. 2.2 with mixing β):
    /// x + βf − (ΔX + βΔF)γ, γ the least-squares minimiser of ‖f − ΔF γ‖ (an SVD solve, whose
    /// cut-off drops the directions that round-off alone separates).
    fn next(&mut self, x: &[f64], gx: &[f64], beta: f64) -> Vec<f64> {
        let f: Vec<f64> = gx.iter().zip(x).map(|(g, u)| g - u).collect();
        if let Some((x0, f0)) = self.last.take() {
            if self.dx.len() == self.depth {
                self.dx.remove(0);
                self.df.remove(0);
            }
            self.dx.push(x.iter().zip(&x0).map(|(a, b)| a - b).collect());
            self.df.push(f.iter().zip(&f0).map(|(a, b)| a - b).collect());
        }
        let mut next: Vec<f64> = x.iter().zip(&f).map(|(u, r)| u + beta * r).collect();
        if !self.df.is_empty() {
            let df = nalgebra::DMatrix::from_fn(f.len(), self.df.len(), |i, j| self.df[j][i]);
            let rhs = nalgebra::DVector::from_column_slice(&f);
            let svd = df.svd(true, true);
            let cut = 1e-12 * svd.singular_values.max();
            if let Ok(gamma) = svd.solve(&rhs, cut) {
                for (j, g) in gamma.iter().enumerate() {
                    for (i, n) in next.iter_mut().enumerate() {
                        *n -= g * (self.dx[j][i] + beta * self.df[j][i]);
                    }
                }
            }
        }
        self.last = Some((x.to_vec(), f));
        next
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn law(kinetic: f64) -> FallingLaw {
        FallingLaw {
            law: FallingFriction {
                kinetic,
                slip_velocity: 0.5,
                second: None,
            },
            speed: 100.0,
        }
    }

    /// Anderson's mixing solves a linear fixed point x = Ax + b of slow contraction (spectral
    /// radius 0.95) in a few steps where the plain iteration needs hundreds: with depth ≥ the
    /// dimension it is GMRES in disguise (Walker & Ni 2011, Th. 2.2), exact after n + 1 steps.
    #[test]
    fn anderson_mixing_solves_a_slow_linear_fixed_point() {
        let a = [[0.95, 0.01, 0.0], [0.0, 0.9, 0.02], [0.01, 0.0, 0.8]];
        let b = [1.0, -0.5, 0.25];
        let g = |x: &[f64]| -> Vec<f64> {
            (0..3)
                .map(|i| b[i] + (0..3).map(|j| a[i][j] * x[j]).sum::<f64>())
                .collect()
        };
        let mut mixing = Anderson::new(ANDERSON_DEPTH);
        let mut x = vec![0.0; 3];
        for _ in 0..5 {
            let gx = g(&x);
            x = mixing.next(&x, &gx, 1.0);
        }
        let r: f64 = g(&x).iter().zip(&x).map(|(g, u)| (g - u).abs()).fold(0.0, f64::max);
        assert!(r < 1e-10, "residual after 5 mixed steps {r}");
        let mut y = vec![0.0; 3];
        for _ in 0..5 {
            y = g(&y);
        }
        let plain: f64 = g(&y).iter().zip(&y).map(|(g, u)| (g - u).abs()).fold(0.0, f64::max);
        assert!(plain > 0.1, "the plain iteration is slow here: {plain}");
    }

    /// μ_s at zero slip, μ_k + (μ_s − μ_k)/e at V|s| = s_h, even in s, exactly μ_s when μ_k = μ_s.
    #[test]
    fn the_law_falls_from_static_to_kinetic() {
        let l = law(0.1);
        assert_eq!(l.coefficient(0.3, 0.0), 0.3);
        let at_sh = 0.1 + 0.2 * (-1.0_f64).exp();
        assert!((l.coefficient(0.3, 0.005) - at_sh).abs() < 1e-15);
        assert_eq!(l.coefficient(0.3, -0.005), l.coefficient(0.3, 0.005));
        assert!((l.coefficient(0.3, 10.0) - 0.1).abs() < 1e-15);
        let flat = law(0.3);
        for s in [0.0, 1e-6, 0.005, -3.0] {
            assert_eq!(flat.coefficient(0.3, s), 0.3);
        }
    }

    /// The two-exponential law is CONTACT's L = 4 formula under the mapping of
    /// [`SecondExponential`]: μ = FKIN + FEXP1 e^(−ln 2 |v|/SABSH1) + FEXP2 e^(−ln 2 |v|/SABSH2)
    /// (eve70a/CONTACT, src/m_friclaw.f90: each term halved at its SABSH), and its slope is the
    /// central difference of the coefficient.
    #[test]
    fn two_exponentials_are_contacts_law() {
        let (fkin, fexp1, sabsh1, fexp2, sabsh2) = (0.18, 0.08, 100.0, 0.04, 2000.0);
        let mu_s = fkin + fexp1 + fexp2;
        let l = FallingLaw {
            law: FallingFriction {
                kinetic: fkin,
                slip_velocity: sabsh1 / std::f64::consts::LN_2,
                second: Some(SecondExponential {
                    share: fexp2 / (fexp1 + fexp2),
                    slip_velocity: sabsh2 / std::f64::consts::LN_2,
                }),
            },
            speed: 45_000.0,
        };
        for s in [0.0, 1e-5, -3e-4, 2e-3, 0.05] {
            let v = 45_000.0 * f64::abs(s);
            let halved = |sabsh: f64| (-std::f64::consts::LN_2 * v / sabsh).exp();
            let contact = fkin + fexp1 * halved(sabsh1) + fexp2 * halved(sabsh2);
            assert!((l.coefficient(mu_s, s) - contact).abs() < 1e-14, "s = {s}");
            if s != 0.0 {
                let h = 1e-7 * s.abs();
                let fd = (l.coefficient(mu_s, s + h) - l.coefficient(mu_s, s - h)) / (2.0 * h);
                assert!(
                    (l.slope(mu_s, s) - fd).abs() <= 1e-6 * fd.abs().max(1e-3),
                    "s = {s}: {fd}"
                );
            }
        }
        // A share of 0 is the one-exponential law, bit for bit.
        let one = FallingLaw {
            law: FallingFriction { second: None, ..l.law },
            ..l
        };
        let zero_share = FallingLaw {
            law: FallingFriction {
                second: Some(SecondExponential {
                    share: 0.0,
                    slip_velocity: sabsh2,
                }),
                ..l.law
            },
            ..l
        };
        for s in [1e-5, 2e-3] {
            assert_eq!(one.coefficient(mu_s, s), zero_share.coefficient(mu_s, s));
            assert_eq!(one.slope(mu_s, s), zero_share.slope(mu_s, s));
        }
    }
}
