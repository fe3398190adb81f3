//! The smooth remainder of the layer's surface kernels beyond the half-plane's, tabulated and
//! integrated against the grid's shape functions.
//!
//! A layer's surface kernels are the Fourier integrals of its compliances
//! ([`super::compliance`]): K_nn(t) = (1/π)∫_0^∞ C_nn(k) cos kt dk (K_tt likewise) and
//! K_nt(t) = −(1/π)∫_0^∞ C_nt(k) sin kt dk, t = x − s. The half-plane's compliances C_hp carry
//! their whole singular part: K = H + S with H the half-plane kernel (its logarithm measured
//! from the datum ℓ, its sign jump) and the remainder
//!
//! ```text
//! S_nn(t) = (1/π)∫_0^∞ [(C_nn − C_hp) cos kt + C_hp e^(−kℓ)] dk
//!         = (1/π)∫_0^k₁ [C_nn cos kt + C_hp (1 − cos kt)] dk − ((1 − ν)/(πG)) (γ + ln k₁ℓ)
//! S_nt(t) = −(1/π)∫_0^k₁ (C_nt − C_hp,nt) sin kt dk
//! ```
//!
//! (the second form: C − C_hp = O(e^(−2kb)) beyond k₁ = 25/b, and ∫_0^k₁ (1 − cos kt)/k dk is the
//! entire part of the cosine integral, γ Euler's constant). The first form's e^(−kℓ) term is
//! the half-plane's datum: (1/π)∫_0^∞ C_hp (cos kt − e^(−kℓ)) dk = −((1 − ν)/(πG)) ln(|t|/ℓ).
//! S is analytic in a strip of width ∼ b about the real axis, so a table of spacing b/24 and
//! quintic interpolation represent it, and a Gauss rule on pieces no longer than b/2 integrates
//! it against the shape functions.
//!
//! **Ageing** (viscoelastic layer, [`crate::body::viscoelastic::aged_kernels`]): the aged kernel
//! K^L(t) = ∫_0^∞ e^(−v) K(t + dLv) dv turns cos kt into (cos kt − d kL sin kt)/(1 + k²L²) and
//! sin kt into (sin kt + d kL cos kt)/(1 + k²L²) (the real and imaginary parts of
//! e^(ikt)/(1 − i d kL)); the aged remainder takes these factors inside its k-integral (the
//! constant is unchanged: ageing keeps a constant), and the half-plane part keeps the aged
//! closed forms of [`crate::body::viscoelastic::aged_kernels`].
//!
//! Unit shear modulus throughout: the model scales by 1/G.

use super::compliance::{half_plane_compliance, layer_compliance};
use crate::body::viscoelastic::aged_kernels::Ageing;
use crate::body::viscoelastic::exponential_integrals::EULER_GAMMA;
use crate::grid::ContactGrid;
use crate::quadrature::gauss_legendre;
use faer::Mat;
use std::f64::consts::PI;

/// k₁·b: the wavenumber beyond which C − C_hp is below 1e-18 of C_hp (∼ 4t² e^(−2t)).
const CUTOFF: f64 = 25.0;
/// Points of the Gauss rule on each wavenumber panel.
const K_POINTS: usize = 16;
/// Table spacing in layer thicknesses.
const TABLE_STEP: f64 = 1.0 / 24.0;
/// Most table points on each side of t = 0.
const MAX_TABLE: usize = 40_000;
/// Points of the Gauss rule on each piece (no longer than b/2) of an element.
const ELEMENT_POINTS: usize = 8;
/// |t|/b beyond which an elastic layer's kernels have vanished (they decay like e^(−c|t|/b),
/// c ≳ 1.3: the end modes of a bonded strip, Papkovich–Fadle), so that the remainder is minus
/// the half-plane's kernel there, in closed form, and the table stops.
const FAR_TAIL: f64 = 40.0;

/// Which of the layer's kernels.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Component {
    /// Normal displacement from pressure (even).
    NormalNormal,
    /// Normal displacement from shear (odd); the tangential one from pressure is its negative.
    NormalTangential,
    /// Tangential displacement from shear (even).
    TangentialTangential,
}

impl Component {
    /// The three components in the order of the remainder blocks [nn, nt, tt] (and of the
    /// tabulated sums' values).
    pub const ALL: [Component; 3] = [
        Component::NormalNormal,
        Component::NormalTangential,
        Component::TangentialTangential,
    ];
}

/// The layer's remainder kernels at unit shear modulus on a table (module docs).
#[derive(Debug, Clone)]
pub struct Remainder {
    thickness: f64,
    origin: f64,
    step: f64,
    values: [Vec<f64>; 3],
    /// Beyond |t| = this [length] (an elastic table only) S = −H in closed form: the
    /// half-plane's datum ℓ and Poisson's ratio.
    tail: Option<(f64, f64, f64)>,
}

/// The wavenumber rule: nodes and weights on [0, k₁], panels graded geometrically from 0.1/L
/// where the ageing factor's pole at k = ±i/L lies near the axis, then no wider than 0.5/b
/// (the compliances' poles) and 3/T (the oscillation of cos kt up to |t| = T).
fn wavenumber_rule(thickness: f64, reach: f64, ageing: Option<&Ageing>) -> (Vec<f64>, Vec<f64>) {
    let k1 = CUTOFF / thickness;
    let wide = (0.5 / thickness).min(3.0 / reach);
    let mut ends = vec![0.0];
    let mut k = ageing.map_or(wide, |a| wide.min(0.1 / a.length));
    while k < wide {
        ends.push(k);
        k *= 2.0;
    }
    let mut k = ends.last().copied().unwrap_or(0.0);
    while k < k1 {
        k = (k + wide).min(k1);
        ends.push(k);
    }
    let (gx, gw) = gauss_legendre(K_POINTS);
    let mut nodes = Vec::with_capacity(ends.len() * K_POINTS);
    let mut weights = Vec::with_capacity(ends.len() * K_POINTS);
    for pair in ends.windows(2) {
        let (a, b) = (pair[0], pair[1]);
        for (x, w) in gx.iter().zip(&gw) {
            nodes.push(0.5 * (a + b) + 0.5 * (b - a) * x);
            weights.push(0.5 * (b - a) * w);
        }
    }
    (nodes, weights)
}

/// Kernel evaluations (wavenumber nodes × table points) of [`Remainder::tabulate`] with these
/// arguments, counted without building anything: the table's cost in time (about 1e8 a second
/// and core) and, through the wavenumber nodes held at once, in memory (40 bytes each). It
/// grows with (reach/b)² where the table spans the grid (a viscoelastic cover's aged table).
pub fn tabulation_work(thickness: f64, reach: f64, ageing: Option<&Ageing>) -> f64 {
    let far = ageing.is_none() && reach > FAR_TAIL * thickness;
    let reach = if far { (FAR_TAIL + 0.5) * thickness } else { reach };
    let step = (TABLE_STEP * thickness).min(reach / 64.0).max(reach / MAX_TABLE as f64);
    let points = 2.0 * ((reach / step).ceil() + 3.0) + 1.0;
    // The panels of `wavenumber_rule`: a geometric run up to `wide`, then steps of `wide`.
    let k_reach = reach.max(thickness);
    let k1 = CUTOFF / thickness;
    let wide = (0.5 / thickness).min(3.0 / k_reach);
    let start = ageing.map_or(wide, |a| wide.min(0.1 / a.length));
    let geometric = if start < wide {
        (wide / start).log2().ceil() + 1.0
    } else {
        0.0
    };
    let linear = ((k1 - wide.min(k1)) / wide).ceil() + 1.0;
    (geometric + linear) * K_POINTS as f64 * points
}

impl Remainder {
    /// The remainders of a layer of thickness b [length] and Poisson's ratio ν, with the
    /// half-plane datum ℓ [length], on |t| ≤ `reach` [length] (the grid's length), aged when
    /// `ageing` is given.
    pub fn tabulate(thickness: f64, poisson: f64, datum: f64, reach: f64, ageing: Option<&Ageing>) -> Self {
        use rayon::prelude::*;
        // Unaged, the kernels vanish beyond FAR_TAIL·b and the closed form takes over; aged, the
        // upstream tail lasts ∼ 40 L, and the table spans the grid.
        let tail = (ageing.is_none() && reach > FAR_TAIL * thickness).then_some((FAR_TAIL * thickness, datum, poisson));
        let reach = tail.map_or(reach, |(cut, _, _)| cut + 0.5 * thickness);
        let step = (TABLE_STEP * thickness).min(reach / 64.0).max(reach / MAX_TABLE as f64);
        // Three points beyond each end for the interpolation stencil.
        let half = (reach / step).ceil() as usize + 3;
        let origin = -(half as f64) * step;
        let integrand = Integrand::new(thickness, poisson, datum, reach, ageing);
        let rows: Vec<[f64; 3]> = (0..=2 * half)
            .into_par_iter()
            .map(|i| integrand.at(origin + i as f64 * step))
            .collect();
        let values = std::array::from_fn(|c| rows.iter().map(|r| r[c]).collect());
        Self {
            thickness,
            origin,
            step,
            values,
            tail,
        }
    }

    /// S(t) of a component by quintic interpolation of the table [length/stress at unit G].
    pub fn value(&self, component: Component, t: f64) -> f64 {
        if let Some((cut, datum, nu)) = self.tail {
            if t.abs() > cut {
                // −H: the half-plane's kernels at unit modulus, −B ln(|t|/ℓ) and A sgn t.
                return match component {
                    Component::NormalTangential => -(1.0 - 2.0 * nu) / 4.0 * t.signum(),
                    _ => (1.0 - nu) / PI * (t.abs() / datum).ln(),
                };
            }
        }
        let table = &self.values[component as usize];
        let x = (t - self.origin) / self.step;
        let first = (x.floor() as isize - 2).clamp(0, table.len() as isize - 6) as usize;
        let mut sum = 0.0;
        for i in 0..6 {
            let mut l = 1.0;
            for j in 0..6 {
                if j != i {
                    l *= (x - (first + j) as f64) / (i as f64 - j as f64);
                }
            }
            sum += l * table[first + i];
        }
        sum
    }

    /// ∫ N_a(s) S(x − s) ds over the element [s1, s2] for each shape function a (entries past
    /// the element's node count are 0), by a Gauss rule on pieces no longer than b/2.
    fn element_integrals(&self, grid: &ContactGrid, component: Component, s1: f64, s2: f64, x: f64) -> [f64; 3] {
        let (gx, gw) = rule();
        let pieces = ((s2 - s1) / (0.5 * self.thickness)).ceil().max(1.0) as usize;
        let h = (s2 - s1) / pieces as f64;
        let npe = grid.kind.nodes_per_element();
        let shapes: Vec<[f64; 3]> = (0..npe).map(|a| grid.kind.shape_polynomial(a)).collect();
        let mut out = [0.0; 3];
        for piece in 0..pieces {
            let a = s1 + piece as f64 * h;
            for (g, w) in gx.iter().zip(gw) {
                let s = a + 0.5 * h * (1.0 + g);
                let xi = 2.0 * (s - s1) / (s2 - s1) - 1.0;
                let f = 0.5 * h * w * self.value(component, x - s);
                for (o, c) in out.iter_mut().zip(&shapes) {
                    *o += f * (c[0] + c[1] * xi + c[2] * xi * xi);
                }
            }
        }
        out
    }

    /// The influence matrix ∫ N_j(s) S(x_i − s) ds of a component on the grid [length/stress
    /// at unit G].
    pub fn matrix(&self, grid: &ContactGrid, component: Component) -> Mat<f64> {
        crate::body::half_space::influence_matrix_of(grid, |s1, s2, x| {
            self.element_integrals(grid, component, s1, s2, x)
        })
    }
}

/// The wavenumber sums of one table (module docs): per wavenumber, k and the weight/π times
/// C_nn, C_nt − C_hp,nt, C_tt and C_hp.
struct Integrand {
    per_k: Vec<[f64; 5]>,
    constant: f64,
    ageing: Option<Ageing>,
}

impl Integrand {
    /// The sums of a layer of thickness b and Poisson's ratio ν with datum ℓ, good for
    /// |t| ≤ `reach`, aged when `ageing` is given.
    fn new(thickness: f64, poisson: f64, datum: f64, reach: f64, ageing: Option<&Ageing>) -> Self {
        let (k, w) = wavenumber_rule(thickness, reach.max(thickness), ageing);
        let per_k = k
            .iter()
            .zip(&w)
            .map(|(&k, &w)| {
                let (c, h) = (
                    layer_compliance(k, thickness, 1.0, poisson),
                    half_plane_compliance(k, 1.0, poisson),
                );
                [k, w / PI * c.nn, w / PI * (c.nt - h.nt), w / PI * c.tt, w / PI * h.nn]
            })
            .collect();
        Self {
            per_k,
            constant: (1.0 - poisson) / PI * (EULER_GAMMA + (CUTOFF / thickness * datum).ln()),
            ageing: ageing.copied(),
        }
    }

    /// [S_nn, S_nt, S_tt] at t, from the wavenumber sums.
    fn at(&self, t: f64) -> [f64; 3] {
        let mut sum = [0.0; 3];
        for &[k, nn, nt, tt, hp] in &self.per_k {
            let (sin, cos) = (k * t).sin_cos();
            let (even, odd) = match self.ageing {
                None => (cos, sin),
                Some(a) => {
                    let kl = a.direction * k * a.length;
                    let f = 1.0 / (1.0 + kl * kl);
                    ((cos - kl * sin) * f, (sin + kl * cos) * f)
                }
            };
            sum[0] += nn * even + hp * (1.0 - even);
            sum[1] -= nt * odd;
            sum[2] += tt * even + hp * (1.0 - even);
        }
        [sum[0] - self.constant, sum[1], sum[2] - self.constant]
    }
}

fn rule() -> &'static (Vec<f64>, Vec<f64>) {
    static RULE: std::sync::OnceLock<(Vec<f64>, Vec<f64>)> = std::sync::OnceLock::new();
    RULE.get_or_init(|| gauss_legendre(ELEMENT_POINTS))
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The datum identity the remainder rests on: ∫_0^∞ (cos kℓ − e^(−kℓ))/k dk = 0, by
    /// panels up to kℓ = 2000π and the cosine integral's asymptotic tail (1/x² − 6/x⁴ at a
    /// multiple x of 2π).
    #[test]
    fn the_half_plane_datum_integral_vanishes() {
        let l = 3.7;
        let (gx, gw) = gauss_legendre(20);
        let n = 4000;
        let h = 2000.0 * PI / l / n as f64;
        let mut sum = 0.0;
        for p in 0..n {
            let a = p as f64 * h;
            for (x, w) in gx.iter().zip(&gw) {
                let k = a + 0.5 * h * (1.0 + x);
                sum += 0.5 * h * w * ((k * l).cos() - (-k * l).exp()) / k;
            }
        }
        let x = 2000.0 * PI;
        sum += 1.0 / (x * x) - 6.0 / x.powi(4);
        assert!(sum.abs() < 1e-12, "{sum}");
    }

    /// The table's quintic interpolation against the sums themselves, between the nodes.
    #[test]
    fn interpolation_reproduces_the_sums() {
        for nu in [0.3, 0.5] {
            let (b, l, reach) = (0.5, 40.0, 6.0);
            let table = Remainder::tabulate(b, nu, l, reach, None);
            let direct = Integrand::new(b, nu, l, reach, None);
            let scale = direct.at(0.0)[0].abs().max(b);
            for t in [-5.3, -0.51, -0.013, 0.0071, 0.27, 2.9, 5.97] {
                let d = direct.at(t);
                for (c, comp) in Component::ALL.into_iter().enumerate() {
                    let v = table.value(comp, t);
                    assert!(
                        (v - d[c]).abs() < 1e-9 * scale,
                        "nu {nu} t {t} {comp:?}: {v} vs {}",
                        d[c]
                    );
                }
            }
        }
    }

    /// The closed-form tail beyond 40 b continues the table: an elastic layer's kernels have
    /// vanished there (the sums and the table agree within 1e-10 from 30 b to 44 b).
    #[test]
    fn the_far_tail_continues_the_table() {
        for nu in [0.3, 0.5] {
            let (b, l) = (0.1, 3.0);
            let direct = Integrand::new(b, nu, l, 4.5, None);
            let tabled = Remainder::tabulate(b, nu, l, 40.0, None);
            assert!(tabled.tail.is_some());
            for t in [-4.3, -3.05, 3.0, 3.9, 4.1, 4.4] {
                let d = direct.at(t);
                for (c, comp) in Component::ALL.into_iter().enumerate() {
                    let v = tabled.value(comp, t);
                    assert!((v - d[c]).abs() < 1e-10, "nu {nu} t {t} {comp:?}: {v} vs {}", d[c]);
                }
            }
        }
    }

    /// Symmetry (S_nn, S_tt even, S_nt odd) and no singularity left at t = 0.
    #[test]
    fn the_remainder_is_odd_or_even_and_smooth_through_zero() {
        let direct = Integrand::new(0.5, 0.3, 40.0, 6.0, None);
        for t in [0.01, 0.4, 3.0] {
            let (p, m) = (direct.at(t), direct.at(-t));
            assert!((p[0] - m[0]).abs() < 1e-13 && (p[2] - m[2]).abs() < 1e-13);
            assert!((p[1] + m[1]).abs() < 1e-13);
        }
        // Smooth: the second difference on the scale b/100 is O(h²), not the log's O(1).
        let h = 0.005;
        for c in 0..3 {
            let second = direct.at(h)[c] - 2.0 * direct.at(0.0)[c] + direct.at(-h)[c];
            assert!(second.abs() < 1e-3, "component {c}: {second}");
        }
    }

    /// The Fourier ageing factors against the definition of aged_kernels.rs,
    /// K^L(t) = ∫_0^∞ e^(−v) K(t + dLv) dv, applied to the elastic table by Gauss panels.
    #[test]
    fn ageing_in_fourier_space_is_the_material_path_integral() {
        let (b, nu, l) = (0.5, 0.35, 40.0);
        let elastic = Remainder::tabulate(b, nu, l, 30.0, None);
        let (gx, gw) = gauss_legendre(12);
        for direction in [1.0, -1.0] {
            let ageing = Ageing { length: 0.4, direction };
            let aged = Integrand::new(b, nu, l, 30.0, Some(&ageing));
            for t in [-1.3, 0.0, 0.6] {
                let mut path = [0.0; 3];
                for p in 0..160 {
                    let (a, e) = (p as f64 * 0.25, (p + 1) as f64 * 0.25);
                    for (x, w) in gx.iter().zip(&gw) {
                        let v = 0.5 * (a + e) + 0.5 * (e - a) * x;
                        let weight = 0.5 * (e - a) * w * (-v).exp();
                        let s = t + direction * ageing.length * v;
                        path[0] += weight * elastic.value(Component::NormalNormal, s);
                        path[1] += weight * elastic.value(Component::NormalTangential, s);
                        path[2] += weight * elastic.value(Component::TangentialTangential, s);
                    }
                }
                let fourier = aged.at(t);
                for c in 0..3 {
                    assert!(
                        (fourier[c] - path[c]).abs() < 1e-8,
                        "d {direction} t {t} c {c}: {} vs {}",
                        fourier[c],
                        path[c]
                    );
                }
            }
        }
    }
}
