//! The half-space body model: closed-form plane-strain half-plane influence coefficients.
//!
//! For a half-plane z ≥ 0 (z into the body) loaded on its surface by a pressure p(s) and a
//! shear q(s) in +x (docs/references.md §3.1; Johnson, *Contact Mechanics*, eqs 2.24–2.25):
//!
//! ```text
//! u_x(x) = −A ∫ p(s) sgn(x−s) ds − B ∫ q(s) ln|x−s| ds
//! u_z(x) = −B ∫ p(s) ln|x−s| ds + A ∫ q(s) sgn(x−s) ds
//! A = (1−2ν)(1+ν)/(2E),   B = 2(1−ν²)/(πE)
//! ```
//!
//! Body B sees the shear −q and its x-displacement enters w with a minus sign, so in the pair
//! convention of [`crate::body`] the coupling terms change sign with the side; summed over the
//! two bodies this gives the dissimilar coupling 2β/E* = 2(A_A − A_B) of docs/references.md §3.3.
//!
//! **Datum.** The logarithm fixes displacements only up to a constant. We measure them from the
//! datum length ℓ = 2R/e, i.e. use ln(|x−s|/ℓ): with it the normal approach under a Hertz
//! pressure equals the centre-to-contact approach of a disc of radius R compressed between two
//! opposite contacts, (2P(1−ν²)/(πE))(ln(4R/a) − ½) (docs/references.md §6b, Johnson eq. 5.36).
//! Under load control the datum only shifts the overlap δ0; nothing else depends on it.
//!
//! The element integrals are exact (closed form in u = s − x) for elements near the field point;
//! for far elements (centre more than [`FAR_FIELD_RATIO`] element lengths away) the closed form
//! loses digits to cancellation (relative error ≈ ε·(d/L)³), so a 12-point Gauss rule is used
//! there, which is exact to round-off for those smooth integrands.

mod applied;
pub mod setup;

use super::flamant::halfplane_interior;
use super::kind::Capabilities;
use super::pair_influence::{joined, shared_or_computed, Family, InfluenceKey, PairInfluence};
use super::{
    circle_profile, circle_profile_slope, BodyFields, BodyModel, ContactLoad, Flexibility, InteriorQuery,
    InteriorResult, Side, StrainOperator,
};
use crate::grid::{ContactGrid, ElementKind};
use crate::interior::PlaneStress;
use crate::material::Elastic;
use crate::quadrature::gauss_legendre;
use faer::{Mat, MatRef};
use std::sync::Arc;

/// What the checks of a case ask of the `half_space` model. An elastic or viscoelastic half-plane: it deforms, takes the aged kernels of a standard linear
/// solid, and gives its interior fields in closed form.
pub const CAPABILITIES: Capabilities = Capabilities {
    name: "half_space",
    deforms: true,
    accepts_viscoelastic: true,
    interior_fields: true,
    boundary_elements: false,
};

/// Distance (in element lengths) from the field point to an element's centre beyond which the
/// element integrals use Gauss quadrature instead of the closed form.
pub const FAR_FIELD_RATIO: f64 = 2.5;

/// Surface kernels of the half-plane.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Kernel {
    /// ln|x − s|.
    Log,
    /// sgn(x − s).
    Sign,
    /// 1/(x − s), as a Cauchy principal value when x lies inside the element.
    Cauchy,
}

impl Kernel {
    fn eval(self, x: f64, s: f64) -> f64 {
        match self {
            Kernel::Log => (x - s).abs().ln(),
            Kernel::Sign => (x - s).signum(),
            Kernel::Cauchy => 1.0 / (x - s),
        }
    }

    /// Moments M_k = ∫_{u1}^{u2} u^k K du, k = 0, 1, 2, with u = s − x (docs/references.md §3.2).
    fn moments(self, u1: f64, u2: f64) -> [f64; 3] {
        match self {
            Kernel::Log => {
                // d/du [u^{k+1}/(k+1)·(ln|u| − 1/(k+1))] = u^k ln|u|;  0·ln 0 := 0. One
                // logarithm per end serves the three moments.
                let f = |u: f64| {
                    if u == 0.0 {
                        return [0.0; 3];
                    }
                    let ln = u.abs().ln();
                    [
                        u * (ln - 1.0),
                        u * u / 2.0 * (ln - 0.5),
                        u * u * u / 3.0 * (ln - 1.0 / 3.0),
                    ]
                };
                let (a, b) = (f(u1), f(u2));
                std::array::from_fn(|k| b[k] - a[k])
            }
            Kernel::Sign => {
                // sgn(x−s) = −sgn(u); ∫ −sgn(u) u^k du = −|u| u^k/(k+1).
                let f = |u: f64, k: i32| -u.abs() * u.powi(k) / (k + 1) as f64;
                [0, 1, 2].map(|k| f(u2, k) - f(u1, k))
            }
            Kernel::Cauchy => [
                // PV ∫ du/(−u) = ln|u1/u2|; ∫ u^k/(−u) du = −(u2^k − u1^k)/k for k ≥ 1.
                (u1 / u2).abs().ln(),
                -(u2 - u1),
                -(u2 * u2 - u1 * u1) / 2.0,
            ],
        }
    }
}

/// ∫ N_a(s) K(x − s) ds over the element [s1, s2] for each of its shape functions a, exactly
/// (entries past the element's node count are 0).
pub fn element_integrals_exact(kind: ElementKind, kernel: Kernel, s1: f64, s2: f64, x: f64) -> [f64; 3] {
    shape_integrals_from_moments(kind, s1, s2, x, kernel.moments(s1 - x, s2 - x))
}

/// ∫ N_a(s) K(x − s) ds over the element [s1, s2] for each shape function a, from the kernel's
/// moments M_k = ∫_{u1}^{u2} u^k K(−u) du, k = 0, 1, 2, in u = s − x (entries past the
/// element's node count are 0): each shape function is a quadratic in u.
pub fn shape_integrals_from_moments(kind: ElementKind, s1: f64, s2: f64, x: f64, moments: [f64; 3]) -> [f64; 3] {
    let (u1, u2) = (s1 - x, s2 - x);
    let length = s2 - s1;
    // ξ = α + γ u maps the element to [−1, 1].
    let alpha = -(u1 + u2) / length;
    let gamma = 2.0 / length;
    let npe = kind.nodes_per_element();
    std::array::from_fn(|a| {
        if a >= npe {
            return 0.0;
        }
        let [c0, c1, c2] = kind.shape_polynomial(a);
        let d0 = c0 + c1 * alpha + c2 * alpha * alpha;
        let d1 = (c1 + 2.0 * c2 * alpha) * gamma;
        let d2 = c2 * gamma * gamma;
        d0 * moments[0] + d1 * moments[1] + d2 * moments[2]
    })
}

/// Element integrals by Gauss quadrature (valid for field points well outside the element).
fn element_integrals_gauss(
    kind: ElementKind,
    kernel: Kernel,
    s1: f64,
    s2: f64,
    x: f64,
    rule: &(Vec<f64>, Vec<f64>),
) -> Vec<f64> {
    let half = 0.5 * (s2 - s1);
    let centre = 0.5 * (s1 + s2);
    (0..kind.nodes_per_element())
        .map(|a| {
            let [c0, c1, c2] = kind.shape_polynomial(a);
            rule.0
                .iter()
                .zip(&rule.1)
                .map(|(&xi, &w)| w * (c0 + c1 * xi + c2 * xi * xi) * kernel.eval(x, centre + half * xi))
                .sum::<f64>()
                * half
        })
        .collect()
}

/// Matrix K_ij = ∫ N_j(s) K(x_i − s) ds over the grid, for every node i and nodal shape j.
///
/// The grid is uniform, so an entry depends only on the offset d = e_i − e_j between the
/// elements of node i and of shape j and on the local indices: the matrix is block-Toeplitz.
/// Only (2·n_elements − 1)·npe element integrals are evaluated (O(m) instead of O(m²)), each on
/// a reference element centred at 0; the matrix is then filled from that table.
pub fn influence_matrix(grid: &ContactGrid, kernel: Kernel) -> Mat<f64> {
    if !grid.is_uniform() || grid.kind.shares_nodes() {
        return influence_matrix_direct(grid, kernel);
    }
    let rule = gauss_legendre(12);
    uniform_influence_matrix_of(grid, |s1, s2, x| {
        if x.abs() > FAR_FIELD_RATIO * (s2 - s1) {
            let g = element_integrals_gauss(grid.kind, kernel, s1, s2, x, &rule);
            std::array::from_fn(|a| g.get(a).copied().unwrap_or(0.0))
        } else {
            element_integrals_exact(grid.kind, kernel, s1, s2, x)
        }
    })
}

/// [`influence_matrix`] from a pair's store when the body has one ([`PairInfluence`]: the
/// other body of the pair computed it on this grid), else computed.
pub fn shared_influence_matrix(pair: Option<&PairInfluence>, grid: &ContactGrid, kernel: Kernel) -> Mat<f64> {
    let key = InfluenceKey {
        family: Family::HalfPlane,
        kernel: kernel as u8,
    };
    shared_or_computed(pair, key, grid, || influence_matrix(grid, kernel))
}

/// [`influence_matrix_of`] on a uniform grid of elements that do not share nodes: an entry
/// depends only on the offset between the elements and the local indices, so only
/// (2·n_elements − 1)·npe element integrals are evaluated, on a reference element centred at 0
/// (`integrals` is called with s1 = −h/2, s2 = h/2 and the field point relative to it).
///
/// Panics (in debug) on a grid [`influence_matrix_of`] would not pass here.
pub fn uniform_influence_matrix_of(
    grid: &ContactGrid,
    integrals: impl Fn(f64, f64, f64) -> [f64; 3] + Sync,
) -> Mat<f64> {
    use rayon::prelude::*;
    debug_assert!(grid.is_uniform() && !grid.kind.shares_nodes());
    let m = grid.n_nodes();
    let ne = grid.n_elements();
    let npe = grid.kind.nodes_per_element();
    let length = grid.element_length();
    let (s1, s2) = (-0.5 * length, 0.5 * length);
    // table[(d + ne − 1)·npe + a] = integrals over the reference element of the shapes, at the
    // field point of local node a of an element d lengths to the right.
    let points: Vec<f64> = (0..(2 * ne - 1))
        .flat_map(|k| {
            let d = k as f64 - (ne - 1) as f64;
            grid.kind
                .node_coordinates()
                .iter()
                .map(move |xi| d * length + 0.5 * length * xi)
        })
        .collect();
    let table: Vec<[f64; 3]> = points.par_iter().map(|&x| integrals(s1, s2, x)).collect();
    Mat::from_fn(m, m, |i, j| {
        let (ei, ai) = grid.element_of(i);
        let (ej, aj) = grid.element_of(j);
        table[(ei + ne - 1 - ej) * npe + ai][aj]
    })
}

/// The influence matrix of a non-uniform grid or of continuous elements: every node–element
/// pair integrated (O(m²)); far elements by the series of [`FarField`].
fn influence_matrix_direct(grid: &ContactGrid, kernel: Kernel) -> Mat<f64> {
    let far_field = FarField::new(grid.kind);
    direct_influence_matrix_of(grid, |s1, s2, x| {
        if (0.5 * (s1 + s2) - x).abs() > FAR_FIELD_RATIO * (s2 - s1) {
            far_field.integrals(kernel, s1, s2, x)
        } else {
            element_integrals_exact(grid.kind, kernel, s1, s2, x)
        }
    })
}

/// Matrix K_ij = Σ_e ∫_e N_j(s) K(x_i − s) ds over the grid for any kernel, given its element
/// integrals `integrals(s1, s2, x)` = [∫ N_a K(x − s) ds]_a over the element [s1, s2]
/// (O(m²) pairs, elements in parallel).
///
/// On a uniform grid of elements that do not share nodes the block-Toeplitz structure is
/// used ([`uniform_influence_matrix_of`]).
pub fn influence_matrix_of(grid: &ContactGrid, integrals: impl Fn(f64, f64, f64) -> [f64; 3] + Sync) -> Mat<f64> {
    if grid.is_uniform() && !grid.kind.shares_nodes() {
        return uniform_influence_matrix_of(grid, integrals);
    }
    direct_influence_matrix_of(grid, integrals)
}

/// [`influence_matrix_of`] pair by pair (O(m²) element integrals).
fn direct_influence_matrix_of(grid: &ContactGrid, integrals: impl Fn(f64, f64, f64) -> [f64; 3] + Sync) -> Mat<f64> {
    use rayon::prelude::*;
    let m = grid.n_nodes();
    let npe = grid.kind.nodes_per_element();
    let integrals = |e: usize, x: f64| integrals(grid.edges[e], grid.edges[e + 1], x);
    let mut k = Mat::<f64>::zeros(m, m);
    if grid.kind.shares_nodes() {
        // Shared end nodes (continuous elements) collect both elements' integrals.
        for (i, &x) in grid.nodes.iter().enumerate() {
            for e in 0..grid.n_elements() {
                for (a, v) in integrals(e, x).into_iter().take(npe).enumerate() {
                    k[(i, grid.global_node(e, a))] += v;
                }
            }
        }
        return k;
    }
    // Each element owns its `npe` columns (contiguous in faer's column-major storage): the
    // elements in parallel, each against every field point.
    k.as_mut()
        .par_col_chunks_mut(npe)
        .enumerate()
        .for_each(|(e, mut cols)| {
            for (i, &x) in grid.nodes.iter().enumerate() {
                for (a, v) in integrals(e, x).into_iter().take(npe).enumerate() {
                    cols[(i, a)] = v;
                }
            }
        });
    k
}

/// Most terms of the far-field series of [`FarField`]: at the closest far element
/// ([`FAR_FIELD_RATIO`] lengths, t = 0.2) 0.2³² ≈ 4e-23 is below round-off.
pub const FAR_FIELD_TERMS: usize = 32;

/// Element integrals for field points beyond [`FAR_FIELD_RATIO`] element lengths from the
/// element's centre c, by the kernel's expansion about c in t = h/D (h the half-length,
/// D = x − c, |t| ≤ 0.2 there), with s = c + hξ:
///
/// ```text
/// ln|x − s|  = ln|D| − Σ_{n≥1} tⁿ ξⁿ / n
/// 1/(x − s)  = (1/D) Σ_{n≥0} tⁿ ξⁿ
/// sgn(x − s) = sgn(D)
/// ```
///
/// so ∫ N_a K ds = h Σ_n (coefficient)·m_{a,n} with the shape moments m_{a,n} = ∫_{−1}^{1} N_a ξⁿ dξ,
/// summed until |t|ⁿ falls below round-off (one logarithm per pair, no cancellation: the
/// closed form loses ≈ ε·(D/h)³ to it there).
#[derive(Debug, Clone)]
pub struct FarField {
    npe: usize,
    /// m_{a,n} for each shape function a and n < [`FAR_FIELD_TERMS`].
    moments: [[f64; FAR_FIELD_TERMS]; 3],
    /// m_{a,n}/n, the logarithm's coefficients (n ≥ 1; entry 0 unused).
    log_moments: [[f64; FAR_FIELD_TERMS]; 3],
}

/// A term of the far-field series below this fraction (2⁻⁵⁴) of the leading one ends it.
const FAR_FIELD_ROUND_OFF: f64 = 5.551115123125783e-17;

impl FarField {
    /// The shape moments of the element kind.
    pub fn new(kind: ElementKind) -> Self {
        // ∫_{−1}^{1} ξ^k dξ.
        let mu = |k: usize| if k.is_multiple_of(2) { 2.0 / (k + 1) as f64 } else { 0.0 };
        let npe = kind.nodes_per_element();
        let moments: [[f64; FAR_FIELD_TERMS]; 3] = std::array::from_fn(|a| {
            let [c0, c1, c2] = if a < npe { kind.shape_polynomial(a) } else { [0.0; 3] };
            std::array::from_fn(|n| c0 * mu(n) + c1 * mu(n + 1) + c2 * mu(n + 2))
        });
        let log_moments = moments.map(|m| std::array::from_fn(|n| if n == 0 { 0.0 } else { m[n] / n as f64 }));
        Self {
            npe,
            moments,
            log_moments,
        }
    }

    /// ∫ N_a(s) K(x − s) ds over [s1, s2] for each shape function a (entries past the
    /// element's node count are 0), for x beyond [`FAR_FIELD_RATIO`] lengths of the centre.
    #[allow(clippy::needless_range_loop)] // the shape functions index three arrays alike
    pub fn integrals(&self, kernel: Kernel, s1: f64, s2: f64, x: f64) -> [f64; 3] {
        let h = 0.5 * (s2 - s1);
        let d = x - 0.5 * (s1 + s2);
        let t = h / d;
        let npe = self.npe;
        let mut out = [0.0; 3];
        match kernel {
            Kernel::Sign => {
                for a in 0..npe {
                    out[a] = d.signum() * h * self.moments[a][0];
                }
            }
            Kernel::Log => {
                // ln|x − s| = ln|D| − Σ_{n≥1} tⁿξⁿ/n, summed until tⁿ is below round-off.
                let mut series = [0.0; 3];
                let mut tn = 1.0;
                for n in 1..FAR_FIELD_TERMS {
                    tn *= t;
                    for a in 0..npe {
                        series[a] += tn * self.log_moments[a][n];
                    }
                    if tn.abs() < FAR_FIELD_ROUND_OFF {
                        break;
                    }
                }
                let ln_d = d.abs().ln();
                for a in 0..npe {
                    out[a] = h * (ln_d * self.moments[a][0] - series[a]);
                }
            }
            Kernel::Cauchy => {
                // 1/(x − s) = (1/D) Σ_{n≥0} tⁿξⁿ.
                let mut series = [0.0; 3];
                let mut tn = 1.0;
                for n in 0..FAR_FIELD_TERMS {
                    for a in 0..npe {
                        series[a] += tn * self.moments[a][n];
                    }
                    tn *= t;
                    if tn.abs() < FAR_FIELD_ROUND_OFF {
                        break;
                    }
                }
                for a in 0..npe {
                    out[a] = h / d * series[a];
                }
            }
        }
        out
    }
}

/// An elastic half-plane standing in for a cylinder of radius `radius`.
#[derive(Debug, Clone)]
pub struct HalfSpace {
    /// Material of the body.
    pub material: Elastic,
    /// Signed radius of the cylinder's profile [length]: positive for a convex body, negative
    /// for a concave one (a ring's bore); sets the undeformed gap and (through |R|) the datum.
    pub radius: f64,
    /// The pair's shared influence matrices, when the body was built as one of a pair
    /// ([`PairInfluence`]); None computes them alone.
    pub pair: Option<Arc<PairInfluence>>,
    /// The family its matrices are shared as ([`Family::HalfPlane`] unless
    /// [`Self::in_pair_of_stand_ins`]).
    pub family: Family,
}

impl HalfSpace {
    /// The body of `material` and signed profile radius `radius` on its own (no pair store).
    pub fn new(material: Elastic, radius: f64) -> Self {
        Self {
            material,
            radius,
            pair: None,
            family: Family::HalfPlane,
        }
    }

    /// The body as one of a pair that shares the half-plane's influence matrices through
    /// `pair` (joined here), or on its own when `pair` is None.
    pub fn in_pair(mut self, pair: Option<&Arc<PairInfluence>>) -> Self {
        self.pair = joined(pair, &[Family::HalfPlane]);
        self.family = Family::HalfPlane;
        self
    }

    /// [`Self::in_pair`] as a BEM body's stand-in, sharing its matrices with the other body's
    /// stand-in only ([`Family::StandInHalfPlane`]).
    pub fn in_pair_of_stand_ins(mut self, pair: Option<&Arc<PairInfluence>>) -> Self {
        self.pair = joined(pair, &[Family::StandInHalfPlane]);
        self.family = Family::StandInHalfPlane;
        self
    }

    /// The influence matrix of `kernel` on `grid` ([`influence_matrix`]), through the pair's
    /// store in the body's family.
    fn kernel_matrix(&self, grid: &ContactGrid, kernel: Kernel) -> Mat<f64> {
        self.shared_kernel(grid, kernel, || influence_matrix(grid, kernel))
    }

    /// Datum length ℓ = 2|R|/e [length] of the logarithmic displacement (see the module docs;
    /// a concave body takes its radius's magnitude: the datum only shifts the overlap δ0).
    pub fn datum_length(&self) -> f64 {
        2.0 * self.radius.abs() / std::f64::consts::E
    }

    /// The half-plane's H blocks (H_p, H_q) on a straight `grid` for the body on `side`, whose
    /// W blocks are the same kernels (W_q = H_p, W_p = −H_q: [`Flexibility::of_half_plane`]):
    /// a caller that transforms the flexibility (carries it to a curved grid, scales its
    /// columns) transforms these two and makes the W blocks last, at half the work.
    pub fn kernel_blocks(&self, grid: &ContactGrid, side: Side) -> (Mat<f64>, Mat<f64>) {
        let log = self.kernel_matrix(grid, Kernel::Log);
        let sgn = self.kernel_matrix(grid, Kernel::Sign);
        self.blocks_of_kernels(log, sgn, &grid.weights, side)
    }

    /// The influence matrix of `kernel` on `grid` from the pair's store when the other body
    /// of the pair made it there, else `compute()`'s (a copy kept for the other body): for
    /// kernels made otherwise than [`influence_matrix`] makes them (carried to a curved grid).
    pub fn shared_kernel(&self, grid: &ContactGrid, kernel: Kernel, compute: impl FnOnce() -> Mat<f64>) -> Mat<f64> {
        let key = InfluenceKey {
            family: self.family,
            kernel: kernel as u8,
        };
        shared_or_computed(self.pair.as_deref(), key, grid, compute)
    }

    /// [`Self::kernel_blocks`] from the kernels' influence matrices K_log (`hp`) and K_sgn
    /// (`hq`), in place: H_p = −B (K_log − w_j ln ℓ), H_q = side·A K_sgn, with `weights` the
    /// w_j of the grid's columns (a grid's own, or those carried with the kernels).
    pub fn blocks_of_kernels(
        &self,
        mut hp: Mat<f64>,
        mut hq: Mat<f64>,
        weights: &[f64],
        side: Side,
    ) -> (Mat<f64>, Mat<f64>) {
        let a_coef = self.material.halfplane_sgn_coefficient();
        let b_coef = self.material.halfplane_log_coefficient();
        let sign = side.sign();
        let ln_datum = self.datum_length().ln();
        // ∫ N_j ln(|x−s|/ℓ) ds = ∫ N_j ln|x−s| ds − w_j ln ℓ; the blocks are made in place, since
        // a graded grid's m² matrices are large and each new one costs its page faults.
        for (j, &w) in weights.iter().enumerate() {
            for v in hp.col_mut(j).iter_mut() {
                *v = -b_coef * (*v - w * ln_datum);
            }
        }
        for j in 0..hq.ncols() {
            for h in hq.col_mut(j).iter_mut() {
                *h *= sign * a_coef;
            }
        }
        (hp, hq)
    }
}

impl BodyModel for HalfSpace {
    fn model_name(&self) -> &'static str {
        "half_space"
    }

    fn flexibility(&self, grid: &ContactGrid, side: Side) -> Flexibility {
        let (hp, hq) = self.kernel_blocks(grid, side);
        Flexibility::of_half_plane(hp, hq)
    }

    /// The blocks of [`HalfSpace::kernel_blocks`] applied without being made
    /// ([`applied::Applied::displacements`]).
    fn displacements(&self, grid: &ContactGrid, side: Side, p: MatRef<'_, f64>, q: MatRef<'_, f64>) -> [Mat<f64>; 2] {
        applied::Applied::new(self, grid, side).displacements(p, q)
    }

    fn profile(&self, x: f64) -> f64 {
        circle_profile(self.radius, x)
    }

    fn profile_slope(&self, x: f64) -> f64 {
        circle_profile_slope(self.radius, x)
    }

    /// ∂w/∂x = −side·2A·p(x) − B·PV∫ q(s)/(x−s) ds, exact for the interpolated tractions.
    fn strain_operator(&self, grid: &ContactGrid, side: Side) -> Option<StrainOperator> {
        let a_coef = self.material.halfplane_sgn_coefficient();
        let b_coef = self.material.halfplane_log_coefficient();
        let m = grid.n_nodes();
        let mut q = self.kernel_matrix(grid, Kernel::Cauchy);
        for j in 0..m {
            for v in q.col_mut(j).iter_mut() {
                *v *= -b_coef;
            }
        }
        // Nodes are interpolation points, so p(x_i) = p_i.
        let mut p = Mat::zeros(m, m);
        for i in 0..m {
            p[(i, i)] = -side.sign() * 2.0 * a_coef;
        }
        Some(StrainOperator { p, q })
    }

    /// [`Self::strain_operator`]'s product without its blocks ([`applied::Applied::strain`]).
    fn strain_at(&self, grid: &ContactGrid, side: Side, p: MatRef<'_, f64>, q: MatRef<'_, f64>) -> Option<Mat<f64>> {
        Some(applied::Applied::new(self, grid, side).strain(p, q))
    }
}

impl BodyFields for HalfSpace {
    /// Flamant / Boussinesq–Cerruti superposition ([`super::flamant`], Eq. H1–H2), the
    /// displacement measured from this model's datum [`HalfSpace::datum_length`], so that at
    /// the surface it equals the displacement the flexibility gives.
    fn interior(&self, query: &InteriorQuery) -> InteriorResult {
        Ok(halfplane_interior(
            &query.load,
            self.material.shear(),
            self.material.poisson,
            self.datum_length(),
            query.side,
            query.points,
            &query.options,
        ))
    }

    /// σz = −p, τxz = −q and σx = −p − (2/π) PV∫ q(s)/(x − s) ds with the body's own shear q
    /// (q on A, −q on B): the Flamant fields at z = 0 (Johnson 1985 §2.2; McEwen's σx = −p − 2μx
    /// under q = μp of a Hertz pressure), plane strain σy = ν(σx + σz).
    fn surface_stress(&self, load: &ContactLoad, side: Side, xs: &[f64]) -> Option<Vec<PlaneStress>> {
        let grid = load.grid;
        let q = Mat::from_fn(grid.n_nodes(), 1, |i, _| side.sign() * load.shear[i]);
        let cauchy = applied::influence_times_at(grid, Kernel::Cauchy, q.as_ref(), xs);
        let nu = self.material.poisson;
        Some(
            xs.iter()
                .enumerate()
                .map(|(i, &x)| {
                    let (p, q) = (
                        grid.interpolate(load.pressure, x),
                        side.sign() * grid.interpolate(load.shear, x),
                    );
                    let sxx = -p - 2.0 / std::f64::consts::PI * cauchy[(i, 0)];
                    PlaneStress {
                        sxx,
                        szz: -p,
                        txz: -q,
                        syy: nu * (sxx - p),
                    }
                })
                .collect(),
        )
    }
}

#[cfg(test)]
mod tests;
