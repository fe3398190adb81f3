//! Whole-case validation: every rule is checked and every violation reported with its key and
//! value (as CONTACT's input check does), so the user fixes a case in one pass.

use super::schema::*;

/// One broken rule.
#[derive(Debug, Clone, PartialEq)]
pub struct Violation {
    /// Dotted key path of the offending value.
    pub key: String,
    /// What is wrong (with the value) and what to do.
    pub message: String,
}

impl std::fmt::Display for Violation {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(f, "{}: {}", self.key, self.message)
    }
}

/// Checks every rule of the case; an empty list means the case is valid.
pub fn validate(case: &Case) -> Vec<Violation> {
    let mut out = Vec::new();
    let mut bad = |key: String, message: String| out.push(Violation { key, message });

    for (name, m) in &case.materials {
        let key = |k: &str| format!("materials.{name}.{k}");
        match (m.young, m.shear) {
            (Some(_), Some(_)) => bad(key("E"), "give either E or G, not both".into()),
            (None, None) => bad(
                key("E"),
                "missing: give Young's modulus E (or the shear modulus G)".into(),
            ),
            (Some(e), None) if !(e > 0.0 && e.is_finite()) => {
                bad(key("E"), format!("Young's modulus must be positive (value = {e})"))
            }
            (None, Some(g)) if !(g > 0.0 && g.is_finite()) => {
                bad(key("G"), format!("shear modulus must be positive (value = {g})"))
            }
            _ => {}
        }
        if !(m.nu > -1.0 && m.nu <= 0.5) {
            bad(
                key("nu"),
                format!("Poisson's ratio must lie in (-1, 0.5] (value = {})", m.nu),
            );
        }
    }

    let undefined_material = |side: &str, material: &str| {
        (!case.materials.contains_key(material)).then(|| Violation {
            key: format!("bodies.{side}.material"),
            message: format!(
                "material `{material}` is not defined under `materials` (defined: {})",
                case.materials.keys().cloned().collect::<Vec<_>>().join(", ")
            ),
        })
    };
    let mut rigid = 0;
    // The profile radii the case gives (None where a mesh gives it), for the pair rule below.
    let mut given = [None, None];
    for (k, (side, body)) in [("A", &case.bodies.a), ("B", &case.bodies.b)].into_iter().enumerate() {
        let radius = match body {
            BodySpec::HalfSpace { material, radius } => {
                if let Some(v) = undefined_material(side, material) {
                    bad(v.key, v.message);
                }
                given[k] = Some(*radius);
                *radius
            }
            BodySpec::Rigid { radius, mesh, .. } => {
                rigid += 1;
                match (radius, mesh) {
                    (Some(r), None) => {
                        given[k] = Some(*r);
                        *r
                    }
                    (None, Some(_)) => 1.0,
                    _ => {
                        bad(
                            format!("bodies.{side}"),
                            "a rigid body takes exactly one of `radius` (the profile radius) or `mesh` \
                             (a Gmsh mesh whose contact group's circle gives it)"
                                .into(),
                        );
                        1.0
                    }
                }
            }
            BodySpec::Bem {
                material,
                boundaries,
                radius,
                contact,
                ..
            } => {
                if let Some(v) = undefined_material(side, material) {
                    bad(v.key, v.message);
                }
                if boundaries.contains_key(contact) {
                    bad(
                        format!("bodies.{side}.boundaries.{contact}"),
                        "the contact group takes the contact tractions; do not give it a boundary condition".into(),
                    );
                }
                for (group, spec) in boundaries {
                    if let BoundarySpec::Prescribed(p) = spec {
                        let n = [p.displacement.is_some(), p.traction.is_some(), p.pressure.is_some()];
                        if n.iter().filter(|&&b| b).count() != 1 {
                            bad(
                                format!("bodies.{side}.boundaries.{group}"),
                                "give `fixed`, `free`, or exactly one of {displacement: [ux, uy]}, {traction: [tx, ty]}, {pressure: p}".into(),
                            );
                        } else {
                            let values = p
                                .displacement
                                .or(p.traction)
                                .map_or(vec![p.pressure.unwrap_or(0.0)], |v| v.to_vec());
                            if values.iter().any(|v| *v != 0.0) {
                                bad(
                                    format!("bodies.{side}.boundaries.{group}"),
                                    "non-zero prescribed data on other groups is not supported in contact runs yet (its \
                                     displacement of the contact surface is not added to the gap); use fixed, free or \
                                     zero values, and load the contact by the case's `load`"
                                        .into(),
                                );
                            }
                        }
                    }
                }
                given[k] = *radius;
                radius.unwrap_or(1.0)
            }
        };
        if !(radius != 0.0 && radius.is_finite()) {
            bad(
                format!("bodies.{side}.radius"),
                format!(
                    "radius must be non-zero and finite (value = {radius}): positive for a convex body, \
                     negative for a concave one (a ring's bore); model a flat as a large radius"
                ),
            );
        }
    }
    if let [Some(ra), Some(rb)] = given {
        if let Some(message) = radius_pair_problem(ra, rb) {
            bad("bodies.A.radius, bodies.B.radius".into(), message);
        }
    }
    if rigid == 2 {
        bad(
            "bodies".into(),
            "both bodies are rigid: at least one must be elastic".into(),
        );
    }

    let c = &case.contact;
    if !(c.friction >= 0.0 && c.friction.is_finite()) {
        bad(
            "contact.friction".into(),
            format!("friction coefficient must be >= 0 (value = {})", c.friction),
        );
    }
    if c.grid.elements == 0 {
        bad(
            "contact.grid.elements".into(),
            "need at least one contact element (value = 0); 21 is the paper's grid".into(),
        );
    }
    if !(c.grid.extent > 1.0 && c.grid.extent.is_finite()) {
        bad(
            "contact.grid.extent".into(),
            format!(
                "the grid must extend beyond the Hertz contact: extent > 1 (value = {}); 1.3 is typical",
                c.grid.extent
            ),
        );
    }
    let bem_body = [&case.bodies.a, &case.bodies.b]
        .into_iter()
        .any(|b| matches!(b, BodySpec::Bem { .. }));
    if bem_body && c.grid.element != crate::grid::ElementKind::DiscontinuousQuadratic {
        bad(
            "contact.grid.element".into(),
            format!(
                "{} elements cannot be used with a bem body: the contact grid is then the mesh's own \
                 contact elements, whose discontinuous quadratic field nodes carry the tractions; \
                 remove the key, or use half_space/rigid bodies",
                c.grid.element.name()
            ),
        );
    }
    if let Some(h) = c.grid.half_length {
        if !(h > 0.0 && h.is_finite()) {
            bad(
                "contact.grid.half_length".into(),
                format!("must be positive (value = {h})"),
            );
        }
    }

    if let Err(m) = case.load.normal_keys.spec() {
        bad("load.normal".into(), m);
    }
    if let Err(m) = case.load.tangential_keys.spec() {
        bad("load.tangential".into(), m);
    }
    let normal_force = match case.load.normal() {
        NormalSpec::Force(p) => {
            if !(p > 0.0 && p.is_finite()) {
                bad(
                    "load.normal.force".into(),
                    format!("normal force must be positive (value = {p})"),
                );
            }
            Some(p)
        }
        NormalSpec::Overlap(d) => {
            if !(d > 0.0 && d.is_finite()) {
                bad(
                    "load.normal.overlap".into(),
                    format!("overlap must be positive (value = {d})"),
                );
            }
            None
        }
    };
    let full_sliding = "no steady rolling exists (full sliding); use |Q| < muP";
    match case.load.tangential() {
        TangentialSpec::Ratio(r) => {
            if r.is_nan() || r.abs() >= 1.0 {
                bad(
                    "load.tangential.ratio".into(),
                    format!("|Q/(muP)| must be < 1 (value = {r}): {full_sliding}"),
                );
            } else if c.friction == 0.0 && r != 0.0 {
                bad(
                    "load.tangential.ratio".into(),
                    "a ratio Q/(muP) needs friction > 0".into(),
                );
            }
        }
        TangentialSpec::Force(q) => {
            if let Some(p) = normal_force {
                if q.is_nan() || q.abs() >= c.friction * p {
                    bad(
                        "load.tangential.force".into(),
                        format!("|Q| = {} must be < muP = {} : {full_sliding}", q.abs(), c.friction * p),
                    );
                }
            }
        }
        TangentialSpec::Creep(x) => {
            if !x.is_finite() {
                bad(
                    "load.tangential.creep".into(),
                    format!("creepage must be finite (value = {x})"),
                );
            }
        }
    }

    let s = &case.solver;
    if !(s.tolerance > 0.0 && s.tolerance < 1.0) {
        bad(
            "solver.tolerance".into(),
            format!("must lie in (0, 1) (value = {})", s.tolerance),
        );
    }
    if s.max_iterations == 0 {
        bad("solver.max_iterations".into(), "must be >= 1 (value = 0)".into());
    }
    if let Penalty::Scale(p) = s.penalty {
        if !(p > 0.0 && p.is_finite()) {
            bad(
                "solver.penalty".into(),
                format!("penalty scale must be positive or `auto` (value = {p})"),
            );
        }
    }
    if let Some(g) = &case.output.interior {
        let body = match g.body.as_str() {
            "A" => Some(&case.bodies.a),
            "B" => Some(&case.bodies.b),
            _ => None,
        };
        match body {
            None => bad(
                "output.interior.body".into(),
                format!("must be A or B (value = {})", g.body),
            ),
            Some(BodySpec::HalfSpace { .. } | BodySpec::Bem { .. }) => {}
            Some(BodySpec::Rigid { .. }) => bad(
                "output.interior.body".into(),
                format!(
                    "body {} is rigid: it does not deform and has no interior stresses; ask for a \
                     half_space or bem body",
                    g.body
                ),
            ),
        }
        for (k, v) in [("x", g.x), ("y", g.y)] {
            if !(v[2] >= 2.0 && v[2].fract() == 0.0 && v[2] <= 10_000.0 && v[1] > v[0]) {
                bad(
                    format!("output.interior.{k}"),
                    format!("give [start, end, points] with end > start and 2..10000 points (value = {v:?})"),
                );
            }
        }
        let inside = if g.body == "B" { g.y[1] < 0.0 } else { g.y[0] > 0.0 };
        if !inside {
            bad(
                "output.interior.y".into(),
                format!(
                    "the points must lie inside body {}: y > 0 for A, y < 0 for B (value = {:?})",
                    g.body, g.y
                ),
            );
        }
    }
    out
}

/// Why two signed profile radii cannot touch in a contact of the kind the models assume, or
/// None. Contact needs a positive relative curvature 1/R* = 1/R_A + 1/R_B > 0: two concave
/// bodies never touch, and a convex body touches a concave one only inside a larger bore,
/// |R_concave| > R_convex (with |R_concave| = R_convex the bodies conform everywhere and
/// 1/R* = 0). Also used by the scene for radii fitted to meshes.
pub fn radius_pair_problem(ra: f64, rb: f64) -> Option<String> {
    if ra == 0.0 || rb == 0.0 || ra.is_nan() || rb.is_nan() || 1.0 / ra + 1.0 / rb > 0.0 {
        return None;
    }
    Some(if ra < 0.0 && rb < 0.0 {
        format!(
            "both bodies are concave (R_A = {ra}, R_B = {rb}): they cannot touch; a negative radius \
             is a ring's bore, the other body must be convex and run inside it"
        )
    } else {
        let (convex, concave) = if ra > 0.0 { (ra, rb) } else { (rb, ra) };
        format!(
            "internal contact needs the concave body's bore larger than the convex body: \
             |R_concave| = {} must exceed R_convex = {convex} (1/R_A + 1/R_B = {:.6e} <= 0: no \
             contact possible)",
            concave.abs(),
            1.0 / ra + 1.0 / rb
        )
    })
}

#[cfg(test)]
mod tests {
    use super::radius_pair_problem;

    #[test]
    fn a_convex_body_touches_a_concave_one_only_inside_a_larger_bore() {
        assert_eq!(radius_pair_problem(40.0, -50.0), None);
        assert_eq!(radius_pair_problem(-50.0, 40.0), None);
        assert_eq!(radius_pair_problem(40.0, 60.0), None);
        let tight = radius_pair_problem(50.0, -50.0).unwrap();
        assert!(tight.contains("must exceed R_convex = 50"), "{tight}");
        assert!(radius_pair_problem(-30.0, 40.0).unwrap().contains("|R_concave| = 30"));
        assert_eq!(radius_pair_problem(-40.0, 30.0), None);
        assert!(radius_pair_problem(-40.0, -60.0)
            .unwrap()
            .contains("both bodies are concave"));
    }
}
