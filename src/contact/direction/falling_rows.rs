//! The Newton rows of slipping nodes under a friction law that falls with the slip velocity
//! (src/contact/falling.rs): the part of [`super`]'s reduced system that a constant μ does
//! not have.

use super::Unknowns;
use faer::Mat;

/// The rows of slipping nodes under a falling law (module docs of [`crate::contact::falling`]): the
/// linearised G4_i = q_i − μ(s_i) p̂_i sgn_i with the slope c_i = sgn_i p̂_i dμ/ds at the
/// node, Δs_i taken from the elastic slip row:
///
/// ```text
/// Δq_i − μ_i sgn_i Δp_i − c_i (B_p Δp + B_q Δq)_i − c_i σ e_i Δξ = −G4_i + μ_i sgn_i·shift_i − c_i G2_i/r_t,i
/// ```
///
/// (shift_i the Φ augmentation G3_i, as for a slipping node without a law).
pub(super) struct FallingRows {
    /// The nodes with a row, in row order.
    pub(super) rows: Vec<usize>,
    /// −c_i at each node (the weight of the node's elastic slip row; 0 where it has no row).
    weight: Vec<f64>,
    /// μ_i sgn_i and the right side of each row, in row order.
    mu_sign: Vec<f64>,
    rhs: Vec<f64>,
}

#[allow(non_snake_case)]
impl FallingRows {
    /// No rows yet, for `m` nodes (0 when no law acts).
    pub(super) fn new(m: usize) -> Self {
        Self {
            rows: Vec::new(),
            weight: vec![0.0; m],
            mu_sign: Vec::new(),
            rhs: Vec::new(),
        }
    }

    /// Adds node i's row: its slope c_i, μ_i sgn_i and its right side.
    pub(super) fn push(&mut self, i: usize, c: f64, mu_sign: f64, rhs: f64) {
        self.rows.push(i);
        self.weight[i] = -c;
        self.mu_sign.push(mu_sign);
        self.rhs.push(rhs);
    }

    /// Writes the rows from `first` into the reduced system; `creep` the free creepage's column
    /// and the flow sign σ.
    pub(super) fn fill(
        &self,
        unknowns: &Unknowns,
        mut J: Option<&mut Mat<f64>>,
        rhs: &mut Mat<f64>,
        first: usize,
        creep: Option<(usize, f64)>,
        pb: &crate::contact::ContactProblem,
    ) {
        if self.rows.is_empty() {
            return;
        }
        for (k, &value) in self.rhs.iter().enumerate() {
            rhs[(first + k, 0)] = value;
        }
        unknowns.fill_elastic(J.as_deref_mut(), rhs, first, &self.rows, &self.weight, &pb.bp, &pb.bq);
        for (k, &i) in self.rows.iter().enumerate() {
            let row = first + k;
            if unknowns.p_col[i].is_none() {
                rhs[(row, 0)] += self.mu_sign[k] * unknowns.p_const[i];
            }
            let Some(J) = J.as_deref_mut() else { continue };
            let q = unknowns.q_col[i].expect("a falling row's shear is an unknown");
            J[(row, q)] += 1.0;
            if let Some(c) = unknowns.p_col[i] {
                J[(row, c)] -= self.mu_sign[k];
            }
            if let Some((c, sigma)) = creep {
                J[(row, c)] += self.weight[i] * sigma * pb.slip_operator.creep_weight[i];
            }
        }
    }

    /// The rows' part of a system's key ([`super::System::system_key`]): each row's node, its
    /// weight −c_i and μ_i sgn_i, by their bits.
    pub(super) fn key_into(&self, key: &mut Vec<u64>) {
        key.push(self.rows.len() as u64);
        for (k, &i) in self.rows.iter().enumerate() {
            key.extend([i as u64, self.weight[i].to_bits(), self.mu_sign[k].to_bits()]);
        }
    }
}
