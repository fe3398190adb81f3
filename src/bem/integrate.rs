//! Element integrals of the Kelvin kernels times the field shape functions, for one source point.
//!
//! For a source X and an element with geometry x(ξ), Jacobian J and field shape functions N_a:
//!
//! ```text
//! h[a][i][j] = ∫ T*_ij(X, x(ξ)) N_a(ξ) J(ξ) dξ        g[a][i][j] = ∫ U*_ij(X, x(ξ)) N_a(ξ) J(ξ) dξ
//! ```
//!
//! Three cases (Brebbia–Telles–Wrobel ch. 3; docs/references.md §9):
//! * **Source off the element** — Gauss–Legendre with the number of points chosen from the
//!   distance. The integrand is analytic except where r² = 0 at complex ξ; with ρ the Bernstein
//!   ellipse parameter of the nearest such point relative to the (sub)interval, n-point Gauss
//!   converges like ρ^(−2n) (Trefethen, *Approximation Theory and Approximation Practice*,
//!   Thm 19.3), so n = ⌈ln(1/tol)/(2 ln ρ)⌉ + 1. The points are found exactly for the quadratic
//!   geometry (roots of x_x(ξ) ± i x_y(ξ) = X_x ± i X_y). When ρ is below
//!   [`QuadratureOptions::min_ellipse`] the interval is halved (adaptive subdivision, as Lachat
//!   & Watson's element subdivision), which keeps the accuracy down to sources at a small
//!   fraction of the element length from it (nearly singular integrals of thin bodies). The
//!   rule itself is [`Quadrature::off_element_points`] of [`crate::quadrature`].
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
use super::fundamental::FundamentalSolution;
use super::kernel::KernelFrame;
use crate::quadrature::Quadrature;
#[cfg(doc)]
use crate::quadrature::QuadratureOptions;

/// Kernel integrals over one element: `[a][i][j]` = local field node a, force direction i,
/// component j.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct ElementIntegrals {
    /// ∫ T*_ij N_a J dξ [-].
    pub h: [[[f64; 2]; 2]; 3],
    /// ∫ U*_ij N_a J dξ [length/stress].
    pub g: [[[f64; 2]; 2]; 3],
}

impl ElementIntegrals {
    /// Adds local node `a`'s 2 × 2 blocks to the collocation rows of one source point:
    /// `rows` holds the two rows of H then the two of G, each `stride` long, and the node's
    /// components are the columns 2·`column` and 2·`column` + 1.
    #[inline]
    pub fn add_node_to_rows(&self, a: usize, rows: &mut [f64], stride: usize, column: usize) {
        for ic in 0..2 {
            for jc in 0..2 {
                rows[ic * stride + 2 * column + jc] += self.h[a][ic][jc];
                rows[(2 + ic) * stride + 2 * column + jc] += self.g[a][ic][jc];
            }
        }
    }
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

/// Integrals of U* and T* over an element for a source at `source` (see the module docs).
pub fn element_integrals<K: FundamentalSolution>(
    quadrature: &Quadrature,
    kernel: &K,
    geometry: &ElementGeometry,
    field: &FieldInterpolation,
    source: [f64; 2],
    position: SourcePosition,
) -> ElementIntegrals {
    let mut out = ElementIntegrals::default();
    match position {
        SourcePosition::Off => off_element(quadrature, kernel, geometry, field, source, &mut out),
        SourcePosition::OnNode { xi, local } => {
            on_element(quadrature, kernel, geometry, field, source, xi, local, &mut out)
        }
    }
    out
}

/// Adaptive Gauss over sub-intervals whose nearest kernel singularity is far enough.
fn off_element<K: FundamentalSolution>(
    quadrature: &Quadrature,
    kernel: &K,
    geometry: &ElementGeometry,
    field: &FieldInterpolation,
    source: [f64; 2],
    out: &mut ElementIntegrals,
) {
    quadrature.off_element_points(&geometry.nodes, source, |xi, weight| {
        accumulate(kernel, geometry, field, source, xi, weight, None, out)
    });
}

/// Split at the source; log-weighted rule for ln(1/t), Gauss–Legendre for the rest.
#[allow(clippy::too_many_arguments)]
fn on_element<K: FundamentalSolution>(
    quadrature: &Quadrature,
    kernel: &K,
    geometry: &ElementGeometry,
    field: &FieldInterpolation,
    source: [f64; 2],
    xi0: f64,
    local: usize,
    out: &mut ElementIntegrals,
) {
    let c_log = kernel.log_coefficient();
    let (x, w) = quadrature.legendre(quadrature.options.singular_points);
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
        let log = quadrature.log_rule();
        for (&t, &wk) in log.0.iter().zip(&log.1) {
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

/// Adds one quadrature point's contribution. `singular = Some((local, c ln t))` adds c ln t to
/// the diagonal of U* (the subtracted logarithm) and skips T* for the shape function `local`.
#[allow(clippy::too_many_arguments)]
#[inline]
fn accumulate<K: FundamentalSolution>(
    kernel: &K,
    geometry: &ElementGeometry,
    field: &FieldInterpolation,
    source: [f64; 2],
    xi: f64,
    weight: f64,
    singular: Option<(usize, f64)>,
    out: &mut ElementIntegrals,
) {
    let x = geometry.point(xi);
    let (jac, normal) = geometry.jacobian_and_normal(xi);
    let n = field.shape(xi);
    let frame = KernelFrame::new(source, x);
    let mut u = kernel.displacement_in(&frame);
    let t = kernel.traction_in(&frame, normal);
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

#[cfg(test)]
mod tests {
    use super::*;
    use crate::bem::kernel::Kelvin;
    use crate::material::Elastic;
    use crate::quadrature::{gauss_legendre, QuadratureOptions};

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
                    let fast = element_integrals(&q, &kernel, &g, &f, source, SourcePosition::Off);
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
            let ints = element_integrals(&q, &kernel, &g, &f, source, SourcePosition::OnNode { xi: xi0, local });
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
}
