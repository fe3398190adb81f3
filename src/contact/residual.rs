//! The residual G(z) of the contact problem and the convergence measure shared by every solution
//! method (González & Abascal §3.2, Eq. 36/43 Φ and Eq. 44 Ψ).
//!
//! Unknowns z = (g, s, p, q, δ0, ξ) (paper Eq. 42; δ0 and ξ only when they are not prescribed).
//! The residual, in the signs of [`crate::contact`], is:
//!
//! ```text
//! G1 = r_n (g − h0 + δ0 − H_p p − H_q q)        elastic normal equations (Eq. 12)
//! G2 = r_t (s − σξ − B_p p − B_q q)             elastic slip equations (Eq. 19)
//! G3 = p − max(0, p − r_n g)          [Φ]       Signorini as a projection (Eq. 24)
//!    = min(p, r_n g)                  [Ψ]       (Eq. 25; the same function: p − max(0, p − y) = min(p, y))
//! G4 = q − Proj[−μp̂, μp̂](q − r_t s)             Coulomb as a projection (Eq. 34)
//!      p̂ = max(0, p − r_n g) [Φ],  max(0, p) [Ψ];  μ = μ(V s) under a falling law
//! G5 = (Σ w_j p_j − P)/L,  G6 = (Σ w_j q_j − Q)/L   load control (Eq. 39), L the grid length
//! ```
//!
//! The elastic rows are scaled by the penalties so that every component of G is a traction:
//! the merit ½‖G‖² is then balanced and the convergence test ‖G‖∞ ≤ tol·p_ref is scale-free.
//! The penalties are dimensionally sound: r_n = c / mean diag(H_p) and r_t = c / mean |diag(B_q)|
//! (stress/length and stress), with the user's scale c (default 1).
//!
//! **One judge for every method.** [`ConvergenceMeasure`] is the scaled residual ‖G_Φ‖∞ / p_ref
//! of the Φ function with the automatic penalties at c = 1, whatever method, formulation or
//! penalty scale produced the iterate: every method stops on it and reports it, so their
//! iteration counts and failures compare on the same footing. For the default Newton (Φ, c = 1)
//! it is exactly the residual the Newton iteration drives to zero.

use super::{ContactProblem, NormalControl, TangentialControl};
use serde::{Deserialize, Serialize};

/// The two projection formulations of the contact conditions.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum Formulation {
    /// Paper Eq. 43: the friction bound uses the augmented pressure max(0, p − r g).
    Phi,
    /// Paper Eq. 44: the friction bound uses max(0, p).
    Psi,
}

/// The unknowns z of the paper (Eq. 42).
#[derive(Debug, Clone, PartialEq)]
pub struct State {
    /// Gap g [length].
    pub gap: Vec<f64>,
    /// Slip s [-].
    pub slip: Vec<f64>,
    /// Pressure p [stress].
    pub pressure: Vec<f64>,
    /// Shear q [stress].
    pub shear: Vec<f64>,
    /// Overlap δ0 [length].
    pub overlap: f64,
    /// Creepage ξ [-].
    pub creep: f64,
}

/// The projection Proj[−b, b](z) onto the friction interval (paper Eq. 29); zero for b ≤ 0.
pub fn projection(z: f64, bound: f64) -> f64 {
    if bound <= 0.0 {
        0.0
    } else {
        z.clamp(-bound, bound)
    }
}

/// The problem together with a formulation and penalties: evaluates G(z).
pub(crate) struct System<'a> {
    pub(crate) pb: &'a ContactProblem,
    pub(crate) form: Formulation,
    /// Normal penalty r_n at each node [stress/length] ([`nodal_penalties`]).
    pub(crate) rn: Vec<f64>,
    /// Tangential penalty r_t at each node [stress].
    pub(crate) rt: Vec<f64>,
    /// The automatic (mean-diagonal) penalties [r_n, r_t] of the scale: what reports show.
    pub(crate) reference: [f64; 2],
    pub(crate) length: f64,
    pub(crate) free_overlap: bool,
    pub(crate) free_creep: bool,
}

impl<'a> System<'a> {
    /// The system of `pb` with formulation `form` and the automatic penalties at scale `scale`.
    pub(crate) fn new(pb: &'a ContactProblem, form: Formulation, scale: f64) -> Self {
        let (rn, rt) = nodal_penalties(pb, scale);
        Self::with_penalties(pb, form, scale, rn, rt)
    }

    /// The system with the automatic pair of [`automatic_penalties`] at every node, also on a
    /// graded grid: the common convergence measure's, whose rows then weigh every node's gap
    /// alike (a Jacobi penalty ∝ 1/h at a node of length h would scale its round-off up).
    pub(crate) fn with_uniform_penalties(pb: &'a ContactProblem, form: Formulation, scale: f64) -> Self {
        let (rn, rt) = automatic_penalties(pb, scale);
        let m = pb.n_nodes();
        Self::with_penalties(pb, form, scale, vec![rn; m], vec![rt; m])
    }

    fn with_penalties(pb: &'a ContactProblem, form: Formulation, scale: f64, rn: Vec<f64>, rt: Vec<f64>) -> Self {
        let (rn_ref, rt_ref) = automatic_penalties(pb, scale);
        Self {
            pb,
            form,
            rn,
            rt,
            reference: [rn_ref, rt_ref],
            length: pb.grid.length(),
            free_overlap: matches!(pb.normal, NormalControl::Force(_)),
            free_creep: !matches!(pb.tangential, TangentialControl::Creep(_)),
        }
    }

    pub(crate) fn m(&self) -> usize {
        self.pb.n_nodes()
    }

    /// Pressure p̂ that sets the friction bound μp̂ (Φ: augmented, Ψ: the pressure itself).
    pub(crate) fn bound_pressure(&self, z: &State, i: usize) -> f64 {
        let (p, g) = (z.pressure[i], z.gap[i]);
        match self.form {
            Formulation::Phi => (p - self.rn[i] * g).max(0.0),
            Formulation::Psi => p.max(0.0),
        }
    }

    /// μ_i [-] that bounds the shear at node i for the iterate z: a falling law's at z's slip
    /// there (the law inside the residual, [`super::falling`]), else the problem's coefficient
    /// (constant, or frozen per node by the falling law's fixed point).
    pub(crate) fn friction(&self, z: &State, i: usize) -> f64 {
        self.pb.friction_of_slip(i, z.slip[i])
    }

    /// dμ_i/ds_i [-] at the iterate z: the falling law's slope at z's slip, 0 without a law.
    pub(crate) fn friction_slope(&self, z: &State, i: usize) -> f64 {
        self.pb
            .falling
            .map_or(0.0, |law| law.slope(self.pb.friction, z.slip[i]))
    }

    /// Whether a node is on the contact branch of the normal projection.
    pub(crate) fn is_contact(&self, z: &State, i: usize) -> bool {
        let (p, g) = (z.pressure[i], z.gap[i]);
        match self.form {
            Formulation::Phi => p - self.rn[i] * g > 0.0,
            Formulation::Psi => p > self.rn[i] * g,
        }
    }

    /// G(z), components in the order of the module docs (G5, G6 only when controlled).
    #[allow(clippy::needless_range_loop)] // several arrays indexed by node: clearer than zips
    pub(crate) fn residual(&self, z: &State) -> Vec<f64> {
        let pb = self.pb;
        let m = self.m();
        let mut r = Vec::with_capacity(4 * m + 2);
        let h = pb.compression(&z.pressure, &z.shear);
        for i in 0..m {
            r.push(self.rn[i] * (z.gap[i] - pb.h0[i] + z.overlap - h[i]));
        }
        let b = crate::linalg::mat_vec2(&pb.bp, &z.pressure, &pb.bq, &z.shear);
        for i in 0..m {
            let e = pb.slip_operator.creep_weight[i];
            r.push(self.rt[i] * (z.slip[i] - pb.flow_sign * (z.creep * e + pb.rigid_slip[i]) - b[i]));
        }
        r.extend(self.projection_residual(z));
        r
    }

    /// Rows G3–G6 of G(z): the projections and the load equations, O(m) (the elastic rows G1,
    /// G2 need the matrix–vector products).
    #[allow(clippy::needless_range_loop)]
    pub(crate) fn projection_residual(&self, z: &State) -> Vec<f64> {
        let pb = self.pb;
        let m = self.m();
        let mut r = Vec::with_capacity(2 * m + 2);
        for i in 0..m {
            let (p, g) = (z.pressure[i], z.gap[i]);
            r.push(match self.form {
                Formulation::Phi => p - (p - self.rn[i] * g).max(0.0),
                Formulation::Psi => p.min(self.rn[i] * g),
            });
        }
        for i in 0..m {
            let bound = self.friction(z, i) * self.bound_pressure(z, i);
            r.push(z.shear[i] - projection(z.shear[i] - self.rt[i] * z.slip[i], bound));
        }
        if let NormalControl::Force(p_total) = pb.normal {
            r.push((pb.grid.integrate(&z.pressure) - p_total) / self.length);
        }
        if let Some((ratio, q_total)) = self.tangential_load() {
            let f_p = pb.grid.integrate(&z.pressure);
            r.push((pb.grid.integrate(&z.shear) - ratio * pb.friction * f_p - q_total) / self.length);
        }
        r
    }

    /// (c_p, Q0) of the tangential load equation Σ w q − c_p μ Σ w p − Q0 = 0, if Q is controlled.
    pub(crate) fn tangential_load(&self) -> Option<(f64, f64)> {
        // A system whose creepage is held fixed (`free_creep` false, also when the problem
        // controls Q: see [`super::creep_secant`]) has no load row.
        if !self.free_creep {
            return None;
        }
        match self.pb.tangential {
            TangentialControl::Force(q) => Some((0.0, q)),
            TangentialControl::Ratio(ratio) => Some((ratio, 0.0)),
            TangentialControl::Creep(_) => None,
        }
    }

    /// Traction scale p_ref of the convergence test [stress]: P/L under force control, r_n·|δ0|
    /// under overlap control.
    pub(crate) fn traction_scale(&self) -> f64 {
        match self.pb.normal {
            NormalControl::Force(p) => p / self.length,
            NormalControl::Overlap(d) => self.reference[0] * d.abs(),
        }
    }
}

/// ‖G‖∞ / max(p_ref, max|p|): the scaled residual of a residual vector.
pub(crate) fn scaled_residual(g: &[f64], z: &State, traction_scale: f64) -> f64 {
    max_abs(g) / traction_scale.max(max_abs(&z.pressure)).max(f64::MIN_POSITIVE)
}

/// z + α Δz.
pub(crate) fn axpy(z: &State, alpha: f64, dz: &State) -> State {
    let comb = |a: &[f64], b: &[f64]| a.iter().zip(b).map(|(x, d)| x + alpha * d).collect();
    State {
        gap: comb(&z.gap, &dz.gap),
        slip: comb(&z.slip, &dz.slip),
        pressure: comb(&z.pressure, &dz.pressure),
        shear: comb(&z.shear, &dz.shear),
        overlap: z.overlap + alpha * dz.overlap,
        creep: z.creep + alpha * dz.creep,
    }
}

/// The merit function Θ = ½‖G‖² (paper Eq. 50).
pub(crate) fn merit(g: &[f64]) -> f64 {
    0.5 * g.iter().map(|v| v * v).sum::<f64>()
}

/// ‖v‖∞.
pub(crate) fn max_abs(g: &[f64]) -> f64 {
    g.iter().fold(0.0, |a, v| a.max(v.abs()))
}

/// The automatic penalties (r_n, r_t) for a problem and scale c: r_n = c / mean diag(H_p)
/// [stress/length], r_t = c / mean |diag(B_q)| [stress].
pub fn automatic_penalties(pb: &ContactProblem, scale: f64) -> (f64, f64) {
    let m = pb.n_nodes();
    let diag_h = (0..m).map(|i| pb.flex.hp[(i, i)]).sum::<f64>() / m as f64;
    let diag_b = (0..m).map(|i| pb.bq[(i, i)].abs()).sum::<f64>() / m as f64;
    (scale / diag_h.abs(), scale / diag_b)
}

/// Element-length ratio (longest over shortest) above which a grid counts as graded and gets
/// per-node penalties ([`nodal_penalties`]): uniform grids and the near-uniform meshes of
/// drawn rollers keep the paper's single pair.
pub const GRADED_GRID_RATIO: f64 = 1.5;

/// Widest departure of a per-node penalty from the mean one ([`nodal_penalties`]): a guard
/// against a diagonal near zero. The error-controlled grids of carter2d (1e-5), of the regime-4
/// pair and of the BEM rollers span 0.0011–457 times the mean, inside it.
pub const JACOBI_PENALTY_RANGE: f64 = 1e4;

/// The penalties at each node for a scale c. On a grid of nearly equal elements, the automatic
/// pair of [`automatic_penalties`] at every node (the paper's choice). On a graded grid
/// (elements differing by more than [`GRADED_GRID_RATIO`]) the diagonals of H_p and B_q span
/// orders of magnitude, and one mean value leaves r·H_ii ≪ 1 at the smallest elements, where
/// the line search then crawls: there r_n,i = c / |H_p,ii| and r_t,i = c / |B_q,ii| (a Jacobi
/// scaling of the projections), kept within [`JACOBI_PENALTY_RANGE`] of the mean pair, and the
/// mean pair where a diagonal is zero or not finite.
pub fn nodal_penalties(pb: &ContactProblem, scale: f64) -> (Vec<f64>, Vec<f64>) {
    let m = pb.n_nodes();
    let (rn, rt) = automatic_penalties(pb, scale);
    if !is_graded(&pb.grid) {
        return (vec![rn; m], vec![rt; m]);
    }
    let jacobi = |d: f64, mean: f64| {
        let r = scale / d.abs();
        if r.is_finite() && d != 0.0 {
            r.clamp(mean / JACOBI_PENALTY_RANGE, mean * JACOBI_PENALTY_RANGE)
        } else {
            mean
        }
    };
    (
        (0..m).map(|i| jacobi(pb.flex.hp[(i, i)], rn)).collect(),
        (0..m).map(|i| jacobi(pb.bq[(i, i)], rt)).collect(),
    )
}

/// Whether the grid's elements differ in length by more than [`GRADED_GRID_RATIO`].
fn is_graded(grid: &crate::grid::ContactGrid) -> bool {
    let lengths = grid.edges.windows(2).map(|w| w[1] - w[0]);
    let (min, max) = lengths.fold((f64::INFINITY, 0.0f64), |(lo, hi), l| (lo.min(l), hi.max(l)));
    max > GRADED_GRID_RATIO * min
}

/// The paper's start vector (Eq. 74): g = −h0, s = 0, p = q = 0, δ0 and ξ zero unless prescribed.
pub fn start_vector(pb: &ContactProblem) -> State {
    let m = pb.n_nodes();
    State {
        gap: pb.h0.iter().map(|h| -h).collect(),
        slip: vec![0.0; m],
        pressure: vec![0.0; m],
        shear: vec![0.0; m],
        overlap: match pb.normal {
            NormalControl::Overlap(d) => d,
            NormalControl::Force(_) => 0.0,
        },
        creep: match pb.tangential {
            TangentialControl::Creep(c) => c,
            _ => 0.0,
        },
    }
}

/// The convergence measure shared by all methods: ‖G_Φ(z)‖∞ / max(p_ref, max|p|) with the
/// automatic penalties at scale 1 (module docs). Dimensionless.
pub struct ConvergenceMeasure<'a> {
    system: System<'a>,
    traction_scale: f64,
}

impl<'a> ConvergenceMeasure<'a> {
    /// The measure of a problem.
    pub fn new(pb: &'a ContactProblem) -> Self {
        let system = System::with_uniform_penalties(pb, Formulation::Phi, 1.0);
        let traction_scale = system.traction_scale();
        Self { system, traction_scale }
    }

    /// Scaled residual of an iterate.
    pub fn of(&self, z: &State) -> f64 {
        scaled_residual(&self.system.residual(z), z, self.traction_scale)
    }

    /// The traction scale p_ref [stress].
    pub fn traction_scale(&self) -> f64 {
        self.traction_scale
    }

    /// Scaled residual of an iterate whose residual `g` under `sys` is already known: reused when
    /// `sys` is the measure's own function (Φ at scale 1), recomputed otherwise.
    pub(crate) fn of_with(&self, sys: &System, g: &[f64], z: &State) -> f64 {
        let same = sys.form == Formulation::Phi && sys.rn == self.system.rn && sys.rt == self.system.rt;
        if same {
            scaled_residual(g, z, self.traction_scale)
        } else if sys.form == Formulation::Phi && is_graded(&sys.pb.grid) {
            // Per-node penalties (a graded grid): the elastic rows G1, G2 differ from the
            // measure's only by their factors r_i; the projection rows are O(m) to redo.
            let m = sys.m();
            let mut r: Vec<f64> = (0..m)
                .map(|i| g[i] * (self.system.rn[i] / sys.rn[i]))
                .chain((0..m).map(|i| g[m + i] * (self.system.rt[i] / sys.rt[i])))
                .collect();
            r.extend(self.system.projection_residual(z));
            scaled_residual(&r, z, self.traction_scale)
        } else {
            self.of(z)
        }
    }

    /// The Φ system at scale 1 behind the measure.
    pub(crate) fn system(&self) -> &System<'a> {
        &self.system
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn solved(case: &str, set: &[String]) -> ContactProblem {
        crate::app::solve_case(&crate::case::shipped(case), set)
            .expect("shipped case solves")
            .problem
    }

    /// Uniform grids keep the paper's single pair; a graded grid (an error-controlled run's)
    /// gets r_i·diag_i = c at every node, over diagonals that span orders of magnitude.
    #[test]
    fn graded_grids_get_jacobi_penalties_and_uniform_grids_the_mean_pair() {
        let uniform = solved("carter2d_contact.yaml", &[]);
        let (rn, rt) = nodal_penalties(&uniform, 2.0);
        let (mean_n, mean_t) = automatic_penalties(&uniform, 2.0);
        assert!(rn.iter().all(|&r| r == mean_n) && rt.iter().all(|&r| r == mean_t));

        let graded = solved("carter2d_contact.yaml", &["contact.grid.tolerance=1e-4".into()]);
        assert!(is_graded(&graded.grid), "the error-controlled grid is graded");
        let (rn, rt) = nodal_penalties(&graded, 2.0);
        for i in 0..graded.n_nodes() {
            let (h, b) = (graded.flex.hp[(i, i)], graded.bq[(i, i)]);
            assert!(
                (rn[i] * h.abs() - 2.0).abs() < 1e-12,
                "node {i}: r_n·H_ii = {}",
                rn[i] * h
            );
            assert!(
                (rt[i] * b.abs() - 2.0).abs() < 1e-12,
                "node {i}: r_t·B_ii = {}",
                rt[i] * b
            );
        }
        let spread =
            |r: &[f64]| r.iter().cloned().fold(0.0, f64::max) / r.iter().cloned().fold(f64::INFINITY, f64::min);
        assert!(spread(&rn) > 10.0, "normal penalties spread only {}", spread(&rn));
    }
}
