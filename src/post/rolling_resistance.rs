//! Rolling resistance and the contact's asymmetry: what a rate-dependent body (viscoelastic)
//! costs to roll.
//!
//! With the pressure p(x) on the common tangent (x from the line of centres), its resultant P
//! acts at the pressure centre x_p = ∫ p x dx / P. In steady rolling the material flows through
//! the contact at V while the gap stays closed, so the surfaces' relative normal velocity at x is
//! V·h0′(x) (h0 the undeformed gap of the bodies' exact profiles) and the pressure does the work
//! P_d = V ∫ p h0′ dx on them per unit length and time: the power the bodies dissipate (zero for
//! a symmetric pressure), the rolling-resistance force
//!
//! ```text
//! F_r = P_d / V = ∫ p h0′ dx,     coefficient F_r/P
//! ```
//!
//! (Johnson, *Contact Mechanics* §8.2; for a rigid cylinder on a flat: the horizontal force that
//! rolls it at zero traction, Hunter 1961). For parabolic profiles h0′ = x/R* and F_r is the
//! familiar P·x_p/R* (1/R* = 1/R_A + 1/R_B), the moment P·x_p over the effective radius; for the
//! circles rollbem models it differs from that by a relative (a/R)², 0.2–0.6 % on the covered
//! rollers of cases/, which is why the exact slope is integrated. x_p and F_r are positive
//! towards the leading edge, where a viscoelastic body's pressure leans. The tangential
//! traction's own dissipation (the creepage's work Q·ξ·V) is not part of it.

use crate::contact::GAP_SLOPE_POINTS;
use crate::grid::ContactGrid;
use serde::Serialize;

/// summary.json's `rolling_resistance`: the asymmetry of the pressure and its cost.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct RollingResistance {
    /// Contact end on the leading side (where the material enters) [length].
    pub leading_edge: f64,
    /// Contact end on the trailing side [length].
    pub trailing_edge: f64,
    /// Pressure centre x_p = ∫ p x dx / P towards the leading edge [length] (0 for a
    /// symmetric pressure).
    pub pressure_centre: f64,
    /// Resistance moment per unit length P·x_p [force·length/length].
    pub moment: f64,
    /// Rolling-resistance force F_r = ∫ p h0′ dx with the exact profiles' slope (P·x_p/R* for
    /// parabolic ones) [force/length].
    pub force: f64,
    /// F_r/P [-].
    pub coefficient: f64,
    /// Rolling speed V [length/time] of the case (null when it gives none).
    pub speed: Option<f64>,
    /// Power V ∫ p h0′ dx = F_r·V the bodies dissipate per unit length of the rollers
    /// [force/length · length/time] (null without a speed).
    pub dissipated_power: Option<f64>,
}

/// The rolling resistance of the nodal pressure `pressure` on `grid`, for a contact whose
/// leading edge lies at the sign `leading` (+1: at +x) of x, the gap's slope `gap_slope` [-] at
/// the points of [`ContactGrid::gauss_points`]`(`[`GAP_SLOPE_POINTS`]`)` and speed `speed`; None
/// when nothing is in contact.
pub fn rolling_resistance(
    grid: &ContactGrid,
    pressure: &[f64],
    extent: Option<[f64; 2]>,
    leading: f64,
    gap_slope: &[f64],
    speed: Option<f64>,
) -> Option<RollingResistance> {
    let [x0, x1] = extent?;
    // p is at most quadratic per element and h0′ within (x/R)⁴ of cubic: four Gauss points
    // integrate p, p·x and p·h0′ to round-off.
    let points = grid.gauss_points(GAP_SLOPE_POINTS);
    let (mut force, mut moment, mut work) = (0.0, 0.0, 0.0);
    for (&(x, w), slope) in points.iter().zip(gap_slope) {
        let p = grid.interpolate(pressure, x) * w;
        force += p;
        moment += p * x;
        work += p * slope;
    }
    if force <= 0.0 {
        return None;
    }
    let pressure_centre = leading * moment / force;
    let resistance = leading * work;
    Some(RollingResistance {
        leading_edge: if leading > 0.0 { x1 } else { x0 },
        trailing_edge: if leading > 0.0 { x0 } else { x1 },
        pressure_centre,
        moment: force * pressure_centre,
        force: resistance,
        coefficient: resistance / force,
        speed,
        dissipated_power: speed.map(|v| resistance * v),
    })
}
