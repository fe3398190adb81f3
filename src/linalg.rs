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
}
