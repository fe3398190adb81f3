//! The Fourier compliance of an elastic layer bonded to a rigid base (plane strain).
//!
//! A layer 0 ≤ z ≤ b (z into the layer from its free face, the base bonded at z = b), shear
//! modulus G, Poisson's ratio ν (ν = ½ allowed), is loaded on its top face by a pressure
//! p = P cos kx (compressive, pushing into the layer) and a shear q = Q sin kx (in +x). Its top
//! face moves by
//!
//! ```text
//! w   = (C_nn P + C_nt Q) cos kx      (into the layer)
//! u_x = (C_tn P + C_tt Q) sin kx      (along +x)
//! ```
//!
//! the frame of docs/references.md §0 and §3.1, so that the pair convention of [`crate::body`]
//! takes the layer's kernels as it takes the half-plane's. With t = kb, κ = 3 − 4ν and
//! D = κ cosh 2t + 2t² + (1 + κ²)/2 (Papkovich–Neuber potentials
//! φ, ψ = (A e^(kz) + B e^(−kz)) cos kx, 2G u = ∇(φ + zψ) − 4(1 − ν)ψ e_z, with u = 0 at z = b):
//!
//! ```text
//! C_nn = ((1 − ν)/(Gk)) (κ sinh 2t − 2t)/D          (docs/references.md §5)
//! C_tt = ((1 − ν)/(Gk)) (κ sinh 2t + 2t)/D
//! C_nt = C_tn = (1/(Gk)) [2t² − (1 − 2ν) κ (cosh 2t − 1)]/(2D)
//! ```
//!
//! C_nt = C_tn is Betti's reciprocity for this pairing (the unit tests check it against a
//! numerical solution of the 4 × 4 boundary system). As t → ∞ they tend to the half-plane's
//! (1 − ν)/(Gk), −(1 − 2ν)/(2Gk), (1 − ν)/(Gk), with an error O(t² e^(−2t)); the thin limits are
//! the Winkler b(1 − 2ν)/(2G(1 − ν)), k²b³/(3G) at ν = ½, and b/G in shear. Units:
//! length/stress.
//!
//! Evaluated with s = e^(−2t) (numerator and denominator times 2s), which neither overflows
//! nor loses digits: sinh 2t − 2t, which cancels at small t, by its series.

/// The four top-face compliances of one wavenumber [length/stress] (module docs).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Compliance {
    /// Normal displacement per unit pressure amplitude.
    pub nn: f64,
    /// Normal displacement per unit shear amplitude (= [`Self::tn`], Betti).
    pub nt: f64,
    /// Tangential displacement per unit pressure amplitude.
    pub tn: f64,
    /// Tangential displacement per unit shear amplitude.
    pub tt: f64,
}

/// sinh x − x [-], accurate for every x ≥ 0 (its series below 1).
fn sinh_minus_x(x: f64) -> f64 {
    if x >= 1.0 {
        return x.sinh() - x;
    }
    // x³/3! + x⁵/5! + …: at x < 1 the 12th term is below 1e-19 of the first.
    let x2 = x * x;
    let mut term = x * x2 / 6.0;
    let mut sum = 0.0;
    let mut n = 3.0;
    for _ in 0..12 {
        sum += term;
        term *= x2 / ((n + 1.0) * (n + 2.0));
        n += 2.0;
    }
    sum
}

/// The dimensionless compliances f(t) = G·k·C at t = kb for Poisson's ratio ν, divided by t
/// (so finite at t = 0): C = (b/G)·f(t)/t.
fn scaled_by_thickness(t: f64, poisson: f64) -> Compliance {
    let kappa = 3.0 - 4.0 * poisson;
    if t == 0.0 {
        let nn = (1.0 - 2.0 * poisson) / (2.0 * (1.0 - poisson));
        return Compliance {
            nn,
            nt: 0.0,
            tn: 0.0,
            tt: 1.0,
        };
    }
    let s = (-2.0 * t).exp();
    let one_minus_s = -(-2.0 * t).exp_m1();
    let one_minus_s2 = -(-4.0 * t).exp_m1();
    // 2s·D and 2s(sinh 2t − 2t).
    let d2 = kappa * (1.0 + s * s) + (4.0 * t * t + 1.0 + kappa * kappa) * s;
    let shx2 = if 2.0 * t < 1.0 {
        2.0 * s * sinh_minus_x(2.0 * t)
    } else {
        one_minus_s2 - 4.0 * t * s
    };
    let nn = (1.0 - poisson) * ((kappa - 1.0) * one_minus_s2 + shx2) / d2;
    let tt = (1.0 - poisson) * (kappa * one_minus_s2 + 4.0 * t * s) / d2;
    let nt = (4.0 * t * t * s - (1.0 - 2.0 * poisson) * kappa * one_minus_s * one_minus_s) / (2.0 * d2);
    Compliance {
        nn: nn / t,
        nt: nt / t,
        tn: nt / t,
        tt: tt / t,
    }
}

/// The layer's compliances at wavenumber k ≥ 0 [1/length] for thickness b [length], shear
/// modulus G [stress] and Poisson's ratio ν (module docs) [length/stress].
pub fn layer_compliance(k: f64, thickness: f64, shear: f64, poisson: f64) -> Compliance {
    let f = scaled_by_thickness(k * thickness, poisson);
    let scale = thickness / shear;
    Compliance {
        nn: f.nn * scale,
        nt: f.nt * scale,
        tn: f.tn * scale,
        tt: f.tt * scale,
    }
}

/// The half-plane's compliances at wavenumber k > 0 in the same pairing: (1 − ν)/(Gk) on the
/// diagonal, −(1 − 2ν)/(2Gk) off it (docs/references.md §3.1) [length/stress].
pub fn half_plane_compliance(k: f64, shear: f64, poisson: f64) -> Compliance {
    let diagonal = (1.0 - poisson) / (shear * k);
    let off = -(1.0 - 2.0 * poisson) / (2.0 * shear * k);
    Compliance {
        nn: diagonal,
        nt: off,
        tn: off,
        tt: diagonal,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// docs/references.md §5's C(k) as printed (cosh/sinh form).
    fn references_c_nn(k: f64, b: f64, g: f64, nu: f64) -> f64 {
        let kappa = 3.0 - 4.0 * nu;
        let t = k * b;
        (1.0 - nu) / (g * k) * (kappa * (2.0 * t).sinh() - 2.0 * t)
            / (kappa * (2.0 * t).cosh() + 2.0 * t * t + 0.5 * (1.0 + kappa * kappa))
    }

    /// An independent solution: the 4 × 4 system of the Papkovich–Neuber potentials
    /// (φ = A1 e^z + A2 e^(−z), ψ = B1 e^z + B2 e^(−z), G = k = 1) solved by elimination, for the
    /// top load (P, Q); returns (w, u_x) at the top.
    fn solved_numerically(t: f64, nu: f64, p: f64, q: f64) -> (f64, f64) {
        let kappa = 3.0 - 4.0 * nu;
        let lambda = 2.0 * nu / (1.0 - 2.0 * nu);
        // [U, W, U', W'] of each unknown at depth z (2U = −(φ + zψ), 2W = φ' + zψ' − κψ).
        let basis = |z: f64| -> [[f64; 4]; 4] {
            let (ep, em) = (z.exp(), (-z).exp());
            [
                [-ep / 2.0, ep / 2.0, -ep / 2.0, ep / 2.0],
                [-em / 2.0, -em / 2.0, em / 2.0, em / 2.0],
                [
                    -z * ep / 2.0,
                    (z - kappa) * ep / 2.0,
                    -(1.0 + z) * ep / 2.0,
                    (1.0 - kappa + z) * ep / 2.0,
                ],
                [
                    -z * em / 2.0,
                    (-z - kappa) * em / 2.0,
                    -(1.0 - z) * em / 2.0,
                    (-(1.0 - kappa) + z) * em / 2.0,
                ],
            ]
        };
        let (top, bottom) = (basis(0.0), basis(t));
        let mut m = [[0.0; 5]; 4];
        for j in 0..4 {
            m[0][j] = bottom[j][0];
            m[1][j] = bottom[j][1];
            // σ_zz = λ(U + W') + 2W' = −P, σ_xz = U' − W = −Q at z = 0.
            m[2][j] = lambda * (top[j][0] + top[j][3]) + 2.0 * top[j][3];
            m[3][j] = top[j][2] - top[j][1];
        }
        m[2][4] = -p;
        m[3][4] = -q;
        for c in 0..4 {
            let pivot = (c..4).max_by(|&a, &b| m[a][c].abs().total_cmp(&m[b][c].abs())).unwrap();
            m.swap(c, pivot);
            let pivot_row = m[c];
            for (r, row) in m.iter_mut().enumerate() {
                if r != c {
                    let f = row[c] / pivot_row[c];
                    for (v, p) in row.iter_mut().zip(&pivot_row).skip(c) {
                        *v -= f * p;
                    }
                }
            }
        }
        let x: Vec<f64> = (0..4).map(|r| m[r][4] / m[r][r]).collect();
        let (u, w) = (0..4).fold((0.0, 0.0), |(u, w), j| (u + x[j] * top[j][0], w + x[j] * top[j][1]));
        (w, u)
    }

    #[test]
    fn c_nn_is_the_references_closed_form() {
        for nu in [0.0, 0.3, 0.45, 0.5] {
            for t in [0.05, 0.5, 2.0, 8.0] {
                let (b, g) = (0.5, 3.0);
                let k = t / b;
                let c = layer_compliance(k, b, g, nu).nn;
                let r = references_c_nn(k, b, g, nu);
                assert!((c - r).abs() <= 1e-12 * r.abs(), "nu {nu} t {t}: {c} vs {r}");
            }
        }
    }

    #[test]
    fn all_four_agree_with_the_boundary_system_and_are_reciprocal() {
        for nu in [0.0, 0.3, 0.45] {
            for t in [0.1, 0.7, 3.0] {
                let c = layer_compliance(1.0, t, 1.0, nu);
                let (w_p, u_p) = solved_numerically(t, nu, 1.0, 0.0);
                let (w_q, u_q) = solved_numerically(t, nu, 0.0, 1.0);
                let tol = 1e-12 * c.tt;
                assert!((c.nn - w_p).abs() < tol, "nn nu {nu} t {t}: {} vs {w_p}", c.nn);
                assert!((c.tn - u_p).abs() < tol, "tn nu {nu} t {t}: {} vs {u_p}", c.tn);
                assert!((c.nt - w_q).abs() < tol, "nt nu {nu} t {t}: {} vs {w_q}", c.nt);
                assert!((c.tt - u_q).abs() < tol, "tt nu {nu} t {t}: {} vs {u_q}", c.tt);
                // Betti: P₁·w(Q₂) = Q₂·u_x(P₁) over a period.
                assert!((w_q - u_p).abs() < tol, "reciprocity nu {nu} t {t}: {w_q} vs {u_p}");
            }
        }
    }

    #[test]
    fn a_thick_layer_is_the_half_plane() {
        for nu in [0.2, 0.5] {
            let (g, k) = (2.0, 3.0);
            let c = layer_compliance(k, 40.0 / k, g, nu);
            let h = half_plane_compliance(k, g, nu);
            assert!((c.nn - h.nn).abs() < 1e-14 * h.nn);
            assert!((c.tt - h.tt).abs() < 1e-14 * h.tt);
            assert!((c.nt - h.nt).abs() < 1e-14 * h.nn);
            assert!((c.nn - (1.0 - nu) / (g * k)).abs() < 1e-14 * h.nn);
        }
    }

    #[test]
    fn thin_layer_limits() {
        let (b, g) = (0.2, 1.5);
        // Compressible: Winkler, next term O(t²).
        let t: f64 = 1e-4;
        for nu in [0.0, 0.3, 0.45] {
            let c = layer_compliance(t / b, b, g, nu);
            let winkler = b * (1.0 - 2.0 * nu) / (2.0 * g * (1.0 - nu));
            assert!((c.nn / winkler - 1.0).abs() < 10.0 * t * t, "nu {nu}");
            assert!((c.tt / (b / g) - 1.0).abs() < 10.0 * t * t, "nu {nu}");
        }
        // Incompressible: (b t²/(15G))(5 − 9t²), next term O(t⁶); the series keeps the digits
        // that sinh 2t − 2t would lose.
        for t in [1e-3, 1e-2] {
            let c = layer_compliance(t / b, b, g, 0.5);
            let two_terms = b * t * t / (15.0 * g) * (5.0 - 9.0 * t * t);
            assert!(
                (c.nn / two_terms - 1.0).abs() < 10.0 * t.powi(4),
                "t {t}: {} vs {two_terms}",
                c.nn
            );
            assert!((c.nn / (t * t * b / (3.0 * g)) - 1.0).abs() < 2.0 * t * t);
        }
        assert_eq!(layer_compliance(0.0, b, g, 0.3).tt, b / g);
    }
}
