//! The scene: a validated case resolved into what the solver stages need — both bodies as one
//! [`BodySetup`] each (built by the [`registry`]), the contact grid, the load controls, the solver settings and the Hertz
//! estimates of the grid actually used.
//!
//! The scene is the only stage that reads body specs and meshes from a case; everything
//! after it (body models, contact problem, post-processing, output) sees the scene. Studies
//! that solve a variant of a case (another body model, a procedural mesh) build a scene from
//! their own [`BodySetup`]s with [`Scene::new`] instead of rewriting the case.

pub mod contact_frame;
pub mod estimates;
pub mod preflight;
pub mod registry;
pub mod validity;

use crate::analytic::Carter;
pub use crate::body::bem::setup::BemSetup;
pub use crate::body::half_space::setup::HalfSpaceSetup;
use crate::body::pair_influence::PairInfluence;
pub use crate::body::rigid::RigidSetup;
pub use crate::body::BodySetup;
use crate::body::{Body, BodyModel, BuildContext, FlexibilityChange, Rolling, RunCaches, Side};
use crate::case::{LoadedCase, NormalSpec, TangentialSpec};
use crate::contact::falling::FallingLaw;
use crate::contact::{ContactFrame, ContactProblem, NewtonSettings, NormalControl, SolverSettings, TangentialControl};
use crate::error::Error;
use crate::grid::ContactGrid;
pub use crate::mesh::LoadedMesh;
pub use estimates::{aligned_half_length, Estimates};
pub use registry::BodySetups;
use std::sync::Arc;
use std::time::Instant;

/// The built body models of A and B.
pub type BodyModels = [Box<dyn Body>; 2];

/// The scenes of an error-controlled grid's passes ([`Scene::with_pass_stand_ins`]).
#[derive(Debug, Clone)]
pub struct PassScenes {
    /// The bodies' stand-ins, which the passes solve with.
    pub passes: Scene,
    /// The stand-ins with the part they know least well known less well, to estimate the
    /// passes' stand-ins' error on the final grid; None when a stand-in cannot give the final
    /// grid's results.
    pub check: Option<Scene>,
    /// How `check`'s bodies differ from `passes`' (A's, B's; None for a body that is the same
    /// in both), when every stand-in with a check knows it as a low-rank change of its
    /// flexibility ([`crate::body::FlexibilityChange`]): the check's problems are then the
    /// passes' plus the changes.
    pub check_changes: Option<[Option<Arc<dyn FlexibilityChange>>; 2]>,
    /// Time [s] the stand-ins' builds spent condensing the bodies, summed over both.
    pub condense_s: f64,
    /// The builds' own times [s], summed over both (they may have run side by side: the
    /// condensation's share of the wall time is `condense_s / build_s`).
    pub build_s: f64,
}

/// A case resolved for solving.
#[derive(Debug, Clone)]
pub struct Scene {
    /// The case it was built from (title, contact and output settings, the resolved values).
    pub case: LoadedCase,
    /// Bodies A and B.
    pub bodies: BodySetups,
    /// The contact grid: a `bem` body's own contact elements (A's first), else the case's
    /// uniform grid around the Hertz contact.
    pub grid: ContactGrid,
    /// The contact's directions at the grid's nodes ([`contact_frame`]).
    pub frame: ContactFrame,
    /// Hertz estimates; their grid entries describe [`Self::grid`].
    pub estimates: Estimates,
    /// What is prescribed normally.
    pub normal: NormalControl,
    /// What is prescribed tangentially.
    pub tangential: TangentialControl,
    /// Solution method and its settings.
    pub solver: SolverSettings,
    /// Coulomb friction coefficient μ [-] (the static one under a falling law).
    pub friction: f64,
    /// The falling friction law of `contact.falling_friction`; None: constant μ.
    pub falling: Option<FallingLaw>,
    /// The error control of `contact.grid.tolerance`; None for a fixed grid.
    pub grid_control: Option<GridControl>,
    /// The fields post-processing computes besides the contact solution.
    pub fields: FieldRequests,
    /// The grid's half-length over the Hertz half-width, `contact.grid.extent` [-] (what a
    /// contact cut off by the grid's ends is told to raise).
    pub grid_extent: f64,
}

/// The fields a run computes after the contact is solved (`output.vtk`, `output.interior`).
#[derive(Debug, Clone, PartialEq)]
pub struct FieldRequests {
    /// Boundary fields of both bodies for VTK.
    pub vtk: bool,
    /// The interior grid of one body, if asked for.
    pub interior: Option<crate::case::InteriorSpec>,
    /// First yield and shakedown of the bodies, if asked for.
    pub strength: Option<crate::case::StrengthSpec>,
}

/// What an error-controlled grid must reach, and its limit.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct GridControl {
    /// Tolerance on the estimated RMS errors of p/p0 and q/(μp0) and the creepage's relative
    /// error [-].
    pub tolerance: f64,
    /// Most elements of the bisected grid before the run stops (exit code 2).
    pub max_elements: usize,
    /// Whether the passes may solve with the bodies' stand-ins (`contact.grid.stand_ins`,
    /// [`Scene::with_pass_stand_ins`]).
    pub stand_ins: bool,
}

impl Scene {
    /// The scene of a case: loads the meshes of its `bem` bodies.
    pub fn from_case(case: &LoadedCase) -> Result<Self, Error> {
        let bodies = registry::setups_of_case(case)?;
        // Before the grid is built: the checks keep it finite and the matrices within memory.
        preflight::check(case, &bodies)?;
        let scene = Self::new(case.clone(), bodies);
        scene.check_max_elements()?;
        // What building the bodies would refuse, found without building them, so that `check`
        // refuses what `run` does.
        for (k, side) in [Side::A, Side::B].into_iter().enumerate() {
            let ctx = BuildContext {
                grid: &scene.grid,
                side,
                rolling: scene.rolling(),
                pair: None,
                responses_only: false,
                run: None,
            };
            scene.bodies[k].preflight(&ctx)?;
        }
        Ok(scene)
    }

    /// The scene of a case's contact, load and solver settings with the given bodies (which
    /// may differ from the case's body specs, e.g. a study's procedural meshes).
    pub fn new(case: LoadedCase, bodies: BodySetups) -> Self {
        let c = &case.case;
        let estimates = Estimates::of(c, &bodies);
        let (grid, estimates) = match bodies.iter().find_map(|b| b.contact_mesh()) {
            Some(own) => {
                let grid = own.mesh.contact_grid();
                let estimates = estimates.with_grid(&grid);
                (grid, estimates)
            }
            None => {
                let g = &c.contact.grid;
                let l = estimates.grid_half_length;
                (ContactGrid::uniform(g.element, g.elements, -l, l), estimates)
            }
        };
        let normal = match c.load.normal() {
            NormalSpec::Force(p) => NormalControl::Force(p),
            NormalSpec::Overlap(d) => NormalControl::Overlap(d),
        };
        let tangential = match c.load.tangential() {
            TangentialSpec::Ratio(r) => TangentialControl::Ratio(r),
            TangentialSpec::Force(q) => TangentialControl::Force(q),
            TangentialSpec::Creep(x) => TangentialControl::Creep(x),
        };
        let solver = solver_settings(&case);
        let frame = contact_frame::contact_frame(&bodies, &grid, c.contact.traction_axes);
        let friction = c.contact.friction;
        // Validation asks a falling law for load.speed; without one the law is not built.
        let falling = c
            .contact
            .falling_friction
            .zip(c.load.speed)
            .map(|(law, speed)| FallingLaw { law, speed });
        let grid_control = c.contact.grid.tolerance.map(|tolerance| GridControl {
            tolerance,
            max_elements: c.contact.grid.max_elements,
            stand_ins: c.contact.grid.stand_ins,
        });
        let fields = FieldRequests {
            vtk: c.output.vtk,
            interior: c.output.interior.clone(),
            strength: c.output.strength.clone(),
        };
        let grid_extent = c.contact.grid.extent;
        Scene {
            case,
            bodies,
            grid,
            frame,
            estimates,
            normal,
            tangential,
            solver,
            friction,
            falling,
            grid_control,
            fields,
            grid_extent,
        }
    }

    /// The same scene on another contact grid spanning the same interval (an error-controlled
    /// grid's refinements): the contact frame and the grid entries of the estimates follow it.
    pub fn with_grid(&self, grid: ContactGrid) -> Scene {
        let frame = contact_frame::contact_frame(&self.bodies, &grid, self.case.case.contact.traction_axes);
        Scene {
            estimates: self.estimates.clone().with_grid(&grid),
            grid,
            frame,
            ..self.clone()
        }
    }

    /// Coulomb friction coefficient μ.
    pub fn friction(&self) -> f64 {
        self.friction
    }

    /// +1 when the leading edge is at x = +a (rolling in +x), −1 otherwise.
    pub fn leading_edge_sign(&self) -> f64 {
        -self.case.case.contact.rolling_direction.flow_sign()
    }

    /// The narrowest relaxation layer of the two bodies behind the leading edge [length]
    /// ([`crate::body::setup::BodySetup::relaxation_layer`]); None when both are elastic.
    pub fn relaxation_layer(&self) -> Option<f64> {
        let speed = self.case.case.load.speed;
        self.bodies
            .iter()
            .filter_map(|b| b.relaxation_layer(speed))
            .reduce(f64::min)
    }

    /// Refuses an error-controlled grid whose `contact.grid.max_elements` is below twice the
    /// start grid's elements when a body's mesh sets that grid: the first pass solves the grid
    /// and its bisection, so the run could only stop at once (the case's own check compares
    /// with `contact.grid.elements`, which such a grid does not use).
    fn check_max_elements(&self) -> Result<(), Error> {
        let (Some(control), Some(own)) = (self.grid_control, self.bodies.iter().find_map(|b| b.contact_mesh())) else {
            return Ok(());
        };
        let elements = self.grid.n_elements();
        if control.max_elements >= 2 * elements {
            return Ok(());
        }
        Err(Error::GridControl {
            case: self.case.path.clone(),
            message: format!(
                "contact.grid.max_elements = {} is less than twice the {elements} elements of the contact \
                 grid, which is the contact group `{}` of the mesh {}: the first pass solves that grid and \
                 its bisection; raise contact.grid.max_elements to at least {}",
                control.max_elements,
                own.group,
                own.mesh.path.display(),
                2 * elements
            ),
        })
    }

    /// Whether a body's own mesh sets the contact grid.
    pub fn grid_from_mesh(&self) -> bool {
        self.bodies.iter().any(|b| b.contact_mesh().is_some())
    }

    /// The scene on a refined contact grid spanning the same interval (an error-controlled
    /// grid's passes): each body follows the grid ([`BodySetup::follow_grid`]: a BEM body cuts
    /// its mesh along it); when a body's mesh sets the grid, the grid is then that mesh's,
    /// which is `grid` node for node.
    pub fn on_grid(&self, grid: ContactGrid) -> Scene {
        if !self.grid_from_mesh() {
            return self.with_grid(grid);
        }
        let bodies = self.bodies.clone().map(|b| b.follow_grid(&grid).unwrap_or(b));
        Scene::new(self.case.clone(), bodies)
    }

    /// The scenes for the passes of an error-controlled grid: each body that offers a cheaper
    /// stand-in ([`BodySetup::pass_stand_in`], fitted on `levels`, two or three grids, coarsest
    /// first) replaced by it, on the start grid; None when no body offers one. The stand-ins
    /// have no mesh of their own: the pass grids are the scene's to choose ([`Self::on_grid`]).
    /// The levels' builds share the caches of `run`, the error-controlled run they are part of.
    pub fn with_pass_stand_ins(
        &self,
        levels: &[&ContactGrid],
        run: Option<&RunCaches>,
    ) -> Result<Option<PassScenes>, Error> {
        if self.grid_control.is_some_and(|g| !g.stand_ins) {
            return Ok(None);
        }
        let mut bodies = self.bodies.clone();
        let mut checks = Some(self.bodies.clone());
        let mut any = false;
        // The two bodies' levels are condensed side by side where memory allows: each
        // condensation is mostly one thread's work, so the second core would idle.
        let build = |k: usize, side: Side| {
            let t = Instant::now();
            let stand_in = self.bodies[k].pass_stand_in(levels, side, self.rolling(), run);
            (stand_in, t.elapsed().as_secs_f64())
        };
        let finest = levels.last().map(|g| g.n_elements());
        let (a, b) = self.side_by_side(finest, || build(0, Side::A), || build(1, Side::B));
        let build_s = a.1 + b.1;
        let (mut condense_s, mut built) = (0.0, Vec::new());
        for (k, (stand_in, _)) in [a, b].into_iter().enumerate() {
            if let Some(s) = stand_in? {
                condense_s += s.condense_s;
                built.push((k, s));
            }
        }
        let mut changes = Some([None, None]);
        for (k, stand_in) in built {
            bodies[k] = stand_in.body;
            match (stand_in.check, checks.as_mut()) {
                (Some(check), Some(c)) => c[k] = check,
                _ => checks = None,
            }
            match (stand_in.check_change, changes.as_mut()) {
                (Some(change), Some(c)) => c[k] = Some(change),
                _ => changes = None,
            }
            any = true;
        }
        if !any || bodies.iter().any(|b| b.contact_mesh().is_some()) {
            return Ok(None);
        }
        Ok(Some(PassScenes {
            passes: Scene { bodies, ..self.clone() },
            check_changes: changes.filter(|_| checks.is_some()),
            check: checks.map(|bodies| Scene { bodies, ..self.clone() }),
            condense_s,
            build_s,
        }))
    }

    /// The shortest element an error-controlled grid may make [length]: twice the length below
    /// which a body's mesh, cut along the grid, would hold an element of zero length
    /// ([`crate::mesh::check::zero_length_tolerance`]), and never below 1e-12 of the grid's
    /// span, where the dyadic cells' ends would part by round-off alone.
    pub fn shortest_grid_element(&self) -> f64 {
        let span = self.grid.edges[self.grid.n_elements()] - self.grid.edges[0];
        self.bodies
            .iter()
            .filter_map(|b| b.contact_mesh())
            .map(|m| 2.0 * crate::mesh::check::zero_length_tolerance(&m.mesh.mesh))
            .fold(1e-12 * span, f64::max)
    }

    /// How the contact moves over the bodies.
    pub fn rolling(&self) -> Rolling {
        estimates::rolling_of(&self.case.case)
    }

    /// The notices of the bodies' inputs (mesh loops turned round), A's first.
    pub fn notices(&self) -> Vec<String> {
        self.bodies.iter().flat_map(|b| b.notices().to_vec()).collect()
    }

    /// Builds both body models on the contact grid, as a pair that computes the influence
    /// matrices both need once ([`PairInfluence`]).
    pub fn body_models(&self) -> Result<BodyModels, Error> {
        self.body_models_built(false, None)
    }

    /// [`Self::body_models`] within a run whose builds share the caches `run`
    /// ([`crate::body::BuildContext::run`]: the error control's, which keeps a BEM body's
    /// condensation for a later build on the same grid).
    pub fn body_models_in(&self, run: Option<&RunCaches>) -> Result<BodyModels, Error> {
        self.body_models_built(false, run)
    }

    /// [`Self::body_models_in`] for a caller that asks the bodies only for their response to a
    /// few loads ([`crate::body::BuildContext::responses_only`]: a BEM body factored, not solved
    /// for every unit load).
    pub fn body_models_for_responses(&self, run: Option<&RunCaches>) -> Result<BodyModels, Error> {
        self.body_models_built(true, run)
    }

    fn body_models_built(&self, responses_only: bool, run: Option<&RunCaches>) -> Result<BodyModels, Error> {
        let pair = Arc::new(PairInfluence::new());
        let build = |k: usize, side: Side| -> Result<Box<dyn Body>, Error> {
            let ctx = BuildContext {
                grid: &self.grid,
                side,
                rolling: self.rolling(),
                pair: Some(&pair),
                responses_only,
                run,
            };
            Ok(self.bodies[k].build(&ctx)?)
        };
        // Side by side where memory allows: a BEM body's condensation is mostly one thread's
        // work. (The bodies only join the pair's store here; they take its matrices when asked
        // for their flexibility.)
        let (a, b) = self.side_by_side(None, || build(0, Side::A), || build(1, Side::B));
        Ok([a?, b?])
    }

    /// `a()` and `b()`, the builds of bodies A and B: on a thread each
    /// ([`crate::limits::bem_builds_fit_side_by_side`] for the bodies' meshes as they are, or
    /// cut along a grid of `contact_elements`), else one after the other.
    fn side_by_side<T: Send>(
        &self,
        contact_elements: Option<usize>,
        a: impl FnOnce() -> T + Send,
        b: impl FnOnce() -> T + Send,
    ) -> (T, T) {
        let nodes = |k: usize| match contact_elements {
            Some(n) => self.bodies[k].discretisation_nodes_on(n),
            None => self.bodies[k].discretisation_nodes(),
        };
        if crate::limits::bem_builds_fit_side_by_side([nodes(0), nodes(1)]) {
            rayon::join(a, b)
        } else {
            (a(), b())
        }
    }

    /// Builds the body models and assembles the contact problem.
    pub fn assemble(&self) -> Result<(BodyModels, ContactProblem), Error> {
        let models = self.body_models()?;
        let problem = self.contact_problem(&models);
        Ok((models, problem))
    }

    /// Assembles the contact problem of the scene from its body models.
    pub fn contact_problem(&self, models: &BodyModels) -> ContactProblem {
        let mut pb = self.contact_problem_without_strain(models, true);
        pb.strain = ContactProblem::strain_of(&pb.grid, models[0].model(), models[1].model(), &pb.frame);
        pb
    }

    /// [`Self::contact_problem`] without the strain operator (an error-controlled run's
    /// intermediate grids; [`ContactProblem::strain_of`] adds it), and with body B's own
    /// flexibility only when `keep_body_b` (the outputs' surface displacements need it; a grid
    /// that cannot be the result does not).
    pub fn contact_problem_without_strain(&self, models: &BodyModels, keep_body_b: bool) -> ContactProblem {
        self.contact_problem_of(models[0].model(), models[1].model(), keep_body_b)
    }

    /// [`Self::contact_problem_without_strain`] of any two body models (A's, B's).
    pub fn contact_problem_of(&self, a: &dyn BodyModel, b: &dyn BodyModel, keep_body_b: bool) -> ContactProblem {
        let c = &self.case.case.contact;
        log::info!(
            target: crate::logging::PROGRESS,
            "assembling the contact problem: {} contact nodes",
            self.grid.n_nodes()
        );
        let mut problem = ContactProblem::assemble(
            self.grid.clone(),
            a,
            b,
            c.slip_derivative,
            self.friction,
            c.rolling_direction,
            self.normal,
            self.tangential,
            self.frame.clone(),
            keep_body_b,
        );
        problem.falling = self.falling;
        problem
    }

    /// Carter's solution for the scene's similar-body estimates, when the case prescribes
    /// Q/μP (Carter 1926).
    pub fn carter_reference(&self) -> Option<Carter> {
        let ratio = match self.case.case.load.tangential() {
            TangentialSpec::Ratio(r) => r,
            _ => return None,
        };
        Some(Carter {
            half_width: self.estimates.hertz_half_width,
            peak_pressure: self.estimates.hertz_peak_pressure,
            friction: self.friction(),
            ratio,
            leading_edge_sign: self.leading_edge_sign(),
        })
    }
}

/// The Newton settings of a case (formulation, penalty scale, tolerance, iteration limit).
pub fn newton_settings(case: &LoadedCase) -> NewtonSettings {
    let s = &case.case.solver;
    NewtonSettings {
        formulation: s.formulation,
        penalty_scale: s.penalty.scale(),
        tolerance: s.tolerance,
        max_iterations: s.max_iterations,
        ..NewtonSettings::default()
    }
}

/// The solver settings of a case: its method, the Newton settings it shares, and the
/// Gauss–Seidel relaxation ω, which `solver.penalty` sets for `gauss_seidel`.
pub fn solver_settings(case: &LoadedCase) -> SolverSettings {
    SolverSettings {
        method: case.case.solver.method,
        newton: newton_settings(case),
        relaxation: case.case.solver.penalty.scale(),
    }
}
