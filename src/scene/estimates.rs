//! Hertz-type estimates of a scene: contact modulus, Dundurs' β, the Hertz contact and the
//! half-length of the uniform contact grid that is built around it.

use super::registry::BodySetups;
use crate::analytic;
use crate::body::setup::{NormalLoad, Rolling};
use crate::case::{Case, NormalSpec, TangentialSpec};
use crate::grid::ContactGrid;
use crate::material::{self, Elastic};
use serde::Serialize;

/// Hertz-type estimates of a scene (also what `rollbem check` prints).
#[derive(Debug, Clone, Serialize)]
pub struct Estimates {
    /// Contact modulus E* [stress].
    pub e_star: f64,
    /// Dundurs' β with A first (κ = 2β in Bentall–Johnson / paper Eq. 78).
    pub dundurs_beta: f64,
    /// Effective radius R*, 1/R* = 1/R_A + 1/R_B with signed radii (a concave bore negative)
    /// [length].
    pub effective_radius: f64,
    /// Normal force P used for the estimates (given, or estimated from the overlap) [force/length].
    pub normal_force: f64,
    /// Hertz half-width a [length], or the contact's half-width from a body's own compliance
    /// when [`Self::scales_from`] names one.
    pub hertz_half_width: f64,
    /// Hertz peak pressure p0 [stress], or the largest pressure from a body's own compliance
    /// when [`Self::scales_from`] names one.
    pub hertz_peak_pressure: f64,
    /// The model whose own compliance gave the half-width and peak pressure
    /// ([`crate::body::BodySetup::own_contact_scales`]: a cover on a rigid core); absent when
    /// they are Hertz's.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub scales_from: Option<&'static str>,
    /// a / R.
    pub half_width_over_radius: f64,
    /// Carter stick-zone width 2a√(1 − |Q|/μP) (similar bodies), if Q/μP is known [length].
    pub carter_stick_width: Option<f64>,
    /// Half the length of the contact grid [length]: L of the uniform grid [−L, L] built around
    /// the Hertz contact, or half the span of a `bem` body's own contact elements when they set
    /// the grid.
    pub grid_half_length: f64,
    /// Node spacing of the contact grid [length].
    pub grid_spacing: f64,
}

impl Estimates {
    /// The estimates of the case's load on two bodies, with the uniform grid the case asks for.
    pub fn of(case: &Case, bodies: &BodySetups) -> Self {
        let [ba, bb] = bodies;
        let (ma, mb) = (ba.hertz_material(), bb.hertz_material());
        let e_star = material::contact_modulus(ma.as_ref(), mb.as_ref());
        let dundurs_beta = material::dundurs_beta(ma.as_ref(), mb.as_ref());
        let radius = material::effective_radius(ba.radius(), bb.radius());
        let normal_force = match case.load.normal() {
            NormalSpec::Force(p) => p,
            NormalSpec::Overlap(d) => load_from_overlap(
                d,
                [(ma, ba.datum_distance()), (mb, bb.datum_distance())],
                radius,
                e_star,
            ),
        };
        // Two bodies without elastic constants (rigid, or a foundation) have no β.
        let dundurs_beta = if dundurs_beta.is_finite() { dundurs_beta } else { 0.0 };
        let hertz_a = analytic::hertz_half_width(normal_force, radius, e_star);
        let rolling = rolling_of(case);
        let load = match case.load.normal() {
            NormalSpec::Force(p) => NormalLoad::Force(p),
            NormalSpec::Overlap(d) => NormalLoad::Overlap(d),
        };
        let own = bodies
            .iter()
            .find_map(|b| Some((b.own_contact_scales(load, radius, hertz_a, rolling)?, b.model_name())));
        let (a, p0, normal_force) = match own {
            Some((s, _)) => (s.half_width, s.peak_pressure, s.normal_force),
            None => (
                hertz_a,
                analytic::hertz_peak_pressure(normal_force, hertz_a),
                normal_force,
            ),
        };
        let ratio = match case.load.tangential() {
            TangentialSpec::Ratio(r) => Some(r),
            TangentialSpec::Force(q) if case.contact.friction > 0.0 => Some(q / (case.contact.friction * normal_force)),
            _ => None,
        };
        let g = &case.contact.grid;
        let grid_half_length = match g.half_length {
            Some(h) => h,
            None if g.align_edges => aligned_half_length(a, g.extent, g.elements),
            None => g.extent * a,
        };
        // Node intervals per element: shared end nodes count once.
        let npe = g.element.node_stride();
        Estimates {
            e_star,
            dundurs_beta,
            effective_radius: radius,
            normal_force,
            hertz_half_width: a,
            hertz_peak_pressure: p0,
            scales_from: own.map(|(_, name)| name),
            half_width_over_radius: a / radius,
            carter_stick_width: ratio
                .filter(|r| r.abs() < 1.0)
                .map(|r| 2.0 * a * (1.0 - r.abs()).sqrt()),
            grid_half_length,
            grid_spacing: 2.0 * grid_half_length / (g.elements * npe) as f64,
        }
    }

    /// The grid entries for a grid that the case did not size (a `bem` body's own contact
    /// elements): its half-span and its node spacing.
    pub fn with_grid(self, grid: &ContactGrid) -> Self {
        Estimates {
            grid_half_length: 0.5 * grid.length(),
            grid_spacing: grid.node_spacing(),
            ..self
        }
    }
}

/// How the case's contact moves over the bodies: the direction of `contact.rolling_direction`
/// and the speed of `load.speed`.
pub fn rolling_of(case: &Case) -> Rolling {
    Rolling {
        direction: -case.contact.rolling_direction.flow_sign(),
        speed: case.load.speed,
    }
}

/// Normal force that gives the overlap δ0 between two half-planes measured from their datums:
/// δ0 = Σ_b (2(1−ν_b²)/(πE_b))·P·(ln(4R_b/a) − ½), a the Hertz half-width of P (Johnson,
/// Contact Mechanics, 1985, Eq. 5.36; the datum of the half-space model, docs/theory.md), R_b
/// each body's [`crate::body::BodySetup::datum_distance`].
/// Used only to size the grid.
fn load_from_overlap(overlap: f64, bodies: [(Option<Elastic>, f64); 2], radius: f64, e_star: f64) -> f64 {
    let approach = |p: f64| {
        let a = analytic::hertz_half_width(p, radius, e_star);
        bodies
            .iter()
            .filter_map(|(m, r)| m.map(|m| m.halfplane_log_coefficient() * p * ((4.0 * r.abs() / a).ln() - 0.5)))
            .sum::<f64>()
    };
    // Bisection in log P: the approach grows with P while a ≪ R.
    let (mut lo, mut hi) = (1e-12 * e_star * radius, 1e-2 * e_star * radius);
    for _ in 0..200 {
        let mid = (lo * hi).sqrt();
        if approach(mid) < overlap {
            lo = mid;
        } else {
            hi = mid;
        }
    }
    (lo * hi).sqrt()
}

/// Half-length L ≈ extent·a of a grid of `elements` equal elements on [−L, L] such that ±a are
/// element boundaries: with k elements outside the contact on each side, L = a·n/(n − 2k).
pub fn aligned_half_length(a: f64, extent: f64, elements: usize) -> f64 {
    let n = elements as f64;
    let k = (0.5 * n * (1.0 - 1.0 / extent)).round().max(1.0);
    if n - 2.0 * k >= 1.0 {
        a * n / (n - 2.0 * k)
    } else {
        extent * a
    }
}
