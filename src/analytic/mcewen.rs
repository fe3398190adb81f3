//! McEwen's stresses of a Hertz line contact under a sliding traction q = μp (Johnson,
//! *Contact Mechanics*, 1985, §7.1 eq. 7.23–7.26; McEwen 1949): the field Johnson's shakedown
//! map is drawn from, in units of p0 and a.

use crate::interior::PlaneStress;

/// The stresses at (x, z) [a], z ≥ 0 the depth, of a Hertz pressure of peak 1 and half-width
/// 1 with the shear q = μp on the body in +x; tension positive, plane strain σy = ν(σx + σz).
/// With m, n the real and imaginary parts of √((x + iz)² − 1) taken with m ≥ 0 and n of the
/// sign of x:
///
/// ```text
/// σx  = −m (1 + (z² + n²)/(m² + n²)) + 2z + μ [n (2 − (z² − m²)/(m² + n²)) − 2x]
/// σz  = −m (1 − (z² + n²)/(m² + n²)) − μ n (m² − z²)/(m² + n²)
/// τxz = −n (m² − z²)/(m² + n²) − μ [m (1 + (z² + n²)/(m² + n²)) − 2z]
/// ```
pub fn sliding_hertz_stress(x: f64, z: f64, mu: f64, nu: f64) -> PlaneStress {
    let b = 1.0 - x * x + z * z;
    let r = (b * b + 4.0 * x * x * z * z).sqrt();
    let m = (0.5 * (r + b)).max(0.0).sqrt();
    let n = (0.5 * (r - b)).max(0.0).sqrt().copysign(x);
    // At the contact's edges on the surface m = n = 0: the ratios' limit there is 0.
    let d = (m * m + n * n).max(1e-300);
    let ratio = (z * z + n * n) / d;
    let sxx = -(m * (1.0 + ratio) - 2.0 * z) + mu * (n * (2.0 - (z * z - m * m) / d) - 2.0 * x);
    let szz = -m * (1.0 - ratio) - mu * n * (m * m - z * z) / d;
    let txz = -n * (m * m - z * z) / d - mu * (m * (1.0 + ratio) - 2.0 * z);
    PlaneStress {
        sxx,
        szz,
        txz,
        syy: nu * (sxx + szz),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// On the surface: σz = −p, τxz = −μp, and inside the contact σx = −p − 2μx (Johnson eq.
    /// 7.19); under the centre of a frictionless contact σz = −p0/√(1 + z²) (eq. 4.49).
    #[test]
    fn the_field_meets_the_surface_tractions_and_the_axis_values() {
        for x in [-0.5, 0.0, 0.7] {
            let s = sliding_hertz_stress(x, 0.0, 0.4, 0.3);
            let p = (1.0f64 - x * x).sqrt();
            assert!((s.szz + p).abs() < 1e-12 && (s.txz + 0.4 * p).abs() < 1e-12, "{s:?}");
            assert!((s.sxx + p + 0.8 * x).abs() < 1e-12);
        }
        for z in [0.3, 0.78, 2.0] {
            let s = sliding_hertz_stress(0.0, z, 0.0, 0.3);
            assert!((s.szz + 1.0 / (1.0f64 + z * z).sqrt()).abs() < 1e-12, "{s:?}");
        }
    }
}
