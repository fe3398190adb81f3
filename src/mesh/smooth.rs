//! The smooth curve under a mesh file's contact group, on which an error-controlled grid's cuts
//! place their new nodes ([`super::cuts::cut_along_grid_on`]).
//!
//! Each quadratic element of a mesh file is the parabola through its three nodes; where the
//! nodes lie on a circle, two neighbouring parabolas meet at their common node with a slope
//! jump of order θ³ (θ the element's half angle), which the original mesh's own collocation
//! hardly sees but a grid cut many times finer does: the kink stays at the user's element ends
//! and the tractions show a step there that refining the grid does not remove. A body that
//! rollbem generated (`geometry:`) places its cuts on its exact circle; a mesh file's contact
//! group whose nodes all lie on one circle gets the same treatment with the circle fitted to
//! them by least squares ([`contact_curve`]). Where the nodes lie on no circle the cuts follow
//! each element's quadratic as before, and [`ContactCurve::Kinked`] measures the slope jumps
//! that leaves, for a notice to the user.

use super::cuts::Circle;
use super::geometry::ElementGeometry;
use super::LoadedMesh;
use std::collections::HashMap;

/// Largest distance of a contact node from the fitted circle, as a fraction of the chord sag
/// h²/(8R) of the group's shortest element, for the group to count as that circle. Moving the
/// nodes onto the circle by δ changes each element's curvature (8·sag/h² for its parabola) by
/// at most δ/sag relative, which a conformal contact amplifies by R/ΔR in the gap's curvature
/// (50 for the roller R 30 in the bore R 30.6 of tests/validation/smooth_cuts.rs): 1e-6 keeps
/// that at 5e-5 or less, below the grid tolerances such runs ask for (1e-4 and up), while a Gmsh
/// file's round-off (5e-16 R, i.e. 1e-11 to 3e-8 of the sag in every shipped mesh) passes by a
/// wide margin. A file written with fewer digits that misses it is cut as before, with the
/// notice of [`kink_notice`].
pub const CIRCLE_FIT_TOLERANCE: f64 = 1e-6;

/// Slope jump [rad] between neighbouring contact elements below which the group counts as
/// smooth (a straight face, whose quadratics are one line: round-off of a mesh file).
pub const SMOOTH_SLOPE_JUMP: f64 = 1e-9;

/// What lies under a mesh's contact group, as far as its cuts are concerned.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum ContactCurve {
    /// Every contact node within [`CIRCLE_FIT_TOLERANCE`] of this circle (fitted to them by
    /// least squares): the cuts place their new nodes on it.
    Circle {
        /// The fitted circle [length].
        circle: Circle,
        /// Largest distance of a contact node from it [length].
        residual: f64,
    },
    /// Neighbouring elements meet without a kink (slope jumps ≤ [`SMOOTH_SLOPE_JUMP`]: a
    /// straight face): the elements' own quadratics are the smooth curve.
    Smooth,
    /// Neither: the cuts follow each element's quadratic and keep the slope jumps at the
    /// element ends.
    Kinked {
        /// Largest slope jump between two neighbouring contact elements at their common node
        /// [rad].
        slope_jump: f64,
        /// That node [length].
        at: [f64; 2],
        /// Largest distance of a contact node from the best-fit circle [length] (None when the
        /// fit has no circle: a nearly straight group).
        residual: Option<f64>,
    },
}

/// The curve under `loaded`'s contact group (module docs): its fitted circle when every
/// contact node lies on it within [`CIRCLE_FIT_TOLERANCE`] of the shortest element's sag, else
/// smooth or kinked by the largest slope jump between its elements.
pub fn contact_curve(loaded: &LoadedMesh) -> ContactCurve {
    let fit = loaded.contact_circle().map(|(centre, radius)| {
        let nodes: Vec<[f64; 2]> = loaded.contact_nodes().collect();
        let circle = refined_fit(&nodes, Circle { centre, radius });
        let residual = nodes
            .iter()
            .map(|p| (distance(*p, circle.centre) - circle.radius).abs())
            .fold(0.0, f64::max);
        (circle, residual)
    });
    if let Some((circle, residual)) = fit {
        let shortest = loaded
            .contact_elements()
            .map(|g| distance(g.nodes[0], g.nodes[1]))
            .fold(f64::INFINITY, f64::min);
        let sag = shortest * shortest / (8.0 * circle.radius);
        if residual <= CIRCLE_FIT_TOLERANCE * sag {
            return ContactCurve::Circle { circle, residual };
        }
    }
    match largest_slope_jump(loaded) {
        Some((slope_jump, at)) if slope_jump > SMOOTH_SLOPE_JUMP => ContactCurve::Kinked {
            slope_jump,
            at,
            residual: fit.map(|f| f.1),
        },
        _ => ContactCurve::Smooth,
    }
}

/// The geometric least-squares circle min Σ (|p − c| − r)² from `start` (the algebraic Kåsa
/// fit of [`LoadedMesh::contact_circle`]): Gauss–Newton steps until they stop changing it.
/// The algebraic fit is exact for exact data but loses digits through its normal equations
/// on a short arc; the geometric one brings the fitted circle to the nodes' round-off.
fn refined_fit(points: &[[f64; 2]], start: Circle) -> Circle {
    let mut c = start;
    for _ in 0..20 {
        let mut a = nalgebra::Matrix3::<f64>::zeros();
        let mut b = nalgebra::Vector3::<f64>::zeros();
        for p in points {
            let d = distance(*p, c.centre);
            if d == 0.0 {
                return start;
            }
            // Residual |p − c| − r and its gradient in (cx, cy, r).
            let row = nalgebra::Vector3::new((c.centre[0] - p[0]) / d, (c.centre[1] - p[1]) / d, -1.0);
            a += row * row.transpose();
            b -= row * (d - c.radius);
        }
        let Some(step) = a.lu().solve(&b) else {
            return c;
        };
        c = Circle {
            centre: [c.centre[0] + step[0], c.centre[1] + step[1]],
            radius: c.radius + step[2],
        };
        if step.norm() <= 1e-15 * c.radius {
            break;
        }
    }
    if c.radius.is_finite() && c.radius > 0.0 {
        c
    } else {
        start
    }
}

/// The largest slope jump [rad] between two contact elements of `loaded` that share an end
/// node (the angle between the first's tangent at ξ = +1 and the second's at ξ = −1), and that
/// node; None when no two contact elements meet.
pub fn largest_slope_jump(loaded: &LoadedMesh) -> Option<(f64, [f64; 2])> {
    let mesh = &loaded.mesh;
    let contact: Vec<usize> = (0..mesh.elements.len())
        .filter(|&e| mesh.elements[e].group == loaded.contact_group)
        .collect();
    // The oriented loops walk every element from its node 0 to its node 1: the element that
    // starts at a node follows the one that ends there.
    let starting_at: HashMap<usize, usize> = contact.iter().map(|&e| (mesh.elements[e].nodes[0], e)).collect();
    contact
        .iter()
        .filter_map(|&e| {
            let node = mesh.elements[e].nodes[1];
            let next = *starting_at.get(&node)?;
            let t0 = ElementGeometry::from_mesh(mesh, e).tangent(1.0);
            let t1 = ElementGeometry::from_mesh(mesh, next).tangent(-1.0);
            let cross = t0[0] * t1[1] - t0[1] * t1[0];
            let dot = t0[0] * t1[0] + t0[1] * t1[1];
            Some((cross.atan2(dot).abs(), mesh.nodes[node]))
        })
        .max_by(|a, b| a.0.total_cmp(&b.0))
}

/// The notice for a contact group whose cuts keep the elements' kinks ([`ContactCurve::Kinked`]),
/// naming the mesh and group, the largest slope jump and where it is, and what to do; None for
/// a circle or a smooth group. `unit` is the case's length unit.
pub fn kink_notice(loaded: &LoadedMesh, group: &str, unit: &str) -> Option<String> {
    let ContactCurve::Kinked {
        slope_jump,
        at,
        residual,
    } = contact_curve(loaded)
    else {
        return None;
    };
    let fit = residual.map_or_else(
        || "no circle fits them".to_string(),
        |r| format!("they lie up to {r:.2e} {unit} off the best-fit circle"),
    );
    Some(format!(
        "{}: the nodes of contact group `{group}` lie on no one circle ({fit}), so the cuts of the \
         error-controlled grid follow each element's own quadratic and keep its slope jumps at the \
         element ends: largest {slope_jump:.2e} rad at ({:.6}, {:.6}); the error estimate does not see \
         this geometric error (mesh the group finer to shrink it)",
        loaded.path.display(),
        at[0],
        at[1]
    ))
}

/// Distance between two points [length].
fn distance(p: [f64; 2], q: [f64; 2]) -> f64 {
    (p[0] - q[0]).hypot(p[1] - q[1])
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::mesh::validate_and_orient;

    /// The mesh `name` of meshes/, oriented, with its group `contact`.
    fn shipped(name: &str) -> LoadedMesh {
        let path = std::path::Path::new(env!("CARGO_MANIFEST_DIR"))
            .join("meshes")
            .join(name);
        let (mesh, _) = crate::mesh::load(&path).unwrap();
        LoadedMesh::new(path, mesh, Vec::new(), "contact").unwrap()
    }

    /// The shipped Gmsh rollers and rings are their circles: every contact node within 1e-14 R
    /// of the fit, whose radius is the .geo's within 1e-10 (a short arc fixes its radius only
    /// to the nodes' round-off over the square of its angle: 3e-12 for fig14's roller, whose
    /// contact group spans 1°).
    #[test]
    fn shipped_circular_contact_groups_are_their_circles() {
        for (name, r) in [
            ("roller_r100_shaft10_A.msh", 100.0),
            ("roller_r150_shaft15_A.msh", 150.0),
            ("bore_a020_ring.msh", 50.0),
            ("bore_a001_roller.msh", 40.0),
            ("bore_c30_ring.msh", 30.6),
        ] {
            match contact_curve(&shipped(name)) {
                ContactCurve::Circle { circle, residual } => {
                    assert!((circle.radius - r).abs() < 1e-10 * r, "{name}: R {}", circle.radius);
                    assert!(residual < 1e-14 * r, "{name}: residual {residual:e}");
                }
                other => panic!("{name}: {other:?}"),
            }
        }
    }

    /// A flat block's contact face is smooth (no circle, no kink).
    #[test]
    fn a_flat_face_is_smooth() {
        assert_eq!(contact_curve(&shipped("halfspace_block_A.msh")), ContactCurve::Smooth);
        assert!(kink_notice(&shipped("halfspace_block_A.msh"), "contact", "mm").is_none());
    }

    /// An ellipse (semi-axes 100 and 50) of 64 quadratic elements, the 8 at its bottom the
    /// contact: no circle fits them; the largest slope jump is the quadratics' own (positive,
    /// small) and the notice names it.
    #[test]
    fn an_ellipse_is_kinked_and_says_so() {
        use crate::mesh::{BoundaryElement, BoundaryMesh, PhysicalGroup};
        let n = 64;
        let at = |k: f64| {
            let t = -0.5 * std::f64::consts::PI + 2.0 * std::f64::consts::PI * k / n as f64;
            [100.0 * t.cos(), 50.0 + 50.0 * t.sin()]
        };
        let mut nodes: Vec<[f64; 2]> = (0..n).map(|k| at(k as f64)).collect();
        let elements = (0..n)
            .map(|k| {
                nodes.push(at(k as f64 + 0.5));
                let contact = !(4..n - 4).contains(&k);
                BoundaryElement {
                    nodes: vec![k, (k + 1) % n, nodes.len() - 1],
                    group: usize::from(!contact),
                }
            })
            .collect();
        let groups = [("contact", 1), ("free", 2)].map(|(name, tag)| PhysicalGroup { tag, name: name.into() });
        let mut mesh = BoundaryMesh::new(nodes, elements, groups.to_vec(), "ellipse");
        validate_and_orient(&mut mesh).unwrap();
        let loaded = LoadedMesh::new("ellipse", mesh, Vec::new(), "contact").unwrap();
        match contact_curve(&loaded) {
            ContactCurve::Kinked {
                slope_jump, residual, ..
            } => {
                assert!(
                    slope_jump > SMOOTH_SLOPE_JUMP && slope_jump < 1e-2,
                    "jump {slope_jump:e}"
                );
                assert!(residual.unwrap() > 1e-3, "residual {residual:?}");
            }
            other => panic!("{other:?}"),
        }
        let notice = kink_notice(&loaded, "contact", "mm").unwrap();
        assert!(
            notice.contains("contact group `contact`") && notice.contains("rad"),
            "{notice}"
        );
    }
}
