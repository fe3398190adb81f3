//! The exponential integrals the aged half-plane kernels are made of, scaled so that they
//! neither overflow nor underflow for any argument c > 0 (Abramowitz & Stegun §5.1):
//!
//! ```text
//! E1(c) = ∫_c^∞ e^(−t)/t dt,          Ei(c) = PV ∫_−∞^c e^t/t dt,
//! e^c E1(c) ~ 1/c,  e^(−c) Ei(c) ~ 1/c   (c → ∞),
//! ```
//!
//! and the antiderivatives G_k, H_k of c^k e^c E1(c) and c^k e^(−c) Ei(c), which are finite at
//! c = 0 although E1 and Ei are not:
//!
//! ```text
//! G_0 = e^c E1(c) + ln c,   G_k = c^k e^c E1(c) − k G_(k−1) + c^k/k,
//! H_0 = ln c − e^(−c) Ei(c), H_k = −c^k e^(−c) Ei(c) + k H_(k−1) + c^k/k,
//! ```
//!
//! (differentiate: (e^c E1)' = e^c E1 − 1/c and (e^(−c) Ei)' = 1/c − e^(−c) Ei). Near c = 0 the
//! logarithms cancel; G_0 and H_0 are summed there as series in which they cancel exactly.

/// Euler–Mascheroni constant γ.
pub const EULER_GAMMA: f64 = 0.577_215_664_901_532_9;

/// Below this argument the series are summed (A&S 5.1.11, 5.1.10); above it the continued
/// fraction (A&S 5.1.22) or the asymptotic series.
const SERIES_LIMIT: f64 = 1.0;

/// Above this argument e^(−c) Ei(c) is the asymptotic series Σ n!/c^(n+1), whose smallest term
/// there (n ≈ c) is ≈ √(2πc) e^(−c) < 1e-16.
const EI_ASYMPTOTIC_LIMIT: f64 = 40.0;

/// Σ_{n≥1} s^n c^n/(n·n!) for s = ±1: the power-series part of E1 (s = −1) and Ei (s = +1).
fn exponential_integral_series(c: f64, sign: f64) -> f64 {
    let mut term = 1.0; // s^n c^n / n!
    let mut sum = 0.0;
    for n in 1..200 {
        term *= sign * c / n as f64;
        let add = term / n as f64;
        sum += add;
        if add.abs() <= f64::EPSILON * sum.abs() {
            break;
        }
    }
    sum
}

/// e^c E1(c) for c > 0 [-].
pub fn e1_scaled(c: f64) -> f64 {
    if c <= SERIES_LIMIT {
        // E1 = −γ − ln c − Σ (−c)^n/(n·n!).
        return c.exp() * (-EULER_GAMMA - c.ln() - exponential_integral_series(c, -1.0));
    }
    // Modified Lentz evaluation of the continued fraction
    // e^c E1(c) = 1/(c + 1 − 1²/(c + 3 − 2²/(c + 5 − …))).
    let tiny = 1e-300;
    let mut b = c + 1.0;
    let mut cf = 1.0 / tiny;
    let mut d = 1.0 / b;
    let mut h = d;
    for i in 1..500 {
        let an = -((i * i) as f64);
        b += 2.0;
        d = 1.0 / (an * d + b);
        cf = b + an / cf;
        let delta = cf * d;
        h *= delta;
        if (delta - 1.0).abs() <= f64::EPSILON {
            break;
        }
    }
    h
}

/// e^(−c) Ei(c) for c > 0 [-] (Ei as a principal value).
pub fn ei_scaled(c: f64) -> f64 {
    if c <= EI_ASYMPTOTIC_LIMIT {
        // Ei = γ + ln c + Σ c^n/(n·n!); every term positive, so the sum keeps its digits.
        return (-c).exp() * (EULER_GAMMA + c.ln() + exponential_integral_series(c, 1.0));
    }
    let mut term = 1.0 / c;
    let mut sum = term;
    for n in 1..200 {
        let next = term * n as f64 / c;
        if next >= term {
            break;
        }
        term = next;
        sum += term;
        if term <= f64::EPSILON * sum {
            break;
        }
    }
    sum
}

/// G_0(c) = e^c E1(c) + ln c [-], −γ at c = 0 (module docs).
pub fn g0(c: f64) -> f64 {
    if c == 0.0 {
        return -EULER_GAMMA;
    }
    if c <= SERIES_LIMIT {
        // e^c(−γ − Σ) − (e^c − 1) ln c: the ln c of E1 cancelled against + ln c.
        return c.exp() * (-EULER_GAMMA - exponential_integral_series(c, -1.0)) - c.exp_m1() * c.ln();
    }
    e1_scaled(c) + c.ln()
}

/// H_0(c) = ln c − e^(−c) Ei(c) [-], −γ at c = 0 (module docs).
pub fn h0(c: f64) -> f64 {
    if c == 0.0 {
        return -EULER_GAMMA;
    }
    if c <= SERIES_LIMIT {
        // −e^(−c)(γ + Σ) + (1 − e^(−c)) ln c.
        return -(-c).exp() * (EULER_GAMMA + exponential_integral_series(c, 1.0)) - (-c).exp_m1() * c.ln();
    }
    c.ln() - ei_scaled(c)
}

/// [G_0, G_1, G_2] at c ≥ 0 (module docs).
pub fn g_antiderivatives(c: f64) -> [f64; 3] {
    let g0 = g0(c);
    // c^k e^c E1(c) = c^k (G_0 − ln c), which is 0 at c = 0 for k ≥ 1.
    let scaled = if c == 0.0 { 0.0 } else { g0 - c.ln() };
    let g1 = c * scaled - g0 + c;
    let g2 = c * c * scaled - 2.0 * g1 + c * c / 2.0;
    [g0, g1, g2]
}

/// [H_0, H_1, H_2] at c ≥ 0 (module docs).
pub fn h_antiderivatives(c: f64) -> [f64; 3] {
    let h0 = h0(c);
    // c^k e^(−c) Ei(c) = c^k (ln c − H_0).
    let scaled = if c == 0.0 { 0.0 } else { c.ln() - h0 };
    let h1 = -c * scaled + h0 + c;
    let h2 = -c * c * scaled + 2.0 * h1 + c * c / 2.0;
    [h0, h1, h2]
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Values from mpmath 1.3 (`mpmath.e1(c)*mpmath.exp(c)`, `mpmath.ei(c)*mpmath.exp(-c)`, 30
    /// digits) at c = 0.5, 1, 2, 10, 50; A&S Table 5.1 agrees to its 10 digits.
    #[test]
    fn scaled_integrals_match_tabulated_values() {
        let e1 = [
            (0.5, 0.922_910_632_483_730_5),
            (1.0, 0.596_347_362_323_194_1),
            (2.0, 0.361_328_616_888_222_6),
            (10.0, 0.091_563_333_939_788_08),
            (50.0, 0.019_615_109_930_114_87),
        ];
        for (c, want) in e1 {
            assert!(
                (e1_scaled(c) / want - 1.0).abs() < 4e-15,
                "e^c E1({c}) = {} want {want}",
                e1_scaled(c)
            );
        }
        let ei = [
            (0.5, 0.275_498_298_551_270_3),
            (1.0, 0.697_174_883_235_066),
            (2.0, 0.670_482_709_790_073_3),
            (10.0, 0.113_147_020_473_410_8),
            (50.0, 0.020_417_045_555_943_99),
        ];
        for (c, want) in ei {
            assert!(
                (ei_scaled(c) / want - 1.0).abs() < 4e-15,
                "e^-c Ei({c}) = {} want {want}",
                ei_scaled(c)
            );
        }
    }

    /// The antiderivatives differentiate back to their integrands (central differences) on
    /// both sides of the series/fraction switch and near 0.
    #[test]
    fn antiderivatives_differentiate_to_their_integrands() {
        for c in [1e-3f64, 0.3, 0.999, 1.001, 2.5, 39.0, 41.0, 120.0] {
            let h = 1e-5 * c.max(1e-2);
            let (gp, gm) = (g_antiderivatives(c + h), g_antiderivatives(c - h));
            let (hp, hm) = (h_antiderivatives(c + h), h_antiderivatives(c - h));
            for k in 0..3 {
                let ck = c.powi(k as i32);
                let dg = (gp[k] - gm[k]) / (2.0 * h);
                let dh = (hp[k] - hm[k]) / (2.0 * h);
                let (want_g, want_h) = (ck * e1_scaled(c), ck * ei_scaled(c));
                assert!(
                    (dg - want_g).abs() < 1e-7 * want_g.abs().max(1.0),
                    "G_{k}'({c}) = {dg} want {want_g}"
                );
                assert!(
                    (dh - want_h).abs() < 1e-7 * want_h.abs().max(1.0),
                    "H_{k}'({c}) = {dh} want {want_h}"
                );
            }
        }
        assert_eq!(g0(0.0), -EULER_GAMMA);
        assert!((g0(1e-12) + EULER_GAMMA).abs() < 1e-10);
        assert!((h0(1e-12) + EULER_GAMMA).abs() < 1e-10);
    }
}
