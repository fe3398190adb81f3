//! Interior displacement and stress of a solved BEM body by Somigliana's identity.
//!
//! At a point X inside the body, from the boundary displacements u and tractions t (reference
//! sheet §9; Brebbia–Telles–Wrobel, *Boundary Element Techniques*, Eq. 3.54 and 3.60):
//!
//! ```text
//! u_i(X)  = ∫_Γ U*_ij t_j dΓ − ∫_Γ T*_ij u_j dΓ                              (S1)
//! σ_ij(X) = ∫_Γ D_kij t_k dΓ − ∫_Γ S_kij u_k dΓ                              (S2)
//! σ_zz    = ν (σ_xx + σ_yy)                                                  (plane strain)
//! ```
//!
//! with the kernels of [`super::kernel`] (D and S stay finite at ν = 0.5, so incompressible
//! bodies work) and u, t interpolated by each element's own shape functions from the nodal
//! solution ([`super::BemSolution`]). The integrands are smooth for X off the boundary, but
//! nearly singular (1/r, 1/r²) when X is close to it. Elements near X are integrated with the
//! adaptive Gauss rule of [`Quadrature::off_element_points`] (intervals halved until the nearest
//! complex singularity lies outside a Bernstein ellipse, points chosen for the target
//! accuracy), so the integration error stays at the quadrature tolerance down to points a small
//! fraction of an element from the boundary; what remains there is the discretisation error of
//! the boundary data, amplified like h/d (docs/validation.md, "Interior stresses").
//! Elements provably far from X ([`FarFieldRules`]) use a whole-element Gauss rule with at
//! least as many points as the adaptive rule would take, tabulated once per element.
//!
//! **Where a point lies.** Each point is first located against the boundary loops:
//! * *outside* — the ray from X towards +x crosses the boundary an even number of times. The
//!   elements are followed as polylines of 16 chords each, which leave the exact quadratic
//!   curve by at most |x''|/512 (1/256 of its sagitta), so the count is exact for every point
//!   farther than that from the boundary;
//! * *boundary* — X lies inside and closer to some element than
//!   [`InteriorOptions::boundary_layer`] times that element's length (distance to the exact
//!   quadratic curve by Newton's method), or, inside or not, within twice the polyline's
//!   deviation of an element (5e-4 of the element length for a 30° arc), where the count could
//!   be wrong;
//! * *inside* otherwise: only these are evaluated.
//!
//! Points are evaluated in parallel (rayon). Units: the mesh's length, the material's stress;
//! fields in the mesh's global axes.

use super::assemble::{BemModel, BemSolution};
use super::element::{ElementGeometry, FieldInterpolation};
use crate::interior::{InteriorOptions, InteriorSample, InteriorValue};
use crate::quadrature::{FarFieldRules, Quadrature};
use rayon::prelude::*;

/// Chords per element of the polyline used by the ray-crossing test.
const CHORDS: usize = 16;

/// One element's geometry for locating points.
#[derive(Debug, Clone)]
struct LocatedElement {
    /// The quadratic geometry.
    geometry: ElementGeometry,
    /// Arc length [length].
    length: f64,
    /// Bound on the distance between the curve and its polyline [length]: |x''|·Δξ²/8 with
    /// Δξ = 2/CHORDS the chords' parameter length (x'' is constant on a quadratic element).
    deviation: f64,
    /// Bounding box (lower, upper corner) of the curve [length].
    lower: [f64; 2],
    /// See `lower`.
    upper: [f64; 2],
    /// Points x(ξ_k), ξ_k = −1 + 2k/CHORDS.
    polyline: [[f64; 2]; CHORDS + 1],
}

impl LocatedElement {
    fn new(geometry: ElementGeometry) -> Self {
        let mut polyline = [[0.0; 2]; CHORDS + 1];
        for (k, p) in polyline.iter_mut().enumerate() {
            *p = geometry.point(-1.0 + 2.0 * k as f64 / CHORDS as f64);
        }
        // The curve lies in the convex hull of its Bézier control points x0, 2xm − (x0 + x1)/2,
        // x1, so their bounding box bounds it.
        let [p0, p1, pm] = geometry.nodes;
        let control = [2.0 * pm[0] - 0.5 * (p0[0] + p1[0]), 2.0 * pm[1] - 0.5 * (p0[1] + p1[1])];
        let mut lower = [f64::INFINITY; 2];
        let mut upper = [f64::NEG_INFINITY; 2];
        for p in [p0, p1, control] {
            for c in 0..2 {
                lower[c] = lower[c].min(p[c]);
                upper[c] = upper[c].max(p[c]);
            }
        }
        let second = geometry.curvature_vector();
        let step = 2.0 / CHORDS as f64;
        Self {
            length: geometry.length(),
            deviation: second[0].hypot(second[1]) * step * step / 8.0,
            geometry,
            lower,
            upper,
            polyline,
        }
    }

    /// Whether X is within `margin` of the bounding box.
    fn near_box(&self, x: [f64; 2], margin: f64) -> bool {
        (0..2).all(|c| x[c] >= self.lower[c] - margin && x[c] <= self.upper[c] + margin)
    }

    /// Distance from X to the curve [length]: the nearest polyline point, refined by Newton's
    /// method on (x(ξ) − X)·x'(ξ) = 0 within [−1, 1].
    fn distance(&self, x: [f64; 2]) -> f64 {
        let d2 = |p: [f64; 2]| (p[0] - x[0]).powi(2) + (p[1] - x[1]).powi(2);
        let k = (0..=CHORDS)
            .min_by(|&a, &b| d2(self.polyline[a]).total_cmp(&d2(self.polyline[b])))
            .unwrap_or(0);
        let mut xi = -1.0 + 2.0 * k as f64 / CHORDS as f64;
        let second = self.geometry.curvature_vector();
        for _ in 0..8 {
            let p = self.geometry.point(xi);
            let t = self.geometry.tangent(xi);
            let r = [p[0] - x[0], p[1] - x[1]];
            let f = r[0] * t[0] + r[1] * t[1];
            let df = t[0] * t[0] + t[1] * t[1] + r[0] * second[0] + r[1] * second[1];
            if df <= 0.0 {
                break;
            }
            let next = (xi - f / df).clamp(-1.0, 1.0);
            let done = (next - xi).abs() < 1e-14;
            xi = next;
            if done {
                break;
            }
        }
        d2(self.geometry.point(xi)).min(d2(self.polyline[k])).sqrt()
    }

    /// Crossings of the ray from X towards +x with the polyline (half-open rule on y, so a
    /// vertex on the ray is counted once).
    fn crossings(&self, x: [f64; 2]) -> usize {
        if x[1] < self.lower[1] || x[1] > self.upper[1] || x[0] > self.upper[0] {
            return 0;
        }
        self.polyline
            .windows(2)
            .filter(|w| {
                let (a, b) = (w[0], w[1]);
                if (a[1] > x[1]) == (b[1] > x[1]) {
                    return false;
                }
                let at = a[0] + (x[1] - a[1]) * (b[0] - a[0]) / (b[1] - a[1]);
                at > x[0]
            })
            .count()
    }
}

/// Where a point lies relative to the body (see the module docs).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Location {
    /// Inside the material, farther than the boundary layer from every element.
    Inside,
    /// Outside the body.
    Outside,
    /// Inside within the boundary layer, or on the boundary.
    Boundary,
}

/// Locates points against the boundary of a BEM model.
#[derive(Debug, Clone)]
pub struct PointLocator {
    elements: Vec<LocatedElement>,
    boundary_layer: f64,
}

impl PointLocator {
    /// A locator for the elements of `model` with the boundary layer of `options`.
    pub fn new(model: &BemModel, options: &InteriorOptions) -> Self {
        Self {
            elements: model
                .discretisation
                .geometry
                .iter()
                .map(|&g| LocatedElement::new(g))
                .collect(),
            boundary_layer: options.boundary_layer,
        }
    }

    /// Where X lies.
    pub fn locate(&self, x: [f64; 2]) -> Location {
        // Within `band` of an element (twice its polyline's deviation from the curve, and at
        // least 1e-9 of its length for a straight one) the crossing count may be wrong: the
        // point is on the boundary whatever the count. Beyond it the count is exact, and an
        // inside point within the layer is on the boundary too.
        let (mut in_band, mut in_layer) = (false, false);
        for e in &self.elements {
            let band = (2.0 * e.deviation).max(1e-9 * e.length);
            let layer = self.boundary_layer * e.length;
            if !e.near_box(x, band.max(layer)) {
                continue;
            }
            let d = e.distance(x);
            in_band |= d <= band;
            in_layer |= d <= layer;
        }
        if in_band {
            return Location::Boundary;
        }
        let crossings: usize = self.elements.iter().map(|e| e.crossings(x)).sum();
        match (crossings % 2 == 1, in_layer) {
            (false, _) => Location::Outside,
            (true, true) => Location::Boundary,
            (true, false) => Location::Inside,
        }
    }
}

/// Largest Gauss rule tabulated per element for the far field.
const FAR_MAX_POINTS: usize = 16;

/// One tabulated quadrature point of an element: everything the integrand needs.
#[derive(Debug, Clone, Copy)]
struct TabulatedPoint {
    /// x(ξ) [length].
    x: [f64; 2],
    /// Outward normal.
    normal: [f64; 2],
    /// Gauss weight × Jacobian [length].
    weight: f64,
    /// Interpolated boundary displacement [length].
    u: [f64; 2],
    /// Interpolated boundary traction [stress].
    t: [f64; 2],
}

/// Per-element data of one evaluation: nodal values, the far-field singularity bound and the
/// tabulated whole-element Gauss rules with n = min_points … FAR_MAX_POINTS points.
struct ElementData {
    nodal_u: [[f64; 2]; 3],
    nodal_t: [[f64; 2]; 3],
    far: FarFieldRules,
    /// rules[n − first] for n points.
    rules: Vec<Vec<TabulatedPoint>>,
    first: usize,
}

impl ElementData {
    fn new(model: &BemModel, solution: &BemSolution, quadrature: &Quadrature, e: usize) -> Self {
        let d = &model.discretisation;
        let ids = d.element_nodes[e];
        let nodal_u = ids.map(|k| solution.displacement[k]);
        let nodal_t = ids.map(|k| solution.traction[k]);
        let first = quadrature.options.min_points.max(2);
        let rules = (first..=FAR_MAX_POINTS)
            .map(|n| {
                let (xs, ws) = quadrature.legendre(n);
                xs.iter()
                    .zip(ws)
                    .map(|(&xi, &w)| {
                        let p = boundary_point(&d.geometry[e], &d.interpolation[e], &nodal_u, &nodal_t, xi);
                        TabulatedPoint {
                            weight: w * p.weight,
                            ..p
                        }
                    })
                    .collect()
            })
            .collect();
        Self {
            nodal_u,
            nodal_t,
            far: quadrature.far_field_rules(&d.geometry[e].nodes, FAR_MAX_POINTS),
            rules,
            first,
        }
    }
}

/// Position, normal, Jacobian (as `weight`) and interpolated u, t at ξ of an element.
#[inline]
fn boundary_point(
    geometry: &ElementGeometry,
    interpolation: &FieldInterpolation,
    nodal_u: &[[f64; 2]; 3],
    nodal_t: &[[f64; 2]; 3],
    xi: f64,
) -> TabulatedPoint {
    let (jac, normal) = geometry.jacobian_and_normal(xi);
    let n = interpolation.shape(xi);
    let mut u = [0.0; 2];
    let mut t = [0.0; 2];
    for a in 0..3 {
        for c in 0..2 {
            u[c] += n[a] * nodal_u[a][c];
            t[c] += n[a] * nodal_t[a][c];
        }
    }
    TabulatedPoint {
        x: geometry.point(xi),
        normal,
        weight: jac,
        u,
        t,
    }
}

/// Fields at interior `points` (the mesh's global axes) of `model` with the boundary solution
/// `solution`: displacement by Eq. S1, stress by Eq. S2 (module docs). Points outside the body
/// or within the boundary layer of `options` are reported as such, not evaluated.
///
/// Cost: every element is integrated for every point. Elements whose singularities are provably
/// far from the point ([`FarFieldRules`]) use a whole-element Gauss rule tabulated once per
/// element (positions, normals, u and t at the points), with as many points as the bound asks
/// for the quadrature tolerance; the others use the adaptive rule.
pub fn interior_fields(
    model: &BemModel,
    solution: &BemSolution,
    points: &[[f64; 2]],
    options: &InteriorOptions,
) -> Vec<InteriorSample> {
    let locator = PointLocator::new(model, options);
    let quadrature = Quadrature::new(model.options.quadrature());
    let elements: Vec<ElementData> = (0..model.discretisation.geometry.len())
        .map(|e| ElementData::new(model, solution, &quadrature, e))
        .collect();
    points
        .par_iter()
        .map(|&x| match locator.locate(x) {
            Location::Inside => InteriorSample::Inside(somigliana(model, &elements, &quadrature, x)),
            Location::Outside => InteriorSample::Outside,
            Location::Boundary => InteriorSample::Boundary,
        })
        .collect()
}

/// Eq. S1–S2 at one interior point X.
fn somigliana(model: &BemModel, elements: &[ElementData], quadrature: &Quadrature, source: [f64; 2]) -> InteriorValue {
    let d = &model.discretisation;
    let kernel = model.kernel();
    let mut u = [0.0; 2];
    // σxx, σyy, τxy.
    let mut s = [0.0; 3];
    let mut add = |p: &TabulatedPoint| {
        let f = kernel.somigliana_integrand(source, p.x, p.normal, p.u, p.t);
        for (sum, v) in u.iter_mut().zip(f.displacement) {
            *sum += p.weight * v;
        }
        for (sum, v) in s.iter_mut().zip(f.stress) {
            *sum += p.weight * v;
        }
    };
    for (e, data) in elements.iter().enumerate() {
        match data.far.points(source) {
            Some(n) if n >= data.first && n <= FAR_MAX_POINTS => data.rules[n - data.first].iter().for_each(&mut add),
            _ => {
                let (geometry, interpolation) = (&d.geometry[e], &d.interpolation[e]);
                quadrature.off_element_points(&geometry.nodes, source, |xi, weight| {
                    let p = boundary_point(geometry, interpolation, &data.nodal_u, &data.nodal_t, xi);
                    add(&TabulatedPoint {
                        weight: weight * p.weight,
                        ..p
                    });
                });
            }
        }
    }
    let szz = kernel.poisson * (s[0] + s[1]);
    InteriorValue {
        displacement: u,
        stress: [s[0], s[1], szz, s[2]],
    }
}
