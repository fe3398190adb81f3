//! Isotropic linear-elastic materials in plane strain and the combined constants of a pair.
//!
//! Conventions: `young` E and `shear` G in the case's stress unit (MPa in the shipped cases),
//! `poisson` ν dimensionless, ν ∈ (−1, 0.5]. ν = 0.5 (incompressible) is allowed: nothing here
//! divides by 1 − 2ν.

use serde::Serialize;

/// An isotropic linear-elastic material.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct Elastic {
    /// Young's modulus E [stress].
    pub young: f64,
    /// Poisson's ratio ν [-], in (−1, 0.5].
    pub poisson: f64,
}

impl Elastic {
    /// Builds a material from Young's modulus and Poisson's ratio.
    pub fn new(young: f64, poisson: f64) -> Self {
        Self { young, poisson }
    }

    /// Builds a material from the shear modulus G and Poisson's ratio (E = 2G(1+ν)).
    pub fn from_shear(shear: f64, poisson: f64) -> Self {
        Self::new(2.0 * shear * (1.0 + poisson), poisson)
    }

    /// Shear modulus G = E / (2(1+ν)) [stress].
    pub fn shear(&self) -> f64 {
        self.young / (2.0 * (1.0 + self.poisson))
    }

    /// Plane-strain compliance (1−ν²)/E [1/stress]: half of 2/(πE*)·π for one body.
    pub fn plane_strain_compliance(&self) -> f64 {
        (1.0 - self.poisson * self.poisson) / self.young
    }

    /// Half-plane sliding coefficient A = (1−2ν)(1+ν)/(2E) [1/stress] of the surface
    /// displacement u_x = −A·P·sgn(x) under a normal line load P (reference sheet §3.1).
    pub fn halfplane_sgn_coefficient(&self) -> f64 {
        (1.0 - 2.0 * self.poisson) * (1.0 + self.poisson) / (2.0 * self.young)
    }

    /// Half-plane logarithmic coefficient B = 2(1−ν²)/(πE) [1/stress] of u_z = −B·P·ln|x|
    /// under a normal line load P (reference sheet §3.1).
    pub fn halfplane_log_coefficient(&self) -> f64 {
        2.0 * self.plane_strain_compliance() / std::f64::consts::PI
    }
}

/// Combined contact modulus E* with 1/E* = (1−ν_A²)/E_A + (1−ν_B²)/E_B [stress].
///
/// A rigid body contributes zero compliance; pass `None` for it.
pub fn contact_modulus(a: Option<&Elastic>, b: Option<&Elastic>) -> f64 {
    let c = a.map_or(0.0, Elastic::plane_strain_compliance) + b.map_or(0.0, Elastic::plane_strain_compliance);
    1.0 / c
}

/// Dundurs' second parameter β with body A first (reference sheet §0):
/// β = ½·[(1−2ν_A)/G_A − (1−2ν_B)/G_B] / [(1−ν_A)/G_A + (1−ν_B)/G_B].
///
/// β > 0 when A has the larger (1−2ν)/G (aluminium as A on steel gives β ≈ 0.144). The
/// González–Abascal paper's Eq. 78 omits the ½ and so gives κ = 2β (≈ 0.288 for that pair).
/// A rigid body (`None`) has zero compliance.
pub fn dundurs_beta(a: Option<&Elastic>, b: Option<&Elastic>) -> f64 {
    let dil = |m: Option<&Elastic>| m.map_or(0.0, |m| (1.0 - 2.0 * m.poisson) / m.shear());
    let dev = |m: Option<&Elastic>| m.map_or(0.0, |m| (1.0 - m.poisson) / m.shear());
    0.5 * (dil(a) - dil(b)) / (dev(a) + dev(b))
}

/// Combined radius R with 1/R = 1/R_A + 1/R_B [length] (both convex).
pub fn effective_radius(radius_a: f64, radius_b: f64) -> f64 {
    1.0 / (1.0 / radius_a + 1.0 / radius_b)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn aluminium_on_steel_beta_matches_reference_sheet() {
        // Reference sheet §3.3: G = 23 000 / 82 000 MPa, ν = 0.31 / 0.28 give β_D = 0.143834.
        let al = Elastic::from_shear(23_000.0, 0.31);
        let st = Elastic::from_shear(82_000.0, 0.28);
        let beta = dundurs_beta(Some(&al), Some(&st));
        assert!((beta - 0.143834).abs() < 1e-6, "beta = {beta}");
        assert!((dundurs_beta(Some(&st), Some(&al)) + beta).abs() < 1e-15);
        // E* = 51 572.3 MPa (reference sheet §4.4).
        let e_star = contact_modulus(Some(&al), Some(&st));
        assert!((e_star - 51_572.3).abs() < 0.1, "E* = {e_star}");
    }

    #[test]
    fn sgn_coefficient_difference_is_beta_over_e_star() {
        // A_A − A_B = β/E* (reference sheet §3.3).
        let a = Elastic::new(70_000.0, 0.33);
        let b = Elastic::new(210_000.0, 0.3);
        let lhs = a.halfplane_sgn_coefficient() - b.halfplane_sgn_coefficient();
        let rhs = dundurs_beta(Some(&a), Some(&b)) / contact_modulus(Some(&a), Some(&b));
        assert!((lhs - rhs).abs() < 1e-12 * rhs.abs());
    }
}
