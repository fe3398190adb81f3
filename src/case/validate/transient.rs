//! The checks of `transient:` (a history of rolling steps): the step, the count, the controls'
//! schedules, and what a history cannot follow (an error-controlled grid, a viscoelastic body).

use super::{magnitude, positive_quantity, shown};
use crate::case::schema::*;
use crate::case::transient::{NormalPlan, Schedule, ShiftPlan, TangentialPlan, TransientSpec};

/// Why a value of a control is out of range, from the value and μ.
type ValueRule = fn(f64, f64) -> Option<String>;

/// Largest number of steps of a history: every step's tractions are kept for the outputs.
pub const MAX_STEPS: usize = 100_000;

/// What is wrong with the case's `transient:` section, as (key, message).
pub(super) fn transient_problems(case: &Case) -> Vec<(String, String)> {
    let Some(t) = &case.transient else {
        return Vec::new();
    };
    let mut out = Vec::new();
    if !(1..=MAX_STEPS).contains(&t.steps) {
        out.push((
            "transient.steps".into(),
            format!(
                "the number of rolling steps must lie in 1..={MAX_STEPS} (value = {})",
                t.steps
            ),
        ));
    }
    if t.write_every == Some(0) {
        out.push((
            "transient.write_every".into(),
            "write every N-th step's files with N >= 1 (1, the default, writes every step; step 0 and the \
             last are always written)"
                .into(),
        ));
    }
    if let Some(l) = t.datum_length.filter(|l| !(*l > 0.0 && l.is_finite())) {
        out.push((
            "transient.datum_length".into(),
            format!(
                "the datum length of the half-plane's displacement must be a positive length, e.g. \
                 b·e^(ν/(1−ν)) for a strip of width b (value = {l})"
            ),
        ));
    }
    if t.initial_slip.is_some() && case.contact.falling_friction.is_none() {
        out.push((
            "transient.initial_slip".into(),
            "the start of a step's solve under a friction law that falls with the slip velocity: give \
             contact.falling_friction, or remove the key (a constant μ has one solution a step)"
                .into(),
        ));
    }
    out.extend(step_problems(case, t));
    out.extend(schedule_problems(case, t));
    out.extend(shift_problems(case, t));
    out.extend(unfollowable_problems(case));
    out
}

/// `transient.step` and `transient.time_step`.
fn step_problems(case: &Case, t: &TransientSpec) -> Vec<(String, String)> {
    let mut out = Vec::new();
    match (t.step, t.time_step) {
        (Some(_), Some(_)) => out.push((
            "transient.step".into(),
            "give either `step` (the rolling distance of a step) or `time_step` (with load.speed), not both".into(),
        )),
        (Some(d), None) => out.extend(
            positive_quantity(d).map(|w| ("transient.step".into(), format!("the rolling distance of a step {w}"))),
        ),
        (None, Some(dt)) => {
            if let Some(w) = positive_quantity(dt) {
                out.push(("transient.time_step".into(), format!("the time step {w}")));
            } else if case.load.speed.is_none() {
                out.push((
                    "transient.time_step".into(),
                    "a time step needs load.speed (the step's rolling distance is speed x time_step); or give \
                     `step`, the distance"
                        .into(),
                ));
            }
        }
        (None, None) => {}
    }
    out
}

/// `transient.normal` and `transient.tangential`: one key each, every value in range.
fn schedule_problems(case: &Case, t: &TransientSpec) -> Vec<(String, String)> {
    let mut out = Vec::new();
    if let Some(Err(m)) = t.normal.as_ref().map(|n| n.plan()) {
        out.push(("transient.normal".into(), m));
    }
    if let Some(Err(m)) = t.tangential.as_ref().map(|n| n.plan()) {
        out.push(("transient.tangential".into(), m));
    }
    if !out.is_empty() {
        return out;
    }
    let (key, schedule) = match crate::case::normal_plan(t, &case.load) {
        NormalPlan::Force(s) => ("transient.normal.force", s),
        NormalPlan::Overlap(s) => ("transient.normal.overlap", s),
    };
    if t.normal.is_some() {
        out.extend(value_problems(
            key,
            &schedule,
            t.steps,
            |v, _| positive_quantity(v),
            case.contact.friction,
        ));
    }
    let (key, schedule, rule): (&str, Schedule, ValueRule) = match crate::case::tangential_plan(t, &case.load) {
        TangentialPlan::Ratio(s) => ("transient.tangential.ratio", s, ratio_problem),
        TangentialPlan::Force(s) => ("transient.tangential.force", s, |v, _| magnitude(v)),
        TangentialPlan::Creep(s) => ("transient.tangential.creep", s, creep_problem),
    };
    if t.tangential.is_some() {
        out.extend(value_problems(key, &schedule, t.steps, rule, case.contact.friction));
    }
    out
}

/// Why a ratio Q/(μP) is out of range at friction `mu`.
fn ratio_problem(r: f64, mu: f64) -> Option<String> {
    if r.is_nan() || r.abs() >= 1.0 {
        Some(format!(
            "|Q/(muP)| must be < 1 (value = {}): beyond it the bodies slide",
            shown(r)
        ))
    } else if mu == 0.0 && r != 0.0 {
        Some("a ratio Q/(muP) needs friction > 0".into())
    } else {
        None
    }
}

/// Why a creepage is out of range.
fn creep_problem(x: f64, _: f64) -> Option<String> {
    (x.is_nan() || x.abs() >= 2.0).then(|| {
        format!(
            "creepage (V_A - V_B)/V must lie in (-2, 2) (value = {}): at |xi| = 2 one surface stands still",
            shown(x)
        )
    })
}

/// The problems of one schedule under `key`: its shape (a table of `steps` values, points whose
/// distances increase) and each value by `rule` (value, μ).
fn value_problems(key: &str, schedule: &Schedule, steps: usize, rule: ValueRule, mu: f64) -> Vec<(String, String)> {
    let mut out = Vec::new();
    match schedule {
        Schedule::Table(v) if v.len() != steps => out.push((
            key.to_string(),
            format!(
                "a table gives one value a rolling step: {} values for transient.steps = {steps}",
                v.len()
            ),
        )),
        Schedule::Points(p) if p.is_empty() => {
            out.push((key.to_string(), "give at least one [distance, value] point".into()))
        }
        Schedule::Points(p) => {
            if let Some(w) = p.iter().find_map(|q| magnitude(q[0])) {
                out.push((key.to_string(), format!("a point's distance {w}")));
            } else if p.windows(2).any(|w| w[1][0] <= w[0][0]) {
                out.push((
                    key.to_string(),
                    "the points' rolled distances must increase strictly ([[s0, v0], [s1, v1], ...], s0 < s1 < ...)"
                        .into(),
                ));
            }
        }
        Schedule::Sine { sine } => {
            if let Some(w) = positive_quantity(sine.wavelength) {
                out.push((key.to_string(), format!("a sine's wavelength {w}")));
            }
            for (name, v) in [
                ("mean", sine.mean),
                ("amplitude", sine.amplitude),
                ("phase", sine.phase),
            ] {
                if let Some(w) = magnitude(v) {
                    out.push((key.to_string(), format!("a sine's {name} {w}")));
                }
            }
        }
        _ => {}
    }
    if let Some(w) = schedule.values().into_iter().find_map(|v| rule(v, mu)) {
        out.push((key.to_string(), w));
    }
    out
}

/// `transient.shift`: exactly one key, in range.
fn shift_problems(case: &Case, t: &TransientSpec) -> Vec<(String, String)> {
    let Some(shift) = &t.shift else {
        return Vec::new();
    };
    let problem = match shift.plan() {
        Err(m) => Some(("transient.shift", m)),
        Ok(ShiftPlan::Ratio(r)) => ratio_problem(r, case.contact.friction).map(|m| ("transient.shift.ratio", m)),
        Ok(ShiftPlan::Force(q)) => magnitude(q).map(|m| ("transient.shift.force", format!("tangential force: {m}"))),
        Ok(ShiftPlan::Displacement(s)) => magnitude(s).map(|m| ("transient.shift.displacement", format!("shift: {m}"))),
    };
    problem.into_iter().map(|(k, m)| (k.to_string(), m)).collect()
}

/// What a history cannot follow: an error-controlled grid (a history keeps one grid: the
/// previous step's displacements live on it) and a viscoelastic body (its kernels are aged
/// along the steady material path; the material's own state is not carried from step to step).
fn unfollowable_problems(case: &Case) -> Vec<(String, String)> {
    let mut out = Vec::new();
    if case.contact.grid.tolerance.is_some() {
        out.push((
            "contact.grid.tolerance".into(),
            "a transient history keeps one grid for all its steps (the previous step's displacements live on \
             it): give a fixed grid (contact.grid.elements) instead"
                .into(),
        ));
    }
    for (side, body) in [("A", &case.bodies.a), ("B", &case.bodies.b)] {
        let Some(name) = body.material_name() else { continue };
        if case.materials.get(name).is_some_and(|m| m.viscoelastic.is_some()) {
            out.push((
                format!("bodies.{side}.material"),
                format!(
                    "material `{name}` is viscoelastic, whose kernels rollbem ages along the steady material path; \
                     a transient history would need the material's own state carried from step to step, which is \
                     not built: give an elastic material with `transient:`"
                ),
            ));
        }
    }
    out
}
