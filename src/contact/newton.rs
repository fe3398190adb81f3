//! Generalized Newton method with Armijo line search (Pang 1990; González & Abascal §4).
//!
//! Unknowns z = (g, s, p, q, δ0, ξ) (paper Eq. 42; δ0 and ξ only when they are not prescribed).
//! The residual G(z), in the signs of [`crate::contact`], is (paper Eq. 43 Φ / Eq. 44 Ψ):
//!
//! ```text
//! G1 = r_n (g − h0 + δ0 − H_p p − H_q q)        elastic normal equations (Eq. 12)
//! G2 = r_t (s − σξ − B_p p − B_q q)             elastic slip equations (Eq. 19)
//! G3 = p − max(0, p − r_n g)          [Φ]       Signorini as a projection (Eq. 24)
//!    = min(p, r_n g)                  [Ψ]       (Eq. 25)
//! G4 = q − Proj[−μp̂, μp̂](q − r_t s)             Coulomb as a projection (Eq. 34)
//!      p̂ = max(0, p − r_n g) [Φ],  max(0, p) [Ψ]
//! G5 = (Σ w_j p_j − P)/L,  G6 = (Σ w_j q_j − Q)/L   load control (Eq. 39), L the grid length
//! ```
//!
//! The elastic rows are scaled by the penalties so that every component of G is a traction:
//! the merit ½‖G‖² is then balanced and the convergence test ‖G‖∞ ≤ tol·p_ref is scale-free.
//! The penalties are dimensionally sound: r_n = c / mean diag(H_p) and r_t = c / mean |diag(B_q)|
//! (stress/length and stress), with the user's scale c (default 1).
//!
//! **Newton step.** The B-derivative pseudo-Jacobian is that of paper Eq. 54–73 (the "modified"
//! choices at ties: a tie counts as open in the normal direction and as stick in the tangential
//! one). Rows G1 and G2 are linear and give Δg, Δs explicitly; open nodes give Δp = −p, Δq = −q;
//! slipping nodes give Δq = μ·sgn·Δp̂ − G4. Substituting all of these leaves a dense system in the
//! pressures of contact nodes, the shears of stick nodes and the free load scalars, solved by LU
//! (faer). Its size is #contact + #stick + #free ≤ 2m + 2, much smaller than the paper's 4m + 2.

use super::{ContactProblem, NormalControl, TangentialControl};
use faer::linalg::solvers::Solve;
use faer::Mat;
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

/// Settings of the generalized Newton method.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields, default)]
pub struct NewtonSettings {
    /// Formulation of the contact conditions. Default = Phi.
    pub formulation: Formulation,
    /// Scale c of the automatic penalties r_n = c/mean diag(H_p), r_t = c/mean|diag(B_q)|. Default = 1.
    pub penalty_scale: f64,
    /// Convergence when ‖G‖∞ ≤ tolerance · p_ref (p_ref a traction scale of the problem). Default = 1e-10.
    pub tolerance: f64,
    /// Maximum number of Newton iterations. Default = 100.
    pub max_iterations: usize,
    /// Armijo constant σ in Θ(z+αΔz) ≤ (1−2σα)Θ(z) (paper §4.1). Default = 0.1.
    pub armijo: f64,
    /// Step reduction factor β of the backtracking, α = β^m (paper §4.1). Default = 0.5.
    pub step_reduction: f64,
    /// Maximum number of step reductions per iteration. Default = 40.
    pub max_backtracks: usize,
}

impl Default for NewtonSettings {
    fn default() -> Self {
        Self {
            formulation: Formulation::Phi,
            penalty_scale: 1.0,
            tolerance: 1e-10,
            max_iterations: 100,
            armijo: 0.1,
            step_reduction: 0.5,
            max_backtracks: 40,
        }
    }
}

/// One Newton iteration in the history.
#[derive(Debug, Clone, Copy, Serialize)]
pub struct IterationRecord {
    /// Scaled residual ‖G‖∞ / p_ref before the step.
    pub residual: f64,
    /// Accepted step length α.
    pub step: f64,
    /// Size of the reduced linear system solved.
    pub system_size: usize,
}

/// Outcome of a solve: the final iterate and how we got there.
#[derive(Debug, Clone, Serialize)]
pub struct NewtonReport {
    /// Whether the scaled residual reached the tolerance.
    pub converged: bool,
    /// Number of Newton steps taken.
    pub iterations: usize,
    /// Final scaled residual ‖G‖∞ / p_ref.
    pub residual: f64,
    /// Residual and step length of every iteration.
    pub history: Vec<IterationRecord>,
    /// Normal penalty r_n [stress/length].
    pub penalty_normal: f64,
    /// Tangential penalty r_t [stress].
    pub penalty_tangential: f64,
    /// Traction scale p_ref of the convergence test [stress].
    pub traction_scale: f64,
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

/// Tangential state of a node for the pseudo-Jacobian.
#[derive(Debug, Clone, Copy, PartialEq)]
enum Tangential {
    Free,
    Stick,
    Slip(f64),
}

/// The problem together with its penalties: evaluates G and its Newton step.
struct System<'a> {
    pb: &'a ContactProblem,
    form: Formulation,
    rn: f64,
    rt: f64,
    length: f64,
    free_overlap: bool,
    free_creep: bool,
}

fn projection(z: f64, bound: f64) -> f64 {
    if bound <= 0.0 {
        0.0
    } else {
        z.clamp(-bound, bound)
    }
}

impl System<'_> {
    fn m(&self) -> usize {
        self.pb.n_nodes()
    }

    fn bound_pressure(&self, p: f64, g: f64) -> f64 {
        match self.form {
            Formulation::Phi => (p - self.rn * g).max(0.0),
            Formulation::Psi => p.max(0.0),
        }
    }

    fn is_contact(&self, p: f64, g: f64) -> bool {
        match self.form {
            Formulation::Phi => p - self.rn * g > 0.0,
            Formulation::Psi => p > self.rn * g,
        }
    }

    fn tangential_state(&self, z: &State, i: usize) -> Tangential {
        let bound = self.pb.friction * self.bound_pressure(z.pressure[i], z.gap[i]);
        let t = z.shear[i] - self.rt * z.slip[i];
        // A zero bound with t = 0 is the paper's tie (Eq. 72–73, "modified"): take the stick
        // derivative, else the paper's start vector (p = 0) leaves Ψ's Newton matrix singular.
        if bound <= 0.0 && t != 0.0 {
            Tangential::Free
        } else if t.abs() <= bound.max(0.0) {
            Tangential::Stick
        } else {
            Tangential::Slip(t.signum())
        }
    }

    #[allow(clippy::needless_range_loop)] // several arrays indexed by node: clearer than zips
    fn residual(&self, z: &State) -> Vec<f64> {
        let pb = self.pb;
        let m = self.m();
        let mut r = Vec::with_capacity(4 * m + 2);
        let h = pb.compression(&z.pressure, &z.shear);
        for i in 0..m {
            r.push(self.rn * (z.gap[i] - pb.h0[i] + z.overlap - h[i]));
        }
        let b = super::mat_vec2(&pb.bp, &z.pressure, &pb.bq, &z.shear);
        for i in 0..m {
            let e = pb.slip_operator.creep_weight[i];
            r.push(self.rt * (z.slip[i] - pb.flow_sign * z.creep * e - b[i]));
        }
        for i in 0..m {
            let (p, g) = (z.pressure[i], z.gap[i]);
            r.push(match self.form {
                Formulation::Phi => p - (p - self.rn * g).max(0.0),
                Formulation::Psi => p.min(self.rn * g),
            });
        }
        for i in 0..m {
            let bound = pb.friction * self.bound_pressure(z.pressure[i], z.gap[i]);
            r.push(z.shear[i] - projection(z.shear[i] - self.rt * z.slip[i], bound));
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
    fn tangential_load(&self) -> Option<(f64, f64)> {
        match self.pb.tangential {
            TangentialControl::Force(q) => Some((0.0, q)),
            TangentialControl::Ratio(ratio) => Some((ratio, 0.0)),
            TangentialControl::Creep(_) => None,
        }
    }

    /// With δ0 free, at least one node must carry the contact row (δ0 appears nowhere else,
    /// and the P row would repeat itself); with ξ free, the Q row needs a node in contact to
    /// stick (see [`System::ensure_stick_row`]). If no node is in contact, the node closest to
    /// contact (largest p − r g) is given the contact derivative, the paper's "modified" choice
    /// at a near-tie. An iterate with every node open is met after a full step into tension,
    /// e.g. on an incompressible layer, whose volume constraint makes the all-contact start
    /// solve for negative pressures everywhere.
    fn ensure_contact_row(&self, z: &State, mut contact: Vec<bool>) -> Vec<bool> {
        if (self.free_overlap || self.free_creep) && !contact.iter().any(|&c| c) {
            let f = |k: usize| z.pressure[k] - self.rn * z.gap[k];
            let k = (0..contact.len()).max_by(|&i, &j| f(i).total_cmp(&f(j))).unwrap_or(0);
            contact[k] = true;
        }
        contact
    }

    /// With ξ free, ξ enters only the stick rows: when every loaded node slips (a full-sliding
    /// active set, met transiently), the Q row becomes a multiple of the P row and the matrix is
    /// singular. The slipping node closest to sticking (smallest (|t| − bound)/bound) then gets
    /// the stick derivative, again a "modified" choice at a near-tie (paper Eq. 60). A contact
    /// node whose friction bound is zero (free) qualifies too, after every slipping one.
    fn ensure_stick_row(&self, z: &State, contact: &[bool], tangential: &mut [Tangential]) {
        if !self.free_creep || tangential.contains(&Tangential::Stick) {
            return;
        }
        let excess = |i: usize| {
            let bound = self.pb.friction * self.bound_pressure(z.pressure[i], z.gap[i]);
            if bound > 0.0 {
                ((z.shear[i] - self.rt * z.slip[i]).abs() - bound) / bound
            } else {
                f64::INFINITY
            }
        };
        if let Some(k) = (0..tangential.len())
            .filter(|&i| contact[i])
            .min_by(|&i, &j| excess(i).total_cmp(&excess(j)))
        {
            tangential[k] = Tangential::Stick;
        }
    }

    /// Solves the linearized equations BG(z)Δz = −G(z) by the reduction in the module docs.
    #[allow(non_snake_case)]
    fn newton_direction(&self, z: &State, G: &[f64]) -> Result<(State, usize), String> {
        let pb = self.pb;
        let m = self.m();
        let (g1, g2, g3, g4) = (&G[0..m], &G[m..2 * m], &G[2 * m..3 * m], &G[3 * m..4 * m]);
        let mu = pb.friction;

        // Δp_j = p_const + [column p_col]; Δq_j = q_const + [column q_col] + q_pcoef·Δp_j.
        let mut n_cols = 0;
        let mut p_col = vec![None; m];
        let mut p_const = vec![0.0; m];
        let mut contact_rows = Vec::new();
        let normal_contact: Vec<bool> = (0..m).map(|i| self.is_contact(z.pressure[i], z.gap[i])).collect();
        let mut tangential: Vec<Tangential> = (0..m).map(|i| self.tangential_state(z, i)).collect();
        let normal_contact = self.ensure_contact_row(z, normal_contact);
        self.ensure_stick_row(z, &normal_contact, &mut tangential);
        for i in 0..m {
            if normal_contact[i] {
                p_col[i] = Some(n_cols);
                n_cols += 1;
                contact_rows.push(i);
            } else {
                p_const[i] = -g3[i];
            }
        }
        let mut q_col = vec![None; m];
        let mut q_const = vec![0.0; m];
        let mut q_pcoef = vec![0.0; m];
        let mut stick_rows = Vec::new();
        for i in 0..m {
            match tangential[i] {
                Tangential::Free => q_const[i] = -g4[i],
                Tangential::Stick => {
                    q_col[i] = Some(n_cols);
                    n_cols += 1;
                    stick_rows.push(i);
                }
                Tangential::Slip(sign) => {
                    let shift = match self.form {
                        Formulation::Phi => g3[i],
                        Formulation::Psi => 0.0,
                    };
                    q_const[i] = -g4[i] + mu * sign * shift;
                    q_pcoef[i] = mu * sign;
                }
            }
        }
        let col_overlap = self.free_overlap.then(|| {
            n_cols += 1;
            n_cols - 1
        });
        let col_creep = self.free_creep.then(|| {
            n_cols += 1;
            n_cols - 1
        });
        let n = n_cols;
        let mut J = Mat::<f64>::zeros(n, n);
        let mut rhs = Mat::<f64>::zeros(n, 1);

        // Adds Σ_j (ap_j Δp_j + aq_j Δq_j) to row `row`, moving known parts to the right side.
        let add_row =
            |J: &mut Mat<f64>, rhs: &mut Mat<f64>, row: usize, ap: &dyn Fn(usize) -> f64, aq: &dyn Fn(usize) -> f64| {
                for j in 0..m {
                    let (a_p, a_q) = (ap(j), aq(j));
                    let cp = a_p + a_q * q_pcoef[j];
                    rhs[(row, 0)] -= cp * p_const[j] + a_q * q_const[j];
                    if let Some(c) = p_col[j] {
                        J[(row, c)] += cp;
                    }
                    if let Some(c) = q_col[j] {
                        J[(row, c)] += a_q;
                    }
                }
            };
        let mut row = 0;
        for &i in &contact_rows {
            rhs[(row, 0)] = -g3[i] + g1[i];
            let rn = self.rn;
            add_row(&mut J, &mut rhs, row, &|j| rn * pb.flex.hp[(i, j)], &|j| {
                rn * pb.flex.hq[(i, j)]
            });
            if let Some(c) = col_overlap {
                J[(row, c)] = -rn;
            }
            row += 1;
        }
        for &i in &stick_rows {
            rhs[(row, 0)] = -g4[i] + g2[i];
            let rt = self.rt;
            add_row(&mut J, &mut rhs, row, &|j| rt * pb.bp[(i, j)], &|j| rt * pb.bq[(i, j)]);
            if let Some(c) = col_creep {
                J[(row, c)] = rt * pb.flow_sign * pb.slip_operator.creep_weight[i];
            }
            row += 1;
        }
        let w = &pb.grid.weights;
        let mut k = 4 * m;
        if self.free_overlap {
            rhs[(row, 0)] = -self.length * G[k];
            add_row(&mut J, &mut rhs, row, &|j| w[j], &|_| 0.0);
            k += 1;
            row += 1;
        }
        if let Some((ratio, _)) = self.tangential_load() {
            rhs[(row, 0)] = -self.length * G[k];
            add_row(&mut J, &mut rhs, row, &|j| -ratio * mu * w[j], &|j| w[j]);
            row += 1;
        }
        debug_assert_eq!(row, n);

        let y = if n > 0 {
            let lu = J.partial_piv_lu();
            lu.solve_in_place(rhs.as_mut());
            rhs
        } else {
            rhs
        };
        if (0..n).any(|r| !y[(r, 0)].is_finite()) {
            return Err(format!("the Newton matrix of size {n} is singular"));
        }
        let dp: Vec<f64> = (0..m)
            .map(|j| p_const[j] + p_col[j].map_or(0.0, |c| y[(c, 0)]))
            .collect();
        let dq: Vec<f64> = (0..m)
            .map(|j| q_const[j] + q_col[j].map_or(0.0, |c| y[(c, 0)]) + q_pcoef[j] * dp[j])
            .collect();
        let d_overlap = col_overlap.map_or(0.0, |c| y[(c, 0)]);
        let d_creep = col_creep.map_or(0.0, |c| y[(c, 0)]);
        let dh = pb.compression(&dp, &dq);
        let db = super::mat_vec2(&pb.bp, &dp, &pb.bq, &dq);
        let dg = (0..m).map(|i| -g1[i] / self.rn - d_overlap + dh[i]).collect();
        let e = &pb.slip_operator.creep_weight;
        let ds = (0..m)
            .map(|i| -g2[i] / self.rt + pb.flow_sign * d_creep * e[i] + db[i])
            .collect();
        Ok((
            State {
                gap: dg,
                slip: ds,
                pressure: dp,
                shear: dq,
                overlap: d_overlap,
                creep: d_creep,
            },
            n,
        ))
    }
}

fn axpy(z: &State, alpha: f64, dz: &State) -> State {
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

fn merit(g: &[f64]) -> f64 {
    0.5 * g.iter().map(|v| v * v).sum::<f64>()
}

fn max_abs(g: &[f64]) -> f64 {
    g.iter().fold(0.0, |a, v| a.max(v.abs()))
}

/// The automatic penalties (r_n, r_t) for a problem and scale c.
pub fn automatic_penalties(pb: &ContactProblem, scale: f64) -> (f64, f64) {
    let m = pb.n_nodes();
    let diag_h = (0..m).map(|i| pb.flex.hp[(i, i)]).sum::<f64>() / m as f64;
    let diag_b = (0..m).map(|i| pb.bq[(i, i)].abs()).sum::<f64>() / m as f64;
    (scale / diag_h.abs(), scale / diag_b)
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

/// Solves the contact problem from the paper's start vector.
pub fn solve(pb: &ContactProblem, settings: &NewtonSettings) -> (State, NewtonReport) {
    let (rn, rt) = automatic_penalties(pb, settings.penalty_scale);
    let sys = System {
        pb,
        form: settings.formulation,
        rn,
        rt,
        length: pb.grid.length(),
        free_overlap: matches!(pb.normal, NormalControl::Force(_)),
        free_creep: !matches!(pb.tangential, TangentialControl::Creep(_)),
    };
    let traction_scale = match pb.normal {
        NormalControl::Force(p) => p / pb.grid.length(),
        NormalControl::Overlap(d) => rn * d.abs(),
    };
    let mut z = start_vector(pb);
    let mut g = sys.residual(&z);
    let mut history = Vec::new();
    let scaled = |g: &[f64], z: &State| max_abs(g) / traction_scale.max(max_abs(&z.pressure)).max(f64::MIN_POSITIVE);
    let mut converged = scaled(&g, &z) <= settings.tolerance;
    while !converged && history.len() < settings.max_iterations {
        let residual = scaled(&g, &z);
        let (dz, size) = match sys.newton_direction(&z, &g) {
            Ok(d) => d,
            Err(_) => break,
        };
        let theta = merit(&g);
        let mut alpha = 1.0;
        let mut trial = axpy(&z, alpha, &dz);
        let mut g_trial = sys.residual(&trial);
        for _ in 0..settings.max_backtracks {
            if merit(&g_trial) <= (1.0 - 2.0 * settings.armijo * alpha) * theta {
                break;
            }
            alpha *= settings.step_reduction;
            trial = axpy(&z, alpha, &dz);
            g_trial = sys.residual(&trial);
        }
        history.push(IterationRecord {
            residual,
            step: alpha,
            system_size: size,
        });
        z = trial;
        g = g_trial;
        converged = scaled(&g, &z) <= settings.tolerance;
    }
    let residual = scaled(&g, &z);
    let report = NewtonReport {
        converged,
        iterations: history.len(),
        residual,
        history,
        penalty_normal: rn,
        penalty_tangential: rt,
        traction_scale,
    };
    (z, report)
}
