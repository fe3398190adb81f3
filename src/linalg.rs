//! Small dense products shared by the body models and the contact solver.

use faer::Mat;

/// y = A x for a dense matrix and a slice (columns of zero x_j skipped).
pub fn mat_vec(a: &Mat<f64>, x: &[f64]) -> Vec<f64> {
    let mut y = vec![0.0; a.nrows()];
    // Column-major storage: accumulate column by column.
    for (j, &xj) in x.iter().enumerate().take(a.ncols()) {
        if xj != 0.0 {
            let col = a.col(j);
            for (i, yi) in y.iter_mut().enumerate() {
                *yi += col[i] * xj;
            }
        }
    }
    y
}

/// y = A x + B z for square dense matrices and slices.
pub fn mat_vec2(a: &Mat<f64>, x: &[f64], b: &Mat<f64>, z: &[f64]) -> Vec<f64> {
    let m = a.nrows();
    let mut y = vec![0.0; m];
    // Column-major storage: accumulate column by column.
    for j in 0..a.ncols() {
        let (xj, zj) = (x[j], z[j]);
        if xj != 0.0 {
            let col = a.col(j);
            for (i, yi) in y.iter_mut().enumerate() {
                *yi += col[i] * xj;
            }
        }
        if zj != 0.0 {
            let col = b.col(j);
            for (i, yi) in y.iter_mut().enumerate() {
                *yi += col[i] * zj;
            }
        }
    }
    y
}

/// Order from which [`lu_solve_in_place`] factors with faer's threads: below it one thread is
/// faster on the two-core machine (an error-controlled carter2d run at tolerance 1e-4, whose
/// largest Newton system is 573: 0.07 s against 0.09 s).
pub const PARALLEL_LU_MIN: usize = 1024;

/// Solves A X = B in place by LU with partial pivoting: `a` is overwritten by its factors and
/// `rhs` by the solution. faer's `PartialPivLu` copies the matrix and then splits it into L and
/// U (three more n × n matrices, each paid in page faults at the sizes of the Newton systems);
/// this factors the caller's matrix where it lies, with faer's same routines.
pub fn lu_solve_in_place(mut a: Mat<f64>, rhs: faer::MatMut<'_, f64>) {
    use faer::dyn_stack::{MemBuffer, MemStack};
    use faer::linalg::lu::partial_pivoting::{factor, solve};
    let n = a.nrows();
    assert_eq!(n, a.ncols(), "a square matrix");
    // Below PARALLEL_LU_MIN unknowns the threads' hand-offs cost more than they share on two
    // cores (docs/performance.md).
    let par = if n < PARALLEL_LU_MIN {
        faer::Par::Seq
    } else {
        faer::get_global_parallelism()
    };
    let mut perm = vec![0usize; n];
    let mut perm_inv = vec![0usize; n];
    let scratch = factor::lu_in_place_scratch::<usize, f64>(n, n, par, Default::default())
        .or(solve::solve_in_place_scratch::<usize, f64>(n, rhs.ncols(), par));
    let mut buffer = MemBuffer::new(scratch);
    let stack = MemStack::new(&mut buffer);
    let (_, row_perm) = factor::lu_in_place(a.as_mut(), &mut perm, &mut perm_inv, par, stack, Default::default());
    // L (unit lower) and U share the factored matrix: each solve reads only its own triangle.
    solve::solve_in_place(a.as_ref(), a.as_ref(), row_perm, rhs, par, stack);
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn products_match_the_definition() {
        let a = Mat::from_fn(3, 3, |i, j| (1 + i + 3 * j) as f64);
        let b = Mat::from_fn(3, 3, |i, j| (i as f64) - (j as f64));
        let (x, z) = ([1.0, 0.0, -2.0], [0.5, 2.0, 0.0]);
        let want: Vec<f64> = (0..3)
            .map(|i| (0..3).map(|j| a[(i, j)] * x[j] + b[(i, j)] * z[j]).sum())
            .collect();
        assert_eq!(mat_vec2(&a, &x, &b, &z), want);
        let ax: Vec<f64> = (0..3).map(|i| (0..3).map(|j| a[(i, j)] * x[j]).sum()).collect();
        assert_eq!(mat_vec(&a, &x), ax);
    }

    /// The in-place LU solves what faer's `PartialPivLu` solves, on both sides of
    /// [`PARALLEL_LU_MIN`], for a nonsymmetric matrix that needs pivoting (zero diagonal in
    /// its first row): the residual A x − b is at round-off of ‖A‖‖x‖.
    #[test]
    fn in_place_lu_solves_like_faer() {
        use faer::linalg::solvers::Solve;
        for n in [7, PARALLEL_LU_MIN + 5] {
            let a = Mat::from_fn(n, n, |i, j| {
                let v = ((i * 7 + j * 13) % 17) as f64 / 17.0 - 0.5;
                if i == j && i > 0 {
                    v + 4.0
                } else if i == 0 && j == 0 {
                    0.0
                } else {
                    v / n as f64
                }
            });
            let b = Mat::from_fn(n, 1, |i, _| (i as f64).sin());
            let mut x = b.clone();
            lu_solve_in_place(a.clone(), x.as_mut());
            let mut reference = b.clone();
            a.partial_piv_lu().solve_in_place(reference.as_mut());
            let r = &a * &x - &b;
            let scale = a.norm_max() * x.norm_max() * n as f64;
            assert!(r.norm_max() <= 1e-14 * scale, "n {n}: residual {:e}", r.norm_max());
            let diff = (&x - &reference).norm_max();
            assert!(
                diff <= 1e-12 * reference.norm_max(),
                "n {n}: differs from faer by {diff:e}"
            );
        }
    }
}
