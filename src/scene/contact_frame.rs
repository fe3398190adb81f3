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

use super::body_setup::BodySetup;
use crate::body::{circle_profile, circle_profile_slope, Side};
use crate::contact::{ContactFrame, TractionAxes};
use crate::grid::ContactGrid;

/// A body's surface at x: slope angle θ [rad], profile h [length] and the signed radius it
/// turns about [length] (infinite for a flat, translating body).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SurfaceAt {
    /// Angle of the surface's tangent from +x [rad].
    pub slope_angle: f64,
    /// Distance from the common tangent, ≥ 0 convex, ≤ 0 concave [length].
    pub profile: f64,
    /// Signed radius of rotation [length].
    pub radius: f64,
}

impl SurfaceAt {
    /// The x-speed of the surface's material relative to its speed at the contact's centre
    /// for a body turning about its centre: 1 − h/R [-].
    pub fn speed_ratio(&self) -> f64 {
        if self.radius.is_finite() {
            1.0 - self.profile / self.radius
        } else {
            1.0
        }
    }
}

impl BodySetup {
    /// The body's surface at x on `side`, None for a half-space (flat in its model).
    pub fn surface_at(&self, x: f64, side: Side) -> Option<SurfaceAt> {
        // y rises into A above the contact and falls into B below it.
        let up = side.sign();
        match self {
            BodySetup::HalfSpace { .. } => None,
            BodySetup::Rigid { radius } => Some(SurfaceAt {
                slope_angle: (up * circle_profile_slope(*radius, x)).atan(),
                profile: circle_profile(*radius, x),
                radius: *radius,
            }),
            BodySetup::Bem(b) => {
                let mesh = &b.mesh;
                let [x0, x1] = mesh.contact_range();
                let (y, slope) = mesh.surface_at(x.clamp(x0, x1))?;
                let touch = mesh.surface_at(0.0).map_or(y, |(y0, _)| y0);
                Some(SurfaceAt {
                    slope_angle: slope.atan(),
                    profile: (y - touch) * up,
                    radius: mesh.contact_radius(),
                })
            }
        }
    }

    /// Plane-strain compliance (1 − ν²)/E [1/stress], zero for a rigid body.
    pub fn compliance(&self) -> f64 {
        self.material().map_or(0.0, |m| m.plane_strain_compliance())
    }
}

/// The contact frame at the nodes of `grid` for the two bodies (module docs); the global axes
/// when `axes` asks for them or a body has no geometry (a half-space).
pub fn contact_frame(bodies: &[BodySetup; 2], grid: &ContactGrid, axes: TractionAxes) -> ContactFrame {
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
