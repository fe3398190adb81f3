//! Sequences of runs of one scene: runs that differ only in their loads, friction coefficient,
//! rolling speed or solver settings share one assembly of the bodies and each starts from the
//! solution of the run solved before it.
//!
//! A sweep over Q/μP, the normal force, the creepage or μ solves the same contact problem
//! (paper Eq. 21) with other controls: the bodies' flexibilities at the contact nodes (and a
//! BEM body's condensation to them), the slip operator, the undeformed gap and the strain
//! operator depend on the bodies and the grid only. [`Shared`] builds them once from a base
//! scene; a [`Chain`] (one per worker thread) holds its own copy of the contact problem, sets
//! each run's controls (μ, the normal and tangential control) in it and solves it warm-started
//! from the last run it solved.
//!
//! **What shares.** A run shares when its case differs from the base's only in `load.*`
//! (normal and tangential loads, creepage, and `load.speed` unless a material is viscoelastic,
//! whose kernels age with the speed), `contact.friction`, `solver.*`, `title` and `output.*`,
//! *and* its scene has the base's contact grid node for node: a normal load sizes the uniform
//! grid around its Hertz contact (unless `contact.grid.half_length` or a body's mesh fixes it),
//! so a run of another normal load on such a grid builds its own ([`Shared::shares`] tells).
//! Error-controlled grids (`contact.grid.tolerance`) build each run's grids themselves and are
//! refused ([`SequenceError::AdaptiveGrid`]); a [`GridChain`] starts each of their runs warm
//! from the last run's result instead ("Error-controlled chains" below).
//!
//! **Error-controlled chains.** A [`GridChain`] solves each run with
//! [`crate::adapt::solve_from`], warm from the last converged run's result: by default
//! ([`GridReuse::StartGrid`], the sweep's) its passes start on the run's own start grid, the
//! last run's solution carried to it; [`GridReuse::LastGrid`] starts them on the last run's
//! final grid, merged back a number of levels (src/adapt/start.rs). Either way a run meets its
//! tolerance by its own estimate and a-priori lengths, as a run alone does. The last run's grid
//! saves no pass (examples/sweep_cost.rs `--adaptive`, docs/performance.md "Sweeps"): its
//! grading sits at the last run's stick/slip point, the run's own has moved by far more than
//! the a-priori length there (30·tolerance·a), so the first pass does not meet the tolerance
//! and the run takes as many passes as from the start grid. Unmerged, the grading of every
//! earlier run's point piles up along the chain (carter2d_contact at 1e-4, 20 values of Q/μP:
//! 422 elements a run against 167 cold, 16 times the CPU time); merged back 4 levels the grids
//! are about the cold runs' and the chain 1.05–1.18 times as fast. On the start grid the chain
//! is 1.05 times as fast, from the warm start alone (7.4–8.9 Newton iterations a run against
//! 12.1–12.4 cold; the solves are the smaller part of such a run), and the passes see the cold
//! run's solutions to the Newton tolerance, so they refine to the cold run's grids: a run's
//! result is the cold run's to the Newton tolerance, whatever run precedes it in its chain,
//! so a sweep's results do not depend on its number of threads, its shards or a resumed
//! sweep's chains (tests/validation/sequence.rs, tests/cli/sweep.rs). Started on a merged
//! grid, a run's result would depend on its chain by up to about twice the tolerance (each is
//! within it of the exact solution): the sweep starts on the start grid.
//!
//! **The warm start.** The Newton method of [`crate::contact`] solves the semismooth equations
//! of the contact and friction conditions, whose projections fix at each iterate which nodes
//! are in contact, in stick and in slip (the active sets). Started from the neighbour's
//! solution (its tractions, gap, slip, overlap and creepage; a prescribed overlap or creepage
//! set to the run's own), its first step is linearised about the neighbour's active sets and
//! taken in full, so it moves every node whose state the new controls change at once (a
//! searched first step would be cut short by the neighbour's small merit and free the nodes one
//! an iteration); the line search applies from the second step on. Close runs differ in a few
//! nodes near the contact edges and the stick–slip point, so few iterations remain. The method with line
//! search is globally convergent, so the start changes the iteration count, not the solution
//! (to the Newton tolerance). From a chain's third run on, when the last three runs' controls
//! lie on one line (a sweep of one key in steps), the start is the secant extrapolation of the
//! last two solutions ([`predicted_start`]): second order in the step where the tractions are
//! smooth in the control, so the iterations left are those of the nodes whose state changes
//! (on 1001 values of Q/μP on 41 elements 0.19 iterations a run against 1.10 from the last
//! solution, examples/sweep_cost.rs). A warm start that has not converged within [`WARM_START_BUDGET`]
//! iterations falls back to the cold start and its restarts
//! ([`crate::contact::restart::solve_neighbour`]); only a converged run is the
//! next one's start.

use crate::contact::methods::{self, Workspace};
use crate::contact::residual::State;
use crate::contact::restart;
use crate::contact::{ContactProblem, NormalControl, TangentialControl};
use crate::error::Error;
use crate::post::{self, Solved, Timings};
use crate::scene::{BodyModels, Scene};
use std::time::Instant;

/// Most Newton iterations a warm start is given before the run falls back to its cold start
/// (cold runs of the shipped cases take 5–12; a warm start that needs more is not paying).
pub const WARM_START_BUDGET: usize = crate::contact::restart::NEIGHBOUR_BUDGET;

/// Why a scene cannot start a sequence.
#[derive(Debug, thiserror::Error)]
pub enum SequenceError {
    /// The scene's bodies could not be built or assembled.
    #[error(transparent)]
    Scene(#[from] Error),
    /// An error-controlled grid builds its own grids for every run.
    #[error(
        "contact.grid.tolerance: an error-controlled grid builds its own grids for every run, so its runs \
         share no assembly; give a fixed grid (contact.grid.elements) to share one"
    )]
    AdaptiveGrid,
}

/// The assembly a sequence shares: the base scene's body models and contact problem.
pub struct Shared {
    base: Scene,
    /// The base case as a tree with the controls' keys (module docs), compared with each run's.
    base_tree: Option<serde_json::Value>,
    models: BodyModels,
    problem: ContactProblem,
    /// Time [s] the shared assembly took (body models and contact problem, condensation
    /// included).
    pub assembly_s: f64,
}

impl Shared {
    /// Builds the body models of `base` and assembles its contact problem once. An
    /// error-controlled grid is refused.
    pub fn new(base: &Scene) -> Result<Self, SequenceError> {
        if base.grid_control.is_some() {
            return Err(SequenceError::AdaptiveGrid);
        }
        let t = Instant::now();
        crate::scene::preflight::check_memory(&base.case, &base.bodies)?;
        let (models, problem) = base.assemble()?;
        Ok(Self {
            base_tree: serde_json::to_value(&base.case.case).ok(),
            base: base.clone(),
            models,
            problem,
            assembly_s: t.elapsed().as_secs_f64(),
        })
    }

    /// The base scene.
    pub fn base(&self) -> &Scene {
        &self.base
    }

    /// Whether `scene` can be solved with this assembly: its case differs from the base's only
    /// in the keys of the module docs, and its contact grid is the base's node for node.
    pub fn shares(&self, scene: &Scene) -> bool {
        scene.grid_control.is_none() && self.differs_only_in_controls(&scene.case.case) && same_grid(&self.base, scene)
    }

    /// `scene` admitted to this assembly when it [`Self::shares`] it.
    pub fn admit(&self, scene: Scene) -> Option<SharedScene> {
        self.shares(&scene).then_some(SharedScene(scene))
    }

    /// The scene of a case that [`Self::shares`] this assembly, with the base's bodies (no
    /// mesh read again); `None` when the case does not share it. The case's load-dependent
    /// checks ([`crate::scene::preflight::check_derived`]) are made as for any run.
    pub fn scene_of(&self, case: crate::case::LoadedCase) -> Result<Option<SharedScene>, Error> {
        if !self.differs_only_in_controls(&case.case) {
            return Ok(None);
        }
        // The memory was checked for the shared assembly, which a run on the same grid reuses.
        crate::scene::preflight::check_derived(&case, &self.base.bodies)?;
        let scene = Scene::new(case, self.base.bodies.clone());
        let shares = scene.grid_control.is_none() && same_grid(&self.base, &scene);
        Ok(shares.then_some(SharedScene(scene)))
    }

    /// Whether a run's case differs from the base's only in loads, friction, solver and output
    /// settings (and the speed, unless a material is viscoelastic): compared as the case trees
    /// with those keys of the run's set to the base's.
    fn differs_only_in_controls(&self, run: &crate::case::Case) -> bool {
        let base = &self.base.case.case;
        let speed_matters = run.materials.values().any(|m| m.viscoelastic.is_some());
        let mut same = run.clone();
        same.title.clone_from(&base.title);
        same.load = crate::case::schema::LoadSpec {
            speed: if speed_matters { run.load.speed } else { base.load.speed },
            ..base.load.clone()
        };
        same.contact.friction = base.contact.friction;
        same.solver = base.solver.clone();
        same.output = base.output.clone();
        match (serde_json::to_value(&same), &self.base_tree) {
            (Ok(a), Some(b)) => &a == b,
            _ => false,
        }
    }

    /// A chain of runs solved one after the other on this assembly (one per worker thread).
    pub fn chain(&self) -> Chain<'_> {
        Chain {
            shared: self,
            problem: Some(self.problem.clone()),
            last: None,
            before_last: None,
            ws: Workspace::new(),
        }
    }
}

/// A scene that shares a [`Shared`] assembly: only [`Shared::admit`] and [`Shared::scene_of`]
/// make one, so a [`Chain`] solves it without comparing the cases again.
pub struct SharedScene(Scene);

impl SharedScene {
    /// The scene.
    pub fn scene(&self) -> &Scene {
        &self.0
    }
}

/// Whether two scenes have the same contact grid (kind, edges and nodes bit for bit).
fn same_grid(a: &Scene, b: &Scene) -> bool {
    a.grid.kind == b.grid.kind && a.grid.edges == b.grid.edges && a.grid.nodes == b.grid.nodes
}

/// One worker's runs on a [`Shared`] assembly, each warm-started from the last converged one.
pub struct Chain<'a> {
    shared: &'a Shared,
    /// The contact problem with the last run's controls (taken while post-processing holds it).
    problem: Option<ContactProblem>,
    /// The solution of the last converged run, with its controls.
    last: Option<(State, Controls)>,
    /// The converged run before it, when the two followed each other: with the last one it
    /// extrapolates the next run's start ([`predicted_start`]).
    before_last: Option<(State, Controls)>,
    ws: Workspace,
}

/// How a run of a chain was started.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Start {
    /// From the solver's own start (the first run of a chain, or after one that failed).
    Cold,
    /// From the last converged run's solution.
    Warm,
}

impl Chain<'_> {
    /// Forgets the last solutions: the next run starts cold.
    pub fn restart_cold(&mut self) {
        self.last = None;
        self.before_last = None;
    }

    /// Solves the run of `scene` (admitted to the chain's assembly; a scene admitted to another
    /// assembly is an internal error) from the last converged run, post-processes it and hands the solved run to
    /// `read`, whose result is returned with how the run started. `start` is when the run
    /// began (its timings; the shared assembly counts in no run's). A converged run becomes the
    /// next one's start.
    pub fn solve_with<T>(
        &mut self,
        scene: SharedScene,
        start: Instant,
        read: impl FnOnce(&Solved) -> T,
    ) -> Result<(T, Start), Error> {
        let SharedScene(scene) = scene;
        // Admitted by its type; the comparison of the case trees (a fifth of a warm run's
        // time) is repeated in debug builds only, for a scene admitted to another assembly.
        debug_assert!(self.shared.shares(&scene), "a run outside the sequence's assembly");
        let mut problem = self.problem.take().unwrap_or_else(|| self.shared.problem.clone());
        set_controls(&mut problem, &scene);
        let controls = Controls::of(&problem);
        let warm = self.last.as_ref().map(|last| {
            restart::with_prescribed(predicted_start(last, self.before_last.as_ref(), &controls), &problem)
        });
        let how = if warm.is_some() { Start::Warm } else { Start::Cold };
        let t = Instant::now();
        let (state, report) =
            methods::solve_from_neighbour_in(&problem, &scene.solver, warm, WARM_START_BUDGET, &mut self.ws);
        let timings = Timings {
            assembly_s: t.duration_since(start).as_secs_f64(),
            solve_s: t.elapsed().as_secs_f64(),
            total_s: start.elapsed().as_secs_f64(),
            ..Timings::default()
        };
        if report.converged {
            self.before_last = self.last.replace((state.clone(), controls));
        } else {
            self.restart_cold();
        }
        let processed = post::process(scene, &self.shared.models, problem, &state, report, timings);
        match processed {
            Ok(solved) => {
                let out = read(&solved);
                self.problem = Some(solved.problem);
                Ok((out, how))
            }
            Err(e) => {
                self.restart_cold();
                Err(e)
            }
        }
    }

    /// [`Self::solve_with`] keeping the whole solved run.
    pub fn solve(&mut self, scene: SharedScene) -> Result<(Solved, Start), Error> {
        let start = Instant::now();
        let mut kept = None;
        let how = self.solve_with(scene, start, |s| kept = Some(s.clone()))?.1;
        let solved = kept.expect("the solved run was read");
        Ok((solved, how))
    }
}

/// The run's controls in the shared problem: μ (and its falling law), the normal and
/// tangential controls (the only parts of the problem that the shared keys change).
fn set_controls(problem: &mut ContactProblem, scene: &Scene) {
    problem.friction = scene.friction;
    // A falling law carries the speed (its static μ is the problem's friction): the run's own.
    problem.falling = scene.falling;
    problem.normal = scene.normal;
    problem.tangential = scene.tangential;
}

/// The controls a sequence varies, as numbers: μ, the normal and the tangential control's
/// values, and which kind each control is (a run of another kind is not on the same line).
#[derive(Debug, Clone, Copy, PartialEq)]
struct Controls {
    values: [f64; 3],
    kinds: [u8; 2],
}

impl Controls {
    fn of(problem: &ContactProblem) -> Self {
        let (normal_kind, normal) = match problem.normal {
            NormalControl::Force(p) => (0, p),
            NormalControl::Overlap(d) => (1, d),
        };
        let (tangential_kind, tangential) = match problem.tangential {
            TangentialControl::Force(q) => (0, q),
            TangentialControl::Ratio(r) => (1, r),
            TangentialControl::Creep(c) => (2, c),
        };
        Self {
            values: [problem.friction, normal, tangential],
            kinds: [normal_kind, tangential_kind],
        }
    }
}

/// The start of the next run from the last two converged ones (a secant predictor, as in
/// numerical continuation: Allgower & Georg, *Introduction to Numerical Continuation Methods*,
/// 2003, §2.2): when the controls of the runs before, last and next lie on one line, at
/// `next = last + s·(last − before)` with 0 < s ≤ 2, the solution is extrapolated by the same
/// s. The contact problem's gap and slip are linear in the tractions and controls, so the
/// extrapolated state satisfies those equations as the runs do; only the contact and friction
/// projections are left to the Newton method, which starts from the active sets of the
/// extrapolated tractions, closer to the next run's than the last run's are. Otherwise (a
/// chain's second run, controls off the line, a change of control kind, a step more than twice
/// the last) the last run's solution, as before.
fn predicted_start(last: &(State, Controls), before: Option<&(State, Controls)>, next: &Controls) -> State {
    let (z1, c1) = last;
    let Some((z0, c0)) = before else {
        return z1.clone();
    };
    let Some(s) = step_ratio(c0, c1, next) else {
        return z1.clone();
    };
    let extrapolate = |a: &[f64], b: &[f64]| a.iter().zip(b).map(|(x1, x0)| x1 + s * (x1 - x0)).collect();
    State {
        gap: extrapolate(&z1.gap, &z0.gap),
        slip: extrapolate(&z1.slip, &z0.slip),
        pressure: extrapolate(&z1.pressure, &z0.pressure),
        shear: extrapolate(&z1.shear, &z0.shear),
        overlap: z1.overlap + s * (z1.overlap - z0.overlap),
        creep: z1.creep + s * (z1.creep - z0.creep),
    }
}

/// s with `next − last = s·(last − before)` in every control (to 1e-9 of its size), when
/// 0 < s ≤ 2 and the kinds agree; None otherwise.
fn step_ratio(before: &Controls, last: &Controls, next: &Controls) -> Option<f64> {
    if before.kinds != last.kinds || last.kinds != next.kinds {
        return None;
    }
    let d1: Vec<f64> = (0..3).map(|i| last.values[i] - before.values[i]).collect();
    let d2: Vec<f64> = (0..3).map(|i| next.values[i] - last.values[i]).collect();
    let norm1: f64 = d1.iter().map(|d| d * d).sum();
    if norm1 == 0.0 {
        return None;
    }
    let s = d1.iter().zip(&d2).map(|(a, b)| a * b).sum::<f64>() / norm1;
    let on_line =
        (0..3).all(|i| (d2[i] - s * d1[i]).abs() <= 1e-9 * (last.values[i].abs() + d2[i].abs() + f64::MIN_POSITIVE));
    (on_line && s > 0.0 && s <= 2.0).then_some(s)
}

/// Where a [`GridChain`]'s runs start their passes, warm from the last run's solution.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum GridReuse {
    /// On the run's own start grid (the sweep's chains; module docs, "Error-controlled
    /// chains", say why).
    StartGrid,
    /// On the last run's final grid with every pair of sibling pieces merged back this many
    /// times ([`crate::adapt::GridStart::coarsened`]; 0: the grid itself).
    LastGrid {
        /// Levels merged.
        merged: u32,
    },
}

/// One worker's error-controlled runs, each started warm from the last converged run's
/// solution (module docs, "Error-controlled chains").
#[derive(Debug, Clone)]
pub struct GridChain {
    /// The last converged run's final grid and solution.
    last: Option<crate::adapt::GridStart>,
    /// Which grid a run starts on.
    reuse: GridReuse,
}

impl Default for GridChain {
    fn default() -> Self {
        Self::new(GridReuse::StartGrid)
    }
}

impl GridChain {
    /// A chain whose runs start as `reuse` says (the sweep's chains: [`GridReuse::StartGrid`]).
    pub fn new(reuse: GridReuse) -> Self {
        Self { last: None, reuse }
    }

    /// Forgets the last run: the next starts cold, as alone.
    pub fn restart_cold(&mut self) {
        self.last = None;
    }

    /// Whether the next run would start warm from the last run (if its start grid is the last
    /// run's).
    pub fn is_warm(&self) -> bool {
        self.last.is_some()
    }

    /// Solves `scene` (error-controlled or not: a fixed grid is solved as alone) warm from the
    /// last converged run, post-processes it and hands it to `read`, whose result is returned;
    /// `start` is when the run began (its timings). A run that met its tolerance is the next
    /// one's start; a failed one makes the next start cold.
    pub fn solve_with<T>(&mut self, scene: Scene, start: Instant, read: impl FnOnce(&Solved) -> T) -> Result<T, Error> {
        let from = self.last.take().map(|s| match self.reuse {
            GridReuse::StartGrid => s.on_start_grid(),
            GridReuse::LastGrid { merged } => s.coarsened(merged),
        });
        let (solved, next) = crate::app::solve_scene_from(scene, start, from.as_ref())?;
        self.last = next.filter(|_| solved.report.converged);
        Ok(read(&solved))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn controls(values: [f64; 3]) -> Controls {
        Controls { values, kinds: [0, 1] }
    }

    #[test]
    fn the_step_ratio_is_taken_on_a_line_of_controls_only() {
        let (a, b) = (controls([0.3, 100.0, 0.50]), controls([0.3, 100.0, 0.51]));
        let s = step_ratio(&a, &b, &controls([0.3, 100.0, 0.53])).expect("on the line");
        assert!((s - 2.0).abs() < 1e-12, "{s}");
        // Off the line (the friction changes too), backwards, too far, or another kind.
        assert_eq!(step_ratio(&a, &b, &controls([0.31, 100.0, 0.52])), None);
        assert_eq!(step_ratio(&a, &b, &controls([0.3, 100.0, 0.50])), None);
        assert_eq!(step_ratio(&a, &b, &controls([0.3, 100.0, 0.54])), None);
        let mut force = controls([0.3, 100.0, 0.52]);
        force.kinds = [0, 0];
        assert_eq!(step_ratio(&a, &b, &force), None);
        // Two runs of the same controls give no direction.
        assert_eq!(step_ratio(&a, &a, &b), None);
    }

    /// The secant predictor is second order in the step: on Carter's problem (100 elements,
    /// Q/μP 0.50, 0.51 → 0.52) the extrapolated shear lies far closer to the next run's than
    /// the last run's does, at the median node (where the traction is a smooth function of
    /// Q/μP: an O(h²) error against O(h)). Only the few nodes the stick–slip point crosses keep
    /// a first-order error (a kink in q as a node turns from stick to slip), which is why the
    /// Newton method still has iterations to do there. Measured: median 8.7e-6 against 5.7e-4
    /// of p0 (66×); 10× asserted.
    #[test]
    fn the_secant_start_lies_closer_to_the_next_run_than_the_last_run() {
        let solved = |ratio: f64| {
            let set = [
                "contact.grid.elements=100".to_string(),
                format!("load.tangential.ratio={ratio}"),
            ];
            let path = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("cases/carter2d_contact.yaml");
            let s = crate::app::solve_case(path.as_path(), &set).expect("carter2d_contact solves");
            let (state, report) = methods::solve_from(&s.problem, &s.scene.solver, None);
            assert!(report.converged);
            (state, Controls::of(&s.problem))
        };
        let (z0, z1, z2) = (solved(0.50), solved(0.51), solved(0.52));
        let predicted = predicted_start(&z1, Some(&z0), &z2.1);
        let p0 = z2.0.pressure.iter().fold(0.0_f64, |m, &p| m.max(p));
        let median_distance = |z: &State| {
            let mut d: Vec<f64> = z
                .shear
                .iter()
                .zip(&z2.0.shear)
                .map(|(a, b)| (a - b).abs() / p0)
                .collect();
            d.sort_by(f64::total_cmp);
            d[d.len() / 2]
        };
        let (secant, last) = (median_distance(&predicted), median_distance(&z1.0));
        println!("median distance of q to the next run: secant start {secant:.2e}, last run {last:.2e}");
        assert!(secant < last / 10.0, "secant {secant:e}, last {last:e}");
    }
}
