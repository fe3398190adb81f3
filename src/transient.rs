//! Transient rolling: a history of steps instead of the steady state, on any body model.
//!
//! Kalker's transient formulation in the frame that moves with the contact (Kalker,
//! *Three-dimensional elastic bodies in rolling contact*, 1990, §1.3; J.A. González and
//! R. Abascal, IJNME 53:843–874, 2002, for the same generalized Newton method): over a step
//! in which the contact rolls a distance Δ, the slip of the material point at node x_i is the
//! rigid shift plus the change of the relative tangential displacement w = u_xA − u_xB at that
//! material point, which one step earlier lay at x_i − σΔ (σ the material's flow sign):
//!
//! ```text
//! S_i = Δ·σ(ξ + k_i) + w_i(t) − w(x_i − σΔ, t − 1)          (distance over the step)
//! s_i = S_i / Δ = σ(ξ + k_i) + (W_p p + W_q q)_i / Δ − w*_i / Δ
//! ```
//!
//! with ξ the step's mean creepage (its rigid shift over Δ) and k the rigid slip of curved
//! bodies' surface speeds. A rolling step measures w from the material at the grid's upstream
//! end u (w − w_u in both terms, the datum of the steady problem's creepage): a half-space's
//! logarithmic displacement has a constant that moves with Q, whose change over a step would
//! otherwise act as a creepage of its own (under a prescribed ξ the force would settle over
//! many contact widths instead of one). [`energy`] balances each step's work, stored energy
//! and dissipation. As the history repeats, w(t) = w(t − 1) and (w_i − w(x_i − σΔ))/Δ
//! is the upwind difference of σ ∂w/∂x over one step: the steady problem (paper Eq. 7) is the
//! limit. A step with Δ = 0 is a shift without rolling (tangential loading of bodies pressed
//! together: Cattaneo–Mindlin); its slip is a distance (S with L = 1 length unit) and its "ξ"
//! is the rigid shift [length].
//!
//! Each step is the steady contact problem of [`crate::contact`] with its slip blocks
//! B = W/L (L = Δ, or 1 for a shift) and its constant slip term k − σw*/L, so the same solver
//! (generalized Newton with line search) solves it, warm-started from the previous step: the
//! bodies' flexibilities are assembled once for the whole history.
//!
//! **The previous displacement at the material point.** w* is the previous step's w
//! interpolated at x_i − σΔ by the grid's own shape functions (quadratic on quadratic
//! elements: exact where Δ is a multiple of the element length, whose shift maps every node of
//! a uniform grid of discontinuous elements onto a node; else an interpolation error O(h³)).
//! Material that enters the grid from upstream carries the displacement of the grid's
//! upstream end (outside the contact on a sensible grid, where it has no traction to act on).
//!
//! **The datum of a step.** Measuring w from the upstream end is a choice the plane problem
//! leaves open: a half-plane's displacement is fixed only up to a constant, and that constant
//! moves with the total shear Q. A 2D model computed on a strip of width b of a 3D half-space
//! (CONTACT's one row of elements, DY = b) measures displacements from infinity instead: on the
//! strip's centre line, Cerruti's solution integrated over the width is the half-plane's
//! −B ∫ q(s) ln(|x − s|/L) ds with L = b·e^(ν/(1−ν)), to O((a/b)²). There the upstream material
//! moves with Q, and over a step that changes Q the move is a rigid shift that acts as a
//! creepage of its own until Q settles. [`History::set_datum_length`] takes that datum: the
//! upstream end's w is then the displacement −ΣB ∫ q(s) ln(|x_u − s|/L) ds of a half-plane pair
//! (B = 2(1−ν²)/(πE) of each deformable body's material), the rest of w relative to it as
//! before. A steady state does not depend on it (only ∂w/∂x enters); a step that changes Q does
//! (docs/friction.md, "Against CONTACT", cases 2 and 4).

pub mod energy;

use crate::contact::methods;
use crate::contact::{ContactProblem, NormalControl, SolveReport, SolverSettings, State, TangentialControl};
use crate::error::Error;

/// Why a history stops.
#[derive(Debug, thiserror::Error)]
pub enum TransientError {
    /// The scene could not be assembled.
    #[error(transparent)]
    Scene(#[from] Error),
    /// A viscoelastic body: its kernels are the steady-rolling ones.
    #[error(
        "body {body}: material `{material}` is viscoelastic, whose kernels rollbem ages along the steady \
         material path; a transient history would need the material's own state carried from step to \
         step, which is not built: give an elastic material for a history"
    )]
    Viscoelastic {
        /// `A` or `B`.
        body: &'static str,
        /// The material's name.
        material: String,
    },
    /// An error-controlled grid: a history keeps one grid.
    #[error(
        "contact.grid.tolerance: a transient history keeps one grid for all its steps (the previous \
         step's displacements live on it): give a fixed grid (contact.grid.elements) instead"
    )]
    AdaptiveGrid,
    /// A step's rolling distance is negative or not finite.
    #[error("a step's rolling distance must be >= 0 and finite (value = {0})")]
    StepDistance(f64),
    /// A step's contact problem did not converge; the steps before it stand.
    #[error(
        "the step ending at rolling distance {rolled} did not converge ({iterations} iterations, residual \
         {residual:e}); the steps before it stand"
    )]
    NotConverged {
        /// The rolling distance at the end of the step [length].
        rolled: f64,
        /// Newton iterations spent.
        iterations: usize,
        /// The last residual.
        residual: f64,
    },
}
use crate::grid::ContactGrid;
use crate::scene::{BodyModels, Scene};

/// One step of a history: how far the contact rolls and what is prescribed.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Step {
    /// Rolling distance Δ ≥ 0 of the step [length]; 0 is a shift without rolling.
    pub distance: f64,
    /// The normal control of the step.
    pub normal: NormalControl,
    /// The tangential control of the step (under a force or ratio, ξ is the step's unknown:
    /// its mean creepage, or for a shift its rigid shift [length]).
    pub tangential: TangentialControl,
}

/// The solution of one step.
#[derive(Debug, Clone)]
pub struct StepSolution {
    /// The step.
    pub step: Step,
    /// Distance rolled from the start of the history to the end of this step [length].
    pub rolled: f64,
    /// The contact state at the end of the step (pressure, shear [stress], slip, overlap, ξ).
    pub state: State,
    /// Newton iterations the step took.
    pub iterations: usize,
    /// The step's tangential energy balance: dissipation, work over the rigid shift and change
    /// of the stored energy [force] (energy per unit length; [`energy`]).
    pub energy: energy::StepEnergy,
}

/// A history on a scene's grid: its contact problem, assembled once.
pub struct History {
    models: BodyModels,
    problem: ContactProblem,
    /// The steady problem's constant slip term k (the rigid slip of the surface speeds).
    rigid_slip: Vec<f64>,
    /// The slip length L of the problem's blocks (Δ, or 1 for a shift) and their datum node
    /// (a rolling step's upstream end); None before the first step.
    length: Option<(f64, Option<usize>)>,
    settings: SolverSettings,
    /// The relative tangential displacement w at the end of the last step [length].
    displacement: Vec<f64>,
    /// The compression h (displacements into both bodies) at the end of the last step [length].
    compression: Vec<f64>,
    state: Option<State>,
    /// The solver's report of the last step solved.
    report: Option<SolveReport>,
    rolled: f64,
    /// The falling friction law of the scene, if any: it acts in rolling steps (whose slip per
    /// rolled distance times the speed is a slip velocity); a shift, without duration, slips
    /// under the static coefficient.
    falling: Option<crate::contact::falling::FallingLaw>,
    /// The Newton systems' memory, kept from step to step with the last LU factors: a step
    /// whose active sets are the last system's solves without factoring (most rolling steps
    /// once the history is smooth; [`methods::Workspace::keeping_factors`]).
    workspace: methods::Workspace,
    /// Where the solve of a rolling step under a falling law starts ([`Self::set_initial_slip`]).
    initial: crate::contact::falling::InitialSlip,
    /// The sum of the deformable bodies' half-plane coefficients B = 2(1−ν²)/(πE) [1/stress].
    log_coefficient: f64,
    /// The upstream end's displacement per nodal shear under the datum length of
    /// [`Self::set_datum_length`] (module docs) [length/stress]; None: the upstream end is the datum.
    datum_row: Option<Vec<f64>>,
}

impl History {
    /// The history of `scene` on its grid, from unloaded bodies. A scene with an
    /// error-controlled grid is refused: a history holds one grid (the previous step's
    /// displacements live on it).
    pub fn new(scene: &Scene) -> Result<Self, TransientError> {
        if scene.grid_control.is_some() {
            return Err(TransientError::AdaptiveGrid);
        }
        let case = &scene.case.case;
        for (body, spec) in [("A", &case.bodies.a), ("B", &case.bodies.b)] {
            let Some(material) = spec.material_name() else { continue };
            if case.materials.get(material).is_some_and(|m| m.viscoelastic.is_some()) {
                return Err(TransientError::Viscoelastic {
                    body,
                    material: material.to_string(),
                });
            }
        }
        let (models, mut problem) = scene.assemble()?;
        let falling = problem.falling;
        let log_coefficient = [&case.bodies.a, &case.bodies.b]
            .into_iter()
            .filter_map(|spec| spec.material_name())
            .map(|name| scene.case.material(name).halfplane_log_coefficient())
            .sum();
        // Every row carries the rigid shift: the steady problem's datum row (no creepage at
        // the upstream end) has no place in a step, whose w is absolute.
        problem.slip_operator.creep_weight.iter_mut().for_each(|e| *e = 1.0);
        let m = problem.n_nodes();
        Ok(Self {
            models,
            report: None,
            rigid_slip: problem.rigid_slip.clone(),
            problem,
            length: None,
            settings: scene.solver,
            displacement: vec![0.0; m],
            compression: vec![0.0; m],
            state: None,
            rolled: 0.0,
            falling,
            workspace: methods::Workspace::keeping_factors(),
            initial: Default::default(),
            log_coefficient,
            datum_row: None,
        })
    }

    /// The history of `scene` continuing from `state`, a solution of the scene's steady problem
    /// on the same grid (CONTACT's transient step after a steady case): the next rolling step's
    /// previous displacement is the steady state's w and its warm start `state`. With
    /// `contact.slip_derivative: first_order` and steps of one node spacing, the steady state is
    /// the history's own fixed point (module docs).
    pub fn from_steady(scene: &Scene, state: State) -> Result<Self, TransientError> {
        let mut history = Self::new(scene)?;
        history.displacement = history.problem.relative_tangential(&state.pressure, &state.shear);
        history.state = Some(state);
        Ok(history)
    }

    /// Where the rolling steps under a falling law start from now on: the last step's state
    /// (the default), or from below or above (CONTACT's initial slip estimate INISLP = 1 or −1;
    /// [`crate::contact::falling::InitialSlip`]): a step of a steep law can have several
    /// solutions, and the start selects one (docs/friction.md).
    pub fn set_initial_slip(&mut self, initial: crate::contact::falling::InitialSlip) {
        self.initial = initial;
    }

    /// Measures the displacement of the rolling steps from now on from the datum length `length`
    /// [length] of a half-plane pair (module docs, "The datum of a step"): a 2D model on a strip
    /// of width b of a 3D half-space (CONTACT's DY) has `length` = b·e^(ν/(1−ν)). None (the
    /// default) measures it from the material at the grid's upstream end, which then takes no
    /// part in a change of Q.
    pub fn set_datum_length(&mut self, length: Option<f64>) {
        self.datum_row = length.map(|ell| {
            let grid = &self.problem.grid;
            let u = self.problem.slip_operator.upstream_end;
            let log = crate::body::half_space::influence_matrix(grid, crate::body::half_space::Kernel::Log);
            let b = self.log_coefficient;
            (0..grid.nodes.len())
                .map(|j| -b * (log[(u, j)] - grid.weights[j] * ell.ln()))
                .collect()
        });
        // The slip blocks are rebuilt by the next step.
        self.length = None;
    }

    /// The upstream end's displacement under `shear` by the datum length (0 without one).
    fn datum_displacement(&self, shear: &[f64]) -> f64 {
        self.datum_row
            .as_ref()
            .map_or(0.0, |c| c.iter().zip(shear).map(|(c, q)| c * q).sum())
    }

    /// The contact grid of the history.
    pub fn grid(&self) -> &ContactGrid {
        &self.problem.grid
    }

    /// The problem of the last step solved (its grid, flexibilities and controls).
    pub fn problem(&self) -> &ContactProblem {
        &self.problem
    }

    /// The bodies' models, built once for the history.
    pub fn models(&self) -> &BodyModels {
        &self.models
    }

    /// The solver's report of the last step solved (None before the first).
    pub fn report(&self) -> Option<&SolveReport> {
        self.report.as_ref()
    }

    /// The Newton systems of the history so far solved with new LU factors and with the kept
    /// factors of an earlier system with the same matrix.
    pub fn factorisations(&self) -> (usize, usize) {
        self.workspace.factorisations()
    }

    /// Solves the next step, warm-started from the last (a rolling step; a shift starts cold).
    /// A step that does not converge is an error naming its distance; the history before it
    /// stands.
    pub fn advance(&mut self, step: Step) -> Result<StepSolution, TransientError> {
        if !(step.distance >= 0.0 && step.distance.is_finite()) {
            return Err(TransientError::StepDistance(step.distance));
        }
        let rolling = step.distance > 0.0;
        let length = if rolling { step.distance } else { 1.0 };
        // A rolling step measures w from the material at the grid's upstream end (the datum
        // node u): w − w_u, whose change over the step does not depend on the constant of a
        // half-space's logarithmic displacement (which moves with Q).
        let datum = rolling.then_some(self.problem.slip_operator.upstream_end);
        if self.length != Some((length, datum)) {
            self.problem.bp = blocks(&self.problem.flex.wp, length, datum);
            self.problem.bq = blocks(&self.problem.flex.wq, length, datum);
            if let (Some(c), true) = (&self.datum_row, rolling) {
                for (j, c) in c.iter().enumerate() {
                    self.problem.bq.col_mut(j).iter_mut().for_each(|b| *b += c / length);
                }
            }
            self.length = Some((length, datum));
        }
        let sigma = self.problem.flow_sign;
        let earlier = displacement_upstream(&self.problem.grid, &self.displacement, sigma * step.distance);
        let previous_shear = self.state.as_ref().map(|s| s.shear.as_slice());
        let datum_before = if rolling {
            previous_shear.map_or(0.0, |q| self.datum_displacement(q))
        } else {
            0.0
        };
        let before = datum.map_or(0.0, |u| self.displacement[u]) - datum_before;
        for ((k, k0), w) in self.problem.rigid_slip.iter_mut().zip(&self.rigid_slip).zip(&earlier) {
            *k = k0 - sigma * (w - before) / length;
        }
        self.problem.normal = step.normal;
        self.problem.tangential = step.tangential;
        self.problem.falling = self.falling.filter(|_| rolling);
        // A shift starts from the solver's own start vector: from the pressed state every node
        // sticks and the Newton method frees the slip zones about one node an iteration (the
        // Cattaneo shift on 81 elements: 56 iterations warm, 9 cold).
        let mut warm = if step.distance > 0.0 { self.state.clone() } else { None };
        // A prescribed overlap or creepage is not an unknown of the solver: it reads it from the
        // start vector, so the warm start carries the step's own value, not the last step's.
        if let Some(w) = warm.as_mut() {
            if let NormalControl::Overlap(d) = step.normal {
                w.overlap = d;
            }
            if let TangentialControl::Creep(c) = step.tangential {
                w.creep = c;
            }
        }
        let side = self.initial;
        let (state, report) = match self.problem.falling {
            Some(law) if side != crate::contact::falling::InitialSlip::Warm => {
                let newton = &self.settings.newton;
                crate::contact::falling::solve_from_side(&self.problem, &law, newton, warm, side, &mut self.workspace)
            }
            _ => methods::solve_from_in(&self.problem, &self.settings, warm, &mut self.workspace),
        };
        if !report.converged {
            return Err(TransientError::NotConverged {
                rolled: self.rolled + step.distance,
                iterations: report.iterations,
                residual: report.residual,
            });
        }
        let displacement = self.problem.relative_tangential(&state.pressure, &state.shear);
        let compression = self.problem.compression(&state.pressure, &state.shear);
        let datum_moved = if rolling {
            let before = self.state.as_ref().map_or(0.0, |s| self.datum_displacement(&s.shear));
            self.datum_displacement(&state.shear) - before
        } else {
            0.0
        };
        let energy = self.energy(&state, [&displacement, &compression], step.distance, datum, datum_moved);
        self.displacement = displacement;
        self.compression = compression;
        self.rolled += step.distance;
        self.state = Some(state.clone());
        self.report = Some(report.clone());
        Ok(StepSolution {
            step,
            rolled: self.rolled,
            state,
            iterations: report.iterations,
            energy,
        })
    }

    /// The energy balance of the step just solved into `state` (w and h at its end in
    /// `[displacement, compression]`) against the last step's (still in `self`), its rolled
    /// distance `distance`, datum node and the move `datum_moved` of the upstream end by the datum length.
    fn energy(
        &self,
        state: &State,
        [displacement, compression]: [&[f64]; 2],
        distance: f64,
        datum: Option<usize>,
        datum_moved: f64,
    ) -> energy::StepEnergy {
        let pb = &self.problem;
        let sigma = pb.flow_sign;
        let length = if distance > 0.0 { distance } else { 1.0 };
        let slip: Vec<f64> = pb
            .slip(&state.pressure, &state.shear, state.creep)
            .iter()
            .map(|s| s * length)
            .collect();
        let rigid: Vec<f64> = self.rigid_slip.iter().map(|k| sigma * length * k).collect();
        let zero = vec![0.0; pb.n_nodes()];
        let (previous_pressure, previous_shear, previous_overlap) = self
            .state
            .as_ref()
            .map_or((&zero, &zero, 0.0), |s| (&s.pressure, &s.shear, s.overlap));
        let moved = datum.map_or(0.0, |u| displacement[u] - self.displacement[u]) - datum_moved;
        // The normal fields at each node's material point one step earlier (module docs of
        // [`energy`]): the profile h₀ stands in the contact's frame, the material moves by σΔ.
        let upstream = |v: &[f64]| displacement_upstream(&pb.grid, v, sigma * distance);
        let previous_gap: Vec<f64> = pb
            .h0
            .iter()
            .zip(&self.compression)
            .map(|(h0, h)| h0 - previous_overlap + h)
            .collect();
        let profile_change: Vec<f64> = pb.h0.iter().zip(upstream(&pb.h0)).map(|(a, b)| a - b).collect();
        energy::step_energy(&energy::StepFields {
            weights: &pb.grid.weights,
            shear: &state.shear,
            slip: &slip,
            displacement,
            previous_shear,
            previous_displacement: &self.displacement,
            pressure: &state.pressure,
            compression,
            previous_pressure,
            previous_compression: &self.compression,
            previous_gap_upstream: &upstream(&previous_gap),
            profile_change: &profile_change,
            approach_change: state.overlap - previous_overlap,
            rigid_slip: &rigid,
            shift: sigma * length * state.creep - moved,
        })
    }
}

/// The slip blocks (W − 1·W_u)/L of a flexibility block W [length/stress]: each row less the
/// datum node u's row (none for a shift), over the slip length L [length].
fn blocks(w: &faer::Mat<f64>, length: f64, datum: Option<usize>) -> faer::Mat<f64> {
    faer::Mat::from_fn(w.nrows(), w.ncols(), |i, j| {
        (w[(i, j)] - datum.map_or(0.0, |u| w[(u, j)])) / length
    })
}

/// w at x_i − `shift` for every node x_i [length]: the grid's interpolation of the nodal
/// values `w`, the points upstream of the grid given the value at its end.
pub fn displacement_upstream(grid: &ContactGrid, w: &[f64], shift: f64) -> Vec<f64> {
    if shift == 0.0 {
        return w.to_vec();
    }
    let (lo, hi) = (grid.edges[0], grid.edges[grid.n_elements()]);
    grid.nodes
        .iter()
        .map(|x| grid.interpolate(w, (x - shift).clamp(lo, hi)))
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::grid::ElementKind;

    /// The shifted interpolation is exact for a quadratic on quadratic elements at any shift,
    /// and takes the end value beyond the grid.
    #[test]
    fn the_previous_displacement_is_interpolated_exactly_for_a_quadratic() {
        let grid = ContactGrid::uniform(ElementKind::DiscontinuousQuadratic, 8, -2.0, 2.0);
        let f = |x: f64| 0.3 + x - 0.7 * x * x;
        let w: Vec<f64> = grid.nodes.iter().map(|&x| f(x)).collect();
        for shift in [0.1, 0.5, -0.37] {
            let moved = displacement_upstream(&grid, &w, shift);
            for (x, v) in grid.nodes.iter().zip(&moved) {
                let at = (x - shift).clamp(-2.0, 2.0);
                assert!((v - f(at)).abs() < 1e-12, "shift {shift}, x {x}: {v} against {}", f(at));
            }
        }
    }
}
