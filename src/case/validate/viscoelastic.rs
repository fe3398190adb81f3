//! The checks of viscoelastic materials and the rolling speed they need.

use super::{magnitude, positive_quantity, shown};
use crate::case::schema::*;

/// What is wrong with a material's `viscoelastic` keys, as (key under `viscoelastic`, message).
pub(super) fn viscoelastic_problems(m: &MaterialSpec, v: &ViscoelasticSpec) -> Vec<(&'static str, String)> {
    let mut out = Vec::new();
    let glassy = match (m.young, m.shear, v.young_rubbery, v.shear_rubbery) {
        (Some(e), None, Some(er), None) => Some((e, er, "E")),
        (None, Some(g), None, Some(gr)) => Some((g, gr, "G")),
        _ => {
            out.push((
                "E_rubbery",
                "give the rubbery (long-term) modulus as the same kind as the glassy one: E_rubbery with E, \
                 or G_rubbery with G (E/G is the glassy, instantaneous modulus)"
                    .to_string(),
            ));
            None
        }
    };
    if let Some((glassy, rubbery, kind)) = glassy {
        let key = if kind == "E" { "E_rubbery" } else { "G_rubbery" };
        if let Some(why) = positive_quantity(rubbery) {
            out.push((key, format!("rubbery modulus {why}")));
        } else if rubbery > glassy {
            out.push((
                key,
                format!(
                    "the rubbery (long-term) modulus {} exceeds the glassy (instantaneous) {kind} = {}: a standard \
                     linear solid softens as it creeps, so give {key} <= {kind}",
                    shown(rubbery),
                    shown(glassy)
                ),
            ));
        }
    }
    if !(v.creep_time >= 0.0 && v.creep_time.is_finite()) {
        out.push((
            "creep_time",
            format!(
                "creep time must be >= 0 and finite (value = {}); 0 gives the rubbery elastic material",
                shown(v.creep_time)
            ),
        ));
    } else if let Some(why) = magnitude(v.creep_time) {
        // The ageing length Vτc enters exponentials of x/(Vτc): beyond the physical range they
        // underflow or overflow.
        out.push(("creep_time", format!("creep time: {why}")));
    }
    out
}

/// Problems of `load.speed` and of viscoelastic materials on bodies that cannot take them.
pub(super) fn rolling_speed_problems(case: &Case) -> Vec<(String, String)> {
    let mut out = Vec::new();
    let creeping = |name: &str| {
        case.materials
            .get(name)
            .and_then(|m| m.viscoelastic.as_ref())
            .map(|v| v.creep_time)
    };
    let mut needs_speed = false;
    for (side, body) in [("A", &case.bodies.a), ("B", &case.bodies.b)] {
        // A rigid body has no material; an elastic one needs no speed and fits every model.
        let Some((material, creep_time)) = body.material_name().and_then(|m| Some((m, creeping(m)?))) else {
            continue;
        };
        let model = body.capabilities();
        if model.accepts_viscoelastic {
            needs_speed |= creep_time > 0.0;
        } else {
            out.push((
                format!("bodies.{side}.material"),
                format!(
                    "material `{material}` is viscoelastic, which rollbem models on `half_space` and `layer` bodies \
                     only (the aged kernels); give this {} body an elastic material or model it as a half_space \
                     (a cover on a rigid core: a layer)",
                    model.name
                ),
            ));
        }
    }
    match case.load.speed {
        Some(v) if !(v > 0.0 && v.is_finite()) => out.push((
            "load.speed".into(),
            format!("rolling speed must be > 0 and finite (value = {})", shown(v)),
        )),
        Some(v) if magnitude(v).is_some() => out.push((
            "load.speed".into(),
            format!("rolling speed: {}", magnitude(v).unwrap_or_default()),
        )),
        None if needs_speed => out.push((
            "load.speed".into(),
            "missing: a viscoelastic material with creep_time > 0 needs the rolling speed V [length/time] \
             (the material's age in the contact is x/V)"
                .into(),
        )),
        _ => {}
    }
    out
}
