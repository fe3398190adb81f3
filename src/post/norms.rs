//! Error norms of nodal values against a reference, over the nodes inside a contact.

use serde::Serialize;

/// The largest and the root-mean-square nodal error over a set of nodes [same unit as the
/// errors]. Both are NaN when the set is empty.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct ErrorNorms {
    /// max_i e_i.
    pub max: f64,
    /// √(Σ e_i² / n).
    pub rms: f64,
}

/// The norms of the errors `error_at(i)` over the nodes i with |x_i| < `half_width` (e.g.
/// |p_i − p_Hertz(x_i)| / p0 inside the Hertz contact).
pub fn nodal_error(x: &[f64], half_width: f64, error_at: impl Fn(usize) -> f64) -> ErrorNorms {
    let e: Vec<f64> = (0..x.len())
        .filter(|&i| x[i].abs() < half_width)
        .map(error_at)
        .collect();
    if e.is_empty() {
        return ErrorNorms {
            max: f64::NAN,
            rms: f64::NAN,
        };
    }
    ErrorNorms {
        max: e.iter().copied().fold(0.0_f64, f64::max),
        rms: (e.iter().map(|v| v * v).sum::<f64>() / e.len() as f64).sqrt(),
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
        // Errors 1, 0, 2 inside |x| < 1; the outer nodes (error 9) are left out.
        let e = nodal_error_against(&x, &values, |_| 0.0, 1.0, 1.0);
        assert_eq!(e.max, 2.0);
        assert!((e.rms - (5.0_f64 / 3.0).sqrt()).abs() < 1e-15);
        let scaled = nodal_error_against(&x, &values, |_| 0.0, 1.0, 2.0);
        assert_eq!(scaled.max, 1.0);
        assert_eq!(nodal_error(&x, 0.1, |i| i as f64).max, 2.0);
        assert!(nodal_error(&x, 0.0, |_| 1.0).rms.is_nan());
    }
}
