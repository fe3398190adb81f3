//! Post-processing inside the bodies: displacement and stress at interior points.
//!
//! Every body model offers its own interior field through
//! [`crate::body::BodyModel::interior`]: the BEM by Somigliana's identity
//! ([`crate::bem::somigliana`]), the half-space by the Flamant / Boussinesq–Cerruti line-load
//! fields of this module, a rigid body none. This module holds what is common: the result of
//! one point ([`InteriorSample`]), the grid of points of `output.interior` ([`InteriorField`]),
//! the invariants written to the outputs, and the half-plane superposition.
//!
//! # Half-plane fields (Flamant superposition)
//! For a half-plane z ≥ 0 (z into the body) loaded on its surface by a pressure p(s) ≥ 0 and a
//! shear q(s) on the body in +x (reference sheet §7, Johnson §2.2), with d = x − s,
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
//! u_z = −B∫p ln(|x−s|/ℓ) + A∫q sgn (reference sheet §3.1), with the model's datum length ℓ
//! ([`crate::body::half_space::HalfSpace::datum_length`]). Displacements of a half-plane are
//! defined only up to that datum (a rigid translation); their differences are physical.
//!
//! The tractions are the grid's interpolants. The kernels peak over a width ~z around s = x, so
//! each element is split into pieces no longer than z/2 before 8-point Gauss quadrature:
//! accurate down to depths of a small fraction of an element (tested against McEwen's closed
//! form).

use crate::grid::ContactGrid;
use crate::quadrature::gauss_legendre;
use std::f64::consts::PI;

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

/// Visits the quadrature points (s, ds) of the contact grid for a field point at depth z, with
/// the interpolated tractions p(s), q(s) (points where both vanish are skipped).
fn superpose(grid: &ContactGrid, p: &[f64], q: &[f64], z: f64, mut visit: impl FnMut(f64, f64, f64, f64)) {
    let (gx, gw) = gauss_legendre(8);
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
                visit(s, ds, ps, qs);
            }
        }
    }
}

/// Stress at (x, z), z > 0 the depth into the body, under the nodal pressure `p` and shear `q`
/// acting on the body (its own +x), interpolated on `grid`; Poisson's ratio `nu`.
pub fn halfplane_stress(grid: &ContactGrid, p: &[f64], q: &[f64], nu: f64, x: f64, z: f64) -> PlaneStress {
    let (mut sx, mut sz, mut t) = (0.0, 0.0, 0.0);
    superpose(grid, p, q, z, |s, ds, ps, qs| {
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
    let (mut ux, mut uz) = (0.0, 0.0);
    superpose(grid, p, q, z, |s, ds, ps, qs| {
        let [kp, kq] = line_load_displacement(x - s, z, nu, datum);
        ux += (ps * kp[0] + qs * kq[0]) * ds;
        uz += (ps * kp[1] + qs * kq[1]) * ds;
    });
    let c = 1.0 / (2.0 * PI * shear);
    [c * ux, c * uz]
}

/// The fields at one interior point, in the contact frame.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct InteriorValue {
    /// Displacement (u_x, u_y) [length] (for a half-space: from its datum, see the module docs).
    pub displacement: [f64; 2],
    /// (σxx, σyy, σzz, τxy) [stress, tension positive], σzz = ν(σxx + σyy) out of plane.
    pub stress: [f64; 4],
}

/// The result of asking a body model for its fields at one point.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum InteriorSample {
    /// The point lies inside the body: its fields.
    Inside(InteriorValue),
    /// The point lies outside the body: nothing to evaluate.
    Outside,
    /// The point lies on the boundary or within the boundary layer
    /// ([`InteriorOptions::boundary_layer`]), where the interior formulas lose accuracy: not
    /// evaluated.
    Boundary,
}

/// Where each point of an [`InteriorField`] lies; written as `status` (CSV: the name; VTK:
/// the code 0 outside, 1 inside, 2 boundary).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum PointStatus {
    /// Not in the body; fields written as 0.
    Outside,
    /// Evaluated.
    Inside,
    /// On the boundary or within the boundary layer; fields written as 0.
    Boundary,
}

impl PointStatus {
    /// Name in the CSV.
    pub fn name(self) -> &'static str {
        match self {
            PointStatus::Outside => "outside",
            PointStatus::Inside => "inside",
            PointStatus::Boundary => "boundary",
        }
    }

    /// Integer code in VTK files: 0 outside, 1 inside, 2 boundary.
    pub fn code(self) -> i32 {
        match self {
            PointStatus::Outside => 0,
            PointStatus::Inside => 1,
            PointStatus::Boundary => 2,
        }
    }
}

/// Accuracy controls shared by the interior evaluations of all models.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct InteriorOptions {
    /// Points inside the body but closer to a boundary element than this fraction of that
    /// element's length (for a half-space: closer to the surface than this fraction of the
    /// contact grid's longest element) are reported as [`InteriorSample::Boundary`] and not
    /// evaluated. Default = 0.05 (docs/validation.md, "Interior stresses (issue 4)", measures
    /// the accuracy down to this distance).
    pub boundary_layer: f64,
}

impl Default for InteriorOptions {
    fn default() -> Self {
        Self { boundary_layer: 0.05 }
    }
}

/// Why a body model cannot give interior fields.
#[derive(Debug, thiserror::Error)]
pub enum InteriorError {
    /// The model has no interior (a rigid body).
    #[error("the {model} model has no interior field (it does not deform); ask for the other body")]
    NoInteriorField {
        /// The model's name.
        model: &'static str,
    },
    /// The BEM body could not be evaluated.
    #[error(transparent)]
    Bem(#[from] crate::bem::BemError),
}

/// Interior fields on a grid of points in the contact frame, for output.
#[derive(Debug, Clone)]
pub struct InteriorField {
    /// `A` or `B`.
    pub body: String,
    /// Model of the body (`half_space`, `bem`).
    pub model: String,
    /// Points (x, y) in the contact frame, x fastest [length].
    pub points: Vec<[f64; 2]>,
    /// Number of points along x and y.
    pub shape: [usize; 2],
    /// Where each point lies; only `Inside` points carry values.
    pub status: Vec<PointStatus>,
    /// (σxx, σyy, σzz, τxy) in the contact frame, σzz the plane-strain out-of-plane stress
    /// [stress, tension positive]; 0 at points not inside.
    pub stress: Vec<[f64; 4]>,
    /// (u_x, u_y) in the contact frame [length]; 0 at points not inside.
    pub displacement: Vec<[f64; 2]>,
}

/// The points of the grid [x0, x1, nx] × [y0, y1, ny] (contact frame, x fastest).
pub fn grid_points(x: [f64; 3], y: [f64; 3]) -> Vec<[f64; 2]> {
    let (nx, ny) = (x[2] as usize, y[2] as usize);
    let at = |v: [f64; 3], n: usize, k: usize| v[0] + (v[1] - v[0]) * k as f64 / (n - 1).max(1) as f64;
    (0..ny)
        .flat_map(|j| (0..nx).map(move |i| [at(x, nx, i), at(y, ny, j)]))
        .collect()
}

impl InteriorField {
    /// Collects the samples of a model at `points` (an nx × ny grid, x fastest).
    pub fn from_samples(
        body: &str,
        model: &str,
        shape: [usize; 2],
        points: Vec<[f64; 2]>,
        samples: &[InteriorSample],
    ) -> Self {
        let mut f = Self {
            body: body.to_string(),
            model: model.to_string(),
            shape,
            status: Vec::with_capacity(points.len()),
            stress: Vec::with_capacity(points.len()),
            displacement: Vec::with_capacity(points.len()),
            points,
        };
        for s in samples {
            let (status, v) = match s {
                InteriorSample::Inside(v) => (PointStatus::Inside, *v),
                InteriorSample::Outside => (PointStatus::Outside, InteriorValue::ZERO),
                InteriorSample::Boundary => (PointStatus::Boundary, InteriorValue::ZERO),
            };
            f.status.push(status);
            f.stress.push(v.stress);
            f.displacement.push(v.displacement);
        }
        f
    }

    /// Numbers of points (inside, outside, in the boundary layer).
    pub fn counts(&self) -> [usize; 3] {
        let n = |s: PointStatus| self.status.iter().filter(|&&x| x == s).count();
        [
            n(PointStatus::Inside),
            n(PointStatus::Outside),
            n(PointStatus::Boundary),
        ]
    }
}

/// A maximum over the evaluated points of an [`InteriorField`].
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize)]
pub struct Peak {
    /// The value [stress].
    pub value: f64,
    /// Where: x [length], contact frame.
    pub x: f64,
    /// Where: y [length], contact frame.
    pub y: f64,
}

/// What summary.json and the run table say about the interior grid.
#[derive(Debug, Clone, PartialEq, serde::Serialize)]
pub struct InteriorSummary {
    /// `A` or `B`.
    pub body: String,
    /// The body's model.
    pub model: String,
    /// Points of the grid.
    pub points: usize,
    /// Points evaluated (status `inside`).
    pub inside: usize,
    /// Points outside the body.
    pub outside: usize,
    /// Points within the boundary layer.
    pub boundary: usize,
    /// Largest principal shear stress τ1 over the evaluated points (null if none).
    pub max_shear: Option<Peak>,
    /// Largest von Mises stress over the evaluated points (null if none).
    pub max_von_mises: Option<Peak>,
}

impl InteriorField {
    /// Counts and maxima of the grid.
    pub fn summary(&self) -> InteriorSummary {
        let [inside, outside, boundary] = self.counts();
        let peak = |which: fn((f64, f64)) -> f64| {
            self.points
                .iter()
                .zip(&self.stress)
                .zip(&self.status)
                .filter(|(_, &st)| st == PointStatus::Inside)
                .map(|((p, s), _)| Peak {
                    value: which(invariants(s)),
                    x: p[0],
                    y: p[1],
                })
                .max_by(|a, b| a.value.total_cmp(&b.value))
        };
        InteriorSummary {
            body: self.body.clone(),
            model: self.model.clone(),
            points: self.points.len(),
            inside,
            outside,
            boundary,
            max_shear: peak(|(_, ms)| ms),
            max_von_mises: peak(|(vm, _)| vm),
        }
    }
}

impl InteriorValue {
    /// All fields zero (written at points that are not evaluated).
    pub const ZERO: Self = Self {
        displacement: [0.0; 2],
        stress: [0.0; 4],
    };
}

/// Fields of a half-plane body at `points` of the contact frame (y > 0 inside A, y < 0 inside
/// B) under the nodal contact tractions (p on both bodies, q on A; B receives −q), for the
/// material (`shear`, `nu`) and the displacement datum `datum` (module docs).
///
/// Each body is its own half-plane z ≥ 0 with z into the body: z = y for A, z = −y for B (a
/// mirror image, x unchanged), loaded by its own shear (q on A, −q on B). Back in the contact
/// frame, u_y = u_z on A and −u_z on B, τxy = τxz on A and −τxz on B. Points with z below
/// `boundary_layer` × the grid's element length are [`InteriorSample::Boundary`], points with
/// z < 0 [`InteriorSample::Outside`].
#[allow(clippy::too_many_arguments)]
pub fn halfplane_interior(
    grid: &ContactGrid,
    p: &[f64],
    q: &[f64],
    shear: f64,
    nu: f64,
    datum: f64,
    side: crate::body::Side,
    points: &[[f64; 2]],
    options: &InteriorOptions,
) -> Vec<InteriorSample> {
    use rayon::prelude::*;
    let sign = side.sign();
    let q_body: Vec<f64> = q.iter().map(|v| sign * v).collect();
    let layer = options.boundary_layer * grid.element_length();
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
            let s = halfplane_stress(grid, p, &q_body, nu, x, z);
            let [ux, uz] = halfplane_displacement(grid, p, &q_body, shear, nu, datum, x, z);
            InteriorSample::Inside(InteriorValue {
                displacement: [ux, sign * uz],
                stress: [s.sxx, s.szz, s.syy, sign * s.txz],
            })
        })
        .collect()
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

    /// At a small depth the interior displacement meets the half-space model's surface
    /// displacement (same datum), for a Hertz pressure and a Carter-like shear, on both sides:
    /// h = u_z (into the body) and w = ±u_x of the pair convention. The depth z = 1e-3 of an
    /// element moves u by about z·|∂u/∂z| ~ 1e-4 of its range.
    #[test]
    fn interior_displacement_meets_the_half_space_surface_displacement() {
        use crate::body::half_space::HalfSpace;
        use crate::body::{BodyModel, Side};
        use crate::material::Elastic;
        let grid = ContactGrid::uniform(ElementKind::DiscontinuousQuadratic, 21, -1.3, 1.3);
        let hs = HalfSpace {
            material: Elastic::new(210_000.0, 0.3),
            radius: 100.0,
        };
        let p: Vec<f64> = grid
            .nodes
            .iter()
            .map(|x| 1000.0 * (1.0 - x * x).max(0.0).sqrt())
            .collect();
        let q: Vec<f64> = grid.nodes.iter().zip(&p).map(|(x, p)| 0.1 * p * x).collect();
        let z = 1e-3 * grid.element_length();
        for side in [Side::A, Side::B] {
            let f = hs.flexibility(&grid, side);
            let h = crate::contact::mat_vec2(&f.hp, &p, &f.hq, &q);
            let w = crate::contact::mat_vec2(&f.wp, &p, &f.wq, &q);
            let range = h.iter().chain(&w).fold(0.0f64, |m, v| m.max(v.abs()));
            let points: Vec<[f64; 2]> = grid.nodes.iter().map(|&x| [x, side.sign() * z]).collect();
            let samples = halfplane_interior(
                &grid,
                &p,
                &q,
                hs.material.shear(),
                0.3,
                hs.datum_length(),
                side,
                &points,
                &InteriorOptions { boundary_layer: 1e-4 },
            );
            for (i, s) in samples.iter().enumerate() {
                let InteriorSample::Inside(v) = s else {
                    panic!("{side:?} node {i}: {s:?}")
                };
                // Contact frame → pair convention: h = ±u_y into the body, w = ±u_x.
                let (hi, wi) = (side.sign() * v.displacement[1], side.sign() * v.displacement[0]);
                assert!((hi - h[i]).abs() < 1e-3 * range, "{side:?} h[{i}]: {hi} vs {}", h[i]);
                assert!((wi - w[i]).abs() < 1e-3 * range, "{side:?} w[{i}]: {wi} vs {}", w[i]);
            }
        }
    }
}
