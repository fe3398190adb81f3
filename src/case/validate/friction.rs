//! The checks of `contact.falling_friction` (src/contact/falling.rs): the law's range, the
//! rolling speed it needs, and what cannot take it.

use super::{magnitude, shown};
use crate::case::schema::*;

/// Largest friction coefficient of a `bem` body's case under a tangential load given as
/// Q/(μP) (`load.tangential.ratio`): measured coefficients of metals and rubber are 0.05–1.5,
/// and a larger one stands in for a contact that sticks. Under a ratio it scales the tangential
/// force instead, Q = ratio·μ·P: beyond 10 the force asked is many times the normal load, far
/// outside Coulomb's law and small strain. The closed-form models are linear and scale-free in
/// it (Carter's half-spaces solve at μ = 1e3 in 13 Newton steps, docs/performance.md), but the
/// BEM bodies' solution breaks down: the rubber tyre of cases/tyre_b05_compressible.yaml at
/// μ = 1e3 (an infinite residual; at 100 no convergence), the true-geometry rollers of
/// cases/fig14_true_geometry.yaml at 1e6 (an infinite residual; at 100 no convergence).
pub const MAX_FRICTION_UNDER_A_RATIO: f64 = 10.0;

/// A friction coefficient above [`MAX_FRICTION_UNDER_A_RATIO`] with a nonzero
/// `load.tangential.ratio` and a `bem` body, as (key, message).
pub(super) fn ratio_of_a_large_friction(case: &Case) -> Option<(String, String)> {
    let mu = case.contact.friction;
    let TangentialSpec::Ratio(r) = case.load.tangential() else {
        return None;
    };
    let bem = [&case.bodies.a, &case.bodies.b]
        .into_iter()
        .any(|b| b.capabilities().boundary_elements);
    (bem && r != 0.0 && mu > MAX_FRICTION_UNDER_A_RATIO).then(|| {
        (
            "contact.friction".into(),
            format!(
                "a friction coefficient of {} with load.tangential.ratio = {} asks a tangential force \
                 Q = ratio·mu·P of {} times the normal load, which the bem bodies cannot carry: real \
                 friction coefficients are 0.05–1.5, and rollbem takes up to {MAX_FRICTION_UNDER_A_RATIO} \
                 under a ratio; for a contact that sticks give the tangential load as \
                 load.tangential.force or load.tangential.creep",
                shown(mu),
                shown(r),
                shown((r * mu).abs())
            ),
        )
    })
}

/// What is wrong with the case's falling friction law, as (key, message).
pub(super) fn falling_friction_problems(case: &Case) -> Vec<(String, String)> {
    let Some(law) = &case.contact.falling_friction else {
        return Vec::new();
    };
    let mut out = Vec::new();
    let mu_s = case.contact.friction;
    if let Some(two) = &law.second {
        if !(0.0..=1.0).contains(&two.share) {
            out.push((
                "contact.falling_friction.second.share".into(),
                format!(
                    "the second exponential's share of the fall from static to kinetic friction must lie in \
                     [0, 1] (value = {}); CONTACT's FEXP1, FEXP2 ≥ 0 map to share = FEXP2/(FEXP1 + FEXP2)",
                    shown(two.share)
                ),
            ));
        }
        if !(two.slip_velocity > 0.0 && two.slip_velocity.is_finite()) {
            out.push((
                "contact.falling_friction.second.slip_velocity".into(),
                format!(
                    "the second exponential's slip velocity must be > 0 and finite (value = {})",
                    shown(two.slip_velocity)
                ),
            ));
        }
    }
    if !(law.kinetic >= 0.0 && law.kinetic <= mu_s) {
        out.push((
            "contact.falling_friction.kinetic".into(),
            format!(
                "the kinetic friction coefficient must lie in [0, contact.friction = {}] (value = {}): \
                 the law falls from the static coefficient to the kinetic one",
                shown(mu_s),
                shown(law.kinetic)
            ),
        ));
    }
    let s_h = law.slip_velocity;
    if !(s_h > 0.0 && s_h.is_finite()) {
        out.push((
            "contact.falling_friction.slip_velocity".into(),
            format!(
                "the slip velocity of the decay must be > 0 and finite (value = {})",
                shown(s_h)
            ),
        ));
    } else if let Some(m) = magnitude(s_h) {
        out.push((
            "contact.falling_friction.slip_velocity".into(),
            format!("slip velocity: {m}"),
        ));
    }
    if case.load.speed.is_none() {
        out.push((
            "load.speed".into(),
            "missing: contact.falling_friction needs the rolling speed V [length/time] (the local slip \
             velocity is V times the slip)"
                .into(),
        ));
    }
    if case.solver.method != Method::Newton {
        out.push((
            "solver.method".into(),
            format!(
                "method `{}` takes a constant friction coefficient only; contact.falling_friction is solved \
                 by `newton` (the fixed point on the nodal friction of src/contact/falling.rs)",
                case.solver.method.name()
            ),
        ));
    }
    out
}
