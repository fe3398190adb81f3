//! The checks of `materials.NAME.yield` and `output.strength`.

use super::positive_quantity;
use crate::case::schema::*;
use crate::case::StrengthSpec;

/// What is wrong with the yield keys of the materials and with `output.strength`, as
/// (key, message).
pub(super) fn strength_problems(case: &Case) -> Vec<(String, String)> {
    let mut out = Vec::new();
    for (name, m) in &case.materials {
        if let Some(y) = &m.yield_stress {
            let key = |k: &str| format!("materials.{name}.yield.{k}");
            match (y.shear, y.tensile) {
                (Some(_), Some(_)) | (None, None) => out.push((
                    format!("materials.{name}.yield"),
                    "give exactly one of `shear` (the shear yield stress k) and `tensile` (the uniaxial \
                     yield stress Y)"
                        .into(),
                )),
                (Some(k), None) => out.extend(positive_quantity(k).map(|w| (key("shear"), format!("k {w}")))),
                (None, Some(t)) => out.extend(positive_quantity(t).map(|w| (key("tensile"), format!("Y {w}")))),
            }
        }
    }
    if let Some(s) = &case.output.strength {
        out.extend(assessed_body_problems(case, s));
        for (k, n) in ["nx", "nz"].iter().zip(s.grid) {
            if !(2..=2000).contains(&n) {
                out.push((
                    "output.strength.grid".into(),
                    format!("{k} must lie in 2..2000 (value = {n})"),
                ));
            }
        }
    }
    out
}

/// The bodies `output.strength` assesses (`bodies`, else those whose material has a yield
/// stress): named A or B, deforming, with an interior model and a yield stress.
fn assessed_body_problems(case: &Case, s: &StrengthSpec) -> Vec<(String, String)> {
    let mut out = Vec::new();
    let key = "output.strength.bodies".to_string();
    let has_yield = |b: &BodySpec| {
        b.material_name()
            .and_then(|m| case.materials.get(m))
            .is_some_and(|m| m.yield_stress.is_some())
    };
    let named = s.bodies.clone().unwrap_or_else(|| {
        [("A", &case.bodies.a), ("B", &case.bodies.b)]
            .into_iter()
            .filter(|(_, b)| has_yield(b))
            .map(|(n, _)| n.to_string())
            .collect()
    });
    if named.is_empty() {
        out.push((
            key.clone(),
            "no body to assess: give the material of a body that deforms a yield stress \
             (materials.NAME.yield), or list the bodies in output.strength.bodies"
                .into(),
        ));
    }
    for name in &named {
        let body = match name.as_str() {
            "A" => &case.bodies.a,
            "B" => &case.bodies.b,
            _ => {
                out.push((key.clone(), format!("must name A or B (value = {name})")));
                continue;
            }
        };
        let model = body.capabilities();
        if !model.deforms {
            out.push((
                key.clone(),
                format!(
                    "body {name} is rigid: it does not deform and has no stresses to assess; leave it out of \
                     `bodies`"
                ),
            ));
        } else if !model.interior_fields {
            out.push((
                key.clone(),
                format!(
                    "body {name} is a {}, whose model gives its surface tractions only, not the stresses \
                     inside the cover; model the cover by `bem` (geometry: covered_roller), or leave it out \
                     of `bodies`",
                    model.name
                ),
            ));
        } else if let Some(material) = body.material_name() {
            let given = case.materials.get(material).is_none_or(|m| m.yield_stress.is_some());
            if !given {
                out.push((
                    format!("materials.{material}.yield"),
                    format!(
                        "missing: output.strength assesses body {name}, so its material needs a yield \
                         stress, e.g. `yield: {{tensile: 1200}}` (Y) or `yield: {{shear: 690}}` (k)"
                    ),
                ));
            }
        }
    }
    out
}
