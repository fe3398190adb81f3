//! Rolling resistance and the contact's asymmetry: what a rate-dependent body (viscoelastic)
//! costs to roll.
//!
//! With the pressure p(x) on the common tangent (x from the line of centres), its resultant P
//! acts at the pressure centre x_p = ∫ p x dx / P. Turning at ω_b = V/R_b, body b must be
//! driven by the moment P·x_p against that couple, so rolling the pair costs the power
//! P·x_p·V·(1/R_A + 1/R_B) = F_r·V with the rolling-resistance force
//!
//! ```text
//! F_r = P·x_p / R*,   1/R* = 1/R_A + 1/R_B,     coefficient F_r/P = x_p/R*
//! ```
//!
//! (Johnson, *Contact Mechanics* §8.2; for a rigid cylinder on a flat: the horizontal force that
//! rolls it at zero traction, Hunter 1961). x_p is measured positive towards the leading edge,
//! where a viscoelastic body's pressure leans, so a resistance is positive. The tangential
//! traction's own dissipation (the creepage's work Q·ξ·V) is not part of it.

use crate::grid::ContactGrid;
use crate::quadrature::gauss_legendre;
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
    /// Rolling-resistance force F_r = P·x_p/R* [force/length].
    pub force: f64,
    /// F_r/P [-].
    pub coefficient: f64,
    /// Rolling speed V [length/time] of the case (null when it gives none).
    pub speed: Option<f64>,
    /// Power F_r·V dissipated per unit length of the rollers [force/length · length/time]
    /// (null without a speed).
    pub dissipated_power: Option<f64>,
}

/// The rolling resistance of the nodal pressure `pressure` on `grid`, for a contact whose
/// leading edge lies at the sign `leading` (+1: at +x) of x, effective radius `radius` R*
/// [length] and speed `speed`; None when nothing is in contact.
pub fn rolling_resistance(
    grid: &ContactGrid,
    pressure: &[f64],
    extent: Option<[f64; 2]>,
    leading: f64,
    radius: f64,
    speed: Option<f64>,
) -> Option<RollingResistance> {
    let [x0, x1] = extent?;
    // p is at most quadratic per element: three Gauss points integrate p·x exactly.
    let (gx, gw) = gauss_legendre(3);
    let (mut force, mut moment) = (0.0, 0.0);
    for e in 0..grid.n_elements() {
        let (a, b) = (grid.edges[e], grid.edges[e + 1]);
        for (xi, w) in gx.iter().zip(&gw) {
            let s = 0.5 * (a + b) + 0.5 * (b - a) * xi;
            let p = grid.interpolate(pressure, s) * 0.5 * (b - a) * w;
            force += p;
            moment += p * s;
        }
    }
    if force <= 0.0 {
        return None;
    }
    let pressure_centre = leading * moment / force;
    let moment = force * pressure_centre;
    let resistance = moment / radius;
    Some(RollingResistance {
        leading_edge: if leading > 0.0 { x1 } else { x0 },
        trailing_edge: if leading > 0.0 { x0 } else { x1 },
        pressure_centre,
        moment,
        force: resistance,
        coefficient: pressure_centre / radius,
        speed,
        dissipated_power: speed.map(|v| resistance * v),
    })
}
