//! Whole-case validation: every rule is checked and every violation reported with its key and
//! value (as CONTACT's input check does), so the user fixes a case in one pass.

use super::schema::*;
use cover::overlap_through_a_cover;
use viscoelastic::{rolling_speed_problems, viscoelastic_problems};
// The per-kind checks of a body's keys, which src/case/kinds.rs runs.
pub(super) use geometry::geometry_violations;

mod cover;
mod friction;
mod geometry;
mod strength;
mod transient;
mod viscoelastic;

/// Magnitudes that a dimensional input (a length, force per length or stress) may take, in any
/// consistent units: [1e-30, 1e30]. Derived quantities are products and quotients of a few of
/// them (the Hertz half-width a = √(4PR/πE*), the peak pressure p0 = 2P/πa, the influence
/// coefficients ~ ln(x)/E*, the gap x²/2R), so they stay far inside the range of a double
/// (1e±308) and never overflow to infinity or underflow to zero. Every real unit system (SI, mm–N–MPa,
/// µm–mN–GPa) puts physical values well inside it.
pub const MAGNITUDE: [f64; 2] = [1e-30, 1e30];

/// Largest friction coefficient: beyond any measured value (μ ≈ 0.05–1.5); large values stand in for full stick.
pub const MAX_FRICTION: f64 = 1e6;

/// Largest grid extent in Hertz half-widths: beyond it the Hertz contact lies inside one or two elements.
pub const MAX_EXTENT: f64 = 100.0;

/// Range of the penalty scale c (`solver.penalty`): the automatic penalty times 1e±12 covers every
/// useful choice; beyond, the projections lose all digits of one of their two terms.
pub const PENALTY_RANGE: [f64; 2] = [1e-12, 1e12];

/// Largest number of contact elements: no machine holds the dense matrices of more (the memory
/// estimate refuses far fewer); the bound keeps the node counts far from integer overflow.
pub const MAX_ELEMENTS: usize = 1_000_000_000;

/// Smallest `contact.grid.tolerance`: the solver's own tolerance and round-off of the nodal
/// tractions lie some decades below.
pub const MIN_GRID_TOLERANCE: f64 = 1e-7;

/// Largest `contact.grid.tolerance` (a 50 % error is no accuracy at all).
pub const MAX_GRID_TOLERANCE: f64 = 0.5;

/// Largest `contact.grid.max_elements` (dense matrices of 3·4000 nodes take some GB).
pub const MAX_ADAPTIVE_ELEMENTS: usize = 4000;

/// Smallest number of elements of a uniform contact grid: with one or two, the elements that hold
/// the Hertz contact are also the end elements of the grid, so no grid length contains the contact.
pub const MIN_UNIFORM_ELEMENTS: usize = 3;

/// A value as the user would write it: plain for everyday magnitudes, in exponent form for tiny
/// or huge ones (so that 1.79e308 is not printed with 300 digits).
pub fn shown(v: f64) -> String {
    if v != 0.0 && v.is_finite() && !(1e-4..1e6).contains(&v.abs()) {
        format!("{v:e}")
    } else {
        format!("{v}")
    }
}

/// Why a positive dimensional value `v` is out of range, if it is.
fn positive_quantity(v: f64) -> Option<String> {
    if !(v > 0.0 && v.is_finite()) {
        Some(format!("must be positive and finite (value = {})", shown(v)))
    } else {
        magnitude(v)
    }
}

/// Why a dimensional value `v` (that may be zero or negative) is out of range, if it is.
fn magnitude(v: f64) -> Option<String> {
    let [lo, hi] = MAGNITUDE;
    if !v.is_finite() {
        Some(format!("must be a finite number (value = {})", shown(v)))
    } else if v != 0.0 && !(lo..=hi).contains(&v.abs()) {
        Some(format!(
            "|value| = {:e} lies outside [{lo:e}, {hi:e}], the range of physical values in any consistent \
             units: check the units of the case",
            v.abs()
        ))
    } else {
        None
    }
}

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

/// The violations of a case, as the checks find them.
pub(super) struct Problems(Vec<Violation>);

impl Problems {
    /// Records that `key` breaks a rule, and why.
    pub(super) fn bad(&mut self, key: String, message: String) {
        self.0.push(Violation { key, message });
    }
}

/// Checks every rule of the case; an empty list means the case is valid.
pub fn validate(case: &Case) -> Vec<Violation> {
    let mut found = Problems(Vec::new());
    material_problems(case, &mut found);
    body_problems(case, &mut found);
    for (key, message) in rolling_speed_problems(case) {
        found.bad(key, message);
    }
    contact_problems(case, &mut found);
    load_problems(case, &mut found);
    solver_problems(case, &mut found);
    interior_problems(case, &mut found);
    for (key, message) in strength::strength_problems(case)
        .into_iter()
        .chain(transient::transient_problems(case))
        .chain(friction::falling_friction_problems(case))
        .chain(friction::ratio_of_a_large_friction(case))
    {
        found.bad(key, message);
    }
    found.0
}

/// The materials: moduli, Poisson's ratio, the viscoelastic keys.
fn material_problems(case: &Case, found: &mut Problems) {
    for (name, m) in &case.materials {
        let key = |k: &str| format!("materials.{name}.{k}");
        match (m.young, m.shear) {
            (Some(_), Some(_)) => found.bad(key("E"), "give either E or G, not both".into()),
            (None, None) => found.bad(
                key("E"),
                "missing: give Young's modulus E (or the shear modulus G)".into(),
            ),
            (Some(e), None) => {
                if let Some(why) = positive_quantity(e) {
                    found.bad(key("E"), format!("Young's modulus {why}"));
                }
            }
            (None, Some(g)) => {
                if let Some(why) = positive_quantity(g) {
                    found.bad(key("G"), format!("shear modulus {why}"));
                }
            }
        }
        if !(m.nu > -1.0 && m.nu <= 0.5) {
            found.bad(
                key("nu"),
                format!("Poisson's ratio must lie in (-1, 0.5] (value = {})", shown(m.nu)),
            );
        }
        if let Some(v) = &m.viscoelastic {
            for (k, message) in viscoelastic_problems(m, v) {
                found.bad(key(&format!("viscoelastic.{k}")), message);
            }
        }
    }
}

/// The bodies: each body's keys by its model, their radii as a pair, not both rigid.
fn body_problems(case: &Case, found: &mut Problems) {
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
    // The key that gives each profile radius: `radius`, or the `geometry:` it comes from.
    let mut radius_keys = ["bodies.A.radius".to_string(), "bodies.B.radius".to_string()];
    for (k, (side, body)) in [("A", &case.bodies.a), ("B", &case.bodies.b)].into_iter().enumerate() {
        if let Some(v) = body.material_name().and_then(|m| undefined_material(side, m)) {
            found.bad(v.key, v.message);
        }
        if !body.capabilities().deforms {
            rigid += 1;
        }
        let profile = body.key_problems(case, side, found);
        given[k] = profile.given;
        if profile.from_geometry {
            radius_keys[k] = format!("bodies.{side}.geometry");
        }
        let radius = profile.checked;
        let nonzero = if radius == 0.0 {
            Some("must be non-zero and finite (value = 0)".to_string())
        } else {
            magnitude(radius)
        };
        if let Some(why) = nonzero {
            found.bad(
                format!("bodies.{side}.radius"),
                format!(
                    "radius {why}: positive for a convex body, negative for a concave one (a ring's bore); \
                     model a flat as a large radius"
                ),
            );
        }
    }
    // A pair whose radii are already refused one by one says nothing more.
    let refused_before = found
        .0
        .iter()
        .any(|v| v.key.contains(".radius") || v.key.contains(".geometry"));
    if let ([Some(ra), Some(rb)], false) = (given, refused_before) {
        if let Some(message) = radius_pair_problem(ra, rb) {
            found.bad(format!("{}, {}", radius_keys[0], radius_keys[1]), message);
        }
    }
    if rigid == 2 {
        found.bad(
            "bodies".into(),
            "both bodies are rigid: at least one must be elastic".into(),
        );
    }
}

/// A layer's cover thickness: positive, and thin against the radius (the layer model takes the
/// cover flat); a thick cover is a bem body.
pub(super) fn layer_thickness_problems(
    case: &Case,
    side: &str,
    material: &str,
    radius: f64,
    thickness: f64,
    found: &mut Problems,
) {
    if let Some(why) = positive_quantity(thickness) {
        found.bad(format!("bodies.{side}.thickness"), format!("cover thickness {why}"));
    } else if radius.is_finite() && thickness >= 0.5 * radius.abs() {
        // The true geometry of a cover is a bem body, which is elastic only.
        let instead = if case.materials.get(material).is_some_and(|m| m.viscoelastic.is_some()) {
            "no model of rollbem takes a viscoelastic cover this thick (the bem body that models \
                 a thick cover is elastic): make the cover thinner than R/2, or give an elastic \
                 material and model the body by `bem` with `geometry: {covered_roller: ...}`"
        } else {
            "model the body by `bem` with `geometry: {covered_roller: ...}`"
        };
        found.bad(
            format!("bodies.{side}.thickness"),
            format!(
                "the layer model takes the cover flat (thickness b << radius R); b = {} is not below \
                     R/2 = {}: {instead}",
                shown(thickness),
                shown(0.5 * radius.abs())
            ),
        );
    }
}

/// The prescribed boundary conditions of a bem body's other groups: exactly one kind each,
/// and zero (a non-zero one would move the contact surface outside the gap the run solves).
pub(super) fn prescribed_boundary_problems(
    side: &str,
    boundaries: &std::collections::BTreeMap<String, BoundarySpec>,
    found: &mut Problems,
) {
    for (group, spec) in boundaries {
        if let BoundarySpec::Prescribed(p) = spec {
            let n = [p.displacement.is_some(), p.traction.is_some(), p.pressure.is_some()];
            if n.iter().filter(|&&b| b).count() != 1 {
                found.bad(
                    format!("bodies.{side}.boundaries.{group}"),
                    "give `fixed`, `free`, or exactly one of {displacement: [ux, uy]}, {traction: [tx, ty]}, {pressure: p}".into(),
                );
            } else {
                let values = p
                    .displacement
                    .or(p.traction)
                    .map_or(vec![p.pressure.unwrap_or(0.0)], |v| v.to_vec());
                if values.iter().any(|v| *v != 0.0) {
                    found.bad(
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
}

/// `contact`: friction and the grid.
fn contact_problems(case: &Case, found: &mut Problems) {
    let c = &case.contact;
    if !(c.friction >= 0.0 && c.friction <= MAX_FRICTION) {
        found.bad(
            "contact.friction".into(),
            format!(
                "friction coefficient must be >= 0 and <= {MAX_FRICTION:e} (value = {})",
                shown(c.friction)
            ),
        );
    }
    // A body meshed in Gmsh brings its own contact elements (the grid follows them); a generated
    // (`geometry:`) body's contact segment is cut into `elements` like a uniform grid.
    let bodies = || [&case.bodies.a, &case.bodies.b].into_iter();
    let meshed_bem = bodies().any(|b| b.has_own_contact_elements());
    let bem_body = bodies().any(|b| b.capabilities().boundary_elements);
    if c.grid.elements == 0 {
        found.bad(
            "contact.grid.elements".into(),
            "need at least one contact element (value = 0); 21 is the paper's grid".into(),
        );
    } else if c.grid.elements > MAX_ELEMENTS {
        found.bad(
            "contact.grid.elements".into(),
            format!(
                "{} elements are beyond the memory of any machine (at most {MAX_ELEMENTS}); 21 is the paper's grid",
                c.grid.elements
            ),
        );
    } else if c.grid.elements < MIN_UNIFORM_ELEMENTS && !meshed_bem {
        found.bad(
            "contact.grid.elements".into(),
            format!(
                "need at least {MIN_UNIFORM_ELEMENTS} elements (value = {}): with fewer, the elements that \
                 carry the contact are the end elements of the grid, which must stay unloaded; 21 is the \
                 paper's grid",
                c.grid.elements
            ),
        );
    }
    if !(c.grid.extent > 1.0 && c.grid.extent <= MAX_EXTENT) {
        found.bad(
            "contact.grid.extent".into(),
            format!(
                "the grid must extend beyond the Hertz contact and hold it in more than a couple of \
                 elements: 1 < extent <= {MAX_EXTENT} (value = {}); 1.3 is typical, use \
                 contact.grid.half_length for a long grid",
                shown(c.grid.extent)
            ),
        );
    }
    if bem_body && c.grid.element != crate::grid::ElementKind::DiscontinuousQuadratic {
        found.bad(
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
        if let Some(why) = positive_quantity(h) {
            found.bad("contact.grid.half_length".into(), why);
        }
    }
    if let Some(tol) = c.grid.tolerance {
        if !(MIN_GRID_TOLERANCE..=MAX_GRID_TOLERANCE).contains(&tol) {
            found.bad(
                "contact.grid.tolerance".into(),
                format!(
                    "the requested error must lie in [{MIN_GRID_TOLERANCE:e}, {MAX_GRID_TOLERANCE}] \
                     (value = {}): below, round-off of the solution is of the same size; 1e-4 is \
                     typical",
                    shown(tol)
                ),
            );
        }
        if c.grid.element == crate::grid::ElementKind::Constant {
            // The estimate compares the grid's interpolant with its bisection's; piecewise
            // constant interpolants differ by O(h) jumps even where the nodal values are exact,
            // so the estimate stays an order above the true error and the grid refines to its
            // limit (Carter at 1e-4 stopped at max_elements with a true error of 9e-5).
            found.bad(
                "contact.grid.element".into(),
                "an error-controlled grid (contact.grid.tolerance) needs quadratic elements: with \
                 constant ones the error estimate is dominated by the jumps of the piecewise-constant \
                 traction and overstates the error tenfold; use discontinuous_quadratic (the default) or \
                 continuous_quadratic, or a fixed grid of constant elements without a tolerance"
                    .into(),
            );
        }
        if c.grid.max_elements < 2 * c.grid.elements.max(1) || c.grid.max_elements > MAX_ADAPTIVE_ELEMENTS {
            found.bad(
                "contact.grid.max_elements".into(),
                format!(
                    "must be at least twice contact.grid.elements ({}) and at most \
                     {MAX_ADAPTIVE_ELEMENTS} (value = {}): the error estimate solves the grid and its \
                     bisection",
                    c.grid.elements, c.grid.max_elements
                ),
            );
        }
    }
}

/// `load`: the normal and tangential controls and their ranges.
fn load_problems(case: &Case, found: &mut Problems) {
    let c = &case.contact;
    if let Err(m) = case.load.normal_keys.spec() {
        found.bad("load.normal".into(), m);
    }
    if let Err(m) = case.load.tangential_keys.spec() {
        found.bad("load.tangential".into(), m);
    }
    let normal_force = match case.load.normal() {
        NormalSpec::Force(p) => {
            if let Some(why) = positive_quantity(p) {
                found.bad("load.normal.force".into(), format!("normal force {why}"));
            }
            Some(p)
        }
        NormalSpec::Overlap(d) => {
            if let Some(why) = positive_quantity(d) {
                found.bad("load.normal.overlap".into(), format!("overlap {why}"));
            }
            for (key, message) in overlap_through_a_cover(&case.bodies, d) {
                found.bad(key, message);
            }
            None
        }
    };
    let full_sliding = "no steady rolling exists (full sliding); use |Q| < muP";
    match case.load.tangential() {
        TangentialSpec::Ratio(r) => {
            if r.is_nan() || r.abs() >= 1.0 {
                found.bad(
                    "load.tangential.ratio".into(),
                    format!("|Q/(muP)| must be < 1 (value = {}): {full_sliding}", shown(r)),
                );
            } else if c.friction == 0.0 && r != 0.0 {
                found.bad(
                    "load.tangential.ratio".into(),
                    "a ratio Q/(muP) needs friction > 0".into(),
                );
            }
        }
        TangentialSpec::Force(q) => {
            if let Some(why) = magnitude(q) {
                found.bad("load.tangential.force".into(), format!("tangential force: {why}"));
            } else if let Some(p) = normal_force {
                if q.is_nan() || q.abs() >= c.friction * p {
                    found.bad(
                        "load.tangential.force".into(),
                        format!("|Q| = {} must be < muP = {} : {full_sliding}", q.abs(), c.friction * p),
                    );
                }
            }
        }
        TangentialSpec::Creep(x) => {
            // ξ = (V_A − V_B)/V with V the mean speed: |ξ| = 2 means that one surface stands still.
            if x.is_nan() || x.abs() >= 2.0 {
                found.bad(
                    "load.tangential.creep".into(),
                    format!(
                        "creepage (V_A - V_B)/V must lie in (-2, 2) (value = {}): at |xi| = 2 one surface \
                         stands still and nothing rolls",
                        shown(x)
                    ),
                );
            }
        }
    }
}

/// `solver`: tolerance, iterations, penalty.
fn solver_problems(case: &Case, found: &mut Problems) {
    let s = &case.solver;
    // A tolerance below round-off (about 1e-14) is allowed: it enters no derived quantity, and
    // the stall test of every method ends such a run with exit 2 and its history.
    if !(s.tolerance > 0.0 && s.tolerance < 1.0) {
        found.bad(
            "solver.tolerance".into(),
            format!(
                "must lie in (0, 1) (value = {}); 1e-10 is the default",
                shown(s.tolerance)
            ),
        );
    }
    if s.max_iterations == 0 {
        found.bad("solver.max_iterations".into(), "must be >= 1 (value = 0)".into());
    }
    if let Penalty::Scale(p) = s.penalty {
        if !(PENALTY_RANGE[0]..=PENALTY_RANGE[1]).contains(&p) {
            found.bad(
                "solver.penalty".into(),
                format!(
                    "penalty scale must be `auto` or lie in [{:e}, {:e}] (value = {}); it multiplies the \
                     automatic penalty",
                    PENALTY_RANGE[0],
                    PENALTY_RANGE[1],
                    shown(p)
                ),
            );
        }
    }
}

/// `output.interior`: a body with an interior, a grid inside it.
fn interior_problems(case: &Case, found: &mut Problems) {
    if let Some(g) = &case.output.interior {
        let body = match g.body.as_str() {
            "A" => Some(&case.bodies.a),
            "B" => Some(&case.bodies.b),
            _ => None,
        };
        match body {
            None => found.bad(
                "output.interior.body".into(),
                format!("must be A or B (value = {})", g.body),
            ),
            Some(body) if !body.capabilities().deforms => found.bad(
                "output.interior.body".into(),
                format!(
                    "body {} is rigid: it does not deform and has no interior stresses; ask for a \
                     half_space or bem body",
                    g.body
                ),
            ),
            Some(body) if !body.capabilities().interior_fields => found.bad(
                "output.interior.body".into(),
                format!(
                    "body {} is a {}, whose model gives its surface only; ask for the other body, or \
                     model the cover by `bem` (geometry: covered_roller)",
                    g.body,
                    body.capabilities().name
                ),
            ),
            // A deforming body with interior fields: the grid is checked below.
            Some(_) => {}
        }
        for (k, v) in [("x", g.x), ("y", g.y)] {
            if let Some(why) = magnitude(v[0]).or_else(|| magnitude(v[1])) {
                found.bad(format!("output.interior.{k}"), format!("start and end: {why}"));
            } else if !(v[2] >= 2.0 && v[2].fract() == 0.0 && v[2] <= 10_000.0 && v[1] > v[0]) {
                found.bad(
                    format!("output.interior.{k}"),
                    format!("give [start, end, points] with end > start and 2..10000 points (value = {v:?})"),
                );
            }
        }
        let inside = if g.body == "B" { g.y[1] < 0.0 } else { g.y[0] > 0.0 };
        if !inside {
            found.bad(
                "output.interior.y".into(),
                format!(
                    "the points must lie inside body {}: y > 0 for A, y < 0 for B (value = {:?})",
                    g.body, g.y
                ),
            );
        }
    }
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
