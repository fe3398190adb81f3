//! Michell/Fourier series for a plane-strain elastic annulus with one rim fixed (u = 0) and the
//! other loaded by a boundary traction: the compliance of each Fourier mode, exact to rounding.
//!
//! Polar coordinates (r, θ) about the annulus centre, e_θ = ∂e_r/∂θ. A load symmetric about
//! θ = 0 has the Fourier form
//!
//! ```text
//! σ_rr = Σ T_n cos nθ,   σ_rθ = Σ S_n sin nθ        (on the loaded rim)
//! u_r  = Σ U_n cos nθ,   u_θ  = Σ V_n sin nθ        (n = 0, 1, 2, …)
//! ```
//!
//! with stresses positive in tension (a contact pressure p is σ_rr = −p on either rim) and u
//! the displacement relative to the fixed rim. The field of mode n is a combination of four
//! Michell terms (Michell 1899; Barber, *Elasticity*, problems in polar coordinates), written
//! here as Kolosov–Muskhelishvili potentials with real coefficients (Muskhelishvili, *Some basic
//! problems of the mathematical theory of elasticity*):
//!
//! ```text
//! 2G(u_r + i u_θ) = e^{−iθ} [κ φ(z) − z conj φ'(z) − conj ψ(z)]                    (M1)
//! σ_rr − i σ_rθ   = φ' + conj φ' − e^{2iθ} [conj z φ''(z) + ψ'(z)]                 (M2)
//! ```
//!
//! κ = 3 − 4ν (plane strain). φ = c z^k gives mode |k − 1| and ψ = d z^k mode |k + 1|:
//!
//! ```text
//! φ = c z^k:  2G U = c r^k (κ − k),  2G V = ±c r^k (κ + k),  T = c k(3 − k) r^{k−1},  S = ±c k(k − 1) r^{k−1}
//! ψ = d z^k:  2G U = −d r^k,         2G V = ±d r^k,          T = −d k r^{k−1},        S = ±d k r^{k−1}
//! ```
//!
//! (± the sign of k − 1, resp. k + 1). Mode n ≥ 2 uses φ: z^{n+1}, z^{1−n} and ψ: z^{n−1},
//! z^{−n−1}. Mode 1 uses φ = z², ψ = z^{−2}, a rigid translation and the pair that carries a net
//! force through every circle, φ = γ ln z, ψ = −κγ ln z, which keeps u single-valued:
//!
//! ```text
//! 2G U = γ(2κ ln r − 1),  2G V = −γ(2κ ln r + 1),  T = (3 + κ)γ/r,  S = (1 − κ)γ/r,
//! force carried in +x by the material outside the circle r on the material inside: 2π(1 + κ)γ.   (M3)
//! ```
//!
//! Mode 0 (symmetric) is Lamé's pair φ = z, ψ = 1/z. Each term is scaled by the radius of the
//! rim where it is largest (growing powers by the outer, decaying by the inner radius), so the
//! 4 × 4 system of the boundary conditions stays well conditioned for thousands of modes.

use crate::material::Elastic;
use nalgebra::{Matrix2, Matrix4, Vector2, Vector4};

/// Why an annulus cannot be built.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum MichellError {
    /// The radii do not describe an annulus (0 < inner < outer, both finite).
    #[error("annulus radii must satisfy 0 < inner < outer (got inner = {inner}, outer = {outer})")]
    Radii {
        /// Inner radius [length].
        inner: f64,
        /// Outer radius [length].
        outer: f64,
    },
    /// The material is not a plane-strain elastic solid (E > 0, −1 < ν ≤ 0.5).
    #[error("material must have E > 0 and −1 < ν ≤ 0.5 (got E = {young}, ν = {poisson})")]
    Material {
        /// Young's modulus [stress].
        young: f64,
        /// Poisson's ratio [-].
        poisson: f64,
    },
}

/// Which rim of the annulus carries the load; the other one is fixed (u = 0).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum LoadedRim {
    /// Loaded at r = inner radius, fixed at the outer radius (a ring pressed from its bore).
    Inner,
    /// Loaded at r = outer radius, fixed at the inner radius (a roller on a rigid shaft).
    Outer,
}

/// Fourier amplitudes of the displacement and the traction components at one radius, for one
/// mode n: u_r = `radial_displacement`·cos nθ, u_θ = `tangential_displacement`·sin nθ,
/// σ_rr = `radial_stress`·cos nθ, σ_rθ = `shear_stress`·sin nθ. Displacements [length],
/// stresses [stress], tension positive.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ModeAmplitudes {
    /// U_n [length].
    pub radial_displacement: f64,
    /// V_n [length].
    pub tangential_displacement: f64,
    /// T_n [stress].
    pub radial_stress: f64,
    /// S_n [stress].
    pub shear_stress: f64,
}

/// Compliance of one Fourier mode at the loaded rim: (U_n, V_n) = C·(T_n, S_n) [length/stress].
/// For n = 0 only `radial_from_radial` is meaningful (the symmetric mode has no u_θ, σ_rθ).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ModeCompliance {
    /// ∂U_n/∂T_n.
    pub radial_from_radial: f64,
    /// ∂U_n/∂S_n.
    pub radial_from_shear: f64,
    /// ∂V_n/∂T_n.
    pub tangential_from_radial: f64,
    /// ∂V_n/∂S_n.
    pub tangential_from_shear: f64,
}

impl ModeCompliance {
    /// (U_n, V_n) [length] under the traction amplitudes (T_n, S_n) [stress].
    pub fn displacement(&self, radial_stress: f64, shear_stress: f64) -> (f64, f64) {
        (
            self.radial_from_radial * radial_stress + self.radial_from_shear * shear_stress,
            self.tangential_from_radial * radial_stress + self.tangential_from_shear * shear_stress,
        )
    }
}

/// One Michell term of a mode (see the module documentation).
#[derive(Debug, Clone, Copy)]
enum Term {
    /// φ = c z^k.
    Phi(i32),
    /// ψ = d z^k.
    Psi(i32),
    /// φ = γ ln(z/L), ψ = −κγ ln(z/L), L the loaded radius.
    ForcePair,
    /// Rigid translation along +x.
    Translation,
}

/// A plane-strain annulus inner ≤ r ≤ outer, fixed on one rim and loaded on the other.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Annulus {
    inner: f64,
    outer: f64,
    material: Elastic,
    loaded: LoadedRim,
}

impl Annulus {
    /// The annulus `inner` ≤ r ≤ `outer` [length] of `material`, loaded on the rim `loaded` and
    /// fixed (u = 0, bonded to a rigid body) on the other.
    pub fn new(inner: f64, outer: f64, material: Elastic, loaded: LoadedRim) -> Result<Self, MichellError> {
        if !(inner > 0.0 && outer > inner && outer.is_finite()) {
            return Err(MichellError::Radii { inner, outer });
        }
        let (young, poisson) = (material.young, material.poisson);
        if !(young > 0.0 && young.is_finite() && poisson > -1.0 && poisson <= 0.5) {
            return Err(MichellError::Material { young, poisson });
        }
        Ok(Self {
            inner,
            outer,
            material,
            loaded,
        })
    }

    /// Radius of the loaded rim [length].
    pub fn loaded_radius(&self) -> f64 {
        match self.loaded {
            LoadedRim::Inner => self.inner,
            LoadedRim::Outer => self.outer,
        }
    }

    /// Radius of the fixed rim [length].
    pub fn fixed_radius(&self) -> f64 {
        match self.loaded {
            LoadedRim::Inner => self.outer,
            LoadedRim::Outer => self.inner,
        }
    }

    /// Which rim is loaded.
    pub fn loaded_rim(&self) -> LoadedRim {
        self.loaded
    }

    /// The material.
    pub fn material(&self) -> Elastic {
        self.material
    }

    fn kappa(&self) -> f64 {
        3.0 - 4.0 * self.material.poisson
    }

    /// The Michell terms of mode n (n = 0: two terms, the radial problem only).
    fn terms(n: usize) -> Vec<Term> {
        let n = n as i32;
        match n {
            0 => vec![Term::Phi(1), Term::Psi(-1)],
            1 => vec![Term::Phi(2), Term::Psi(-2), Term::ForcePair, Term::Translation],
            _ => vec![Term::Phi(n + 1), Term::Phi(1 - n), Term::Psi(n - 1), Term::Psi(-n - 1)],
        }
    }

    /// Amplitudes of one term (unit coefficient, scaled as in the module docs) at radius r.
    fn term_amplitudes(&self, term: Term, r: f64) -> ModeAmplitudes {
        let (g2, kappa) = (2.0 * self.material.shear(), self.kappa());
        // Growing powers are scaled by the outer radius, decaying ones by the inner radius.
        let scale = |k: i32| if k >= 0 { self.outer } else { self.inner };
        let sign = |m: i32| if m < 0 { -1.0 } else { 1.0 };
        match term {
            Term::Phi(k) => {
                let l = scale(k);
                let (x, kf) = (r / l, k as f64);
                let (xk, xk1) = (x.powi(k), x.powi(k - 1));
                let s = sign(k - 1);
                ModeAmplitudes {
                    radial_displacement: l * xk * (kappa - kf) / g2,
                    tangential_displacement: s * l * xk * (kappa + kf) / g2,
                    radial_stress: kf * (3.0 - kf) * xk1,
                    shear_stress: s * kf * (kf - 1.0) * xk1,
                }
            }
            Term::Psi(k) => {
                let l = scale(k);
                let (x, kf) = (r / l, k as f64);
                let (xk, xk1) = (x.powi(k), x.powi(k - 1));
                let s = sign(k + 1);
                ModeAmplitudes {
                    radial_displacement: -l * xk / g2,
                    tangential_displacement: s * l * xk / g2,
                    radial_stress: -kf * xk1,
                    shear_stress: s * kf * xk1,
                }
            }
            Term::ForcePair => {
                let l = self.loaded_radius();
                let ln = (r / l).ln();
                ModeAmplitudes {
                    radial_displacement: l * (2.0 * kappa * ln - 1.0) / g2,
                    tangential_displacement: -l * (2.0 * kappa * ln + 1.0) / g2,
                    radial_stress: (3.0 + kappa) * l / r,
                    shear_stress: (1.0 - kappa) * l / r,
                }
            }
            Term::Translation => {
                let l = self.loaded_radius() / g2;
                ModeAmplitudes {
                    radial_displacement: l,
                    tangential_displacement: -l,
                    radial_stress: 0.0,
                    shear_stress: 0.0,
                }
            }
        }
    }

    /// Coefficients of the terms of mode n that satisfy u = 0 on the fixed rim and
    /// (σ_rr, σ_rθ) = (T_n, S_n) cos/sin nθ on the loaded rim.
    fn coefficients(&self, n: usize, radial_stress: f64, shear_stress: f64) -> Vec<f64> {
        let terms = Self::terms(n);
        let (rf, rl) = (self.fixed_radius(), self.loaded_radius());
        if n == 0 {
            let f: Vec<_> = terms.iter().map(|&t| self.term_amplitudes(t, rf)).collect();
            let l: Vec<_> = terms.iter().map(|&t| self.term_amplitudes(t, rl)).collect();
            let a = Matrix2::new(
                f[0].radial_displacement,
                f[1].radial_displacement,
                l[0].radial_stress,
                l[1].radial_stress,
            );
            // The Lamé system is regular for every annulus with ν < 0.5 (determinant ∝ 1 + (1−2ν)ρ²
            // or its ring analogue), so the solve cannot fail on a validated annulus.
            let c = a
                .lu()
                .solve(&Vector2::new(0.0, radial_stress))
                .unwrap_or_else(Vector2::zeros);
            return c.iter().copied().collect();
        }
        let mut a = Matrix4::zeros();
        for (j, &t) in terms.iter().enumerate() {
            let (f, l) = (self.term_amplitudes(t, rf), self.term_amplitudes(t, rl));
            a[(0, j)] = f.radial_displacement;
            a[(1, j)] = f.tangential_displacement;
            a[(2, j)] = l.radial_stress;
            a[(3, j)] = l.shear_stress;
        }
        let rhs = Vector4::new(0.0, 0.0, radial_stress, shear_stress);
        let c = a.lu().solve(&rhs).unwrap_or_else(Vector4::zeros);
        c.iter().copied().collect()
    }

    /// Amplitudes of mode n at radius r (inner ≤ r ≤ outer) for the traction amplitudes
    /// (T_n, S_n) [stress] on the loaded rim (S_0 is ignored: mode 0 is the radial problem).
    pub fn mode_field(&self, n: usize, radial_stress: f64, shear_stress: f64, r: f64) -> ModeAmplitudes {
        let c = self.coefficients(n, radial_stress, shear_stress);
        let mut out = ModeAmplitudes {
            radial_displacement: 0.0,
            tangential_displacement: 0.0,
            radial_stress: 0.0,
            shear_stress: 0.0,
        };
        for (&t, cj) in Self::terms(n).iter().zip(c) {
            let a = self.term_amplitudes(t, r);
            out.radial_displacement += cj * a.radial_displacement;
            out.tangential_displacement += cj * a.tangential_displacement;
            out.radial_stress += cj * a.radial_stress;
            out.shear_stress += cj * a.shear_stress;
        }
        if n == 0 {
            out.tangential_displacement = 0.0;
            out.shear_stress = 0.0;
        }
        out
    }

    /// Compliance of mode n at the loaded rim.
    pub fn compliance(&self, n: usize) -> ModeCompliance {
        let r = self.loaded_radius();
        let from_t = self.mode_field(n, 1.0, 0.0, r);
        if n == 0 {
            return ModeCompliance {
                radial_from_radial: from_t.radial_displacement,
                radial_from_shear: 0.0,
                tangential_from_radial: 0.0,
                tangential_from_shear: 0.0,
            };
        }
        let from_s = self.mode_field(n, 0.0, 1.0, r);
        ModeCompliance {
            radial_from_radial: from_t.radial_displacement,
            radial_from_shear: from_s.radial_displacement,
            tangential_from_radial: from_t.tangential_displacement,
            tangential_from_shear: from_s.tangential_displacement,
        }
    }

    /// Compliances of modes 0..=`modes`.
    pub fn compliances(&self, modes: usize) -> Vec<ModeCompliance> {
        (0..=modes).map(|n| self.compliance(n)).collect()
    }

    /// Force per unit length in +x [force/length] that the material outside the circle r
    /// exerts on the material inside it, for the mode-1 traction amplitudes (T_1, S_1) on the
    /// loaded rim: πr(T_1(r) − S_1(r)) from the stresses at r (the same for every r, by
    /// equilibrium, when the field is right).
    pub fn mode_one_force(&self, radial_stress: f64, shear_stress: f64, r: f64) -> f64 {
        let a = self.mode_field(1, radial_stress, shear_stress, r);
        std::f64::consts::PI * r * (a.radial_stress - a.shear_stress)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::f64::consts::PI;

    fn steel() -> Elastic {
        Elastic::new(210_000.0, 0.3)
    }

    #[test]
    fn bonded_core_is_lame() {
        // docs/references.md §8.2: annulus on a rigid core r_s = 15, R = 150, p = 30 MPa, steel:
        // u_r(R) = −1.098748e−2 mm, σ_rr(r_s) = −41.832669 MPa.
        let a = Annulus::new(15.0, 150.0, steel(), LoadedRim::Outer).unwrap();
        let u = a.compliance(0).radial_from_radial * -30.0;
        assert!((u + 1.098748e-2).abs() < 1e-8, "u = {u}");
        let s = a.mode_field(0, -30.0, 0.0, 15.0);
        assert!((s.radial_stress + 41.832669).abs() < 1e-5, "{s:?}");
    }

    #[test]
    fn ring_with_fixed_rim_under_bore_pressure_is_lame() {
        // u(b) = 0, σ_rr(a) = −p: A = −p/(1 + (1−2ν)b²/a²), B = −(1−2ν)A b², u_r = ((1+ν)/E)((1−2ν)A r + B/r).
        let (ri, ro, p) = (50.0, 65.0, 100.0);
        let m = steel();
        let nu = m.poisson;
        let a_ = -p / (1.0 + (1.0 - 2.0 * nu) * ro * ro / (ri * ri));
        let b_ = -(1.0 - 2.0 * nu) * a_ * ro * ro;
        let u = (1.0 + nu) / m.young * ((1.0 - 2.0 * nu) * a_ * ri + b_ / ri);
        let ring = Annulus::new(ri, ro, m, LoadedRim::Inner).unwrap();
        let got = ring.compliance(0).radial_from_radial * -p;
        assert!((got - u).abs() < 1e-12 * u.abs().max(1e-3), "{got} vs {u}");
    }

    /// Solid disc (radius R) and infinite plate with a hole (radius R) under σ_rr = −p cos nθ,
    /// σ_rθ = 0, n ≥ 2 (derived from (M1)–(M2) with the regular, resp. decaying, terms only):
    /// disc U = −(pR/4G)[κ/(n+1) + 1/(n−1)], V = (pR/4G)[1/(n−1) − κ/(n+1)];
    /// plate U = (pR/4G)[κ/(n−1) + 1/(n+1)].
    #[test]
    fn small_core_and_far_rim_reach_the_solid_disc_and_the_infinite_plate() {
        let m = steel();
        let (g, k) = (m.shear(), 3.0 - 4.0 * m.poisson);
        let r = 10.0;
        let disc = Annulus::new(1e-3, r, m, LoadedRim::Outer).unwrap();
        let plate = Annulus::new(r, 1e4, m, LoadedRim::Inner).unwrap();
        for n in [2usize, 3, 7, 40, 400, 4000] {
            let nf = n as f64;
            let c = disc.compliance(n);
            let u = -(r / (4.0 * g)) * (k / (nf + 1.0) + 1.0 / (nf - 1.0));
            let v = (r / (4.0 * g)) * (1.0 / (nf - 1.0) - k / (nf + 1.0));
            // Under σ_rr = −cos nθ.
            // The rigid core of radius 1e−4 R changes mode n by O(1e−4^(2n−2)): 1e−8 at n = 2.
            assert!((-c.radial_from_radial - u).abs() < 1e-7 * u.abs(), "disc U n={n}");
            assert!((-c.tangential_from_radial - v).abs() < 1e-7 * u.abs(), "disc V n={n}");
            let up = (r / (4.0 * g)) * (k / (nf - 1.0) + 1.0 / (nf + 1.0));
            let cp = plate.compliance(n);
            // The fixed rim at 1000R changes mode 2 by O((R/R_o)²) = 1e−6 (4.5e−6 measured).
            assert!(
                (-cp.radial_from_radial - up).abs() < 1e-5 * up.abs(),
                "plate U n={n}: {} vs {up}",
                -cp.radial_from_radial
            );
        }
    }

    #[test]
    fn high_modes_are_the_half_plane() {
        // Half-plane under p cos(kx): surface displacement into the body (κ+1)p/(4Gk), k = n/R,
        // so U_n = (κ+1)R/(4Gn) per unit T_n (tension moves the rim out), to O(1/n).
        let a = Annulus::new(5.0, 40.0, steel(), LoadedRim::Outer).unwrap();
        let (g, k) = (steel().shear(), 3.0 - 4.0 * 0.3);
        for n in [1000usize, 10_000] {
            let c = a.compliance(n);
            let hp = (k + 1.0) * 40.0 / (4.0 * g * n as f64);
            assert!((c.radial_from_radial / hp - 1.0).abs() < 2.0 / n as f64, "n = {n}");
            // Reciprocity of the loaded rim: ∂U/∂S = ∂V/∂T (Betti, cos/sin pairs).
            let rel = (c.radial_from_shear - c.tangential_from_radial).abs() / c.radial_from_radial.abs();
            assert!(rel < 1e-9, "n = {n}: {c:?}");
        }
    }

    #[test]
    fn betti_reciprocity_for_every_mode() {
        for (inner, outer, rim) in [(5.0, 40.0, LoadedRim::Outer), (50.0, 65.0, LoadedRim::Inner)] {
            let a = Annulus::new(inner, outer, steel(), rim).unwrap();
            for n in 1..60 {
                let c = a.compliance(n);
                let scale = c.radial_from_radial.abs().max(c.tangential_from_shear.abs());
                assert!(
                    (c.radial_from_shear - c.tangential_from_radial).abs() < 1e-10 * scale,
                    "{rim:?} n = {n}: {c:?}"
                );
            }
        }
    }

    #[test]
    fn boundary_conditions_and_equilibrium_of_mode_one() {
        // u = 0 on the fixed rim; the net force is the same through every circle and equals the
        // resultant πR(T_1 − S_1) of the rim traction.
        for (inner, outer, rim) in [(5.0, 40.0, LoadedRim::Outer), (50.0, 65.0, LoadedRim::Inner)] {
            let a = Annulus::new(inner, outer, steel(), rim).unwrap();
            let (t, s) = (-3.0, 0.7);
            let f = a.mode_field(1, t, s, a.fixed_radius());
            assert!(f.radial_displacement.abs() < 1e-15 && f.tangential_displacement.abs() < 1e-15);
            let rl = a.loaded_radius();
            let expected = PI * rl * (t - s);
            for r in [inner, 0.5 * (inner + outer), outer] {
                let force = a.mode_one_force(t, s, r);
                assert!(
                    (force - expected).abs() < 1e-10 * expected.abs(),
                    "r = {r}: {force} vs {expected}"
                );
            }
        }
    }
}
