//! Where a scene's inputs leave what its models are valid for: the warnings that `rollbem run`
//! prints and records in summary.json (`warnings`), and that `rollbem check` prints too. They
//! do not stop a run; they say which result to distrust and why.
//!
//! * **Small strain.** Every model is linear elasticity: the peak pressure (solved, else the
//!   Hertz estimate) over a deformable body's Young's modulus, the order of the contact strains, above
//!   [`MAX_PRESSURE_OVER_MODULUS`] leaves it (a rubber cover at p0/E = 0.3, a unit mistake in E).
//! * **The half-space idealisation.** A body modelled as a half-plane carries the error the
//!   measured tables of `crate::advice` give for the scene's a/R (rollers on shafts, or a
//!   roller in a bore); above [`MAX_HALF_SPACE_ERROR`] of p0 or μp0 the true geometry is needed.
//! * **First-order BEM meshes.** Gmsh `line2` elements follow a circle by chords; on the shipped
//!   rollers they move the creepage and p_max by about 0.7 % against `line3` meshes.

use super::registry::BodySetups;
use super::Estimates;
use crate::advice::{self, HalfSpaceError};

/// Largest p0/E of a deformable body taken as small strain [-].
pub const MAX_PRESSURE_OVER_MODULUS: f64 = 0.05;

/// Smallest share of the pair's compliance (1 − ν²)/E for which a half-plane body's
/// idealisation error is warned about [-]: below it the other body's deformation sets the
/// contact (a steel roller, 4e-6 of a 10 MPa rubber cover's compliance).
pub const MIN_COMPLIANCE_SHARE: f64 = 0.01;

/// Largest estimated half-space error (fraction of p0 in pressure, of μp0 in shear) that passes
/// without a warning [-]: the default accuracy of `rollbem check`'s model advice.
pub const MAX_HALF_SPACE_ERROR: f64 = 0.01;

/// The convex body's radius R1 when the other body is concave (a roller in a ring's bore),
/// else None.
pub fn convex_radius_in_a_bore(bodies: &BodySetups) -> Option<f64> {
    let [ra, rb] = [bodies[0].radius(), bodies[1].radius()];
    match (ra < 0.0, rb < 0.0) {
        (true, false) => Some(rb),
        (false, true) => Some(ra),
        _ => None,
    }
}

/// The half-space model's estimated error on the scene's rollers (or roller in a bore), from
/// the measured tables of `crate::advice` (measured with every compliant body a half-space),
/// times the share of the pair's compliance held by the bodies the half-space question concerns
/// ([`half_plane_share`]): the error is those bodies' displacements' and, to first order,
/// scales with them (a steel half-space on a rubber cover shares in almost none).
pub fn half_space_error(bodies: &BodySetups, est: &Estimates) -> HalfSpaceError {
    let error = match convex_radius_in_a_bore(bodies) {
        Some(r1) => advice::internal_error(est.hertz_half_width / r1),
        None => advice::roller_error(est.half_width_over_radius),
    };
    let share = half_plane_share(bodies);
    if share == 1.0 {
        return error;
    }
    HalfSpaceError {
        pressure: share * error.pressure,
        shear: error.shear.map(|q| share * q),
        basis: format!(
            "{}, times {share:.2e}: the half-space bodies' share of the compliance",
            error.basis
        ),
        ..error
    }
}

/// The share [-] of the pair's plane-strain compliance (1 − ν²)/E held by the bodies whose
/// model the half-space question concerns ([`crate::body::BodySetup::shares_half_space_error`]):
/// 1 when every compliant body is one, 0 when none is (or nothing deforms).
pub fn half_plane_share(bodies: &BodySetups) -> f64 {
    let total: f64 = bodies.iter().map(|b| b.compliance()).sum();
    let idealised: f64 = bodies
        .iter()
        .filter(|b| b.shares_half_space_error())
        .map(|b| b.compliance())
        .sum();
    if total > 0.0 {
        idealised / total
    } else {
        0.0
    }
}

/// Why the contact frame a case asks for explicitly (`contact.traction_axes: contact`) cannot
/// be had: a body without a geometry of its own (a half-space is flat in its model) leaves the
/// tractions along the global axes. None when the case did not ask (the default) or was
/// honoured.
pub fn traction_axes_warning(case: &crate::case::LoadedCase, bodies: &BodySetups) -> Option<String> {
    let asked = case.resolved.pointer("/contact/traction_axes").and_then(|v| v.as_str());
    let flat = ["A", "B"]
        .iter()
        .zip(bodies)
        .find_map(|(side, b)| b.surface_at(0.0, crate::body::Side::A).is_none().then_some(side))?;
    (asked == Some("contact")).then(|| {
        format!(
            "contact.traction_axes: contact cannot be honoured: body {flat} ({}) is flat in its model, \
             so the tractions act along the global axes (summary.json `traction_axes`); model both \
             bodies with their geometry (`bem` or `rigid`) for the contact's own axes",
            bodies[if *flat == "A" { 0 } else { 1 }].model_name()
        )
    })
}

/// The validity warnings of a scene (module docs), A's body first. `solved_peak` is the solved
/// peak pressure p_max [stress] once there is one: the small-strain test then uses it instead of
/// the Hertz estimate, which understates it 1.6–2.2 times on a thin cover (whose contact is
/// stiffer than a half-plane's).
pub fn warnings(bodies: &BodySetups, est: &Estimates, solved_peak: Option<f64>) -> Vec<String> {
    let mut out = Vec::new();
    let (p0, which) = match solved_peak.filter(|p| p.is_finite() && *p > 0.0) {
        Some(p) => (p, "solved peak pressure p_max"),
        None if est.scales_from.is_some() => (est.hertz_peak_pressure, "estimated peak pressure p0"),
        None => (est.hertz_peak_pressure, "Hertz peak pressure p0"),
    };
    for (side, body) in ["A", "B"].iter().zip(bodies) {
        if let Some(m) = body.hertz_material() {
            let ratio = p0 / m.young;
            if ratio > MAX_PRESSURE_OVER_MODULUS {
                out.push(format!(
                    "body {side}: the {which} = {p0:.4e} is {ratio:.3} of its Young's modulus \
                     E = {:.4e}: strains of this size leave linear elasticity (small strain, every model \
                     here); take the results as indicative, or check the units of E and the load",
                    m.young
                ));
            }
        }
        if let Some(own) = body.contact_mesh() {
            let first_order = own.mesh.mesh.elements.iter().filter(|e| e.nodes.len() == 2).count();
            if first_order > 0 {
                out.push(format!(
                    "body {side}: {first_order} of the {} elements of {} are first-order (2-node): they \
                     follow a curved boundary by chords (on the shipped rollers the creepage and p_max \
                     move by about 0.7 % against quadratic elements); mesh with `Mesh.ElementOrder = 2`",
                    own.mesh.mesh.elements.len(),
                    own.mesh.path.display()
                ));
            }
        }
    }
    // A half-plane body that carries a negligible share of the pair's compliance (a steel
    // roller on a rubber cover) passes its idealisation's error on to the contact only at that
    // share.
    let total: f64 = bodies.iter().map(|b| b.compliance()).sum();
    let matters =
        |b: &std::sync::Arc<dyn crate::body::BodySetup>| total > 0.0 && b.compliance() / total >= MIN_COMPLIANCE_SHARE;
    if let Some(side) = ["A", "B"]
        .iter()
        .zip(bodies)
        .find_map(|(side, b)| (b.idealises_as_half_plane() && matters(b)).then_some(side))
    {
        let e = half_space_error(bodies, est);
        let worst = e.shear.map_or(e.pressure, |q| q.max(e.pressure));
        if worst > MAX_HALF_SPACE_ERROR {
            let remedy = if bodies.iter().all(|b| b.has_true_geometry_model()) {
                "model the bodies with `model: bem` (docs/choosing-a-model.md)"
            } else {
                "the true-geometry model (bem) is elastic only, so a viscoelastic body keeps this error \
                 (docs/viscoelastic.md)"
            };
            out.push(format!(
                "body {side} is a half-space, which assumes a contact much smaller than the radii: here \
                 ({}) its estimated error against the true geometry is {:.1} % of p0 in pressure{}; {remedy}",
                e.basis,
                100.0 * e.pressure,
                e.shear
                    .map_or(String::new(), |q| format!(", {:.1} % of μp0 in shear", 100.0 * q))
            ));
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::bem::BoundaryCondition;
    use crate::body::half_space::setup::HalfSpaceSetup;
    use crate::body::rigid::RigidSetup;
    use crate::material::Elastic;
    use crate::mesh::LoadedMesh;
    use crate::scene::BemSetup;
    use std::sync::Arc;

    fn estimates(p0: f64, a_over_r: f64) -> Estimates {
        Estimates {
            e_star: 1.0,
            dundurs_beta: 0.0,
            effective_radius: 50.0,
            normal_force: 1.0,
            hertz_half_width: 50.0 * a_over_r,
            hertz_peak_pressure: p0,
            scales_from: None,
            half_width_over_radius: a_over_r,
            carter_stick_width: None,
            grid_half_length: 1.0,
            grid_spacing: 0.1,
        }
    }

    fn half_spaces() -> BodySetups {
        let steel = Elastic::new(210_000.0, 0.3);
        [
            Arc::new(HalfSpaceSetup {
                material: steel,
                radius: 100.0,
            }),
            Arc::new(HalfSpaceSetup {
                material: steel,
                radius: 100.0,
            }),
        ]
    }

    /// Carter's steel rollers (p0 = 1154 N/mm², a/R = 0.02) pass; the same with E = 210 N/mm²
    /// (p0/E = 0.17, a/R = 0.63) is warned twice for small strain and once for the half-space.
    #[test]
    fn small_strain_and_the_half_space_are_warned_beyond_their_validity() {
        assert!(warnings(&half_spaces(), &estimates(1154.0, 0.02), None).is_empty());
        let soft = [0, 1].map(|_| -> Arc<dyn crate::body::BodySetup> {
            Arc::new(HalfSpaceSetup {
                material: Elastic::new(210.0, 0.3),
                radius: 100.0,
            })
        });
        let w = warnings(&soft, &estimates(36.5, 0.63), None);
        assert_eq!(w.len(), 3, "{w:?}");
        assert!(w[0].contains("body A") && w[0].contains("small strain"));
        assert!(w[2].contains("half-space") && w[2].contains("a/R = 6.300e-1"));
    }

    /// After solving, the solved peak pressure decides: a Hertz estimate of p0/E = 0.03 passes
    /// before the solve, a solved p_max twice that (a thin cover's stiffer contact) is warned.
    #[test]
    fn the_solved_peak_pressure_decides_small_strain() {
        let soft = [0, 1].map(|_| -> Arc<dyn crate::body::BodySetup> {
            Arc::new(HalfSpaceSetup {
                material: Elastic::new(1000.0, 0.3),
                radius: 100.0,
            })
        });
        assert!(warnings(&soft, &estimates(30.0, 0.005), None).is_empty());
        let w = warnings(&soft, &estimates(30.0, 0.005), Some(60.0));
        assert_eq!(w.len(), 2, "{w:?}");
        assert!(w[0].contains("solved peak pressure p_max = 6.0000e1"), "{w:?}");
    }

    /// A BEM body meshed with 2-node elements is warned; a rigid partner is not.
    #[test]
    fn first_order_bem_meshes_are_warned() {
        let path = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/data/msh/square_linear.msh");
        let (mesh, notices) = crate::mesh::load(&path).unwrap();
        let mesh = LoadedMesh::new(path, mesh, notices, "bottom").unwrap();
        let conditions = vec![("bottom".into(), BoundaryCondition::Contact)];
        let linear: Arc<dyn crate::body::BodySetup> = Arc::new(BemSetup {
            radius: f64::INFINITY,
            ..BemSetup::on_start_mesh(
                mesh,
                Elastic::new(210_000.0, 0.3),
                "bottom".into(),
                conditions,
                None,
                None,
            )
        });
        let bodies: BodySetups = [Arc::new(RigidSetup { radius: 100.0 }), linear];
        let w = warnings(&bodies, &estimates(100.0, 0.01), None);
        assert_eq!(w.len(), 1, "{w:?}");
        assert!(w[0].starts_with("body B:") && w[0].contains("first-order"), "{}", w[0]);
    }
}
