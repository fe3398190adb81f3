//! Error norms of nodal values against a reference, over the nodes inside a contact.
//!
//! The RMS is weighted by the length each node stands for (half the distance to each
//! neighbour, [`node_lengths`]): on a uniform grid that is the plain RMS, on a graded one it is
//! the L2 norm of the error over the contact, not a count dominated by the clustered nodes.

use serde::Serialize;

/// The largest and the root-mean-square nodal error over a set of nodes [same unit as the
/// errors]. Both are NaN when the set is empty.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct ErrorNorms {
    /// max_i e_i.
    pub max: f64,
    /// √(Σ w_i e_i² / Σ w_i), w_i the length node i stands for.
    pub rms: f64,
}

/// The length each node stands for [length]: half the distance to each neighbour (to its one
/// neighbour at the ends of the row); `x` increasing.
pub fn node_lengths(x: &[f64]) -> Vec<f64> {
    let n = x.len();
    (0..n)
        .map(|i| {
            let left = if i > 0 { x[i] - x[i - 1] } else { 0.0 };
            let right = if i + 1 < n { x[i + 1] - x[i] } else { 0.0 };
            0.5 * (left + right)
        })
        .collect()
}

/// The norms of the errors `error_at(i)` over the nodes i with |x_i| < `half_width` (e.g.
/// |p_i − p_Hertz(x_i)| / p0 inside the Hertz contact).
pub fn nodal_error(x: &[f64], half_width: f64, error_at: impl Fn(usize) -> f64) -> ErrorNorms {
    let w = node_lengths(x);
    let inside: Vec<usize> = (0..x.len()).filter(|&i| x[i].abs() < half_width).collect();
    if inside.is_empty() {
        return ErrorNorms {
            max: f64::NAN,
            rms: f64::NAN,
        };
    }
    let e: Vec<f64> = inside.iter().map(|&i| error_at(i)).collect();
    let length: f64 = inside.iter().map(|&i| w[i]).sum();
    let sum: f64 = inside.iter().zip(&e).map(|(&i, v)| w[i] * v * v).sum();
    ErrorNorms {
        max: e.iter().copied().fold(0.0_f64, f64::max),
        rms: (sum / length).sqrt(),
    }
}

/// The norms of |values_i − exact(x_i)| / scale over the nodes with |x_i| < `half_width`.
pub fn nodal_error_against(
    x: &[f64],
    values: &[f64],
    exact: impl Fn(f64) -> f64,
    half_width: f64,
    scale: f64,
) -> ErrorNorms {
    nodal_error(x, half_width, |i| (values[i] - exact(x[i])).abs() / scale)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn norms_of_known_errors_over_the_inner_nodes() {
        let x = [-2.0, -0.5, 0.0, 0.5, 2.0];
        let values = [9.0, 1.0, 0.0, -2.0, 9.0];
        // Errors 1, 0, 2 inside |x| < 1 standing for lengths 1, 0.5, 1; the outer nodes
        // (error 9) are left out: RMS √((1 + 4)/2.5).
        let e = nodal_error_against(&x, &values, |_| 0.0, 1.0, 1.0);
        assert_eq!(e.max, 2.0);
        assert!((e.rms - 2.0_f64.sqrt()).abs() < 1e-15);
        let scaled = nodal_error_against(&x, &values, |_| 0.0, 1.0, 2.0);
        assert_eq!(scaled.max, 1.0);
        assert_eq!(nodal_error(&x, 0.1, |i| i as f64).max, 2.0);
        assert!(nodal_error(&x, 0.0, |_| 1.0).rms.is_nan());
    }

    #[test]
    fn on_equally_spaced_nodes_the_weighted_rms_is_the_plain_rms() {
        let x: Vec<f64> = (0..21).map(|i| -1.0 + 0.1 * i as f64).collect();
        let e = |i: usize| (i as f64 * 0.37).sin();
        let inside: Vec<usize> = (0..21).filter(|&i| x[i].abs() < 0.75).collect();
        let plain = (inside.iter().map(|&i| e(i) * e(i)).sum::<f64>() / inside.len() as f64).sqrt();
        assert!((nodal_error(&x, 0.75, e).rms - plain).abs() < 1e-14);
    }
}
