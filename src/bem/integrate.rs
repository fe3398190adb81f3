//! Element integrals of the Kelvin kernels times the field shape functions, for one source point.
//!
//! For a source X and an element with geometry x(ξ), Jacobian J and field shape functions N_a:
//!
//! ```text
//! h[a][i][j] = ∫ T*_ij(X, x(ξ)) N_a(ξ) J(ξ) dξ        g[a][i][j] = ∫ U*_ij(X, x(ξ)) N_a(ξ) J(ξ) dξ
//! ```
//!
//! Three cases (Brebbia–Telles–Wrobel ch. 3; reference sheet §9):
//! * **Source off the element** — Gauss–Legendre with the number of points chosen from the
//!   distance. The integrand is analytic except where r² = 0 at complex ξ; with ρ the Bernstein
//!   ellipse parameter of the nearest such point relative to the (sub)interval, n-point Gauss
//!   converges like ρ^(−2n) (Trefethen, *Approximation Theory and Approximation Practice*,
//!   Thm 19.3), so n = ⌈ln(1/tol)/(2 ln ρ)⌉ + 1. The points are found exactly for the quadratic
//!   geometry (roots of x_x(ξ) ± i x_y(ξ) = X_x ± i X_y). When ρ is below
//!   [`QuadratureOptions::min_ellipse`] the interval is halved (adaptive subdivision, as Lachat
//!   & Watson's element subdivision), which keeps the accuracy down to sources at a small
//!   fraction of the element length from it (nearly singular integrals of thin bodies).
//! * **Source on the element at ξ0** (a field node of the element) — the element is split at ξ0
//!   and each part mapped to t ∈ [0, 1] (ξ = ξ0 ± ℓt). The weakly singular U* uses
//!   ln(1/r) = ln(1/t) + ln(t/r): the first part with a log-weighted Gauss rule
//!   (∫₀¹ f(t) ln(1/t) dt, exact for polynomial f of degree 2n−1), the smooth remainder with
//!   Gauss–Legendre. T* times the shape functions that vanish at ξ0 is bounded and smooth on
//!   each part: Gauss–Legendre.
//! * **The strongly singular T* times the shape function that is 1 at ξ0** is not computed
//!   here: the assembly gets the whole diagonal block (free term + CPV) from rigid-body
//!   translation, Σ_j H_ij = 0 (Brebbia–Telles–Wrobel §4.3).

// Index loops mirror the tensor notation of the formulas (a: shape function, i, j: components).
#![allow(clippy::needless_range_loop)]

use super::element::{ElementGeometry, FieldInterpolation};
use super::kernel::Kelvin;
use crate::quadrature::gauss_legendre;
use nalgebra::Complex;

/// Kernel integrals over one element: `[a][i][j]` = local field node a, force direction i,
/// component j.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct ElementIntegrals {
    /// ∫ T*_ij N_a J dξ [-].
    pub h: [[[f64; 2]; 2]; 3],
    /// ∫ U*_ij N_a J dξ [length/stress].
    pub g: [[[f64; 2]; 2]; 3],
}

/// Where the source point lies relative to the element.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum SourcePosition {
    /// Off the element (possibly very close to it).
    Off,
    /// At the element's field node `local`, at ξ = `xi`. The T* integral of that node's shape
    /// function is left at zero (it belongs to the rigid-body diagonal).
    OnNode {
        /// Intrinsic coordinate of the source.
        xi: f64,
        /// Local field node (0 start, 1 end, 2 mid) at the source.
        local: usize,
    },
}

/// Accuracy controls of the element integration.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct QuadratureOptions {
    /// Target relative accuracy of the regular and nearly singular integrals.
    pub tolerance: f64,
    /// Smallest Bernstein-ellipse parameter ρ accepted without subdividing (ρ = 3 needs 14
    /// points for 1e-12).
    pub min_ellipse: f64,
    /// Fewest Gauss points per (sub)interval.
    pub min_points: usize,
    /// Most Gauss points per (sub)interval.
    pub max_points: usize,
    /// Deepest subdivision (intervals of 2^−depth of the element).
    pub max_depth: usize,
    /// Gauss–Legendre points per part of a singular element.
    pub singular_points: usize,
    /// Log-weighted Gauss points per part of a singular element.
    pub log_points: usize,
}

impl Default for QuadratureOptions {
    fn default() -> Self {
        Self {
            tolerance: 1e-12,
            min_ellipse: 3.0,
            min_points: 4,
            max_points: 24,
            max_depth: 30,
            singular_points: 16,
            log_points: 12,
        }
    }
}

/// Precomputed quadrature rules shared by all element integrals of an assembly.
#[derive(Debug, Clone)]
pub struct Quadrature {
    /// The controls.
    pub options: QuadratureOptions,
    /// Gauss–Legendre rules on [−1, 1], index n − 1 for n points.
    legendre: Vec<(Vec<f64>, Vec<f64>)>,
    /// Log-weighted rule on [0, 1] for the weight ln(1/t).
    log: (Vec<f64>, Vec<f64>),
    /// ln(1/tolerance).
    log_inv_tolerance: f64,
}

impl Quadrature {
    /// Builds the rules for `options`.
    pub fn new(options: QuadratureOptions) -> Self {
        let top = options.max_points.max(options.singular_points).max(1);
        Self {
            options,
            legendre: (1..=top).map(gauss_legendre).collect(),
            log: log_gauss(options.log_points.max(1)),
            log_inv_tolerance: (1.0 / options.tolerance).ln(),
        }
    }

    /// The n-point Gauss–Legendre rule on [−1, 1] (n clamped to the precomputed range).
    pub fn legendre(&self, n: usize) -> &(Vec<f64>, Vec<f64>) {
        &self.legendre[n.clamp(1, self.legendre.len()) - 1]
    }

    /// Integrals of U* and T* over an element for a source at `source` (see the module docs).
    pub fn element_integrals(
        &self,
        kernel: &Kelvin,
        geometry: &ElementGeometry,
        field: &FieldInterpolation,
        source: [f64; 2],
        position: SourcePosition,
    ) -> ElementIntegrals {
        let mut out = ElementIntegrals::default();
        match position {
            SourcePosition::Off => self.off_element(kernel, geometry, field, source, &mut out),
            SourcePosition::OnNode { xi, local } => {
                self.on_element(kernel, geometry, field, source, xi, local, &mut out)
            }
        }
        out
    }

    /// Adaptive Gauss over sub-intervals whose nearest kernel singularity is far enough.
    fn off_element(
        &self,
        kernel: &Kelvin,
        geometry: &ElementGeometry,
        field: &FieldInterpolation,
        source: [f64; 2],
        out: &mut ElementIntegrals,
    ) {
        self.off_element_points(geometry, source, |xi, weight| {
            accumulate(kernel, geometry, field, source, xi, weight, None, out)
        });
    }

    /// Visits the quadrature points (ξ, weight in dξ) of the adaptive Gauss rule for an element
    /// and a source off it (see the module docs): intervals are halved until the nearest complex
    /// singularity of r² or J lies outside the Bernstein ellipse of parameter
    /// [`QuadratureOptions::min_ellipse`], and each interval gets the points its ellipse needs
    /// for [`QuadratureOptions::tolerance`]. The estimate is that of a 1/r kernel; it serves the
    /// 1/r² kernels (T*, V, S) as well, whose Gauss error decays at the same geometric rate.
    /// Any kernel can be integrated with it: the caller evaluates its integrand at x(ξ) and
    /// multiplies by J(ξ) and the weight.
    ///
    /// Nothing is allocated (this runs once per element and source point: millions of times
    /// for an interior grid); the subdivision depth is capped at [`MAX_DEPTH`], below which
    /// intervals are finer than the resolution of ξ in double precision.
    pub fn off_element_points(&self, geometry: &ElementGeometry, source: [f64; 2], mut visit: impl FnMut(f64, f64)) {
        let o = &self.options;
        let poles = complex_singularities(geometry, source);
        let max_depth = o.max_depth.min(MAX_DEPTH);
        // Depth-first: at most one pending sibling per level, so max_depth + 1 entries.
        let mut stack = [(0.0, 0.0, 0usize); MAX_DEPTH + 1];
        stack[0] = (-1.0, 1.0, 0);
        let mut top = 1;
        while top > 0 {
            top -= 1;
            let (lo, hi, depth) = stack[top];
            let rho = bernstein_parameter(poles.as_slice(), lo, hi);
            if rho < o.min_ellipse && depth < max_depth {
                let mid = 0.5 * (lo + hi);
                stack[top] = (lo, mid, depth + 1);
                stack[top + 1] = (mid, hi, depth + 1);
                top += 2;
                continue;
            }
            let n = points_for(rho, self.log_inv_tolerance).clamp(o.min_points, o.max_points);
            let (x, w) = self.legendre(n);
            let half = 0.5 * (hi - lo);
            for (&s, &wk) in x.iter().zip(w) {
                visit(0.5 * (lo + hi) + half * s, wk * half);
            }
        }
    }

    /// Split at the source; log-weighted rule for ln(1/t), Gauss–Legendre for the rest.
    #[allow(clippy::too_many_arguments)]
    fn on_element(
        &self,
        kernel: &Kelvin,
        geometry: &ElementGeometry,
        field: &FieldInterpolation,
        source: [f64; 2],
        xi0: f64,
        local: usize,
        out: &mut ElementIntegrals,
    ) {
        let c_log = kernel.log_coefficient();
        let (x, w) = self.legendre(self.options.singular_points);
        for (length, direction) in [(xi0 + 1.0, -1.0), (1.0 - xi0, 1.0)] {
            if length <= 0.0 {
                continue;
            }
            // ξ = ξ0 + direction·length·t, dξ = length dt.
            for (&s, &wk) in x.iter().zip(w) {
                let t = 0.5 * (1.0 + s);
                let xi = xi0 + direction * length * t;
                let weight = 0.5 * wk * length;
                // U* + c ln t = c ln(t·ℓ/r) + … is smooth at t → 0.
                accumulate(
                    kernel,
                    geometry,
                    field,
                    source,
                    xi,
                    weight,
                    Some((local, c_log * t.ln())),
                    out,
                );
            }
            // c ∫ ln(1/t) N_a J dξ on the diagonal components.
            for (&t, &wk) in self.log.0.iter().zip(&self.log.1) {
                let xi = xi0 + direction * length * t;
                let nj = field.shape(xi);
                let jac = geometry.jacobian(xi);
                for a in 0..3 {
                    let v = c_log * nj[a] * jac * wk * length;
                    out.g[a][0][0] += v;
                    out.g[a][1][1] += v;
                }
            }
        }
    }
}

/// Adds one quadrature point's contribution. `singular = Some((local, c ln t))` adds c ln t to
/// the diagonal of U* (the subtracted logarithm) and skips T* for the shape function `local`.
#[allow(clippy::too_many_arguments)]
#[inline]
fn accumulate(
    kernel: &Kelvin,
    geometry: &ElementGeometry,
    field: &FieldInterpolation,
    source: [f64; 2],
    xi: f64,
    weight: f64,
    singular: Option<(usize, f64)>,
    out: &mut ElementIntegrals,
) {
    let x = geometry.point(xi);
    let tangent = geometry.tangent(xi);
    let jac = tangent[0].hypot(tangent[1]);
    let normal = [tangent[1] / jac, -tangent[0] / jac];
    let n = field.shape(xi);
    let mut u = kernel.displacement(source, x);
    let t = kernel.traction(source, x, normal);
    let skip = if let Some((local, log_shift)) = singular {
        u[0][0] += log_shift;
        u[1][1] += log_shift;
        Some(local)
    } else {
        None
    };
    let wj = weight * jac;
    for a in 0..3 {
        let f = n[a] * wj;
        for i in 0..2 {
            for j in 0..2 {
                out.g[a][i][j] += u[i][j] * f;
                if skip != Some(a) {
                    out.h[a][i][j] += t[i][j] * f;
                }
            }
        }
    }
}

/// Gauss points needed for relative accuracy tol when the nearest singularity has Bernstein
/// parameter ρ: error ≈ ρ^(−2n).
/// `log_inv_tol` = ln(1/tol), computed once per [`Quadrature`].
fn points_for(rho: f64, log_inv_tol: f64) -> usize {
    if !rho.is_finite() {
        return 1;
    }
    let n = log_inv_tol / (2.0 * rho.max(1.0 + 1e-12).ln());
    n.ceil() as usize + 1
}

/// Deepest interval halving of [`Quadrature::off_element_points`] whatever the options: 2^−50
/// of the element is at the resolution of ξ ∈ [−1, 1] in double precision.
pub const MAX_DEPTH: usize = 50;

/// Up to `N` complex numbers, without allocation.
#[derive(Debug, Clone, Copy)]
struct Few<const N: usize> {
    values: [Complex<f64>; N],
    len: usize,
}

impl<const N: usize> Few<N> {
    fn new() -> Self {
        Self {
            values: [Complex::new(0.0, 0.0); N],
            len: 0,
        }
    }

    fn push(&mut self, z: Complex<f64>) {
        self.values[self.len] = z;
        self.len += 1;
    }

    fn as_slice(&self) -> &[Complex<f64>] {
        &self.values[..self.len]
    }
}

/// Complex ξ where the integrand is singular: r² = 0 (roots of P±(ξ) = (x_x − X_x) ± i(x_y − X_y))
/// and J = 0 (roots of x'_x ± i x'_y), for the quadratic map x(ξ) = a + bξ + cξ².
fn complex_singularities(geometry: &ElementGeometry, source: [f64; 2]) -> Few<6> {
    let [p0, p1, pm] = geometry.nodes;
    // x(ξ) = pm + ξ (p1 − p0)/2 + ξ² ((p0 + p1)/2 − pm)
    let a = [pm[0] - source[0], pm[1] - source[1]];
    let b = [0.5 * (p1[0] - p0[0]), 0.5 * (p1[1] - p0[1])];
    let c = [0.5 * (p0[0] + p1[0]) - pm[0], 0.5 * (p0[1] + p1[1]) - pm[1]];
    let mut roots = Few::new();
    for sign in [1.0, -1.0] {
        let z = |v: [f64; 2]| Complex::new(v[0], sign * v[1]);
        for r in quadratic_roots(z(c), z(b), z(a)).as_slice() {
            roots.push(*r);
        }
        // J² = x'·x' = (x'_x + i x'_y)(x'_x − i x'_y), x' = b + 2cξ.
        for r in quadratic_roots(Complex::new(0.0, 0.0), z(c) * 2.0, z(b)).as_slice() {
            roots.push(*r);
        }
    }
    roots
}

/// Roots of c2 ξ² + c1 ξ + c0 (complex coefficients); degenerate leading terms drop roots.
fn quadratic_roots(c2: Complex<f64>, c1: Complex<f64>, c0: Complex<f64>) -> Few<2> {
    let mut r = Few::new();
    let scale = c0.norm().max(c1.norm()).max(c2.norm());
    if scale == 0.0 {
        return r;
    }
    if c2.norm() <= 1e-14 * scale {
        if c1.norm() > 1e-14 * scale {
            r.push(-c0 / c1);
        }
        return r;
    }
    let disc = (c1 * c1 - c2 * c0 * 4.0).sqrt();
    // Numerically stable pair: q = −(c1 + sgn·disc)/2, roots q/c2 and c0/q.
    let q = if (c1.conj() * disc).re >= 0.0 {
        -(c1 + disc) * 0.5
    } else {
        -(c1 - disc) * 0.5
    };
    r.push(q / c2);
    if q.norm() > 0.0 {
        r.push(c0 / q);
    }
    r
}

/// Smallest Bernstein-ellipse parameter ρ = a + √(a² − 1) of the singularities relative to the
/// interval [lo, hi], with a = (|s − 1| + |s + 1|)/2 the semi-major axis through the point s
/// in the interval's own coordinate s ∈ [−1, 1].
fn bernstein_parameter(poles: &[Complex<f64>], lo: f64, hi: f64) -> f64 {
    let mid = 0.5 * (lo + hi);
    let half = 0.5 * (hi - lo);
    poles
        .iter()
        .map(|p| {
            let s = (p - mid) / half;
            // |z| as √(z·z̄): Complex::norm calls hypot, several times slower.
            let a = 0.5 * ((s - 1.0).norm_sqr().sqrt() + (s + 1.0).norm_sqr().sqrt());
            a + (a * a - 1.0).max(0.0).sqrt()
        })
        .fold(f64::INFINITY, f64::min)
}

/// A lower bound, cheap to evaluate, on the Bernstein-ellipse parameter ρ (relative to the
/// whole element ξ ∈ [−1, 1]) of every complex singularity of an off-element integrand, for
/// far-field sources: it spares the root finding of [`Quadrature::off_element_points`] for the
/// many elements far from an interior point.
///
/// With x(ξ) = x_m + bξ + cξ² (x_m the mid node), a singularity of 1/r, r² = 0 at complex ξ*,
/// satisfies x_m − X = −(bξ* + cξ*²), so D = |X − x_m| ≤ |b||ξ*| + |c||ξ*|² (the triangle
/// inequality in ℂ², b and c real vectors): |ξ*| ≥ R(D) = 2D/(|b| + √(|b|² + 4|c|D)). The zeros
/// of the Jacobian, (b + 2cξ)·(b + 2cξ) = 0, a real quadratic with complex-conjugate roots, have
/// |ξ| = |b|/(2|c|). A point s with |s| = R ≥ 1 has ρ(s) = a + √(a² − 1) with
/// a = (|s − 1| + |s + 1|)/2 ≥ R, hence ρ ≥ R + √(R² − 1) for both kinds.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SingularityBound {
    /// x_m [length].
    centre: [f64; 2],
    /// |b| [length].
    b: f64,
    /// |c| [length].
    c: f64,
    /// The bound on ρ from the Jacobian's zeros (infinite for a straight element).
    rho_jacobian: f64,
}

impl SingularityBound {
    /// The bound of an element.
    pub fn new(geometry: &ElementGeometry) -> Self {
        let [p0, p1, pm] = geometry.nodes;
        let b = (0.5 * (p1[0] - p0[0])).hypot(0.5 * (p1[1] - p0[1]));
        let c = (0.5 * (p0[0] + p1[0]) - pm[0]).hypot(0.5 * (p0[1] + p1[1]) - pm[1]);
        let rho_jacobian = if c > 0.0 {
            ellipse_of_radius(b / (2.0 * c))
        } else {
            f64::INFINITY
        };
        Self {
            centre: pm,
            b,
            c,
            rho_jacobian,
        }
    }

    /// A lower bound on ρ of every singularity for a source at `source` (see the type's docs).
    pub fn rho_lower_bound(&self, source: [f64; 2]) -> f64 {
        let (dx, dy) = (source[0] - self.centre[0], source[1] - self.centre[1]);
        let d = (dx * dx + dy * dy).sqrt();
        let radius = 2.0 * d / (self.b + (self.b * self.b + 4.0 * self.c * d).sqrt());
        ellipse_of_radius(radius).min(self.rho_jacobian)
    }
}

/// R + √(R² − 1) for R ≥ 1, else 1: the smallest ρ of a point at distance R from 0.
fn ellipse_of_radius(radius: f64) -> f64 {
    if radius > 1.0 {
        radius + (radius * radius - 1.0).sqrt()
    } else {
        1.0
    }
}

impl SingularityBound {
    /// The distance D from the mid node beyond which the bound reaches ρ: the inverse of
    /// [`Self::rho_lower_bound`], D = |c|R² + |b|R with R = (ρ + 1/ρ)/2 [length]; infinite when
    /// the Jacobian's zeros keep the bound below ρ at any distance.
    fn distance_for(&self, rho: f64) -> f64 {
        if self.rho_jacobian < rho {
            return f64::INFINITY;
        }
        let radius = 0.5 * (rho + 1.0 / rho);
        self.c * radius * radius + self.b * radius
    }
}

/// Far-field Gauss rules of one element for a [`Quadrature`]: the squared distances from the mid
/// node beyond which n = first, first + 1, … points on the whole element meet the tolerance by
/// the [`SingularityBound`] (without subdivision), so that choosing the rule for a source costs
/// a few comparisons.
#[derive(Debug, Clone, PartialEq)]
pub struct FarFieldRules {
    /// The mid node [length].
    centre: [f64; 2],
    /// Fewest points ([`QuadratureOptions::min_points`]).
    first: usize,
    /// distance2[n − first]: squared distance [length²] from which n points suffice
    /// (non-increasing in n).
    distance2: Vec<f64>,
}

impl FarFieldRules {
    /// The number of Gauss–Legendre points on the whole element [−1, 1] that meet the tolerance
    /// for `source`, or `None` when the source may be near (then use
    /// [`Quadrature::off_element_points`]). When it is `Some(n)`, the adaptive rule would not
    /// subdivide and would use at most n points, so this rule is at least as accurate.
    #[inline]
    pub fn points(&self, source: [f64; 2]) -> Option<usize> {
        let (dx, dy) = (source[0] - self.centre[0], source[1] - self.centre[1]);
        let d2 = dx * dx + dy * dy;
        self.distance2.iter().position(|&t| d2 >= t).map(|k| self.first + k)
    }
}

impl Quadrature {
    /// The far-field rules of an element with up to `max_points` points (see
    /// [`FarFieldRules`]): n points need ρ ≥ max(min_ellipse, tol^(−1/(2(n − 1)))), the
    /// inverse of the point count n = ⌈ln(1/tol)/(2 ln ρ)⌉ + 1 of the adaptive rule.
    pub fn far_field_rules(&self, geometry: &ElementGeometry, max_points: usize) -> FarFieldRules {
        let bound = SingularityBound::new(geometry);
        let o = &self.options;
        let first = o.min_points.max(2);
        let distance2 = (first..=max_points.min(o.max_points))
            .map(|n| {
                let rho = (self.log_inv_tolerance / (2.0 * (n - 1) as f64))
                    .exp()
                    .max(o.min_ellipse);
                bound.distance_for(rho).powi(2)
            })
            .collect();
        FarFieldRules {
            centre: bound.centre,
            first,
            distance2,
        }
    }
}

/// n-point Gauss rule for ∫₀¹ f(t) ln(1/t) dt, exact for polynomials of degree 2n − 1.
///
/// Recurrence coefficients by Gautschi's modified Chebyshev algorithm (*Orthogonal
/// Polynomials: Computation and Approximation*, 2004, Alg. 2.1) from the modified moments on
/// the shifted Legendre polynomials, ∫₀¹ P*_k(t) ln(1/t) dt = (−1)^k/(k(k+1)) (k ≥ 1, and 1 for
/// k = 0) — well conditioned, unlike ordinary moments — then Golub–Welsch.
pub fn log_gauss(n: usize) -> (Vec<f64>, Vec<f64>) {
    let m2 = 2 * n;
    // Monic shifted Legendre: π_{k+1} = (t − ½) π_k − b_k π_{k−1}, b_k = k²/(4(4k² − 1)).
    let a_rec = vec![0.5; m2];
    let b_rec: Vec<f64> = (0..m2)
        .map(|k| {
            let k = k as f64;
            if k == 0.0 {
                1.0
            } else {
                k * k / (4.0 * (4.0 * k * k - 1.0))
            }
        })
        .collect();
    // Modified moments of the monic polynomials: P*_k has leading coefficient (2k)!/(k!)².
    let moments: Vec<f64> = (0..m2)
        .map(|k| {
            if k == 0 {
                return 1.0;
            }
            let mut lead = 1.0;
            for j in 1..=k {
                lead *= (k + j) as f64 / j as f64;
            }
            let sign = if k % 2 == 0 { 1.0 } else { -1.0 };
            sign / ((k * (k + 1)) as f64) / lead
        })
        .collect();
    let mut alpha = vec![0.0; n];
    let mut beta = vec![0.0; n];
    let mut sigma_prev = vec![0.0; m2]; // σ_{k−2, ·}
    let mut sigma = moments.clone(); // σ_{k−1, ·}
    alpha[0] = a_rec[0] + moments[1] / moments[0];
    beta[0] = moments[0];
    for k in 1..n {
        let mut next = vec![0.0; m2];
        for l in k..(m2 - k) {
            next[l] = sigma[l + 1] - (alpha[k - 1] - a_rec[l]) * sigma[l] - beta[k - 1] * sigma_prev[l]
                + b_rec[l] * sigma[l - 1];
        }
        alpha[k] = a_rec[k] + next[k + 1] / next[k] - sigma[k] / sigma[k - 1];
        beta[k] = next[k] / sigma[k - 1];
        sigma_prev = sigma;
        sigma = next;
    }
    let jacobi = nalgebra::DMatrix::from_fn(n, n, |i, j| {
        if i == j {
            alpha[i]
        } else if i + 1 == j || j + 1 == i {
            beta[i.max(j)].sqrt()
        } else {
            0.0
        }
    });
    let eig = nalgebra::SymmetricEigen::new(jacobi);
    let mut pairs: Vec<(f64, f64)> = (0..n)
        .map(|i| (eig.eigenvalues[i], beta[0] * eig.eigenvectors[(0, i)].powi(2)))
        .collect();
    pairs.sort_by(|p, q| p.0.total_cmp(&q.0));
    pairs.into_iter().unzip()
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::material::Elastic;

    #[test]
    fn log_gauss_matches_the_reference_sheet_and_integrates_log_moments() {
        // Reference sheet §9 (Stroud & Secrest for n = 2).
        let (t, w) = log_gauss(2);
        assert!((t[0] - 0.112008806166976).abs() < 1e-13 && (t[1] - 0.602276908118738).abs() < 1e-13);
        assert!((w[0] - 0.718539319030384).abs() < 1e-13 && (w[1] - 0.281460680969616).abs() < 1e-13);
        let (t, w) = log_gauss(8);
        assert!((t[0] - 0.013320244160892).abs() < 1e-13 && (t[7] - 0.953326450056360).abs() < 1e-13);
        assert!((w[0] - 0.164416604728003).abs() < 1e-13 && (w[7] - 0.003686407104028).abs() < 1e-13);
        // ∫₀¹ t^k ln(1/t) dt = 1/(k+1)², exact up to degree 2n − 1.
        for n in [3, 6, 12, 16] {
            let (t, w) = log_gauss(n);
            for k in 0..(2 * n) {
                let q: f64 = t.iter().zip(&w).map(|(t, w)| w * t.powi(k as i32)).sum();
                let exact = 1.0 / ((k + 1) * (k + 1)) as f64;
                assert!(
                    (q - exact).abs() < 1e-13 * exact.max(1e-3),
                    "n={n} k={k}: {q} vs {exact}"
                );
            }
        }
    }

    fn brute_force(kernel: &Kelvin, g: &ElementGeometry, f: &FieldInterpolation, source: [f64; 2]) -> ElementIntegrals {
        // Composite Gauss over 4000 panels: a reference for nearly singular cases (source
        // off the element), accurate to ~1e-13 for distances ≥ 1e-3 element lengths.
        let mut out = ElementIntegrals::default();
        let (x, w) = gauss_legendre(10);
        let panels = 4000;
        for p in 0..panels {
            let lo = -1.0 + 2.0 * p as f64 / panels as f64;
            let half = 1.0 / panels as f64;
            for (&s, &wk) in x.iter().zip(&w) {
                accumulate(kernel, g, f, source, lo + half * (1.0 + s), wk * half, None, &mut out);
            }
        }
        out
    }

    fn max_rel_diff(a: &ElementIntegrals, b: &ElementIntegrals) -> f64 {
        let scale_h = b.h.iter().flatten().flatten().fold(0.0f64, |m, v| m.max(v.abs()));
        let scale_g = b.g.iter().flatten().flatten().fold(0.0f64, |m, v| m.max(v.abs()));
        let mut e = 0.0f64;
        for a_ in 0..3 {
            for i in 0..2 {
                for j in 0..2 {
                    e = e.max((a.h[a_][i][j] - b.h[a_][i][j]).abs() / scale_h);
                    e = e.max((a.g[a_][i][j] - b.g[a_][i][j]).abs() / scale_g);
                }
            }
        }
        e
    }

    #[test]
    fn nearly_singular_integrals_are_accurate_down_to_a_tenth_of_the_element_length() {
        let kernel = Kelvin::new(&Elastic::new(1000.0, 0.3), 10.0);
        let q = Quadrature::new(QuadratureOptions::default());
        // A curved element (30° arc of radius 3) and a straight one of length 2.
        let r = 3.0f64;
        let arc = ElementGeometry {
            nodes: [
                [r * (-0.25f64).sin(), r * (-0.25f64).cos()],
                [r * 0.25f64.sin(), r * 0.25f64.cos()],
                [0.0, r],
            ],
        };
        let straight = ElementGeometry {
            nodes: [[-1.0, 0.0], [1.0, 0.0], [0.0, 0.0]],
        };
        let f = FieldInterpolation::CONTINUOUS;
        for g in [arc, straight] {
            let length = g.length();
            for (xi, d) in [(0.3, 0.1), (-0.95, 0.1), (0.0, 0.05), (1.0, 0.1), (0.6, 2.0)] {
                // Source at distance d·L from x(ξ), on either side, along the normal.
                for side in [1.0, -1.0] {
                    let p = g.point(xi);
                    let n = g.normal(xi);
                    let source = [p[0] + side * d * length * n[0], p[1] + side * d * length * n[1]];
                    let fast = q.element_integrals(&kernel, &g, &f, source, SourcePosition::Off);
                    let slow = brute_force(&kernel, &g, &f, source);
                    let e = max_rel_diff(&fast, &slow);
                    assert!(e < 1e-11, "xi={xi} d={d} side={side}: {e}");
                }
            }
        }
    }

    #[test]
    fn singular_log_integral_matches_the_closed_form_on_a_straight_element() {
        // Straight element [−1, 1] on the x axis, source at ξ0: ∫ ln(1/|ξ−ξ0|) N_a dξ has a
        // closed form; check the U*_11 − U*_22 split too (r,1² = 1, r,2² = 0 on the line).
        let kernel = Kelvin::new(&Elastic::new(1000.0, 0.25), 1.0);
        let q = Quadrature::new(QuadratureOptions::default());
        let g = ElementGeometry {
            nodes: [[-1.0, 0.0], [1.0, 0.0], [0.0, 0.0]],
        };
        let f = FieldInterpolation::DISCONTINUOUS;
        for (local, xi0) in [(0usize, -2.0 / 3.0), (2, 0.0), (1, 2.0 / 3.0)] {
            let source = g.point(xi0);
            let ints = q.element_integrals(&kernel, &g, &f, source, SourcePosition::OnNode { xi: xi0, local });
            // Reference: composite rule on each side of ξ0 with a graded mesh towards ξ0.
            let mut reference = [0.0; 3];
            let (x, w) = gauss_legendre(20);
            for (lo, hi) in [(-1.0, xi0), (xi0, 1.0)] {
                let levels = 50;
                for l in 0..levels {
                    // Geometric panels towards ξ0: [ξ0 ± δ_{l+1}, ξ0 ± δ_l], δ_l = len·2^−l.
                    let len: f64 = hi - lo;
                    let (a, b) = if lo == xi0 {
                        (xi0 + len * 0.5f64.powi(l + 1), xi0 + len * 0.5f64.powi(l))
                    } else {
                        (xi0 - len * 0.5f64.powi(l), xi0 - len * 0.5f64.powi(l + 1))
                    };
                    for (&s, &wk) in x.iter().zip(&w) {
                        let xi = 0.5 * (a + b) + 0.5 * (b - a) * s;
                        let n = f.shape(xi);
                        for k in 0..3 {
                            reference[k] += 0.5 * (b - a) * wk * n[k] * (1.0 / (xi - xi0).abs()).ln();
                        }
                    }
                }
            }
            let c = kernel.log_coefficient();
            let cu = 1.0 / (8.0 * std::f64::consts::PI * kernel.shear * (1.0 - kernel.poisson));
            for k in 0..3 {
                // ∫ N_k dξ (polynomial: Gauss is exact).
                let ints_n: f64 = x.iter().zip(&w).map(|(&s, &wk)| wk * f.shape(s)[k]).sum();
                let expected_22 = c * reference[k];
                let expected_11 = c * reference[k] + cu * ints_n;
                assert!(
                    (ints.g[k][1][1] - expected_22).abs() < 1e-12 * c,
                    "{k}: {} vs {expected_22}",
                    ints.g[k][1][1]
                );
                assert!((ints.g[k][0][0] - expected_11).abs() < 1e-12 * c, "{k}");
                assert!(ints.g[k][0][1].abs() < 1e-15 * c);
            }
            // On a straight element ∂r/∂n = 0 and T*_ij N_b is odd about ξ0 only through
            // (r,i n_j − r,j n_i)/r: the skipped diagonal node has h = 0.
            assert_eq!(ints.h[local], [[0.0; 2]; 2]);
        }
    }

    #[test]
    fn singularity_bound_is_below_every_singularity() {
        // Arcs of 10°, 30° and 90°, a straight element and an unevenly parametrised parabola;
        // sources on a grid around each: the bound never exceeds the exact smallest ρ (the
        // roots of complex_singularities), and it is tight far away (within 25 % at 20 lengths).
        let arc = |deg: f64| {
            let h = 0.5 * deg.to_radians();
            ElementGeometry {
                nodes: [[-(h.sin()), h.cos()], [h.sin(), h.cos()], [0.0, 1.0]],
            }
        };
        let elements = [
            arc(10.0),
            arc(30.0),
            arc(90.0),
            ElementGeometry {
                nodes: [[0.0, 0.0], [2.0, 0.0], [1.0, 0.0]],
            },
            ElementGeometry {
                nodes: [[0.0, 0.0], [2.0, 0.3], [0.8, 0.4]],
            },
        ];
        for g in &elements {
            let bound = SingularityBound::new(g);
            let length = g.length();
            for i in -20..=20 {
                for j in -20..=20 {
                    let source = [0.37 * length * i as f64, 0.41 * length * j as f64 + 0.013];
                    let exact = bernstein_parameter(complex_singularities(g, source).as_slice(), -1.0, 1.0);
                    let lower = bound.rho_lower_bound(source);
                    assert!(lower <= exact * (1.0 + 1e-12), "{g:?} at {source:?}: {lower} > {exact}");
                }
            }
            let far = [20.0 * length, 3.0];
            let (lower, exact) = (
                bound.rho_lower_bound(far),
                bernstein_parameter(complex_singularities(g, far).as_slice(), -1.0, 1.0),
            );
            assert!(
                lower > 0.75 * exact.min(bound.rho_jacobian),
                "{g:?}: {lower} vs {exact}"
            );
        }
    }

    #[test]
    fn far_field_rules_never_use_fewer_points_than_the_adaptive_rule() {
        // For sources all around three elements: whenever the far-field rule applies, the
        // adaptive rule does not subdivide and uses at most as many points. On the 30° arc and
        // the straight element it serves most sources; on the strongly curved parabola (mid node
        // a quarter of the chord off it) the Jacobian's complex zeros are too close to [−1, 1]
        // for 12 points, so the far-field rule never applies there.
        let q = Quadrature::new(QuadratureOptions::default());
        let h = 15f64.to_radians();
        for g in [
            ElementGeometry {
                nodes: [[-(h.sin()), h.cos()], [h.sin(), h.cos()], [0.0, 1.0]],
            },
            ElementGeometry {
                nodes: [[0.0, 0.0], [2.0, 0.0], [1.0, 0.0]],
            },
            ElementGeometry {
                nodes: [[0.0, 0.0], [2.0, 0.3], [0.8, 0.4]],
            },
        ] {
            let rules = q.far_field_rules(&g, 12);
            let mut used = 0;
            for i in -30..=30 {
                for j in -30..=30 {
                    let source = [0.9 * i as f64 + 0.01, 0.7 * j as f64 + 0.02];
                    let Some(n) = rules.points(source) else { continue };
                    used += 1;
                    let mut intervals = 0;
                    let mut adaptive = 0;
                    let mut last = f64::NAN;
                    q.off_element_points(&g, source, |xi, _| {
                        adaptive += 1;
                        if xi < last {
                            intervals += 1;
                        }
                        last = xi;
                    });
                    assert!(
                        intervals == 0 && adaptive <= n,
                        "{source:?}: far {n}, adaptive {adaptive}"
                    );
                }
            }
            let curved = g.nodes[2] == [0.8, 0.4];
            assert!(
                if curved { used == 0 } else { used > 3000 },
                "{g:?} {rules:?}: far-field rule used for {used} of 3721 sources"
            );
        }
    }
}
