//! Complex points where an integrand over a quadratic element is singular: the zeros of r² and
//! of the Jacobian, found exactly as roots of complex quadratics.

use super::QuadraticNodes;
use nalgebra::Complex;

/// Up to `N` complex numbers, without allocation.
#[derive(Debug, Clone, Copy)]
pub struct Few<const N: usize> {
    values: [Complex<f64>; N],
    len: usize,
}

impl<const N: usize> Default for Few<N> {
    fn default() -> Self {
        Self::new()
    }
}

impl<const N: usize> Few<N> {
    /// None yet.
    pub fn new() -> Self {
        Self {
            values: [Complex::new(0.0, 0.0); N],
            len: 0,
        }
    }

    /// Appends `z`; panics beyond `N` (a programming error: the callers know their count).
    pub fn push(&mut self, z: Complex<f64>) {
        self.values[self.len] = z;
        self.len += 1;
    }

    /// The numbers pushed so far.
    pub fn as_slice(&self) -> &[Complex<f64>] {
        &self.values[..self.len]
    }
}

/// Complex ξ where the integrand is singular: r² = 0 (roots of P±(ξ) = (x_x − X_x) ± i(x_y − X_y))
/// and J = 0 (roots of x'_x ± i x'_y), for the quadratic map x(ξ) = a + bξ + cξ².
pub fn complex_singularities(nodes: &QuadraticNodes, source: [f64; 2]) -> Few<6> {
    let [p0, p1, pm] = *nodes;
    // x(ξ) = pm + ξ (p1 − p0)/2 + ξ² ((p0 + p1)/2 − pm)
    let a = [pm[0] - source[0], pm[1] - source[1]];
    let b = [0.5 * (p1[0] - p0[0]), 0.5 * (p1[1] - p0[1])];
    let c = [0.5 * (p0[0] + p1[0]) - pm[0], 0.5 * (p0[1] + p1[1]) - pm[1]];
    let mut roots = Few::new();
    for sign in [1.0, -1.0] {
        let z = |v: [f64; 2]| Complex::new(v[0], sign * v[1]);
        for r in quadratic_roots(z(c), z(b), z(a)).as_slice() {
            roots.push(*r);
        }
        // J² = x'·x' = (x'_x + i x'_y)(x'_x − i x'_y), x' = b + 2cξ.
        for r in quadratic_roots(Complex::new(0.0, 0.0), z(c) * 2.0, z(b)).as_slice() {
            roots.push(*r);
        }
    }
    roots
}

/// Roots of c2 ξ² + c1 ξ + c0 (complex coefficients); degenerate leading terms drop roots.
pub fn quadratic_roots(c2: Complex<f64>, c1: Complex<f64>, c0: Complex<f64>) -> Few<2> {
    let mut r = Few::new();
    let scale = modulus(c0).max(modulus(c1)).max(modulus(c2));
    if scale == 0.0 {
        return r;
    }
    if modulus(c2) <= 1e-14 * scale {
        if modulus(c1) > 1e-14 * scale {
            r.push(-c0 / c1);
        }
        return r;
    }
    let disc = principal_sqrt(c1 * c1 - c2 * c0 * 4.0);
    // Numerically stable pair: q = −(c1 + sgn·disc)/2, roots q/c2 and c0/q.
    let q = if (c1.conj() * disc).re >= 0.0 {
        -(c1 + disc) * 0.5
    } else {
        -(c1 - disc) * 0.5
    };
    r.push(q / c2);
    if modulus(q) > 0.0 {
        r.push(c0 / q);
    }
    r
}

/// |z| as √(z·z̄): `Complex::norm` calls `hypot`, several times slower, and the coefficients
/// here (differences of mesh coordinates) are far from over- and underflow.
#[inline]
fn modulus(z: Complex<f64>) -> f64 {
    z.norm_sqr().sqrt()
}

/// The principal square root of z (Re ≥ 0), algebraically: `Complex::sqrt` goes through the
/// polar form (hypot, atan2 and sincos). The half-sum is taken on the side where it does not
/// cancel: √((|z| + |x|)/2) on the real or the imaginary part by the sign of x = Re z.
#[inline]
fn principal_sqrt(z: Complex<f64>) -> Complex<f64> {
    let m = modulus(z);
    if m == 0.0 {
        return Complex::new(0.0, 0.0);
    }
    let t = (0.5 * (m + z.re.abs())).sqrt();
    if z.re >= 0.0 {
        Complex::new(t, 0.5 * z.im / t)
    } else {
        Complex::new(0.5 * z.im.abs() / t, t.copysign(z.im))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The algebraic square root is num-complex's polar one to round-off, on every side of
    /// the branch cut (the negative real axis, with either sign of zero) and at scales from
    /// 1e-12 to 1e12.
    #[test]
    fn principal_sqrt_is_the_polar_square_root() {
        for scale in [1e-12, 1e-3, 1.0, 1e5, 1e12] {
            for (re, im) in [
                (1.0, 0.0),
                (-1.0, 0.0),
                (-1.0, -0.0),
                (0.0, 1.0),
                (0.0, -1.0),
                (3.0, 4.0),
                (-3.0, 4.0),
                (-3.0, -4.0),
                (1e-9, -1.0),
                (-1.0, 1e-9),
                (-1.0, -1e-9),
            ] {
                let z = Complex::new(re * scale, im * scale);
                let (ours, polar) = (principal_sqrt(z), z.sqrt());
                assert!(
                    (ours - polar).norm() <= 1e-15 * polar.norm(),
                    "sqrt({z}) = {ours}, polar {polar}"
                );
                assert!(ours.re >= 0.0);
            }
        }
        assert_eq!(principal_sqrt(Complex::new(0.0, 0.0)), Complex::new(0.0, 0.0));
    }

    /// Both roots of a complex quadratic satisfy it to round-off, also when one is tiny
    /// against the other (the stable pair), and a vanishing leading term leaves the linear root.
    #[test]
    fn quadratic_roots_solve_the_quadratic() {
        let c = |re, im| Complex::new(re, im);
        for (c2, c1, c0) in [
            (c(1.0, 0.0), c(-3.0, 0.0), c(2.0, 0.0)),
            (c(1.0, 0.5), c(0.2, -1.0), c(3.0, 2.0)),
            (c(1.0, 0.0), c(1e8, 0.0), c(1.0, 0.0)),
            (c(0.0, 2.0), c(1.0, 1.0), c(-1.0, 0.0)),
            (c(1.0, 0.0), c(0.0, 0.0), c(4.0, 0.0)),
        ] {
            let roots = quadratic_roots(c2, c1, c0);
            assert_eq!(roots.as_slice().len(), 2);
            for &x in roots.as_slice() {
                let value = c2 * x * x + c1 * x + c0;
                let size = (c2 * x * x).norm() + (c1 * x).norm() + c0.norm();
                assert!(value.norm() <= 1e-14 * size, "{c2}ξ² + {c1}ξ + {c0} at {x}: {value}");
            }
        }
        let linear = quadratic_roots(c(0.0, 0.0), c(2.0, 0.0), c(-1.0, 0.0));
        assert_eq!(linear.as_slice(), &[c(0.5, 0.0)]);
    }
}
