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
//! (to the Newton tolerance). A warm start that has not converged within [`WARM_START_BUDGET`]
//! iterations falls back to the cold start and its restarts
//! ([`crate::contact::restart::solve_neighbour`]); only a converged run is the
//! next one's start.

use crate::contact::methods::{self, Workspace};
use crate::contact::residual::State;
use crate::contact::restart;
use crate::contact::ContactProblem;
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
    /// The solution of the last converged run.
    last: Option<State>,
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
    /// Forgets the last solution: the next run starts cold.
    pub fn restart_cold(&mut self) {
        self.last = None;
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
        let warm = self.last.take().map(|z| restart::with_prescribed(z, &problem));
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
            self.last = Some(state.clone());
        }
        let processed = post::process(scene, &self.shared.models, problem, &state, report, timings);
        match processed {
            Ok(solved) => {
                let out = read(&solved);
                self.problem = Some(solved.problem);
                Ok((out, how))
            }
            Err(e) => {
                self.last = None;
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
