//! Frictionless conformal contact of a roller in a ring bore, from Michell/Fourier series:
//! the independent reference for internal contact of any arc size.
//!
//! **Scene** (plane strain, per unit axial length). The ring: an annulus R2 ≤ r ≤ R3 centred at
//! O2 = (0, 0), bonded to a rigid housing at its rim r = R3. The roller: an annulus r0 ≤ r ≤ R1
//! bonded to a rigid shaft of radius r0, R1 ≤ R2, centred at O1 = (d, 0). Unloaded, the roller
//! touches the bore at (R2, 0) with d = ΔR = R2 − R1 ≥ 0 (ΔR = 0: zero clearance). The shaft is
//! pushed towards +x by the force P per unit length; it moves by the **approach** δ, d = ΔR + δ,
//! and the ring's rim reacts −P. θ is the polar angle of the bore about O2 from +x, θ1 that of
//! the roller about O1.
//!
//! **Pairing and gap** (docs/conformal.md eq. C1–C4). The bore point at θ is paired with the
//! point of the roller's rigidly moved circle on the same ray from O2, at distance
//! s(θ) = d cos θ + √(R1² − d² sin² θ) and roller angle θ1(θ) (exact two-circle geometry).
//! The contact traction acts along a unit vector n(ψ) at the angle ψ(θ) from +x: on the ring
//! +p·n per unit bore arc, on the roller the equal and opposite force. The gap along n is
//! g = (R2 − s)·(e_r(θ)·n) + (u_ring(θ) − u_roller(θ1))·n, with the displacements from the
//! Michell series of each annulus ([`super::michell`]). Signorini: p ≥ 0, g ≥ 0, pg = 0, on an
//! unknown arc |θ| ≤ θc.
//!
//! **Solution.** p(θ) = Σ_j c_j T_{2j}(θ/θc)/√(1 − θ²/θc²) on the arc, collocation of g = 0 at the
//! positive roots of T_{2K} plus the load equation, for (c_j, δ). The arc θc is the root of the
//! edge coefficient Σ c_j (a bounded pressure, zero at the edges), found by Brent's method; the
//! geometric nonlinearity in d (rigid gap and pairing) is iterated to convergence.
//!
//! **Displacements.** By default each body's rim kernels are summed in closed form (the solid
//! disc's and the infinite plate's mode sums, plus the geometrically convergent remainder due to
//! the shaft and the rim, [`kernel`]) and integrated against the pressure terms by product
//! integration: spectral convergence in K, no mode truncation. With
//! [`SeriesResolution::truncation`] = Some(M) the plain Fourier series is summed to mode M
//! instead (Fourier coefficients of the tractions by Gauss–Chebyshev quadrature): the
//! independent path used to check the first one and to show the truncation error.

mod kernel;
mod model;
mod solution;

use super::michell::{Annulus, LoadedRim, MichellError, ModeCompliance};
use crate::material::Elastic;
use kernel::{ChebyshevRule, RimKernel};
use model::{brent, chebyshev_even};
use nalgebra::{DMatrix, DVector};
use std::f64::consts::PI;

/// Why a conformal contact cannot be solved.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum ConformalError {
    /// An annulus is invalid.
    #[error(transparent)]
    Annulus(#[from] MichellError),
    /// The roller does not fit the bore, or is too small for the pairing along rays from the
    /// ring centre (needs R1 ≤ R2 < 2R1).
    #[error("need roller radius R1 ≤ bore radius R2 < 2·R1 (got R1 = {roller}, R2 = {bore})")]
    Fit {
        /// Roller radius [length].
        roller: f64,
        /// Bore radius [length].
        bore: f64,
    },
    /// The load is not positive and finite.
    #[error("load must be positive and finite (got {0})")]
    Load(f64),
    /// The series resolution is too coarse to be meaningful.
    #[error("resolution needs at least 2 pressure terms and, when truncated, 16 modes (got {terms}, {modes:?})")]
    Resolution {
        /// Pressure terms.
        terms: usize,
        /// Fourier modes of a truncated series.
        modes: Option<usize>,
    },
    /// No contact arc below ~170° carries the load (the roller would wrap the bore).
    #[error("no contact arc below {max_degrees}° carries the load: load too large for this clearance")]
    ArcTooLarge {
        /// The largest half-angle tried [degree].
        max_degrees: f64,
    },
    /// The iteration did not converge.
    #[error("conformal contact iteration did not converge: {0}")]
    NotConverged(String),
}

/// Direction of the contact traction.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub enum TractionDirection {
    /// Along the common normal of the deformed surfaces, linearised: the normal of the ring
    /// turned towards the roller's by the ring's share of the compliance,
    /// ψ = θ + w(θ1 − θ), w = c_ring/(c_ring + c_roller), c = (1 − ν²)/E (each body takes its
    /// share of the gap, as in Hertz theory). Equal and opposite on the two bodies. For similar
    /// materials the bisector of the two normals.
    #[default]
    CommonNormal,
    /// Along the load line (global −x on the roller, +x on the ring) everywhere: what a model
    /// with tractions along fixed global axes applies. Not frictionless in the strict sense
    /// (it has a component along the surfaces); for comparisons only.
    LoadLine,
}

/// How the rigid gap depends on the approach δ.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum RigidGap {
    /// Linear in δ, like every displacement of linear elasticity: the pairing, the directions
    /// and ∂s/∂d are those of the unloaded geometry d = ΔR (eq. C4 with d = ΔR). The problem is
    /// then linear in (p, δ) for a given arc; with zero clearance the arc does not depend on
    /// the load. What Persson's and Ciavarella & Decuzzi's theory and a linear contact model
    /// (gap = g0 − δ·n_x + u) solve.
    #[default]
    Linear,
    /// The two circles at their final distance d = ΔR + δ (pairing, directions and rigid gap
    /// iterated to convergence): adds the geometric term ~δ²/(2R), significant only when δ is
    /// not small against the clearance.
    Exact,
}

/// Resolution of the series solution.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SeriesResolution {
    /// Number K of Chebyshev terms of the pressure (and of collocation points).
    pub pressure_terms: usize,
    /// Nodes Q of the Gauss–Chebyshev rule on the arc; 0 chooses 3K + 40 (more when the
    /// shaft or the rim is close to the contact: their remainder series must be resolved).
    pub quadrature: usize,
    /// `None`: closed-form kernels (default). `Some(M)`: the plain Fourier series to mode M.
    pub truncation: Option<usize>,
}

impl Default for SeriesResolution {
    /// K = 24 terms, automatic quadrature, closed-form kernels: the half-angle converges to
    /// ~1e−10 and the pressure to ~1e−8 of p_max for arcs from 0.3° to 85°
    /// (tests/validation/conformal_series.rs).
    fn default() -> Self {
        Self {
            pressure_terms: 24,
            quadrature: 0,
            truncation: None,
        }
    }
}

/// The roller: an annulus on a rigid shaft.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Roller {
    /// Outer radius R1 [length].
    pub radius: f64,
    /// Shaft radius r0 [length]: u = 0 at r = r0.
    pub shaft_radius: f64,
    /// Material.
    pub material: Elastic,
}

/// The ring: an annulus with a fixed rim.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Ring {
    /// Bore radius R2 [length], R1 ≤ R2 < 2R1.
    pub bore_radius: f64,
    /// Rim radius R3 [length]: u = 0 at r = R3.
    pub rim_radius: f64,
    /// Material.
    pub material: Elastic,
}

/// A roller on a rigid shaft pressed into the bore of a ring with a fixed rim, frictionless.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct DiscInBore {
    /// The roller (body 1).
    pub roller: Roller,
    /// The ring (body 2).
    pub ring: Ring,
    /// Direction of the contact traction.
    pub direction: TractionDirection,
    /// Dependence of the rigid gap on the approach.
    pub rigid_gap: RigidGap,
    /// Resolution of the series.
    pub resolution: SeriesResolution,
}

/// The solved contact. Angles in radians, lengths and stresses in the input's units.
#[derive(Debug, Clone)]
pub struct ConformalSolution {
    /// Load P per unit length [force/length].
    pub load: f64,
    /// Contact half-angle θc on the bore, about the ring centre [rad].
    pub half_angle: f64,
    /// Contact half-angle θ1(θc) on the roller, about the roller centre [rad].
    pub roller_half_angle: f64,
    /// Contact half-width on the roller, the arc R1·θ1(θc) [length].
    pub half_width: f64,
    /// Approach δ: displacement of the shaft towards the contact, relative to the fixed rim,
    /// from the unloaded touching position [length].
    pub approach: f64,
    /// Largest contact pressure, per unit bore arc length [stress].
    pub peak_pressure: f64,
    /// Edge coefficient left by the root search, relative to P/(R2θc) (~1e−12).
    pub edge_residual: f64,
    model: Model,
    coefficients: Vec<f64>,
    centre_distance: f64,
    /// δ beyond the pairing's centre distance (linear rigid gap) [length].
    step: f64,
}

/// One point of the contact pressure, with its position on both bodies.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PressureSample {
    /// Polar angle θ on the bore [rad].
    pub ring_angle: f64,
    /// Polar angle θ1 of the paired roller point [rad].
    pub roller_angle: f64,
    /// Arc length R2·θ along the bore from the contact centre [length].
    pub ring_arc: f64,
    /// Arc length R1·θ1 along the roller from the contact centre [length].
    pub roller_arc: f64,
    /// Pressure per unit bore arc length [stress].
    pub pressure: f64,
    /// Pressure per unit roller arc length, p·R2/(R1 dθ1/dθ) [stress].
    pub roller_pressure: f64,
    /// Direction ψ of the traction, from +x [rad]: the ring receives p(cos ψ, sin ψ) per unit
    /// bore arc length, the roller the opposite force.
    pub direction: f64,
}

/// Everything fixed by the scene: the two rims' kernels (or mode compliances).
#[derive(Debug, Clone)]
struct Model {
    r1: f64,
    r2: f64,
    clearance: f64,
    ring_share: f64,
    direction: TractionDirection,
    terms: usize,
    quadrature: usize,
    truncation: Option<usize>,
    roller_kernel: RimKernel,
    ring_kernel: RimKernel,
    roller_modes: Vec<ModeCompliance>,
    ring_modes: Vec<ModeCompliance>,
}

/// The pairing of the bore point θ with the roller (docs/conformal.md eq. C1–C2).
#[derive(Debug, Clone, Copy)]
struct Pair {
    theta: f64,
    theta1: f64,
    /// dθ1/dθ.
    dtheta1: f64,
    /// Distance from O2 to the roller's rigid circle along the ray θ.
    s: f64,
    /// ∂s/∂d.
    ds_dd: f64,
    /// Direction of the traction.
    psi: f64,
}

impl Pair {
    /// Rim tractions per unit contact pressure (eq. C3): (σ_rr, σ_rθ) of the bore per unit
    /// bore angle, then (σ_rr, σ_rθ)·dθ1/dθ of the roller (its traction per unit bore angle).
    fn tractions(&self, ratio: f64) -> [f64; 4] {
        let (s2, c2) = (self.psi - self.theta).sin_cos();
        let (s1, c1) = (self.psi - self.theta1).sin_cos();
        [-c2, -s2, -ratio * c1, -ratio * s1]
    }
}

/// Rim displacements at a set of targets, one row per pressure term, one column per target:
/// u_r and u_θ of the bore at θ, and of the roller at θ1(θ).
struct RimDisplacements {
    ring_r: DMatrix<f64>,
    ring_t: DMatrix<f64>,
    roller_r: DMatrix<f64>,
    roller_t: DMatrix<f64>,
}

/// The arc problem for one half-angle: coefficients, centre-distance step and edge coefficient.
struct Arc {
    coefficients: Vec<f64>,
    step: f64,
    edge: f64,
}

/// Load P [force/length] of a pin in a hole of an infinite plate (Persson 1964), elastically
/// similar, frictionless, in the same-radius linear theory, for the contact half-angle α [rad]
/// and the radial clearance ΔR [length] (docs/conformal.md eq. C14, derived there):
///
/// P = πE*ΔR / [cos⁴(α/2)(1 + ln cos(α/2))/sin²(α/2) − sin²(α/2)].
///
/// Small α: P → πE*ΔRα²/4, Hertz with R* = R²/ΔR. Infinite at the zero-clearance angle
/// [`pin_in_plate_zero_clearance_angle`]; NaN beyond it (no such contact).
pub fn pin_in_plate_load(half_angle: f64, clearance: f64, e_star: f64) -> f64 {
    let (s, c) = (0.5 * half_angle).sin_cos();
    let denominator = c.powi(4) * (1.0 + c.ln()) / (s * s) - s * s;
    if denominator > 0.0 {
        PI * e_star * clearance / denominator
    } else {
        f64::NAN
    }
}

/// Contact pressure [stress] of the pin in the plate at the angle θ for the half-angle α, the
/// load P per unit length and the radius R (docs/conformal.md eq. C13):
///
/// p = p₁√((cos θ − cos α)(1 + cos θ)) + 2B artanh√((cos θ − cos α)/(1 + cos θ)),
/// p₁ = P/(πR), B = p₁cos⁴(α/2)/(2 sin²(α/2)).
pub fn pin_in_plate_pressure(theta: f64, half_angle: f64, load: f64, radius: f64) -> f64 {
    let (ct, ca) = (theta.cos(), half_angle.cos());
    if ct <= ca {
        return 0.0;
    }
    let p1 = load / (PI * radius);
    let (s, c) = (0.5 * half_angle).sin_cos();
    let b = p1 * c.powi(4) / (2.0 * s * s);
    p1 * ((ct - ca) * (1.0 + ct)).sqrt() + 2.0 * b * ((ct - ca) / (1.0 + ct)).sqrt().atanh()
}

/// Contact half-angle of the pin in the plate with zero clearance [rad], the same for every
/// load: the root of cos⁴(α/2)(1 + ln cos(α/2)) = sin⁴(α/2), 84.83° (docs/conformal.md eq. C15).
pub fn pin_in_plate_zero_clearance_angle() -> f64 {
    let f = |a: f64| {
        let (s, c) = (0.5 * a).sin_cos();
        c.powi(4) * (1.0 + c.ln()) - s.powi(4)
    };
    let (a, b) = (1.4, 1.5);
    brent(f, a, b, f(a), f(b), 1e-15).unwrap_or(f64::NAN)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn chebyshev_even_terms() {
        let t: f64 = 0.3;
        let v = chebyshev_even(t, 4);
        let exact: Vec<f64> = (0..4).map(|j| ((2 * j) as f64 * t.acos()).cos()).collect();
        for (a, b) in v.iter().zip(exact) {
            assert!((a - b).abs() < 1e-14);
        }
    }

    #[test]
    fn pairing_is_the_two_circle_geometry() {
        let steel = Elastic::new(210_000.0, 0.3);
        let scene = DiscInBore::new(
            Roller {
                radius: 40.0,
                shaft_radius: 5.0,
                material: steel,
            },
            Ring {
                bore_radius: 50.0,
                rim_radius: 65.0,
                material: steel,
            },
        );
        let m = Model::new(&scene).unwrap();
        let d = 10.02;
        for th in [0.0, 0.1, 0.3] {
            let p = m.pair(th, d);
            // The paired point lies on the roller circle and on the ray.
            let (x, y) = (p.s * th.cos(), p.s * th.sin());
            assert!((((x - d).powi(2) + y * y).sqrt() - 40.0).abs() < 1e-12);
            assert!((p.theta1 - y.atan2(x - d)).abs() < 1e-14);
            // Derivatives by central differences.
            let h = 1e-6;
            let dt = (m.pair(th + h, d).theta1 - m.pair(th - h, d).theta1) / (2.0 * h);
            assert!((dt - p.dtheta1).abs() < 1e-7, "{dt} {}", p.dtheta1);
            let ds = (m.pair(th, d + h).s - m.pair(th, d - h).s) / (2.0 * h);
            assert!((ds - p.ds_dd).abs() < 1e-7);
            // Similar materials: the traction bisects the two normals.
            assert!((p.psi - 0.5 * (p.theta + p.theta1)).abs() < 1e-15);
        }
    }
}
