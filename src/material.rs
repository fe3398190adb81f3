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
    /// displacement u_x = −A·P·sgn(x) under a normal line load P (docs/references.md §3.1).
    pub fn halfplane_sgn_coefficient(&self) -> f64 {
        (1.0 - 2.0 * self.poisson) * (1.0 + self.poisson) / (2.0 * self.young)
    }

    /// Half-plane logarithmic coefficient B = 2(1−ν²)/(πE) [1/stress] of u_z = −B·P·ln|x|
    /// under a normal line load P (docs/references.md §3.1).
    pub fn halfplane_log_coefficient(&self) -> f64 {
        2.0 * self.plane_strain_compliance() / std::f64::consts::PI
    }
}

/// A standard linear solid (Zener model) with a constant Poisson's ratio: the shear and bulk
/// moduli relax alike, from the glassy (instantaneous) modulus E_g to the rubbery (long-term)
/// one E_r, with creep compliance J(t) = 1/E_r − (1/E_r − 1/E_g)·e^(−t/τc) (Johnson, *Contact
/// Mechanics* §6.2; docs/viscoelastic.md for the other parametrisations).
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct StandardLinearSolid {
    /// Glassy (instantaneous) constants: E_g [stress] and ν [-].
    pub glassy: Elastic,
    /// Rubbery (long-term) Young's modulus E_r ≤ E_g [stress].
    pub rubbery_young: f64,
    /// Creep (retardation) time τc ≥ 0 [time]: the time constant of the creep under constant
    /// stress.
    pub creep_time: f64,
}

impl StandardLinearSolid {
    /// Rubbery (long-term) constants E_r, ν.
    pub fn rubbery(&self) -> Elastic {
        Elastic::new(self.rubbery_young, self.glassy.poisson)
    }

    /// Relaxation time τe = τc·E_r/E_g [time]: the time constant of the stress relaxation under
    /// constant strain.
    pub fn relaxation_time(&self) -> f64 {
        self.creep_time * self.rubbery_young / self.glassy.young
    }

    /// The relaxing fraction f = E_g/E_r − 1 [-] (CONTACT's `FG` when its `GG` is the glassy
    /// modulus).
    pub fn relaxing_fraction(&self) -> f64 {
        self.glassy.young / self.rubbery_young - 1.0
    }
}

/// Combined contact modulus E* with 1/E* = (1−ν_A²)/E_A + (1−ν_B²)/E_B [stress].
///
/// A rigid body contributes zero compliance; pass `None` for it.
pub fn contact_modulus(a: Option<&Elastic>, b: Option<&Elastic>) -> f64 {
    let c = a.map_or(0.0, Elastic::plane_strain_compliance) + b.map_or(0.0, Elastic::plane_strain_compliance);
    1.0 / c
}

/// Dundurs' second parameter β with body A first (docs/references.md §0):
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

/// Material A that gives Dundurs' β (A first, as in [`dundurs_beta`]) against material B.
///
/// A's Poisson's ratio is ν_A = ν_B·(1 − 2|β|) (so β = 0 gives A = B, and a large β gets the
/// more compressible A it needs), and its shear modulus follows from β's definition solved for
/// 1/G_A: with d(ν) = (1 − 2ν) and e(ν) = 2(1 − ν),
/// 1/G_A = (1/G_B)·(d(ν_B) + β e(ν_B)) / (d(ν_A) − β e(ν_A)).
/// β > 0 makes A the softer body (aluminium on steel: β ≈ 0.144).
///
/// Returns `None` when no elastic A reaches β against B: both bracketed factors must be positive
/// (β < 0 needs d(ν_B) − |β| e(ν_B) > 0: a body B of ν = 0.3 admits β > −0.2857 only, the value
/// of a rigid A).
pub fn material_for_beta(b: &Elastic, beta: f64) -> Option<Elastic> {
    let d = |nu: f64| 1.0 - 2.0 * nu;
    let e = |nu: f64| 2.0 * (1.0 - nu);
    let nu_a = b.poisson * (1.0 - 2.0 * beta.abs());
    let (num, den) = (d(b.poisson) + beta * e(b.poisson), d(nu_a) - beta * e(nu_a));
    if !(beta.abs() < 0.5 && num > 0.0 && den > 0.0) {
        return None;
    }
    let shear_a = b.shear() * den / num;
    Some(Elastic::from_shear(shear_a, nu_a))
}

/// Combined radius R* with 1/R* = 1/R_A + 1/R_B [length], radii signed: positive for a convex
/// body, negative for a concave one (internal contact, a roller in a ring's bore: 1/R* =
/// 1/R_roller − 1/|R_bore|). Positive whenever contact is possible (R_A + R_B > 0).
pub fn effective_radius(radius_a: f64, radius_b: f64) -> f64 {
    1.0 / (1.0 / radius_a + 1.0 / radius_b)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn aluminium_on_steel_beta_matches_the_references() {
        // docs/references.md §3.3: G = 23 000 / 82 000 MPa, ν = 0.31 / 0.28 give β_D = 0.143834.
        let al = Elastic::from_shear(23_000.0, 0.31);
        let st = Elastic::from_shear(82_000.0, 0.28);
        let beta = dundurs_beta(Some(&al), Some(&st));
        assert!((beta - 0.143834).abs() < 1e-6, "beta = {beta}");
        assert!((dundurs_beta(Some(&st), Some(&al)) + beta).abs() < 1e-15);
        // E* = 51 572.3 MPa (docs/references.md §4.4).
        let e_star = contact_modulus(Some(&al), Some(&st));
        assert!((e_star - 51_572.3).abs() < 0.1, "E* = {e_star}");
    }

    #[test]
    fn material_for_beta_reaches_the_target_beta() {
        let steel = Elastic::new(210_000.0, 0.3);
        for beta in [-0.2, 0.0, 0.144, 0.288, 0.45] {
            let a = material_for_beta(&steel, beta).expect("reachable");
            let got = dundurs_beta(Some(&a), Some(&steel));
            assert!((got - beta).abs() < 1e-12, "β = {beta}: got {got}");
            assert!(a.young > 0.0 && a.poisson > -1.0 && a.poisson <= 0.5);
        }
        let same = material_for_beta(&steel, 0.0).expect("β = 0");
        assert!((same.young / steel.young - 1.0).abs() < 1e-14 && same.poisson == steel.poisson);
        assert!(material_for_beta(&steel, -0.3).is_none() && material_for_beta(&steel, 0.5).is_none());
    }

    #[test]
    fn sgn_coefficient_difference_is_beta_over_e_star() {
        // A_A − A_B = β/E* (docs/references.md §3.3).
        let a = Elastic::new(70_000.0, 0.33);
        let b = Elastic::new(210_000.0, 0.3);
        let lhs = a.halfplane_sgn_coefficient() - b.halfplane_sgn_coefficient();
        let rhs = dundurs_beta(Some(&a), Some(&b)) / contact_modulus(Some(&a), Some(&b));
        assert!((lhs - rhs).abs() < 1e-12 * rhs.abs());
    }
}

/// The yield criterion of a strength assessment (`output.strength.criterion`): which
/// equivalent shear stress τ_eq reaches the shear yield stress k ([`crate::post::strength`]).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, serde::Deserialize, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum YieldCriterion {
    /// von Mises, τ_eq = σ_vm/√3, k = Y/√3.
    #[default]
    VonMises,
    /// Tresca over the three principal stresses, τ_eq = (σ_max − σ_min)/2, k = Y/2.
    Tresca,
}

impl YieldCriterion {
    /// The name in cases and outputs (`von_mises`, `tresca`).
    pub fn name(self) -> &'static str {
        match self {
            YieldCriterion::VonMises => "von_mises",
            YieldCriterion::Tresca => "tresca",
        }
    }

    /// The shear yield stress k [stress] of a material with uniaxial (tensile) yield stress
    /// `tensile` Y [stress]: Y/√3 for von Mises, Y/2 for Tresca (Johnson 1985 §1.3).
    pub fn shear_yield_of_tensile(self, tensile: f64) -> f64 {
        match self {
            YieldCriterion::VonMises => tensile / 3f64.sqrt(),
            YieldCriterion::Tresca => 0.5 * tensile,
        }
    }
}

/// A material's yield stress as the case gives it (`materials.NAME.yield`).
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum YieldStress {
    /// The shear yield stress k [stress], used as given by either criterion.
    Shear(f64),
    /// The uniaxial (tensile) yield stress Y [stress], turned into k by the criterion.
    Tensile(f64),
}

impl YieldStress {
    /// The shear yield stress k [stress] under `criterion`.
    pub fn shear_yield(self, criterion: YieldCriterion) -> f64 {
        match self {
            YieldStress::Shear(k) => k,
            YieldStress::Tensile(y) => criterion.shear_yield_of_tensile(y),
        }
    }
}
