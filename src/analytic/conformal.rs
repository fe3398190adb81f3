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

use super::michell::{Annulus, LoadedRim, MichellError, ModeCompliance};
use crate::material::Elastic;
use kernel::{ChebyshevRule, RimKernel};
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
    /// (tests/conformal_series.rs).
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

impl Model {
    fn new(scene: &DiscInBore) -> Result<Self, ConformalError> {
        let (r1, r2) = (scene.roller.radius, scene.ring.bore_radius);
        if !(r1 > 0.0 && r2 >= r1 && r2 < 2.0 * r1) {
            return Err(ConformalError::Fit { roller: r1, bore: r2 });
        }
        let res = scene.resolution;
        if res.pressure_terms < 2 || res.truncation.is_some_and(|m| m < 16) {
            return Err(ConformalError::Resolution {
                terms: res.pressure_terms,
                modes: res.truncation,
            });
        }
        let roller = Annulus::new(scene.roller.shaft_radius, r1, scene.roller.material, LoadedRim::Outer)?;
        let ring = Annulus::new(r2, scene.ring.rim_radius, scene.ring.material, LoadedRim::Inner)?;
        let (c1, c2) = (
            scene.roller.material.plane_strain_compliance(),
            scene.ring.material.plane_strain_compliance(),
        );
        let (roller_modes, ring_modes) = match res.truncation {
            Some(m) => (roller.compliances(m), ring.compliances(m)),
            None => (Vec::new(), Vec::new()),
        };
        Ok(Self {
            r1,
            r2,
            clearance: r2 - r1,
            ring_share: c2 / (c1 + c2),
            direction: scene.direction,
            terms: res.pressure_terms,
            quadrature: res.quadrature,
            truncation: res.truncation,
            roller_kernel: RimKernel::new(&roller),
            ring_kernel: RimKernel::new(&ring),
            roller_modes,
            ring_modes,
        })
    }

    /// Pairing of the bore point θ for the centre distance d (eq. C1–C2).
    fn pair(&self, theta: f64, d: f64) -> Pair {
        let (st, ct) = theta.sin_cos();
        let root = (self.r1 * self.r1 - d * d * st * st).max(0.0).sqrt();
        let s = d * ct + root;
        let ds_dtheta = -d * st - d * d * st * ct / root;
        let ds_dd = ct - d * st * st / root;
        // Roller point X = s e_r(θ); θ1 = arg(X − O1); dθ1/dθ = ((X − O1) × X')/|X − O1|².
        let (x, y) = (s * ct - d, s * st);
        let theta1 = y.atan2(x);
        let (xp, yp) = (ds_dtheta * ct - s * st, ds_dtheta * st + s * ct);
        let dtheta1 = (x * yp - y * xp) / (x * x + y * y);
        let psi = match self.direction {
            TractionDirection::CommonNormal => theta + self.ring_share * (theta1 - theta),
            TractionDirection::LoadLine => 0.0,
        };
        Pair {
            theta,
            theta1,
            dtheta1,
            s,
            ds_dd,
            psi,
        }
    }

    /// Nodes of the product-integration rule for the arc θc: 3K + 40, plus what the
    /// remainder series of the shaft and the rim need across the arc.
    fn rule_size(&self, theta_c: f64, d: f64) -> usize {
        if self.quadrature > 0 {
            return self.quadrature;
        }
        let span = theta_c.max(self.pair(theta_c, d).theta1.abs());
        let rest = self
            .roller_kernel
            .remainder_modes()
            .max(self.ring_kernel.remainder_modes());
        3 * self.terms + 40 + (1.5 * rest as f64 * span).ceil() as usize
    }

    fn displacements(&self, theta_c: f64, d: f64, targets: &[Pair]) -> RimDisplacements {
        match self.truncation {
            None => self.kernel_displacements(theta_c, d, targets),
            Some(m) => self.fourier_displacements(theta_c, d, targets, m),
        }
    }

    /// Closed-form kernels and product integration (eq. C6–C9).
    fn kernel_displacements(&self, theta_c: f64, d: f64, targets: &[Pair]) -> RimDisplacements {
        let k = self.terms;
        let rule = ChebyshevRule::new(self.rule_size(theta_c, d));
        let sources: Vec<Pair> = rule.nodes.iter().map(|&t| self.pair(theta_c * t, d)).collect();
        let tractions: Vec<[f64; 4]> = sources.iter().map(|p| p.tractions(self.r2 / self.r1)).collect();
        let basis: Vec<Vec<f64>> = rule.nodes.iter().map(|&t| chebyshev_even(t, k)).collect();
        let nt = targets.len();
        let mut out = RimDisplacements {
            ring_r: DMatrix::zeros(k, nt),
            ring_t: DMatrix::zeros(k, nt),
            roller_r: DMatrix::zeros(k, nt),
            roller_t: DMatrix::zeros(k, nt),
        };
        let reg = rule.regular_weight();
        let factor = theta_c / PI;
        for (col, tg) in targets.iter().enumerate() {
            let t = tg.theta / theta_c;
            let (wl, ws) = (rule.log_weights(t), rule.sign_weights(t));
            for body in 0..2 {
                let (kern, target_angle) = if body == 0 {
                    (&self.ring_kernel, tg.theta)
                } else {
                    (&self.roller_kernel, tg.theta1)
                };
                let (mut ur, mut ut) = (vec![0.0; k], vec![0.0; k]);
                for (i, src) in sources.iter().enumerate() {
                    let (source_angle, slope) = if body == 0 {
                        (src.theta, theta_c)
                    } else {
                        (src.theta1, theta_c * src.dtheta1)
                    };
                    let u = target_angle - source_angle;
                    let dt = t - rule.nodes[i];
                    // ln|u| = ln|t − τ| + ln|u/(t − τ)|, the second smooth (its limit ln|dΘ/dτ|).
                    let ratio = if dt.abs() > 1e-12 {
                        (u / dt).abs().ln()
                    } else {
                        slope.abs().ln()
                    };
                    let [rr, rs, tt] = kern.eval(u);
                    let w = |x: kernel::Split| wl[i] * x.ln + ws[i] * x.sgn + reg * (x.ln * ratio + x.smooth);
                    let (wrr, wrs, wtt) = (w(rr), w(rs), w(tt));
                    let (sig, tau) = if body == 0 {
                        (tractions[i][0], tractions[i][1])
                    } else {
                        (tractions[i][2], tractions[i][3])
                    };
                    let (a, b) = (wrr * sig - wrs * tau, wrs * sig + wtt * tau);
                    for j in 0..k {
                        ur[j] += a * basis[i][j];
                        ut[j] += b * basis[i][j];
                    }
                }
                let (mr, mt) = if body == 0 {
                    (&mut out.ring_r, &mut out.ring_t)
                } else {
                    (&mut out.roller_r, &mut out.roller_t)
                };
                for j in 0..k {
                    mr[(j, col)] = factor * ur[j];
                    mt[(j, col)] = factor * ut[j];
                }
            }
        }
        out
    }

    /// Plain Fourier series to mode M: traction amplitudes by Gauss–Chebyshev quadrature (even
    /// integrands: the positive half of the rule), then Σ C_n (T_n, S_n) (cos, sin) nθ.
    fn fourier_displacements(&self, theta_c: f64, d: f64, targets: &[Pair], m: usize) -> RimDisplacements {
        let k = self.terms;
        let theta1_c = self.pair(theta_c, d).theta1.abs();
        // cos(nθc τ)·T_2j needs a rule exact to degree ~ Mθc + 2K.
        let half = ((m as f64 * theta_c.max(theta1_c) + 2.0 * k as f64) / 4.0).ceil() as usize + 24;
        let q = 2 * half;
        let nodes: Vec<f64> = (1..=half)
            .map(|i| ((2 * i - 1) as f64 * PI / (2 * q) as f64).cos())
            .collect();
        let w = 2.0 * PI / q as f64;
        let mut basis = DMatrix::zeros(k, half);
        let mut comp = vec![[0.0; 4]; half];
        let mut trig2 = [DMatrix::zeros(half, m + 1), DMatrix::zeros(half, m + 1)];
        let mut trig1 = [DMatrix::zeros(half, m + 1), DMatrix::zeros(half, m + 1)];
        for (i, &t) in nodes.iter().enumerate() {
            let pr = self.pair(theta_c * t, d);
            for (j, v) in chebyshev_even(t, k).into_iter().enumerate() {
                basis[(j, i)] = v;
            }
            comp[i] = pr.tractions(self.r2 / self.r1);
            fill_trig(&mut trig2, i, pr.theta);
            fill_trig(&mut trig1, i, pr.theta1);
        }
        let scale = theta_c * w / PI;
        let project = |c: usize, tr: &DMatrix<f64>| {
            let mut b = basis.clone();
            for (i, ci) in comp.iter().enumerate() {
                b.column_mut(i).scale_mut(ci[c] * scale);
            }
            let mut out = b * tr;
            // Mode 0 is the mean: 1/(2π) instead of 1/π.
            out.column_mut(0).scale_mut(0.5);
            out
        };
        let (t2, s2, t1, s1) = (
            project(0, &trig2[0]),
            project(1, &trig2[1]),
            project(2, &trig1[0]),
            project(3, &trig1[1]),
        );
        let amplitudes = |comps: &[ModeCompliance], t: &DMatrix<f64>, s: &DMatrix<f64>| {
            let (mut u, mut v) = (DMatrix::zeros(k, m + 1), DMatrix::zeros(k, m + 1));
            for (n, c) in comps.iter().enumerate() {
                for j in 0..k {
                    let (un, vn) = c.displacement(t[(j, n)], s[(j, n)]);
                    u[(j, n)] = un;
                    v[(j, n)] = if n == 0 { 0.0 } else { vn };
                }
            }
            (u, v)
        };
        let (u2, v2) = amplitudes(&self.ring_modes, &t2, &s2);
        let (u1, v1) = amplitudes(&self.roller_modes, &t1, &s1);
        let nt = targets.len();
        let mut cos2 = DMatrix::zeros(m + 1, nt);
        let mut sin2 = DMatrix::zeros(m + 1, nt);
        let mut cos1 = DMatrix::zeros(m + 1, nt);
        let mut sin1 = DMatrix::zeros(m + 1, nt);
        for (col, p) in targets.iter().enumerate() {
            fill_trig_column(&mut cos2, &mut sin2, col, p.theta);
            fill_trig_column(&mut cos1, &mut sin1, col, p.theta1);
        }
        RimDisplacements {
            ring_r: &u2 * &cos2,
            ring_t: &v2 * &sin2,
            roller_r: &u1 * &cos1,
            roller_t: &v1 * &sin1,
        }
    }

    /// Elastic part of the gap along n at target `col`, per pressure term (eq. C4).
    fn elastic_gap(&self, disp: &RimDisplacements, col: usize, p: &Pair) -> Vec<f64> {
        let (sn2, cn2) = (p.psi - p.theta).sin_cos();
        let (sn1, cn1) = (p.psi - p.theta1).sin_cos();
        (0..self.terms)
            .map(|j| {
                disp.ring_r[(j, col)] * cn2 + disp.ring_t[(j, col)] * sn2
                    - disp.roller_r[(j, col)] * cn1
                    - disp.roller_t[(j, col)] * sn1
            })
            .collect()
    }

    /// Solves the arc problem for the half-angle θc, linearised about the centre distance d.
    fn arc(&self, theta_c: f64, d: f64, load: f64) -> Arc {
        let k = self.terms;
        // Collocation at the positive roots of T_2K.
        let colloc: Vec<Pair> = (0..k)
            .map(|m| self.pair(theta_c * ((2 * m + 1) as f64 * PI / (4 * k) as f64).cos(), d))
            .collect();
        let disp = self.displacements(theta_c, d, &colloc);
        let mut a = DMatrix::zeros(k + 1, k + 1);
        let mut b = DVector::zeros(k + 1);
        for (m, p) in colloc.iter().enumerate() {
            for (j, g) in self.elastic_gap(&disp, m, p).into_iter().enumerate() {
                a[(m, j)] = g;
            }
            // Rigid gap (R2 − s(d + Δd))·cos(ψ − θ), linear in the step Δd (eq. C4).
            let cn2 = (p.psi - p.theta).cos();
            a[(m, k)] = -p.ds_dd * cn2;
            b[m] = -(self.r2 - p.s) * cn2;
        }
        // Load: P = ∫ p cos ψ R2 dθ (eq. C5), Gauss–Chebyshev (even integrand, positive half).
        let half = 2 * k + 16;
        let w = PI / half as f64;
        for i in 1..=half {
            let t = ((2 * i - 1) as f64 * PI / (4 * half) as f64).cos();
            let pr = self.pair(theta_c * t, d);
            for (j, v) in chebyshev_even(t, k).into_iter().enumerate() {
                a[(k, j)] += self.r2 * theta_c * w * v * pr.psi.cos();
            }
        }
        b[k] = load;
        let x = a
            .lu()
            .solve(&b)
            .unwrap_or_else(|| DVector::from_element(k + 1, f64::NAN));
        let coefficients: Vec<f64> = x.iter().take(k).copied().collect();
        let edge = coefficients.iter().sum::<f64>() * self.r2 * theta_c / load;
        Arc {
            coefficients,
            step: x[k],
            edge,
        }
    }

    /// Half-angle whose pressure is bounded (edge coefficient zero), by bracketing and Brent.
    fn bounded_arc(&self, guess: f64, d: f64, load: f64) -> Result<(f64, Arc), ConformalError> {
        let f = |th: f64| self.arc(th, d, load).edge;
        let max_angle = 150.0_f64.to_radians();
        let (mut lo, mut hi) = (guess, guess);
        let (mut f_lo, mut f_hi) = (f(lo), f(lo));
        if !f_lo.is_finite() {
            return Err(ConformalError::NotConverged(format!(
                "singular arc system at θc = {guess}"
            )));
        }
        // Too small an arc needs a compressive edge singularity (positive coefficient).
        while f_hi > 0.0 {
            lo = hi;
            f_lo = f_hi;
            hi = (hi * 1.25).min(max_angle);
            f_hi = f(hi);
            if hi >= max_angle && f_hi > 0.0 {
                return Err(ConformalError::ArcTooLarge {
                    max_degrees: max_angle.to_degrees(),
                });
            }
        }
        while f_lo < 0.0 {
            hi = lo;
            f_hi = f_lo;
            lo /= 1.25;
            f_lo = f(lo);
            if lo < 1e-7 {
                return Err(ConformalError::NotConverged("no contact arc above 1e−7 rad".into()));
            }
        }
        let theta = brent(f, lo, hi, f_lo, f_hi, 1e-14)?;
        Ok((theta, self.arc(theta, d, load)))
    }
}

impl DiscInBore {
    /// Scene with the default traction direction (common normal) and resolution.
    pub fn new(roller: Roller, ring: Ring) -> Self {
        Self {
            roller,
            ring,
            direction: TractionDirection::default(),
            rigid_gap: RigidGap::default(),
            resolution: SeriesResolution::default(),
        }
    }

    /// Combined contact modulus E* with 1/E* = (1−ν1²)/E1 + (1−ν2²)/E2 [stress].
    pub fn contact_modulus(&self) -> f64 {
        1.0 / (self.roller.material.plane_strain_compliance() + self.ring.material.plane_strain_compliance())
    }

    /// Effective radius R* with 1/R* = 1/R1 − 1/R2 (internal contact) [length]; infinite for
    /// zero clearance.
    pub fn effective_radius(&self) -> f64 {
        let inv = 1.0 / self.roller.radius - 1.0 / self.ring.bore_radius;
        if inv > 0.0 {
            1.0 / inv
        } else {
            f64::INFINITY
        }
    }

    /// Hertz half-width a = √(4PR*/(πE*)) for the load P [length]; infinite for zero clearance.
    pub fn hertz_half_width(&self, load: f64) -> f64 {
        super::hertz_half_width(load, self.effective_radius(), self.contact_modulus())
    }

    /// Solves the contact for the load P > 0 [force/length].
    pub fn solve(&self, load: f64) -> Result<ConformalSolution, ConformalError> {
        if !(load > 0.0 && load.is_finite()) {
            return Err(ConformalError::Load(load));
        }
        let model = Model::new(self)?;
        let hertz = self.hertz_half_width(load);
        let mut theta = if hertz.is_finite() {
            (hertz / model.r2).min(1.0)
        } else {
            1.0
        };
        let mut d = model.clearance;
        if self.rigid_gap == RigidGap::Linear {
            let (th, arc) = model.bounded_arc(theta, d, load)?;
            return Ok(ConformalSolution::new(model, load, th, d, arc));
        }
        // The rigid gap and the pairing depend on d only weakly (δ ≪ R): Newton on d converges
        // in two or three steps.
        for _ in 0..30 {
            let (th, arc) = model.bounded_arc(theta, d, load)?;
            theta = th;
            d += arc.step;
            if arc.step.abs() <= 1e-13 * model.r1 {
                let (th, arc) = model.bounded_arc(theta, d, load)?;
                return Ok(ConformalSolution::new(model, load, th, d, arc));
            }
        }
        Err(ConformalError::NotConverged("centre distance".into()))
    }
}

impl DiscInBore {
    /// Solves the contact for a prescribed approach δ > 0 [length] (zero clearance or not): the
    /// load P with `solve(P).approach` = δ to 1e−12, by Brent's method on ln P.
    pub fn solve_approach(&self, approach: f64) -> Result<ConformalSolution, ConformalError> {
        if !(approach > 0.0 && approach.is_finite()) {
            return Err(ConformalError::Load(approach));
        }
        // A probe load gives the scale: δ grows with P a little faster than linearly (Hertz:
        // δ ∝ P ln(1/P) at small load), so P·δ/δ_probe is a good first guess.
        let probe = 1e-6 * self.contact_modulus() * self.roller.radius;
        let scale = self.solve(probe)?.approach;
        let f = |ln_p: f64| -> f64 {
            match self.solve(ln_p.exp()) {
                Ok(s) => s.approach / approach - 1.0,
                Err(_) => f64::NAN,
            }
        };
        let guess = (probe * approach / scale).ln();
        let (mut lo, mut hi) = (guess - 0.5, guess + 0.5);
        let (mut f_lo, mut f_hi) = (f(lo), f(hi));
        for _ in 0..60 {
            if !(f_lo.is_finite() && f_hi.is_finite()) {
                return Err(ConformalError::ArcTooLarge { max_degrees: 150.0 });
            }
            if f_lo <= 0.0 && f_hi >= 0.0 {
                let ln_p = brent(f, lo, hi, f_lo, f_hi, 1e-13)?;
                return self.solve(ln_p.exp());
            }
            if f_lo > 0.0 {
                (hi, f_hi) = (lo, f_lo);
                lo -= 1.0;
                f_lo = f(lo);
            } else {
                (lo, f_lo) = (hi, f_hi);
                hi += 1.0;
                f_hi = f(hi);
            }
        }
        Err(ConformalError::NotConverged("load for the approach".into()))
    }
}

impl ConformalSolution {
    /// `d` is the centre distance of the pairing; the approach is d + Δd − ΔR (Δd = 0 when the
    /// exact iteration has converged).
    fn new(model: Model, load: f64, theta_c: f64, d: f64, arc: Arc) -> Self {
        let pair = model.pair(theta_c, d);
        let mut sol = Self {
            load,
            half_angle: theta_c,
            roller_half_angle: pair.theta1,
            half_width: model.r1 * pair.theta1,
            approach: d + arc.step - model.clearance,
            peak_pressure: 0.0,
            edge_residual: arc.edge,
            model,
            coefficients: arc.coefficients,
            centre_distance: d,
            step: arc.step,
        };
        sol.peak_pressure = sol.find_peak();
        sol
    }

    /// Pressure per unit bore arc length at the bore angle θ [stress]; zero outside the arc.
    /// The edge coefficient left by the root search (~1e−12) is removed so that p(±θc) = 0.
    pub fn pressure(&self, theta: f64) -> f64 {
        let t = theta.abs() / self.half_angle;
        if t >= 1.0 {
            return 0.0;
        }
        let v = chebyshev_even(t, self.coefficients.len());
        let num: f64 =
            v.iter().zip(&self.coefficients).map(|(a, b)| a * b).sum::<f64>() - self.coefficients.iter().sum::<f64>();
        num / (1.0 - t * t).sqrt()
    }

    /// `count` samples of the pressure from the contact centre to the edge, on both bodies.
    pub fn pressure_profile(&self, count: usize) -> Vec<PressureSample> {
        let last = count.max(2) - 1;
        (0..=last)
            .map(|i| self.sample(self.half_angle * i as f64 / last as f64))
            .collect()
    }

    /// The pressure and the paired positions at the bore angle θ.
    pub fn sample(&self, theta: f64) -> PressureSample {
        let pr = self.model.pair(theta, self.centre_distance);
        let p = self.pressure(theta);
        PressureSample {
            ring_angle: theta,
            roller_angle: pr.theta1,
            ring_arc: self.model.r2 * theta,
            roller_arc: self.model.r1 * pr.theta1,
            pressure: p,
            roller_pressure: p * self.model.r2 / (self.model.r1 * pr.dtheta1),
            direction: pr.psi,
        }
    }

    /// Deformed gap along the traction direction between the bore at θ and its paired roller
    /// point [length]: zero (to the resolution) on the arc, positive outside it.
    pub fn gap(&self, theta: f64) -> f64 {
        let pr = self.model.pair(theta, self.centre_distance);
        let disp = self.model.displacements(self.half_angle, self.centre_distance, &[pr]);
        let elastic: f64 = self
            .model
            .elastic_gap(&disp, 0, &pr)
            .iter()
            .zip(&self.coefficients)
            .map(|(g, c)| g * c)
            .sum();
        let rigid = self.model.r2 - pr.s - self.step * pr.ds_dd;
        rigid * (pr.psi - pr.theta).cos() + elastic
    }

    /// Radial displacements (outwards positive) of the bore at θ and of the roller at the
    /// paired angle θ1(θ) [length], relative to the fixed rim and the shaft.
    pub fn radial_displacements(&self, theta: f64) -> (f64, f64) {
        let pr = self.model.pair(theta, self.centre_distance);
        let disp = self.model.displacements(self.half_angle, self.centre_distance, &[pr]);
        let dot = |m: &DMatrix<f64>| {
            (0..self.coefficients.len())
                .map(|j| m[(j, 0)] * self.coefficients[j])
                .sum()
        };
        (dot(&disp.ring_r), dot(&disp.roller_r))
    }

    fn find_peak(&self) -> f64 {
        let n = 400;
        let (mut best, mut at) = (0.0, 0.0);
        for i in 0..n {
            let th = self.half_angle * i as f64 / n as f64;
            let p = self.pressure(th);
            if p > best {
                best = p;
                at = th;
            }
        }
        // Golden-section refinement around the best sample.
        let h = self.half_angle / n as f64;
        let (mut a, mut b) = ((at - h).max(0.0), (at + h).min(self.half_angle));
        let g = 0.5 * (5.0_f64.sqrt() - 1.0);
        for _ in 0..60 {
            let (c, d) = (b - g * (b - a), a + g * (b - a));
            if self.pressure(c) > self.pressure(d) {
                b = d;
            } else {
                a = c;
            }
        }
        best.max(self.pressure(0.5 * (a + b)))
    }
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

/// T_0(t), T_2(t), …, T_{2(k−1)}(t).
fn chebyshev_even(t: f64, k: usize) -> Vec<f64> {
    let mut out = Vec::with_capacity(k);
    let (mut prev, mut cur) = (1.0, t);
    out.push(1.0);
    for n in 2..2 * k - 1 {
        let next = 2.0 * t * cur - prev;
        prev = cur;
        cur = next;
        if n % 2 == 0 {
            out.push(cur);
        }
    }
    out
}

/// Row i of the (cos nθ, sin nθ) tables, n = 0..=M, by the rotation recurrence.
fn fill_trig(tables: &mut [DMatrix<f64>; 2], i: usize, theta: f64) {
    let (st, ct) = theta.sin_cos();
    let (mut c, mut s) = (1.0, 0.0);
    for n in 0..tables[0].ncols() {
        tables[0][(i, n)] = c;
        tables[1][(i, n)] = s;
        (c, s) = (c * ct - s * st, s * ct + c * st);
    }
}

/// Column m of the (cos nθ, sin nθ) tables, n = 0..=M.
fn fill_trig_column(cos: &mut DMatrix<f64>, sin: &mut DMatrix<f64>, m: usize, theta: f64) {
    let (st, ct) = theta.sin_cos();
    let (mut c, mut s) = (1.0, 0.0);
    for n in 0..cos.nrows() {
        cos[(n, m)] = c;
        sin[(n, m)] = s;
        (c, s) = (c * ct - s * st, s * ct + c * st);
    }
}

/// Brent's root finder on a bracket [a, b] with f(a)·f(b) < 0, to the absolute tolerance `tol`.
fn brent(f: impl Fn(f64) -> f64, a: f64, b: f64, fa: f64, fb: f64, tol: f64) -> Result<f64, ConformalError> {
    let (mut a, mut b, mut fa, mut fb) = (a, b, fa, fb);
    if fa.abs() < fb.abs() {
        std::mem::swap(&mut a, &mut b);
        std::mem::swap(&mut fa, &mut fb);
    }
    let (mut c, mut fc) = (a, fa);
    let mut mflag = true;
    let mut d = 0.0;
    for _ in 0..200 {
        if fb == 0.0 || (b - a).abs() < tol * b.abs().max(1e-300) {
            return Ok(b);
        }
        let mut s = if fa != fc && fb != fc {
            a * fb * fc / ((fa - fb) * (fa - fc))
                + b * fa * fc / ((fb - fa) * (fb - fc))
                + c * fa * fb / ((fc - fa) * (fc - fb))
        } else {
            b - fb * (b - a) / (fb - fa)
        };
        let lo = (3.0 * a + b) / 4.0;
        let out_of_range = !((s > lo.min(b)) && (s < lo.max(b)));
        if out_of_range
            || (mflag && (s - b).abs() >= (b - c).abs() / 2.0)
            || (!mflag && (s - b).abs() >= (c - d).abs() / 2.0)
        {
            s = 0.5 * (a + b);
            mflag = true;
        } else {
            mflag = false;
        }
        let fs = f(s);
        if !fs.is_finite() {
            return Err(ConformalError::NotConverged(format!(
                "non-finite edge coefficient at θc = {s}"
            )));
        }
        d = c;
        c = b;
        fc = fb;
        if fa * fs < 0.0 {
            b = s;
            fb = fs;
        } else {
            a = s;
            fa = fs;
        }
        if fa.abs() < fb.abs() {
            std::mem::swap(&mut a, &mut b);
            std::mem::swap(&mut fa, &mut fb);
        }
    }
    Err(ConformalError::NotConverged("Brent on the contact half-angle".into()))
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
