//! What a body model can be asked for before any body is built: the answers the case's checks
//! need of a `model:` (which materials it takes, whether it has an interior, whether it is a
//! boundary element model). Each model declares its own in its module, so that the checks ask
//! these questions instead of naming kinds, and a new model answers them where it is written.

/// The capabilities of one body model, as the checks of a case ask them.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Capabilities {
    /// The model's name under `model:` in a case (`half_space`, `layer`, `rigid`, `bem`).
    pub name: &'static str,
    /// Whether the body deforms: false for a rigid body, which has no material, no stresses
    /// and cannot be paired with another rigid body.
    pub deforms: bool,
    /// Whether the model takes a viscoelastic material (a standard linear solid): only models
    /// with aged kernels do; the others need an elastic one.
    pub accepts_viscoelastic: bool,
    /// Whether the model gives stresses and displacements inside the body
    /// (`output.interior`, `output.strength`), not only its surface.
    pub interior_fields: bool,
    /// Whether the body is a boundary element model: its contact grid is its mesh's contact
    /// elements (discontinuous quadratic only), and its solution breaks down under a
    /// tangential force many times the normal load.
    pub boundary_elements: bool,
}
