//! The Newton direction of the generalized Newton method (González & Abascal §4, Eq. 54–73).
//!
//! The B-derivative pseudo-Jacobian is that of paper Eq. 54–73 (the "modified" choices at ties: a
//! tie counts as open in the normal direction and as stick in the tangential one). Rows G1 and G2
//! of the residual ([`super::residual`]) are linear and give Δg, Δs explicitly; open nodes give
//! Δp = −p, Δq = −q; slipping nodes give Δq = μ·sgn·Δp̂ − G4. Substituting all of these leaves a
//! dense system in the pressures of contact nodes, the shears of stick nodes and the free load
//! scalars, solved by LU (faer). Its size is #contact + #stick + #free ≤ 2m + 2, much smaller than
//! the paper's 4m + 2.
//!
//! **Blocks.** The same direction serves the two halves of the problem for the NORM/TANG
//! alternation ([`super::norm_tang`]): [`Block::Normal`] keeps q and ξ frozen and solves rows
//! G1, G3, G5 for (g, p, δ0); [`Block::Tangential`] keeps p and δ0 frozen and solves rows G2, G4,
//! G6 for (s, q, ξ) with the friction bound μ max(0, p) of the frozen pressure (Kalker's TANG with
//! a given traction bound). The elastic rows are kept satisfied in both, so g and s follow the
//! tractions. [`Block::Coupled`] is the full problem.

use super::residual::{Formulation, State, System};
use super::workspace::{Tangential, Workspace};
use crate::linalg::mat_vec2;
use faer::Mat;
use falling_rows::FallingRows;
use system::SystemRows;

mod falling_rows;
mod system;

/// The reduced Newton system has no accurate solution (a non-finite entry after the LU solve):
/// the active sets of the iterate leave it singular.
#[derive(Debug, Clone, Copy, PartialEq, Eq, thiserror::Error)]
#[error("the Newton matrix of size {size} is singular")]
pub struct SingularNewtonMatrix {
    /// Size of the reduced system.
    pub size: usize,
}

/// Which unknowns a Newton solve updates (module docs).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Block {
    /// The coupled problem: every unknown.
    Coupled,
    /// The normal problem: (g, p, δ0) with q and ξ frozen (Kalker's NORM).
    Normal,
    /// The tangential problem: (s, q, ξ) with p and δ0 frozen (Kalker's TANG).
    Tangential,
}

impl Block {
    /// Whether the block solves the normal unknowns (g, p, δ0).
    pub(crate) fn solves_normal(self) -> bool {
        self != Block::Tangential
    }

    /// Whether the block solves the tangential unknowns (s, q, ξ).
    pub(crate) fn solves_tangential(self) -> bool {
        self != Block::Normal
    }
}

impl System<'_> {
    /// G(z) restricted to a block: the rows the block does not solve are set to zero (the
    /// layout, and so the indexing of the Newton step, stays that of the full residual).
    pub(crate) fn block_residual(&self, z: &State, block: Block) -> Vec<f64> {
        let mut r = self.residual(z);
        let m = self.m();
        if !block.solves_tangential() {
            r[3 * m..4 * m].fill(0.0);
            if self.free_creep {
                let k = r.len() - 1;
                r[k] = 0.0;
            }
        }
        if !block.solves_normal() {
            r[2 * m..3 * m].fill(0.0);
            if self.free_overlap {
                r[4 * m] = 0.0;
            }
        }
        r
    }

    fn tangential_state(&self, z: &State, i: usize) -> Tangential {
        let bound = self.friction(z, i) * self.bound_pressure(z, i);
        let t = z.shear[i] - self.rt[i] * z.slip[i];
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

    /// With δ0 free, at least one node must carry the contact row (δ0 appears nowhere else,
    /// and the P row would repeat itself); with ξ free, the Q row needs a node in contact to
    /// stick (see [`System::ensure_stick_row`]). If no node is in contact, the node closest to
    /// contact (largest p − r g) is given the contact derivative, the paper's "modified" choice
    /// at a near-tie. An iterate with every node open is met after a full step into tension,
    /// e.g. on an incompressible layer, whose volume constraint makes the all-contact start
    /// solve for negative pressures everywhere.
    fn ensure_contact_row(&self, z: &State, contact: &mut [bool], block: Block) {
        let needed = (self.free_overlap && block.solves_normal()) || (self.free_creep && block.solves_tangential());
        if needed && !contact.iter().any(|&c| c) {
            let f = |k: usize| z.pressure[k] - self.rn[k] * z.gap[k];
            let k = (0..contact.len()).max_by(|&i, &j| f(i).total_cmp(&f(j))).unwrap_or(0);
            contact[k] = true;
        }
    }

    /// With ξ free, ξ enters only the stick rows: when every loaded node slips (a full-sliding
    /// active set, met transiently), the Q row becomes a multiple of the P row and the matrix is
    /// singular. The slipping node closest to sticking (smallest (|t| − bound)/bound) then gets
    /// the stick derivative, again a "modified" choice at a near-tie (paper Eq. 60). A contact
    /// node whose friction bound is zero (free) qualifies too, after every slipping one.
    fn ensure_stick_row(&self, z: &State, contact: &[bool], tangential: &mut [Tangential], block: Block) {
        if !(self.free_creep && block.solves_tangential()) || tangential.contains(&Tangential::Stick) {
            return;
        }
        let excess = |i: usize| {
            let bound = self.friction(z, i) * self.bound_pressure(z, i);
            if bound > 0.0 {
                ((z.shear[i] - self.rt[i] * z.slip[i]).abs() - bound) / bound
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

    /// Solves the linearized equations BG(z)Δz = −G(z) by the reduction in the module docs, in
    /// the memory of `ws` (its matrix, pivots and work vectors, overwritten).
    /// Returns Δz and the size of the reduced system.
    #[allow(non_snake_case)]
    pub(crate) fn newton_direction(
        &self,
        z: &State,
        G: &[f64],
        block: Block,
        ws: &mut Workspace,
    ) -> Result<(State, usize), SingularNewtonMatrix> {
        let m = self.m();
        let (g2, g3, g4) = (&G[m..2 * m], &G[2 * m..3 * m], &G[3 * m..4 * m]);

        // Δp_j = p_const + [column p_col]; Δq_j = q_const + [column q_col] + q_pcoef·Δp_j.
        let mut n_cols = 0;
        let mut p_col = std::mem::take(&mut ws.p_col);
        reset(&mut p_col, m, None);
        let mut p_const = std::mem::take(&mut ws.p_const);
        reset(&mut p_const, m, 0.0);
        let mut contact_rows = std::mem::take(&mut ws.contact_rows);
        contact_rows.clear();
        let mut normal_contact = std::mem::take(&mut ws.normal_contact);
        normal_contact.clear();
        normal_contact.extend((0..m).map(|i| self.is_contact(z, i)));
        let mut tangential = std::mem::take(&mut ws.tangential);
        tangential.clear();
        tangential.extend((0..m).map(|i| self.tangential_state(z, i)));
        self.ensure_contact_row(z, &mut normal_contact, block);
        self.ensure_stick_row(z, &normal_contact, &mut tangential, block);
        // Frozen unknowns of a block: Δp = 0 (Tangential) or Δq = 0 (Normal), no rows or columns.
        let (solve_p, solve_q) = (block.solves_normal(), block.solves_tangential());
        let free_overlap = self.free_overlap && solve_p;
        let free_creep = self.free_creep && solve_q;
        for i in (0..m).filter(|_| solve_p) {
            if normal_contact[i] {
                p_col[i] = Some(n_cols);
                n_cols += 1;
                contact_rows.push(i);
            } else {
                p_const[i] = -g3[i];
            }
        }
        let mut q_col = std::mem::take(&mut ws.q_col);
        reset(&mut q_col, m, None);
        let mut q_const = std::mem::take(&mut ws.q_const);
        reset(&mut q_const, m, 0.0);
        let mut q_pcoef = std::mem::take(&mut ws.q_pcoef);
        reset(&mut q_pcoef, m, 0.0);
        let mut stick_rows = std::mem::take(&mut ws.stick_rows);
        stick_rows.clear();
        let mut falling = FallingRows::new(self.pb.falling.map_or(0, |_| m));
        for i in (0..m).filter(|_| solve_q) {
            match tangential[i] {
                Tangential::Free => q_const[i] = -g4[i],
                Tangential::Stick => {
                    q_col[i] = Some(n_cols);
                    n_cols += 1;
                    stick_rows.push(i);
                }
                Tangential::Slip(sign) => {
                    let shift = if self.form == Formulation::Phi { g3[i] } else { 0.0 };
                    let mu_i = self.friction(z, i);
                    // A falling law: Δq_i also follows Δs_i, which the elastic slip rows tie
                    // to every traction, so Δq_i is an unknown with a row of its own.
                    let c = sign * self.bound_pressure(z, i) * self.friction_slope(z, i);
                    if c != 0.0 {
                        q_col[i] = Some(n_cols);
                        n_cols += 1;
                        falling.push(i, c, mu_i * sign, -g4[i] + mu_i * sign * shift - c * g2[i] / self.rt[i]);
                    } else {
                        q_const[i] = -g4[i] + mu_i * sign * shift;
                        q_pcoef[i] = mu_i * sign;
                    }
                }
            }
        }
        // The load unknowns δ0 and ξ, when free, take the last columns.
        let col_overlap = free_overlap.then_some(n_cols);
        n_cols += usize::from(free_overlap);
        let col_creep = free_creep.then_some(n_cols);
        n_cols += usize::from(free_creep);
        let n = n_cols;
        let unknowns = Unknowns {
            p_col: &p_col,
            p_const: &p_const,
            q_col: &q_col,
            q_const: &q_const,
            q_pcoef: &q_pcoef,
        };
        // A workspace that keeps factors solves a system whose inputs are the kept one's with
        // those factors, and then fills only the right side.
        let rows = SystemRows {
            contact: &contact_rows,
            stick: &stick_rows,
            falling: &falling,
            overlap: col_overlap,
            creep: col_creep,
        };
        let key = ws.keeps_factors().then(|| self.system_key(&unknowns, &rows));
        let kept = key.as_deref().is_some_and(|k| ws.kept_for(k));
        let (J, rhs) = ws.system(n, !kept);
        let J = (!kept).then_some(J);
        let row = self.fill_system(J, rhs, &unknowns, &rows, G, (free_overlap, free_creep));
        debug_assert_eq!(row, n);

        ws.solve_system(key);
        let y = &ws.rhs;
        let singular = (0..n).any(|r| !y[(r, 0)].is_finite());
        let (dp, dq) = unknowns.tractions(y);
        let d_overlap = col_overlap.map_or(0.0, |c| y[(c, 0)]);
        let d_creep = col_creep.map_or(0.0, |c| y[(c, 0)]);
        // The work vectors go back to the workspace for the next step.
        ws.p_col = p_col;
        ws.p_const = p_const;
        ws.q_col = q_col;
        ws.q_const = q_const;
        ws.q_pcoef = q_pcoef;
        ws.contact_rows = contact_rows;
        ws.stick_rows = stick_rows;
        ws.normal_contact = normal_contact;
        ws.tangential = tangential;
        if singular {
            return Err(SingularNewtonMatrix { size: n });
        }
        Ok((self.step_of_tractions(G, dp, dq, d_overlap, d_creep), n))
    }

    /// The full Newton step from the reduced system's tractions Δp, Δq and the load unknowns
    /// Δδ0, Δξ: the gap and slip increments follow from the elastic rows (gap and slip in the
    /// units of the state, the creep along the flow direction `flow_sign`).
    #[allow(non_snake_case)]
    fn step_of_tractions(&self, G: &[f64], dp: Vec<f64>, dq: Vec<f64>, d_overlap: f64, d_creep: f64) -> State {
        let pb = self.pb;
        let m = self.m();
        let (g1, g2) = (&G[0..m], &G[m..2 * m]);
        let dh = pb.compression(&dp, &dq);
        let db = mat_vec2(&pb.bp, &dp, &pb.bq, &dq);
        let dg = (0..m).map(|i| -g1[i] / self.rn[i] - d_overlap + dh[i]).collect();
        let e = &pb.slip_operator.creep_weight;
        let ds = (0..m)
            .map(|i| -g2[i] / self.rt[i] + pb.flow_sign * d_creep * e[i] + db[i])
            .collect();
        State {
            gap: dg,
            slip: ds,
            pressure: dp,
            shear: dq,
            overlap: d_overlap,
            creep: d_creep,
        }
    }
}

/// `v` as `m` copies of `value`, keeping its allocation.
fn reset<T: Clone>(v: &mut Vec<T>, m: usize, value: T) {
    v.clear();
    v.resize(m, value);
}

/// The tractions of the reduced system: Δp_j = p_const_j + [column p_col_j] and
/// Δq_j = q_const_j + [column q_col_j] + q_pcoef_j·Δp_j (a node's known parts in the
/// constants, its unknowns, if any, in the named columns of the reduced matrix).
struct Unknowns<'a> {
    p_col: &'a [Option<usize>],
    p_const: &'a [f64],
    q_col: &'a [Option<usize>],
    q_const: &'a [f64],
    q_pcoef: &'a [f64],
}

#[allow(non_snake_case)]
impl Unknowns<'_> {
    /// Adds Σ_j (ap_j Δp_j + aq_j Δq_j) to row `row`, moving known parts to the right side.
    fn add_row(
        &self,
        mut J: Option<&mut Mat<f64>>,
        rhs: &mut Mat<f64>,
        row: usize,
        ap: &dyn Fn(usize) -> f64,
        aq: &dyn Fn(usize) -> f64,
    ) {
        for j in 0..self.p_const.len() {
            let (a_p, a_q) = (ap(j), aq(j));
            let cp = a_p + a_q * self.q_pcoef[j];
            rhs[(row, 0)] -= cp * self.p_const[j] + a_q * self.q_const[j];
            let Some(J) = J.as_deref_mut() else { continue };
            if let Some(c) = self.p_col[j] {
                J[(row, c)] += cp;
            }
            if let Some(c) = self.q_col[j] {
                J[(row, c)] += a_q;
            }
        }
    }

    /// The elastic rows r_i (A_p Δp + A_q Δq)_i from row `first`, filled column by column:
    /// faer stores the flexibilities and J by columns, so a column j of both is read and
    /// written in order. Known parts (Δp_j, Δq_j fixed at open or slipping nodes) move to the
    /// right side.
    #[allow(clippy::too_many_arguments)]
    fn fill_elastic(
        &self,
        mut J: Option<&mut Mat<f64>>,
        rhs: &mut Mat<f64>,
        first: usize,
        rows: &[usize],
        r: &[f64],
        a_p: &Mat<f64>,
        a_q: &Mat<f64>,
    ) {
        let end = first + rows.len();
        for j in 0..self.p_const.len() {
            let (col_p, col_q) = (a_p.col_as_slice(j), a_q.col_as_slice(j));
            let coef = self.q_pcoef[j];
            let (known_p, known_q) = (self.p_const[j], self.q_const[j]);
            if known_p != 0.0 || known_q != 0.0 {
                let out = &mut rhs.col_as_slice_mut(0)[first..end];
                for (o, &i) in out.iter_mut().zip(rows) {
                    let (ap, aq) = (r[i] * col_p[i], r[i] * col_q[i]);
                    *o -= (ap + aq * coef) * known_p + aq * known_q;
                }
            }
            // Without the matrix (the kept factors solve it) only the right side is made.
            let Some(J) = J.as_deref_mut() else { continue };
            if let Some(c) = self.p_col[j] {
                let out = &mut J.col_as_slice_mut(c)[first..end];
                for (o, &i) in out.iter_mut().zip(rows) {
                    let (ap, aq) = (r[i] * col_p[i], r[i] * col_q[i]);
                    *o += ap + aq * coef;
                }
            }
            if let Some(c) = self.q_col[j] {
                let out = &mut J.col_as_slice_mut(c)[first..end];
                for (o, &i) in out.iter_mut().zip(rows) {
                    *o += r[i] * col_q[i];
                }
            }
        }
    }

    /// Δp and Δq from the reduced system's solution `y`.
    fn tractions(&self, y: &Mat<f64>) -> (Vec<f64>, Vec<f64>) {
        let m = self.p_const.len();
        let dp: Vec<f64> = (0..m)
            .map(|j| self.p_const[j] + self.p_col[j].map_or(0.0, |c| y[(c, 0)]))
            .collect();
        let dq: Vec<f64> = (0..m)
            .map(|j| self.q_const[j] + self.q_col[j].map_or(0.0, |c| y[(c, 0)]) + self.q_pcoef[j] * dp[j])
            .collect();
        (dp, dq)
    }
}

#[cfg(test)]
mod tests {
    //! Finite-difference check of the pseudo-Jacobian of the Newton step.
    //!
    //! G(z) is piecewise linear: the elastic and load rows are linear, and the projections are
    //! linear on each branch (open / contact, stick / slip ±). Inside one piece the B-derivative
    //! is the Jacobian, and the Newton direction Δz solves J Δz = −G, so along it
    //! G(z + εΔz) = (1 − ε) G(z) up to round-off, as long as no node changes branch. That checks
    //! every row of the reduced system of `newton_direction` (and the back-substitution of Δg, Δs,
    //! Δq at slipping and open nodes) against the residual it linearizes, for both formulations,
    //! each control and each block.
    use super::*;
    use crate::contact::residual::{axpy, start_vector, ConvergenceMeasure};
    use crate::contact::{ContactProblem, NormalControl, TangentialControl};

    /// The assembled problem of a shipped case and its solution by full Newton steps along
    /// [`System::newton_direction`] (Φ, automatic penalties) to the default tolerance.
    fn solved(case: &str, set: &[String]) -> (ContactProblem, State) {
        let pb = crate::app::solve_case(&crate::case::shipped(case), set)
            .expect("shipped case solves")
            .problem;
        let sys = System::new(&pb, Formulation::Phi, 1.0);
        let measure = ConvergenceMeasure::new(&pb);
        let mut z = start_vector(&pb);
        for _ in 0..100 {
            if measure.of(&z) <= 1e-10 {
                break;
            }
            let g = sys.block_residual(&z, Block::Coupled);
            let (dz, _) = sys
                .newton_direction(&z, &g, Block::Coupled, &mut Workspace::new())
                .expect("regular");
            z = axpy(&z, 1.0, &dz);
        }
        assert!(measure.of(&z) <= 1e-10, "full Newton steps did not converge");
        (pb, z)
    }

    /// A deterministic perturbation of a solution that leaves a mix of open, stick and slip
    /// nodes, with no node on a branch boundary.
    fn perturbed(z: &State, p0: f64, mu: f64) -> State {
        let m = z.pressure.len();
        let wave = |i: usize, f: f64, ph: f64| (f * i as f64 + ph).sin();
        State {
            pressure: (0..m).map(|i| z.pressure[i] + 0.05 * p0 * wave(i, 1.7, 0.3)).collect(),
            shear: (0..m)
                .map(|i| z.shear[i] + 0.05 * mu * p0 * wave(i, 2.3, 1.1))
                .collect(),
            gap: (0..m).map(|i| z.gap[i] * (1.0 + 0.1 * wave(i, 0.9, 0.7))).collect(),
            slip: (0..m).map(|i| z.slip[i] + 1e-5 * wave(i, 1.3, 2.0)).collect(),
            overlap: z.overlap * 1.01,
            creep: z.creep * 1.05,
        }
    }

    /// Branch of every node: (normal contact, tangential state).
    fn branches(sys: &System, z: &State) -> Vec<(bool, Tangential)> {
        (0..sys.m())
            .map(|i| (sys.is_contact(z, i), sys.tangential_state(z, i)))
            .collect()
    }

    /// max |G(z + εΔz) − (1 − ε)G(z)| / (ε max|G(z)|) along the Newton direction of `block`.
    fn linearization_error(sys: &System, z: &State, block: Block, eps: f64) -> f64 {
        let g = sys.block_residual(z, block);
        let (dz, _) = sys
            .newton_direction(z, &g, block, &mut Workspace::new())
            .expect("regular Newton matrix");
        if !block.solves_normal() {
            assert!(
                dz.pressure.iter().all(|&d| d == 0.0) && dz.overlap == 0.0,
                "frozen p moved"
            );
        }
        if !block.solves_tangential() {
            assert!(dz.shear.iter().all(|&d| d == 0.0) && dz.creep == 0.0, "frozen q moved");
        }
        let trial = axpy(z, eps, &dz);
        assert_eq!(
            branches(sys, z),
            branches(sys, &trial),
            "the step crossed a kink: use a smaller ε"
        );
        let g_trial = sys.block_residual(&trial, block);
        let scale = g.iter().fold(0.0_f64, |a, v| a.max(v.abs()));
        let err = g
            .iter()
            .zip(&g_trial)
            .fold(0.0_f64, |a, (g0, g1)| a.max((g1 - (1.0 - eps) * g0).abs()));
        err / (eps * scale)
    }

    /// On a uniform grid (the paper's penalty pair) and on an error-controlled graded grid
    /// (per-node penalties, [`crate::contact::residual::nodal_penalties`]).
    #[test]
    fn newton_direction_linearizes_the_residual_on_every_branch() {
        linearizes_on_every_branch("carter_051.yaml", &[]);
        linearizes_on_every_branch("carter2d_contact.yaml", &["contact.grid.tolerance=1e-4".into()]);
    }

    fn linearizes_on_every_branch(case: &str, set: &[String]) {
        let (pb0, z0) = solved(case, set);
        let p0 = z0.pressure.iter().fold(0.0_f64, |a, &p| a.max(p));
        let z = perturbed(&z0, p0, pb0.friction);
        let p_total = pb0.grid.integrate(&z0.pressure);
        let q_total = pb0.grid.integrate(&z0.shear);
        let controls = [
            (NormalControl::Force(p_total), TangentialControl::Ratio(0.51)),
            (NormalControl::Force(p_total), TangentialControl::Force(q_total)),
            (NormalControl::Force(p_total), TangentialControl::Creep(z0.creep)),
            (NormalControl::Overlap(z0.overlap), TangentialControl::Ratio(0.51)),
            (NormalControl::Overlap(z0.overlap), TangentialControl::Creep(z0.creep)),
        ];
        for (normal, tangential) in controls {
            let pb = ContactProblem {
                normal,
                tangential,
                ..pb0.clone()
            };
            for form in [Formulation::Phi, Formulation::Psi] {
                let sys = System::new(&pb, form, 1.0);
                let b = branches(&sys, &z);
                let open = b.iter().filter(|(c, _)| !c).count();
                let stick = b.iter().filter(|(c, t)| *c && *t == Tangential::Stick).count();
                let slip = b.iter().filter(|(c, t)| *c && matches!(t, Tangential::Slip(_))).count();
                assert!(
                    open > 0 && stick > 0 && slip > 0,
                    "{form:?}: the state must mix branches (open {open}, stick {stick}, slip {slip})"
                );
                // TANG always runs with Ψ's bound (see `solve_block`): under Φ the bound
                // μ max(0, p − r g) moves with g, which the frozen-pressure block does not linearize.
                let blocks: &[Block] = match form {
                    Formulation::Phi => &[Block::Coupled, Block::Normal],
                    Formulation::Psi => &[Block::Coupled, Block::Normal, Block::Tangential],
                };
                for &block in blocks {
                    let e = linearization_error(&sys, &z, block, 1e-6);
                    // Measured: 7e-8 (coupled, normal), 9e-9 (tangential): round-off of ε = 1e-6.
                    assert!(
                        e < 1e-6,
                        "{form:?} {normal:?} {tangential:?} {block:?}: relative error {e:.3e}"
                    );
                }
            }
        }
    }

    /// Under a falling law G4 is no longer piecewise linear (μ(s) is an exponential of the
    /// slip), so along the direction G(z + εΔz) − (1 − ε)G(z) = O(ε²): the relative error of
    /// [`linearization_error`] falls in proportion to ε (taken large enough that the O(ε²)
    /// part stands above round-off, small enough that no node changes branch). Without the slope rows of
    /// `FallingRows` it would stay O(1) (the μ'(s)Δs part of ΔG4 missing).
    #[test]
    fn newton_direction_linearizes_a_falling_law() {
        let (pb0, z0) = solved("carter_051.yaml", &[]);
        let p0 = z0.pressure.iter().fold(0.0_f64, |a, &p| a.max(p));
        let z = perturbed(&z0, p0, pb0.friction);
        // The decay slip velocity at the slip's scale (V = 1): μ varies by tens of percent
        // over the slipping nodes.
        let s_max = z.slip.iter().fold(0.0_f64, |a, &s| a.max(s.abs()));
        let law = crate::contact::falling::FallingLaw {
            law: crate::contact::falling::FallingFriction {
                kinetic: 0.5 * pb0.friction,
                slip_velocity: 0.05 * s_max,
                second: None,
            },
            speed: 1.0,
        };
        let pb = ContactProblem {
            falling: Some(law),
            ..pb0
        };
        for form in [Formulation::Phi, Formulation::Psi] {
            let sys = System::new(&pb, form, 1.0);
            let slipping = (0..sys.m())
                .filter(|&i| sys.is_contact(&z, i) && matches!(sys.tangential_state(&z, i), Tangential::Slip(_)))
                .filter(|&i| sys.friction_slope(&z, i).abs() > 1.0)
                .count();
            assert!(slipping > 0, "{form:?}: slipping nodes on the law's slope");
            let coarse = linearization_error(&sys, &z, Block::Coupled, 1e-3);
            let fine = linearization_error(&sys, &z, Block::Coupled, 1e-4);
            // Measured (Φ and Ψ alike): 9.2e-5 at ε = 1e-3, 9.2e-6 at 1e-4; without the slope
            // rows, 8.7e-2 at 1e-3.
            assert!(coarse < 1e-3, "{form:?}: relative error {coarse:.3e} at ε = 1e-3");
            let ratio = coarse / fine;
            assert!(
                (5.0..20.0).contains(&ratio),
                "{form:?}: the error falls as ε ({coarse:.3e} → {fine:.3e})"
            );
        }
    }

    #[test]
    fn a_wrong_jacobian_is_detected() {
        // The check is sharp: the same state with the friction coefficient changed only in the
        // residual (not in the direction) must fail it.
        let (pb, z0) = solved("carter_051.yaml", &[]);
        let p0 = z0.pressure.iter().fold(0.0_f64, |a, &p| a.max(p));
        let z = perturbed(&z0, p0, pb.friction);
        let sys = System::new(&pb, Formulation::Phi, 1.0);
        let g = sys.block_residual(&z, Block::Coupled);
        let (dz, _) = sys
            .newton_direction(&z, &g, Block::Coupled, &mut Workspace::new())
            .expect("regular");
        let other = ContactProblem {
            friction: pb.friction * 1.01,
            ..pb.clone()
        };
        let sys2 = System::new(&other, Formulation::Phi, 1.0);
        let eps = 1e-6;
        let g0 = sys2.block_residual(&z, Block::Coupled);
        let g1 = sys2.block_residual(&axpy(&z, eps, &dz), Block::Coupled);
        let scale = g0.iter().fold(0.0_f64, |a, v| a.max(v.abs()));
        let err = g0
            .iter()
            .zip(&g1)
            .fold(0.0_f64, |a, (a0, a1)| a.max((a1 - (1.0 - eps) * a0).abs()));
        assert!(err / (eps * scale) > 1e-3, "relative error {:.3e}", err / (eps * scale));
    }
}
