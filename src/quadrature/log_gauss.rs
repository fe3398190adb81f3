//! Gauss rules for the logarithmic weight ln(1/t) on [0, 1].

/// n-point Gauss rule for ∫₀¹ f(t) ln(1/t) dt, exact for polynomials of degree 2n − 1.
///
/// Recurrence coefficients by Gautschi's modified Chebyshev algorithm (*Orthogonal
/// Polynomials: Computation and Approximation*, 2004, Alg. 2.1) from the modified moments on
/// the shifted Legendre polynomials, ∫₀¹ P*_k(t) ln(1/t) dt = (−1)^k/(k(k+1)) (k ≥ 1, and 1 for
/// k = 0) — well conditioned, unlike ordinary moments — then Golub–Welsch.
pub fn log_gauss(n: usize) -> (Vec<f64>, Vec<f64>) {
    let m2 = 2 * n;
    // Monic shifted Legendre: π_{k+1} = (t − ½) π_k − b_k π_{k−1}, b_k = k²/(4(4k² − 1)).
    let a_rec = vec![0.5; m2];
    let b_rec: Vec<f64> = (0..m2)
        .map(|k| {
            let k = k as f64;
            if k == 0.0 {
                1.0
            } else {
                k * k / (4.0 * (4.0 * k * k - 1.0))
            }
        })
        .collect();
    // Modified moments of the monic polynomials: P*_k has leading coefficient (2k)!/(k!)².
    let moments: Vec<f64> = (0..m2)
        .map(|k| {
            if k == 0 {
                return 1.0;
            }
            let mut lead = 1.0;
            for j in 1..=k {
                lead *= (k + j) as f64 / j as f64;
            }
            let sign = if k % 2 == 0 { 1.0 } else { -1.0 };
            sign / ((k * (k + 1)) as f64) / lead
        })
        .collect();
    let mut alpha = vec![0.0; n];
    let mut beta = vec![0.0; n];
    let mut sigma_prev = vec![0.0; m2]; // σ_{k−2, ·}
    let mut sigma = moments.clone(); // σ_{k−1, ·}
    alpha[0] = a_rec[0] + moments[1] / moments[0];
    beta[0] = moments[0];
    for k in 1..n {
        let mut next = vec![0.0; m2];
        for l in k..(m2 - k) {
            next[l] = sigma[l + 1] - (alpha[k - 1] - a_rec[l]) * sigma[l] - beta[k - 1] * sigma_prev[l]
                + b_rec[l] * sigma[l - 1];
        }
        alpha[k] = a_rec[k] + next[k + 1] / next[k] - sigma[k] / sigma[k - 1];
        beta[k] = next[k] / sigma[k - 1];
        sigma_prev = sigma;
        sigma = next;
    }
    let jacobi = nalgebra::DMatrix::from_fn(n, n, |i, j| {
        if i == j {
            alpha[i]
        } else if i + 1 == j || j + 1 == i {
            beta[i.max(j)].sqrt()
        } else {
            0.0
        }
    });
    let eig = nalgebra::SymmetricEigen::new(jacobi);
    let mut pairs: Vec<(f64, f64)> = (0..n)
        .map(|i| (eig.eigenvalues[i], beta[0] * eig.eigenvectors[(0, i)].powi(2)))
        .collect();
    pairs.sort_by(|p, q| p.0.total_cmp(&q.0));
    pairs.into_iter().unzip()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn log_gauss_matches_the_references_and_integrates_log_moments() {
        // Stroud & Secrest, Gaussian Quadrature Formulas (1966), for n = 2.
        let (t, w) = log_gauss(2);
        assert!((t[0] - 0.112008806166976).abs() < 1e-13 && (t[1] - 0.602276908118738).abs() < 1e-13);
        assert!((w[0] - 0.718539319030384).abs() < 1e-13 && (w[1] - 0.281460680969616).abs() < 1e-13);
        let (t, w) = log_gauss(8);
        assert!((t[0] - 0.013320244160892).abs() < 1e-13 && (t[7] - 0.953326450056360).abs() < 1e-13);
        assert!((w[0] - 0.164416604728003).abs() < 1e-13 && (w[7] - 0.003686407104028).abs() < 1e-13);
        // ∫₀¹ t^k ln(1/t) dt = 1/(k+1)², exact up to degree 2n − 1.
        for n in [3, 6, 12, 16] {
            let (t, w) = log_gauss(n);
            for k in 0..(2 * n) {
                let q: f64 = t.iter().zip(&w).map(|(t, w)| w * t.powi(k as i32)).sum();
                let exact = 1.0 / ((k + 1) * (k + 1)) as f64;
                assert!(
                    (q - exact).abs() < 1e-13 * exact.max(1e-3),
                    "n={n} k={k}: {q} vs {exact}"
                );
            }
        }
    }
}
