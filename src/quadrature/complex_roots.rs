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
    let scale = c0.norm().max(c1.norm()).max(c2.norm());
    if scale == 0.0 {
        return r;
    }
    if c2.norm() <= 1e-14 * scale {
        if c1.norm() > 1e-14 * scale {
            r.push(-c0 / c1);
        }
        return r;
    }
    let disc = (c1 * c1 - c2 * c0 * 4.0).sqrt();
    // Numerically stable pair: q = −(c1 + sgn·disc)/2, roots q/c2 and c0/q.
    let q = if (c1.conj() * disc).re >= 0.0 {
        -(c1 + disc) * 0.5
    } else {
        -(c1 - disc) * 0.5
    };
    r.push(q / c2);
    if q.norm() > 0.0 {
        r.push(c0 / q);
    }
    r
}
