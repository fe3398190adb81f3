//! Closed-form reference solutions in plane strain: the oracles of the validation tests and the
//! estimates printed by `rollbem check`.
//!
//! Conventions of docs/theory.md (docs/references.md §0–§4): P per unit length, E* the contact modulus,
//! R the effective radius 1/R = 1/R_A + 1/R_B, β Dundurs' parameter with A first.

pub mod conformal;
pub mod creepage;
pub mod mcewen;
pub mod michell;

use std::f64::consts::PI;

/// Hertz half-width a = √(4PR/(πE*)) [length] (Johnson eq. 4.43; docs/references.md §1).
pub fn hertz_half_width(load: f64, radius: f64, e_star: f64) -> f64 {
    (4.0 * load * radius / (PI * e_star)).sqrt()
}

/// Hertz peak pressure p0 = 2P/(πa) [stress].
pub fn hertz_peak_pressure(load: f64, half_width: f64) -> f64 {
    2.0 * load / (PI * half_width)
}

/// Load P = πa²E*/(4R) that gives the Hertz half-width a [force/length].
pub fn hertz_load(half_width: f64, radius: f64, e_star: f64) -> f64 {
    PI * half_width * half_width * e_star / (4.0 * radius)
}

/// Hertz pressure p0·√(1 − x²/a²) (zero outside the contact) [stress].
pub fn hertz_pressure(x: f64, half_width: f64, peak: f64) -> f64 {
    let t = 1.0 - (x / half_width).powi(2);
    if t > 0.0 {
        peak * t.sqrt()
    } else {
        0.0
    }
}

/// Carter's steady rolling solution for similar bodies (β = 0), docs/references.md §2, in the
/// frame of docs/theory.md with the leading edge at x = `leading_edge_sign`·a.
#[derive(Debug, Clone, Copy)]
pub struct Carter {
    /// Hertz half-width a [length].
    pub half_width: f64,
    /// Hertz peak pressure p0 [stress].
    pub peak_pressure: f64,
    /// Friction coefficient μ.
    pub friction: f64,
    /// Load ratio Q/(μP) ∈ (−1, 1).
    pub ratio: f64,
    /// +1 when the leading edge is at x = +a (rolling in +x), −1 otherwise.
    pub leading_edge_sign: f64,
}

impl Carter {
    /// Stick half-width c = a√(1 − |Q|/(μP)) [length].
    pub fn stick_half_width(&self) -> f64 {
        self.half_width * (1.0 - self.ratio.abs()).sqrt()
    }

    /// Centre of the stick zone, which touches the leading edge [length].
    pub fn stick_centre(&self) -> f64 {
        self.leading_edge_sign * (self.half_width - self.stick_half_width())
    }

    /// Stick zone [x0, x1] [length].
    pub fn stick_zone(&self) -> [f64; 2] {
        let (d, c) = (self.stick_centre(), self.stick_half_width());
        [d - c, d + c]
    }

    /// Shear q(x) = sgn(Q)·μ[p0√(1−x²/a²) − p0(c/a)√(1−(x−d)²/c²)] [stress].
    pub fn shear(&self, x: f64) -> f64 {
        let (a, c, d) = (self.half_width, self.stick_half_width(), self.stick_centre());
        let outer = hertz_pressure(x, a, self.peak_pressure);
        let inner = hertz_pressure(x - d, c, self.peak_pressure * c / a);
        self.ratio.signum() * self.friction * (outer - inner)
    }

    /// Slip s(x) = velocity of A relative to B divided by |V| [-] (docs/references.md §2, mirrored
    /// into the frame of docs/theory.md): zero in the stick zone and outside the contact, and in the
    /// slip zone s = −sgn(Q)·(μ/R)·√((x − d)² − c²), with d the stick-zone centre, c its
    /// half-width and R the effective radius. The sign does not depend on the rolling
    /// direction: Coulomb's q = −μp·sgn(s) with q = sgn(Q)·μp in the slip zone.
    pub fn slip(&self, x: f64, radius: f64) -> f64 {
        let (c, d) = (self.stick_half_width(), self.stick_centre());
        if x.abs() >= self.half_width || (x - d).abs() <= c {
            return 0.0;
        }
        -self.ratio.signum() * self.friction / radius * ((x - d).powi(2) - c * c).sqrt()
    }

    /// Magnitude of the creepage |ξ| = (μa/R)(1 − √(1 − |Q|/(μP))) for effective radius R.
    /// Its sign: ξ has the sign of −Q for material flowing in +x (docs/references.md §2) and of Q
    /// for flow in −x, i.e. sgn ξ = sgn(Q)·`leading_edge_sign`.
    pub fn creep(&self, radius: f64) -> f64 {
        let magnitude = self.friction * self.half_width / radius * (1.0 - (1.0 - self.ratio.abs()).sqrt());
        self.ratio.signum() * self.leading_edge_sign * magnitude
    }
}

/// Free rolling, complete-slip limit μ → 0: ξ = 0.914772·β·a/R (docs/references.md §4.4a).
pub fn free_rolling_creep_complete_slip(beta: f64, half_width: f64, radius: f64) -> f64 {
    // t0 solves t√(1−t²) + asin t = π/4: the central zone carries half the load.
    let mut t: f64 = 0.4;
    for _ in 0..50 {
        let f = t * (1.0 - t * t).sqrt() + t.asin() - PI / 4.0;
        let df = 2.0 * (1.0 - t * t).sqrt();
        t -= f / df;
    }
    beta * half_width / radius * (1.0 - t * t).sqrt()
}

/// Bufler's oscillation index ε = ln((1+β)/(1−β))/(2π).
pub fn bufler_epsilon(beta: f64) -> f64 {
    ((1.0 + beta) / (1.0 - beta)).ln() / (2.0 * PI)
}

/// Free rolling, no-slip limit μ → ∞ (Bufler): ξ = 2εa/R with a the actual half-width
/// a = a_Hertz/√(1+4ε²) (docs/references.md §4.4b). Returns (ξ, a, p(0)).
pub fn free_rolling_no_slip(beta: f64, load: f64, radius: f64, e_star: f64) -> (f64, f64, f64) {
    let eps = bufler_epsilon(beta);
    let a = hertz_half_width(load, radius, e_star) / (1.0 + 4.0 * eps * eps).sqrt();
    let p_centre = e_star * a / (2.0 * radius) * (PI * eps).cosh();
    (2.0 * eps * a / radius, a, p_centre)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn hertz_worked_example_of_the_references() {
        // Steel rollers R = 100 mm each: E* = 115 384.6 MPa, R = 50 mm, a = 1 mm.
        let e_star = 210_000.0 / (2.0 * (1.0 - 0.09));
        let p = hertz_load(1.0, 50.0, e_star);
        assert!((p - 1812.46).abs() < 0.01, "P = {p}");
        assert!((hertz_peak_pressure(p, 1.0) - 1153.85).abs() < 0.01);
        assert!((hertz_pressure(0.5, 1.0, 1153.846) - 999.260).abs() < 1e-2);
    }

    #[test]
    fn carter_worked_example_of_the_references() {
        // Q/μP = 0.51, flow in +x (leading edge −a): ξR/(μa) = −0.3; q/(μp0) table.
        let c = Carter {
            half_width: 1.0,
            peak_pressure: 1.0,
            friction: 1.0,
            ratio: 0.51,
            leading_edge_sign: -1.0,
        };
        assert!((c.creep(1.0) + 0.3).abs() < 1e-12);
        // Slip: sR/(μa) = −2√(1 − c/a) = −1.09545 at the trailing edge (+a here), −0.427083 at
        // x/a = 0.52 (sheet §2, its trailing edge) and 0 in the stick zone [−1, 0.4].
        assert!((c.slip(0.999_999_999, 1.0) + 1.09545).abs() < 1e-5);
        assert!((c.slip(0.52, 1.0) + 0.427083).abs() < 1e-6);
        assert_eq!(c.slip(0.0, 1.0), 0.0);
        // Mirrored (leading edge +a): the trailing edge is −a, same sign of the slip.
        let m = Carter {
            leading_edge_sign: 1.0,
            ..c
        };
        assert!((m.slip(-0.52, 1.0) + 0.427083).abs() < 1e-6);
        let xs = [-0.9, -0.5, 0.0, 0.5, 0.9];
        let qs = [0.075335, 0.195205, 0.367544, 0.866025, 0.435890];
        for (x, q) in xs.iter().zip(qs) {
            assert!((c.shear(*x) - q).abs() < 1e-6, "x={x}");
        }
    }

    #[test]
    fn free_rolling_limits_of_the_references() {
        // CONTACT's Bentall–Johnson case: β = 0.143834, a = 0.1 mm, R = 25 mm → ξ = 5.26300e−4.
        let xi = free_rolling_creep_complete_slip(0.143834, 0.1, 25.0);
        assert!((xi - 5.26300e-4).abs() < 2e-9, "xi = {xi}");
        let (xi, a, p0) = free_rolling_no_slip(0.143834, 16.2019, 25.0, 51_572.3);
        assert!((xi - 3.67269e-4).abs() < 2e-9, "xi = {xi}");
        assert!((a - 0.0995775).abs() < 1e-7);
        assert!((p0 - 103.788).abs() < 2e-3);
    }
}

/// Shape factor h(ρ, ν) of the approach of an annulus bonded to a rigid shaft (ρ = r_s/R) under
/// one Hertz contact (docs/references.md §6c, Michell series with the n = 1 log terms):
/// h = t0 + t1 + t2 + t3, t3 = −Σ_{n≥2} [c_n(ρ) − c_n(0)].
pub fn shaft_roller_shape_factor(rho: f64, nu: f64) -> f64 {
    let k = 3.0 - 4.0 * nu;
    let t0 = 0.25 * (1.0 - 2.0 * nu) * ((1.0 - rho * rho) / (1.0 + (1.0 - 2.0 * nu) * rho * rho) - 2.0);
    let r4 = rho.powi(4);
    let t1 = -(k * rho.ln()
        + (nu * k - 2.0 * (1.0 - 2.0 * nu) * rho * rho + (2.0 - 7.0 * nu + 4.0 * nu * nu) * r4) / (1.0 + k * r4))
        / (8.0 * (1.0 - nu));
    let t2 = -(1.0 - nu) * std::f64::consts::LN_2 + k / 8.0;
    let c_zero = |n: f64| (1.0 - 2.0 * nu - 2.0 * n * (1.0 - nu)) / (2.0 * (n * n - 1.0));
    let mut t3 = 0.0;
    for n in 2..400 {
        let term = shaft_series_coefficient(n as f64, rho, nu) - c_zero(n as f64);
        t3 -= term;
        if term.abs() < 1e-17 {
            break;
        }
    }
    t0 + t1 + t2 + t3
}

/// c_n(ρ) of docs/references.md §6c: ½[−(n+4ν−2)b1 − n b2 + (n−4ν+2)b3' ρ^{n−1} + n b4' ρ^{n+1}]
/// with (b1, b2, b3', b4') from the 4×4 boundary-condition system of the Michell term n.
fn shaft_series_coefficient(n: f64, x: f64, nu: f64) -> f64 {
    let (xm, xp) = (x.powf(n - 1.0), x.powf(n + 1.0));
    let a = nalgebra::Matrix4::new(
        -(n - 2.0) * (n + 1.0),
        -n * (n - 1.0),
        -(n - 1.0) * (n + 2.0) * xm,
        -n * (n + 1.0) * xp,
        n * (n + 1.0),
        n * (n - 1.0),
        -n * (n - 1.0) * xm,
        -n * (n + 1.0) * xp,
        -(n + 4.0 * nu - 2.0) * xp,
        -n * xm,
        n - 4.0 * nu + 2.0,
        n,
        (n - 4.0 * nu + 4.0) * xp,
        n * xm,
        n + 4.0 * nu - 4.0,
        n,
    );
    let b = a
        .lu()
        .solve(&nalgebra::Vector4::new(-1.0, 0.0, 0.0, 0.0))
        .unwrap_or_else(nalgebra::Vector4::zeros);
    0.5 * (-(n + 4.0 * nu - 2.0) * b[0] - n * b[1] + (n - 4.0 * nu + 2.0) * b[2] * xm + n * b[3] * xp)
}

/// Approach of the contact point towards the centre of a roller of radius R bonded to a rigid
/// shaft of radius r_s, under one Hertz contact of half-width a and load P per unit length
/// (docs/references.md §6c): δ = (2P(1−ν²)/(πE))(ln(4R/a) − ½) + (P/(πG))·h(r_s/R, ν), up to
/// O(a/R) [length].
pub fn shaft_roller_approach(
    load: f64,
    radius: f64,
    shaft_radius: f64,
    half_width: f64,
    material: &crate::material::Elastic,
) -> f64 {
    let (e, nu) = (material.young, material.poisson);
    2.0 * load * (1.0 - nu * nu) / (std::f64::consts::PI * e) * ((4.0 * radius / half_width).ln() - 0.5)
        + load / (std::f64::consts::PI * material.shear()) * shaft_roller_shape_factor(shaft_radius / radius, nu)
}

#[cfg(test)]
mod shaft_tests {
    use super::*;

    #[test]
    fn shape_factor_matches_the_references_table() {
        for (rho, nu, h) in [
            (0.1, 0.3, 0.268286),
            (0.2, 0.3, 0.003146),
            (0.5, 0.3, -0.538345),
            (0.1, 0.25, 0.274411),
        ] {
            let got = shaft_roller_shape_factor(rho, nu);
            assert!((got - h).abs() < 2e-6, "h({rho}, {nu}) = {got}, sheet {h}");
        }
    }

    #[test]
    fn approach_of_the_steel_rollers_worked_example() {
        // docs/references.md §6c: R = 150 and 300 mm on shafts ρ = 0.1, steel, a = 1 mm, P = 906.229.
        let steel = crate::material::Elastic::new(210_000.0, 0.3);
        let d1 = shaft_roller_approach(906.229, 150.0, 15.0, 1.0, &steel);
        let d2 = shaft_roller_approach(906.229, 300.0, 30.0, 1.0, &steel);
        assert!((d1 - 1.570049e-2).abs() < 2e-8, "{d1}");
        assert!((d2 - 1.743336e-2).abs() < 2e-8, "{d2}");
    }
}
