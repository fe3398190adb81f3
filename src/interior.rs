//! Stresses inside a half-space body under the contact tractions (Flamant superposition).
//!
//! For a half-plane z ≥ 0 (z into the body) loaded on its surface by a pressure p(s) ≥ 0 and a
//! shear q(s) on the body in +x (reference sheet §7, Johnson §2.2), with r² = (x−s)² + z²:
//!
//! ```text
//! σx  = −(2/π) ∫ [p (x−s)² z + q (x−s)³] / r⁴ ds
//! σz  = −(2/π) ∫ [p z³ + q (x−s) z²] / r⁴ ds
//! τxz = −(2/π) ∫ [p (x−s) z² + q (x−s)² z] / r⁴ ds
//! ```
//!
//! stresses positive in tension; plane strain σ_out = ν(σx + σz). The tractions are the grid's
//! interpolants. The kernel peaks over a width ~z around s = x, so each element is split into
//! pieces no longer than z/2 before 8-point Gauss quadrature: accurate down to depths of a small
//! fraction of an element (tested against McEwen's closed form).

use crate::grid::ContactGrid;
use crate::quadrature::gauss_legendre;

/// Plane-strain stress at a point [stress]: in-plane σx, σz (z into the body), τxz, and the
/// out-of-plane σy = ν(σx + σz).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PlaneStress {
    /// σ along the surface.
    pub sxx: f64,
    /// σ normal to the surface (z into the body).
    pub szz: f64,
    /// Shear τxz.
    pub txz: f64,
    /// Out-of-plane σ (plane strain).
    pub syy: f64,
}

impl PlaneStress {
    /// Principal shear stress τ1 = √(((σx − σz)/2)² + τxz²) [stress].
    pub fn max_shear(&self) -> f64 {
        (0.25 * (self.sxx - self.szz).powi(2) + self.txz * self.txz).sqrt()
    }

    /// von Mises equivalent stress with the plane-strain σy [stress].
    pub fn von_mises(&self) -> f64 {
        let (a, b, c) = (self.sxx, self.szz, self.syy);
        (0.5 * ((a - b).powi(2) + (b - c).powi(2) + (c - a).powi(2)) + 3.0 * self.txz * self.txz).sqrt()
    }
}

/// Stress at (x, z), z > 0 the depth into the body, under the nodal pressure `p` and shear `q`
/// acting on the body (its own +x), interpolated on `grid`; Poisson's ratio `nu`.
pub fn halfplane_stress(grid: &ContactGrid, p: &[f64], q: &[f64], nu: f64, x: f64, z: f64) -> PlaneStress {
    let (gx, gw) = gauss_legendre(8);
    let (mut sx, mut sz, mut t) = (0.0, 0.0, 0.0);
    for e in 0..grid.n_elements() {
        let (a, b) = (grid.edges[e], grid.edges[e + 1]);
        let pieces = ((b - a) / (0.5 * z)).ceil().clamp(1.0, 4096.0) as usize;
        let h = (b - a) / pieces as f64;
        for k in 0..pieces {
            let (lo, hi) = (a + k as f64 * h, a + (k + 1) as f64 * h);
            for (xi, w) in gx.iter().zip(&gw) {
                let s = 0.5 * (lo + hi) + 0.5 * (hi - lo) * xi;
                let ds = 0.5 * (hi - lo) * w;
                let (ps, qs) = (grid.interpolate(p, s), grid.interpolate(q, s));
                if ps == 0.0 && qs == 0.0 {
                    continue;
                }
                let d = x - s;
                let r4 = (d * d + z * z).powi(2);
                sx += (ps * d * d * z + qs * d * d * d) / r4 * ds;
                sz += (ps * z * z * z + qs * d * z * z) / r4 * ds;
                t += (ps * d * z * z + qs * d * d * z) / r4 * ds;
            }
        }
    }
    let c = -2.0 / std::f64::consts::PI;
    let (sxx, szz, txz) = (c * sx, c * sz, c * t);
    PlaneStress {
        sxx,
        szz,
        txz,
        syy: nu * (sxx + szz),
    }
}

/// Interior stresses on a grid of points in the contact frame, for output.
#[derive(Debug, Clone)]
pub struct InteriorField {
    /// `A` or `B`.
    pub body: String,
    /// Points (x, y) in the contact frame, x fastest [length].
    pub points: Vec<[f64; 2]>,
    /// Number of points along x and y.
    pub shape: [usize; 2],
    /// (σxx, σyy, σzz, τxy) in the contact frame, σzz the plane-strain out-of-plane stress
    /// [stress, tension positive].
    pub stress: Vec<[f64; 4]>,
}

/// Stresses of a half-space body on the grid [x0, x1, nx] × [y0, y1, ny] of the contact frame
/// (y > 0 inside A, y < 0 inside B) under the contact tractions (p, q on A; B sees −q).
pub fn interior_field(
    grid: &ContactGrid,
    p: &[f64],
    q: &[f64],
    nu: f64,
    body: &str,
    x: [f64; 3],
    y: [f64; 3],
) -> InteriorField {
    let (nx, ny) = (x[2] as usize, y[2] as usize);
    let b = body == "B";
    let q_body: Vec<f64> = q.iter().map(|v| if b { -v } else { *v }).collect();
    let mut points = Vec::with_capacity(nx * ny);
    let mut stress = Vec::with_capacity(nx * ny);
    for j in 0..ny {
        let yj = y[0] + (y[1] - y[0]) * j as f64 / (ny - 1) as f64;
        for i in 0..nx {
            let xi = x[0] + (x[1] - x[0]) * i as f64 / (nx - 1) as f64;
            let depth = if b { -yj } else { yj };
            let s = halfplane_stress(grid, p, &q_body, nu, xi, depth);
            // Local z is +y for A and −y for B: the shear changes sign with the axis.
            let txy = if b { -s.txz } else { s.txz };
            points.push([xi, yj]);
            stress.push([s.sxx, s.szz, s.syy, txy]);
        }
    }
    InteriorField {
        body: body.to_string(),
        points,
        shape: [nx, ny],
        stress,
    }
}

/// von Mises and principal shear of a (σxx, σyy, σzz, τxy) stress.
pub fn invariants(s: &[f64; 4]) -> (f64, f64) {
    let ps = PlaneStress {
        sxx: s[0],
        szz: s[1],
        syy: s[2],
        txz: s[3],
    };
    (ps.von_mises(), ps.max_shear())
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::grid::ElementKind;

    /// McEwen's closed form (reference sheet §7): Hertz pressure p0 = 1, a = 1 and the sliding
    /// shear q = μp. The tractions are interpolated from nodal values on 161 discontinuous
    /// quadratic elements whose edges include ±a, so the only error is the interpolation of the
    /// square root near the edges (≈ 1e-4 here).
    #[test]
    fn mcewen_reference_values() {
        let grid = ContactGrid::uniform(ElementKind::DiscontinuousQuadratic, 161, -1.3, 1.3);
        let p: Vec<f64> = grid.nodes.iter().map(|x| (1.0 - x * x).max(0.0).sqrt()).collect();
        let table = [
            (
                0.0,
                [
                    (0.0, 0.5, [-0.341641, -0.894427, 0.0]),
                    (0.4, 0.5, [-0.321820, -0.800008, -0.142156]),
                    (-0.8, 0.2, [-0.402105, -0.548635, 0.192451]),
                    (1.3, 0.4, [-0.252236, -0.076712, -0.125193]),
                ],
            ),
            (
                0.2,
                [
                    (0.0, 0.5, [-0.341641, -0.894427, -0.068328]),
                    (0.4, 0.5, [-0.377982, -0.828439, -0.206520]),
                    (-0.8, 0.2, [-0.215358, -0.510145, 0.112030]),
                    (1.3, 0.4, [-0.378713, -0.101751, -0.175640]),
                ],
            ),
        ];
        for (mu, points) in table {
            let q: Vec<f64> = p.iter().map(|v| mu * v).collect();
            for (x, z, [sx, sz, txz]) in points {
                let s = halfplane_stress(&grid, &p, &q, 0.3, x, z);
                for (got, want, name) in [(s.sxx, sx, "σx"), (s.szz, sz, "σz"), (s.txz, txz, "τxz")] {
                    assert!((got - want).abs() < 2e-3, "μ={mu} ({x}, {z}) {name}: {got} vs {want}");
                }
            }
        }
    }

    /// Hertz: max τ1 = 0.300283 p0 at depth 0.786151 a on the axis (reference sheet §7).
    #[test]
    fn hertz_maximum_shear_below_the_surface() {
        let grid = ContactGrid::uniform(ElementKind::DiscontinuousQuadratic, 161, -1.3, 1.3);
        let p: Vec<f64> = grid.nodes.iter().map(|x| (1.0 - x * x).max(0.0).sqrt()).collect();
        let q = vec![0.0; p.len()];
        let (mut best, mut at) = (0.0, 0.0);
        for k in 0..=200 {
            let z = 0.6 + 0.4 * k as f64 / 200.0;
            let t = halfplane_stress(&grid, &p, &q, 0.3, 0.0, z).max_shear();
            if t > best {
                best = t;
                at = z;
            }
        }
        assert!(
            (best / 0.300283 - 1.0).abs() < 0.02 && (at - 0.786151).abs() < 0.02,
            "τ1 = {best} at z = {at}"
        );
    }
}
