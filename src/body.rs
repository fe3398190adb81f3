//! Body models: what one body offers the contact problem, and what it can show afterwards.
//!
//! A body model gives exactly one thing to the contact problem ([`BodyModel`]): its
//! [`Flexibility`] at the contact grid, plus its undeformed profile and (where it has one) an
//! operator for the surface strain used to re-check the slip. The contact solver never knows
//! which model it talks to. Post-processing asks the model, through [`BodyFields`], for what it
//! can show under the solved tractions ([`ContactLoad`]): its boundary
//! ([`BodyFields::boundary_field`]) and its interior fields ([`BodyFields::interior`]). A run
//! holds each body as a [`Body`], which is both.
//!
//! | model | file | flexibility | fields |
//! |---|---|---|---|
//! | `half_space` | [`half_space`] | closed-form half-plane integrals | Flamant superposition ([`flamant`]) |
//! | `bem` | [`bem`](mod@bem) | condensed BEM ([`crate::bem`]) | boundary solution, Somigliana |
//! | `rigid` | [`rigid`] | zero | none |
//! | `layer` | [`layer`] | half-plane integrals + the layer's Fourier remainder | none |
//!
//! plus two wrappers: [`transfer::Transferred`] (a body known on its own contact nodes, seen on
//! the common grid) and [`WithCircularProfile`] (the profile replaced by a circle).
//!
//! # Pair convention
//! All quantities are written so that the two bodies' contributions simply add:
//! * loads: the nodal pressure p ≥ 0 (compressive, acting on both bodies) and the shear q that
//!   B exerts on A, positive in +x (B receives −q);
//! * `h` is the body's normal surface displacement **into the body** (its share of the
//!   compression; the gap closes by h_A + h_B);
//! * `w` is the body's share of the relative tangential displacement w = u_xA − u_xB, i.e.
//!   w = u_xA for body A and w = −u_xB for body B.

pub mod bem;
pub mod flamant;
pub mod half_space;
pub mod kind;
pub mod layer;
pub mod pair_influence;
pub mod rigid;
pub mod run_caches;
pub mod scales;
pub mod setup;
pub mod transfer;
pub mod viscoelastic;

use crate::grid::ContactGrid;
use crate::interior::{InteriorOptions, InteriorSample, PlaneStress};
use crate::linalg::mat_vec2;
use faer::{Mat, MatRef};
pub use kind::Capabilities;
pub use run_caches::{BodyLineage, RunCaches};
use serde::Serialize;
pub use setup::{BodySetup, BuildContext, BuildError, ContactMesh, FlexibilityChange, PassStandIn, Rolling, SurfaceAt};

/// Which body of the pair: A is the upper body (y > 0), B the lower one.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
pub enum Side {
    /// Upper body; y points from B into A.
    A,
    /// Lower body.
    B,
}

impl Side {
    /// +1 for A, −1 for B: the sign with which this body's x-displacement enters w = u_xA − u_xB.
    pub fn sign(self) -> f64 {
        match self {
            Side::A => 1.0,
            Side::B => -1.0,
        }
    }
}

/// Flexibility of one body at the m contact nodes, in the pair convention of this module.
///
/// Each block is m × m: entry (i, j) is the displacement at node i due to a unit nodal value
/// of the traction at node j (the traction interpolated by the grid's shape functions).
/// Units: length / stress.
#[derive(Debug, Clone)]
pub struct Flexibility {
    /// ∂h_i/∂p_j: normal displacement into the body due to pressure.
    pub hp: Mat<f64>,
    /// ∂h_i/∂q_j: normal displacement into the body due to shear (dissimilar coupling).
    pub hq: Mat<f64>,
    /// ∂w_i/∂p_j: tangential share due to pressure (dissimilar coupling).
    pub wp: Mat<f64>,
    /// ∂w_i/∂q_j: tangential share due to shear.
    pub wq: Mat<f64>,
}

impl Flexibility {
    /// A body that does not deform.
    pub fn zero(m: usize) -> Self {
        Self {
            hp: Mat::zeros(m, m),
            hq: Mat::zeros(m, m),
            wp: Mat::zeros(m, m),
            wq: Mat::zeros(m, m),
        }
    }

    /// A half-plane's blocks from its pressure block H_p and coupling block H_q: the same kernel
    /// gives w from q (W_q = H_p), and w couples to p with the other sign (W_p = −H_q;
    /// docs/references.md §3.1).
    pub fn of_half_plane(hp: Mat<f64>, hq: Mat<f64>) -> Self {
        Self {
            wq: hp.clone(),
            wp: -&hq,
            hp,
            hq,
        }
    }

    /// Normal displacement into the body h = H_p p + H_q q at the nodes [length].
    pub fn normal(&self, p: &[f64], q: &[f64]) -> Vec<f64> {
        mat_vec2(&self.hp, p, &self.hq, q)
    }

    /// Tangential share w = W_p p + W_q q at the nodes [length].
    pub fn tangential(&self, p: &[f64], q: &[f64]) -> Vec<f64> {
        mat_vec2(&self.wp, p, &self.wq, q)
    }
}

/// A change of a body's flexibility on a grid, of low rank: each block (in the order hp, hq,
/// wp, wq of [`Flexibility`], the same axes and pair convention) is `left · right[k]`, with
/// `left` m × r shared by the four and `right[k]` r × m. Units: length / stress, carried by
/// `right`.
#[derive(Debug, Clone)]
pub struct LowRankFlexibility {
    /// The blocks' common left factor, m × r [-].
    pub left: Mat<f64>,
    /// Each block's right factor, r × m [length/stress].
    pub right: [Mat<f64>; 4],
}

/// Operator giving the tangential surface strain share ∂w/∂x at the nodes from nodal (p, q),
/// evaluated by the boundary-integral derivative rather than by differencing w.
/// Units: 1/stress. Entries follow the same pair convention as [`Flexibility`].
#[derive(Debug, Clone)]
pub struct StrainOperator {
    /// ∂(∂w/∂x)_i/∂p_j.
    pub p: Mat<f64>,
    /// ∂(∂w/∂x)_i/∂q_j.
    pub q: Mat<f64>,
}

/// A model of one body, as seen by the contact problem.
pub trait BodyModel {
    /// Short model name for reports (`half_space`, `rigid`, `bem`).
    fn model_name(&self) -> &'static str;

    /// Flexibility at the grid's nodes, for this body placed on `side`.
    fn flexibility(&self, grid: &ContactGrid, side: Side) -> Flexibility;

    /// The surface displacements under k loads at the grid's nodes, for this body placed on
    /// `side`: [h, w] with h = H_p p + H_q q and w = W_p p + W_q q column by column (`p`, `q`
    /// m × k nodal tractions [stress], h and w m × k [length]; pair convention, global axes).
    /// The flexibility's product (the default); a model that can answer a few loads without
    /// making its whole flexibility (a BEM body built with
    /// [`BuildContext::responses_only`]: factored, not solved for every unit load) does so.
    fn displacements(&self, grid: &ContactGrid, side: Side, p: MatRef<'_, f64>, q: MatRef<'_, f64>) -> [Mat<f64>; 2] {
        let f = self.flexibility(grid, side);
        [&f.hp * p + &f.hq * q, &f.wp * p + &f.wq * q]
    }

    /// Undeformed distance [length] of this body's surface from the common tangent line at
    /// abscissa x (≥ 0 for a convex body); the two bodies' profiles add up to the initial gap.
    fn profile(&self, x: f64) -> f64;

    /// Slope dh/dx [-] of [`Self::profile`] at x: by default a central difference over a
    /// millionth of |x| (the profile is smooth at that scale: a mesh's quadratic, a circle);
    /// a model with a closed-form profile gives its exact slope.
    fn profile_slope(&self, x: f64) -> f64 {
        let step = 1e-6 * x.abs().max(f64::MIN_POSITIVE.sqrt());
        (self.profile(x + step) - self.profile(x - step)) / (2.0 * step)
    }

    /// Surface-strain operator for the boundary-integral re-check of the slip, if the model
    /// has one.
    fn strain_operator(&self, grid: &ContactGrid, side: Side) -> Option<StrainOperator>;

    /// The surface strain ∂w/∂x [-] at the grid's nodes under the k loads (p, q) (m × k
    /// each, global axes as [`Self::displacements`]): the strain operator's product (the
    /// default); closed-form models integrate it without making the operator's m × m blocks.
    fn strain_at(&self, grid: &ContactGrid, side: Side, p: MatRef<'_, f64>, q: MatRef<'_, f64>) -> Option<Mat<f64>> {
        let op = self.strain_operator(grid, side)?;
        Some(&op.p * p + &op.q * q)
    }

    /// Wall time [s] the model spent (assembling, condensing) when it was built; zero for
    /// closed-form models.
    fn stage_seconds(&self) -> (f64, f64) {
        (0.0, 0.0)
    }
}

/// The nodal contact tractions on a grid, in the pair convention: the load under which
/// post-processing asks a body for its fields.
#[derive(Debug, Clone, Copy)]
pub struct ContactLoad<'a> {
    /// The grid whose shape functions interpolate the nodal values.
    pub grid: &'a ContactGrid,
    /// Nodal pressure p ≥ 0 [stress], on both bodies.
    pub pressure: &'a [f64],
    /// Nodal shear q [stress] that B exerts on A, +x (B receives −q).
    pub shear: &'a [f64],
}

/// What post-processing asks a body for inside it: the fields at `points` (contact frame: y > 0
/// inside A, y < 0 inside B) of the body placed on `side`, under `load`.
#[derive(Debug, Clone, Copy)]
pub struct InteriorQuery<'a> {
    /// Which body of the pair.
    pub side: Side,
    /// The contact tractions.
    pub load: ContactLoad<'a>,
    /// The points [length], contact frame.
    pub points: &'a [[f64; 2]],
    /// Accuracy controls (the boundary layer left out).
    pub options: InteriorOptions,
}

/// One [`InteriorSample`] per point of an [`InteriorQuery`], or why the model cannot give them.
pub type InteriorResult = Result<Vec<InteriorSample>, FieldError>;

/// What a body model can show under a solved [`ContactLoad`] (post-processing; the solver does
/// not use it).
pub trait BodyFields {
    /// The body's whole boundary under the load, for output; None for models without a
    /// boundary (half-space, rigid).
    fn boundary_field(&self, _load: &ContactLoad) -> Option<Result<BoundaryField, FieldError>> {
        None
    }

    /// Displacement and stress at the points of `query`. One [`InteriorSample`] per point: the
    /// fields in the contact frame, or why the point was not evaluated (outside the body, or
    /// within the boundary layer of the query's options). Models without an interior field
    /// (rigid) return [`FieldError::NoInteriorField`].
    fn interior(&self, query: &InteriorQuery) -> InteriorResult;

    /// The stresses at the body's surface under the load at the abscissae `xs` (the grid's
    /// nodes, or points outside the grid; not an element end), in the body's own frame (x along
    /// the contact, z into the body; σz = −p), for models that give them in closed form; None
    /// for the others, whose surface is then approached by their interior field (a strength
    /// assessment uses them: the surface governs at high friction).
    fn surface_stress(&self, _load: &ContactLoad, _side: Side, _xs: &[f64]) -> Option<Vec<PlaneStress>> {
        None
    }

    /// Where the interior field puts the body's undeformed surface at abscissa x: its distance
    /// [length] from the common tangent line, away from the other body (the convention of
    /// [`BodyModel::profile`]). A depth z below the surface is then the point at
    /// y = ±(surface + z) of the contact frame. 0 for a model whose field is a flat half-plane.
    fn field_surface(&self, _x: f64) -> f64 {
        0.0
    }
}

/// A body of a run: a [`BodyModel`] for the solver and its [`BodyFields`] for post-processing.
/// Implemented for every type that is both (and Send: a scene builds its two bodies side by
/// side; Sync: the runs of a sequence on several threads read one pair of built bodies,
/// [`crate::sequence`]).
pub trait Body: BodyModel + BodyFields + Send + Sync {
    /// The body as the contact problem sees it.
    fn model(&self) -> &dyn BodyModel;
    /// The body as post-processing sees it.
    fn fields(&self) -> &dyn BodyFields;
}

impl<T: BodyModel + BodyFields + Send + Sync> Body for T {
    fn model(&self) -> &dyn BodyModel {
        self
    }

    fn fields(&self) -> &dyn BodyFields {
        self
    }
}

/// Why a body model cannot give its fields.
#[derive(Debug, thiserror::Error)]
pub enum FieldError {
    /// The model has no interior (a rigid body).
    #[error("the {model} model has no interior field (it does not deform); ask for the other body")]
    NoInteriorField {
        /// The model's name.
        model: &'static str,
    },
    /// The model gives its surface only (a layer on a rigid core).
    #[error("the {model} model gives no interior field ({why}); ask for the other body, or model this one by `bem`")]
    NoInteriorModel {
        /// The model's name.
        model: &'static str,
        /// Why it has none.
        why: &'static str,
    },
    /// The BEM body could not be evaluated.
    #[error(transparent)]
    Bem(#[from] crate::bem::BemError),
}

/// A body's boundary, element by element, for VTK output (global axes of the mesh, which are
/// the contact frame). Each element contributes three points in VTK's quadratic-edge order
/// (start, end, mid); points of neighbouring elements are not shared, because tractions may
/// jump between elements.
#[derive(Debug, Clone)]
pub struct BoundaryField {
    /// Points [length], three per element.
    pub points: Vec<[f64; 2]>,
    /// Displacement at each point [length].
    pub displacement: Vec<[f64; 2]>,
    /// Traction t = σ·n at each point, n out of the material [stress].
    pub traction: Vec<[f64; 2]>,
    /// Physical group index of each element.
    pub group: Vec<i32>,
    /// Names of the groups, by index.
    pub group_names: Vec<String>,
}

/// Undeformed height of a circle of signed radius `radius` above its tangent at horizontal
/// distance x: R − √(R² − x²) (the exact profile, not the parabola x²/2R). A convex body
/// (R > 0) bends away from the other body (height ≥ 0); a concave one (R < 0, a ring's bore)
/// bends towards it, and its height is −(|R| − √(R² − x²)) ≤ 0. Beyond |x| = |R| the circle has
/// no point and the height is taken as ±|R| (the grid is always much shorter than |R|).
pub fn circle_profile(radius: f64, x: f64) -> f64 {
    let r = radius.abs();
    let r2 = r * r - x * x;
    if r2 <= 0.0 {
        return radius.signum() * r;
    }
    // x²/(R + √(R²−x²)) avoids the cancellation of R − √(R²−x²) for x ≪ R.
    radius.signum() * x * x / (r + r2.sqrt())
}

/// Slope dh/dx of [`circle_profile`] at x [-]: x/√(R² − x²) with the sign of R (infinite
/// beyond |x| = |R|, where the circle has no point).
pub fn circle_profile_slope(radius: f64, x: f64) -> f64 {
    let r2 = radius * radius - x * x;
    if r2 <= 0.0 {
        return radius.signum() * x.signum() * f64::INFINITY;
    }
    radius.signum() * x / r2.sqrt()
}

/// A body model whose undeformed profile is replaced by a circle of the given radius, e.g. a
/// BEM block standing in for a half-space whose gap is that of the real cylinders (paper §2,
/// Fig. 2: "the initial normal separation … calculated assuming the real cylinder's geometry").
pub struct WithCircularProfile {
    /// The model giving the flexibility and the fields.
    pub inner: Box<dyn Body>,
    /// Profile radius [length].
    pub radius: f64,
}

impl BodyModel for WithCircularProfile {
    fn model_name(&self) -> &'static str {
        self.inner.model_name()
    }

    fn flexibility(&self, grid: &ContactGrid, side: Side) -> Flexibility {
        self.inner.flexibility(grid, side)
    }

    fn displacements(&self, grid: &ContactGrid, side: Side, p: MatRef<'_, f64>, q: MatRef<'_, f64>) -> [Mat<f64>; 2] {
        self.inner.displacements(grid, side, p, q)
    }

    fn profile(&self, x: f64) -> f64 {
        circle_profile(self.radius, x)
    }

    fn profile_slope(&self, x: f64) -> f64 {
        circle_profile_slope(self.radius, x)
    }

    fn strain_operator(&self, grid: &ContactGrid, side: Side) -> Option<StrainOperator> {
        self.inner.strain_operator(grid, side)
    }

    fn strain_at(&self, grid: &ContactGrid, side: Side, p: MatRef<'_, f64>, q: MatRef<'_, f64>) -> Option<Mat<f64>> {
        self.inner.strain_at(grid, side, p, q)
    }

    fn stage_seconds(&self) -> (f64, f64) {
        self.inner.stage_seconds()
    }
}

impl BodyFields for WithCircularProfile {
    fn boundary_field(&self, load: &ContactLoad) -> Option<Result<BoundaryField, FieldError>> {
        self.inner.boundary_field(load)
    }

    fn interior(&self, query: &InteriorQuery) -> InteriorResult {
        self.inner.interior(query)
    }

    fn surface_stress(&self, load: &ContactLoad, side: Side, xs: &[f64]) -> Option<Vec<PlaneStress>> {
        self.inner.surface_stress(load, side, xs)
    }

    fn field_surface(&self, x: f64) -> f64 {
        self.inner.field_surface(x)
    }
}

#[cfg(test)]
mod tests {
    use super::{circle_profile, circle_profile_slope};

    #[test]
    fn a_concave_profile_is_the_convex_one_mirrored() {
        for x in [0.0, 1e-4, 0.3, 7.0] {
            let (convex, concave) = (circle_profile(50.0, x), circle_profile(-50.0, x));
            assert_eq!(convex, -concave);
            let exact = 50.0 - (2500.0 - x * x).sqrt();
            assert!((convex - exact).abs() <= 1e-15 * 50.0, "x = {x}");
            assert!((circle_profile_slope(-50.0, x) + x / (2500.0 - x * x).sqrt()).abs() < 1e-15);
        }
        // Roller 40 in bore −50: the gap is x²/2R* with R* = 200 at small x.
        let x = 1e-2;
        let gap = circle_profile(40.0, x) + circle_profile(-50.0, x);
        assert!((gap / (x * x / 400.0) - 1.0).abs() < 1e-6);
    }
}
