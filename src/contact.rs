//! The steady rolling contact problem on the contact grid (González & Abascal §3).
//!
//! After each body has been condensed to its flexibility at the contact nodes, the gap and the
//! slip are affine in the nodal tractions (paper Eq. 21):
//!
//! ```text
//! g = h0 − δ0 + H_p p + H_q q                (compression h = H_p p + H_q q, Eq. 11–13)
//! s = σ (ξ + D w),  w = W_p p + W_q q        (Eq. 15–20; B = σ D W)
//! ```
//!
//! with the user-facing signs of docs/theory.md: p ≥ 0 compressive, q the shear on A in +x, g ≥ 0,
//! s the slip velocity of A relative to B divided by |V|, ξ = (V_A − V_B)/V, δ0 the overlap.
//! σ = sgn(V) is the sign of the material flow through the contact: material enters at the
//! leading edge, so rolling in +x (the contact moves +x over the bodies) means flow in −x, σ = −1.
//!
//! **Mapping to the paper's notation** (documented once here and in docs/theory.md):
//! p_n = −p, p_t = q, T_n = g, s_t = s, ξ0 = ξ, δ0 = δ0. The paper's T (Eq. 17) is our D
//! multiplied by σ; the paper writes the contact conditions for p_n ≤ 0, we for p ≥ 0, so its
//! min(0, p_n + r T_n) becomes −max(0, p − r g).

mod creep_secant;
pub mod direction;
pub mod falling;
pub mod frame;
pub mod gauss_seidel;
pub mod methods;
pub mod newton;
pub mod norm_tang;
pub mod report;
pub mod residual;
pub mod restart;
pub mod slip_operator;
pub mod stall;
mod start;
pub mod workspace;

use crate::body::{BodyModel, Flexibility, LowRankFlexibility, Side, StrainOperator};
use crate::grid::ContactGrid;
use crate::linalg::mat_vec2;
use faer::Mat;
pub use frame::{ContactForces, ContactFrame, TractionAxes};
pub use report::{GaussSeidelSettings, IterationRecord, Method, NewtonSettings, SolveReport, SolverSettings};
pub use residual::{Formulation, State};
use serde::{Deserialize, Serialize};
pub use slip_operator::{SlipDerivative, SlipOperator};
pub use workspace::Workspace;

/// Direction in which the contact moves over the bodies (docs/theory.md, conventions).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
pub enum RollingDirection {
    /// The contact moves in +x over the bodies; material flows in −x; leading edge at x = +a.
    #[serde(rename = "+x")]
    PlusX,
    /// The contact moves in −x over the bodies; material flows in +x; leading edge at x = −a.
    #[serde(rename = "-x")]
    MinusX,
}

impl RollingDirection {
    /// σ = sgn(V), the sign of the material velocity through the contact along x.
    pub fn flow_sign(self) -> f64 {
        match self {
            RollingDirection::PlusX => -1.0,
            RollingDirection::MinusX => 1.0,
        }
    }
}

/// What is prescribed in the normal direction.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum NormalControl {
    /// Normal force P > 0 per unit length [force/length]; the overlap δ0 is unknown.
    Force(f64),
    /// Overlap δ0 [length]; P is computed.
    Overlap(f64),
}

/// What is prescribed in the tangential direction.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum TangentialControl {
    /// Tangential force Q [force/length]; the creepage ξ is unknown.
    Force(f64),
    /// Ratio Q/(μP) ∈ (−1, 1); the creepage ξ is unknown (linear in the tractions, so it mixes
    /// freely with either normal control).
    Ratio(f64),
    /// Creepage ξ [-]; Q is computed.
    Creep(f64),
}

/// Gauss points per element at which [`ContactProblem::gap_slope`] is given: the pressure is
/// quadratic on an element and a circle's slope x/√(R² − x²) cubic to within (x/R)⁴, so four
/// points integrate p·h0′ to round-off on a grid much shorter than the radii.
pub const GAP_SLOPE_POINTS: usize = 4;

/// The assembled contact problem: everything the solver needs, and nothing about the bodies.
#[derive(Debug, Clone)]
pub struct ContactProblem {
    /// The contact grid.
    pub grid: ContactGrid,
    /// Sum of the bodies' flexibilities (pair convention of [`crate::body`]).
    pub flex: Flexibility,
    /// Body B's own flexibility, for the bodies' surface displacements (A's is `flex` less
    /// B's: one set of m × m blocks fewer to allocate on every grid). None on the intermediate
    /// grids of an error-controlled run, which are solved but not written: src/adapt.rs drops
    /// it on every grid whose solution cannot be the result (four m × m blocks fewer held while
    /// the next grid is solved) and restores it on one that ends a run unexpectedly.
    pub body_b: Option<BodyBShare>,
    /// Slip operator: B_p = σ D W_p, B_q = σ D W_q (paper Eq. 20) [1/stress].
    pub bp: Mat<f64>,
    /// See `bp`.
    pub bq: Mat<f64>,
    /// The difference operator D (paper Eq. 17 without its sign σ).
    pub slip_operator: SlipOperator,
    /// Undeformed gap h0(x_i) from the true profiles [length].
    pub h0: Vec<f64>,
    /// Slope dh0/dx [-] of the undeformed gap (both bodies' exact profiles) at the points of
    /// [`ContactGrid::gauss_points`]`(`[`GAP_SLOPE_POINTS`]`)`: what the rolling resistance
    /// integrates the pressure against (src/post/rolling_resistance.rs).
    pub gap_slope: Vec<f64>,
    /// Coulomb friction coefficient μ ≥ 0; the static one μ_s of a falling law (`falling`),
    /// which also turns a prescribed ratio Q/(μP) into a force.
    pub friction: f64,
    /// The friction law falling with the slip velocity and the rolling speed it needs; None:
    /// constant μ = `friction` ([`falling`]).
    pub falling: Option<falling::FallingLaw>,
    /// The friction coefficient μ_i [-] at every node, frozen during one solve of the outer
    /// fixed point of [`falling::solve`]; None: `friction` at every node.
    pub nodal_friction: Option<Vec<f64>>,
    /// σ = sgn(V), see [`RollingDirection::flow_sign`].
    pub flow_sign: f64,
    /// Normal control.
    pub normal: NormalControl,
    /// Tangential control.
    pub tangential: TangentialControl,
    /// Combined boundary-integral strain operator ∂w/∂x, when both models have one.
    pub strain: Option<StrainShare>,
    /// The contact's directions at the nodes, in which `flex`, `body_b` and `strain` are
    /// written ([`frame`]).
    pub frame: ContactFrame,
    /// Rigid slip of the surface speeds k_i times the creepage weight e_i [-] ([`frame`]).
    pub rigid_slip: Vec<f64>,
}

impl ContactProblem {
    /// The combined boundary-integral strain operator of two body models on a grid, in the
    /// contact frame, when both have one (none on grids of continuous elements, below).
    pub fn strain_of(
        grid: &ContactGrid,
        body_a: &dyn BodyModel,
        body_b: &dyn BodyModel,
        frame: &ContactFrame,
    ) -> Option<StrainShare> {
        // On a grid whose elements share end nodes the principal value of the strain kernel at a
        // shared node is the sum of two element integrals that diverge separately (only their
        // sum is finite), so the boundary-integral slip is not evaluated there.
        if grid.kind.shares_nodes() {
            return None;
        }
        // One body's operator after the other, each turned in place and B's summed where A's
        // lies (as the flexibilities are): two m × m blocks at a time beside the sum.
        let mut sum = frame.strain(body_a.strain_operator(grid, Side::A)?, Side::A);
        let b = frame.strain(body_b.strain_operator(grid, Side::B)?, Side::B);
        sum.p += &b.p;
        sum.q += &b.q;
        Some(StrainShare::Operator(sum))
    }

    /// [`Self::strain_of`] under the tractions (`pressure`, `shear`) alone, each body's
    /// [`BodyModel::strain_at`] under its loads in global axes ([`ContactFrame::global_loads`],
    /// the column transformation of [`ContactFrame::strain`]): an error-controlled run's result
    /// (src/adapt.rs), whose outputs need the strain of its solution only.
    pub fn strain_under(
        grid: &ContactGrid,
        bodies: [&dyn BodyModel; 2],
        frame: &ContactFrame,
        pressure: &[f64],
        shear: &[f64],
    ) -> Option<StrainShare> {
        if grid.kind.shares_nodes() {
            return None;
        }
        let mut strain = vec![0.0; grid.n_nodes()];
        for (body, side) in bodies.into_iter().zip([Side::A, Side::B]) {
            let (pg, qg) = frame.global_load_columns(side, pressure, shear);
            let s = body.strain_at(grid, side, pg.as_ref(), qg.as_ref())?;
            for (i, v) in strain.iter_mut().enumerate() {
                *v += s[(i, 0)];
            }
        }
        Some(StrainShare::Under {
            tractions: Tractions::of(pressure, shear),
            strain,
        })
    }

    /// Assembles the problem from the two body models on a grid, in the contact `frame` at
    /// its nodes ([`ContactFrame::global_axes`] for tractions along x and y). The strain
    /// operator, which only the outputs' boundary-integral slip uses, is left out (`strain` is
    /// none): [`Self::strain_of`] adds it, so that the intermediate grids of an error-controlled
    /// run skip it.
    #[allow(clippy::too_many_arguments)]
    pub fn assemble(
        grid: ContactGrid,
        body_a: &dyn BodyModel,
        body_b: &dyn BodyModel,
        derivative: SlipDerivative,
        friction: f64,
        rolling: RollingDirection,
        normal: NormalControl,
        tangential: TangentialControl,
        frame: ContactFrame,
        keep_body_b: bool,
    ) -> Self {
        assert_eq!(frame.normal_angle.len(), grid.n_nodes(), "one frame direction per node");
        // The pair's flexibility is summed where A's lies.
        let mut flex = frame.flexibility(body_a.flexibility(&grid, Side::A), Side::A);
        let fb = frame.flexibility(body_b.flexibility(&grid, Side::B), Side::B);
        flex.hp += &fb.hp;
        flex.hq += &fb.hq;
        flex.wp += &fb.wp;
        flex.wq += &fb.wq;
        // Dropped before the slip operator's blocks are made when not kept: the assembly's peak
        // is then eight m × m blocks, not ten (the braking bore's last pass: 31 MB).
        let kept_b = match keep_body_b {
            true => Some(BodyBShare::Flexibility(fb)),
            false => {
                drop(fb);
                None
            }
        };
        let h0 = grid
            .nodes
            .iter()
            .map(|&x| body_a.profile(x) + body_b.profile(x))
            .collect();
        let gap_slope = grid
            .gauss_points(GAP_SLOPE_POINTS)
            .iter()
            .map(|&(x, _)| body_a.profile_slope(x) + body_b.profile_slope(x))
            .collect();
        let flow_sign = rolling.flow_sign();
        let slip_operator = SlipOperator::new(&grid, derivative, flow_sign);
        let bp = slip_operator.apply_scaled(&flex.wp, flow_sign);
        let bq = slip_operator.apply_scaled(&flex.wq, flow_sign);
        let rigid_slip = frame
            .rigid_slip
            .iter()
            .zip(&slip_operator.creep_weight)
            .map(|(k, e)| k * e)
            .collect();
        Self {
            grid,
            flex,
            body_b: kept_b,
            bp,
            bq,
            slip_operator,
            h0,
            gap_slope,
            friction,
            falling: None,
            nodal_friction: None,
            flow_sign,
            normal,
            tangential,
            strain: None,
            frame,
            rigid_slip,
        }
    }

    /// The same problem with the bodies' flexibilities changed by `changes` (A's, B's; None:
    /// unchanged), each a low-rank term in global axes turned into this problem's frame and
    /// added to the pair's flexibility; the slip operator's blocks follow. Body B's own
    /// flexibility and the strain operator are not carried (the changed problem is solved,
    /// not written).
    pub fn with_flexibility_changes(&self, changes: [Option<&LowRankFlexibility>; 2]) -> Self {
        let mut flex = self.flex.clone();
        self.frame.add_low_rank(&mut flex, &sided(changes), 1.0);
        let bp = self.slip_operator.apply_scaled(&flex.wp, self.flow_sign);
        let bq = self.slip_operator.apply_scaled(&flex.wq, self.flow_sign);
        Self {
            grid: self.grid.clone(),
            flex,
            body_b: None,
            bp,
            bq,
            slip_operator: self.slip_operator.clone(),
            h0: self.h0.clone(),
            gap_slope: self.gap_slope.clone(),
            friction: self.friction,
            falling: self.falling,
            nodal_friction: self.nodal_friction.clone(),
            flow_sign: self.flow_sign,
            normal: self.normal,
            tangential: self.tangential,
            strain: None,
            frame: self.frame.clone(),
            rigid_slip: self.rigid_slip.clone(),
        }
    }

    /// This problem without its slip operator's blocks B_p, B_q (two m × m blocks, which only a
    /// solve reads), while it waits: for its outputs, or as the base of changed problems
    /// ([`WithoutSlipBlocks`]).
    pub fn without_slip_blocks(mut self) -> WithoutSlipBlocks {
        self.bp = Mat::zeros(0, 0);
        self.bq = Mat::zeros(0, 0);
        WithoutSlipBlocks(self)
    }

    /// The friction coefficient μ_i [-] that bounds the shear at node `i`: the frozen nodal
    /// value of a falling law's fixed point, else the constant `friction`.
    pub fn friction_at(&self, i: usize) -> f64 {
        match &self.nodal_friction {
            Some(mu) => mu[i],
            None => self.friction,
        }
    }

    /// The friction coefficient [-] at node `i` of a solution whose slip there is `slip` [-]:
    /// the falling law at that slip ([`falling::FallingLaw::coefficient`]), else
    /// [`Self::friction_at`].
    pub fn friction_of_slip(&self, i: usize, slip: f64) -> f64 {
        match &self.falling {
            Some(law) => law.coefficient(self.friction, slip),
            None => self.friction_at(i),
        }
    }

    /// Number of contact nodes m.
    pub fn n_nodes(&self) -> usize {
        self.grid.n_nodes()
    }

    /// Gap g = h0 − δ0 + H_p p + H_q q at every node [length].
    pub fn gap(&self, p: &[f64], q: &[f64], overlap: f64) -> Vec<f64> {
        let h = self.compression(p, q);
        self.h0.iter().zip(h).map(|(h0, h)| h0 - overlap + h).collect()
    }

    /// Total compression h = H_p p + H_q q (sum of the displacements into the bodies) [length].
    pub fn compression(&self, p: &[f64], q: &[f64]) -> Vec<f64> {
        mat_vec2(&self.flex.hp, p, &self.flex.hq, q)
    }

    /// Relative tangential displacement w = u_xA − u_xB = W_p p + W_q q [length].
    pub fn relative_tangential(&self, p: &[f64], q: &[f64]) -> Vec<f64> {
        mat_vec2(&self.flex.wp, p, &self.flex.wq, q)
    }

    /// Slip s = σ(ξ + k + D w) at every node [-] (paper Eq. 19; k the rigid slip of curved
    /// bodies' surface speeds, zero in global axes: [`frame`]).
    pub fn slip(&self, p: &[f64], q: &[f64], creep: f64) -> Vec<f64> {
        let b = mat_vec2(&self.bp, p, &self.bq, q);
        let e = &self.slip_operator.creep_weight;
        b.into_iter()
            .zip(e)
            .zip(&self.rigid_slip)
            .map(|((v, e), k)| self.flow_sign * (creep * e + k) + v)
            .collect()
    }

    /// Slip velocity s = σ(ξ + k + ∂w/∂x) at every node [-] (k the rigid slip of [`frame`]), for
    /// the outputs: [`Self::slip`] at every
    /// node but the upstream end, whose row in the problem is the datum equation of w (see
    /// [`SlipOperator`]); there the derivative is taken downstream
    /// (src/contact/slip_operator.rs). Same tractions, same solution: only that node differs.
    pub fn slip_velocity(&self, p: &[f64], q: &[f64], creep: f64) -> Vec<f64> {
        let mut s = self.slip(p, q, creep);
        let op = &self.slip_operator;
        if !op.end_velocity_row.is_empty() {
            let dw: f64 = op
                .end_velocity_row
                .iter()
                .map(|&(j, c)| c * self.relative_tangential_at(j, p, q))
                .sum();
            let k = self.frame.rigid_slip[op.upstream_end];
            s[op.upstream_end] = self.flow_sign * (creep + k + dw);
        }
        s
    }

    /// w_j = (W_p p + W_q q)_j, one node of [`Self::relative_tangential`] [length].
    fn relative_tangential_at(&self, j: usize, p: &[f64], q: &[f64]) -> f64 {
        let (wp, wq) = (&self.flex.wp, &self.flex.wq);
        (0..p.len()).map(|k| wp[(j, k)] * p[k] + wq[(j, k)] * q[k]).sum()
    }

    /// Slip from the boundary-integral strain operator, s = σ(ξ + k + ∂w/∂x), if available.
    ///
    /// Panics on a strain kept for other tractions than `p`, `q` ([`StrainShare::Under`]).
    pub fn slip_from_strain(&self, p: &[f64], q: &[f64], creep: f64) -> Option<Vec<f64>> {
        self.strain.as_ref().map(|share| {
            let dw = match share {
                StrainShare::Operator(op) => mat_vec2(&op.p, p, &op.q, q),
                StrainShare::Under { tractions, strain } => {
                    tractions.assert_are(p, q, "the surface strain");
                    strain.clone()
                }
            };
            dw.into_iter()
                .zip(&self.frame.rigid_slip)
                .map(|(dw, k)| self.flow_sign * (creep + k + dw))
                .collect()
        })
    }
}

/// Surface displacements of the two bodies at the contact nodes [length].
#[derive(Debug, Clone)]
pub struct SurfaceDisplacements {
    /// Normal displacement of A, positive into A (+y).
    pub normal_a: Vec<f64>,
    /// Tangential displacement of A along +x.
    pub tangential_a: Vec<f64>,
    /// Normal displacement of B, positive into B (−y).
    pub normal_b: Vec<f64>,
    /// Tangential displacement of B along +x.
    pub tangential_b: Vec<f64>,
}

impl ContactProblem {
    /// Each body's surface displacements under the tractions (half-space bodies: relative to
    /// their logarithmic datum).
    ///
    /// Panics on a problem whose `body_b` was dropped (an intermediate grid of src/adapt.rs,
    /// which never reaches the outputs), or kept for other tractions than `p`, `q`.
    pub fn surface_displacements(&self, p: &[f64], q: &[f64]) -> SurfaceDisplacements {
        let (normal_b, tangential_b) = match self
            .body_b
            .as_ref()
            .expect("the final grid's problem keeps body B's share")
        {
            BodyBShare::Flexibility(f) => (f.normal(p, q), f.tangential(p, q)),
            BodyBShare::Under(load) => {
                load.tractions.assert_are(p, q, "body B's displacement");
                (load.normal.clone(), load.tangential.clone())
            }
        };
        let less = |total: Vec<f64>, of_b: &[f64]| total.iter().zip(of_b).map(|(t, v)| t - v).collect();
        SurfaceDisplacements {
            normal_a: less(self.compression(p, q), &normal_b),
            tangential_a: less(self.relative_tangential(p, q), &tangential_b),
            normal_b,
            // w_B = −u_xB in the pair convention.
            tangential_b: tangential_b.into_iter().map(|v| -v).collect(),
        }
    }
}

/// The pair's surface-strain operator ∂w/∂x, for the boundary-integral check of the slip.
#[derive(Debug, Clone)]
pub enum StrainShare {
    /// The operator's blocks in the contact frame ([`ContactProblem::strain_of`]).
    Operator(StrainOperator),
    /// Its product with one set of tractions only, the result's
    /// ([`ContactProblem::strain_under`]).
    Under {
        /// The tractions it is for.
        tractions: Tractions,
        /// ∂w/∂x of the pair at the nodes [-].
        strain: Vec<f64>,
    },
}

/// The nodal tractions a product was kept for ([`StrainShare::Under`], [`BodyBLoad`]).
#[derive(Debug, Clone)]
pub struct Tractions {
    /// p at the nodes [stress].
    pub pressure: Vec<f64>,
    /// q at the nodes [stress].
    pub shear: Vec<f64>,
}

impl Tractions {
    fn of(pressure: &[f64], shear: &[f64]) -> Self {
        Self {
            pressure: pressure.to_vec(),
            shear: shear.to_vec(),
        }
    }

    /// Panics unless (`p`, `q`) are these tractions: a product kept for the result's
    /// tractions answers for them only (`what` names it in the message).
    fn assert_are(&self, p: &[f64], q: &[f64], what: &str) {
        assert!(
            self.pressure == p && self.shear == q,
            "{what} was kept for the final tractions, not these"
        );
    }
}

/// Body B's share of the pair's flexibility, for the bodies' own surface displacements.
#[derive(Debug, Clone)]
pub enum BodyBShare {
    /// Its flexibility in the contact frame (a grid's assembly makes it anyway).
    Flexibility(Flexibility),
    /// Its displacements under one set of tractions only, the result's (an error-controlled
    /// run's final grid, src/adapt.rs: four m × m blocks fewer than the flexibility).
    Under(BodyBLoad),
}

/// Body B's displacements in the contact frame under the nodal tractions `pressure`, `shear`
/// (pair convention, as [`Flexibility::normal`] and [`Flexibility::tangential`] give them).
#[derive(Debug, Clone)]
pub struct BodyBLoad {
    /// The tractions they are for.
    pub tractions: Tractions,
    /// h_B = (H_p p + H_q q)_B [length].
    pub normal: Vec<f64>,
    /// w_B = (W_p p + W_q q)_B [length].
    pub tangential: Vec<f64>,
}

impl BodyBLoad {
    /// Body B's displacements under (`pressure`, `shear`) from its model `body`, turned into
    /// `frame` as [`ContactFrame::flexibility`] turns its blocks: the load into global axes
    /// per column ([`ContactFrame::global_loads`]), h' = h − tan ψ_i w per row.
    pub fn of(body: &dyn BodyModel, grid: &ContactGrid, frame: &ContactFrame, pressure: &[f64], shear: &[f64]) -> Self {
        let (pg, qg) = frame.global_load_columns(Side::B, pressure, shear);
        let [h, w] = body.displacements(grid, Side::B, pg.as_ref(), qg.as_ref());
        let tangential: Vec<f64> = (0..grid.n_nodes()).map(|i| w[(i, 0)]).collect();
        let normal = (0..grid.n_nodes())
            .map(|i| h[(i, 0)] - frame.normal_angle[i].tan() * tangential[i])
            .collect();
        Self {
            tractions: Tractions::of(pressure, shear),
            normal,
            tangential,
        }
    }
}

/// The changes of bodies A and B (None: unchanged) with their sides.
fn sided(changes: [Option<&LowRankFlexibility>; 2]) -> Vec<(&LowRankFlexibility, Side)> {
    changes
        .into_iter()
        .zip([Side::A, Side::B])
        .filter_map(|(c, side)| c.map(|c| (c, side)))
        .collect()
}

/// A contact problem that waits without its slip operator's blocks B_p = σ D W_p and
/// B_q = σ D W_q: two m × m blocks fewer held. An error-controlled run holds its result so
/// while the bodies' meshes are checked (the result's outputs come after, src/adapt.rs), and
/// holds the base of the checks' changed problems so, whose blocks are made for the change
/// alone. Everything else is the problem's; [`Self::with_slip_blocks`] makes the blocks again
/// from W and gives the whole problem back, the only way to a problem that can be solved.
#[derive(Debug, Clone)]
pub struct WithoutSlipBlocks(ContactProblem);

impl WithoutSlipBlocks {
    /// The contact grid of the problem.
    pub fn grid(&self) -> &ContactGrid {
        &self.0.grid
    }

    /// The contact's directions at the nodes ([`ContactProblem::frame`]).
    pub fn frame(&self) -> &ContactFrame {
        &self.0.frame
    }

    /// Number of contact nodes m.
    pub fn n_nodes(&self) -> usize {
        self.0.n_nodes()
    }

    /// The whole problem again, its slip blocks B_p = σ D W_p and B_q = σ D W_q made from W.
    pub fn with_slip_blocks(self) -> ContactProblem {
        let mut pb = self.0;
        pb.bp = pb.slip_operator.apply_scaled(&pb.flex.wp, pb.flow_sign);
        pb.bq = pb.slip_operator.apply_scaled(&pb.flex.wq, pb.flow_sign);
        pb
    }

    /// `f` of the problem with the bodies' flexibilities changed by `changes` as
    /// [`ContactProblem::with_flexibility_changes`] makes it, made in this problem's place and
    /// taken back after: no second copy of the pair's four blocks, and the slip blocks made for
    /// the changed flexibility only (dropped again after `f`). Taking the change back leaves
    /// the flexibility within round-off of its values (the sum and difference of the same
    /// terms).
    pub fn with_flexibility_changes<R>(
        &mut self,
        changes: [Option<&LowRankFlexibility>; 2],
        f: impl FnOnce(&ContactProblem) -> R,
    ) -> R {
        let changes = sided(changes);
        let pb = &mut self.0;
        pb.frame.add_low_rank(&mut pb.flex, &changes, 1.0);
        pb.bp = pb.slip_operator.apply_scaled(&pb.flex.wp, pb.flow_sign);
        pb.bq = pb.slip_operator.apply_scaled(&pb.flex.wq, pb.flow_sign);
        let result = f(pb);
        pb.frame.add_low_rank(&mut pb.flex, &changes, -1.0);
        pb.bp = Mat::zeros(0, 0);
        pb.bq = Mat::zeros(0, 0);
        result
    }
}

#[cfg(test)]
mod tests {
    use crate::body::Side;

    /// Each body's surface displacements are its own flexibility applied to the tractions (A's
    /// is kept as the pair's less B's): for a dissimilar pair, against each model's flexibility
    /// assembled on its own, and A's and B's normal displacements add up to the compression.
    #[test]
    fn each_bodys_surface_displacements_are_its_own_flexibility_applied() {
        let path = crate::case::shipped("dissimilar_al_steel_075.yaml");
        let loaded = crate::case::load(&path, &[]).expect("shipped case loads");
        let scene = crate::scene::Scene::from_case(&loaded).expect("scene");
        let (models, pb) = scene.assemble().expect("assembles");
        let x = &pb.grid.nodes;
        let p: Vec<f64> = x.iter().map(|&x| 100.0 * (1.0 - x * x).max(0.0).sqrt()).collect();
        let q: Vec<f64> = x.iter().zip(&p).map(|(x, p)| 0.2 * p * x).collect();
        let d = pb.surface_displacements(&p, &q);
        let own = |side: Side, k: usize| models[k].model().flexibility(&pb.grid, side);
        let (fa, fb) = (own(Side::A, 0), own(Side::B, 1));
        let close = |got: &[f64], want: &[f64], what: &str| {
            let scale = want.iter().fold(0.0f64, |m, v| m.max(v.abs()));
            for (g, w) in got.iter().zip(want) {
                assert!((g - w).abs() <= 1e-12 * scale, "{what}: {g} vs {w}");
            }
        };
        close(&d.normal_a, &fa.normal(&p, &q), "u_n_A");
        close(&d.tangential_a, &fa.tangential(&p, &q), "u_t_A");
        close(&d.normal_b, &fb.normal(&p, &q), "u_n_B");
        let minus_wb: Vec<f64> = fb.tangential(&p, &q).iter().map(|v| -v).collect();
        close(&d.tangential_b, &minus_wb, "u_t_B");
        let sum: Vec<f64> = d.normal_a.iter().zip(&d.normal_b).map(|(a, b)| a + b).collect();
        close(&sum, &pb.compression(&p, &q), "u_n_A + u_n_B");
    }
}
