//! Closed-form reference solutions in plane strain: the oracles of the validation tests and the
//! estimates printed by `rollbem check`.
//!
//! Conventions of DESIGN §2 (reference sheet §0–§4): P per unit length, E* the contact modulus,
//! R the effective radius 1/R = 1/R_A + 1/R_B, β Dundurs' parameter with A first.

use std::f64::consts::PI;

/// Hertz half-width a = √(4PR/(πE*)) [length] (Johnson eq. 4.43; reference sheet §1).
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

/// Carter's steady rolling solution for similar bodies (β = 0), reference sheet §2, in the
/// frame of DESIGN §2 with the leading edge at x = `leading_edge_sign`·a.
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

    /// Magnitude of the creepage |ξ| = (μa/R)(1 − √(1 − |Q|/(μP))) for effective radius R.
    /// Its sign: ξ has the sign of −Q for material flowing in +x (reference sheet §2) and of Q
    /// for flow in −x, i.e. sgn ξ = sgn(Q)·`leading_edge_sign`.
    pub fn creep(&self, radius: f64) -> f64 {
        let magnitude = self.friction * self.half_width / radius * (1.0 - (1.0 - self.ratio.abs()).sqrt());
        self.ratio.signum() * self.leading_edge_sign * magnitude
    }
}

/// Free rolling, complete-slip limit μ → 0: ξ = 0.914772·β·a/R (reference sheet §4.4a).
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
/// a = a_Hertz/√(1+4ε²) (reference sheet §4.4b). Returns (ξ, a, p(0)).
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
    fn hertz_worked_example_of_reference_sheet() {
        // Steel rollers R = 100 mm each: E* = 115 384.6 MPa, R = 50 mm, a = 1 mm.
        let e_star = 210_000.0 / (2.0 * (1.0 - 0.09));
        let p = hertz_load(1.0, 50.0, e_star);
        assert!((p - 1812.46).abs() < 0.01, "P = {p}");
        assert!((hertz_peak_pressure(p, 1.0) - 1153.85).abs() < 0.01);
        assert!((hertz_pressure(0.5, 1.0, 1153.846) - 999.260).abs() < 1e-2);
    }

    #[test]
    fn carter_worked_example_of_reference_sheet() {
        // Q/μP = 0.51, flow in +x (leading edge −a): ξR/(μa) = −0.3; q/(μp0) table.
        let c = Carter {
            half_width: 1.0,
            peak_pressure: 1.0,
            friction: 1.0,
            ratio: 0.51,
            leading_edge_sign: -1.0,
        };
        assert!((c.creep(1.0) + 0.3).abs() < 1e-12);
        let xs = [-0.9, -0.5, 0.0, 0.5, 0.9];
        let qs = [0.075335, 0.195205, 0.367544, 0.866025, 0.435890];
        for (x, q) in xs.iter().zip(qs) {
            assert!((c.shear(*x) - q).abs() < 1e-6, "x={x}");
        }
    }

    #[test]
    fn free_rolling_limits_of_reference_sheet() {
        // CONTACT's Bentall–Johnson case: β = 0.143834, a = 0.1 mm, R = 25 mm → ξ = 5.26300e−4.
        let xi = free_rolling_creep_complete_slip(0.143834, 0.1, 25.0);
        assert!((xi - 5.26300e-4).abs() < 2e-9, "xi = {xi}");
        let (xi, a, p0) = free_rolling_no_slip(0.143834, 16.2019, 25.0, 51_572.3);
        assert!((xi - 3.67269e-4).abs() < 2e-9, "xi = {xi}");
        assert!((a - 0.0995775).abs() < 1e-7);
        assert!((p0 - 103.788).abs() < 2e-3);
    }
}
