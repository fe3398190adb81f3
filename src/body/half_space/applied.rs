//! The half-plane's influence matrices applied to a few loads without making them.
//!
//! An error-controlled run's outputs need body B's surface displacements under the final
//! tractions alone: one product of its flexibility with one load. On the final grid of m nodes
//! the flexibility is four m × m blocks (62 MB at 1398 nodes, bore_a020_braking at 1e-3), made
//! only for that product; here each row of the kernel's influence matrix is integrated, used
//! and dropped, which costs the same element integrals and no m × m memory.

use super::{element_integrals_exact, FarField, HalfSpace, Kernel, FAR_FIELD_RATIO};
use crate::body::Side;
use crate::grid::ContactGrid;
use faer::{Mat, MatRef};
use rayon::prelude::*;

/// K·V for the influence matrix K_ij = Σ_e ∫_e N_j(s) K(x_i − s) ds of `kernel` on `grid`
/// (the matrix of [`super::influence_matrix`], to the rounding of the element integrals) and
/// the loads V (m × k, one load per column), row by row (module docs). Units: those of K's
/// integrals (length times the kernel's) times V's.
pub fn influence_times(grid: &ContactGrid, kernel: Kernel, v: MatRef<'_, f64>) -> Mat<f64> {
    influence_times_at(grid, kernel, v, &grid.nodes)
}

/// [`influence_times`] at the points `xs` instead of the nodes (one row per point; for the
/// Cauchy kernel no point may lie on an element end where the load jumps).
pub fn influence_times_at(grid: &ContactGrid, kernel: Kernel, v: MatRef<'_, f64>, xs: &[f64]) -> Mat<f64> {
    let (m, k) = (xs.len(), v.ncols());
    assert_eq!(v.nrows(), grid.n_nodes(), "one load value per node");
    let npe = grid.kind.nodes_per_element();
    let far_field = FarField::new(grid.kind);
    let rows: Vec<Vec<f64>> = xs
        .par_iter()
        .map(|&x| {
            let mut row = vec![0.0; k];
            for e in 0..grid.n_elements() {
                let (s1, s2) = (grid.edges[e], grid.edges[e + 1]);
                // The same split between the far-field series and the closed form as the matrix.
                let integrals = if (0.5 * (s1 + s2) - x).abs() > FAR_FIELD_RATIO * (s2 - s1) {
                    far_field.integrals(kernel, s1, s2, x)
                } else {
                    element_integrals_exact(grid.kind, kernel, s1, s2, x)
                };
                for (a, &kij) in integrals.iter().take(npe).enumerate() {
                    let j = grid.global_node(e, a);
                    for (c, r) in row.iter_mut().enumerate() {
                        *r += kij * v[(j, c)];
                    }
                }
            }
            row
        })
        .collect();
    Mat::from_fn(m, k, |i, c| rows[i][c])
}

/// The half-plane's operators on `grid` for body `side`, applied to loads without their blocks
/// being made: its two coefficients A (sgn kernel) and B (log kernel) [length/stress] taken
/// once for both products.
pub(super) struct Applied<'a> {
    half: &'a HalfSpace,
    grid: &'a ContactGrid,
    side: Side,
    a_coef: f64,
    b_coef: f64,
}

impl<'a> Applied<'a> {
    /// The operators of `half` on `grid` as body `side`.
    pub(super) fn new(half: &'a HalfSpace, grid: &'a ContactGrid, side: Side) -> Self {
        let a_coef = half.material.halfplane_sgn_coefficient();
        let b_coef = half.material.halfplane_log_coefficient();
        Applied {
            half,
            grid,
            side,
            a_coef,
            b_coef,
        }
    }

    /// The half-plane's displacements [h, w] under the loads (p, q) (m × k each): the blocks of
    /// [`HalfSpace::kernel_blocks`] applied without being made, h = H_p p + H_q q and
    /// w = −H_q p + H_p q, with H_p v = −B (K_log v − (wᵀv) ln ℓ) and H_q v = side·A K_sgn v
    /// [length].
    pub(super) fn displacements(&self, p: MatRef<'_, f64>, q: MatRef<'_, f64>) -> [Mat<f64>; 2] {
        let (grid, a_coef, b_coef) = (self.grid, self.a_coef, self.b_coef);
        let ln_datum = self.half.datum_length().ln();
        let (m, k) = (p.nrows(), p.ncols());
        let loads = Mat::from_fn(m, 2 * k, |i, c| if c < k { p[(i, c)] } else { q[(i, c - k)] });
        let log = influence_times(grid, Kernel::Log, loads.as_ref());
        let sgn = influence_times(grid, Kernel::Sign, loads.as_ref());
        let forces: Vec<f64> = (0..2 * k)
            .map(|c| (0..m).map(|j| grid.weights[j] * loads[(j, c)]).sum())
            .collect();
        let hp = |i: usize, c: usize| -b_coef * (log[(i, c)] - forces[c] * ln_datum);
        let hq = |i: usize, c: usize| self.side.sign() * a_coef * sgn[(i, c)];
        [
            Mat::from_fn(m, k, |i, c| hp(i, c) + hq(i, k + c)),
            Mat::from_fn(m, k, |i, c| -hq(i, c) + hp(i, k + c)),
        ]
    }

    /// The half-plane's surface strain ∂w/∂x = −side·2A·p − B·PV∫ q(s)/(x − s) ds at the nodes
    /// under the loads (p, q) (m × k each), its Cauchy integral applied without being made [-].
    pub(super) fn strain(&self, p: MatRef<'_, f64>, q: MatRef<'_, f64>) -> Mat<f64> {
        let cauchy = influence_times(self.grid, Kernel::Cauchy, q);
        Mat::from_fn(p.nrows(), p.ncols(), |i, c| {
            -self.side.sign() * 2.0 * self.a_coef * p[(i, c)] - self.b_coef * cauchy[(i, c)]
        })
    }
}

#[cfg(test)]
mod tests {
    use super::super::influence_matrix;
    use super::*;
    use crate::grid::ElementKind;

    /// The rows integrated one by one give the matrix's product, for every kernel, on a graded
    /// grid (the direct matrix), a uniform one (the block-Toeplitz matrix, whose far elements
    /// take Gauss's rule instead of the series) and one of continuous elements (shared nodes).
    #[test]
    fn the_rows_integrated_one_by_one_give_the_matrix_product() {
        let graded = ContactGrid::from_edges(
            ElementKind::DiscontinuousQuadratic,
            vec![-1.0, -0.5, -0.2, -0.05, 0.0, 0.02, 0.1, 0.4, 1.0],
        );
        let uniform = ContactGrid::uniform(ElementKind::DiscontinuousQuadratic, 9, -1.0, 1.0);
        let continuous = ContactGrid::uniform(ElementKind::ContinuousQuadratic, 6, -1.0, 1.0);
        for grid in [graded, uniform, continuous] {
            let m = grid.n_nodes();
            let v = Mat::from_fn(m, 2, |i, c| (1.0 + i as f64).sin() + c as f64 * (0.3 * i as f64).cos());
            for kernel in [Kernel::Log, Kernel::Sign, Kernel::Cauchy] {
                let k = influence_matrix(&grid, kernel);
                let want = &k * &v;
                let got = influence_times(&grid, kernel, v.as_ref());
                let scale = want.norm_max();
                let diff = (&got - &want).norm_max();
                assert!(diff <= 1e-13 * scale, "{kernel:?} on {m} nodes: {diff:e} of {scale:e}");
            }
        }
    }
}
