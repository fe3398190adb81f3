//! Free-rolling creepage of two unequal elastic rollers on rigid shafts, at second order in
//! a/R: the curvature effect that a half-space model does not have (docs/conformal.md §4).
//!
//! **Scene.** Rollers A and B (outer radii R_A, R_B, bonded to rigid shafts r_A, r_B, the same
//! material), pressed together by the Hertz pressure p(X) = p0√(1 − X²/a²) of half-width a
//! (1/R* = 1/R_A + 1/R_B, P = πa²E*/(4R*)), rolling freely (Q = 0) with full stick (μ → ∞, or
//! slip zones small). ξ = (V_A − V_B)/V with V_i = Ω_i R_i the rigid surface speeds.
//!
//! **Slip.** In steady rolling the material of body i crosses the contact at the speed
//! V_i(1 + D_i), D_i the tangential stretch of its surface. Full stick with a traction bounded at
//! the trailing edge and Q = 0 gives, for the D_A − D_B even in X (docs/conformal.md eq. R3):
//!
//! ```text
//! ξ = −(1/π) ∫_{−1}^{1} [D_A(at) − D_B(at)] / √(1 − t²) dt.
//! ```
//!
//! Two linearisations of the curved contact give two D's:
//! - **local normal** ([`FreeRollingCreepage::local_normal`]): the pressure acts along each
//!   body's own normal (σ_rr = −p(Rθ), σ_rθ = 0), and D is the hoop strain of the surface
//!   ε_θθ = (∂u_θ/∂θ + u_r)/R, the true speed of the material along the deformed surface;
//! - **global axes** ([`FreeRollingCreepage::global_axes`]): the pressure acts along the global
//!   normal of the contact grid (σ_rr = −p cos²θ, σ_rθ = p sin θ cos θ per unit arc, p per unit
//!   X = R sin θ), and D = ∂u_x/∂X of the global x displacement at uniform rigid speeds,
//!   which is ε_θθ + tan θ·(∂u_r/∂θ − u_θ)/R (docs/conformal.md eq. R4), what a contact model with
//!   displacements and tractions along fixed axes computes.
//!
//! **Series.** With the Michell mode compliances of [`super::michell::Annulus`], the mode n of
//! the hoop strain and of the surface rotation ω = (∂u_r/∂θ − u_θ)/R are, for a solid disc and
//! n ≥ 2 exactly (docs/conformal.md eq. R5),
//!
//! ```text
//! ε_n = [(κ−1)T_n + (κ+1)S_n]/(4G),   ω_n = [−(κ+1)T_n + (1−κ)S_n]/(4G),
//! ```
//!
//! so ε = (κ−1)σ_rr/(4G) − (κ+1)H[σ_rθ]/(4G) + …, ω = −(κ+1)H[σ_rr]/(4G) + (1−κ)σ_rθ/(4G) + …,
//! H the periodic Hilbert transform (conjugate function), plus modes 0 and 1 and the shaft's
//! correction, which decays geometrically in n. H is integrated exactly against Chebyshev
//! expansions of the tractions on the arc.

use super::michell::{Annulus, LoadedRim, MichellError};
use crate::material::Elastic;
use std::f64::consts::PI;

/// Why the creepage cannot be computed.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum CreepageError {
    /// A roller is not a valid annulus.
    #[error(transparent)]
    Annulus(#[from] MichellError),
    /// The prediction assumes similar materials (then the half-space creepage is zero).
    #[error("the rollers must have the same material (free rolling of dissimilar rollers has a first-order creepage)")]
    Dissimilar,
    /// The mode remainders did not decay (the surface's modes do not tend to the half-plane's).
    #[error("the Michell mode remainders do not decay")]
    Remainder,
    /// The half-width is not small against the radii.
    #[error("half-width must satisfy 0 < a < R/4 for both rollers (got a = {0})")]
    HalfWidth(f64),
}

/// A roller bonded to a rigid shaft.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ShaftRoller {
    /// Outer radius R [length].
    pub radius: f64,
    /// Shaft radius r [length], u = 0 there.
    pub shaft_radius: f64,
    /// Material.
    pub material: Elastic,
}

/// A ring whose bore holds a roller (internal contact), its rim fixed.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct BoreRing {
    /// Bore radius R2 [length].
    pub bore_radius: f64,
    /// Rim radius R3 [length], u = 0 there.
    pub rim_radius: f64,
    /// Material.
    pub material: Elastic,
}

/// Free-rolling creepage ξ = (V_A − V_B)/V [-] of roller A on roller B (A first).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct FreeRollingCreepage {
    /// Tractions along each body's local normal, slip from the hoop strain.
    pub local_normal: f64,
    /// Tractions along the global axes of the contact grid, slip from ∂u_x/∂X of the global
    /// displacement at uniform rigid speeds.
    pub global_axes: f64,
    /// Tractions along the global axes, slip from the hoop strain: the share of the traction
    /// direction alone (it differs from `local_normal` at third order only).
    pub global_tractions_hoop_strain: f64,
    /// Load P per unit length of the Hertz pressure used [force/length].
    pub load: f64,
}

impl FreeRollingCreepage {
    /// [global axes, local normal].
    pub fn as_array(&self) -> [f64; 2] {
        [self.global_axes, self.local_normal]
    }
}

/// Leading-order closed form for solid rollers (shafts → 0) whose load is reacted at the
/// centre (docs/conformal.md eq. R6–R7): [global axes, local normal] with
/// ξ_local = −(P/(4πG))(1/R_A − 1/R_B), ξ_global = ξ_local − (a²/4)(1/R_A² − 1/R_B²).
pub fn free_rolling_creepage_solid_rollers(
    radius_a: f64,
    radius_b: f64,
    half_width: f64,
    material: &Elastic,
) -> [f64; 2] {
    let e_star = 1.0 / (2.0 * material.plane_strain_compliance());
    let r_star = 1.0 / (1.0 / radius_a + 1.0 / radius_b);
    let load = super::hertz_load(half_width, r_star, e_star);
    let local = -load / (4.0 * PI * material.shear()) * (1.0 / radius_a - 1.0 / radius_b);
    let kinematic = -0.25 * half_width * half_width * (radius_a.powi(-2) - radius_b.powi(-2));
    [local + kinematic, local]
}

/// How the Hertz pressure is applied to one body.
#[derive(Debug, Clone, Copy, PartialEq)]
enum Loading {
    LocalNormal,
    GlobalAxes,
}

/// Tangential stretch of one roller's surface at the contact points X = a·t_j.
struct Roller {
    radius: f64,
    kappa: f64,
    g4: f64,
    /// Sign of the Hilbert-transform parts: +1 convex (a roller), −1 concave (a bore).
    hilbert: f64,
    /// Mode remainders (hoop strain and rotation, per unit T and per unit S), n = 0..N.
    strain_t: Vec<f64>,
    strain_s: Vec<f64>,
    rotation_t: Vec<f64>,
    rotation_s: Vec<f64>,
}

impl Roller {
    fn new(r: &ShaftRoller) -> Result<Self, CreepageError> {
        let ann = Annulus::new(r.shaft_radius, r.radius, r.material, LoadedRim::Outer)?;
        Self::of_surface(&ann, r.radius, r.material, 1.0, 1e-13)
    }

    /// The bore of a ring whose rim is fixed: the same local parts, the Hilbert parts of the
    /// opposite sign (the material lies outside the circle: measured, the modes of the inner
    /// rim tend to them), its own remainders. Its compliances round at about 1e-11 of the
    /// half-plane's (against 1e-13 for a roller), where the remainders are declared zero.
    fn bore(r: &BoreRing) -> Result<Self, CreepageError> {
        let ann = Annulus::new(r.bore_radius, r.rim_radius, r.material, LoadedRim::Inner)?;
        Self::of_surface(&ann, r.bore_radius, r.material, -1.0, 1e-10)
    }

    /// `hilbert` the sign of the half-plane's Hilbert-transform parts (+1 for a convex
    /// surface), `rounding` the relative size below which a remainder is zero.
    fn of_surface(
        ann: &Annulus,
        radius: f64,
        material: Elastic,
        hilbert: f64,
        rounding: f64,
    ) -> Result<Self, CreepageError> {
        let r = ShaftRoller {
            radius,
            shaft_radius: 0.0,
            material,
        };
        let kappa = 3.0 - 4.0 * r.material.poisson;
        let g4 = 4.0 * r.material.shear();
        let (e_t, e_s, w_t, w_s) = half_plane_parts(kappa, g4, hilbert);
        let (mut strain_t, mut strain_s, mut rotation_t, mut rotation_s) = (vec![], vec![], vec![], vec![]);
        let mut quiet = 0;
        for n in 0..100_000 {
            let c = ann.compliance(n);
            let nf = n as f64;
            // ε_n = (nV_n + U_n)/R, ω_n = (−nU_n − V_n)/R per unit T_n and per unit S_n.
            let et = (nf * c.tangential_from_radial + c.radial_from_radial) / r.radius;
            let es = (nf * c.tangential_from_shear + c.radial_from_shear) / r.radius;
            let wt = (-nf * c.radial_from_radial - c.tangential_from_radial) / r.radius;
            let ws = (-nf * c.radial_from_shear - c.tangential_from_shear) / r.radius;
            let rest = [et - e_t, es - e_s, wt - w_t, ws - w_s];
            strain_t.push(rest[0]);
            strain_s.push(rest[1]);
            rotation_t.push(rest[2]);
            rotation_s.push(rest[3]);
            // The shaft's correction decays like (r/R)^(2n): stop at the rounding of the modes.
            let small = rest.iter().all(|x| x.abs() < rounding * e_s.abs());
            quiet = if n >= 2 && small { quiet + 1 } else { 0 };
            if quiet >= 3 {
                break;
            }
        }
        if quiet < 3 {
            return Err(CreepageError::Remainder);
        }
        Ok(Self {
            radius: r.radius,
            kappa,
            g4,
            hilbert,
            strain_t,
            strain_s,
            rotation_t,
            rotation_s,
        })
    }

    /// Surface stretch D(t_j) at the contact points X = a·t_j under the Hertz pressure of
    /// half-width a and peak p0, for the loading and the matching slip measure.
    fn stretch(&self, loading: Loading, hoop_only: bool, a: f64, p0: f64, targets: &[f64]) -> Vec<f64> {
        let r = self.radius;
        // Half-angle of the loaded arc and the arc variable τ = θ/θc.
        let theta_c = match loading {
            Loading::LocalNormal => a / r,
            Loading::GlobalAxes => (a / r).asin(),
        };
        // Tractions on the arc as √(1 − τ²)·g(τ): g of σ_rr and of σ_rθ.
        let g = |tau: f64| -> (f64, f64) {
            match loading {
                Loading::LocalNormal => (-p0, 0.0),
                Loading::GlobalAxes => {
                    let th = theta_c * tau;
                    // 1 − (R sin θ/a)² = (1 − τ²)·h(τ) with sin²θc − sin²θ = sin(θc−θ) sin(θc+θ).
                    let sinc = |x: f64| if x.abs() < 1e-12 { 1.0 } else { x.sin() / x };
                    let h = theta_c * theta_c * sinc(theta_c * (1.0 - tau)) * sinc(theta_c * (1.0 + tau))
                        / theta_c.sin().powi(2);
                    let p = p0 * h.sqrt();
                    let (s, c) = th.sin_cos();
                    (-p * c * c, p * s * c)
                }
            }
        };
        let cheb = SecondKind::new(96);
        let gs: Vec<(f64, f64)> = cheb.nodes.iter().map(|&x| g(x)).collect();
        let (rr_coef, rt_coef) = (
            cheb.coefficients(&gs.iter().map(|v| v.0).collect::<Vec<_>>()),
            cheb.coefficients(&gs.iter().map(|v| v.1).collect::<Vec<_>>()),
        );
        // Fourier amplitudes T_n, S_n for the remainder modes (few, θc small).
        let nmax = self.strain_t.len();
        let (mut tn, mut sn) = (vec![0.0; nmax], vec![0.0; nmax]);
        for (i, &x) in cheb.nodes.iter().enumerate() {
            let w = cheb.weights[i] * theta_c / PI;
            let th = theta_c * x;
            for n in 0..nmax {
                let (s, c) = (n as f64 * th).sin_cos();
                let f = if n == 0 { 0.5 } else { 1.0 };
                tn[n] += f * w * gs[i].0 * c;
                sn[n] += w * gs[i].1 * s;
            }
        }
        let (e_t, e_s, w_t, w_s) = half_plane_parts(self.kappa, self.g4, self.hilbert);
        targets
            .iter()
            .map(|&t| {
                let th = match loading {
                    Loading::LocalNormal => a * t / r,
                    Loading::GlobalAxes => (a * t / r).asin(),
                };
                let tau = th / theta_c;
                let w = (1.0 - tau * tau).max(0.0).sqrt();
                let (srr, srt) = (w * cheb.evaluate(&rr_coef, tau), w * cheb.evaluate(&rt_coef, tau));
                // Conjugates H[σ] = (1/2π) PV∫ σ(φ) cot((θ−φ)/2) dφ on the arc.
                let h_rr = cheb.conjugate(&rr_coef, &gs, 0, tau, theta_c);
                let h_rt = cheb.conjugate(&rt_coef, &gs, 1, tau, theta_c);
                // Σ S_n cos nθ = −H[σ_rθ]; Σ T_n sin nθ = H[σ_rr].
                let mut eps = e_t * srr - e_s * h_rt;
                let mut rot = w_t * h_rr + w_s * srt;
                for n in 0..nmax {
                    let (s, c) = (n as f64 * th).sin_cos();
                    eps += (self.strain_t[n] * tn[n] + self.strain_s[n] * sn[n]) * c;
                    rot += (self.rotation_t[n] * tn[n] + self.rotation_s[n] * sn[n]) * s;
                }
                if hoop_only {
                    eps
                } else {
                    eps + th.tan() * rot
                }
            })
            .collect()
    }
}

/// The half-plane parts (ε per unit σ_rr, ε per unit H[σ_rθ] with its minus, ω per unit
/// H[σ_rr], ω per unit σ_rθ) of a surface's hoop strain and rotation (module docs, R5), the
/// Hilbert parts with the sign `hilbert`.
fn half_plane_parts(kappa: f64, g4: f64, hilbert: f64) -> (f64, f64, f64, f64) {
    (
        (kappa - 1.0) / g4,
        hilbert * (kappa + 1.0) / g4,
        -hilbert * (kappa + 1.0) / g4,
        (1.0 - kappa) / g4,
    )
}

/// Chebyshev expansion of the second kind on [−1, 1]: f(τ) = √(1−τ²) Σ g_k U_k(τ).
struct SecondKind {
    nodes: Vec<f64>,
    weights: Vec<f64>,
}

impl SecondKind {
    /// N-point Gauss–Chebyshev rule of the second kind: ∫√(1−τ²) f ≈ Σ w_i f(τ_i).
    fn new(n: usize) -> Self {
        let h = PI / (n + 1) as f64;
        let nodes = (1..=n).map(|i| (i as f64 * h).cos()).collect();
        let weights = (1..=n).map(|i| h * (i as f64 * h).sin().powi(2)).collect();
        Self { nodes, weights }
    }

    /// g_k = (2/π) ∫√(1−τ²) g U_k, k < N, from the node values of g.
    fn coefficients(&self, g: &[f64]) -> Vec<f64> {
        let n = self.nodes.len();
        (0..n)
            .map(|k| {
                (2.0 / PI)
                    * self
                        .nodes
                        .iter()
                        .zip(&self.weights)
                        .zip(g)
                        .map(|((&x, &w), &gi)| w * gi * chebyshev_u(k, x))
                        .sum::<f64>()
            })
            .collect()
    }

    fn evaluate(&self, coef: &[f64], x: f64) -> f64 {
        coef.iter().enumerate().map(|(k, c)| c * chebyshev_u(k, x)).sum()
    }

    /// (1/2π) PV∫ √(1−τ²) g(τ) cot(θc(t−τ)/2) θc dτ: the 2/u part exactly,
    /// (1/π) PV∫ √(1−τ²) U_k(τ)/(t−τ) dτ = T_{k+1}(t), and the smooth rest by quadrature.
    fn conjugate(&self, coef: &[f64], g: &[(f64, f64)], which: usize, t: f64, theta_c: f64) -> f64 {
        let singular: f64 = coef.iter().enumerate().map(|(k, c)| c * chebyshev_t(k + 1, t)).sum();
        let smooth: f64 = self
            .nodes
            .iter()
            .zip(&self.weights)
            .zip(g)
            .map(|((&x, &w), gi)| {
                let u = theta_c * (t - x);
                let v = if which == 0 { gi.0 } else { gi.1 };
                w * v * cot_minus_pole(u)
            })
            .sum();
        singular + theta_c / (2.0 * PI) * smooth
    }
}

/// cot(u/2) − 2/u, smooth and odd (≈ −u/6).
fn cot_minus_pole(u: f64) -> f64 {
    if u.abs() < 1e-4 {
        -u / 6.0 - u.powi(3) / 360.0
    } else {
        1.0 / (0.5 * u).tan() - 2.0 / u
    }
}

fn chebyshev_u(k: usize, x: f64) -> f64 {
    let (mut a, mut b) = (1.0, 2.0 * x);
    if k == 0 {
        return 1.0;
    }
    for _ in 1..k {
        (a, b) = (b, 2.0 * x * b - a);
    }
    b
}

fn chebyshev_t(k: usize, x: f64) -> f64 {
    if x.abs() <= 1.0 {
        (k as f64 * x.acos()).cos()
    } else {
        let (mut a, mut b) = (1.0, x);
        if k == 0 {
            return 1.0;
        }
        for _ in 1..k {
            (a, b) = (b, 2.0 * x * b - a);
        }
        b
    }
}

/// Free-rolling creepage ξ = (V_A − V_B)/V of roller `a` on roller `b` under the Hertz contact
/// of half-width `half_width` [length], for both linearisations (module docs).
pub fn free_rolling_creepage(
    a: &ShaftRoller,
    b: &ShaftRoller,
    half_width: f64,
) -> Result<FreeRollingCreepage, CreepageError> {
    if a.material != b.material {
        return Err(CreepageError::Dissimilar);
    }
    if !(half_width > 0.0 && half_width < 0.25 * a.radius.min(b.radius)) {
        return Err(CreepageError::HalfWidth(half_width));
    }
    let (ra, rb) = (Roller::new(a)?, Roller::new(b)?);
    let e_star = 1.0 / (2.0 * a.material.plane_strain_compliance());
    let r_star = 1.0 / (1.0 / a.radius + 1.0 / b.radius);
    let load = super::hertz_load(half_width, r_star, e_star);
    let t = chebyshev_nodes(CREEP_AVERAGE_NODES);
    let p0 = super::hertz_peak_pressure(load, half_width);
    let average = |loading: Loading, hoop: bool| {
        let da = ra.stretch(loading, hoop, half_width, p0, &t);
        let db = rb.stretch(loading, hoop, half_width, p0, &t);
        -da.iter().zip(&db).map(|(x, y)| x - y).sum::<f64>() / t.len() as f64
    };
    Ok(FreeRollingCreepage {
        local_normal: average(Loading::LocalNormal, true),
        global_axes: average(Loading::GlobalAxes, false),
        global_tractions_hoop_strain: average(Loading::GlobalAxes, true),
        load,
    })
}

/// Free-rolling creepage ξ = (V_A − V_B)/V [-] of a roller A on its shaft in the bore of a ring
/// B with its rim fixed, under the Hertz contact of half-width `half_width` [length] with
/// 1/R* = 1/R1 − 1/R2, for tractions along each body's own normal and the slip of the hoop
/// strains (the model's `traction_axes: contact`; module docs: R3 with D_B the bore's hoop
/// strain). Returns (ξ, P).
pub fn free_rolling_creepage_in_a_bore(
    roller: &ShaftRoller,
    ring: &BoreRing,
    half_width: f64,
) -> Result<(f64, f64), CreepageError> {
    if roller.material != ring.material {
        return Err(CreepageError::Dissimilar);
    }
    if !(half_width > 0.0 && half_width < 0.25 * roller.radius && roller.radius < ring.bore_radius) {
        return Err(CreepageError::HalfWidth(half_width));
    }
    let (ra, rb) = (Roller::new(roller)?, Roller::bore(ring)?);
    let e_star = 1.0 / (2.0 * roller.material.plane_strain_compliance());
    let r_star = 1.0 / (1.0 / roller.radius - 1.0 / ring.bore_radius);
    let load = super::hertz_load(half_width, r_star, e_star);
    let p0 = super::hertz_peak_pressure(load, half_width);
    let t = chebyshev_nodes(CREEP_AVERAGE_NODES);
    let da = ra.stretch(Loading::LocalNormal, true, half_width, p0, &t);
    let db = rb.stretch(Loading::LocalNormal, true, half_width, p0, &t);
    let xi = -da.iter().zip(&db).map(|(x, y)| x - y).sum::<f64>() / t.len() as f64;
    Ok((xi, load))
}

/// Nodes of the Gauss–Chebyshev (first kind) rule of the creepage average (module docs).
pub const CREEP_AVERAGE_NODES: usize = 64;

/// The n Gauss–Chebyshev (first kind) nodes cos((2i − 1)π/(2n)), i = 1 … n.
fn chebyshev_nodes(n: usize) -> Vec<f64> {
    (1..=n)
        .map(|i| ((2 * i - 1) as f64 * PI / (2 * n) as f64).cos())
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn chebyshev_hilbert_identity() {
        // (1/π) PV∫ √(1−τ²) U_2(τ)/(t−τ) dτ = T_3(t): check T_3 via the conjugate with θc → 0
        // against a direct principal-value quadrature (subtraction of the pole).
        let cheb = SecondKind::new(64);
        let g: Vec<(f64, f64)> = cheb.nodes.iter().map(|&x| (chebyshev_u(2, x), 0.0)).collect();
        let coef = cheb.coefficients(&g.iter().map(|v| v.0).collect::<Vec<_>>());
        assert!((coef[2] - 1.0).abs() < 1e-13 && coef[0].abs() < 1e-13);
        for t in [0.3, -0.8] {
            let got = cheb.conjugate(&coef, &g, 0, t, 1e-9);
            let exact = chebyshev_t(3, t);
            assert!((got - exact).abs() < 1e-9, "{got} vs {exact}");
        }
    }

    /// The bore's free-rolling creepage: positive for a roller in a bore of one material (the
    /// roller's surface faster), growing like a² (ξ/a² constant to O(a/R): within 3 % from
    /// a = 0.5 to 2 mm in a 40/50 bore), and refused for dissimilar materials or a roller
    /// larger than the bore.
    #[test]
    fn free_rolling_in_a_bore_grows_like_a_squared() {
        let steel = Elastic::new(210_000.0, 0.3);
        let roller = ShaftRoller {
            radius: 40.0,
            shaft_radius: 5.0,
            material: steel,
        };
        let ring = BoreRing {
            bore_radius: 50.0,
            rim_radius: 65.0,
            material: steel,
        };
        let (x1, _) = free_rolling_creepage_in_a_bore(&roller, &ring, 0.5).unwrap();
        let (x2, _) = free_rolling_creepage_in_a_bore(&roller, &ring, 2.0).unwrap();
        assert!(x1 > 0.0 && x2 > 0.0);
        assert!((x2 / 16.0 / x1 - 1.0).abs() < 0.03, "{x1} {x2}");
        let brass = Elastic::new(100_000.0, 0.34);
        assert!(free_rolling_creepage_in_a_bore(
            &roller,
            &BoreRing {
                material: brass,
                ..ring
            },
            1.0
        )
        .is_err());
        let big = ShaftRoller { radius: 60.0, ..roller };
        assert!(free_rolling_creepage_in_a_bore(&big, &ring, 1.0).is_err());
    }
}
