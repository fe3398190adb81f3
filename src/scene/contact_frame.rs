//! The contact's own directions at the grid's nodes, from the two bodies' true geometry
//! ([`crate::contact::frame`] says how the contact problem uses them).
//!
//! Each body with a geometry (a `bem` body's mesh, a rigid circle) gives at x its surface's
//! slope angle θ_b, its profile h_b and its signed radius R_b (about which it turns). The
//! interface's tangent angle is the common normal of the deformed surfaces in linear theory:
//! each body takes a share of the gap proportional to its compliance c_b = (1 − ν_b²)/E_b, so
//!
//! ```text
//! ψ = (c_B θ_A + c_A θ_B) / (c_A + c_B)      (a rigid body's own normal when the other deforms)
//! ```
//!
//! (docs/conformal.md §3, the series' `CommonNormal`: ψ = θ + w(θ1 − θ), w = c2/(c1 + c2)).
//! For two equal rollers of one material ψ = 0 by symmetry. A half-space body is flat in its
//! model, so a scene with one keeps the global axes.

use super::registry::BodySetups;
use crate::body::Side;
pub use crate::body::SurfaceAt;
use crate::contact::{ContactFrame, TractionAxes};
use crate::grid::ContactGrid;

/// The contact frame at the nodes of `grid` for the two bodies (module docs); the global axes
/// when `axes` asks for them or a body has no geometry (a half-space).
pub fn contact_frame(bodies: &BodySetups, grid: &ContactGrid, axes: TractionAxes) -> ContactFrame {
    let m = grid.n_nodes();
    if axes == TractionAxes::Global {
        return ContactFrame::global_axes(m);
    }
    let (ca, cb) = (bodies[0].compliance(), bodies[1].compliance());
    let mut frame = ContactFrame::global_axes(m);
    for (i, &x) in grid.nodes.iter().enumerate() {
        let (Some(a), Some(b)) = (bodies[0].surface_at(x, Side::A), bodies[1].surface_at(x, Side::B)) else {
            return ContactFrame::global_axes(m);
        };
        let psi = (cb * a.slope_angle + ca * b.slope_angle) / (ca + cb);
        frame.normal_angle[i] = psi;
        frame.arc_scale[0][i] = a.slope_angle.cos() / psi.cos();
        frame.arc_scale[1][i] = b.slope_angle.cos() / psi.cos();
        frame.rigid_slip[i] = a.speed_ratio() - b.speed_ratio();
    }
    frame
}
