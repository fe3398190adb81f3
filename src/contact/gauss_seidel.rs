//! Projected Gauss–Seidel (method `gauss_seidel`): the projection equations of the contact
//! conditions used as a fixed-point map, one node at a time.
//!
//! Sources: E.A.H. Vollebregt, *User guide for CONTACT* (VORtech, public), the solvers
//! ConvexGS and SteadyGS of the tangential problem (element-wise Gauss–Seidel with the local
//! friction problem solved exactly, SteadyGS visiting the elements in the rolling direction);
//! Kalker 1990 §5 for the underlying NORM/TANG split; Cryer (1971) for projected SOR.
//!
//! **One sweep** visits the nodes from the upstream end of the grid (where material enters, the
//! leading edge) to the downstream end, as SteadyGS does: the slip of a node depends, through the steady-rolling
//! difference operator, on its own shear and on that of its upstream neighbours, so marching
//! with the flow makes the tangential update nearly a forward substitution. At node i, with all
//! other tractions at their latest values:
//!
//! ```text
//! p_i ← max(0, p_i − ω g_i / H_p,ii)            Eq. 24 as a fixed point, local gap driven to 0
//! q_i ← Proj[−μ p_i, μ p_i](q_i − ω s_i / B_q,ii) Eq. 34 as a fixed point, local slip driven to 0
//! ```
//!
//! and g, s are updated by the columns of H and B of node i (O(m) per node, O(m²) per sweep).
//! ω = 1 solves each node's local normal problem exactly; ω is the relaxation factor
//! ([`GaussSeidelSettings::relaxation`]; the case's `solver.penalty` sets it) of projected SOR
//! (0 < ω < 2 for a symmetric positive definite H_p). The tangential update is relaxed further, by
//! [`TANGENTIAL_RELAXATION`] = 0.25: the steady-rolling slip operator B_q = σ D W_q is not
//! diagonally dominant (its off-diagonal part is a discrete Cauchy kernel, Σ_j |B_ij| ≈ B_ii ln m),
//! and the exact local solve overshoots. Measured on Carter (21 elements, second-order slip,
//! sweeping with the flow): a tangential relaxation of 1, 0.5 or 0.4 diverges to full sliding,
//! 0.25 converges in about 1100 sweeps; sweeping against the flow needs 0.3 and three times as many
//! sweeps. Where B_q,ii ≤ 0 (the local slip does not grow with the local shear, so the local
//! problem has no unique solution) the mean |diag B_q| is used instead.
//!
//! **Load control** (the unknowns δ0 and ξ): after each sweep, a Lagrange-type row per
//! controlled load, updated the Gauss–Seidel way with its own diagonal: raising δ0 by Δ raises
//! every contact node's local update by ω Δ/H_p,ii, so
//! δ0 ← δ0 − (Σ w p − P) / (ω Σ_contact w_i/H_p,ii); likewise
//! ξ ← ξ − (Σ w q − Q) / (−σ ω Σ_stick w_i e_i/B_q,ii) over the sticking nodes (all contact
//! nodes when none sticks). This diagonal estimate of ∂P/∂δ0 exceeds the true stiffness (the
//! off-diagonal flexibility is ignored), so the load rows are under-relaxed: they converge
//! monotonically but slowly, as the pressure itself does on a fine grid.
//!
//! **What we simplify.** CONTACT solves the normal problem by a conjugate-gradient method
//! (NormCG) and iterates the tangential Gauss–Seidel with the pressure fixed; here both
//! directions are swept together in one Gauss–Seidel pass (a nonlinear block Gauss–Seidel with
//! 1×1 blocks), so no inner solver is involved and the sweep is the iteration unit.
//!
//! **Stopping.** After each sweep the projection rows of the common measure are evaluated from
//! the incrementally updated g and s (O(m)); when they pass, g and s are recomputed exactly and
//! the full measure decides. g and s are also recomputed every [`RESYNC_SWEEPS`] sweeps. The
//! sweeps also stop when they stall ([`super::stall::GAUSS_SEIDEL_STALL`]: no 10 % gain on the
//! best residual in 500 sweeps).

use super::report::{GaussSeidelSettings, IterationRecord, Method, SolveReport};
use super::residual::{projection, scaled_residual, start_vector, ConvergenceMeasure, Formulation, State};
use super::stall::{Progress, GAUSS_SEIDEL_STALL};
use super::{ContactProblem, NormalControl, TangentialControl};

/// Sweeps between exact recomputations of the gap and the slip (against round-off drift).
pub const RESYNC_SWEEPS: usize = 64;

/// Scaled residual beyond which the sweeps are declared diverged and stopped.
pub const DIVERGED: f64 = 1e8;

/// Relaxation of the tangential local update relative to the normal one (module docs).
pub const TANGENTIAL_RELAXATION: f64 = 0.25;

/// Iterate of the sweep: tractions, load scalars and the gap and slip they produce.
struct Sweep<'a> {
    pb: &'a ContactProblem,
    /// Relaxation factor ω [-].
    omega: f64,
    /// Local normal relaxation ω / H_p,ii [stress/length].
    rn: Vec<f64>,
    /// Local tangential relaxation ω / B_q,ii [stress].
    rt: Vec<f64>,
    /// Node order of a sweep (upstream first).
    order: Vec<usize>,
    p: Vec<f64>,
    q: Vec<f64>,
    g: Vec<f64>,
    s: Vec<f64>,
    overlap: f64,
    creep: f64,
}

impl<'a> Sweep<'a> {
    fn new(pb: &'a ContactProblem, omega: f64) -> Self {
        let m = pb.n_nodes();
        let mean_bq = (0..m).map(|i| pb.bq[(i, i)].abs()).sum::<f64>() / m as f64;
        let rn = (0..m).map(|i| omega / pb.flex.hp[(i, i)]).collect();
        let omega_t = omega * TANGENTIAL_RELAXATION;
        let rt = (0..m)
            .map(|i| {
                let b = pb.bq[(i, i)];
                omega_t / if b > 0.0 { b } else { mean_bq }
            })
            .collect();
        // Flow in −x (σ < 0) enters at the right end.
        let order = if pb.flow_sign < 0.0 {
            (0..m).rev().collect()
        } else {
            (0..m).collect()
        };
        let z = start_vector(pb);
        let mut sweep = Self {
            pb,
            omega,
            rn,
            rt,
            order,
            p: z.pressure,
            q: z.shear,
            g: Vec::new(),
            s: Vec::new(),
            overlap: z.overlap,
            creep: z.creep,
        };
        sweep.resync();
        sweep
    }

    /// Recomputes g and s exactly from the tractions.
    fn resync(&mut self) {
        self.g = self.pb.gap(&self.p, &self.q, self.overlap);
        self.s = self.pb.slip(&self.p, &self.q, self.creep);
    }

    /// Adds column j of (H_p, B_p) or (H_q, B_q) times Δ to (g, s).
    fn add_column(&mut self, j: usize, delta: f64, normal: bool) {
        let (h, b) = if normal {
            (&self.pb.flex.hp, &self.pb.bp)
        } else {
            (&self.pb.flex.hq, &self.pb.bq)
        };
        let (hc, bc) = (h.col(j), b.col(j));
        for (i, (g, s)) in self.g.iter_mut().zip(self.s.iter_mut()).enumerate() {
            *g += hc[i] * delta;
            *s += bc[i] * delta;
        }
    }

    /// One Gauss–Seidel pass over the nodes, then the load rows.
    fn sweep(&mut self) {
        let mu = self.pb.friction;
        for k in 0..self.order.len() {
            let i = self.order[k];
            let p_new = (self.p[i] - self.rn[i] * self.g[i]).max(0.0);
            let dp = p_new - self.p[i];
            if dp != 0.0 {
                self.p[i] = p_new;
                self.add_column(i, dp, true);
            }
            let q_new = projection(self.q[i] - self.rt[i] * self.s[i], mu * self.p[i]);
            let dq = q_new - self.q[i];
            if dq != 0.0 {
                self.q[i] = q_new;
                self.add_column(i, dq, false);
            }
        }
        self.update_overlap();
        self.update_creep();
    }

    /// δ0 ← δ0 − (Σ w p − P)/K with K the diagonal estimate of ∂P/∂δ0 (module docs).
    fn update_overlap(&mut self) {
        let NormalControl::Force(total) = self.pb.normal else {
            return;
        };
        let w = &self.pb.grid.weights;
        let defect = self.pb.grid.integrate(&self.p) - total;
        let stiffness = |all: bool| -> f64 {
            (0..self.p.len())
                .filter(|&i| all || self.p[i] > 0.0)
                .map(|i| w[i] * self.rn[i])
                .sum()
        };
        let k = match stiffness(false) {
            k if k > 0.0 => k,
            _ => stiffness(true),
        };
        let d = -defect / k;
        self.overlap += d;
        self.g.iter_mut().for_each(|g| *g -= d);
    }

    /// ξ ← ξ − (Σ w q − c_p μ Σ w p − Q0)/K with K the diagonal estimate of ∂Q/∂ξ over the
    /// sticking nodes (module docs).
    fn update_creep(&mut self) {
        let (ratio, q0) = match self.pb.tangential {
            TangentialControl::Force(q) => (0.0, q),
            TangentialControl::Ratio(r) => (r, 0.0),
            TangentialControl::Creep(_) => return,
        };
        let pb = self.pb;
        let (w, e) = (&pb.grid.weights, &pb.slip_operator.creep_weight);
        let mu = pb.friction;
        let defect = pb.grid.integrate(&self.q) - ratio * mu * pb.grid.integrate(&self.p) - q0;
        let stiffness = |stick_only: bool| -> f64 {
            (0..self.p.len())
                .filter(|&i| self.p[i] > 0.0 && (!stick_only || self.q[i].abs() < mu * self.p[i]))
                .map(|i| -pb.flow_sign * w[i] * e[i] * self.rt[i])
                .sum()
        };
        let k = match stiffness(true) {
            k if k != 0.0 => k,
            _ => stiffness(false),
        };
        if k == 0.0 || !k.is_finite() {
            return;
        }
        let d = -defect / k;
        self.creep += d;
        for (s, e) in self.s.iter_mut().zip(e) {
            *s += pb.flow_sign * e * d;
        }
    }

    fn state(&self) -> State {
        State {
            gap: self.g.clone(),
            slip: self.s.clone(),
            pressure: self.p.clone(),
            shear: self.q.clone(),
            overlap: self.overlap,
            creep: self.creep,
        }
    }
}

/// Solves the contact problem by projected Gauss–Seidel sweeps from the paper's start vector,
/// at most `settings.max_sweeps` sweeps with the relaxation ω = `settings.relaxation`.
pub fn solve(
    pb: &ContactProblem,
    settings: &GaussSeidelSettings,
    measure: &ConvergenceMeasure,
) -> (State, SolveReport) {
    let mut it = Sweep::new(pb, settings.relaxation);
    let sys = measure.system();
    let scale = measure.traction_scale();
    let cheap = |it: &Sweep| {
        let z = it.state();
        scaled_residual(&sys.projection_residual(&z), &z, scale)
    };
    let mut history = Vec::new();
    let mut residual = measure.of(&it.state());
    let mut converged = residual <= settings.tolerance;
    let mut progress = Progress::new(GAUSS_SEIDEL_STALL, residual);
    while !converged && history.len() < settings.max_sweeps && !progress.stalled() {
        crate::cancel::checkpoint();
        history.push(IterationRecord {
            residual,
            step: it.omega,
            system_size: 0,
            inner_iterations: 0,
        });
        it.sweep();
        if history.len() % RESYNC_SWEEPS == 0 {
            it.resync();
        }
        residual = cheap(&it);
        if history.len() % 100 == 0 {
            log::info!(
                target: crate::logging::PROGRESS,
                "Gauss-Seidel sweep {}: scaled residual {residual:.2e} (tolerance {:.0e})",
                history.len(),
                settings.tolerance
            );
        }
        if !residual.is_finite() || residual > DIVERGED {
            break;
        }
        if residual <= settings.tolerance {
            it.resync();
            residual = measure.of(&it.state());
            converged = residual <= settings.tolerance;
        }
        progress.record(residual);
    }
    it.resync();
    let z = it.state();
    // A diverged iterate is reported with a finite residual (no NaN in outputs).
    let residual = match measure.of(&z) {
        r if r.is_finite() => r,
        _ => f64::MAX,
    };
    let report = SolveReport {
        method: Method::GaussSeidel,
        // The sweeps use no formulation: `methods::solve` records the one asked for.
        formulation: Formulation::Phi,
        converged: converged && residual <= settings.tolerance,
        iterations: history.len(),
        inner_iterations: history.len(),
        residual,
        history,
        penalty_normal: it.rn.iter().sum::<f64>() / it.rn.len() as f64,
        penalty_tangential: it.rt.iter().sum::<f64>() / it.rt.len() as f64,
        traction_scale: scale,
        wall_time_s: 0.0,
        fallbacks: Vec::new(),
    };
    (z, report)
}
