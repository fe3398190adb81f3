//! The half-plane surface kernels aged by a standard linear solid's creep in steady rolling.
//!
//! In the contact frame the material flows through the contact at the rolling speed V; the
//! material now at x was at x + d·V·s a time s ago (d = +1 when the contact moves in +x over
//! the body, so that material enters at the leading edge x = +a). A steady surface traction
//! gives the unit-compliance elastic displacement W(x); the creep compliance
//! J(s) = 1/G_r − (1/G_r − 1/G_g) e^(−s/τc) turns it into (Stieltjes convolution along the
//! material path, integrated by parts; Johnson, *Contact Mechanics* §7.2; Hunter 1961)
//!
//! ```text
//! u(x) = W(x)/G_g + (1/G_r − 1/G_g) ∫_0^∞ e^(−v) W(x + d·L·v) dv,   L = V τc,
//! ```
//!
//! so every half-plane kernel K(t), t = x − s, gains an aged twin
//! K^L(t) = ∫_0^∞ e^(−v) K(t + d L v) dv. With w = d·t and c = |w|/L:
//!
//! ```text
//! ln|t|     → Λ(w) = ln L + G_0(c)  (w > 0),   ln L + H_0(c)  (w < 0),   ln L − γ at 0
//! sgn t     → d·S(w),  S = 1 (w > 0),  2e^(w/L) − 1 (w < 0)
//! 1/t       → d·R(w)/L, R = e^c E1(c) (w > 0),  −e^(−c) Ei(c) (w < 0)
//! ```
//!
//! (G_0, H_0 and the exponential integrals in [`super::exponential_integrals`]). Λ is finite at
//! w = 0 (its singular part is −(w/L) ln|w/L|), S is continuous, R has the logarithmic
//! singularity of the elastic 1/t's principal value. As L → 0 each tends to its elastic kernel;
//! as L → ∞ the aged part tends to a constant (Λ) or to d (S): the glassy limit.
//!
//! **Element integrals** ∫ N_a(s) K^L(x − s) ds, in three regimes:
//! * near elements no shorter than L: exact, from the antiderivatives of w^k Λ, w^k S, w^k R
//!   (G_k, H_k and E_k(w) = ∫_0^w v^k e^(v/L) dv), well conditioned there;
//! * near elements shorter than L: a 16-point Gauss rule on each side of x, graded as s − x ∝ z³
//!   towards x, which turns Λ's w ln w into a z⁵ ln z the rule integrates to round-off; the aged
//!   1/t as (∫ N Λ − ∫ N ln|t|)/L, the second term exact;
//! * far elements (centre beyond [`FAR_FIELD_RATIO`] lengths): a Gauss rule of 12 points, as
//!   for the elastic kernels, down to 5 points beyond 25 lengths ([`far_points`]).

use super::exponential_integrals::{e1_scaled, ei_scaled, g0, g_antiderivatives, h0, h_antiderivatives, EULER_GAMMA};
use crate::body::half_space::{element_integrals_exact, shape_integrals_from_moments, Kernel, FAR_FIELD_RATIO};
use crate::grid::ElementKind;
use crate::quadrature::gauss_legendre;
use std::sync::OnceLock;

/// G_k(0) and H_k(0), k = 0, 1, 2 (recursions of [`super::exponential_integrals`] at c = 0).
const G_AT_ZERO: [f64; 3] = [-EULER_GAMMA, EULER_GAMMA, -2.0 * EULER_GAMMA];
const H_AT_ZERO: [f64; 3] = [-EULER_GAMMA, -EULER_GAMMA, -2.0 * EULER_GAMMA];

/// Points of the graded Gauss rule on each side of the field point.
const GRADED_POINTS: usize = 16;

/// Points of the Gauss rule on a far element whose centre is `ratio` element lengths from the
/// field point. The kernels are analytic but at the field point, so an n-point rule errs by
/// about (2·ratio)^(−2n) (Trefethen, *Approximation Theory and Approximation Practice*,
/// Thm 19.3) times the shape's degree loss: 12 points at 2.5 lengths (as for the elastic
/// kernels), fewer further out, all below 1e-16. The exponential of the aged sign varies on the
/// scale L; where an element is longer than L its far-upstream weight e^(−ratio·h/L) is below
/// that error.
fn far_points(ratio: f64) -> usize {
    match ratio {
        r if r < 5.0 => 12,
        r if r < 10.0 => 9,
        r if r < 25.0 => 7,
        _ => 5,
    }
}

fn rule(n: usize) -> &'static (Vec<f64>, Vec<f64>) {
    static RULES: OnceLock<Vec<(Vec<f64>, Vec<f64>)>> = OnceLock::new();
    &RULES.get_or_init(|| {
        (0..=GRADED_POINTS)
            .map(|n| if n == 0 { (vec![], vec![]) } else { gauss_legendre(n) })
            .collect()
    })[n]
}

/// The ageing of one body in steady rolling: the length L = V·τc [length] the material travels
/// in one creep time and the direction d = ±1 it comes from (module docs).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Ageing {
    /// L = V τc > 0 [length].
    pub length: f64,
    /// +1 when the contact moves in +x over the body (material comes from +x), −1 otherwise.
    pub direction: f64,
}

impl Ageing {
    /// Λ(w): the aged logarithm [-] (module docs).
    fn aged_log(&self, w: f64) -> f64 {
        let c = w.abs() / self.length;
        self.length.ln() + if w > 0.0 { g0(c) } else { h0(c) }
    }

    /// R(w): the aged 1/t times L [-], logarithmically singular at w = 0.
    fn aged_cauchy_times_length(&self, w: f64) -> f64 {
        let c = w.abs() / self.length;
        if w > 0.0 {
            e1_scaled(c)
        } else {
            -ei_scaled(c)
        }
    }

    /// S(w): the aged sign [-].
    fn aged_sign(&self, w: f64) -> f64 {
        if w >= 0.0 {
            1.0
        } else {
            2.0 * (w / self.length).exp() - 1.0
        }
    }

    /// The aged kernel K^L(t) at t = x − s (module docs).
    pub fn kernel(&self, kernel: Kernel, t: f64) -> f64 {
        let (d, w) = (self.direction, self.direction * t);
        match kernel {
            Kernel::Log => self.aged_log(w),
            Kernel::Sign => d * self.aged_sign(w),
            Kernel::Cauchy => d * self.aged_cauchy_times_length(w) / self.length,
        }
    }

    /// P_k(w) = ∫_0^w v^k f(v) dv, k = 0, 1, 2, for the kernel's function f of w (Λ, S or R/L).
    fn antiderivatives(&self, kernel: Kernel, w: f64) -> [f64; 3] {
        let l = self.length;
        let c = w.abs() / l;
        // ∫_0^w v^k R(v) dv / L^(k+1): G_k(c) − G_k(0) for w > 0, (−1)^k (H_k(c) − H_k(0)) below.
        let aged_part = || -> [f64; 3] {
            if w >= 0.0 {
                let g = g_antiderivatives(c);
                std::array::from_fn(|k| g[k] - G_AT_ZERO[k])
            } else {
                let h = h_antiderivatives(c);
                std::array::from_fn(|k| if k % 2 == 0 { 1.0 } else { -1.0 } * (h[k] - H_AT_ZERO[k]))
            }
        };
        match kernel {
            Kernel::Log => {
                let r = aged_part();
                std::array::from_fn(|k| {
                    let kp = (k + 1) as f64;
                    let log_part = if w == 0.0 {
                        0.0
                    } else {
                        w.powi(k as i32 + 1) / kp * (w.abs().ln() - 1.0 / kp)
                    };
                    log_part + l.powi(k as i32 + 1) * r[k]
                })
            }
            Kernel::Cauchy => {
                let r = aged_part();
                std::array::from_fn(|k| l.powi(k as i32) * r[k])
            }
            Kernel::Sign => {
                let power = |k: usize| w.powi(k as i32 + 1) / (k + 1) as f64;
                if w >= 0.0 {
                    return std::array::from_fn(power);
                }
                let ek = exponential_moments(w, l);
                std::array::from_fn(|k| 2.0 * ek[k] - power(k))
            }
        }
    }

    /// Moments M_k = ∫_{u1}^{u2} u^k K^L(−u) du, u = s − x, exactly: with w = −d u,
    /// M_k = σ (−d)^(k+1) [P_k(w2) − P_k(w1)], σ = d for the odd kernels (sign, 1/t).
    fn moments_exact(&self, kernel: Kernel, u1: f64, u2: f64) -> [f64; 3] {
        let d = self.direction;
        let sigma = if kernel == Kernel::Log { 1.0 } else { d };
        let (p1, p2) = (
            self.antiderivatives(kernel, -d * u1),
            self.antiderivatives(kernel, -d * u2),
        );
        std::array::from_fn(|k| sigma * (-d).powi(k as i32 + 1) * (p2[k] - p1[k]))
    }

    /// ∫ N_a(s) K^L(x − s) ds over [s1, s2] for each shape function a of `kind` (entries past
    /// its node count are 0), in the regime the module docs give for the element.
    pub fn element_integrals(&self, kind: ElementKind, kernel: Kernel, s1: f64, s2: f64, x: f64) -> [f64; 3] {
        let length = s2 - s1;
        let ratio = (0.5 * (s1 + s2) - x).abs() / length;
        if ratio > FAR_FIELD_RATIO {
            return self.gauss_integrals(kind, kernel, [s1, s2], x, rule(far_points(ratio)), false);
        }
        if length >= self.length {
            return shape_integrals_from_moments(kind, s1, s2, x, self.moments_exact(kernel, s1 - x, s2 - x));
        }
        if kernel == Kernel::Cauchy {
            // R/L = (Λ − ln|w|)/L: Λ is smooth enough for the graded rule, ln|t| is exact.
            let aged = self.element_integrals(kind, Kernel::Log, s1, s2, x);
            let elastic = element_integrals_exact(kind, Kernel::Log, s1, s2, x);
            return std::array::from_fn(|a| self.direction * (aged[a] - elastic[a]) / self.length);
        }
        self.gauss_integrals(kind, kernel, [s1, s2], x, rule(GRADED_POINTS), true)
    }

    /// ∫ N_a(s) ∂K^L_sgn/∂x ds over [s1, s2]: the aged counterpart of the elastic sign
    /// kernel's derivative 2δ(x − s), here S'(d(x − s)) = (2/L) e^(w/L) for w < 0 and 0 above
    /// (continuous S has no jump). Exact: P_k(w) = (2/L) E_k(w) for w < 0.
    pub fn sign_derivative_integrals(&self, kind: ElementKind, s1: f64, s2: f64, x: f64) -> [f64; 3] {
        let (d, l) = (self.direction, self.length);
        let p = |w: f64| -> [f64; 3] {
            if w >= 0.0 {
                [0.0; 3]
            } else {
                exponential_moments(w, l).map(|e| 2.0 / l * e)
            }
        };
        let (p1, p2) = (p(-d * (s1 - x)), p(-d * (s2 - x)));
        let moments = std::array::from_fn(|k| (-d).powi(k as i32 + 1) * (p2[k] - p1[k]));
        shape_integrals_from_moments(kind, s1, s2, x, moments)
    }

    /// Gauss rule on [s1, s2], split at x when x is inside; `graded` maps each part as
    /// s = x_near ± (part length)·z³ from the end nearest to x.
    fn gauss_integrals(
        &self,
        kind: ElementKind,
        kernel: Kernel,
        [s1, s2]: [f64; 2],
        x: f64,
        rule: &(Vec<f64>, Vec<f64>),
        graded: bool,
    ) -> [f64; 3] {
        let npe = kind.nodes_per_element();
        let (centre, half) = (0.5 * (s1 + s2), 0.5 * (s2 - s1));
        let mut out = [0.0; 3];
        let parts: &[(f64, f64)] = if x > s1 && x < s2 {
            &[(x, s1), (x, s2)]
        } else {
            &[(s1, s2)]
        };
        for &(a, b) in parts {
            // The part from `near` to `far`: near is the end closest to x.
            let (near, far) = if (a - x).abs() <= (b - x).abs() { (a, b) } else { (b, a) };
            let span = far - near;
            for (&xi, &wt) in rule.0.iter().zip(&rule.1) {
                let z = 0.5 * (xi + 1.0);
                let (s, jac) = if graded {
                    (near + span * z * z * z, span * 3.0 * z * z * 0.5)
                } else {
                    (near + span * z, span * 0.5)
                };
                let k = self.kernel(kernel, x - s) * wt * jac.abs();
                let eta = (s - centre) / half;
                for (a, o) in out.iter_mut().enumerate().take(npe) {
                    let [c0, c1, c2] = kind.shape_polynomial(a);
                    *o += (c0 + c1 * eta + c2 * eta * eta) * k;
                }
            }
        }
        out
    }
}

/// E_k(w) = ∫_0^w v^k e^(v/L) dv for w ≤ 0, k = 0, 1, 2: E_0 = L(e^(w/L) − 1),
/// E_k = L(w^k e^(w/L) − k E_(k−1)).
fn exponential_moments(w: f64, l: f64) -> [f64; 3] {
    let e = (w / l).exp();
    let e0 = l * (w / l).exp_m1();
    let e1 = l * (w * e - e0);
    let e2 = l * (w * w * e - 2.0 * e1);
    [e0, e1, e2]
}

#[cfg(test)]
mod tests {
    use super::*;

    /// ∫_0^∞ e^(−v) K(t + dLv) dv by brute force: a composite Gauss rule in v split at the
    /// kernel's singular point and graded into it — independent of the closed forms.
    fn aged_by_quadrature(kernel: Kernel, ageing: &Ageing, t: f64) -> f64 {
        let (l, d) = (ageing.length, ageing.direction);
        let k = |v: f64| {
            let arg = t + d * l * v;
            match kernel {
                Kernel::Log => arg.abs().ln(),
                Kernel::Sign => arg.signum(),
                Kernel::Cauchy => 1.0 / arg,
            }
        };
        let rule = gauss_legendre(40);
        let singular = -d * t / l; // v where the argument vanishes
                                   // Panels graded geometrically into the singular point from both sides, then out to v = 60.
        let mut breaks = vec![0.0, 60.0];
        let centre = singular.max(0.0);
        for i in 0..40 {
            let step = centre.max(1.0) * 0.5f64.powi(i);
            breaks.extend(
                [centre - step, centre + step]
                    .into_iter()
                    .filter(|v| *v > 0.0 && *v < 60.0),
            );
        }
        breaks.push(centre);
        for v in [2.0, 4.0, 8.0, 16.0, 32.0] {
            breaks.push(centre + v);
        }
        breaks.retain(|v| *v <= 60.0);
        breaks.sort_by(f64::total_cmp);
        breaks.dedup();
        let mut sum = 0.0;
        for pair in breaks.windows(2) {
            let (a, b) = (pair[0], pair[1]);
            for (&xi, &w) in rule.0.iter().zip(&rule.1) {
                let v = 0.5 * (a + b) + 0.5 * (b - a) * xi;
                sum += 0.5 * (b - a) * w * (-v).exp() * k(v);
            }
        }
        if kernel == Kernel::Cauchy && singular > 0.0 {
            // principal value: not covered by this brute force
            return f64::NAN;
        }
        sum
    }

    #[test]
    fn pointwise_kernels_equal_the_ageing_integral() {
        for d in [1.0, -1.0] {
            let ageing = Ageing {
                length: 0.7,
                direction: d,
            };
            for t in [-3.0, -0.9, -0.2, -1e-3, 1e-3, 0.2, 0.9, 3.0, 40.0] {
                for kernel in [Kernel::Log, Kernel::Sign, Kernel::Cauchy] {
                    let want = aged_by_quadrature(kernel, &ageing, t);
                    if want.is_nan() {
                        continue;
                    }
                    let got = ageing.kernel(kernel, t);
                    assert!(
                        (got - want).abs() < 1e-9 * want.abs().max(1.0),
                        "{kernel:?} d={d} t={t}: {got} vs {want}"
                    );
                }
            }
        }
    }

    /// Element integrals in all three regimes against a fine composite rule of the pointwise
    /// kernel over the element (the same kernel, an independent integration).
    #[test]
    fn element_integrals_agree_with_fine_quadrature_in_every_regime() {
        let kind = ElementKind::DiscontinuousQuadratic;
        let (s1, s2) = (-0.3, 0.5);
        for length in [1e-3, 0.05, 0.79, 0.81, 3.0, 200.0] {
            for d in [1.0, -1.0] {
                let ageing = Ageing { length, direction: d };
                for x in [-0.3, 0.1, 0.5, 0.9, 2.6, 5.7, -12.0, 12.1, -31.9] {
                    for kernel in [Kernel::Log, Kernel::Sign, Kernel::Cauchy] {
                        let got = ageing.element_integrals(kind, kernel, s1, s2, x);
                        let want = fine_element_integrals(&ageing, kind, kernel, s1, s2, x);
                        for a in 0..3 {
                            let scale = want.iter().map(|v| v.abs()).fold(1e-3, f64::max);
                            assert!(
                                (got[a] - want[a]).abs() < 1e-8 * scale,
                                "{kernel:?} L={length} d={d} x={x} a={a}: {} vs {}",
                                got[a],
                                want[a]
                            );
                        }
                    }
                }
            }
        }
    }

    /// 2000 graded panels per side of x: slow, independent, accurate to ~1e-10 for the kernels'
    /// weak singularities; the Cauchy kernel's principal value (x in the element) by
    /// subtracting its elastic part.
    fn fine_element_integrals(
        ageing: &Ageing,
        kind: ElementKind,
        kernel: Kernel,
        s1: f64,
        s2: f64,
        x: f64,
    ) -> [f64; 3] {
        if kernel == Kernel::Cauchy && x >= s1 && x <= s2 {
            let aged = fine_element_integrals(ageing, kind, Kernel::Log, s1, s2, x);
            let elastic = element_integrals_exact(kind, Kernel::Log, s1, s2, x);
            return std::array::from_fn(|a| ageing.direction * (aged[a] - elastic[a]) / ageing.length);
        }
        let rule = gauss_legendre(8);
        let (centre, half) = (0.5 * (s1 + s2), 0.5 * (s2 - s1));
        let mut out = [0.0; 3];
        let mut edges = vec![s1, s2];
        if x > s1 && x < s2 {
            edges.insert(1, x);
        }
        let panels = 2000;
        for pair in edges.windows(2) {
            let (a, b) = (pair[0], pair[1]);
            for p in 0..panels {
                // geometric grading towards both ends
                let f = |i: f64| {
                    let r = i / panels as f64;
                    a + (b - a) * (0.5 - 0.5 * (std::f64::consts::PI * r).cos())
                };
                let (pa, pb) = (f(p as f64), f(p as f64 + 1.0));
                for (&xi, &w) in rule.0.iter().zip(&rule.1) {
                    let s = 0.5 * (pa + pb) + 0.5 * (pb - pa) * xi;
                    let k = ageing.kernel(kernel, x - s) * w * 0.5 * (pb - pa);
                    let eta = (s - centre) / half;
                    for (a, o) in out.iter_mut().enumerate().take(kind.nodes_per_element()) {
                        let [c0, c1, c2] = kind.shape_polynomial(a);
                        *o += (c0 + c1 * eta + c2 * eta * eta) * k;
                    }
                }
            }
        }
        out
    }

    #[test]
    fn aged_kernels_tend_to_the_elastic_ones_as_the_creep_length_vanishes() {
        let ageing = Ageing {
            length: 1e-9,
            direction: 1.0,
        };
        let kind = ElementKind::Constant;
        for kernel in [Kernel::Log, Kernel::Sign] {
            let aged = ageing.element_integrals(kind, kernel, -0.2, 0.3, 0.05);
            let elastic = element_integrals_exact(kind, kernel, -0.2, 0.3, 0.05);
            for a in 0..1 {
                assert!(
                    (aged[a] - elastic[a]).abs() < 1e-7,
                    "{kernel:?}: {aged:?} vs {elastic:?}"
                );
            }
        }
    }

    /// The aged 1/t and the aged sign's derivative are the x-derivatives of the aged logarithm
    /// and sign (central differences), in every regime.
    #[test]
    fn derivative_kernels_are_the_derivatives_of_their_kernels() {
        let kind = ElementKind::DiscontinuousQuadratic;
        let (s1, s2) = (-0.3, 0.5);
        for length in [0.05, 0.8, 3.0] {
            for d in [1.0, -1.0] {
                let ageing = Ageing { length, direction: d };
                for x in [0.13, 1.7, 6.0, -4.0] {
                    let h = 1e-5;
                    let fd = |kernel: Kernel| -> [f64; 3] {
                        let (p, m) = (
                            ageing.element_integrals(kind, kernel, s1, s2, x + h),
                            ageing.element_integrals(kind, kernel, s1, s2, x - h),
                        );
                        std::array::from_fn(|a| (p[a] - m[a]) / (2.0 * h))
                    };
                    let (cauchy, dlog) = (
                        ageing.element_integrals(kind, Kernel::Cauchy, s1, s2, x),
                        fd(Kernel::Log),
                    );
                    let (dsign_exact, dsign) = (ageing.sign_derivative_integrals(kind, s1, s2, x), fd(Kernel::Sign));
                    for a in 0..3 {
                        assert!(
                            (cauchy[a] - dlog[a]).abs() < 1e-6 * cauchy[a].abs().max(1e-2),
                            "L={length} d={d} x={x}: {cauchy:?} vs {dlog:?}"
                        );
                        assert!(
                            (dsign_exact[a] - dsign[a]).abs() < 1e-6 * dsign[a].abs().max(1e-2),
                            "L={length} d={d} x={x}: {dsign_exact:?} vs {dsign:?}"
                        );
                    }
                }
            }
        }
    }
}
