//! A body of a scene before it meets a contact grid: the one extension point per body model.
//!
//! The scene holds each body as an `Arc<dyn BodySetup>`. Everything the stages after the case
//! ask of a body goes through this trait, so a new body model is one type that implements it
//! (in its own module under `src/body/`) plus one arm in the registry that turns its case keys
//! into it (`src/scene/registry.rs`); what the case's checks ask of it before it is built is
//! its [`crate::body::Capabilities`], answered per kind in `src/case/kinds.rs`. Nothing in
//! `contact/`, `adapt/`, `post/` or `output/` changes (docs/architecture.md, "A new body
//! model").
//!
//! What a setup owns:
//! * what the scene's estimates need: its profile radius, the elastic constants that stand for
//!   it in the Hertz estimates, the datum of its normal approach, its surface geometry for the
//!   contact frame;
//! * its cost: the size of its own discretisation, for the memory estimate;
//! * building its [`Body`] on a contact grid ([`BodySetup::build`]), given the side and the
//!   rolling kinematics ([`BuildContext`]);
//! * following a refined grid ([`BodySetup::follow_grid`]): a BEM body cuts its own mesh along
//!   the grid, a closed-form model has nothing to change.

use super::run_caches::RunCaches;
use super::{circle_profile, circle_profile_slope, Body, LowRankFlexibility, Side};
use crate::body::pair_influence::PairInfluence;
use crate::grid::ContactGrid;
use crate::material::Elastic;
use crate::mesh::LoadedMesh;
use std::sync::Arc;

/// How the contact moves over the bodies: what a rate-dependent model (viscoelastic) needs
/// beyond the grid. Elastic models ignore it.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Rolling {
    /// +1 when the contact moves in +x over the bodies (material enters at x = +a), −1 when
    /// it moves in −x.
    pub direction: f64,
    /// Rolling speed V [length/time], when the case gives one.
    pub speed: Option<f64>,
}

/// A contact's size and peak pressure as a body's own compliance gives them
/// ([`BodySetup::own_contact_scales`]).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ContactScales {
    /// Half-width a of the contact [length].
    pub half_width: f64,
    /// Largest pressure [stress].
    pub peak_pressure: f64,
    /// The normal force P [force/length]: the given one, or the one the overlap takes.
    pub normal_force: f64,
}

/// What presses the bodies together, for [`BodySetup::own_contact_scales`].
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum NormalLoad {
    /// Normal force P per unit length [force/length].
    Force(f64),
    /// Overlap δ0 [length] measured from the body's datum (a cover: its rigid core).
    Overlap(f64),
}

/// What a body model is built with besides its own keys.
#[derive(Debug, Clone, Copy)]
pub struct BuildContext<'a> {
    /// The contact grid the flexibility is wanted at.
    pub grid: &'a ContactGrid,
    /// Which body of the pair.
    pub side: Side,
    /// The rolling kinematics.
    pub rolling: Rolling,
    /// The store of influence matrices the pair's bodies share on this grid, if the caller
    /// builds a pair ([`PairInfluence`]: a half-plane body joins it and takes from it).
    pub pair: Option<&'a Arc<PairInfluence>>,
    /// Whether the caller will ask the body only for its response to a few loads
    /// ([`crate::body::BodyModel::displacements`]) and its boundary field, not for its whole
    /// flexibility: a model that answers those more cheaply prepares for that (a BEM body is
    /// factored, not solved for every unit load of its contact nodes). Anything else it is
    /// asked still works, at the full cost.
    pub responses_only: bool,
    /// The caches of the run the build is part of ([`RunCaches`]: a BEM body's condensation
    /// kept for a later build on the same grid), if the caller runs the error control; None
    /// (a fixed grid, a sweep's or Python's single build): nothing is kept between builds.
    pub run: Option<&'a RunCaches>,
}

/// A body's contact group on its own mesh: a body that has one sets the contact grid (its
/// contact elements are the grid's).
#[derive(Debug, Clone, Copy)]
pub struct ContactMesh<'a> {
    /// The checked and oriented mesh.
    pub mesh: &'a LoadedMesh,
    /// Name of the contact group.
    pub group: &'a str,
}

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
    /// The surface of a circle of signed radius `radius` at x, seen from `side`.
    pub fn of_circle(radius: f64, x: f64, side: Side) -> Self {
        // y rises into A above the contact and falls into B below it.
        Self {
            slope_angle: (side.sign() * circle_profile_slope(radius, x)).atan(),
            profile: circle_profile(radius, x),
            radius,
        }
    }

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

/// Why a body model could not be built on a grid.
#[derive(Debug, thiserror::Error)]
pub enum BuildError {
    /// The BEM model of the body failed (a singular system, a mesh it cannot use).
    #[error(transparent)]
    Bem(#[from] crate::bem::BemError),
    /// The body's own contact nodes do not cover the grid.
    #[error(transparent)]
    Transfer(#[from] super::transfer::TransferError),
    /// Building the body would cost far more than the estimates `rollbem check` prints
    /// (the message names the key to change).
    #[error("{0}")]
    Cost(String),
}

/// A body's stand-in for the passes of an error-controlled grid ([`BodySetup::pass_stand_in`]).
#[derive(Debug, Clone)]
pub struct PassStandIn {
    /// The stand-in the passes solve with.
    pub body: Arc<dyn BodySetup>,
    /// The same stand-in with a part known less well, whose solution on the final grid,
    /// compared with `body`'s, estimates `body`'s error there; None when `body` cannot give
    /// the final grid's results (its strain or its fields), and the final grid is solved with
    /// the body itself.
    pub check: Option<Arc<dyn BodySetup>>,
    /// How `check` differs from `body`, when that is a low-rank change of the flexibility on
    /// any grid: the check's contact problem is then the passes' problem plus the change
    /// (src/adapt/stand_ins.rs) instead of a new assembly of both bodies. None: the check is
    /// built as a body of its own.
    pub check_change: Option<Arc<dyn FlexibilityChange>>,
    /// Wall time [s] the stand-in's build spent condensing the body (part of its build time;
    /// the run reports it as condensation).
    pub condense_s: f64,
}

/// A change of a body's flexibility known as a low-rank term on any contact grid (a pass
/// stand-in's check against the stand-in: src/body/bem/stand_in.rs).
pub trait FlexibilityChange: std::fmt::Debug + Send + Sync {
    /// The change on `grid` for the body on `side`, in global axes and the pair convention of
    /// [`super::Flexibility`].
    fn on_grid(&self, grid: &ContactGrid, side: Side) -> LowRankFlexibility;
}

/// What a body with its own mesh changed outside the contact
/// ([`BodySetup::with_free_boundary_bisected`], [`BodySetup::with_free_boundary_coarsened`]) is
/// built for.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum ChangedFor {
    /// Solved once by the check of the body mesh's error, which compares its solution with the
    /// body's as given: its element integrals to [`CHECK_QUADRATURE_TOLERANCE`], nothing of it
    /// kept.
    Check,
    /// The run's body from then on (the check's bisection adopted): integrals as the body's own.
    Run,
}

/// Relative accuracy of the element integrals of a body changed for the check of the body
/// mesh's error ([`ChangedFor::Check`]), against 1e-12 for the run's own bodies. The check
/// measures differences of its solution from the given bodies' that matter from a fifth of the
/// tolerance (2e-7 at the tightest tolerance, 1e-6): integrals to 1e-9 move them by about that
/// relative, and the estimates of both bores of cases/ at 1e-3 are the same to three digits
/// while their bisected bodies' assembly takes a sixth less (docs/performance.md).
pub const CHECK_QUADRATURE_TOLERANCE: f64 = 1e-9;

/// One body of a scene, ready to build its model on a contact grid (module docs).
pub trait BodySetup: std::fmt::Debug + Send + Sync {
    /// The model's name in outputs (`half_space`, `rigid`, `bem`, …).
    fn model_name(&self) -> &'static str;

    /// Signed profile radius [length]: positive convex, negative concave, infinite for a flat
    /// profile (the Hertz estimates' radius).
    fn radius(&self) -> f64;

    /// The elastic constants that stand for the body in the Hertz estimates (grid size, the
    /// error's units), in the Dundurs coupling of the estimates and in the contact frame's
    /// share of the gap; None for a body that does not deform. A model with more than one
    /// modulus says here which one sizes the contact.
    fn hertz_material(&self) -> Option<Elastic>;

    /// Plane-strain compliance (1 − ν²)/E of [`Self::hertz_material`] [1/stress], zero for a
    /// rigid body.
    fn compliance(&self) -> f64 {
        self.hertz_material().map_or(0.0, |m| m.plane_strain_compliance())
    }

    /// The contact's half-width and peak pressure under `load` against a rigid cylinder of
    /// signed `effective_radius` [length], rolling as `rolling` says, when
    /// the body's own compliance rather than the half-plane of [`Self::hertz_material`] sets
    /// them (a cover bonded to a rigid core: [`crate::body::scales`]; a foundation that is no
    /// continuum). They then size the grid and the errors' units in place of Hertz's, and
    /// `rollbem check` prints them. None (the default): the Hertz estimates hold.
    /// `hertz_half_width` [length] is the Hertz estimate of the same load, a start.
    fn own_contact_scales(
        &self,
        _load: NormalLoad,
        _effective_radius: f64,
        _hertz_half_width: f64,
        _rolling: Rolling,
    ) -> Option<ContactScales> {
        None
    }

    /// Whether the model replaces the body by an elastic half-plane (its error against the true
    /// geometry then grows with a/R, and the validity warnings estimate it).
    fn idealises_as_half_plane(&self) -> bool {
        false
    }

    /// The body's true geometry idealised: the elastic half-plane of its material and profile
    /// radius, for a model of the true geometry (`bem`); None for a model that is already an
    /// idealisation or has none of the kind (the default). The error control solves the scene
    /// once with these in the bodies' place to tell the share of the creepage the geometry sets
    /// (src/adapt/geometry_share.rs).
    fn half_plane_twin(&self) -> Option<std::sync::Arc<dyn BodySetup>> {
        None
    }

    /// Whether the body is the elastic half-plane of [`Self::hertz_material`] that the Hertz
    /// estimates describe, so that they compare with its solved contact (the run's table
    /// prints them beside it when both bodies are); false by default.
    fn hertz_applies(&self) -> bool {
        false
    }

    /// Whether the half-space model's measured error against the true geometry (the model
    /// advice of `rollbem check`) concerns this body: true for a body a half-space models, or
    /// could model in place of its true geometry (`bem`); false for a model with an
    /// idealisation of its own (a cover on a rigid core).
    fn shares_half_space_error(&self) -> bool {
        true
    }

    /// Whether a true-geometry (`bem`) model of the same physics exists, so that the advice may
    /// suggest it when the half-space idealisation errs: false for physics the BEM lacks (a
    /// viscoelastic material).
    fn has_true_geometry_model(&self) -> bool {
        true
    }

    /// The body's contact group on its own mesh, if it has one (it then sets the grid).
    fn contact_mesh(&self) -> Option<ContactMesh<'_>> {
        None
    }

    /// The body's surface at x on `side` for the contact frame, None when the model is flat
    /// (a half-space: the frame then keeps the global axes).
    fn surface_at(&self, x: f64, side: Side) -> Option<SurfaceAt>;

    /// Distance R_b [length] of the datum of the body's normal approach, in the half-plane
    /// estimate of the force an overlap gives (ln(4R_b/a)): its profile radius by default.
    fn datum_distance(&self) -> f64 {
        self.radius().abs()
    }

    /// Kernel evaluations [-] the body's own tables cost on `ctx.grid` (a layer cover's,
    /// which grow with (grid/b)²), for the cost `rollbem check` estimates; 0 by default.
    fn kernel_table_evaluations(&self, _ctx: &BuildContext) -> f64 {
        0.0
    }

    /// Depth [length] of a thin layer of the body under its contact (a cover on a rigid core),
    /// for the model advice; None when the body is not a thin layer.
    fn layer_thickness(&self) -> Option<f64> {
        None
    }

    /// Width [length] of the layer behind the contact's leading edge over which the body's
    /// material, entering the contact at `speed` [length/time], relaxes from its instantaneous
    /// to its long-term response: V·τe (τe the relaxation time) for a standard linear solid, None
    /// for an elastic body. The error control grades the leading edge to it a priori
    /// (src/adapt.rs), since an element wider than the layer misplaces the edge's pressure.
    fn relaxation_layer(&self, _speed: Option<f64>) -> Option<f64> {
        None
    }

    /// Nodes of the body's own discretisation (a BEM body's boundary nodes, the contact's
    /// field nodes included), for the memory estimate; None for a closed-form model.
    fn discretisation_nodes(&self) -> Option<usize> {
        None
    }

    /// [`Self::discretisation_nodes`] once the body has followed a grid of `contact_elements`
    /// elements (an error-controlled grid at its limit), for the memory estimate of a
    /// tolerance run; the same as on the start grid by default.
    fn discretisation_nodes_on(&self, _contact_elements: usize) -> Option<usize> {
        self.discretisation_nodes()
    }

    /// The boundary nodes the passes of an error-controlled grid condense the body with when it
    /// offers them a stand-in ([`Self::pass_stand_in`]): its own contact grid bisected
    /// `bisections` times (the finest level the stand-in is fitted on), its elements outside
    /// the contact bisected once more for the check of its mesh. None for a body that offers
    /// no stand-in (the passes condense it on their own grids: [`Self::discretisation_nodes_on`])
    /// or has no discretisation of its own.
    fn stand_in_nodes(&self, _bisections: usize) -> Option<usize> {
        None
    }

    /// Notices of the body's inputs (a mesh loop turned round), for the console.
    fn notices(&self) -> &[String] {
        &[]
    }

    /// The checks of [`Self::build`] that need no large computation (a BEM body: its boundary
    /// conditions hold it against rigid motion, its contact group has the grid's nodes and
    /// faces the other body), so that `rollbem check` refuses what `run` would; nothing by
    /// default.
    fn preflight(&self, _ctx: &BuildContext) -> Result<(), BuildError> {
        Ok(())
    }

    /// Builds the body model on `ctx.grid`, seen from `ctx.side`.
    fn build(&self, ctx: &BuildContext) -> Result<Box<dyn Body>, BuildError>;

    /// The body on a refined contact grid spanning the same interval (an error-controlled
    /// grid's passes): a new setup when the body's own discretisation follows the grid (a BEM
    /// body's mesh cut along it), None when the body is unchanged (closed-form models: they
    /// build on any grid).
    fn follow_grid(&self, _grid: &ContactGrid) -> Option<Arc<dyn BodySetup>> {
        None
    }

    /// The same body with every element of its own discretisation outside the contact (a BEM
    /// body's free boundary, shaft, rim) bisected, its contact elements unchanged: what the
    /// error control solves the final grid with once more to estimate the body mesh's error
    /// (docs/theory.md, "Error-controlled grids"). None for a body without a mesh of its own
    /// (closed-form models: half-space, rigid, viscoelastic).
    fn with_free_boundary_bisected(&self, _for: ChangedFor) -> Option<Arc<dyn BodySetup>> {
        None
    }

    /// The same body with the elements of its own discretisation outside the contact merged in
    /// pairs, its contact elements unchanged: the cheaper comparison the error control tries
    /// first to bound the body mesh's error (docs/theory.md, "Error-controlled grids"). None
    /// for a body without a mesh of its own, or without two neighbouring elements to merge.
    fn with_free_boundary_coarsened(&self, _for: ChangedFor) -> Option<Arc<dyn BodySetup>> {
        None
    }

    /// The body's own mesh outside the contact, for messages: its file (or the label of a
    /// generated mesh) and the groups [`Self::with_free_boundary_bisected`] refines; None for
    /// a body without a mesh.
    fn free_boundary_label(&self) -> Option<String> {
        None
    }

    /// A cheaper model of the same body for the passes of an error-controlled grid, built from
    /// the body on each of `levels` (two or three grids, coarsest first, each the bisection of
    /// the one before). None (the default) when the body is cheap already: every pass then
    /// builds the body itself. A BEM body offers the half-plane plus its smooth remainder
    /// ([`crate::body::bem::stand_in`]), its builds sharing `run`'s caches when given.
    fn pass_stand_in(
        &self,
        _levels: &[&ContactGrid],
        _side: Side,
        _rolling: Rolling,
        _run: Option<&RunCaches>,
    ) -> Result<Option<PassStandIn>, BuildError> {
        Ok(None)
    }
}
