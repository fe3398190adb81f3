//! The case file schema (cases/README.md documents every key). Every struct rejects unknown keys; each field documents its
//! unit and default. Lengths, forces and stresses are in the case's consistent units.

use super::strength::{StrengthSpec, YieldSpec};
pub use crate::contact::falling::FallingFriction;
pub use crate::contact::Formulation;
pub use crate::contact::Method;
use crate::contact::{RollingDirection, SlipDerivative, TractionAxes};
use crate::grid::ElementKind;
pub use crate::mesh::parametric::Shape;
use serde::{Deserialize, Serialize};
use std::collections::BTreeMap;

/// A whole case file.
#[derive(Debug, Clone, Deserialize, Serialize)]
#[serde(deny_unknown_fields)]
pub struct Case {
    /// Free text shown in reports. Default = "".
    #[serde(default)]
    pub title: String,
    /// Unit labels (only printed; the numbers must be consistent). Default = mm, N.
    #[serde(default)]
    pub units: Units,
    /// Named materials.
    pub materials: BTreeMap<String, MaterialSpec>,
    /// The two bodies: A (upper) and B (lower).
    pub bodies: Bodies,
    /// Friction, rolling direction and contact grid.
    pub contact: ContactSpec,
    /// Normal and tangential load or kinematics.
    pub load: LoadSpec,
    /// Solver settings. Default = generalized Newton, Φ, automatic penalty.
    #[serde(default)]
    pub solver: SolverSpec,
    /// Output settings.
    #[serde(default)]
    pub output: OutputSpec,
    /// A history of rolling steps instead of the steady state. Default = none (steady).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub transient: Option<super::transient::TransientSpec>,
}

/// Unit labels.
#[derive(Debug, Clone, Deserialize, Serialize)]
#[serde(deny_unknown_fields)]
pub struct Units {
    /// Length unit label. Default = "mm".
    pub length: String,
    /// Force unit label. Default = "N".
    pub force: String,
    /// Time unit label (creep times, speeds). Default = "s".
    #[serde(default = "default_time_unit")]
    pub time: String,
}

fn default_time_unit() -> String {
    "s".into()
}

impl Units {
    /// Unit of a force per unit length of the cylinders (P, Q), e.g. `N/mm`.
    pub fn force_per_length(&self) -> String {
        format!("{}/{}", self.force, self.length)
    }

    /// Unit of a stress (p, q, E, G), e.g. `N/mm^2`.
    pub fn stress(&self) -> String {
        format!("{}/{}^2", self.force, self.length)
    }

    /// Unit of a speed, e.g. `mm/s`.
    pub fn speed(&self) -> String {
        format!("{}/{}", self.length, self.time)
    }

    /// Unit of a power per unit length of the cylinders (a force per length times a speed),
    /// e.g. `N/mm*mm/s`.
    pub fn power_per_length(&self) -> String {
        format!("{}*{}", self.force_per_length(), self.speed())
    }

    /// Unit of a stress per length (the normal penalty r_n), e.g. `N/mm^3`.
    pub fn stress_per_length(&self) -> String {
        format!("{}/{}^3", self.force, self.length)
    }
}

impl Default for Units {
    fn default() -> Self {
        Self {
            length: "mm".into(),
            force: "N".into(),
            time: default_time_unit(),
        }
    }
}

/// An isotropic elastic material: Poisson's ratio and exactly one of E or G.
#[derive(Debug, Clone, Deserialize, Serialize)]
#[serde(deny_unknown_fields)]
pub struct MaterialSpec {
    /// Young's modulus [stress].
    #[serde(rename = "E", default)]
    pub young: Option<f64>,
    /// Shear modulus [stress] (instead of E).
    #[serde(rename = "G", default)]
    pub shear: Option<f64>,
    /// Poisson's ratio ν ∈ (−1, 0.5].
    pub nu: f64,
    /// Makes the material a standard linear solid: `E`/`G` above is then its glassy
    /// (instantaneous) modulus and these keys give its rubbery modulus and creep time.
    #[serde(default)]
    pub viscoelastic: Option<ViscoelasticSpec>,
    /// The yield stress, for `output.strength`: exactly one of `shear` (k) and `tensile` (Y).
    #[serde(rename = "yield", default)]
    pub yield_stress: Option<YieldSpec>,
}

/// The keys under `materials.NAME.viscoelastic`: exactly one of `E_rubbery` and `G_rubbery`
/// (the same kind of modulus as the glassy one), and `creep_time`.
#[derive(Debug, Clone, Deserialize, Serialize)]
#[serde(deny_unknown_fields)]
pub struct ViscoelasticSpec {
    /// Rubbery (long-term) Young's modulus E_r ≤ E [stress].
    #[serde(rename = "E_rubbery", default)]
    pub young_rubbery: Option<f64>,
    /// Rubbery (long-term) shear modulus G_r ≤ G [stress].
    #[serde(rename = "G_rubbery", default)]
    pub shear_rubbery: Option<f64>,
    /// Creep (retardation) time τc ≥ 0 [time]; 0 gives the rubbery elastic material.
    pub creep_time: f64,
}

/// The pair of bodies.
#[derive(Debug, Clone, Deserialize, Serialize)]
#[serde(deny_unknown_fields)]
pub struct Bodies {
    /// Upper body (y > 0).
    #[serde(rename = "A")]
    pub a: BodySpec,
    /// Lower body (y < 0).
    #[serde(rename = "B")]
    pub b: BodySpec,
}

/// One body and its model.
#[derive(Debug, Clone, Deserialize, Serialize)]
#[serde(tag = "model", rename_all = "snake_case", deny_unknown_fields)]
pub enum BodySpec {
    /// Elastic half-plane with the profile of a cylinder of the given radius.
    HalfSpace {
        /// Name of a material under `materials`.
        material: String,
        /// Profile radius [length].
        radius: f64,
    },
    /// A cover of thickness `thickness` bonded to a rigid core, its outer radius `radius` the
    /// profile (flat-layer kernels, b ≪ R; docs/viscoelastic.md, "The layer"). An elastic or
    /// viscoelastic material.
    Layer {
        /// Name of a material under `materials`.
        material: String,
        /// Outer radius of the cover [length] (the profile).
        radius: f64,
        /// Cover thickness b [length] over the rigid core.
        thickness: f64,
    },
    /// Rigid cylinder: its profile is a circle, given by `radius` or fitted to the contact
    /// segment of a Gmsh mesh (exactly one of the two).
    Rigid {
        /// Profile radius [length].
        #[serde(default)]
        radius: Option<f64>,
        /// Gmsh boundary mesh whose contact group's circle gives the profile radius, relative to
        /// the case file (e.g. the same roller mesh a `bem` run would use).
        #[serde(default)]
        mesh: Option<String>,
        /// Physical group of the contact segment in `mesh`. Default = "contact".
        #[serde(default = "default_contact_group")]
        contact: String,
    },
    /// Boundary element model of the body's true geometry, from a Gmsh boundary mesh or a
    /// parametric geometry that rollbem meshes itself (exactly one of `mesh` and `geometry`).
    Bem {
        /// Gmsh MSH 4.1 boundary mesh (line3 or line2 elements), relative to the case file.
        #[serde(default)]
        mesh: Option<String>,
        /// A parametric body (roller, ring, covered roller, block) meshed by rollbem, instead
        /// of `mesh`.
        #[serde(default, deserialize_with = "geometry_key")]
        geometry: Option<GeometrySpec>,
        /// Name of a material under `materials`.
        material: String,
        /// Physical group of the contact segment. Default = "contact".
        #[serde(default = "default_contact_group")]
        contact: String,
        /// Boundary condition of every other physical group of the mesh. With `geometry`,
        /// optional: the family's groups not given keep their defaults (the shaft, rim, bond or
        /// far face fixed, the rest free).
        #[serde(default)]
        boundaries: BTreeMap<String, BoundarySpec>,
        /// Profile radius for the undeformed gap [length]; default = the mesh's own geometry.
        /// Give it for a block standing in for a half-space (paper Fig. 2).
        #[serde(default)]
        radius: Option<f64>,
    },
}

/// A parametric body that rollbem meshes itself (cases/README.md, "Parametric bodies"):
/// exactly one family key. Lengths in the case's unit.
#[derive(Debug, Clone, Deserialize, Serialize)]
#[serde(rename_all = "snake_case", deny_unknown_fields)]
pub enum GeometrySpec {
    /// A solid disc on a rigid shaft (groups `contact`, `free`, `shaft`).
    Roller(RollerGeometry),
    /// A ring: contact on its concave bore, outer rim (groups `contact`, `bore`, `rim`).
    Ring(RingGeometry),
    /// A cover layer bonded to a core (groups `contact`, `free`, `bonded`).
    CoveredRoller(CoveredRollerGeometry),
    /// A rectangle standing in for a half-space (groups `contact`, `free`, `far`).
    Block(BlockGeometry),
}

/// Reads `geometry:` with messages that name the key: inside a body (a tagged enum) the key
/// path of a parse error ends at the body, so the message itself says `geometry` and lists the
/// families or fields.
fn geometry_key<'de, D: serde::Deserializer<'de>>(d: D) -> Result<Option<GeometrySpec>, D::Error> {
    let value: Option<serde_json::Value> = Option::deserialize(d)?;
    value
        .map(|v| {
            GeometrySpec::deserialize(v).map_err(|e| {
                serde::de::Error::custom(format!(
                    "geometry: {e} (the families: {{roller: {{radius, shaft}}}}, {{ring: {{bore, rim}}}}, \
                     {{covered_roller: {{radius, cover_thickness, core}}}}, {{block: {{width, depth}}}})"
                ))
            })
        })
        .transpose()
}

impl GeometrySpec {
    /// The body's family and lengths, as the mesh generator takes them.
    pub fn shape(&self) -> Shape {
        match self {
            GeometrySpec::Roller(r) => Shape::Roller {
                radius: r.radius,
                shaft: r.shaft,
            },
            GeometrySpec::Ring(r) => Shape::Ring {
                bore: r.bore,
                rim: r.rim,
            },
            GeometrySpec::CoveredRoller(c) => Shape::CoveredRoller {
                radius: c.radius,
                cover_thickness: c.cover_thickness,
            },
            GeometrySpec::Block(b) => Shape::Block {
                width: b.width,
                depth: b.depth,
            },
        }
    }
}

/// `geometry: {roller: {radius, shaft}}`.
#[derive(Debug, Clone, Deserialize, Serialize)]
#[serde(deny_unknown_fields)]
pub struct RollerGeometry {
    /// Outer radius R [length].
    pub radius: f64,
    /// Radius of the shaft (the inner circle) [length], 0 < shaft < radius.
    pub shaft: f64,
}

/// `geometry: {ring: {bore, rim}}`.
#[derive(Debug, Clone, Deserialize, Serialize)]
#[serde(deny_unknown_fields)]
pub struct RingGeometry {
    /// Bore radius [length] (the profile radius is −bore: concave).
    pub bore: f64,
    /// Outer rim radius [length], > bore.
    pub rim: f64,
}

/// `geometry: {covered_roller: {radius, cover_thickness, core}}`.
#[derive(Debug, Clone, Deserialize, Serialize)]
#[serde(deny_unknown_fields)]
pub struct CoveredRollerGeometry {
    /// Outer radius R of the cover [length].
    pub radius: f64,
    /// Thickness b of the cover [length], 0 < b < R.
    pub cover_thickness: f64,
    /// The core: `rigid` (the cover's inner circle fixed). Default = rigid.
    #[serde(default)]
    pub core: CoreSpec,
}

/// The core of a covered roller.
#[derive(Debug, Clone, Deserialize, Serialize)]
#[serde(untagged)]
pub enum CoreSpec {
    /// `rigid`.
    Keyword(CoreKeyword),
    /// `{material: NAME}`: an elastic core (refused: it needs a two-region BEM).
    Elastic {
        /// Name of a material under `materials`.
        material: String,
    },
}

impl Default for CoreSpec {
    fn default() -> Self {
        CoreSpec::Keyword(CoreKeyword::Rigid)
    }
}

/// The keyword cores.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Deserialize, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum CoreKeyword {
    /// A rigid core: the cover's inner circle does not move.
    Rigid,
}

/// `geometry: {block: {width, depth}}`.
#[derive(Debug, Clone, Deserialize, Serialize)]
#[serde(deny_unknown_fields)]
pub struct BlockGeometry {
    /// Width of the block (its contact face) [length].
    pub width: f64,
    /// Depth of the block below its contact face [length].
    pub depth: f64,
}

fn default_contact_group() -> String {
    "contact".into()
}

/// Boundary condition of a physical group of a `bem` body.
#[derive(Debug, Clone, Deserialize, Serialize)]
#[serde(untagged)]
pub enum BoundarySpec {
    /// `fixed` (u = 0, a rigid shaft or bonded core) or `free` (t = 0).
    Keyword(BoundaryKeyword),
    /// Prescribed displacement or traction.
    Prescribed(PrescribedBoundary),
}

/// The keyword boundary conditions.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Deserialize, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum BoundaryKeyword {
    /// u = 0.
    Fixed,
    /// t = 0.
    Free,
}

/// A prescribed vector on a group: exactly one key.
#[derive(Debug, Clone, Default, Deserialize, Serialize)]
#[serde(deny_unknown_fields)]
pub struct PrescribedBoundary {
    /// Uniform displacement (u_x, u_y) [length].
    pub displacement: Option<[f64; 2]>,
    /// Uniform traction (t_x, t_y) [stress].
    pub traction: Option<[f64; 2]>,
    /// Normal pressure p (compressive positive) [stress].
    pub pressure: Option<f64>,
}

/// Friction, rolling direction and the contact grid.
#[derive(Debug, Clone, Deserialize, Serialize)]
#[serde(deny_unknown_fields)]
pub struct ContactSpec {
    /// Coulomb friction coefficient μ ≥ 0; the static one μ_s under `falling_friction`.
    pub friction: f64,
    /// Friction falling with the local slip velocity from `friction` to `{kinetic: μ_k,
    /// slip_velocity: s_h}`, optionally with a second exponential `second: {share: w,
    /// slip_velocity: s_h2}` (src/contact/falling.rs); needs `load.speed` and `solver.method:
    /// newton`. Default: none (constant μ).
    #[serde(default)]
    pub falling_friction: Option<FallingFriction>,
    /// Direction in which the contact moves over the bodies: "+x" or "-x". Default = "+x".
    #[serde(default = "default_rolling")]
    pub rolling_direction: RollingDirection,
    /// Contact grid. Default = 21 discontinuous quadratic elements over ±1.3 Hertz half-widths.
    #[serde(default)]
    pub grid: GridSpec,
    /// Steady-rolling derivative of the slip. Default = second_order.
    #[serde(default = "default_derivative")]
    pub slip_derivative: SlipDerivative,
    /// Axes of the contact tractions with true-geometry (bem, rigid) bodies: `contact` (along
    /// the normal and tangent of the contact interface, with the rigid surface speeds of curved
    /// bodies in the slip) or `global` (along x and y everywhere). Half-space bodies are flat:
    /// a scene with one uses the global axes either way. Default = contact.
    #[serde(default)]
    pub traction_axes: TractionAxes,
}

fn default_rolling() -> RollingDirection {
    RollingDirection::PlusX
}

fn default_derivative() -> SlipDerivative {
    SlipDerivative::SecondOrder
}

/// The contact grid.
#[derive(Debug, Clone, Deserialize, Serialize)]
#[serde(deny_unknown_fields, default)]
pub struct GridSpec {
    /// Number of traction elements. Default = 21 (the paper's grid).
    pub elements: usize,
    /// Half-length of the grid in Hertz half-widths (> 1). Default = 1.3.
    pub extent: f64,
    /// Half-length of the grid [length]; overrides `extent` when given. Default = none.
    pub half_length: Option<f64>,
    /// Traction interpolation. Default = discontinuous_quadratic.
    pub element: ElementKind,
    /// Adjust the half-length (keeping it near `extent`) so that the Hertz edges ±a fall on
    /// element boundaries: the square-root edge of the pressure then never sits inside an
    /// element, and errors decrease steadily with refinement. Ignored with `half_length`.
    /// Default = true.
    pub align_edges: bool,
    /// Error-controlled grid: the estimated RMS errors of p/p0 and q/(μp0) over the contact and
    /// the creepage's relative error (relative to at least 5 % of Carter's complete-slip
    /// creepage μa/R*) that the run must reach (e.g. 1e-4). The grid of
    /// `elements` is the start; rollbem refines it where the estimated error is large (towards
    /// the contact edges and the stick/slip points) until the estimates are below the
    /// tolerance; a `bem` body's contact elements (the start grid) are cut along it. Default =
    /// none (the fixed grid of `elements`, or a bem body's mesh).
    pub tolerance: Option<f64>,
    /// Largest number of contact elements an error-controlled grid may use; reaching it without
    /// the tolerance ends the run with exit code 2 and the estimate. Default = 1000.
    pub max_elements: usize,
    /// Whether the passes of an error-controlled grid solve a `bem` body through its cheaper
    /// stand-in (its half-plane plus a smooth remainder fitted to the full BEM, checked against
    /// the full BEM at the end; docs/theory.md) rather than cutting and condensing the full BEM
    /// in every pass. Both give results within the tolerance; the stand-ins are faster.
    /// Default = true.
    pub stand_ins: bool,
    /// Whether the condensations of one `bem` body on the grids of an error-controlled run share
    /// the part of the BEM matrices that the cuts along the grid leave unchanged (integrated
    /// once per run) instead of assembling every grid's matrices afresh. The results agree to
    /// the element integrals' accuracy; only the time differs. Default = true.
    pub reuse_far_field: bool,
    /// Whether `rollbem run` estimates the error of a fixed grid's solution (one more solve on
    /// the grid with every element halved, compared with it: summary.json `error_estimate`).
    /// An error-controlled grid always estimates its own. Default = true.
    pub estimate: bool,
}

impl Default for GridSpec {
    fn default() -> Self {
        Self {
            elements: 21,
            extent: 1.3,
            half_length: None,
            element: ElementKind::DiscontinuousQuadratic,
            align_edges: true,
            tolerance: None,
            max_elements: 1000,
            stand_ins: true,
            reuse_far_field: true,
            estimate: true,
        }
    }
}

/// Normal and tangential loading.
#[derive(Debug, Clone, Deserialize, Serialize)]
#[serde(deny_unknown_fields)]
pub struct LoadSpec {
    /// Normal load: `{force: P}` [force/length] or `{overlap: δ0}` [length].
    #[serde(rename = "normal")]
    pub normal_keys: NormalKeys,
    /// Tangential load: `{ratio: Q/(μP)}`, `{force: Q}` [force/length] or `{creep: ξ}`. Default = {ratio: 0}.
    #[serde(rename = "tangential", default)]
    pub tangential_keys: TangentialKeys,
    /// Rolling speed V > 0 [length/time]: the speed at which the contact moves over the bodies'
    /// material; needed by viscoelastic materials (with a creep time > 0), ignored by elastic ones.
    #[serde(default)]
    pub speed: Option<f64>,
}

/// The keys under `load.normal`: exactly one must be given.
#[derive(Debug, Clone, Default, Deserialize, Serialize)]
#[serde(deny_unknown_fields)]
pub struct NormalKeys {
    /// Normal force per unit length P > 0.
    pub force: Option<f64>,
    /// Rigid overlap δ0 > 0.
    pub overlap: Option<f64>,
}

/// The keys under `load.tangential`: at most one may be given (none means ratio 0).
#[derive(Debug, Clone, Default, Deserialize, Serialize)]
#[serde(deny_unknown_fields)]
pub struct TangentialKeys {
    /// Q/(μP) ∈ (−1, 1).
    pub ratio: Option<f64>,
    /// Tangential force per unit length Q.
    pub force: Option<f64>,
    /// Creepage ξ = (V_A − V_B)/V.
    pub creep: Option<f64>,
}

/// Normal load or kinematics.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum NormalSpec {
    /// Normal force per unit length P > 0.
    Force(f64),
    /// Rigid overlap δ0 > 0.
    Overlap(f64),
}

/// Tangential load or kinematics.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum TangentialSpec {
    /// Q/(μP) ∈ (−1, 1).
    Ratio(f64),
    /// Tangential force per unit length Q.
    Force(f64),
    /// Creepage ξ = (V_A − V_B)/V.
    Creep(f64),
}

impl NormalKeys {
    /// The normal control, or a message if not exactly one key is given.
    pub fn spec(&self) -> Result<NormalSpec, String> {
        match (self.force, self.overlap) {
            (Some(p), None) => Ok(NormalSpec::Force(p)),
            (None, Some(d)) => Ok(NormalSpec::Overlap(d)),
            _ => Err("give exactly one of `force` (P) or `overlap` (delta0)".into()),
        }
    }
}

impl TangentialKeys {
    /// The tangential control, or a message if more than one key is given.
    pub fn spec(&self) -> Result<TangentialSpec, String> {
        match (self.ratio, self.force, self.creep) {
            (None, None, None) => Ok(TangentialSpec::Ratio(0.0)),
            (Some(r), None, None) => Ok(TangentialSpec::Ratio(r)),
            (None, Some(q), None) => Ok(TangentialSpec::Force(q)),
            (None, None, Some(x)) => Ok(TangentialSpec::Creep(x)),
            _ => Err("give only one of `ratio` (Q/muP), `force` (Q) or `creep` (xi)".into()),
        }
    }
}

impl LoadSpec {
    /// The normal control (validated cases only; an invalid one falls back to zero force).
    pub fn normal(&self) -> NormalSpec {
        self.normal_keys.spec().unwrap_or(NormalSpec::Force(0.0))
    }

    /// The tangential control (validated cases only).
    pub fn tangential(&self) -> TangentialSpec {
        self.tangential_keys.spec().unwrap_or(TangentialSpec::Ratio(0.0))
    }
}

/// Solver settings.
#[derive(Debug, Clone, Deserialize, Serialize)]
#[serde(deny_unknown_fields, default)]
pub struct SolverSpec {
    /// Solution method: `newton` (generalized Newton with line search, the default),
    /// `newton_plain` (no line search), `norm_tang` (Kalker's NORM/TANG alternation) or
    /// `gauss_seidel` (projected Gauss–Seidel sweeps). See docs/stability.md. Default = newton.
    pub method: Method,
    /// Projection formulation: phi (paper Eq. 43) or psi (Eq. 44). Default = phi.
    pub formulation: Formulation,
    /// `auto` (scale 1) or a positive scale c of the automatic penalties (for `gauss_seidel` the
    /// relaxation factor ω of its local updates). Default = auto.
    pub penalty: Penalty,
    /// Scaled residual at which the solver stops. Default = 1e-10.
    pub tolerance: f64,
    /// Maximum number of iterations, in the method's own unit: Newton steps, NORM/TANG
    /// alternations, or Gauss–Seidel sweeps (which need thousands). Default = 100.
    pub max_iterations: usize,
}

impl Default for SolverSpec {
    fn default() -> Self {
        Self {
            method: Method::Newton,
            formulation: Formulation::Phi,
            penalty: Penalty::Auto(AutoTag::Auto),
            tolerance: 1e-10,
            max_iterations: 100,
        }
    }
}

/// Penalty choice: the word `auto` or a positive scale.
#[derive(Debug, Clone, Copy, Deserialize, Serialize)]
#[serde(untagged)]
pub enum Penalty {
    /// `auto`: scale 1.
    Auto(AutoTag),
    /// A positive scale c.
    Scale(f64),
}

/// The literal `auto`.
#[derive(Debug, Clone, Copy, Deserialize, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum AutoTag {
    /// `auto`.
    Auto,
}

impl Penalty {
    /// The penalty scale c.
    pub fn scale(self) -> f64 {
        match self {
            Penalty::Auto(_) => 1.0,
            Penalty::Scale(c) => c,
        }
    }
}

/// A grid of interior points in the contact frame: y > 0 lies in A, y < 0 in B. The body's
/// model gives the fields (`half_space`: Flamant superposition; `bem`: Somigliana's identity);
/// a rigid body has none. Points outside the body or within the boundary layer are flagged in
/// the output's `status` and not evaluated.
#[derive(Debug, Clone, PartialEq, Deserialize, Serialize)]
#[serde(deny_unknown_fields)]
pub struct InteriorSpec {
    /// `A` or `B`.
    pub body: String,
    /// [x0, x1, nx]: nx points from x0 to x1 [length].
    pub x: [f64; 3],
    /// [y0, y1, ny]: ny points from y0 to y1 [length], inside the body.
    pub y: [f64; 3],
}

fn default_true() -> bool {
    true
}

/// Output settings.
#[derive(Debug, Clone, Deserialize, Serialize)]
#[serde(deny_unknown_fields)]
pub struct OutputSpec {
    /// Output folder, relative to the case file. Default = out/<case file stem> next to the case.
    #[serde(default)]
    pub dir: Option<String>,
    /// VTK files for ParaView: contact.vtu and result.pvd. Default = true.
    #[serde(default = "default_true")]
    pub vtk: bool,
    /// Interior displacement and stress grid (interior_<body>.csv / .vtu). Default = null.
    #[serde(default)]
    pub interior: Option<InteriorSpec>,
    /// First yield and shakedown of the bodies (summary.json `strength`,
    /// residual_stress_<body>.csv). Default = null.
    #[serde(default)]
    pub strength: Option<StrengthSpec>,
}

impl Default for OutputSpec {
    fn default() -> Self {
        Self {
            dir: None,
            vtk: true,
            interior: None,
            strength: None,
        }
    }
}
