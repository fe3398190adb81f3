//! Fields inside a half-plane body under the contact tractions: the Flamant / Boussinesq–Cerruti
//! line-load superposition, the interior fields of the [`super::half_space`] model.
//!
//! For a half-plane z ≥ 0 (z into the body) loaded on its surface by a pressure p(s) ≥ 0 and a
//! shear q(s) on the body in +x (docs/references.md §7, Johnson §2.2), with d = x − s,
//! r² = d² + z², θ = atan2(d, z) the angle from the inward normal:
//!
//! ```text
//! σx  = −(2/π) ∫ [p d² z + q d³] / r⁴ ds                                     (sheet §7)
//! σz  = −(2/π) ∫ [p z³ + q d z²] / r⁴ ds
//! τxz = −(2/π) ∫ [p d z² + q d² z] / r⁴ ds
//! u_x = (1/(2πG)) ∫ { p [d z/r² − (1−2ν) θ] − q [z²/r² + 2(1−ν) ln(r/ℓ)] } ds   (H1)
//! u_z = (1/(2πG)) ∫ { p [z²/r² − 2(1−ν) ln(r/ℓ)] + q [d z/r² + (1−2ν) θ] } ds   (H2)
//! ```
//!
//! stresses positive in tension; plane strain σ_out = ν(σx + σz). (H1, H2) are the plane-strain
//! displacements of the Flamant fields (integrate the strains of the radial stress
//! σ_rr = −2(P cos θ + Q sin θ)/(πr) in polar coordinates; checked against Hooke's law in the
//! tests), with the rigid translation chosen so that on the surface z = 0 they are exactly the
//! half-space model's surface displacements, u_x = −A∫p sgn − B∫q ln(|x−s|/ℓ) and
//! u_z = −B∫p ln(|x−s|/ℓ) + A∫q sgn (docs/references.md §3.1), with the model's datum length ℓ
//! ([`super::half_space::HalfSpace::datum_length`]). Displacements of a half-plane are
//! defined only up to that datum (a rigid translation); their differences are physical.
//!
//! The tractions are the grid's interpolants. The kernels vary over a length r = √(d² + z²),
//! so each element is split into pieces no longer than half the distance from the field point
//! to the element (at least z/2) before 8-point Gauss quadrature: accurate down to depths of a
//! small fraction of an element (tested against McEwen's closed form), while the elements far
//! from the point, where the kernels are smooth, take one piece.

use super::{ContactLoad, Side};
use crate::grid::ContactGrid;
use crate::interior::{InteriorOptions, InteriorSample, InteriorValue, PlaneStress};
use crate::quadrature::gauss_legendre;
use rayon::prelude::*;
use std::f64::consts::PI;

/// The tractions of a contact grid at its quadrature points: one 8-point Gauss rule per
/// element, interpolated once for every field point far from the element; elements near a
/// field point are subdivided for it ([`TractionQuadrature::visit`]).
pub struct TractionQuadrature<'a> {
    grid: &'a ContactGrid,
    p: &'a [f64],
    q: &'a [f64],
    /// Per element: (s, ds, p(s), q(s)) at its 8 Gauss points.
    whole: Vec<[[f64; 4]; 8]>,
    /// Per element with its mid node at its centre: p and q as polynomials c0 + c1 ξ + c2 ξ²
    /// of the element's ξ ∈ [−1, 1] (the pieces of a subdivided element read them instead of
    /// searching the grid for every Gauss point).
    polynomials: Vec<Option<[[f64; 3]; 2]>>,
}

/// The Gauss rule of the superposition: 8 points per element or piece.
const GAUSS_POINTS: usize = 8;

impl<'a> TractionQuadrature<'a> {
    /// The quadrature of the nodal pressure `p` and shear `q` on `grid`.
    pub fn new(grid: &'a ContactGrid, p: &'a [f64], q: &'a [f64]) -> Self {
        let polynomials: Vec<_> = (0..grid.n_elements())
            .map(|e| {
                let centred = grid.mids[e] == 0.5 * (grid.edges[e] + grid.edges[e + 1]);
                centred.then(|| {
                    let mut c = [[0.0; 3]; 2];
                    for a in 0..grid.kind.nodes_per_element() {
                        let (n, j) = (grid.kind.shape_polynomial(a), grid.global_node(e, a));
                        for k in 0..3 {
                            c[0][k] += n[k] * p[j];
                            c[1][k] += n[k] * q[j];
                        }
                    }
                    c
                })
            })
            .collect();
        let mut out = Self {
            grid,
            p,
            q,
            whole: Vec::new(),
            polynomials,
        };
        out.whole = (0..grid.n_elements())
            .map(|e| {
                let mut pts = [[0.0; 4]; 8];
                out.piece(e, grid.edges[e], grid.edges[e + 1], |k, v| pts[k] = v);
                pts
            })
            .collect();
        out
    }

    /// The Gauss points of [lo, hi] ⊂ element `e` as (s, ds, p(s), q(s)), with their index.
    fn piece(&self, e: usize, lo: f64, hi: f64, mut out: impl FnMut(usize, [f64; 4])) {
        let (gx, gw) = gauss_legendre(GAUSS_POINTS);
        let (a, b) = (self.grid.edges[e], self.grid.edges[e + 1]);
        for (k, (xi, w)) in gx.iter().zip(&gw).enumerate() {
            let s = 0.5 * (lo + hi) + 0.5 * (hi - lo) * xi;
            let ds = 0.5 * (hi - lo) * w;
            let (ps, qs) = match &self.polynomials[e] {
                Some([cp, cq]) => {
                    let t = (2.0 * s - a - b) / (b - a);
                    (cp[0] + t * (cp[1] + t * cp[2]), cq[0] + t * (cq[1] + t * cq[2]))
                }
                None => (self.grid.interpolate(self.p, s), self.grid.interpolate(self.q, s)),
            };
            out(k, [s, ds, ps, qs]);
        }
    }

    /// Visits the quadrature points (s, ds, p(s), q(s)) for a field point (x, z), z the depth
    /// (points where both tractions vanish are skipped; module docs for the subdivision).
    fn visit(&self, x: f64, z: f64, mut visit: impl FnMut(f64, f64, f64, f64)) {
        let mut take = |v: [f64; 4]| {
            if v[2] != 0.0 || v[3] != 0.0 {
                visit(v[0], v[1], v[2], v[3]);
            }
        };
        for (e, whole) in self.whole.iter().enumerate() {
            let (a, b) = (self.grid.edges[e], self.grid.edges[e + 1]);
            let distance = (a - x).max(x - b).max(0.0).max(z);
            let pieces = ((b - a) / (0.5 * distance)).ceil().clamp(1.0, 4096.0) as usize;
            if pieces == 1 {
                whole.iter().for_each(|v| take(*v));
                continue;
            }
            let h = (b - a) / pieces as f64;
            for k in 0..pieces {
                let lo = a + k as f64 * h;
                self.piece(e, lo, lo + h, |_, v| take(v));
            }
        }
    }

    /// Stress at (x, z), z > 0 the depth into the body, Poisson's ratio `nu` (sheet §7).
    pub fn stress(&self, nu: f64, x: f64, z: f64) -> PlaneStress {
        let (mut sx, mut sz, mut t) = (0.0, 0.0, 0.0);
        self.visit(x, z, |s, ds, ps, qs| {
            let d = x - s;
            let r4 = (d * d + z * z).powi(2);
            sx += (ps * d * d * z + qs * d * d * d) / r4 * ds;
            sz += (ps * z * z * z + qs * d * z * z) / r4 * ds;
            t += (ps * d * z * z + qs * d * d * z) / r4 * ds;
        });
        let c = -2.0 / PI;
        let (sxx, szz, txz) = (c * sx, c * sz, c * t);
        PlaneStress {
            sxx,
            szz,
            txz,
            syy: nu * (sxx + szz),
        }
    }

    /// Displacement (u_x, u_z) [length] at (x, z) of a half-plane of shear modulus `shear`
    /// and Poisson's ratio `nu`, from the datum length `datum` (Eq. H1–H2).
    pub fn displacement(&self, shear: f64, nu: f64, datum: f64, x: f64, z: f64) -> [f64; 2] {
        let (mut ux, mut uz) = (0.0, 0.0);
        self.visit(x, z, |s, ds, ps, qs| {
            let [kp, kq] = line_load_displacement(x - s, z, nu, datum);
            ux += (ps * kp[0] + qs * kq[0]) * ds;
            uz += (ps * kp[1] + qs * kq[1]) * ds;
        });
        let c = 1.0 / (2.0 * PI * shear);
        [c * ux, c * uz]
    }
}

/// Stress at (x, z), z > 0 the depth into the body, under the nodal pressure `p` and shear `q`
/// acting on the body (its own +x), interpolated on `grid`; Poisson's ratio `nu`.
pub fn halfplane_stress(grid: &ContactGrid, p: &[f64], q: &[f64], nu: f64, x: f64, z: f64) -> PlaneStress {
    TractionQuadrature::new(grid, p, q).stress(nu, x, z)
}

/// The line-load displacement kernels of Eq. H1–H2 without the factor 1/(2πG):
/// `[[u_x, u_z] of a unit pressure, [u_x, u_z] of a unit shear]` at offset d = x − s, depth z.
fn line_load_displacement(d: f64, z: f64, nu: f64, datum: f64) -> [[f64; 2]; 2] {
    let r2 = d * d + z * z;
    let (dz, zz) = (d * z / r2, z * z / r2);
    let theta = d.atan2(z);
    let log = 0.5 * (r2 / (datum * datum)).ln();
    [
        [dz - (1.0 - 2.0 * nu) * theta, zz - 2.0 * (1.0 - nu) * log],
        [-(zz + 2.0 * (1.0 - nu) * log), dz + (1.0 - 2.0 * nu) * theta],
    ]
}

/// Displacement (u_x, u_z) [length] at (x, z), z > 0 the depth, of a half-plane of shear modulus
/// `shear` and Poisson's ratio `nu` under the nodal `p` and `q` (as [`halfplane_stress`]),
/// measured from the datum length `datum` [length] (module docs, Eq. H1–H2).
#[allow(clippy::too_many_arguments)]
pub fn halfplane_displacement(
    grid: &ContactGrid,
    p: &[f64],
    q: &[f64],
    shear: f64,
    nu: f64,
    datum: f64,
    x: f64,
    z: f64,
) -> [f64; 2] {
    TractionQuadrature::new(grid, p, q).displacement(shear, nu, datum, x, z)
}

/// Fields of a half-plane body at `points` of the contact frame (y > 0 inside A, y < 0 inside
/// B) under the contact load (p on both bodies, q on A; B receives −q), for the
/// material (`shear`, `nu`) and the displacement datum `datum` (module docs).
///
/// Each body is its own half-plane z ≥ 0 with z into the body: z = y for A, z = −y for B (a
/// mirror image, x unchanged), loaded by its own shear (q on A, −q on B). Back in the contact
/// frame, u_y = u_z on A and −u_z on B, τxy = τxz on A and −τxz on B. Points with z below
/// `boundary_layer` × the grid's element length are [`InteriorSample::Boundary`], points with
/// z < 0 [`InteriorSample::Outside`].
pub fn halfplane_interior(
    load: &ContactLoad,
    shear: f64,
    nu: f64,
    datum: f64,
    side: Side,
    points: &[[f64; 2]],
    options: &InteriorOptions,
) -> Vec<InteriorSample> {
    let (grid, p, q) = (load.grid, load.pressure, load.shear);
    let sign = side.sign();
    let q_body: Vec<f64> = q.iter().map(|v| sign * v).collect();
    let layer = options.boundary_layer * grid.element_length();
    let tractions = TractionQuadrature::new(grid, p, &q_body);
    points
        .par_iter()
        .map(|&[x, y]| {
            let z = sign * y;
            if z < 0.0 {
                return InteriorSample::Outside;
            }
            if z <= layer {
                return InteriorSample::Boundary;
            }
            let s = tractions.stress(nu, x, z);
            let [ux, uz] = if options.displacements {
                tractions.displacement(shear, nu, datum, x, z)
            } else {
                [0.0; 2]
            };
            InteriorSample::Inside(InteriorValue {
                displacement: [ux, sign * uz],
                stress: [s.sxx, s.szz, s.syy, sign * s.txz],
            })
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::grid::ElementKind;

    /// McEwen's closed form (docs/references.md §7): Hertz pressure p0 = 1, a = 1 and the sliding
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

    /// Hertz: max τ1 = 0.300283 p0 at depth 0.786151 a on the axis (docs/references.md §7).
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

    /// Eq. H1–H2 are the displacements of the Flamant stresses: central differences of the
    /// line-load displacement through plane-strain Hooke's law give the sheet's §7 point-load
    /// stresses (step 1e-6 at r ~ 1: error ~1e-9 of the stress).
    #[test]
    fn line_load_displacements_have_the_flamant_stresses() {
        let (g, datum) = (80_000.0, 3.7);
        for nu in [0.0, 0.3, 0.45] {
            let lambda = 2.0 * g * nu / (1.0 - 2.0 * nu);
            for (d, z) in [(0.3, 0.5), (-1.2, 0.2), (0.05, 1.4), (2.0, 0.01)] {
                let h = 1e-6;
                let u = |d: f64, z: f64| {
                    let k = line_load_displacement(d, z, nu, datum);
                    k.map(|row| row.map(|v| v / (2.0 * PI * g)))
                };
                // ∂u/∂x = ∂u/∂d at fixed s.
                let (xp, xm, zp, zm) = (u(d + h, z), u(d - h, z), u(d, z + h), u(d, z - h));
                for load in 0..2 {
                    let exx = (xp[load][0] - xm[load][0]) / (2.0 * h);
                    let ezz = (zp[load][1] - zm[load][1]) / (2.0 * h);
                    let gxz = (zp[load][0] - zm[load][0] + xp[load][1] - xm[load][1]) / (2.0 * h);
                    let sxx = lambda * (exx + ezz) + 2.0 * g * exx;
                    let szz = lambda * (exx + ezz) + 2.0 * g * ezz;
                    let txz = g * gxz;
                    let r4 = (d * d + z * z).powi(2);
                    let c = -2.0 / PI / r4;
                    let (p, q) = if load == 0 { (1.0, 0.0) } else { (0.0, 1.0) };
                    let exact = [
                        c * (p * d * d * z + q * d * d * d),
                        c * (p * z * z * z + q * d * z * z),
                        c * (p * d * z * z + q * d * d * z),
                    ];
                    let scale = exact.iter().fold(0.0f64, |m, v| m.max(v.abs()));
                    for (got, want) in [sxx, szz, txz].iter().zip(exact) {
                        assert!(
                            (got - want).abs() < 1e-6 * scale,
                            "nu={nu} ({d}, {z}) load {load}: {got} vs {want}"
                        );
                    }
                }
            }
        }
    }
}
