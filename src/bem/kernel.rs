//! Plane-strain Kelvin fundamental solution: displacement kernel U* and traction kernel T*.
//!
//! Convention of Brebbia, Telles & Wrobel, *Boundary Element Techniques* (1984), §3.2
//! (docs/references.md §9): X is the source (collocation) point, x the field point, r⃗ = x − X,
//! r = |r⃗|, r,i = r_i/r, ∂r/∂n = r,i n_i with n the unit normal at x pointing out of the
//! material. Entry (i, j) is the j-component at x due to a unit line force in direction i at X:
//!
//! ```text
//! U*_ij = [ (3−4ν) ln(ℓ/r) δij + r,i r,j ] / (8πG(1−ν))
//! T*_ij = −[ ∂r/∂n ((1−2ν) δij + 2 r,i r,j) − (1−2ν)(r,i n_j − r,j n_i) ] / (4π(1−ν) r)
//! ```
//!
//! U* is in 1/stress (displacement per unit line force, force/length), T* in 1/length. Nothing divides by 1 − 2ν, so ν = 0.5 (incompressible) is valid.
//!
//! **Length scale ℓ.** The textbook kernel has ln(1/r): it depends on the length unit. Adding a
//! constant to U* changes ∫U* t dΓ by the constant times the resultant force, which vanishes
//! for any equilibrated body, so ℓ does not change the exact solution; it does move the
//! "degenerate scale" at which the discrete G operator becomes singular (for a circle of
//! radius a with ℓ = 1 this happens at a = exp(1/(2(3−4ν))) ≈ 1.3 length units for ν = 0.3).
//! Choosing ℓ several times the body size keeps every body far from it whatever the unit
//! ([`super::BemOptions::log_length_scale`]).

// Index loops mirror the tensor notation of the formulas.
#![allow(clippy::needless_range_loop)]

use crate::material::Elastic;
use std::f64::consts::PI;

/// The geometry every kernel starts from: for a source X and a field point x, r⃗ = x − X,
/// r = |r⃗| and the unit vector g = r⃗/r (r,i in the index notation of the module docs).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct KernelFrame {
    /// r = |x − X| [length].
    pub r: f64,
    /// 1/r [1/length].
    pub inv_r: f64,
    /// g = r⃗/r, i.e. r,i [-].
    pub g: [f64; 2],
}

impl KernelFrame {
    /// The frame of `source` X and `field` x: r = √(r⃗·r⃗) and g = r⃗·(1/r). `sqrt` rather than
    /// `hypot` (several times slower, and a sixth of a BEM assembly): r² neither overflows nor
    /// underflows for any distance between points of a mesh in engineering units
    /// (1e-150 < r < 1e150).
    #[inline]
    pub fn new(source: [f64; 2], field: [f64; 2]) -> Self {
        let d = [field[0] - source[0], field[1] - source[1]];
        let r = (d[0] * d[0] + d[1] * d[1]).sqrt();
        let inv_r = 1.0 / r;
        Self {
            r,
            inv_r,
            g: [d[0] * inv_r, d[1] * inv_r],
        }
    }

    /// ∂r/∂n = g·n for the unit normal `normal` at the field point [-].
    #[inline]
    pub fn drdn(&self, normal: [f64; 2]) -> f64 {
        self.g[0] * normal[0] + self.g[1] * normal[1]
    }
}

/// The Kelvin kernels of one material, with the constants precomputed.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Kelvin {
    /// Poisson's ratio ν [-].
    pub poisson: f64,
    /// Shear modulus G [stress].
    pub shear: f64,
    /// Length scale ℓ of the logarithm [length] (see the module docs).
    pub length_scale: f64,
    /// 1/(8πG(1−ν)) [1/stress].
    c_u: f64,
    /// 1/(4π(1−ν)) [-].
    c_t: f64,
}

impl Kelvin {
    /// Kernels of `material` with the logarithm measured from `length_scale` [length].
    pub fn new(material: &Elastic, length_scale: f64) -> Self {
        let nu = material.poisson;
        let g = material.shear();
        Self {
            poisson: nu,
            shear: g,
            length_scale,
            c_u: 1.0 / (8.0 * PI * g * (1.0 - nu)),
            c_t: 1.0 / (4.0 * PI * (1.0 - nu)),
        }
    }

    /// Coefficient c of the logarithmic part c·ln(1/r)·δij of U* [1/stress]: (3−4ν)/(8πG(1−ν)).
    pub fn log_coefficient(&self) -> f64 {
        (3.0 - 4.0 * self.poisson) * self.c_u
    }

    /// U*_ij(X, x) [1/stress]: displacement j at `field` due to a unit line force i at
    /// `source`.
    pub fn displacement(&self, source: [f64; 2], field: [f64; 2]) -> [[f64; 2]; 2] {
        self.displacement_in(&KernelFrame::new(source, field))
    }

    /// U*_ij in the frame of a source and field point [1/stress].
    #[inline]
    pub fn displacement_in(&self, frame: &KernelFrame) -> [[f64; 2]; 2] {
        let (r, g) = (frame.r, frame.g);
        let log = (3.0 - 4.0 * self.poisson) * (self.length_scale / r).ln();
        let mut u = [[0.0; 2]; 2];
        for (i, row) in u.iter_mut().enumerate() {
            for (j, v) in row.iter_mut().enumerate() {
                let delta = if i == j { log } else { 0.0 };
                *v = self.c_u * (delta + g[i] * g[j]);
            }
        }
        u
    }

    /// T*_ij(X, x, n) [1/length]: traction j on a surface of unit outward normal `normal` at
    /// `field` due to a unit force i at `source`.
    pub fn traction(&self, source: [f64; 2], field: [f64; 2], normal: [f64; 2]) -> [[f64; 2]; 2] {
        self.traction_in(&KernelFrame::new(source, field), normal)
    }

    /// T*_ij in the frame of a source and field point, for the unit outward normal `normal` at
    /// the field point [1/length].
    #[inline]
    pub fn traction_in(&self, frame: &KernelFrame, normal: [f64; 2]) -> [[f64; 2]; 2] {
        let (r, g, drdn) = (frame.r, frame.g, frame.drdn(normal));
        let c12 = 1.0 - 2.0 * self.poisson;
        let scale = -self.c_t / r;
        let mut t = [[0.0; 2]; 2];
        for (i, row) in t.iter_mut().enumerate() {
            for (j, v) in row.iter_mut().enumerate() {
                let delta = if i == j { c12 } else { 0.0 };
                *v = scale * (drdn * (delta + 2.0 * g[i] * g[j]) - c12 * (g[i] * normal[j] - g[j] * normal[i]));
            }
        }
        t
    }
}

/// Derivatives of U* and T* with respect to the source point X (docs/references.md §9; the kernels
/// of the displacement-gradient identity, paper Eq. 79):
///
/// ```text
/// W_ijk = ∂U*_ij/∂X_k = [ (3−4ν) r,k δij − δik r,j − δjk r,i + 2 r,i r,j r,k ] / (8πG(1−ν) r)
/// V_ijk = ∂T*_ij/∂X_k = { 2 ∂r/∂n [ δik r,j + δjk r,i − (1−2ν) δij r,k − 4 r,i r,j r,k ]
///                         + n_k [ (1−2ν) δij + 2 r,i r,j ]
///                         + 2(1−2ν) r,k (r,i n_j − r,j n_i) − (1−2ν)(δik n_j − δjk n_i) }
///                       / (4π(1−ν) r²)
/// ```
///
/// so that at an interior point u_i,k(X) = ∫ W_ijk t_j dΓ − ∫ V_ijk u_j dΓ. Indexing is
/// `[i][j][k]`: force direction i, field component j, derivative direction k. W is in
/// 1/(stress·length), V in 1/length². Nothing divides by 1 − 2ν.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct GradientKernels {
    /// W_ijk = ∂U*_ij/∂X_k [1/(stress·length)].
    pub w: [[[f64; 2]; 2]; 2],
    /// V_ijk = ∂T*_ij/∂X_k [1/length²].
    pub v: [[[f64; 2]; 2]; 2],
}

impl Kelvin {
    /// W and V at `field` (outward normal `normal`) for a source at `source` (see
    /// [`GradientKernels`]).
    pub fn gradient(&self, source: [f64; 2], field: [f64; 2], normal: [f64; 2]) -> GradientKernels {
        let KernelFrame { r, g, .. } = KernelFrame::new(source, field);
        let mut out = self.gradient_angular(g, normal);
        let (sw, sv) = (1.0 / r, 1.0 / (r * r));
        for i in 0..2 {
            for j in 0..2 {
                for k in 0..2 {
                    out.w[i][j][k] *= sw;
                    out.v[i][j][k] *= sv;
                }
            }
        }
        out
    }

    /// The angular parts Ŵ = r·W [1/stress] and V̂ = r²·V [-] as polynomials in the components of
    /// g (= r⃗/r for the kernels; any vector for the Laurent expansion of the hypersingular
    /// integrals, [`super::hypersingular`]) and of the normal n. Ŵ is odd in g, V̂ even.
    pub fn gradient_angular(&self, g: [f64; 2], normal: [f64; 2]) -> GradientKernels {
        let n = normal;
        let drdn = g[0] * n[0] + g[1] * n[1];
        let c12 = 1.0 - 2.0 * self.poisson;
        let kappa = 3.0 - 4.0 * self.poisson;
        let mut out = GradientKernels {
            w: [[[0.0; 2]; 2]; 2],
            v: [[[0.0; 2]; 2]; 2],
        };
        for i in 0..2 {
            for j in 0..2 {
                for k in 0..2 {
                    let (dij, dik, djk) = (delta(i, j), delta(i, k), delta(j, k));
                    let ggg = g[i] * g[j] * g[k];
                    out.w[i][j][k] = self.c_u * (kappa * g[k] * dij - dik * g[j] - djk * g[i] + 2.0 * ggg);
                    out.v[i][j][k] = self.c_t
                        * (2.0 * drdn * (dik * g[j] + djk * g[i] - c12 * dij * g[k] - 4.0 * ggg)
                            + n[k] * (c12 * dij + 2.0 * g[i] * g[j])
                            + 2.0 * c12 * g[k] * (g[i] * n[j] - g[j] * n[i])
                            - c12 * (dik * n[j] - djk * n[i]));
                }
            }
        }
        out
    }

    /// Directional derivative d/ds V̂(g + s·dg, n + s·dn) at s = 0 [-] of the angular part of
    /// V (see [`Kelvin::gradient_angular`]): the product rule applied term by term. Needed for
    /// the 1/δ Laurent coefficient of the hypersingular integral (docs/references.md §9,
    /// "∂K̂/∂g · c + ∂K̂/∂n · n1").
    pub fn v_angular_derivative(&self, g: [f64; 2], n: [f64; 2], dg: [f64; 2], dn: [f64; 2]) -> [[[f64; 2]; 2]; 2] {
        let drdn = g[0] * n[0] + g[1] * n[1];
        let d_drdn = dg[0] * n[0] + dg[1] * n[1] + g[0] * dn[0] + g[1] * dn[1];
        let c12 = 1.0 - 2.0 * self.poisson;
        let mut out = [[[0.0; 2]; 2]; 2];
        for i in 0..2 {
            for j in 0..2 {
                for k in 0..2 {
                    let (dij, dik, djk) = (delta(i, j), delta(i, k), delta(j, k));
                    let bracket = dik * g[j] + djk * g[i] - c12 * dij * g[k] - 4.0 * g[i] * g[j] * g[k];
                    let d_bracket = dik * dg[j] + djk * dg[i]
                        - c12 * dij * dg[k]
                        - 4.0 * (dg[i] * g[j] * g[k] + g[i] * dg[j] * g[k] + g[i] * g[j] * dg[k]);
                    let cross = g[i] * n[j] - g[j] * n[i];
                    let d_cross = dg[i] * n[j] + g[i] * dn[j] - dg[j] * n[i] - g[j] * dn[i];
                    out[i][j][k] = self.c_t
                        * (2.0 * (d_drdn * bracket + drdn * d_bracket)
                            + dn[k] * (c12 * dij + 2.0 * g[i] * g[j])
                            + n[k] * 2.0 * (dg[i] * g[j] + g[i] * dg[j])
                            + 2.0 * c12 * (dg[k] * cross + g[k] * d_cross)
                            - c12 * (dik * dn[j] - djk * dn[i]));
                }
            }
        }
        out
    }
}

/// Kronecker delta.
fn delta(a: usize, b: usize) -> f64 {
    if a == b {
        1.0
    } else {
        0.0
    }
}

/// Kernels of the interior stress identity (Somigliana's identity differentiated and passed
/// through Hooke's law; docs/references.md §9, Brebbia–Telles–Wrobel Eq. 3.60):
///
/// ```text
/// σ_ij(X) = ∫ D_kij t_k dΓ − ∫ S_kij u_k dΓ
/// D_kij = [ (1−2ν)(δki r,j + δkj r,i − δij r,k) + 2 r,i r,j r,k ] / (4π(1−ν) r)
/// S_kij = G/(2π(1−ν) r²) · { 2 ∂r/∂n [ (1−2ν) δij r,k + ν(δik r,j + δjk r,i) − 4 r,i r,j r,k ]
///                            + 2ν(n_i r,j r,k + n_j r,i r,k)
///                            + (1−2ν)(2 n_k r,i r,j + n_j δik + n_i δjk) − (1−4ν) n_k δij }
/// ```
///
/// D_kij = C_ijlm ∂U*_lk/∂X_m and S_kij = C_ijlm ∂T*_lk/∂X_m (C the plane-strain stiffness), but
/// written out so that nothing divides by 1 − 2ν: both stay finite at ν = 0.5, where Hooke's λ
/// is infinite. Indexing is `[k][i][j]`: boundary component k, stress component ij (symmetric
/// in i, j). D is in 1/length, S in stress/length².
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct StressKernels {
    /// D_kij [1/length].
    pub d: [[[f64; 2]; 2]; 2],
    /// S_kij [stress/length²].
    pub s: [[[f64; 2]; 2]; 2],
}

impl Kelvin {
    /// D and S at `field` (outward normal `normal`) for an interior point at `source` (see
    /// [`StressKernels`]).
    pub fn stress(&self, source: [f64; 2], field: [f64; 2], normal: [f64; 2]) -> StressKernels {
        let frame = KernelFrame::new(source, field);
        let (r, g, drdn) = (frame.r, frame.g, frame.drdn(normal));
        let nu = self.poisson;
        let c12 = 1.0 - 2.0 * nu;
        let c14 = 1.0 - 4.0 * nu;
        // 1/(4π(1−ν) r) and G/(2π(1−ν) r²) = 2G·c_t/r².
        let (cd, cs) = (self.c_t / r, 2.0 * self.shear * self.c_t / (r * r));
        let delta = |a: usize, b: usize| if a == b { 1.0 } else { 0.0 };
        let mut out = StressKernels {
            d: [[[0.0; 2]; 2]; 2],
            s: [[[0.0; 2]; 2]; 2],
        };
        for k in 0..2 {
            for i in 0..2 {
                for j in 0..2 {
                    let (dij, dik, djk) = (delta(i, j), delta(i, k), delta(j, k));
                    let ggg = g[i] * g[j] * g[k];
                    out.d[k][i][j] = cd * (c12 * (dik * g[j] + djk * g[i] - dij * g[k]) + 2.0 * ggg);
                    out.s[k][i][j] = cs
                        * (2.0 * drdn * (c12 * dij * g[k] + nu * (dik * g[j] + djk * g[i]) - 4.0 * ggg)
                            + 2.0 * nu * (normal[i] * g[j] * g[k] + normal[j] * g[i] * g[k])
                            + c12 * (2.0 * normal[k] * g[i] * g[j] + normal[j] * dik + normal[i] * djk)
                            - c14 * normal[k] * dij);
                }
            }
        }
        out
    }
}

/// The integrands of Somigliana's identities for displacement and stress at an interior
/// point, contracted with the boundary data: for boundary displacement u and traction t at the
/// field point,
///
/// ```text
/// du_i  = U*_ij t_j − T*_ij u_j                  (integrand of u_i(X), Eq. S1 of super::somigliana)
/// dσ_ij = D_kij t_k − S_kij u_k                  (integrand of σ_ij(X), Eq. S2)
/// ```
///
/// written out with g = r⃗/r, so that no kernel array is formed (this is the inner loop of an
/// interior grid):
///
/// ```text
/// U*_ij t_j = c_u [ (3−4ν) ln(ℓ/r) t_i + g_i (g·t) ]
/// T*_ij u_j = −(c_t/r) [ ∂r/∂n ((1−2ν) u_i + 2 g_i (g·u)) − (1−2ν)(g_i (n·u) − n_i (g·u)) ]
/// D_kij t_k = (c_t/r) [ (1−2ν)(t_i g_j + t_j g_i − δij (g·t)) + 2 g_i g_j (g·t) ]
/// S_kij u_k = (2G c_t/r²) { 2 ∂r/∂n [ (1−2ν) δij (g·u) + ν(u_i g_j + u_j g_i) − 4 g_i g_j (g·u) ]
///             + 2ν (n_i g_j + n_j g_i)(g·u) + (1−2ν)(2 (n·u) g_i g_j + n_j u_i + n_i u_j)
///             − (1−4ν)(n·u) δij }
/// ```
///
/// with c_u = 1/(8πG(1−ν)), c_t = 1/(4π(1−ν)). Returns (du [length/length], [dσxx, dσyy, dτxy]
/// [stress/length]); multiply by dΓ.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SomiglianaIntegrand {
    /// du_i [1/length × length].
    pub displacement: [f64; 2],
    /// (dσxx, dσyy, dτxy) [stress/length].
    pub stress: [f64; 3],
}

impl Kelvin {
    /// The contracted integrands at `field` (outward normal `normal`, boundary displacement `u`
    /// and traction `t`) for the interior point `source` (see [`SomiglianaIntegrand`]).
    #[inline]
    pub fn somigliana_integrand(
        &self,
        source: [f64; 2],
        field: [f64; 2],
        normal: [f64; 2],
        u: [f64; 2],
        t: [f64; 2],
    ) -> SomiglianaIntegrand {
        let frame = KernelFrame::new(source, field);
        let (inv_r, g, drdn) = (frame.inv_r, frame.g, frame.drdn(normal));
        let n = normal;
        let nu = self.poisson;
        let (c12, c14) = (1.0 - 2.0 * nu, 1.0 - 4.0 * nu);
        let (gu, gt, nu_n) = (
            g[0] * u[0] + g[1] * u[1],
            g[0] * t[0] + g[1] * t[1],
            n[0] * u[0] + n[1] * u[1],
        );
        // a = c_t/r, b = 2G c_t/r².
        let a = self.c_t * inv_r;
        let b = 2.0 * self.shear * a * inv_r;
        // Displacement, the formulas above regrouped:
        // du_i = c_u κ ln(ℓ/r) t_i + g_i (c_u (g·t) + 2a ∂r/∂n (g·u) − a(1−2ν)(n·u))
        //        + a(1−2ν)(∂r/∂n u_i + n_i (g·u)).
        let log_term = self.c_u * (3.0 - 4.0 * nu) * (self.length_scale * inv_r).ln();
        let along_g = self.c_u * gt + 2.0 * a * drdn * gu - a * c12 * nu_n;
        let du = [0, 1].map(|i| log_term * t[i] + along_g * g[i] + a * c12 * (drdn * u[i] + n[i] * gu));
        // Stress, regrouped with sym(p, q)_ij = p_i q_j + p_j q_i:
        // dσ_ij = sym(v, g) − b(1−2ν) sym(n, u) + c_g g_i g_j − c_δ δij, where
        // v = a(1−2ν) t − 2bν (∂r/∂n u + (g·u) n),
        // c_g = 2a (g·t) + b (8 ∂r/∂n (g·u) − 2(1−2ν)(n·u)),
        // c_δ = a(1−2ν)(g·t) + b (2(1−2ν) ∂r/∂n (g·u) − (1−4ν)(n·u)).
        let v = [0, 1].map(|i| a * c12 * t[i] - 2.0 * b * nu * (drdn * u[i] + gu * n[i]));
        let cg = 2.0 * a * gt + b * (8.0 * drdn * gu - 2.0 * c12 * nu_n);
        let cd = a * c12 * gt + b * (2.0 * c12 * drdn * gu - c14 * nu_n);
        let bn = b * c12;
        let ds = [
            2.0 * (v[0] * g[0] - bn * n[0] * u[0]) + cg * g[0] * g[0] - cd,
            2.0 * (v[1] * g[1] - bn * n[1] * u[1]) + cg * g[1] * g[1] - cd,
            v[0] * g[1] + v[1] * g[0] - bn * (n[0] * u[1] + n[1] * u[0]) + cg * g[0] * g[1],
        ];
        SomiglianaIntegrand {
            displacement: du,
            stress: ds,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn kernels(nu: f64) -> Kelvin {
        Kelvin::new(&Elastic::new(210_000.0, nu), 7.0)
    }

    /// Stress at `x` of the displacement field u_j = U*_ij(X, x) (i fixed), by central
    /// differences and plane-strain Hooke's law σ = λ tr ε I + 2Gε.
    fn fd_stress(k: &Kelvin, i: usize, source: [f64; 2], x: [f64; 2], h: f64) -> [[f64; 2]; 2] {
        let mut grad = [[0.0; 2]; 2]; // grad[j][m] = ∂u_j/∂x_m
        for m in 0..2 {
            let mut xp = x;
            let mut xm = x;
            xp[m] += h;
            xm[m] -= h;
            let (up, um) = (k.displacement(source, xp), k.displacement(source, xm));
            for j in 0..2 {
                grad[j][m] = (up[i][j] - um[i][j]) / (2.0 * h);
            }
        }
        let nu = k.poisson;
        let lambda = 2.0 * k.shear * nu / (1.0 - 2.0 * nu);
        let tr = grad[0][0] + grad[1][1];
        let mut s = [[0.0; 2]; 2];
        for j in 0..2 {
            for m in 0..2 {
                let eps = 0.5 * (grad[j][m] + grad[m][j]);
                s[j][m] = 2.0 * k.shear * eps + if j == m { lambda * tr } else { 0.0 };
            }
        }
        s
    }

    #[test]
    fn traction_kernel_is_the_traction_of_the_displacement_kernel() {
        // T*_ij = σ^(i)_jk n_k with σ^(i) the stress of the field U*_i·: checks the sign, the
        // (1−2ν) terms and the normalisation of T* against U* (ν = 0.5 is covered by the BEM
        // tests; Hooke's λ is infinite there).
        for nu in [0.0, 0.3, 0.45] {
            let k = kernels(nu);
            let source = [0.3, -0.2];
            for (x, n) in [
                ([1.1, 0.4], [0.6, 0.8]),
                ([-0.5, -1.7], [-1.0, 0.0]),
                ([0.35, 0.1], [0.28, -0.96]),
            ] {
                let t = k.traction(source, x, n);
                for i in 0..2 {
                    let s = fd_stress(&k, i, source, x, 1e-5);
                    for j in 0..2 {
                        let fd = s[j][0] * n[0] + s[j][1] * n[1];
                        assert!(
                            (fd - t[i][j]).abs() < 1e-7 * t[i][j].abs().max(1e-3),
                            "nu={nu} x={x:?} ij={i}{j}: fd {fd} vs T* {}",
                            t[i][j]
                        );
                    }
                }
            }
        }
    }

    #[test]
    fn displacement_kernel_is_symmetric_and_reciprocal() {
        let k = kernels(0.3);
        let (a, b) = ([0.2, 0.7], [-1.3, 2.9]);
        let uab = k.displacement(a, b);
        let uba = k.displacement(b, a);
        assert!((uab[0][1] - uab[1][0]).abs() < 1e-20);
        for i in 0..2 {
            for j in 0..2 {
                // Betti: u_j(b) due to force i at a equals u_i(a) due to force j at b.
                assert!((uab[i][j] - uba[j][i]).abs() < 1e-18);
            }
        }
        // At r = ℓ the logarithm vanishes and U* = r,i r,j / (8πG(1−ν)).
        let u = k.displacement([0.0, 0.0], [7.0, 0.0]);
        let c = 1.0 / (8.0 * PI * k.shear * 0.7);
        assert!((u[0][0] - c).abs() < 1e-15 * c && u[1][1].abs() < 1e-15 * c);
    }

    #[test]
    fn traction_kernel_integrates_to_minus_the_unit_force_around_the_source() {
        // A disc around the load is in equilibrium: ∮ T*_ij dΓ = −δij with n pointing away from
        // the source; around a circle that does not contain the source the integral is 0.
        for nu in [0.3, 0.5] {
            let k = kernels(nu);
            let n = 720;
            for (centre, expected) in [([0.0, 0.0], -1.0), ([3.0, 1.0], 0.0)] {
                let mut sum = [[0.0; 2]; 2];
                let radius = 0.7;
                for s in 0..n {
                    let a = 2.0 * PI * (s as f64 + 0.5) / n as f64;
                    let nrm = [a.cos(), a.sin()];
                    let x = [centre[0] + radius * nrm[0], centre[1] + radius * nrm[1]];
                    let t = k.traction([0.0, 0.0], x, nrm);
                    for i in 0..2 {
                        for j in 0..2 {
                            sum[i][j] += t[i][j] * radius * 2.0 * PI / n as f64;
                        }
                    }
                }
                for i in 0..2 {
                    for j in 0..2 {
                        let e = if i == j { expected } else { 0.0 };
                        assert!((sum[i][j] - e).abs() < 1e-12, "nu={nu} {i}{j}: {}", sum[i][j]);
                    }
                }
            }
        }
    }

    #[test]
    fn gradient_kernels_are_source_derivatives_of_u_and_t() {
        // Central differences in the source point X, at several ν including 0.5.
        for nu in [0.0, 0.3, 0.5] {
            let k = kernels(nu);
            for (source, x, n) in [
                ([0.3, -0.2], [1.1, 0.4], [0.6, 0.8]),
                ([0.0, 0.0], [-0.5, -1.7], [-1.0, 0.0]),
                ([0.31, 0.05], [0.35, 0.1], [0.28, -0.96]),
            ] {
                let gk = k.gradient(source, x, n);
                let h = 1e-6;
                for m in 0..2 {
                    let (mut sp, mut sm) = (source, source);
                    sp[m] += h;
                    sm[m] -= h;
                    let (up, um) = (k.displacement(sp, x), k.displacement(sm, x));
                    let (tp, tm) = (k.traction(sp, x, n), k.traction(sm, x, n));
                    for i in 0..2 {
                        for j in 0..2 {
                            let fw = (up[i][j] - um[i][j]) / (2.0 * h);
                            let fv = (tp[i][j] - tm[i][j]) / (2.0 * h);
                            let (w, v) = (gk.w[i][j][m], gk.v[i][j][m]);
                            let sw = gk.w.iter().flatten().flatten().fold(0.0f64, |a, b| a.max(b.abs()));
                            let sv = gk.v.iter().flatten().flatten().fold(0.0f64, |a, b| a.max(b.abs()));
                            assert!((fw - w).abs() < 1e-6 * sw, "nu={nu} W{i}{j}{m}: fd {fw} vs {w}");
                            assert!((fv - v).abs() < 1e-6 * sv, "nu={nu} V{i}{j}{m}: fd {fv} vs {v}");
                        }
                    }
                }
            }
        }
    }

    #[test]
    fn angular_derivative_of_v_matches_central_differences() {
        // V̂ is a polynomial of degree 5 in s along (dg, dn) ((g·n) g_i g_j g_k), so the
        // 5-point difference has the error h⁴ f⁽⁵⁾/30 ~ 1e-12 at h = 1e-3 and round-off
        // ~ ε/h ~ 1e-13: bound 1e-10 of the largest entry.
        for nu in [0.0, 0.3, 0.5] {
            let k = kernels(nu);
            let (g, n) = ([0.6, 0.8], [0.28, -0.96]);
            let (dg, dn) = ([-0.8, 0.6], [0.3, 0.1]);
            let d = k.v_angular_derivative(g, n, dg, dn);
            let at = |s: f64| {
                k.gradient_angular(
                    [g[0] + s * dg[0], g[1] + s * dg[1]],
                    [n[0] + s * dn[0], n[1] + s * dn[1]],
                )
                .v
            };
            let h = 1e-3;
            let (m2, m1, p1, p2) = (at(-2.0 * h), at(-h), at(h), at(2.0 * h));
            let scale = d.iter().flatten().flatten().fold(0.0f64, |a, b| a.max(b.abs()));
            for i in 0..2 {
                for j in 0..2 {
                    for c in 0..2 {
                        let fd = (m2[i][j][c] - 8.0 * m1[i][j][c] + 8.0 * p1[i][j][c] - p2[i][j][c]) / (12.0 * h);
                        assert!(
                            (fd - d[i][j][c]).abs() < 1e-10 * scale,
                            "nu={nu} {i}{j}{c}: {fd} vs {}",
                            d[i][j][c]
                        );
                    }
                }
            }
        }
    }

    /// Hooke's law (plane strain) applied to a displacement gradient grad[l][m] = ∂u_l/∂X_m.
    fn hooke(k: &Kelvin, grad: [[f64; 2]; 2]) -> [[f64; 2]; 2] {
        let nu = k.poisson;
        let lambda = 2.0 * k.shear * nu / (1.0 - 2.0 * nu);
        let tr = grad[0][0] + grad[1][1];
        let mut s = [[0.0; 2]; 2];
        for i in 0..2 {
            for j in 0..2 {
                s[i][j] = k.shear * (grad[i][j] + grad[j][i]) + if i == j { lambda * tr } else { 0.0 };
            }
        }
        s
    }

    #[test]
    fn stress_kernels_are_hooke_of_the_source_derivatives_of_u_and_t() {
        // D_kij = C_ijlm ∂U*_lk/∂X_m, S_kij = C_ijlm ∂T*_lk/∂X_m, by central differences in the
        // source point X (step 1e-6 on r ≈ 0.06 … 1.8: truncation ~1e-9, round-off ~1e-10,
        // relative to the largest entry); Hooke needs ν < 0.5.
        for nu in [0.0, 0.3, 0.45] {
            let k = kernels(nu);
            for (source, x, n) in [
                ([0.3, -0.2], [1.1, 0.4], [0.6, 0.8]),
                ([0.0, 0.0], [-0.5, -1.7], [-1.0, 0.0]),
                ([0.31, 0.05], [0.35, 0.1], [0.28, -0.96]),
            ] {
                let sk = k.stress(source, x, n);
                let h = 1e-6;
                // fd_u[l][k][m] = ∂U*_lk/∂X_m, same for T*.
                let (mut fd_u, mut fd_t) = ([[[0.0; 2]; 2]; 2], [[[0.0; 2]; 2]; 2]);
                for m in 0..2 {
                    let (mut sp, mut sm) = (source, source);
                    sp[m] += h;
                    sm[m] -= h;
                    let (up, um) = (k.displacement(sp, x), k.displacement(sm, x));
                    let (tp, tm) = (k.traction(sp, x, n), k.traction(sm, x, n));
                    for l in 0..2 {
                        for c in 0..2 {
                            fd_u[l][c][m] = (up[l][c] - um[l][c]) / (2.0 * h);
                            fd_t[l][c][m] = (tp[l][c] - tm[l][c]) / (2.0 * h);
                        }
                    }
                }
                let sd = sk.d.iter().flatten().flatten().fold(0.0f64, |a, b| a.max(b.abs()));
                let ss = sk.s.iter().flatten().flatten().fold(0.0f64, |a, b| a.max(b.abs()));
                for c in 0..2 {
                    // The field u_l = U*_lc (c fixed) and its stress.
                    let grad = |f: &[[[f64; 2]; 2]; 2]| [[f[0][c][0], f[0][c][1]], [f[1][c][0], f[1][c][1]]];
                    let (hd, hs) = (hooke(&k, grad(&fd_u)), hooke(&k, grad(&fd_t)));
                    for i in 0..2 {
                        for j in 0..2 {
                            let (d, s) = (sk.d[c][i][j], sk.s[c][i][j]);
                            assert!(
                                (hd[i][j] - d).abs() < 1e-6 * sd,
                                "nu={nu} D{c}{i}{j}: fd {} vs {d}",
                                hd[i][j]
                            );
                            assert!(
                                (hs[i][j] - s).abs() < 1e-6 * ss,
                                "nu={nu} S{c}{i}{j}: fd {} vs {s}",
                                hs[i][j]
                            );
                        }
                    }
                }
            }
        }
    }

    #[test]
    fn stress_kernels_are_finite_and_continuous_at_the_incompressible_limit() {
        // At ν = 0.5 Hooke's λ is infinite but D and S are polynomials in ν: they must be finite
        // and differ from ν = 0.5 − 1e-6 by O(1e-6) of their size.
        let (source, x, n) = ([0.3, -0.2], [1.1, 0.4], [0.6, 0.8]);
        let at = |nu: f64| kernels(nu).stress(source, x, n);
        let (a, b) = (at(0.5), at(0.5 - 1e-6));
        let flat = |s: &StressKernels| -> Vec<f64> { s.d.iter().chain(&s.s).flatten().flatten().copied().collect() };
        let (fa, fb) = (flat(&a), flat(&b));
        let scale = fa.iter().fold(0.0f64, |m, v| m.max(v.abs()));
        assert!(fa.iter().all(|v| v.is_finite()) && scale > 0.0);
        for (p, q) in fa.iter().zip(&fb) {
            assert!((p - q).abs() < 1e-5 * scale, "{p} vs {q}");
        }
    }

    #[test]
    fn contracted_somigliana_integrand_equals_the_kernel_contractions() {
        for nu in [0.0, 0.3, 0.5] {
            let k = kernels(nu);
            for (source, x, n, u, t) in [
                ([0.3, -0.2], [1.1, 0.4], [0.6, 0.8], [1e-3, -2e-3], [50.0, -20.0]),
                ([0.0, 0.0], [-0.5, -1.7], [-1.0, 0.0], [-3e-4, 1e-4], [7.0, 3.0]),
                ([0.31, 0.05], [0.35, 0.1], [0.28, -0.96], [2e-3, 5e-4], [-1.0, 30.0]),
            ] {
                let f = k.somigliana_integrand(source, x, n, u, t);
                let (us, ts, sk) = (
                    k.displacement(source, x),
                    k.traction(source, x, n),
                    k.stress(source, x, n),
                );
                for i in 0..2 {
                    let want: f64 = (0..2).map(|j| us[i][j] * t[j] - ts[i][j] * u[j]).sum();
                    let scale = (0..2)
                        .map(|j| (us[i][j] * t[j]).abs() + (ts[i][j] * u[j]).abs())
                        .sum::<f64>();
                    assert!((f.displacement[i] - want).abs() <= 1e-13 * scale, "nu={nu} u{i}");
                }
                for (slot, (i, j)) in [(0, 0), (1, 1), (0, 1)].into_iter().enumerate() {
                    let want: f64 = (0..2).map(|c| sk.d[c][i][j] * t[c] - sk.s[c][i][j] * u[c]).sum();
                    let scale = (0..2)
                        .map(|c| (sk.d[c][i][j] * t[c]).abs() + (sk.s[c][i][j] * u[c]).abs())
                        .sum::<f64>();
                    assert!((f.stress[slot] - want).abs() <= 1e-13 * scale, "nu={nu} s{i}{j}");
                }
            }
        }
    }
}
