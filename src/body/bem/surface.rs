//! The slope of a BEM body's contact surface that the contact frame reads
//! ([`crate::scene::contact_frame`]): its element's, or its contact circle's where the element's
//! own slope is round-off.

use super::setup::BemSetup;
use crate::mesh::geometry::ElementGeometry;

impl BemSetup {
    /// The slope angle [rad] of the contact surface at `point` on `element` (at ξ = `xi`), whose
    /// own tangent there makes `on_element` with +x: the contact circle's where the body has one
    /// and the two differ by no more than the round-off of the element's nodes
    /// ([`crate::mesh::geometry::ElementGeometry::tangent_angle_round_off`]), else the
    /// element's. A short element cut along a fine grid has its nodes on the circle to a few
    /// ulps of the circle's coordinates (src/mesh/cuts.rs), so its tangent, from differences of
    /// nodes 1e-6 mm apart, carries a noise of ~1e-8 rad (~1e-6 rad at 1e-8 mm) that is nothing
    /// but round-off; the contact frame ([`crate::scene::contact_frame`]) turned with it node to
    /// node and stepped the normal gap by tan ψ·w (w ≈ 2e-2 mm on the generated bore of
    /// tests/data/bore_c30_tractive.yaml), which the contact solver resolved as a pressure
    /// ripple of 0.15 p0 at 1e-6 mm and 15 p0 at 6e-8 mm (tests/validation/stand_in_surface.rs).
    /// Where the element differs from the circle by more (the kinks of a start mesh's
    /// quadratics, 1.4e-6 rad at the ends of 1 mm elements; a mesh file's non-circular contact
    /// surface), the element's slope is kept: the choice moves the slope by no more than its
    /// own round-off.
    pub(super) fn slope_angle_at(&self, element: &ElementGeometry, xi: f64, point: [f64; 2], on_element: f64) -> f64 {
        let Some(circle) = self.contact_circle else {
            return on_element;
        };
        let Some(on_circle) = circle.slope_angle_at(point) else {
            return on_element;
        };
        let node_error = circle
            .placement_round_off()
            .max(4.0 * f64::EPSILON * element.nodes.iter().flatten().fold(0.0_f64, |m, v| m.max(v.abs())));
        if (on_circle - on_element).abs() <= element.tangent_angle_round_off(xi, node_error) {
            on_circle
        } else {
            on_element
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::adapt::cells::{Action, DyadicGrid};
    use crate::body::bem::setup::fig14_roller_in;
    use crate::body::setup::BodySetup;
    use crate::body::Side;
    use crate::material::Elastic;
    use crate::mesh::cuts::Circle;

    /// On a grid halved 28 times towards a point inside a contact element, the roller cut along
    /// it (its new contact nodes on its fitted circle, to round-off) has tiny elements whose own
    /// slopes scatter about the circle's by the nodes' round-off over their lengths; the surface
    /// takes the circle's slope there, and the element's where the two differ by more than that
    /// round-off (a circle the mesh does not lie on).
    #[test]
    fn a_tiny_cut_elements_slope_is_its_circles() {
        use crate::mesh::smooth::{contact_curve, ContactCurve};
        let plain = fig14_roller_in(Elastic::new(210_000.0, 0.3));
        let ContactCurve::Circle { circle, .. } = contact_curve(&plain.mesh) else {
            panic!("the roller's contact group is a circle");
        };
        let setup = BemSetup {
            contact_circle: Some(circle),
            ..plain
        };
        let start = DyadicGrid::new(&setup.mesh.contact_grid());
        let k = start.len() / 2;
        let [lo, hi] = [start.root().edges[k], start.root().edges[k + 1]];
        let point = lo + 0.3 * (hi - lo);
        let mut action = vec![Action::Keep; start.len()];
        action[k] = Action::GradeTowards(point, 28);
        let grid = start.refined(&action).grid();
        let cut = setup.followed(&grid);
        let (mut noise, mut tiny) = (0.0_f64, 0);
        for &x in grid.nodes.iter().filter(|&&x| (x - point).abs() < 1e-6) {
            let (element, xi) = cut.mesh.contact_element_at(x).expect("on the contact");
            let (y, slope) = cut.mesh.surface_at(x).expect("on the contact");
            let on_circle = circle.slope_angle_at([x, y]).expect("on the circle");
            assert!(element.jacobian(xi) < 1e-6, "a tiny element at x = {x}");
            let at = cut.surface_at(x, Side::A).expect("on the contact");
            assert_eq!(at.slope_angle.to_bits(), on_circle.to_bits(), "x = {x}");
            noise = noise.max((slope.atan() - on_circle).abs());
            tiny += 1;
        }
        // The check can fail: the cut elements' own slopes are off the circle's by their
        // round-off (measured up to 1.2e-4 rad).
        assert!(
            tiny > 10 && noise > 1e-9,
            "{tiny} nodes, element slopes within {noise:e} rad"
        );
        // A circle 1e-6 larger, which the mesh does not lie on (its slopes ~1e-8 rad off the
        // elements' at the contact's ends): the elements' own slopes are kept, to the bit.
        let off = BemSetup {
            contact_circle: Some(Circle {
                radius: circle.radius * (1.0 + 1e-6),
                ..circle
            }),
            ..setup.clone()
        };
        for &x in &grid.edges[..grid.n_elements()] {
            let (_, slope) = off.mesh.surface_at(x).expect("on the contact");
            let at = off.surface_at(x, Side::A).expect("on the contact");
            if x.abs() > 0.1 {
                assert_eq!(at.slope_angle.to_bits(), slope.atan().to_bits(), "x = {x}");
            }
        }
    }
}
