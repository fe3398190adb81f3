//! Error-controlled contact grids (`contact.grid.tolerance`): solve, estimate the error, refine
//! where it is large, repeat until the estimate meets the tolerance.
//!
//! The tractions of a rolling contact are smooth except at a few points where they behave
//! like a square root: the contact edges (p ∝ √(a − |x|)) and the ends of the stick zones and
//! slip reversals (q − μp ∝ √(x − x_s)). On a uniform grid those few elements set the error,
//! which falls only as N⁻¹ while the dense solve costs N³. Here the grid is graded towards them.
//!
//! One pass on a grid G ([`cells::DyadicGrid`]: dyadic pieces of the case's uniform start grid):
//!
//! 1. solve on G (warm start from the previous pass's solution) and on its bisection H;
//! 2. estimate the error of H's solution from the difference of the two, with an indicator per
//!    element of G: an [`estimate::ErrorEstimator`] ([`estimate::BisectionEstimator`] unless
//!    [`solve_with`] is given another): its [`estimate::Comparison`] is all that steps 3 and 4
//!    read of the estimate (besides it they read only where H's solution has its square-root
//!    points);
//! 3. if the estimated RMS errors of p/p0 and q/(μp0) over the contact and the relative
//!    errors of the creepage and (where controlled) the overlap are all ≤ the tolerance, H's
//!    solution is the result;
//! 4. else refine G. Each element has a local indicator (how far H's solution over it departs
//!    from one polynomial of the element's degree): large at the square-root points, small
//!    where the solution is smooth, and blind to the smooth error those points spread, which
//!    refining them removes. The squared estimate is taken to fall with the indicators' sum,
//!    so the sum must fall by (SAFETY·tolerance/estimate)², shared equally among the elements.
//!    An element above its share is halved k times towards the contact edge or stick/slip
//!    point it holds (k from its indicator: next to a square-root point the share falls by 4
//!    per halving), or halved once when it holds none; sibling pieces in the open region with
//!    a negligible share are merged back; neighbours stay within a length ratio of 2.
//!    When the creepage's estimate alone exceeds the tolerance, with those of p and q below
//!    [`CREEPAGE_ALONE`] times the tolerance, every element in the contact is halved at least
//!    once: the creepage is a functional of the shear over the whole stick zone, its error the
//!    smooth error there, which the indicators do not see and the marking by shares halves
//!    only a few elements a pass (bore_a020_braking at 1e-3, whose creepage nearly cancels:
//!    five passes to 542 elements, its estimate falling 1.3–1.6 times a pass; halving the
//!    contact: three passes to 466 elements, 8.9 times in the pass that halved it).
//!
//! The loop asks these steps of *error contributions*, each one implementation of
//! [`contribution::ErrorContribution`] returning one value, a [`contribution::Contribution`]
//! (met, refine, rebuild, ended): the contact grid's estimate of steps 2–3
//! ([`contribution::ContactGrid`]), the overlap under force control between bodies with a
//! datum ([`overlap::Overlap`]), the BEM bodies' stand-ins (the passes solve cheaper stand-ins
//! until the final grid is checked against the bodies themselves: `stand_ins::StandIns`), and
//! the bodies' own meshes outside the contact (a BEM body's free boundary, shaft, rim: checked
//! once the grid meets the tolerance and bisected while their estimate exceeds it,
//! `body_mesh::BodyMeshes`). One pass of `controlled`: solve G and H, collect the
//! contributions in order, and act on the first that is not met — mark and refine the
//! contact grid (step 4), solve again from G on other bodies (rebuild), or stop; with all met,
//! the result. The loop names no kind of body: the stand-ins' contribution gives the scene the
//! passes solve, and on half-space scenes the stand-ins and meshes have nothing to check.
//!
//! The result is H's solution; summary.json reports the estimate (`error_estimate`) and the
//! grid's passes. With the estimate not reached within `contact.grid.max_elements` elements
//! the run ends with exit code 2: the best solution comes back marked (`reached: false`), and
//! `rollbem run` writes its summary.json with `converged: false` and the last estimate.
//!
//! Refinement has a floor (src/adapt/floor.rs): where a pass's traction estimate rises to more
//! than [`floor::RISE`] times the best pass's on the same scene, and above the tolerance, the grid has reached element
//! lengths at which the solution's own noise exceeds its discretisation error; the run ends
//! with exit code 2, the best pass's solution and estimate its result, the error naming the
//! element length at which the estimate rose.
//!
//! A fixed grid (no `contact.grid.tolerance`) is the same loop stopped after its first solve:
//! [`solve`] is the one driver of every run.

mod a_priori;
pub mod body_mesh;
pub mod cells;
pub mod contribution;
mod corrections;
pub mod estimate;
pub mod fixed;
pub mod floor;
pub mod geometry_share;
mod marking;
pub mod overlap;
mod scales;
mod stand_ins;
mod start;

pub use start::GridStart;

use crate::body::RunCaches;
use crate::contact::residual::State;
use crate::contact::restart;
use crate::contact::{
    methods, BodyBLoad, BodyBShare, ContactProblem, SolveReport, SolverSettings, WithoutSlipBlocks, Workspace,
};
use crate::error::Error;
use crate::grid::ContactGrid;
use crate::post::adaptation::{AdaptationStep, ErrorEstimate, GridAdaptation};
use crate::post::Timings;
use crate::scene::{BodyModels, Scene};
use a_priori::APriori;
use cells::DyadicGrid;
use contribution::{Env, ErrorContribution, Held, Rebuild, Round, Verdict};
use estimate::ErrorEstimator;
use scales::HertzScales;
use std::time::Instant;

/// Fraction of the tolerance that the refinement aims at, so that the next pass usually meets
/// the tolerance rather than falls just short of it (then costing another pass).
pub const SAFETY: f64 = 0.6;

/// How far below the tolerance the estimates of p and q must lie for a creepage estimate above
/// it to halve every element in the contact (module docs, step 4).
pub const CREEPAGE_ALONE: f64 = 0.1;

/// Deepest grading of one element in one pass (2⁻¹² of its length).
pub const MAX_DEPTH_PER_PASS: u32 = 12;

/// The a-priori length rule: an element of the result that holds a square-root point is at
/// most this times tolerance·a long (docs/theory.md, "Error-controlled grids"); at the end of a
/// stick zone under a falling friction law, of exponent λ < 1/2, a·(this·tolerance)^(1/(λ+1/2))
/// (src/adapt/a_priori.rs).
pub const A_PRIORI_LENGTH: f64 = 30.0;

/// Most passes before the run gives up (each pass at least halves one element).
pub const MAX_PASSES: usize = 40;

/// A scene solved on an error-controlled grid, ready for post-processing.
pub struct Adapted {
    /// The scene on the final (bisected) grid.
    pub scene: Scene,
    /// Its body models.
    pub models: BodyModels,
    /// Its contact problem.
    pub problem: ContactProblem,
    /// The solution.
    pub state: State,
    /// The report of the final solve.
    pub report: SolveReport,
    /// Times of the stages, summed over the passes.
    pub timings: Timings,
    /// How the grid was reached (None for a fixed grid).
    pub adaptation: Option<GridAdaptation>,
    /// Where a neighbouring run may start its passes ([`solve_from`]): this run's final grid
    /// and solution, when it is error-controlled and met its tolerance (None otherwise).
    pub grid_start: Option<GridStart>,
}

/// One grid assembled and solved; its problem whole, or waiting for its outputs or the
/// checks without its slip blocks (`Solve<WithoutSlipBlocks>`).
struct Solve<P = ContactProblem> {
    /// Whether its bodies are the BEM bodies' stand-ins (post-processing then takes the scene
    /// of the bodies themselves, [`finished`]).
    from_stand_ins: bool,
    scene: Scene,
    models: BodyModels,
    problem: P,
    state: State,
    report: SolveReport,
}

impl<P> Solve<P> {
    /// The same solve with its problem turned by `f`.
    fn with_problem<Q>(self, f: impl FnOnce(P) -> Q) -> Solve<Q> {
        Solve {
            from_stand_ins: self.from_stand_ins,
            scene: self.scene,
            models: self.models,
            problem: f(self.problem),
            state: self.state,
            report: self.report,
        }
    }
}

impl Solve {
    /// The solve with its problem's slip blocks dropped (two m × m blocks), while it waits: its
    /// solution's outputs come after the check of the bodies' meshes, which solves other
    /// problems, and the checks of the stand-ins change its problem for their own blocks.
    fn without_slip_blocks(self) -> Solve<WithoutSlipBlocks> {
        self.with_problem(ContactProblem::without_slip_blocks)
    }
}

impl Solve<WithoutSlipBlocks> {
    /// The solve with its problem whole again (its slip blocks made from W), for its outputs.
    fn with_slip_blocks(self) -> Solve {
        self.with_problem(WithoutSlipBlocks::with_slip_blocks)
    }
}

/// Builds the scene's models, assembles and solves (from `warm`, carried from the grid it was
/// solved on), adding the times to `timings`. Unless the solve `may_be_final` (a fixed grid's:
/// its solution is the run's result), body B's own flexibility, which only the outputs read, is
/// dropped before the solve: four m × m blocks fewer held while later grids, the checks of the
/// stand-ins and of the bodies' meshes are solved ([`finished`] makes it again for the result).
/// The bodies are built with the caches of `run`, the run the solve is part of, if any.
fn solve_on(
    scene: Scene,
    warm: Option<(&ContactGrid, &State)>,
    may_be_final: bool,
    run: Option<&RunCaches>,
    timings: &mut Timings,
    ws: &mut Workspace,
) -> Result<Solve, Error> {
    solve_on_from(scene, warm, WarmFrom::Pass, may_be_final, run, timings, ws)
}

/// Where a warm start comes from: the run's own previous grid, or a neighbouring run's result
/// ([`solve_from`]), whose controls differ.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum WarmFrom {
    /// The run's own previous grid.
    Pass,
    /// A neighbouring run's result ([`solve_from`]).
    Neighbour,
}

/// [`solve_on`] from a warm start that came `from` a pass or a neighbour.
fn solve_on_from(
    scene: Scene,
    warm: Option<(&ContactGrid, &State)>,
    from: WarmFrom,
    may_be_final: bool,
    run: Option<&RunCaches>,
    timings: &mut Timings,
    ws: &mut Workspace,
) -> Result<Solve, Error> {
    let t = Instant::now();
    let models = scene.body_models_in(run)?;
    let built = t.elapsed().as_secs_f64();
    // The strain operator serves only the outputs: the final grid's is added by `finished`.
    let problem = scene.contact_problem_without_strain(&models, may_be_final);
    let condense_s = condensation_share(&models, built);
    timings.assembly_s += t.elapsed().as_secs_f64() - condense_s;
    timings.condense_s += condense_s;
    let (state, report) = solve_problem(&problem, &scene.solver, warm, from, timings, ws);
    Ok(Solve {
        from_stand_ins: false,
        scene,
        models,
        problem,
        state,
        report,
    })
}

/// Solves `problem` with `solver` (from `warm`, carried from the grid it was solved on),
/// adding the time to `timings`. A warm start `from` a neighbouring run (its controls differ)
/// takes the problem's own prescribed overlap or creepage, its first Newton step in full, and
/// gives way to the cold start after [`restart::NEIGHBOUR_BUDGET`] iterations, as a sequence's
/// runs are started (src/sequence.rs, "The warm start").
fn solve_problem(
    problem: &ContactProblem,
    solver: &SolverSettings,
    warm: Option<(&ContactGrid, &State)>,
    from: WarmFrom,
    timings: &mut Timings,
    ws: &mut Workspace,
) -> (State, SolveReport) {
    log::info!(
        target: crate::logging::PROGRESS,
        "solving: {}, {} contact nodes",
        solver.method.name(),
        problem.n_nodes()
    );
    let t = Instant::now();
    let warm = warm.map(|(grid, z)| carried(&problem.grid, grid, z));
    let solved = match from {
        WarmFrom::Pass => methods::solve_from_in(problem, solver, warm, ws),
        WarmFrom::Neighbour => {
            let warm = warm.map(|z| restart::with_prescribed(z, problem));
            methods::solve_from_neighbour_in(problem, solver, warm, restart::NEIGHBOUR_BUDGET, ws)
        }
    };
    timings.solve_s += t.elapsed().as_secs_f64();
    solved
}

/// The part of the models' build time `built` [s] that was condensation: the bodies build side
/// by side, so their own stage times (assembly, condensation) overlap and are taken as shares.
fn condensation_share(models: &BodyModels, built: f64) -> f64 {
    let (a, c) = models.iter().fold((0.0, 0.0), |(a, c), m| {
        let (ma, mc) = m.stage_seconds();
        (a + ma, c + mc)
    });
    Timings::share_of_wall(built, c, a + c)
}

/// A state of `from`'s grid carried to `grid`: tractions, gap and slip interpolated
/// by `from`'s shape functions (p and g clipped at 0). Interpolating the gap and slip too, rather
/// than recomputing them from the carried tractions, keeps the complementarity of the solution:
/// a node inside the contact's stick zone starts with g = 0 and s = 0, so the first Newton step
/// starts from the old active sets instead of from the noise of the tractions' interpolation
/// error (largest at the very nodes the refinement adds).
fn carried(grid: &ContactGrid, from: &ContactGrid, z: &State) -> State {
    let x = &grid.nodes;
    let field = |v: &[f64]| -> Vec<f64> { x.iter().map(|&x| from.interpolate(v, x)).collect() };
    let mut pressure = field(&z.pressure);
    let mut gap = field(&z.gap);
    for (p, g) in pressure.iter_mut().zip(&mut gap) {
        *p = p.max(0.0);
        *g = g.max(0.0);
    }
    State {
        gap,
        slip: field(&z.slip),
        pressure,
        shear: field(&z.shear),
        overlap: z.overlap,
        creep: z.creep,
    }
}

/// Solves the scene: on its grid when the grid is fixed, else on a grid refined until the
/// estimated error meets the scene's tolerance (module docs). A solve that does not converge
/// ends the loop: its solution comes back with `report.converged == false`.
pub fn solve(scene: &Scene) -> Result<Adapted, Error> {
    solve_with(scene, &mut estimate::BisectionEstimator)
}

/// [`solve`] with another error estimator: the estimate that decides convergence and the
/// indicators the refinement marks by come from `estimator` alone.
pub fn solve_with(scene: &Scene, estimator: &mut dyn ErrorEstimator) -> Result<Adapted, Error> {
    solve_from_with(scene, None, estimator)
}

/// [`solve`], an error-controlled grid's passes starting from `from` (a neighbouring run's
/// final grid and solution, src/adapt/start.rs) when it [`GridStart::fits`] the scene, else
/// from the scene's start grid. The result meets the same tolerance either way; it is another
/// grid's solution, so it differs from the run started on the start grid by up to the
/// tolerance (both are within it of the exact solution, by the estimate).
pub fn solve_from(scene: &Scene, from: Option<&GridStart>) -> Result<Adapted, Error> {
    solve_from_with(scene, from, &mut estimate::BisectionEstimator)
}

/// [`solve_with`] from `from` as [`solve_from`].
fn solve_from_with(
    scene: &Scene,
    from: Option<&GridStart>,
    estimator: &mut dyn ErrorEstimator,
) -> Result<Adapted, Error> {
    let Some(control) = scene.grid_control else {
        // What the run's body builds share (a BEM body's condensation kept for a later build on
        // the same grid): held here, passed to every build, dropped when the run returns.
        let run = RunCaches::new();
        let mut timings = Timings::default();
        let only = solve_on(
            scene.clone(),
            None,
            true,
            Some(&run),
            &mut timings,
            &mut Workspace::new(),
        )?;
        return Ok(finished(only, scene, timings, None));
    };
    let check_grid = stand_ins::body_mesh_check_grid(&DyadicGrid::new(&scene.grid), control.tolerance);
    let mut contributions: [Box<dyn ErrorContribution + '_>; 4] = [
        Box::new(contribution::ContactGrid { estimator }),
        Box::new(overlap::Overlap),
        Box::new(stand_ins::StandIns::default()),
        Box::new(body_mesh::BodyMeshes {
            grid: check_grid,
            bisections: 0,
        }),
    ];
    controlled(scene, &mut contributions, from.filter(|f| f.fits(scene)))
}

/// The error-control loop of the module docs on `scene` (which has a tolerance), with
/// `contributions` asked in their order ([`contribution`]): solve the pass, collect the
/// contributions, then mark and refine, rebuild, or stop. The passes start on the scene's start
/// grid, or on `from`'s grid warm from its solution (a neighbouring run's, [`solve_from`]).
fn controlled(
    scene: &Scene,
    contributions: &mut [Box<dyn ErrorContribution + '_>],
    from: Option<&GridStart>,
) -> Result<Adapted, Error> {
    let control = scene.grid_control.expect("an error-controlled grid");
    let (tolerance, max_elements) = (control.tolerance, control.max_elements);
    // What the run's body builds share (a BEM body's condensation kept for a later build on the
    // same grid): held here, passed to every build, dropped with what it holds when the run
    // returns.
    let run = RunCaches::new();
    // One solver workspace for every solve of the run: it grows to the largest grid's system.
    let mut env = Env {
        run: &run,
        timings: Timings::default(),
        ws: Workspace::new(),
        steps: Vec::new(),
        tolerance,
    };
    let mut bodies = scene.clone();
    // The scene the passes solve in the bodies' place, if a contribution offers one (fitted
    // on the levels of the bodies' start grid, wherever the passes start).
    let mut passes = started(contributions, &bodies, &DyadicGrid::new(&bodies.grid), &mut env)?;
    let (mut coarse, mut warm): (DyadicGrid, Option<(ContactGrid, State)>) = match from {
        Some(f) => (f.coarse.clone(), Some((f.grid.clone(), f.state.clone()))),
        None => (DyadicGrid::new(&scene.grid), None),
    };
    // The first solve of a run started from a neighbour's result is started as a neighbour's.
    let mut warm_from = if from.is_some() {
        WarmFrom::Neighbour
    } else {
        WarmFrom::Pass
    };
    let mut run_scales: Option<HertzScales> = None;
    let mut shortest = bodies.shortest_grid_element();
    // The passes on the current bodies start here (MAX_PASSES counts them).
    let mut first_step = 0;
    // The best pass on the scene the passes solve now (src/adapt/floor.rs).
    let mut watch = floor::FloorWatch::default();
    loop {
        // Solve: G and its bisection H.
        let pass_scene = passes.as_ref().unwrap_or(&bodies);
        let solved = solve_pass(pass_scene, &coarse, warm.take(), warm_from, passes.is_some(), &mut env)?;
        warm_from = WarmFrom::Pass;
        let (g, h) = match solved {
            Ok(pair) => pair,
            Err(unconverged) => return Ok(ended(unconverged, &bodies, env, true, None)),
        };
        let hertz = *run_scales.get_or_insert_with(|| HertzScales::of_run(&bodies, &g.problem, &g.state));
        let singular = marking::singular_points(&h.problem, &h.state);
        let lengths = APriori::of_pass(&bodies, &h, &singular, tolerance, hertz.half_width);
        let step = AdaptationStep {
            elements: h.problem.grid.n_elements(),
            nodes: h.problem.n_nodes(),
            estimate: NO_ESTIMATE,
            iterations: g.report.iterations + h.report.iterations,
        };
        let mut round = Round {
            bodies: &bodies,
            coarse: &coarse,
            g: Some(g),
            h: Some(Held::Whole(h)),
            scales: hertz.scales(&bodies),
            singular,
            lengths,
            comparison: None,
            estimate: NO_ESTIMATE,
            env: &mut env,
        };
        // Collect the contributions.
        let verdict = collected(contributions, &mut round, step)?;
        let Round {
            g,
            h,
            singular,
            lengths,
            comparison,
            estimate,
            ..
        } = round;
        drop(g);
        let h = h.expect("the pass's result");
        match verdict {
            Verdict::Met => {
                let mut done = ended(h.whole(), &bodies, env, true, None);
                done.grid_start = Some(GridStart {
                    coarse,
                    grid: done.problem.grid.clone(),
                    state: done.state.clone(),
                });
                return Ok(done);
            }
            Verdict::Ended { reached, too_coarse } => {
                return Ok(ended(h.whole(), &bodies, env, reached, too_coarse));
            }
            Verdict::Rebuild(rebuild) => {
                watch.reset();
                warm = Some(h.into_warm());
                if let Rebuild::New(rebuilt) = rebuild {
                    bodies = *rebuilt;
                    passes = started(contributions, &bodies, &DyadicGrid::new(&bodies.grid), &mut env)?;
                    run_scales = None;
                    shortest = bodies.shortest_grid_element();
                    first_step = env.steps.len();
                } else {
                    passes = None;
                }
            }
            Verdict::Refine => {
                let cmp = comparison.expect("the contact grid's comparison");
                // The floor: an estimate risen far above the best pass's is the solution's noise.
                let traction = floor::traction_estimate(&cmp.estimate);
                if let Some(best) = watch.risen(traction, tolerance).cloned() {
                    let pass_scene = passes.as_ref().unwrap_or(&bodies);
                    return floor::at_the_floor(pass_scene, &bodies, best, traction, h, passes.is_some(), env);
                }
                watch.offer(floor::Best::of(&h, traction, estimate, env.steps.len()));
                // Mark.
                let marked = marking::actions(&coarse, &cmp, &estimate, &singular, tolerance, &lengths, shortest);
                let Some(marked) = marked else {
                    log::warn!(
                        "the contact grid cannot be refined further: its elements reached the shortest length \
                         the bodies' meshes can be cut to ({shortest:.3e})"
                    );
                    return Ok(ended(h.whole(), &bodies, env, false, None));
                };
                // Refine, unless the grid would outgrow the limits.
                let next = coarse.refined(&marked);
                log::debug!("singular points {singular:?}; next grid {} elements", next.len());
                let finer = 2 * next.len();
                let ends = finer > max_elements || env.steps.len() - first_step >= MAX_PASSES;
                if ends || !crate::scene::preflight::finer_grid_fits(&bodies.case, &bodies.bodies, finer) {
                    // The best solution reached, marked: the driver reports it as not converged.
                    return Ok(ended(h.whole(), &bodies, env, false, None));
                }
                warm = Some(h.into_warm());
                coarse = next;
            }
        }
    }
}

/// The estimate of a pass before its contributions fill it in.
const NO_ESTIMATE: ErrorEstimate = ErrorEstimate {
    pressure_rms: 0.0,
    shear_rms: 0.0,
    creep_rel: 0.0,
    overlap_rel: None,
    body_mesh: None,
};

/// Every contribution started on `bodies` ([`ErrorContribution::start`]): the scene the passes
/// solve in their place, the last offered (None: the bodies themselves).
fn started(
    contributions: &mut [Box<dyn ErrorContribution + '_>],
    bodies: &Scene,
    start: &DyadicGrid,
    env: &mut Env<'_>,
) -> Result<Option<Scene>, Error> {
    let mut passes = None;
    for c in contributions.iter_mut() {
        if let Some(s) = c.start(bodies, start, env)? {
            passes = Some(s);
        }
    }
    Ok(passes)
}

/// One pass's solves on `scene`: the grid `coarse` (warm from `warm`, which came `warm_from`
/// a pass or a neighbouring run) and its bisection (warm from the first); `Err` holds the
/// solve that did not converge.
fn solve_pass(
    scene: &Scene,
    coarse: &DyadicGrid,
    warm: Option<(ContactGrid, State)>,
    warm_from: WarmFrom,
    from_stand_ins: bool,
    env: &mut Env<'_>,
) -> Result<Result<(Solve, Solve), Solve>, Error> {
    let (timings, ws) = (&mut env.timings, &mut env.ws);
    let warm = warm.as_ref().map(|(g, z)| (g, z));
    let mut g = solve_on_from(
        scene.on_grid(coarse.grid()),
        warm,
        warm_from,
        false,
        Some(env.run),
        timings,
        ws,
    )?;
    g.from_stand_ins = from_stand_ins;
    if !g.report.converged {
        return Ok(Err(g));
    }
    let on_g = Some((&g.problem.grid, &g.state));
    let mut h = solve_on(
        scene.on_grid(coarse.bisected().grid()),
        on_g,
        false,
        Some(env.run),
        timings,
        ws,
    )?;
    h.from_stand_ins = from_stand_ins;
    if !h.report.converged {
        return Ok(Err(h));
    }
    Ok(Ok((g, h)))
}

/// The contributions' verdict on `round`: each asked in order, those that
/// [`ErrorContribution::checks_the_result`] only while every one before them is met; the first
/// verdict that is not met, or met. The pass's `step` is recorded (with the pass's estimate)
/// before the first check, which may complete it.
fn collected(
    contributions: &mut [Box<dyn ErrorContribution + '_>],
    round: &mut Round<'_, '_>,
    mut step: AdaptationStep,
) -> Result<Verdict, Error> {
    let mut verdict = Verdict::Met;
    let mut recorded = false;
    for c in contributions.iter_mut() {
        if c.checks_the_result() {
            if !recorded {
                step.estimate = round.estimate;
                record(round, step);
                recorded = true;
            }
            if !matches!(verdict, Verdict::Met) {
                break;
            }
        }
        let found = c.assess(round)?;
        log::debug!("error control: {}: {:?}", found.name, found.verdict);
        if matches!(verdict, Verdict::Met) {
            verdict = found.verdict;
        }
    }
    if !recorded {
        step.estimate = round.estimate;
        record(round, step);
    }
    Ok(verdict)
}

/// The pass's `step` appended to the run's passes, and logged.
fn record(round: &mut Round<'_, '_>, step: AdaptationStep) {
    let e = step.estimate;
    round.env.steps.push(step);
    log::info!(
        target: crate::logging::PROGRESS,
        "error control, pass {}: {} elements, estimated error: pressure {:.2e} p0, shear {:.2e} mu p0, \
         creepage {:.2e}, overlap {}",
        round.env.steps.len(),
        step.elements,
        e.pressure_rms,
        e.shear_rms,
        e.creep_rel,
        e.overlap_rel.map_or("not controlled".to_string(), |o| format!("{o:.2e}"))
    );
}

/// The run's result: `s` on `bodies`, `reached` or not (`too_coarse`: the bodies whose meshes
/// were too coarse for the tolerance).
fn ended(s: Solve, bodies: &Scene, env: Env<'_>, reached: bool, too_coarse: Option<String>) -> Adapted {
    let mut done = finished(s, bodies, env.timings, Some((env.tolerance, env.steps)));
    if let Some(a) = done.adaptation.as_mut() {
        a.reached = reached;
        a.coarse_body_mesh = too_coarse;
    }
    done
}

/// The result of the loop: the last solve with the tolerance and the passes so far (None for a
/// fixed grid). A solve of the stand-ins keeps their models and takes the scene of `bodies`
/// (the bodies themselves) on its grid, for their notices, validity and summary.
fn finished(mut s: Solve, bodies: &Scene, mut timings: Timings, passes: Option<(f64, Vec<AdaptationStep>)>) -> Adapted {
    let t = Instant::now();
    if s.from_stand_ins {
        s.scene = bodies.on_grid(s.problem.grid.clone());
    }
    // The outputs need the strain of the result's tractions only (`ContactSolution::from_state`).
    s.problem.strain = ContactProblem::strain_under(
        &s.problem.grid,
        [s.models[0].model(), s.models[1].model()],
        &s.problem.frame,
        &s.state.pressure,
        &s.state.shear,
    );
    // An error-controlled run's solves drop it (`solve_on`): the result's outputs need only
    // its displacements under the result's tractions (those of `ContactSolution::from_state`,
    // pressure ≥ 0), not its four m × m blocks.
    if s.problem.body_b.is_none() {
        let pressure: Vec<f64> = s.state.pressure.iter().map(|p| p.max(0.0)).collect();
        s.problem.body_b = Some(BodyBShare::Under(BodyBLoad::of(
            s.models[1].model(),
            &s.problem.grid,
            &s.problem.frame,
            &pressure,
            &s.state.shear,
        )));
    }
    timings.assembly_s += t.elapsed().as_secs_f64();
    timings.total_s = timings.assembly_s + timings.condense_s + timings.solve_s;
    Adapted {
        adaptation: passes.map(|(tolerance, steps)| GridAdaptation {
            tolerance,
            estimate: steps.last().map(|s| s.estimate),
            refinements: steps.len().saturating_sub(1),
            steps,
            reached: true,
            coarse_body_mesh: None,
            floor: None,
            results_from_stand_ins: s.from_stand_ins,
        }),
        grid_start: None,
        scene: s.scene,
        models: s.models,
        problem: s.problem,
        state: s.state,
        report: s.report,
        timings,
    }
}
