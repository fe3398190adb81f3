//! Rim kernels of an annulus in closed form, and product integration against the Chebyshev
//! pressure terms (docs/conformal.md eq. C6–C9).
//!
//! A symmetric rim traction (σ(φ) even, τ(φ) odd, per unit angle) displaces the loaded rim by
//!
//! ```text
//! u_r(θ) = (1/π) ∫ [K_rr(θ−φ) σ(φ) − K_rs(θ−φ) τ(φ)] dφ,
//! u_θ(θ) = (1/π) ∫ [K_rs(θ−φ) σ(φ) + K_θθ(θ−φ) τ(φ)] dφ,                      (C6)
//! K_rr(u) = ½C⁰_rr + Σ_{n≥1} C^n_rr cos nu,  K_rs(u) = Σ_{n≥1} C^n_rs sin nu,  K_θθ(u) = Σ_{n≥1} C^n_θθ cos nu,
//! ```
//!
//! with C^n the mode compliances of [`crate::analytic::michell::Annulus`] (C_rs = C_θr by
//! Betti). For n ≥ 2 they tend geometrically fast to those of the solid disc (roller) or the
//! infinite plate with a hole (ring), which are rational in n, with R/(4G) as factor:
//!
//! ```text
//! disc:  C_rr = C_θθ = κ/(n+1) + 1/(n−1),     C_rs = κ/(n+1) − 1/(n−1)
//! plate: C_rr = C_θθ = −κ/(n−1) − 1/(n+1),    C_rs = κ/(n−1) − 1/(n+1)              (C7)
//! ```
//!
//! and whose mode sums are closed forms in L(u) = −ln|2 sin(u/2)| = Σ cos(nu)/n and
//! W(u) = (π sgn u − u)/2 = Σ sin(nu)/n (|u| < 2π):
//!
//! ```text
//! Σ_{n≥2} cos nu/(n−1) = cos u L − sin u W,       Σ_{n≥2} sin nu/(n−1) = sin u L + cos u W,
//! Σ_{n≥2} cos nu/(n+1) = cos u L + sin u W − 1 − ½cos u,
//! Σ_{n≥2} sin nu/(n+1) = −sin u L + cos u W − ½ sin u.                              (C8)
//! ```
//!
//! So every kernel is K(u) = A(u) ln|u| + B(u) sgn u + C(u), A, B, C smooth, C holding the
//! remainder Σ (C^n − C^n_canonical) and the modes 0 and 1. Against a pressure term
//! T_k(τ)/√(1−τ²) the ln and sgn parts are integrated exactly (Mason & Handscomb,
//! *Chebyshev Polynomials*, on integral equations):
//!
//! ```text
//! ∫ ln|t−τ| T_k(τ)/√(1−τ²) dτ = −π ln 2 (k = 0), −(π/k) T_k(t) (k ≥ 1)                |t| ≤ 1
//!                              = π ln((y + √(y²−1))/2), −(π/k)(sgn t)^k (y − √(y²−1))^k   y = |t| > 1
//! ∫ sgn(t−τ) T_k(τ)/√(1−τ²) dτ = π − 2 arccos t (k = 0), −2 sin(k arccos t)/k (k ≥ 1)  (C9)
//! ```
//!
//! after interpolating the smooth factor at the nodes of a Q-point Gauss–Chebyshev rule.

use crate::analytic::michell::{Annulus, LoadedRim};
use std::f64::consts::PI;

/// A kernel value split as A·ln|u| + B·sgn u + C.
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub(crate) struct Split {
    pub ln: f64,
    pub sgn: f64,
    pub smooth: f64,
}

/// The kernels K_rr, K_rs (= K_θr) and K_θθ of one annulus' loaded rim.
#[derive(Debug, Clone)]
pub(crate) struct RimKernel {
    /// Coefficients of Σcos nu/(n−1) and Σcos nu/(n+1) in the canonical K_rr = K_θθ.
    cos_minus: f64,
    cos_plus: f64,
    /// Coefficients of Σsin nu/(n−1) and Σsin nu/(n+1) in the canonical K_rs.
    sin_minus: f64,
    sin_plus: f64,
    /// Remainders C^n − C^n_canonical (n ≥ 2) and the modes 0 (halved) and 1.
    rest_rr: Vec<f64>,
    rest_rs: Vec<f64>,
    rest_tt: Vec<f64>,
}

/// −ln|2 sin(u/2)/u|: the smooth part of L(u) = −ln|u| + ℓ(u), |u| < 2π.
fn ell(u: f64) -> f64 {
    if u.abs() < 1e-8 {
        return u * u / 24.0;
    }
    -(2.0 * (0.5 * u).sin() / u).abs().ln()
}

impl RimKernel {
    /// Kernels of the loaded rim of `annulus` (modes beyond the remainder's length differ from
    /// the canonical body by less than 1e−14 of their compliance).
    pub fn new(annulus: &Annulus) -> Self {
        let m = annulus.material();
        let r = annulus.loaded_radius();
        let f = r / (4.0 * m.shear());
        let kappa = 3.0 - 4.0 * m.poisson;
        let loaded_outer = annulus.loaded_rim() == LoadedRim::Outer;
        // (C7) in terms of (C8): disc K_rr = κ Σcos/(n+1) + Σcos/(n−1), K_rs = κ Σsin/(n+1) − Σsin/(n−1);
        // plate K_rr = −κ Σcos/(n−1) − Σcos/(n+1), K_rs = κ Σsin/(n−1) − Σsin/(n+1).
        let (cos_minus, cos_plus, sin_minus, sin_plus) = if loaded_outer {
            (f, kappa * f, -f, kappa * f)
        } else {
            (-kappa * f, -f, kappa * f, -f)
        };
        let canonical = |n: f64| -> (f64, f64) {
            let (a, b) = (1.0 / (n - 1.0), 1.0 / (n + 1.0));
            (cos_minus * a + cos_plus * b, sin_minus * a + sin_plus * b)
        };
        let c0 = annulus.compliance(0);
        let c1 = annulus.compliance(1);
        let (mut rest_rr, mut rest_rs, mut rest_tt) = (
            vec![0.5 * c0.radial_from_radial, c1.radial_from_radial],
            vec![0.0, c1.radial_from_shear],
            vec![0.0, c1.tangential_from_shear],
        );
        // The remainder decays geometrically until it reaches the rounding of the 4 × 4 solves
        // (~1e−16 of C^n): stop there.
        let mut quiet = 0;
        for n in 2..200_000 {
            let c = annulus.compliance(n);
            let (cc, cs) = canonical(n as f64);
            let (a, b, d) = (
                c.radial_from_radial - cc,
                c.radial_from_shear - cs,
                c.tangential_from_shear - cc,
            );
            rest_rr.push(a);
            rest_rs.push(b);
            rest_tt.push(d);
            let tiny = 1e-14 * cc.abs().max(cs.abs());
            quiet = if a.abs().max(b.abs()).max(d.abs()) < tiny {
                quiet + 1
            } else {
                0
            };
            if quiet >= 3 {
                break;
            }
        }
        Self {
            cos_minus,
            cos_plus,
            sin_minus,
            sin_plus,
            rest_rr,
            rest_rs,
            rest_tt,
        }
    }

    /// Number of modes kept in the remainder.
    pub fn remainder_modes(&self) -> usize {
        self.rest_rr.len()
    }

    /// (K_rr, K_rs, K_θθ) at u, |u| < 2π, each split as A ln|u| + B sgn u + C.
    pub fn eval(&self, u: f64) -> [Split; 3] {
        let (su, cu) = u.sin_cos();
        let l = ell(u);
        let h = 0.5 * u;
        // (C8) with L = −ln|u| + ℓ and W = (π/2) sgn u − u/2.
        let cos_m = Split {
            ln: -cu,
            sgn: -0.5 * PI * su,
            smooth: cu * l + h * su,
        };
        let cos_p = Split {
            ln: -cu,
            sgn: 0.5 * PI * su,
            smooth: cu * l - h * su - 1.0 - 0.5 * cu,
        };
        let sin_m = Split {
            ln: -su,
            sgn: 0.5 * PI * cu,
            smooth: su * l - h * cu,
        };
        let sin_p = Split {
            ln: su,
            sgn: 0.5 * PI * cu,
            smooth: -su * l - h * cu - 0.5 * su,
        };
        let comb = |a: f64, x: Split, b: f64, y: Split| Split {
            ln: a * x.ln + b * y.ln,
            sgn: a * x.sgn + b * y.sgn,
            smooth: a * x.smooth + b * y.smooth,
        };
        let mut rr = comb(self.cos_minus, cos_m, self.cos_plus, cos_p);
        let mut rs = comb(self.sin_minus, sin_m, self.sin_plus, sin_p);
        let mut tt = rr;
        let (mut c, mut s) = (1.0, 0.0);
        for n in 0..self.rest_rr.len() {
            rr.smooth += self.rest_rr[n] * c;
            rs.smooth += self.rest_rs[n] * s;
            tt.smooth += self.rest_tt[n] * c;
            (c, s) = (c * cu - s * su, s * cu + c * su);
        }
        [rr, rs, tt]
    }
}

/// A Q-point Gauss–Chebyshev rule of the first kind with its product-integration weights.
#[derive(Debug, Clone)]
pub(crate) struct ChebyshevRule {
    /// Nodes τ_i = cos((2i − 1)π/(2Q)), i = 1..Q.
    pub nodes: Vec<f64>,
    /// (2 − δ_k0)/Q · T_k(τ_i), row k, column i: the interpolation operator.
    interp: Vec<Vec<f64>>,
}

impl ChebyshevRule {
    pub fn new(q: usize) -> Self {
        let nodes: Vec<f64> = (1..=q)
            .map(|i| ((2 * i - 1) as f64 * PI / (2 * q) as f64).cos())
            .collect();
        let interp = (0..q)
            .map(|k| {
                let f = if k == 0 { 1.0 } else { 2.0 } / q as f64;
                (1..=q)
                    .map(|i| f * (k as f64 * (2 * i - 1) as f64 * PI / (2 * q) as f64).cos())
                    .collect()
            })
            .collect();
        Self { nodes, interp }
    }

    /// Weight of the regular part: ∫ h/√(1−τ²) dτ ≈ (π/Q) Σ h(τ_i).
    pub fn regular_weight(&self) -> f64 {
        PI / self.nodes.len() as f64
    }

    fn apply(&self, moments: &[f64]) -> Vec<f64> {
        let q = self.nodes.len();
        let mut w = vec![0.0; q];
        for (row, &m) in self.interp.iter().zip(moments) {
            for (wi, &r) in w.iter_mut().zip(row) {
                *wi += m * r;
            }
        }
        w
    }

    /// Weights W_i(t) with ∫ ln|t−τ| h(τ)/√(1−τ²) dτ ≈ Σ W_i h(τ_i), any t (C9).
    pub fn log_weights(&self, t: f64) -> Vec<f64> {
        let q = self.nodes.len();
        let mut lam = vec![0.0; q];
        if t.abs() <= 1.0 {
            lam[0] = -PI * std::f64::consts::LN_2;
            let phi = t.acos();
            for (k, l) in lam.iter_mut().enumerate().skip(1) {
                *l = -PI / k as f64 * (k as f64 * phi).cos();
            }
        } else {
            let y = t.abs();
            let root = (y * y - 1.0).sqrt();
            lam[0] = PI * (0.5 * (y + root)).ln();
            let r = (y - root) * t.signum();
            let mut rk = 1.0;
            for (k, l) in lam.iter_mut().enumerate().skip(1) {
                rk *= r;
                *l = -PI / k as f64 * rk;
            }
        }
        self.apply(&lam)
    }

    /// Weights S_i(t) with ∫ sgn(t−τ) h(τ)/√(1−τ²) dτ ≈ Σ S_i h(τ_i), any t (C9).
    pub fn sign_weights(&self, t: f64) -> Vec<f64> {
        let q = self.nodes.len();
        let mut mu = vec![0.0; q];
        if t.abs() < 1.0 {
            let phi = t.acos();
            mu[0] = PI - 2.0 * phi;
            for (k, m) in mu.iter_mut().enumerate().skip(1) {
                *m = -2.0 * (k as f64 * phi).sin() / k as f64;
            }
        } else {
            mu[0] = PI * t.signum();
        }
        self.apply(&mu)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::material::Elastic;

    /// Plain truncated sums of the mode compliances, for comparison with the closed forms.
    fn truncated(a: &Annulus, u: f64, modes: usize) -> [f64; 3] {
        let mut out = [0.0; 3];
        for n in 0..=modes {
            let c = a.compliance(n);
            let w = if n == 0 { 0.5 } else { 1.0 };
            let (s, co) = (n as f64 * u).sin_cos();
            out[0] += w * c.radial_from_radial * co;
            if n > 0 {
                out[1] += c.radial_from_shear * s;
                out[2] += c.tangential_from_shear * co;
            }
        }
        out
    }

    #[test]
    fn closed_form_kernels_match_the_mode_sums() {
        let steel = Elastic::new(210_000.0, 0.3);
        for a in [
            Annulus::new(5.0, 40.0, steel, LoadedRim::Outer).unwrap(),
            Annulus::new(50.0, 65.0, steel, LoadedRim::Inner).unwrap(),
        ] {
            let k = RimKernel::new(&a);
            assert!(k.remainder_modes() < 200, "{}", k.remainder_modes());
            for u in [0.3, 1.0, -2.0, 3.0] {
                let split = k.eval(u);
                let closed: Vec<f64> = split
                    .iter()
                    .map(|s| s.ln * u.abs().ln() + s.sgn * u.signum() + s.smooth)
                    .collect();
                // The truncated sums converge like 1/M (log kernel) away from u = 0; compare at
                // M = 40 000 with a tolerance of a few 1/M of the compliance scale R/(4G).
                let sums = truncated(&a, u, 40_000);
                let scale = a.loaded_radius() / (4.0 * steel.shear());
                for (c, s) in closed.iter().zip(sums) {
                    assert!((c - s).abs() < 2e-4 * scale, "u = {u}: closed {c}, sum {s}");
                }
            }
        }
    }

    #[test]
    fn product_integration_is_exact_for_known_integrals() {
        let rule = ChebyshevRule::new(40);
        // ∫ ln|t−τ| T_3(τ)/√ = −(π/3) T_3(t) inside, −(π/3)(y−√(y²−1))³ outside (t > 1).
        let t3 = |x: f64| 4.0 * x * x * x - 3.0 * x;
        for t in [0.2, -0.7, 0.999, 1.5, -3.0] {
            let w = rule.log_weights(t);
            let got: f64 = w.iter().zip(&rule.nodes).map(|(w, &x)| w * t3(x)).sum();
            let exact = if t.abs() <= 1.0 {
                -PI / 3.0 * t3(t)
            } else {
                let y: f64 = t.abs();
                -PI / 3.0 * t.signum() * (y - (y * y - 1.0).sqrt()).powi(3)
            };
            assert!((got - exact).abs() < 1e-13, "t = {t}: {got} vs {exact}");
        }
        // Outside, a smooth integrand checks the continuation by plain quadrature on many nodes.
        let fine = ChebyshevRule::new(4000);
        for t in [1.3, -2.0] {
            let f = |x: f64| (1.0 + x * x) * (t - x).abs().ln();
            let plain: f64 = fine.nodes.iter().map(|&x| f(x)).sum::<f64>() * fine.regular_weight();
            let w = rule.log_weights(t);
            let got: f64 = w.iter().zip(&rule.nodes).map(|(w, &x)| w * (1.0 + x * x)).sum();
            assert!((got - plain).abs() < 1e-9, "t = {t}: {got} vs {plain}");
        }
        // ∫ sgn(t−τ)(1 + τ)/√(1−τ²) dτ = (π − 2φ) + 2 sin φ... with φ = arccos t: check by parts.
        for t in [0.3_f64, -0.5] {
            let phi: f64 = t.acos();
            let exact = (PI - 2.0 * phi) - 2.0 * phi.sin();
            let w = rule.sign_weights(t);
            let got: f64 = w.iter().zip(&rule.nodes).map(|(w, &x)| w * (1.0 + x)).sum();
            assert!((got - exact).abs() < 1e-13, "t = {t}: {got} vs {exact}");
        }
    }

    #[test]
    fn approach_of_a_roller_on_its_shaft_is_the_full_series_of_the_references() {
        // docs/references.md §6c: steel rollers R = 150 and 300 mm on shafts of 15 and 30 mm,
        // one Hertz contact a = 1 mm, P = 906.229 N/mm: the approach of the shaft centre to the
        // contact point is 1.570358e−2 and 1.743492e−2 mm by the full series (the O(a/R) formula
        // gives 3e−6 and 2e−6 less). δ = −u_r(0) from K_rr and product integration, with the
        // Hertz pressure over the arc length Rθ; tolerance 1e−8 mm, the quoted digits.
        let steel = Elastic::new(210_000.0, 0.3);
        let p0 = 2.0 * 906.229 / PI;
        for (r, shaft, expected) in [(150.0, 15.0, 1.570358e-2), (300.0, 30.0, 1.743492e-2)] {
            let kern = RimKernel::new(&Annulus::new(shaft, r, steel, LoadedRim::Outer).unwrap());
            let rule = ChebyshevRule::new(64);
            let theta_c = 1.0 / r;
            let (wl, ws) = (rule.log_weights(0.0), rule.sign_weights(0.0));
            let mut u = 0.0;
            for (i, &tau) in rule.nodes.iter().enumerate() {
                let [rr, _, _] = kern.eval(-theta_c * tau);
                let w = wl[i] * rr.ln + ws[i] * rr.sgn + rule.regular_weight() * (rr.ln * theta_c.ln() + rr.smooth);
                // σ_rr = −p0√(1−τ²) = −p0(1−τ²)/√(1−τ²): the rule's weight carries the 1/√.
                u += w * -p0 * (1.0 - tau * tau);
            }
            let delta = -u * theta_c / PI;
            assert!(
                (delta - expected).abs() < 1e-8,
                "R = {r}: δ = {delta:e}, expected {expected:e}"
            );
        }
    }
}
