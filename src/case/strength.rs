//! The case keys of a strength assessment: `materials.NAME.yield` and `output.strength`.

use serde::{Deserialize, Serialize};

/// The keys under `materials.NAME.yield`: exactly one of `shear` (the shear yield stress k,
/// used as given by either criterion) and `tensile` (the uniaxial yield stress Y: k = Y/√3 for
/// von Mises, Y/2 for Tresca).
#[derive(Debug, Clone, Copy, Deserialize, Serialize)]
#[serde(deny_unknown_fields)]
pub struct YieldSpec {
    /// Shear yield stress k > 0 [stress].
    #[serde(default)]
    pub shear: Option<f64>,
    /// Uniaxial (tensile) yield stress Y > 0 [stress].
    #[serde(default)]
    pub tensile: Option<f64>,
}

/// `output.strength`: first yield and the shakedown limit of steady rolling of each body
/// from its interior stresses under the solved tractions (docs/strength.md).
#[derive(Debug, Clone, PartialEq, Deserialize, Serialize)]
#[serde(deny_unknown_fields)]
pub struct StrengthSpec {
    /// `von_mises` or `tresca`. Default = von_mises.
    #[serde(default)]
    pub criterion: crate::material::YieldCriterion,
    /// The bodies to assess, `[A]`, `[B]` or `[A, B]`. Default = every body whose material
    /// has a yield stress.
    #[serde(default)]
    pub bodies: Option<Vec<String>>,
    /// [nx, nz]: points of the interior grid along the surface and in depth, over 4 contact
    /// half-widths × 2 half-widths below the contact. Default = [201, 100].
    #[serde(default = "default_strength_grid")]
    pub grid: [usize; 2],
}

fn default_strength_grid() -> [usize; 2] {
    [201, 100]
}
