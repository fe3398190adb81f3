//! The checks of `contact.falling_friction` (src/contact/falling.rs): the law's range, the
//! rolling speed it needs, and what cannot take it.

use super::{magnitude, shown};
use crate::case::schema::*;

/// What is wrong with the case's falling friction law, as (key, message).
pub(super) fn falling_friction_problems(case: &Case) -> Vec<(String, String)> {
    let Some(law) = &case.contact.falling_friction else {
        return Vec::new();
    };
    let mut out = Vec::new();
    let mu_s = case.contact.friction;
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
    if case.transient.is_some() {
        out.push((
            "contact.falling_friction".into(),
            "a transient history takes a constant friction coefficient only (the fixed point on the nodal \
             friction is built for steady rolling); remove contact.falling_friction or the transient section"
                .into(),
        ));
    }
    out
}
