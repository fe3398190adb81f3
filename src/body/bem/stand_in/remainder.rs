//! The smooth remainder R(x, s) of a BEM body's flexibility against the half-plane's, as
//! tensor-product Chebyshev series fitted on a level grid (src/body/bem/stand_in.rs, module
//! docs): the fit, Richardson's extrapolation of two fits, the series' blocks on any grid, and
//! the difference of two series as a low-rank change.

use crate::body::LowRankFlexibility;
use crate::grid::ContactGrid;
use faer::{Mat, MatRef};
use nalgebra::DMatrix;

/// The Chebyshev polynomials T_0..T_d at `x`, mapped from [lo, hi] to [−1, 1] (one row each).
pub(super) fn chebyshev_rows(x: &[f64], lo: f64, hi: f64, degree: usize) -> DMatrix<f64> {
    DMatrix::from_fn(x.len(), degree + 1, |i, k| {
        let t = ((2.0 * x[i] - lo - hi) / (hi - lo)).clamp(-1.0, 1.0);
        (k as f64 * t.acos()).cos()
    })
}

/// d/dx of the Chebyshev polynomials T_0..T_d at `x`, mapped from [lo, hi] to [−1, 1]:
/// T_k'(t) = k U_{k−1}(t) (U the second kind, by its recurrence), times dt/dx = 2/(hi − lo).
fn chebyshev_derivative_rows(x: &[f64], lo: f64, hi: f64, degree: usize) -> DMatrix<f64> {
    let dt_dx = 2.0 / (hi - lo);
    DMatrix::from_fn(x.len(), degree + 1, |i, k| {
        let t = ((2.0 * x[i] - lo - hi) / (hi - lo)).clamp(-1.0, 1.0);
        let (mut u_prev, mut u) = (0.0, 1.0); // U_{-1}, U_0
        for _ in 1..k {
            let next = 2.0 * t * u - u_prev;
            u_prev = u;
            u = next;
        }
        if k == 0 {
            0.0
        } else {
            k as f64 * u * dt_dx
        }
    })
}

/// The least-squares fit of a series of degree d over a grid's nodes: P⁺ = (TᵀT)⁻¹Tᵀ with
/// T the Chebyshev rows of the nodes, and the right factor W⁻¹P⁺ᵀ (W the nodes' weights) that
/// a block's samples (B − H)_ij / w_j meet on the right.
pub(super) struct FitFactors {
    /// P⁺, (d + 1) × m.
    pub(super) pinv: DMatrix<f64>,
    /// W⁻¹P⁺ᵀ, m × (d + 1) [1/length].
    pub(super) right: Mat<f64>,
}

impl FitFactors {
    pub(super) fn on(grid: &ContactGrid, span: [f64; 2], degree: usize) -> Self {
        let t = chebyshev_rows(&grid.nodes, span[0], span[1], degree);
        // The normal equations of a (degree + 1)-column basis, well conditioned on the nodes of
        // a grid that covers its interval.
        let pinv = (t.transpose() * &t)
            .try_inverse()
            .unwrap_or_else(|| DMatrix::zeros(degree + 1, degree + 1))
            * t.transpose();
        let right = Mat::from_fn(grid.n_nodes(), degree + 1, |j, l| pinv[(l, j)] / grid.weights[j]);
        Self { pinv, right }
    }
}

/// Columns of the remainder made at a time by [`SmoothRemainder::add_to`].
const ADD_COLUMNS: usize = 64;

/// The smooth remainder R(x, s) of a body's operator blocks (the four flexibility blocks, or
/// the two of the surface strain) as Chebyshev series.
#[derive(Debug, Clone)]
pub struct SmoothRemainder {
    /// The interval the series map to [−1, 1] (the start grid's span) [length].
    span: [f64; 2],
    /// Degree in each variable.
    degree: usize,
    /// Coefficients of each block [the block's unit per length].
    pub(super) coefficients: Vec<DMatrix<f64>>,
}

impl SmoothRemainder {
    /// The least-squares series of (B − H)_ij / w_j over the nodes of `grid` for each pair
    /// (B, H) of a body's block and the half-plane's, from the blocks' products with the fit's
    /// right factor ([`FitFactors::right`]): each block's coefficients are P⁺(B − H)W⁻¹P⁺ᵀ with
    /// P⁺ the fit's pseudo-inverse and W the weights, so B enters only as B·(W⁻¹P⁺ᵀ), d + 1
    /// loads per traction component, not B itself.
    pub(super) fn fitted(products: &[(Mat<f64>, Mat<f64>)], fit: &FitFactors, span: [f64; 2], degree: usize) -> Self {
        let coefficients = products
            .iter()
            .map(|(bv, hv)| {
                let d = DMatrix::from_fn(bv.nrows(), bv.ncols(), |i, l| bv[(i, l)] - hv[(i, l)]);
                &fit.pinv * d
            })
            .collect();
        Self {
            span,
            degree,
            coefficients,
        }
    }

    /// Richardson's extrapolation of a first-order error: 2·fine − coarse.
    pub(super) fn extrapolated(coarse: &Self, fine: &Self) -> Self {
        Self {
            span: fine.span,
            degree: fine.degree,
            coefficients: coarse
                .coefficients
                .iter()
                .zip(&fine.coefficients)
                .map(|(c, f)| 2.0 * f - c)
                .collect(),
        }
    }

    /// Adds the remainder's blocks on `grid`, R(x_i, s_j)·w_j, to `targets` (one per block, in
    /// the order of the coefficients): in place, where a flexibility on a large grid would
    /// otherwise take four more matrices of its size per body and pass.
    pub fn add_to<'a>(&self, grid: &ContactGrid, targets: impl Iterator<Item = &'a mut Mat<f64>>) {
        let t = chebyshev_rows(&grid.nodes, self.span[0], self.span[1], self.degree);
        for (c, target) in self.coefficients.iter().zip(targets) {
            add_weighted_product(&(&t * c), &t, &grid.weights, target);
        }
    }

    /// The four blocks of [`Self::add_to`] applied to the loads `p`, `q` (m × k each) on
    /// `grid`, in factors (no m × m block made): [h, w] = [R_hp p + R_hq q, R_wp p + R_wq q],
    /// each block T C Tᵀ diag(w) [length].
    pub fn times(&self, grid: &ContactGrid, p: MatRef<'_, f64>, q: MatRef<'_, f64>) -> [Mat<f64>; 2] {
        let t = chebyshev_rows(&grid.nodes, self.span[0], self.span[1], self.degree);
        let (m, k) = (grid.n_nodes(), p.ncols());
        let (tp, tq) = (weighted_projection(&t, grid, p), weighted_projection(&t, grid, q));
        let c = &self.coefficients;
        let block_pair = |a: usize, b: usize| {
            let y = &t * (&c[a] * &tp + &c[b] * &tq);
            Mat::from_fn(m, k, |i, l| y[(i, l)])
        };
        [block_pair(0, 1), block_pair(2, 3)]
    }

    /// The two blocks of [`Self::add_w_derivatives_to`] applied to the loads `p`, `q` (m × k
    /// each) on `grid`, in factors: ∂R_wp/∂x p + ∂R_wq/∂x q [-].
    pub fn w_derivatives_times(&self, grid: &ContactGrid, p: MatRef<'_, f64>, q: MatRef<'_, f64>) -> Mat<f64> {
        let t = chebyshev_rows(&grid.nodes, self.span[0], self.span[1], self.degree);
        let dt = chebyshev_derivative_rows(&grid.nodes, self.span[0], self.span[1], self.degree);
        let (m, k) = (grid.n_nodes(), p.ncols());
        let (tp, tq) = (weighted_projection(&t, grid, p), weighted_projection(&t, grid, q));
        let c = &self.coefficients;
        let y = &dt * (&c[2] * tp + &c[3] * tq);
        Mat::from_fn(m, k, |i, l| y[(i, l)])
    }

    /// `other` less this remainder on `grid`, as a low-rank change of the four blocks: left the
    /// Chebyshev rows T(x_i), right (ΔC T(s_j)ᵀ)·w_j with ΔC the difference of the coefficients
    /// (the entries [`Self::add_to`] would add, in factors). Both must be series of one span
    /// and degree (the fits of one stand-in's levels).
    pub(super) fn change_to(&self, other: &Self, grid: &ContactGrid) -> LowRankFlexibility {
        assert!(
            self.span == other.span && self.degree == other.degree,
            "a change between series of one span and degree"
        );
        let t = chebyshev_rows(&grid.nodes, self.span[0], self.span[1], self.degree);
        let (m, r) = (grid.n_nodes(), self.degree + 1);
        let left = Mat::from_fn(m, r, |i, l| t[(i, l)]);
        let right = std::array::from_fn(|k| {
            let d = (&other.coefficients[k] - &self.coefficients[k]) * t.transpose();
            Mat::from_fn(r, m, |l, j| d[(l, j)] * grid.weights[j])
        });
        LowRankFlexibility { left, right }
    }

    /// Adds ∂R/∂x of the w blocks (wp, wq) on `grid`, ∂R(x_i, s_j)/∂x·w_j (the surface strain
    /// of the remainder's tangential displacement), to `targets` (the strain's p and q
    /// blocks): in place, a few columns at a time, as [`Self::add_to`].
    pub(super) fn add_w_derivatives_to(&self, grid: &ContactGrid, targets: [&mut Mat<f64>; 2]) {
        let t = chebyshev_rows(&grid.nodes, self.span[0], self.span[1], self.degree);
        let dt = chebyshev_derivative_rows(&grid.nodes, self.span[0], self.span[1], self.degree);
        for (k, target) in [2, 3].into_iter().zip(targets) {
            add_weighted_product(&(&dt * &self.coefficients[k]), &t, &grid.weights, target);
        }
    }
}

/// Tᵀ diag(w) V: the loads V (m × k) weighted by the grid's node weights and projected on the
/// Chebyshev rows T (m × r), the right half of a series block T C Tᵀ diag(w) applied to V.
fn weighted_projection(t: &DMatrix<f64>, grid: &ContactGrid, v: MatRef<'_, f64>) -> DMatrix<f64> {
    t.transpose() * DMatrix::from_fn(v.nrows(), v.ncols(), |j, c| grid.weights[j] * v[(j, c)])
}

/// Adds (L Tᵀ)_ij·w_j to `target` (m × m; L m × r, T m × r): a few columns at a time, since an
/// m × m product would be one more matrix of the grid's size per block (each entry is the same
/// short sum either way).
fn add_weighted_product(left: &DMatrix<f64>, t: &DMatrix<f64>, weights: &[f64], target: &mut Mat<f64>) {
    let m = left.nrows();
    for first in (0..m).step_by(ADD_COLUMNS) {
        let n = ADD_COLUMNS.min(m - first);
        let r = left * t.rows(first, n).transpose();
        for (k, &w) in weights[first..first + n].iter().enumerate() {
            let column = &r.as_slice()[k * m..(k + 1) * m];
            for (a, &b) in target.col_as_slice_mut(first + k).iter_mut().zip(column) {
                *a += b * w;
            }
        }
    }
}
