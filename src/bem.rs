//! Plane-strain elastostatic boundary element method (direct BEM, collocation).
//!
//! The boundary displacement integral equation (Somigliana's identity at a boundary point,
//! Brebbia–Telles–Wrobel, *Boundary Element Techniques*, 1984, Eq. 3.56 / docs/references.md §9)
//!
//! ```text
//! c_ij(X) u_j(X) + CPV∫_Γ T*_ij(X, x) u_j(x) dΓ = ∫_Γ U*_ij(X, x) t_j(x) dΓ
//! ```
//!
//! is collocated at every field node X of a quadratic boundary mesh, giving H u = G t with H
//! (2N × 2N, dimensionless) and G (2N × 2N, length/stress). The modules follow the data flow:
//!
//! * [`kernel`] — Kelvin kernels U*, T*, their source derivatives, and the interior stress
//!   kernels D, S (all valid for ν = 0.5);
//! * [`element`] — quadratic/linear geometry, continuous / discontinuous / partially
//!   discontinuous quadratic field interpolation;
//! * [`integrate`] — regular, nearly singular (adaptive subdivision) and singular (log-weighted
//!   Gauss) element integrals;
//! * [`discretise`] — field nodes: where elements share nodes and where they do not (corners,
//!   changes of boundary condition, contact groups);
//! * [`hypersingular`] — displacement gradient at boundary points (HBEM, paper Eq. 79) from the
//!   solved boundary values;
//! * [`assemble`] — H and G (parallel over collocation points), boundary conditions, solve;
//! * [`condense`](mod@condense) — flexibility at the contact nodes (global axes), the HBEM
//!   surface strain there, and the boundary solution under given contact tractions (the body
//!   model built on it is `crate::body::bem`);
//! * [`reuse`] — the far-field block of H and G integrated once and shared by the cut meshes of
//!   an error-controlled grid's passes;
//! * [`somigliana`] — interior displacement and stress from the boundary solution (kernels
//!   U*, T*, D, S).
//!
//! **Incompressible material (ν = 0.5).** The kernels stay finite, but the Kelvin displacement
//! field is then divergence-free, so ∮ U*_ij n_j dΓ = 0 around every closed loop: G annihilates
//! a uniform pressure on any loop. Consequences, both checked in `tests/bem/lame.rs`:
//! * on a loop whose displacements are all prescribed (a fixed shaft or core) the computed
//!   traction is determined only up to a uniform pressure c·n on that loop. Displacements
//!   everywhere (hence the contact flexibility), and the resultant force and moment on the loop,
//!   are unaffected; the pressure level on the core is not reliable;
//! * with tractions prescribed on two or more loops (a ring loaded on its bore and its outside)
//!   the displacement is not unique: the model refuses with
//!   [`BemError::IncompressibleTractionLoops`]. Use ν = 0.499 there (accuracy degrades like
//!   1/(1 − 2ν)).
//!
//! **Units and signs.** Lengths in the mesh's unit, tractions in the material's stress unit.
//! u is the displacement vector, t = σ·n the traction vector (force per unit boundary length per
//! unit thickness) on the boundary with n pointing out of the material; both in the global
//! (x, y) axes of the mesh.

pub mod assemble;
pub mod condense;
pub mod discretise;
pub mod element;
pub mod fundamental;
pub mod hypersingular;
pub mod integrate;
pub mod kernel;
pub mod reuse;
pub mod somigliana;

pub use assemble::{BemModel, BemOptions, BemSolution, Pin};
pub use condense::{condense, condense_reusing, factor_reusing, ContactFlexibility};
pub use discretise::{Discretisation, FieldNode};

use crate::mesh::MeshError;
use std::sync::Arc;

/// A vector field on the boundary, evaluated at a field node from its position [length] and its
/// unit outward normal; returns a displacement [length] or a traction [stress] in global axes.
pub type BoundaryFunction = Arc<dyn Fn([f64; 2], [f64; 2]) -> [f64; 2] + Send + Sync>;

/// What is prescribed on one component of the boundary data (global axes).
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Component {
    /// The displacement component [length]; the traction component is unknown.
    Displacement(f64),
    /// The traction component [stress]; the displacement component is unknown.
    Traction(f64),
}

/// Boundary condition of one physical group.
#[derive(Clone)]
pub enum BoundaryCondition {
    /// u = 0 (a rigid shaft or a bonded core).
    Fixed,
    /// t = 0.
    Free,
    /// Uniform displacement vector (u_x, u_y) [length].
    Displacement([f64; 2]),
    /// Uniform traction vector (t_x, t_y) [stress].
    Traction([f64; 2]),
    /// Normal pressure p [stress], positive compressive: t = −p n.
    Pressure(f64),
    /// One condition per global component (x, y), e.g. a symmetry plane x = 0:
    /// `[Displacement(0.0), Traction(0.0)]`.
    Components([Component; 2]),
    /// Displacement given as a function of (position, outward normal).
    DisplacementField(BoundaryFunction),
    /// Traction given as a function of (position, outward normal).
    TractionField(BoundaryFunction),
    /// The contact surface: discontinuous quadratic elements (González & Abascal §5) loaded by
    /// the contact tractions, which are unknown to the body. A plain [`BemModel::solve`] takes
    /// them as zero; [`condense()`] takes them as the unit loads of the flexibility.
    Contact,
}

impl std::fmt::Debug for BoundaryCondition {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            Self::Fixed => write!(f, "Fixed"),
            Self::Free => write!(f, "Free"),
            Self::Displacement(u) => write!(f, "Displacement({u:?})"),
            Self::Traction(t) => write!(f, "Traction({t:?})"),
            Self::Pressure(p) => write!(f, "Pressure({p})"),
            Self::Components(c) => write!(f, "Components({c:?})"),
            Self::DisplacementField(_) => write!(f, "DisplacementField(..)"),
            Self::TractionField(_) => write!(f, "TractionField(..)"),
            Self::Contact => write!(f, "Contact"),
        }
    }
}

impl BoundaryCondition {
    /// The data at a field node at `position` with outward `normal`, per global component.
    pub fn components(&self, position: [f64; 2], normal: [f64; 2]) -> [Component; 2] {
        use Component::{Displacement as D, Traction as T};
        match self {
            Self::Fixed => [D(0.0), D(0.0)],
            Self::Free | Self::Contact => [T(0.0), T(0.0)],
            Self::Displacement(u) => [D(u[0]), D(u[1])],
            Self::Traction(t) => [T(t[0]), T(t[1])],
            Self::Pressure(p) => [T(-p * normal[0]), T(-p * normal[1])],
            Self::Components(c) => *c,
            Self::DisplacementField(f) => {
                let u = f(position, normal);
                [D(u[0]), D(u[1])]
            }
            Self::TractionField(f) => {
                let t = f(position, normal);
                [T(t[0]), T(t[1])]
            }
        }
    }

    /// Whether the group uses fully discontinuous elements (contact groups).
    pub fn is_contact(&self) -> bool {
        matches!(self, Self::Contact)
    }
}

/// Everything that can stop a BEM model from being built or solved.
#[derive(Debug, thiserror::Error)]
pub enum BemError {
    /// The mesh is unusable.
    #[error(transparent)]
    Mesh(#[from] MeshError),
    /// The material constants are out of range.
    #[error("{path}: invalid material E = {young}, ν = {poisson}: E must be positive and ν in (−1, 0.5]")]
    InvalidMaterial {
        /// The mesh.
        path: String,
        /// Young's modulus.
        young: f64,
        /// Poisson's ratio.
        poisson: f64,
    },
    /// A physical group has no boundary condition.
    #[error(
        "{path}: physical group `{group}` has no boundary condition; give it one of fixed, free, \
         displacement, traction, pressure or contact (groups with conditions: {given})"
    )]
    MissingCondition {
        /// The mesh.
        path: String,
        /// The group without a condition.
        group: String,
        /// The groups that have one.
        given: String,
    },
    /// A group was given two boundary conditions.
    #[error("{path}: physical group `{group}` has more than one boundary condition")]
    DuplicateCondition {
        /// The mesh.
        path: String,
        /// The group.
        group: String,
    },
    /// No displacement is prescribed anywhere: the solution is defined up to a rigid motion.
    #[error(
        "{path}: no displacement is prescribed on any group, so the body can move as a rigid body; \
         fix a group (e.g. `shaft: fixed`) or prescribe a displacement"
    )]
    RigidBodyMotion {
        /// The mesh.
        path: String,
    },
    /// The linear system could not be solved accurately (typically an insufficient support).
    #[error(
        "{path}: the BEM system is singular or nearly so (smallest/largest LU pivot \
         {pivot_ratio:.1e}); check that the prescribed displacements prevent every rigid-body \
         motion (two translations and the rotation)"
    )]
    SingularSystem {
        /// The mesh.
        path: String,
        /// Smallest over largest pivot magnitude of the LU factorisation.
        pivot_ratio: f64,
    },
    /// ν = 0.5 with tractions prescribed on more than one boundary loop (see the module docs).
    #[error(
        "{path}: with ν = 0.5 the boundary displacement equation cannot tell a uniform pressure on \
         a closed loop from none, so a body with tractions on several loops ({loops}) has no \
         unique solution; prescribe the displacement on all but one loop (e.g. fix the shaft) \
         or use ν slightly below 0.5 (0.499: the error then grows like 1/(1 − 2ν))"
    )]
    IncompressibleTractionLoops {
        /// The mesh.
        path: String,
        /// The groups of each loop carrying tractions.
        loops: String,
    },
    /// A point constraint refers to a field node that does not exist.
    #[error("{path}: pin on field node {node}, but the model has {count} field nodes")]
    BadPin {
        /// The mesh.
        path: String,
        /// The node index given.
        node: usize,
        /// Number of field nodes.
        count: usize,
    },
    /// A boundary point for the displacement gradient that is not strictly inside an element.
    #[error(
        "{path}: the displacement gradient needs a point strictly inside an element (element < \
         {count}, −1 < ξ < 1), got element {element}, ξ = {xi}"
    )]
    BadGradientPoint {
        /// The mesh.
        path: String,
        /// The element index given.
        element: usize,
        /// The intrinsic coordinate given.
        xi: f64,
        /// Number of elements.
        count: usize,
    },
    /// The contact group does not match the contact grid.
    #[error("{path}: contact group `{group}` does not match the contact grid: {problem}")]
    ContactGridMismatch {
        /// The mesh.
        path: String,
        /// The contact group.
        group: String,
        /// What differs.
        problem: String,
    },
}

/// The boundary conditions of the roller on a rigid shaft of cases/fig14_true_geometry.yaml
/// (meshes/roller_r150_shaft15_A.msh: its surface free, its bore fixed, its contact group
/// loaded), which the tests of several modules build.
#[cfg(test)]
pub(crate) fn fixed_shaft_roller_conditions() -> Vec<(String, BoundaryCondition)> {
    vec![
        ("free".into(), BoundaryCondition::Free),
        ("shaft".into(), BoundaryCondition::Fixed),
        ("contact".into(), BoundaryCondition::Contact),
    ]
}
