//! Checks of a case's bodies before the scene builds its grid and anything large: the contact
//! groups of `bem` bodies must be arcs along x, the Hertz estimates and the grid they imply must
//! be finite and physical, and the memory the case needs must be available. They run in
//! `rollbem check` as in `rollbem run` (both build their scene with [`super::Scene::from_case`]),
//! so a case that check accepts does not fail here later.

use super::estimates::Estimates;
use super::registry::BodySetups;
use crate::case::validate::shown;
use crate::case::{CaseError, LoadedCase, NormalSpec, Violation};
use crate::error::Error;
use crate::limits::{self, MemoryError, MemoryEstimate, ProblemSizes};

/// Smallest Hertz half-width over the effective radius that a case may imply: below, the gap
/// x²/2R of the contact is 1e-20 of the radius and the case is a unit mistake, not a contact.
pub const MIN_HALF_WIDTH_OVER_RADIUS: f64 = 1e-10;

/// Checks the contact segments, the derived quantities and the memory of a case with its
/// bodies resolved; returns the memory estimate.
pub fn check(case: &LoadedCase, bodies: &BodySetups) -> Result<MemoryEstimate, Error> {
    check_derived(case, bodies)?;
    check_memory(case, bodies)
}

/// The checks of [`check`] that depend on the loads (contact segments, derived scales), without
/// the memory estimate: for a run on an assembly already built and checked (a sequence's).
pub fn check_derived(case: &LoadedCase, bodies: &BodySetups) -> Result<(), Error> {
    let mut violations = contact_segment_violations(bodies);
    if violations.is_empty() {
        let est = Estimates::of(&case.case, bodies);
        violations = derived_violations(case, &est, bodies);
    }
    if !violations.is_empty() {
        return Err(Error::Case(CaseError::Invalid {
            path: case.path.clone(),
            violations,
        }));
    }
    Ok(())
}

/// A derived value, short: exponent form when tiny or huge, else at most six decimals.
fn sig(v: f64) -> String {
    if v != 0.0 && v.is_finite() && !(1e-3..1e5).contains(&v.abs()) {
        format!("{v:.4e}")
    } else {
        let s = format!("{v:.6}");
        let s = if s.contains('.') {
            s.trim_end_matches('0').trim_end_matches('.')
        } else {
            &s
        };
        s.to_string()
    }
}

/// Whether the contact grid is a `bem` body's own (the case's grid keys are then unused).
fn grid_from_mesh(bodies: &BodySetups) -> bool {
    bodies.iter().any(|b| b.contact_mesh().is_some())
}

/// The contact group of each `bem` body must be an arc along x, which the contact grid is made
/// from (its elements' end points in x): no element without extent in x, no two elements over the
/// same x. With two `bem` bodies, the second's contact group must cover the grid the first's gives
/// (the tolerance of [`crate::body::transfer`]: 1e-9 of the segment's length).
fn contact_segment_violations(bodies: &BodySetups) -> Vec<Violation> {
    let mut out = Vec::new();
    let mut ranges = Vec::new();
    for (k, side) in ["A", "B"].into_iter().enumerate() {
        let Some(own) = bodies[k].contact_mesh() else {
            continue;
        };
        let (lm, contact) = (own.mesh, own.group);
        let m = &lm.mesh;
        let tol = 1e-9 * m.size();
        let mut spans: Vec<[f64; 3]> = m
            .elements
            .iter()
            .filter(|e| e.group == lm.contact_group)
            .map(|e| {
                let (a, b) = e.ends();
                let (xa, xb) = (m.nodes[a][0], m.nodes[b][0]);
                [xa.min(xb), xa.max(xb), m.nodes[a][1]]
            })
            .collect();
        spans.sort_by(|p, q| p[0].total_cmp(&q[0]));
        let key = format!("bodies.{side}.contact");
        let path = lm.path.display();
        if let Some(s) = spans.iter().find(|s| s[1] - s[0] <= tol) {
            out.push(Violation {
                key,
                message: format!(
                    "an element of group `{contact}` in {path} at ({}, {}) runs across x (no extent along \
                     it): the contact group must be the arc of the outline that faces the other body, \
                     along x",
                    sig(s[0]),
                    sig(s[2])
                ),
            });
            continue;
        }
        if let Some(w) = spans.windows(2).find(|w| w[1][0] < w[0][1] - tol) {
            out.push(Violation {
                key,
                message: format!(
                    "group `{contact}` in {path} covers x = {} twice (it folds back, or wraps round the \
                     body): the contact group must be a single arc along x, the part of the outline that \
                     faces the other body",
                    sig(w[1][0])
                ),
            });
            continue;
        }
        ranges.push((side, path.to_string(), contact.to_string(), lm.contact_range()));
    }
    if let [(sa, ma, ca, [a0, a1]), (sb, mb, cb, [b0, b1])] = ranges.as_slice() {
        // The grid is A's contact group; B's must cover it.
        let tol = 1e-9 * (b1 - b0);
        if *a0 < b0 - tol || *a1 > b1 + tol {
            out.push(Violation {
                key: format!("bodies.{sb}.mesh"),
                message: format!(
                    "the contact grid is group `{ca}` of body {sa}'s mesh {ma}, on x in [{}, {}], but group \
                     `{cb}` of {mb} covers only [{}, {}]: lengthen the contact group of {mb} (or shorten \
                     that of {ma}) so that it covers the grid",
                    sig(*a0),
                    sig(*a1),
                    sig(*b0),
                    sig(*b1)
                ),
            });
        }
    }
    out
}

/// The Hertz estimates and the grid must be finite and physical: a contact narrower than the
/// radius, and not vanishingly small.
fn derived_violations(case: &LoadedCase, est: &Estimates, bodies: &BodySetups) -> Vec<Violation> {
    let mut out = Vec::new();
    let mut bad = |key: &str, message: String| {
        out.push(Violation {
            key: key.to_string(),
            message,
        })
    };
    let r = est.effective_radius;
    if !(r.is_finite() && r > 0.0) {
        bad(
            "bodies",
            format!(
                "the effective radius 1/(1/R_A + 1/R_B) is {} (both profiles flat): the Hertz estimates that \
                 size the grid are undefined; give `radius` to the bem body (or bodies) whose contact \
                 group is straight",
                sig(r)
            ),
        );
        return out;
    }
    let a = est.hertz_half_width;
    let ratio = a / r;
    match case.case.load.normal() {
        NormalSpec::Force(p) => {
            if ratio.is_nan() || ratio >= 1.0 {
                bad(
                    "load.normal.force",
                    format!(
                        "P = {} gives a Hertz half-width a = {} beyond the effective radius R = {} \
                         (a/R = {}): no cylinder contact carries this load; lower the load, or check \
                         the units of P against those of E and the radii",
                        shown(p),
                        sig(a),
                        shown(r),
                        sig(ratio)
                    ),
                );
            } else if ratio < MIN_HALF_WIDTH_OVER_RADIUS {
                bad(
                    "load.normal.force",
                    format!(
                        "P = {} gives a Hertz half-width a = {} of only {} times the effective radius \
                         R = {}: below {MIN_HALF_WIDTH_OVER_RADIUS:e} this is a unit mistake; check the \
                         units of P against those of E and the radii",
                        shown(p),
                        sig(a),
                        sig(ratio),
                        shown(r)
                    ),
                );
            }
        }
        NormalSpec::Overlap(d) => {
            if d.is_nan() || d >= r {
                bad(
                    "load.normal.overlap",
                    format!(
                        "the overlap {} is not smaller than the effective radius R = {}: the bodies would \
                         pass through each other; lower it, or check its units against those of the radii",
                        shown(d),
                        shown(r)
                    ),
                );
            }
        }
    }
    if !grid_from_mesh(bodies) {
        let (l, h) = (est.grid_half_length, est.grid_spacing);
        let key = if case.case.contact.grid.half_length.is_some() {
            "contact.grid.half_length"
        } else {
            "contact.grid.extent"
        };
        if !(l.is_finite() && l > 0.0 && h > 0.0 && h.is_finite()) {
            bad(
                key,
                format!(
                    "the grid [-L, L] with L = {} and node spacing {} is not a usable grid",
                    sig(l),
                    sig(h)
                ),
            );
        } else if a.is_nan() || h >= a {
            // With nodes farther apart than a, the whole contact falls between two nodes.
            bad(
                key,
                format!(
                    "the grid's node spacing {} (L = {}, {} elements) is not smaller than the Hertz \
                     half-width a = {}: the contact would fall between two nodes; shorten the grid or \
                     add contact.grid.elements",
                    sig(h),
                    sig(l),
                    case.case.contact.grid.elements,
                    sig(a)
                ),
            );
        }
    }
    // A contact as wide as the smaller body (a load too large, or a roller in a bore with almost
    // no clearance) has no Hertz-type solution: the grid runs along x, and the contact's arc
    // must stay within the angle a contact group may span.
    let r_min = bodies.iter().map(|b| b.radius().abs()).fold(f64::INFINITY, f64::min);
    let arc_limit = r_min * crate::body::bem::MAX_CONTACT_ANGLE_DEG.to_radians().sin();
    let internal = bodies[0].radius() * bodies[1].radius() < 0.0;
    let clearance = (bodies[0].radius().abs() - bodies[1].radius().abs()).abs();
    if out.is_empty() && a.is_finite() && a >= arc_limit {
        let key = match case.case.load.normal() {
            NormalSpec::Force(_) => "load.normal.force",
            NormalSpec::Overlap(_) => "load.normal.overlap",
        };
        let conformal = if internal {
            format!(
                " (a roller in a bore of clearance |R_bore| - |R_roller| = {})",
                sig(clearance)
            )
        } else {
            String::new()
        };
        out.push(Violation {
            key: key.to_string(),
            message: format!(
                "the Hertz half-width a = {} reaches the smaller body's radius |R| = {} (a/|R| = {}; a \
                 contact of steady rolling along x spans at most {}°, a ≤ {}): no contact of this size \
                 exists between these cylinders{conformal}; lower the load{}",
                sig(a),
                shown(r_min),
                sig(a / r_min),
                2.0 * crate::body::bem::MAX_CONTACT_ANGLE_DEG,
                sig(arc_limit),
                if internal { ", or enlarge the clearance" } else { "" }
            ),
        });
    }
    out
}

/// The problem sizes of a case with its bodies resolved: on its grid, or for an error-controlled
/// grid on the grid its tolerance is expected to need ([`expected_elements`]).
pub fn problem_sizes(case: &LoadedCase, bodies: &BodySetups) -> ProblemSizes {
    let c = &case.case;
    match c.contact.grid.tolerance {
        Some(tol) => {
            let mut sizes = problem_sizes_on(case, bodies, Some(expected_elements(tol, c.contact.grid.max_elements)));
            // The passes solve BEM bodies through their stand-ins, condensed on the start grid's
            // coarse levels, so the tolerance's grid costs contact nodes only; the full bodies
            // on the final grid are built when interior fields are asked (or the stand-ins miss
            // the tolerance: each finer grid is then asked whether it fits,
            // [`finer_grid_fits`]).
            let interior = c.output.interior.is_some() || c.output.strength.is_some();
            if c.contact.grid.stand_ins && !interior {
                let finest = crate::body::bem::stand_in::level_bisections(tol) + 1;
                for (k, nodes) in sizes.bem_nodes.iter_mut().enumerate() {
                    if let Some(n) = bodies[k].stand_in_nodes(finest) {
                        *nodes = Some(n);
                    }
                }
            }
            sizes
        }
        None => {
            let mut sizes = problem_sizes_on(case, bodies, None);
            // A fixed grid's error estimate solves the grid halved (src/adapt/fixed.rs): twice
            // the contact nodes, the bodies' meshes cut at as many more points only.
            if c.contact.grid.estimate {
                sizes.contact_nodes *= 2;
            }
            sizes
        }
    }
}

/// The elements an error-controlled contact grid is expected to reach at `tolerance` (capped by
/// `max_elements`): 115 at 1e-3, twice as many a decade of the tolerance lower (∝ TOL^(−0.3)).
/// Measured final grids of the shipped BEM cases (carter_051_true, fig14_true_geometry,
/// bore_a020_tractive) at 1e-3 / 1e-4 / 1e-5: 80–152 / 152–336 / 336–454 elements; the
/// quadratic elements' error falls like h² to h³ between the graded square-root points, and
/// each decade took 1.9–2.2 times the elements. The run itself stops refining before a grid that
/// would not fit in memory ([`grid_fits_in_memory`]), so an under-estimate never aborts a run.
pub fn expected_elements(tolerance: f64, max_elements: usize) -> usize {
    const AT_1E3: f64 = 115.0;
    let n = AT_1E3 * (1e-3 / tolerance.clamp(1e-12, 1.0)).powf(0.3);
    (n.ceil() as usize).min(max_elements)
}

/// Whether the case's bodies on a contact grid of `elements` elements fit in the memory
/// available ([`limits::available_memory`]) — what an error-controlled run checks before each
/// finer grid.
pub fn grid_fits_in_memory(case: &LoadedCase, bodies: &BodySetups, elements: usize) -> bool {
    let estimate = MemoryEstimate::of(&problem_sizes_on(case, bodies, Some(elements)));
    estimate.bytes() <= limits::available_memory().unwrap_or(limits::FALLBACK_AVAILABLE_BYTES)
}

/// [`grid_fits_in_memory`] for the next grid of an error-controlled run, with a warning when it
/// does not (the run then keeps the best solution reached and ends not converged).
pub fn finer_grid_fits(case: &LoadedCase, bodies: &BodySetups, elements: usize) -> bool {
    let fits = grid_fits_in_memory(case, bodies, elements);
    if !fits {
        log::warn!(
            "error control stopped before a grid of {elements} elements: its matrices would not fit in the \
             memory available ({}); the best solution reached is kept",
            limits::available_memory().map_or("unknown".into(), limits::human_bytes)
        );
    }
    fits
}

/// The problem sizes of a case with its bodies resolved, its contact grid cut into `elements`
/// elements where given (the mesh's contact group is then cut into that many), else its own.
fn problem_sizes_on(case: &LoadedCase, bodies: &BodySetups, elements: Option<usize>) -> ProblemSizes {
    let c = &case.case;
    let limit = elements;
    let contact_nodes = match bodies.iter().find_map(|b| b.contact_mesh()) {
        // The mesh's discontinuous quadratic contact elements carry three nodes each.
        Some(own) => {
            let lm = own.mesh;
            let mesh_elements = lm.mesh.elements.iter().filter(|e| e.group == lm.contact_group).count();
            3 * limit.map_or(mesh_elements, |n| n.max(mesh_elements))
        }
        None => {
            let kind = c.contact.grid.element;
            let n = limit.unwrap_or(c.contact.grid.elements);
            kind.node_stride().saturating_mul(n) + usize::from(kind.shares_nodes())
        }
    };
    let bem_nodes = [0, 1].map(|k| match limit {
        Some(n) => bodies[k].discretisation_nodes_on(n),
        None => bodies[k].discretisation_nodes(),
    });
    let interior_points = c
        .output
        .interior
        .as_ref()
        .map_or(0, |g| (g.x[2] as usize).saturating_mul(g.y[2] as usize));
    ProblemSizes {
        contact_nodes,
        bem_nodes,
        interior_points,
        vtk: c.output.vtk,
    }
}

/// Refuses a case whose estimated peak memory exceeds what the machine has available; returns
/// the estimate. Also for scenes built from their own bodies (the studies').
pub fn check_memory(case: &LoadedCase, bodies: &BodySetups) -> Result<MemoryEstimate, Error> {
    let sizes = problem_sizes(case, bodies);
    let estimate = MemoryEstimate::of(&sizes);
    let available = limits::available_memory().unwrap_or(limits::FALLBACK_AVAILABLE_BYTES);
    if estimate.bytes() <= available {
        return Ok(estimate);
    }
    Err(Error::Memory(MemoryError {
        case: case.path.clone(),
        needed: estimate.bytes(),
        available,
        breakdown: breakdown(&sizes, &estimate),
        advice: advice(case, bodies, &sizes, &estimate, available),
    }))
}

/// The estimate's terms with the sizes behind them.
fn breakdown(sizes: &ProblemSizes, e: &MemoryEstimate) -> String {
    let mut parts = vec![format!(
        "{} for the dense matrices of {} contact nodes",
        limits::human_bytes(e.contact),
        sizes.contact_nodes
    )];
    if let Some(n) = sizes.bem_nodes.iter().flatten().max() {
        parts.push(format!(
            "{} for the BEM matrices of a body of {n} boundary nodes",
            limits::human_bytes(e.bem)
        ));
    }
    if sizes.interior_points > 0 {
        parts.push(format!(
            "{} for {} interior points",
            limits::human_bytes(e.interior),
            sizes.interior_points
        ));
    }
    parts.join(", ")
}

/// What to change: the key (or mesh) behind the largest term, and how far.
fn advice(case: &LoadedCase, bodies: &BodySetups, sizes: &ProblemSizes, e: &MemoryEstimate, available: f64) -> String {
    let c = &case.case;
    let room = |others: f64| (available - limits::BASE_BYTES - others).max(0.0);
    let mesh_of = |k: usize| {
        bodies[k]
            .contact_mesh()
            .map_or_else(String::new, |own| own.mesh.path.display().to_string())
    };
    if e.interior >= e.contact.max(e.bem) {
        let per_point = e.interior / sizes.interior_points.max(1) as f64;
        let fit = room(e.contact + e.bem) / per_point;
        let g = c.output.interior.as_ref();
        let (nx, ny) = g.map_or((0.0, 0.0), |g| (g.x[2], g.y[2]));
        let vtk = if c.output.vtk {
            let share = limits::BYTES_PER_INTERIOR_POINT / limits::BYTES_PER_INTERIOR_POINT_VTK;
            format!(
                " (or set output.vtk: false, which takes {:.0} % of the memory per point)",
                100.0 * share
            )
        } else {
            String::new()
        };
        return format!(
            "ask fewer output.interior points: now {nx} x {ny} = {}, about {:.0} fit{vtk}",
            sizes.interior_points,
            fit.floor()
        );
    }
    if let Some(tolerance) = c.contact.grid.tolerance {
        // The grid (and a mesh's cut contact group) grows as the tolerance asks.
        return format!(
            "raise contact.grid.tolerance (now {tolerance:e}): the estimate is for the grid of about {} \
             elements this tolerance is expected to need{}",
            expected_elements(tolerance, c.contact.grid.max_elements),
            if grid_from_mesh(bodies) {
                ", the mesh's contact group cut into as many"
            } else {
                ""
            }
        );
    }
    if e.bem > e.contact {
        let k = if sizes.bem_nodes[0] >= sizes.bem_nodes[1] { 0 } else { 1 };
        let side = ["A", "B"][k];
        let nodes = sizes.bem_nodes[k].unwrap_or(0);
        let fit = (room(e.contact + e.interior) / limits::BYTES_PER_BEM_UNKNOWN_SQUARED).sqrt() / 2.0;
        let fits = if fit >= 1.0 {
            format!("about {:.0} fit", fit.floor())
        } else {
            "no BEM body fits beside the rest of the case".to_string()
        };
        return format!(
            "coarsen the mesh of bodies.{side} ({}, {nodes} boundary nodes; {fits})",
            mesh_of(k)
        );
    }
    match bodies.iter().position(|b| b.contact_mesh().is_some()) {
        Some(k) => {
            let group = bodies[k].contact_mesh().map_or("contact", |own| own.group);
            format!(
                "the contact grid is the contact group `{group}` of {}: mesh it with fewer elements",
                mesh_of(k)
            )
        }
        None => {
            let stride = c.contact.grid.element.node_stride() as f64;
            let fit = (room(e.bem + e.interior) / limits::BYTES_PER_CONTACT_NODE_SQUARED).sqrt() / stride;
            let (key, now) = match c.contact.grid.tolerance {
                Some(_) => ("max_elements", c.contact.grid.max_elements),
                None => ("elements", c.contact.grid.elements),
            };
            format!("lower contact.grid.{key} (now {now}; about {:.0} fit)", fit.floor())
        }
    }
}

/// What to change when the solved contact reaches an end of the grid: the grid keys for a
/// uniform grid; the mesh's contact group (or the load) when the grid is a `bem` body's own.
pub fn grid_too_short_advice(case: &LoadedCase, bodies: &BodySetups) -> String {
    let c = &case.case;
    let meshes: Vec<(&str, String, &str)> = ["A", "B"]
        .into_iter()
        .zip(bodies)
        .filter_map(|(side, b)| {
            b.contact_mesh()
                .map(|own| (side, own.mesh.path.display().to_string(), own.group))
        })
        .collect();
    // A `geometry:` body's mesh (labelled `<geometry …>`) is sized by the case's grid keys,
    // unless a mesh file sets the contact elements.
    let generated = |m: &&(&str, String, &str)| m.1.starts_with("<geometry");
    let bem = meshes.iter().find(|m| !generated(m)).or(meshes.first());
    match bem {
        Some((side, mesh, _)) if mesh.starts_with("<geometry") => format!(
            "The grid is the contact segment rollbem generated for body {side}'s geometry around the \
             Hertz contact: increase contact.grid.extent (now {}), or give contact.grid.half_length",
            shown(c.contact.grid.extent)
        ),
        Some((side, mesh, contact)) => format!(
            "The grid is the contact group `{contact}` of body {side}'s mesh {mesh}: extend that group \
             over a longer arc in the mesh, or lower the load"
        ),
        None if c.contact.grid.half_length.is_some() => format!(
            "Increase contact.grid.half_length (now {})",
            shown(c.contact.grid.half_length.unwrap_or(0.0))
        ),
        None => format!(
            "Increase contact.grid.extent (now {}), or give contact.grid.half_length",
            shown(c.contact.grid.extent)
        ),
    }
}
