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
//! Once the grid meets the tolerance, the bodies' own meshes outside the contact (a BEM
//! body's free boundary, shaft, rim) are checked too ([`body_mesh`]: the bodies solved on a
//! coarser check grid as given and with them bisected), and bisected while their estimate
//! exceeds the tolerance (the contact grid refined again on the bisected bodies).
//! Under force control between bodies with a datum the overlap is controlled with the
//! creepage ([`overlap`]).
//!
//! The result is H's solution; summary.json reports the estimate (`error_estimate`) and the
//! grid's passes. With the estimate not reached within `contact.grid.max_elements` elements
//! the run ends with exit code 2: the best solution comes back marked (`reached: false`), and
//! `rollbem run` writes its summary.json with `converged: false` and the last estimate.
//!
//! A fixed grid (no `contact.grid.tolerance`) is the same loop stopped after its first solve:
//! [`solve`] is the one driver of every run.

mod a_priori;
pub mod body_mesh;
pub mod cells;
mod corrections;
pub mod estimate;
pub mod fixed;
pub mod overlap;
mod scales;
mod stand_ins;

use crate::body::RunCaches;
use crate::contact::residual::State;
use crate::contact::{
    methods, BodyBLoad, BodyBShare, ContactProblem, SolveReport, SolverSettings, WithoutSlipBlocks, Workspace,
};
use crate::error::Error;
use crate::grid::ContactGrid;
use crate::post::adaptation::{AdaptationStep, GridAdaptation};
use crate::post::{ContactSolution, NodeState, Timings};
use crate::scene::{BodyModels, Scene};
use a_priori::{resolved, APriori};
use cells::{Action, DyadicGrid};
use estimate::{Comparison, ErrorEstimator, Pass, Scales};
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
/// most this times tolerance·a long (docs/theory.md, "Error-controlled grids").
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
    let t = Instant::now();
    let models = scene.body_models_in(run)?;
    let built = t.elapsed().as_secs_f64();
    // The strain operator serves only the outputs: the final grid's is added by `finished`.
    let problem = scene.contact_problem_without_strain(&models, may_be_final);
    let condense_s = condensation_share(&models, built);
    timings.assembly_s += t.elapsed().as_secs_f64() - condense_s;
    timings.condense_s += condense_s;
    let (state, report) = solve_problem(&problem, &scene.solver, warm, timings, ws);
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
/// adding the time to `timings`.
fn solve_problem(
    problem: &ContactProblem,
    solver: &SolverSettings,
    warm: Option<(&ContactGrid, &State)>,
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
    let warm = warm.map(|(from, z)| carried(&problem.grid, from, z));
    let solved = methods::solve_from_in(problem, solver, warm, ws);
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
    // One solver workspace for every solve of the run: it grows to the largest grid's system.
    let mut ws = Workspace::new();
    let mut timings = Timings::default();
    // What the run's body builds share (a BEM body's condensation kept for a later build on the
    // same grid): held here, passed to every build, dropped with what it holds when the run
    // returns.
    let run = RunCaches::new();
    let Some(control) = scene.grid_control else {
        let only = solve_on(scene.clone(), None, true, Some(&run), &mut timings, &mut ws)?;
        return Ok(finished(only, scene, timings, None));
    };
    let tolerance = control.tolerance;
    let check_grid = stand_ins::body_mesh_check_grid(&DyadicGrid::new(&scene.grid), tolerance);
    let mut steps: Vec<AdaptationStep> = Vec::new();
    let mut scene = scene.clone();
    // After the bodies' meshes are bisected, the refinement resumes from the last pass's grid.
    let mut resume: Option<(DyadicGrid, ContactGrid, State)> = None;
    for bisections in 0..=body_mesh::MAX_BODY_MESH_BISECTIONS {
        let refined = refine(
            &scene,
            resume.take(),
            estimator,
            &run,
            &mut timings,
            &mut steps,
            &mut ws,
        )?;
        let (met, scales, last) = match refined {
            Refined::Met(met, scales, last) => (met, scales, last),
            Refined::Ended(s, reached) => {
                let mut best = finished(s, &scene, timings, Some((tolerance, steps)));
                if let Some(a) = best.adaptation.as_mut() {
                    a.reached = reached;
                }
                return Ok(best);
            }
        };
        // The result waits for its outputs without its slip blocks (`Refined::Met`): two m × m
        // blocks fewer beside the check's bodies (the braking bore's: 31 MB).
        let warm = (met.problem.grid(), &met.state);
        let first = bisections == 0;
        // The check solves on a coarser grid than the final one: the final grid's Newton matrix
        // goes before the check's condensations are made (the braking bore's: 25 MB).
        ws = Workspace::new();
        let checked = body_mesh::check_on(
            &scene,
            &check_grid,
            warm,
            scales,
            tolerance,
            first,
            &run,
            &mut timings,
            &mut ws,
        )?;
        let Some(checked) = checked else {
            return Ok(finished(
                met.with_slip_blocks(),
                &scene,
                timings,
                Some((tolerance, steps)),
            ));
        };
        let mut e = checked.estimate;
        e.bisections = bisections;
        if let Some(last) = steps.last_mut() {
            last.estimate.body_mesh = Some(e);
        }
        let adopt = checked.bisected.filter(|_| e.largest() > tolerance);
        let Some(bisected) = adopt.filter(|_| bisections < body_mesh::MAX_BODY_MESH_BISECTIONS) else {
            let too_coarse = (e.largest() > tolerance).then(|| body_mesh::meshed_bodies(&scene));
            let mut done = finished(met.with_slip_blocks(), &scene, timings, Some((tolerance, steps)));
            if let (Some(a), Some(bodies)) = (done.adaptation.as_mut(), too_coarse) {
                a.reached = false;
                a.coarse_body_mesh = Some(bodies);
            }
            return Ok(done);
        };
        // The bisected bodies are adopted: the contact grid is refined again on them from the
        // last pass's grid, warm from its solution (the bisection outside the contact moves the
        // square-root points only within the grid's tolerance; starting over from the start
        // grid repeated every pass: bore_a001 at 1e-5, about 67 s).
        log::info!(
            target: crate::logging::PROGRESS,
            "error control: the bodies' meshes outside the contact are too coarse for the tolerance; \
             solving again with them bisected"
        );
        resume = Some((last, met.problem.grid().clone(), met.state.clone()));
        scene = bisected;
    }
    unreachable!("the loop returns on its last bisection")
}

/// How the refinement of the contact grid ended: on a grid that meets the tolerance (with the
/// units of its estimate; the solve waiting for its outputs without its slip blocks), or otherwise (a solve that did not converge, `reached` true; the
/// element limit or the pass limit, `reached` false).
enum Refined {
    Met(Solve<WithoutSlipBlocks>, Scales, DyadicGrid),
    Ended(Solve, bool),
}

/// The loop of the module docs on `scene`'s bodies as they are: passes until the contact
/// grid meets the tolerance (each pass appended to `steps`), its bodies built with the run's
/// caches `run`.
fn refine(
    scene: &Scene,
    resume: Option<(DyadicGrid, ContactGrid, State)>,
    estimator: &mut dyn ErrorEstimator,
    run: &RunCaches,
    timings: &mut Timings,
    steps: &mut Vec<AdaptationStep>,
    ws: &mut Workspace,
) -> Result<Refined, Error> {
    let control = scene.grid_control.expect("an error-controlled grid");
    let (tolerance, max_elements) = (control.tolerance, control.max_elements);
    let start = DyadicGrid::new(&scene.grid);
    let shortest = scene.shortest_grid_element();
    // The stand-ins are fitted on the levels of the start grid, wherever the passes start.
    let mut stand_ins = stand_ins::PassStandIns::build(scene, &start, tolerance, run, timings)?;
    let (mut coarse, mut warm) = match resume {
        Some((grid, from, state)) => (grid, Some((from, state))),
        None => (start, None),
    };
    let mut hertz: Option<HertzScales> = None;
    let first_step = steps.len();
    loop {
        let pass_scene = stand_ins.passes.as_ref().unwrap_or(scene);
        let from_stand_ins = stand_ins.passes.is_some();
        let mut g = solve_on(
            pass_scene.on_grid(coarse.grid()),
            warm.as_ref().map(|(g, z)| (g, z)),
            false,
            Some(run),
            timings,
            ws,
        )?;
        g.from_stand_ins = from_stand_ins;
        if !g.report.converged {
            return Ok(Refined::Ended(g, true));
        }
        let hertz = *hertz.get_or_insert_with(|| HertzScales::of_run(scene, &g.problem, &g.state));
        let scales = hertz.scales(scene);
        let mut h = solve_on(
            pass_scene.on_grid(coarse.bisected().grid()),
            Some((&g.problem.grid, &g.state)),
            false,
            Some(run),
            timings,
            ws,
        )?;
        h.from_stand_ins = from_stand_ins;
        if !h.report.converged {
            return Ok(Refined::Ended(h, true));
        }
        let singular = singular_points(&h.problem, &h.state);
        let mut cmp = estimator.estimate(&Pass {
            coarse_grid: &g.problem.grid,
            coarse: &g.state,
            fine_grid: &h.problem.grid,
            fine: &h.state,
            singular: &singular,
            scales,
        });
        if overlap::controlled(scene) {
            cmp.estimate.overlap_rel = Some(overlap::relative_error(g.state.overlap, h.state.overlap));
        }
        let e = cmp.estimate;
        steps.push(AdaptationStep {
            elements: h.problem.grid.n_elements(),
            nodes: h.problem.n_nodes(),
            estimate: e,
            iterations: g.report.iterations + h.report.iterations,
        });
        log::info!(
            target: crate::logging::PROGRESS,
            "error control, pass {}: {} elements, estimated error: pressure {:.2e} p0, shear {:.2e} mu p0, \
             creepage {:.2e}, overlap {}",
            steps.len(),
            h.problem.grid.n_elements(),
            e.pressure_rms,
            e.shear_rms,
            e.creep_rel,
            e.overlap_rel.map_or("not controlled".to_string(), |o| format!("{o:.2e}"))
        );
        let half_width = hertz.half_width;
        let lengths = APriori::of_pass(scene, &h, &singular, tolerance, half_width);
        if e.within(tolerance) && resolved(&h.problem.grid, &singular, &lengths) {
            match stand_ins.finish(scene, g, h, e, scales, tolerance, steps.last_mut(), run, timings, ws)? {
                stand_ins::Final::Met(s) => return Ok(Refined::Met(s, scales, coarse)),
                stand_ins::Final::Ended(s) => return Ok(Refined::Ended(s, true)),
                stand_ins::Final::GoOn(full) => {
                    warm = Some((full.problem.grid, full.state));
                    continue;
                }
            }
        }
        let Some(marked) = actions(&coarse, &cmp, &singular, tolerance, &lengths, shortest) else {
            log::warn!(
                "the contact grid cannot be refined further: its elements reached the shortest length \
                 the bodies' meshes can be cut to ({shortest:.3e})"
            );
            return Ok(Refined::Ended(h, false));
        };
        let next = coarse.refined(&marked);
        log::debug!("singular points {singular:?}; next grid {} elements", next.len());
        let finer = 2 * next.len();
        let ends = finer > max_elements || steps.len() - first_step >= MAX_PASSES;
        if ends || !crate::scene::preflight::finer_grid_fits(&scene.case, &scene.bodies, finer) {
            // The best solution reached, marked: the driver reports it as not converged.
            return Ok(Refined::Ended(h, false));
        }
        warm = Some((h.problem.grid, h.state));
        coarse = next;
    }
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
            results_from_stand_ins: s.from_stand_ins,
        }),
        scene: s.scene,
        models: s.models,
        problem: s.problem,
        state: s.state,
        report: s.report,
        timings,
    }
}

/// Where the tractions have square-root points [length]: between neighbouring nodes where the
/// contact opens (an edge), where stick turns to slip, and where the slip reverses.
fn singular_points(pb: &ContactProblem, z: &State) -> Vec<f64> {
    let sol = ContactSolution::from_state(pb, z);
    let x = &pb.grid.nodes;
    (1..x.len())
        .filter(|&i| {
            let (a, b) = (sol.state[i - 1], sol.state[i]);
            let reversal = a == NodeState::Slip && b == NodeState::Slip && sol.shear[i - 1] * sol.shear[i] < 0.0;
            a != b || reversal
        })
        .map(|i| 0.5 * (x[i - 1] + x[i]))
        .collect()
}

/// What to do with each element of `coarse` (module docs, step 4), no element of the bisection
/// of the result shorter than `shortest` [length]; None when no element can be halved.
fn actions(
    coarse: &DyadicGrid,
    cmp: &Comparison,
    singular: &[f64],
    tolerance: f64,
    lengths: &APriori,
    shortest: f64,
) -> Option<Vec<Action>> {
    let indicator = &cmp.detail;
    let active = indicator.iter().filter(|&&z| z > 0.0).count().max(1);
    // The estimate (squared) is taken to fall with the sum of the local indicators: to bring
    // the largest of the three estimates to SAFETY·tolerance, the sum must fall by `factor`,
    // shared equally among the elements that carry it.
    let largest = cmp.estimate.largest();
    let factor = if largest > 0.0 {
        (SAFETY * tolerance / largest).powi(2).min(1.0)
    } else {
        1.0
    };
    let target = indicator.iter().sum::<f64>() * factor / active as f64;
    // The creepage's error alone above the tolerance, the tractions' an order of magnitude
    // below it: the creepage is a functional of the shear over the whole stick zone, and its
    // error is the smooth error there, which the indicators do not see: every element in the
    // contact is halved (module docs).
    let e = &cmp.estimate;
    let creepage_alone = e.creep_rel > tolerance && e.pressure_rms.max(e.shear_rms) <= CREEPAGE_ALONE * tolerance;
    let mut action: Vec<Action> = coarse
        .cells()
        .iter()
        .zip(indicator)
        .zip(&cmp.open)
        .map(|((&c, &z), &open)| {
            let (x0, x1) = (coarse.end(c, false), coarse.end(c, true));
            let inside = singular.iter().copied().find(|&x| x >= x0 && x <= x1);
            // The nearest square-root point, when it lies within an element length: the
            // discrete transition may sit one node off the true one, in this element.
            let near = singular
                .iter()
                .copied()
                .filter(|&x| (x0 - x).max(x - x1).max(0.0) <= x1 - x0)
                .min_by(|a, b| (a - 0.5 * (x0 + x1)).abs().total_cmp(&(b - 0.5 * (x0 + x1)).abs()));
            // An element of H holding a square-root point is at most A_PRIORI_LENGTH·tolerance·a
            // long: a node beside the point has an error ∝ √(h/a), standing for a length h, so
            // its share of the RMS is ∝ h/a whatever the estimate saw (a node can fall close
            // enough to the point that both grids miss its error). Graded there in one pass, as
            // deep as the rule asks: the point is located to H's node spacing, and where the next
            // pass finds it elsewhere it grades again there, as [`resolved`] asks of every pass.
            // (Three halvings a pass at most, as before, left the rule for one more pass where
            // the estimate already met the tolerance: fig14_true_geometry at 1e-5, four passes
            // to 518 elements against three to 454 now.)
            let a_priori = inside.map_or(0, |x| {
                // G's element is halved once more in H.
                let ratio = (x1 - x0) / (2.0 * lengths.at(x));
                if ratio > 1.0 {
                    (ratio.log2().ceil() as u32).min(MAX_DEPTH_PER_PASS)
                } else {
                    0
                }
            });
            if z > target && target > 0.0 {
                let ratio = (z / target).log2();
                let depth =
                    |per_halving: f64| (ratio / per_halving).ceil().clamp(1.0, f64::from(MAX_DEPTH_PER_PASS)) as u32;
                match inside.or(near) {
                    // Next to a square-root point the share falls by 4 per halving.
                    Some(x) => Action::GradeTowards(x.clamp(x0, x1), depth(2.0).max(a_priori)),
                    // Where the solution is smooth, by 2⁷ (nodal error h³, over a length h): one
                    // halving a pass is plenty, and keeps a pass from multiplying the grid.
                    None => Action::Split(depth(7.0).min(1)),
                }
            } else if let (Some(x), true) = (inside, a_priori > 0) {
                Action::GradeTowards(x, a_priori)
            } else if creepage_alone && !open {
                Action::Split(1)
            } else if open && inside.is_none() && z <= target / 64.0 {
                Action::Merge
            } else {
                Action::Keep
            }
        })
        .collect();
    // The grid's H halves each element of the result once more: 2^(depth + 1) pieces of an
    // element must each be at least `shortest` long.
    let deepest: Vec<u32> = coarse
        .cells()
        .iter()
        .map(|&c| {
            let pieces = (coarse.end(c, true) - coarse.end(c, false)) / shortest;
            (pieces.log2().floor() - 1.0).max(0.0) as u32
        })
        .collect();
    for (a, &d) in action.iter_mut().zip(&deepest) {
        *a = match *a {
            Action::Split(_) | Action::GradeTowards(..) if d == 0 => Action::Keep,
            Action::Split(k) => Action::Split(k.min(d)),
            Action::GradeTowards(x, k) => Action::GradeTowards(x, k.min(d)),
            other => other,
        };
    }
    // Never a pass without a refinement: the element with the largest share is halved.
    if !action
        .iter()
        .any(|a| matches!(a, Action::Split(_) | Action::GradeTowards(..)))
    {
        let worst = (0..indicator.len())
            .filter(|&k| deepest[k] > 0)
            .max_by(|&a, &b| indicator[a].total_cmp(&indicator[b]))?;
        action[worst] = Action::Split(1);
    }
    Some(action)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::grid::ElementKind;

    /// A grid of four elements of length 1/2 on [−1, 1] whose third holds a square-root point
    /// at 0.3 and carries all the error, far above the tolerance.
    fn marked(shortest: f64) -> Option<Vec<Action>> {
        let coarse = DyadicGrid::new(&ContactGrid::uniform(ElementKind::DiscontinuousQuadratic, 4, -1.0, 1.0));
        let cmp = Comparison {
            estimate: crate::post::adaptation::ErrorEstimate {
                pressure_rms: 1e-1,
                shear_rms: 1e-1,
                creep_rel: 1e-1,
                overlap_rel: None,
                body_mesh: None,
            },
            detail: vec![0.0, 0.0, 1.0, 0.0],
            open: vec![false; 4],
        };
        let lengths = APriori {
            everywhere: A_PRIORI_LENGTH * 1e-4,
            leading_edge: None,
        };
        actions(&coarse, &cmp, &[0.3], 1e-4, &lengths, shortest)
    }

    /// The grading towards a square-root point stops where the grid's bisection would hold an
    /// element shorter than the bodies' meshes can be cut to; with no element left to halve
    /// there is nothing to do (the run then ends, not reaching the tolerance, instead of cutting
    /// a mesh into elements of zero length).
    #[test]
    fn no_element_is_graded_below_the_shortest_length() {
        let depth = |a: &Action| match *a {
            Action::GradeTowards(_, k) | Action::Split(k) => k,
            _ => 0,
        };
        // Unlimited: graded as deep as a pass grades.
        let free = marked(1e-12).expect("a refinement");
        assert!(depth(&free[2]) > 3, "{:?}", free[2]);
        // Pieces of 1/16 at most (1/2 halved three times, once more in H): depth 2.
        let limited = marked(1.0 / 16.0).expect("a refinement");
        assert_eq!(depth(&limited[2]), 2, "{:?}", limited[2]);
        // Elements of 1/2 whose bisection is 1/4 already: none can be halved.
        assert!(marked(0.2).is_none());
    }
}
