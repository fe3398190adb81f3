//! The reduced Newton system of [`super`] as numbers: its rows filled from the problem's
//! flexibilities and the unknowns' layout, and its *key*, the inputs the matrix is made of, by
//! which a workspace that keeps factors finds a system it has factored
//! (src/contact/workspace.rs, "Kept factors").

use super::{FallingRows, Unknowns};
use crate::contact::residual::System;
use faer::Mat;

/// The rows of a reduced system besides the load rows: the contact rows' nodes, the stick
/// rows' nodes, the falling-law rows, and the columns of δ0 and ξ when they are free.
pub(super) struct SystemRows<'a> {
    pub(super) contact: &'a [usize],
    pub(super) stick: &'a [usize],
    pub(super) falling: &'a FallingRows,
    pub(super) overlap: Option<usize>,
    pub(super) creep: Option<usize>,
}

impl System<'_> {
    /// Everything the reduced Newton matrix is made of, by its bits: the problem's
    /// flexibilities (by address and diagonal: they stay in place while a workspace keeps
    /// factors of them, and a history that changes its slip blocks makes new ones) and weights
    /// (by address), the row
    /// weights r_n and r_t, the rows and columns (the nodes of each kind in order, the
    /// load columns), the coefficients q_pcoef and the falling rows' slopes and μ_i sgn_i, the
    /// load row's Q/(μP) and μ. Two systems with the same key have the same matrix bit for
    /// bit, so a [`Workspace`] keeping factors solves the second with the first's LU without
    /// filling its matrix.
    pub(super) fn system_key(&self, unknowns: &Unknowns, rows: &SystemRows) -> Vec<u64> {
        let pb = self.pb;
        let mut key = Vec::with_capacity(8 * self.m() + 32);
        for a in [&pb.flex.hp, &pb.flex.hq, &pb.bp, &pb.bq] {
            key.extend([a.as_ptr() as u64, a.nrows() as u64, a.ncols() as u64]);
            // The diagonal too: a problem dropped and another made in its memory differs there.
            key.extend((0..a.nrows().min(a.ncols())).map(|i| a[(i, i)].to_bits()));
        }
        key.extend([
            pb.grid.weights.as_ptr() as u64,
            pb.slip_operator.creep_weight.as_ptr() as u64,
            pb.flow_sign.to_bits(),
            pb.friction.to_bits(),
        ]);
        key.extend(
            self.rn
                .iter()
                .chain(&self.rt)
                .chain(unknowns.q_pcoef)
                .map(|v| v.to_bits()),
        );
        for nodes in [rows.contact, rows.stick] {
            key.push(nodes.len() as u64);
            key.extend(nodes.iter().map(|&i| i as u64));
        }
        rows.falling.key_into(&mut key);
        key.extend([rows.overlap, rows.creep].map(|c| c.map_or(u64::MAX, |c| c as u64)));
        let ratio = self.tangential_load().map_or(f64::NAN, |(ratio, _)| ratio);
        key.push(ratio.to_bits());
        key
    }
}

#[allow(non_snake_case)]
impl System<'_> {
    /// Fills the reduced system's rows: the contact rows (elastic gap), the stick rows (elastic
    /// slip), the falling-law rows and the load rows (G5 when δ0 is free, G6 when ξ is), with
    /// their right sides from the residual `G`; the matrix `J` only when given (a system the
    /// kept factors solve needs only its right side). `free` = (δ0 free, ξ free). Returns the
    /// number of rows filled.
    pub(super) fn fill_system(
        &self,
        mut J: Option<&mut Mat<f64>>,
        rhs: &mut Mat<f64>,
        unknowns: &Unknowns,
        rows: &SystemRows,
        G: &[f64],
        (free_overlap, free_creep): (bool, bool),
    ) -> usize {
        let pb = self.pb;
        let m = self.m();
        let (g1, g2, g3, g4) = (&G[0..m], &G[m..2 * m], &G[2 * m..3 * m], &G[3 * m..4 * m]);
        for (k, &i) in rows.contact.iter().enumerate() {
            rhs[(k, 0)] = -g3[i] + g1[i];
        }
        unknowns.fill_elastic(
            J.as_deref_mut(),
            rhs,
            0,
            rows.contact,
            &self.rn,
            &pb.flex.hp,
            &pb.flex.hq,
        );
        if let (Some(c), Some(J)) = (rows.overlap, J.as_deref_mut()) {
            for (k, &i) in rows.contact.iter().enumerate() {
                J[(k, c)] = -self.rn[i];
            }
        }
        let first = rows.contact.len();
        for (k, &i) in rows.stick.iter().enumerate() {
            rhs[(first + k, 0)] = -g4[i] + g2[i];
        }
        unknowns.fill_elastic(J.as_deref_mut(), rhs, first, rows.stick, &self.rt, &pb.bp, &pb.bq);
        if let (Some(c), Some(J)) = (rows.creep, J.as_deref_mut()) {
            for (k, &i) in rows.stick.iter().enumerate() {
                J[(first + k, c)] = self.rt[i] * pb.flow_sign * pb.slip_operator.creep_weight[i];
            }
        }
        let mut row = first + rows.stick.len();
        let creep = rows.creep.map(|c| (c, pb.flow_sign));
        rows.falling.fill(unknowns, J.as_deref_mut(), rhs, row, creep, pb);
        row += rows.falling.rows.len();
        let w = &pb.grid.weights;
        // G5 sits at 4m whenever δ0 is free, G6 after it: the layout of the full residual.
        let k = 4 * m + usize::from(self.free_overlap);
        if free_overlap {
            rhs[(row, 0)] = -self.length * G[4 * m];
            unknowns.add_row(J.as_deref_mut(), rhs, row, &|j| w[j], &|_| 0.0);
            row += 1;
        }
        if let (true, Some((ratio, _))) = (free_creep, self.tangential_load()) {
            let mu = pb.friction;
            rhs[(row, 0)] = -self.length * G[k];
            unknowns.add_row(J, rhs, row, &|j| -ratio * mu * w[j], &|j| w[j]);
            row += 1;
        }
        row
    }
}
