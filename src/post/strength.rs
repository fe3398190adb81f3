//! Strength of a body from its elastic interior stresses: first yield and the shakedown limit
//! of steady rolling by Melan's static theorem (Johnson, *Contact Mechanics*, 1985, §4.2, §9.4).
//!
//! Frame: x along the surface (the rolling direction), z the depth into the body, y out of the
//! plane; stresses tension positive, [`PlaneStress`] (σy the plane-strain out-of-plane stress).
//! The material yields when its equivalent shear stress τ_eq reaches the shear yield stress k:
//!
//! * von Mises: τ_eq = σ_vm / √3 (k = Y/√3),
//! * Tresca: τ_eq = (σ_max − σ_min)/2 over the **three** principal stresses (the two in-plane
//!   ones and σy), k = Y/2. Inside the body σy is usually the intermediate principal stress and
//!   τ_eq is the in-plane principal shear τ1; near the surface, where the in-plane stresses are
//!   close to equal (under the centre of a Hertz contact σx = σz = −p0, σy = −2ν p0), σy can be
//!   the extreme one and the full Tresca stress exceeds τ1.
//!
//! **First yield**: the factor λ_y = min k / τ_eq over the points on the stresses.
//!
//! **Shakedown** (steady rolling, plane strain): a residual stress that does not change along
//! the rolling direction and is self-equilibrated with a free surface depends on the depth only
//! and has σz^r = τxz^r = 0, leaving r = (σx^r(z), σy^r(z)). Melan: the body shakes down at
//! the factor λ if some such r keeps λσ^e(x, z) + r within yield at every x of each depth.
//! τ_eq is convex and positively homogeneous of degree one in the stress, so with r = λ r',
//! the largest λ of one depth row is in closed form
//!
//! λ_sd(z) = k / min_{r'} max_x τ_eq(σ^e(x, z) + r'),
//!
//! a convex min-max in two variables (one for the in-plane Tresca, where σy^r drops out),
//! solved by nested golden-section searches (the inner minimum over r_y of a jointly convex
//! function is convex in r_x). λ_sd = min over the depths; its residual is λ_sd r'.
//! For a frictionless Hertz contact σx^r absorbs the direct stresses and the limit is set by
//! |τxz|max = 0.250 p0 at z = 0.50a: p0 = 4.0k for both criteria.

pub mod assess;

use crate::interior::{InteriorField, PlaneStress, PointStatus};

pub use crate::material::YieldCriterion as Criterion;

impl Criterion {
    /// The equivalent shear stress τ_eq of `s` [stress]: yield when τ_eq = k.
    pub fn equivalent_shear(self, s: &PlaneStress) -> f64 {
        match self {
            Criterion::VonMises => s.von_mises() / 3f64.sqrt(),
            Criterion::Tresca => {
                let c = 0.5 * (s.sxx + s.szz);
                let t = s.max_shear();
                let (hi, lo) = ((c + t).max(s.syy), (c - t).min(s.syy));
                0.5 * (hi - lo)
            }
        }
    }
}

/// The point where yield starts and the factor on the stresses that takes it there.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct FirstYield {
    /// λ_y = k / τ_eq at the point [-]: the stresses times λ_y first reach yield.
    pub factor: f64,
    /// Position along the surface [length].
    pub x: f64,
    /// Depth [length].
    pub z: f64,
}

/// First yield over points `(x, z)` with their stresses and the shear yield stress `k`
/// [stress]; None when no point is stressed.
pub fn first_yield(points: &[[f64; 2]], stress: &[PlaneStress], k: f64, criterion: Criterion) -> Option<FirstYield> {
    let mut best: Option<FirstYield> = None;
    for (p, s) in points.iter().zip(stress) {
        let t = criterion.equivalent_shear(s);
        if t > 0.0 {
            let factor = k / t;
            if best.is_none_or(|b| factor < b.factor) {
                best = Some(FirstYield {
                    factor,
                    x: p[0],
                    z: p[1],
                });
            }
        }
    }
    best
}

/// The shakedown limit of one depth row.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct RowShakedown {
    /// Depth of the row [length].
    pub z: f64,
    /// λ_sd(z) [-]: the largest factor on the elastic stresses for which a residual exists.
    pub factor: f64,
    /// The residual (σx^r, σy^r) at λ_sd(z) [stress].
    pub residual: [f64; 2],
}

/// Golden-section minimum of a convex `f` on [lo, hi]: (argument, value). 48 reductions by
/// the golden ratio leave 1e-10 of the interval, far below the interior fields' accuracy.
fn golden(mut lo: f64, mut hi: f64, f: &mut dyn FnMut(f64) -> f64) -> (f64, f64) {
    const G: f64 = 0.618_033_988_749_894_8;
    let (mut c, mut d) = (hi - G * (hi - lo), lo + G * (hi - lo));
    let (mut fc, mut fd) = (f(c), f(d));
    for _ in 0..48 {
        if fc <= fd {
            hi = d;
            (d, fd) = (c, fc);
            c = hi - G * (hi - lo);
            fc = f(c);
        } else {
            lo = c;
            (c, fc) = (d, fd);
            d = lo + G * (hi - lo);
            fd = f(d);
        }
    }
    if fc <= fd {
        (c, fc)
    } else {
        (d, fd)
    }
}

/// max_x τ_eq(σ^e + r) of one row as a function of the residual r = (r_x, r_y), minimised
/// over r_y in closed form or by a golden section: (best r_y, value).
///
/// von Mises: 6 J2(σ + r) = q(r) + l·r + c with q(r) = r_x² + r_y² + (r_y − r_x)² the same for
/// every point, l = 2(2A − C, 2C − A), c = A² + C² + (C − A)² + 6τ², A = σx − σz,
/// C = σy − σz; so the row's maximum is q(r) + max_i(l_i·r + c_i), and τ_eq = √J2.
/// Tresca: for a given r_x the in-plane principal stresses c ± t are fixed; σy + r_y enters only
/// through |c ± t − σy − r_y|/2, whose maximum over the row is least at the mid-range of the
/// α = c ± t − σy: max(max t, (max α − min α)/4).
#[derive(Clone)]
struct RowResidual {
    criterion: Criterion,
    row: Vec<PlaneStress>,
    /// von Mises: (l_x, l_y, c) of each point.
    affine: Vec<[f64; 3]>,
    /// Bounds of the residual search [stress].
    range: f64,
}

impl RowResidual {
    fn new(row: &[PlaneStress], criterion: Criterion) -> Option<Self> {
        let range = 2.0
            * row
                .iter()
                .map(|s| s.sxx.abs() + s.szz.abs() + s.syy.abs() + s.txz.abs())
                .fold(0.0, f64::max);
        let affine = row
            .iter()
            .map(|s| {
                let (a, c) = (s.sxx - s.szz, s.syy - s.szz);
                [
                    2.0 * (2.0 * a - c),
                    2.0 * (2.0 * c - a),
                    a * a + c * c + (c - a) * (c - a) + 6.0 * s.txz * s.txz,
                ]
            })
            .collect();
        (range > 0.0).then(|| Self {
            criterion,
            row: row.to_vec(),
            affine,
            range,
        })
    }

    /// (r_y, min over r_y of max_x τ_eq) for the residual r_x.
    fn best_over_ry(&self, rx: f64) -> (f64, f64) {
        match self.criterion {
            Criterion::VonMises => {
                let six_j2 = |ry: f64| {
                    let q = rx * rx + ry * ry + (ry - rx) * (ry - rx);
                    let m = self
                        .affine
                        .iter()
                        .map(|a| a[0] * rx + a[1] * ry + a[2])
                        .fold(f64::NEG_INFINITY, f64::max);
                    q + m
                };
                let (ry, v) = golden(-self.range, self.range, &mut |ry| six_j2(ry));
                (ry, (v / 6.0).max(0.0).sqrt())
            }
            Criterion::Tresca => {
                let (mut t_max, mut lo, mut hi) = (0.0f64, f64::INFINITY, f64::NEG_INFINITY);
                for s in &self.row {
                    let c = 0.5 * (s.sxx + rx + s.szz);
                    let t = (0.25 * (s.sxx + rx - s.szz).powi(2) + s.txz * s.txz).sqrt();
                    t_max = t_max.max(t);
                    for alpha in [c + t - s.syy, c - t - s.syy] {
                        lo = lo.min(alpha);
                        hi = hi.max(alpha);
                    }
                }
                (0.5 * (lo + hi), t_max.max(0.25 * (hi - lo)))
            }
        }
    }
}

/// min_r max_x τ_eq(σ^e + r) of a row: (r_x, r_y, the value), by an active set. The min–max
/// of a few points (the worst at r = 0 first) is solved by [`RowResidual`], the whole row
/// checked at its optimum, and the points above it join the set until none is: the optimum of
/// a subset that the whole row does not exceed is the whole row's (a few rounds of a dozen
/// points instead of the whole row in every step of the nested searches).
fn row_min_max(row: &[PlaneStress], criterion: Criterion) -> Option<(f64, f64, f64)> {
    const BATCH: usize = 12;
    let full = RowResidual::new(row, criterion)?;
    let shifted = |s: &PlaneStress, rx: f64, ry: f64| PlaneStress {
        sxx: s.sxx + rx,
        syy: s.syy + ry,
        ..*s
    };
    let worst_first = |rx: f64, ry: f64, t: f64, active: &[bool]| {
        let mut above: Vec<(f64, usize)> = row
            .iter()
            .enumerate()
            .filter(|(i, _)| !active[*i])
            .map(|(i, s)| (criterion.equivalent_shear(&shifted(s, rx, ry)), i))
            .filter(|(v, _)| *v > t)
            .collect();
        above.sort_by(|a, b| b.0.total_cmp(&a.0));
        above.into_iter().take(BATCH).map(|(_, i)| i).collect::<Vec<_>>()
    };
    let mut active = vec![false; row.len()];
    let mut chosen = worst_first(0.0, 0.0, -1.0, &active);
    loop {
        for &i in &chosen {
            active[i] = true;
        }
        let subset: Vec<PlaneStress> = (0..row.len()).filter(|&i| active[i]).map(|i| row[i]).collect();
        let mut sub = RowResidual::new(&subset, criterion).unwrap_or_else(|| RowResidual { ..full.clone() });
        sub.range = full.range;
        let (rx, _) = golden(-sub.range, sub.range, &mut |rx| sub.best_over_ry(rx).1);
        let (ry, t) = sub.best_over_ry(rx);
        chosen = worst_first(rx, ry, t * (1.0 + 1e-12) + 1e-12 * full.range, &active);
        if chosen.is_empty() {
            return Some((rx, ry, t));
        }
    }
}

/// Shakedown limit of one depth row `z` with the elastic stresses `row` along x (module
/// docs): λ_sd(z) = k / min_r max_x τ_eq(σ^e + r). None for an empty or unstressed row.
pub fn row_shakedown(z: f64, row: &[PlaneStress], k: f64, criterion: Criterion) -> Option<RowShakedown> {
    // Far from the contact the elastic stresses vanish, so the residual alone must lie within
    // yield there too: the row gets the point of zero stress wherever its sampled span ends.
    let far = PlaneStress {
        sxx: 0.0,
        szz: 0.0,
        txz: 0.0,
        syy: 0.0,
    };
    let row: Vec<PlaneStress> = row.iter().copied().chain(std::iter::once(far)).collect();
    let (rx, ry, t) = row_min_max(&row, criterion)?;
    if t <= 0.0 {
        return None;
    }
    let factor = k / t;
    Some(RowShakedown {
        z,
        factor,
        residual: [factor * rx, factor * ry],
    })
}

/// Where the shakedown limit is set, which says what happens above it (Johnson 1985 §9.4,
/// Fig. 9.12).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum ShakedownMode {
    /// Governed at the surface (the shallowest row): above the limit the surface flows
    /// plastically on every pass (surface ratchetting, high friction).
    Surface,
    /// Governed below the surface: above the limit plastic shakedown or subsurface ratchetting.
    Subsurface,
}

impl ShakedownMode {
    /// The name in outputs (`surface`, `subsurface`).
    pub fn name(self) -> &'static str {
        match self {
            ShakedownMode::Surface => "surface",
            ShakedownMode::Subsurface => "subsurface",
        }
    }
}

/// Shakedown of a grid of depth rows.
#[derive(Debug, Clone, PartialEq)]
pub struct Shakedown {
    /// λ_sd = min over the rows [-].
    pub factor: f64,
    /// Depth of the governing row [length].
    pub z: f64,
    /// Where it is governed.
    pub mode: ShakedownMode,
    /// Every row's limit and the residual at λ_sd (σx^r, σy^r), shallowest first.
    pub rows: Vec<RowShakedown>,
}

/// Depth rows: (depth [length], elastic stresses along x).
pub type Rows = Vec<(f64, Vec<PlaneStress>)>;

/// Shakedown over `rows` of (depth, stresses along x) with the shear yield stress `k`.
pub fn shakedown(rows: &[(f64, Vec<PlaneStress>)], k: f64, criterion: Criterion) -> Option<Shakedown> {
    use rayon::prelude::*;
    let mut out: Vec<RowShakedown> = rows
        .par_iter()
        .filter_map(|(z, r)| row_shakedown(*z, r, k, criterion))
        .collect();
    out.sort_by(|a, b| a.z.abs().total_cmp(&b.z.abs()));
    let g = out.iter().min_by(|a, b| a.factor.total_cmp(&b.factor))?;
    let (factor, z) = (g.factor, g.z);
    let mode = if z == out[0].z {
        ShakedownMode::Surface
    } else {
        ShakedownMode::Subsurface
    };
    // The residual that proves λ_sd: each row's r' = residual/factor at λ_sd.
    for r in &mut out {
        r.residual = [r.residual[0] * factor / r.factor, r.residual[1] * factor / r.factor];
    }
    Some(Shakedown {
        factor,
        z,
        mode,
        rows: out,
    })
}

/// The plane stress of an interior sample (σxx, σyy, σzz, τxy) with y the in-plane second axis
/// and σzz the out-of-plane stress ([`crate::interior::InteriorField::stress`]).
pub fn plane_stress(s: &[f64; 4]) -> PlaneStress {
    PlaneStress {
        sxx: s[0],
        szz: s[1],
        syy: s[2],
        txz: s[3],
    }
}

/// The depth rows of an interior field (its rows of constant second coordinate, the points
/// inside the body only), for [`shakedown`]; the depth is the second coordinate as the field
/// holds it.
pub fn field_rows(field: &InteriorField) -> Vec<(f64, Vec<PlaneStress>)> {
    let nx = field.shape[0];
    (0..field.shape[1])
        .filter_map(|j| {
            let idx = j * nx..(j + 1) * nx;
            let row: Vec<PlaneStress> = idx
                .clone()
                .filter(|&i| field.status[i] == PointStatus::Inside)
                .map(|i| plane_stress(&field.stress[i]))
                .collect();
            (!row.is_empty()).then(|| (field.points[idx.start][1], row))
        })
        .collect()
}

#[cfg(test)]
mod tests;
