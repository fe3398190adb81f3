//! The driver: case → body models → contact problem → solver → solution → outputs.

use crate::analytic::{self, Carter};
use crate::bem::{BemModel, BemOptions, BoundaryCondition};
use crate::body::bem::BemBody;
use crate::body::half_space::HalfSpace;
use crate::body::rigid::Rigid;
use crate::body::transfer::Transferred;
use crate::body::{Body, BoundaryField, ContactLoad, InteriorQuery, Side, WithCircularProfile};
use crate::case::{self, BodySpec, BoundaryKeyword, BoundarySpec, LoadedCase, NormalSpec, TangentialSpec};
use crate::contact::methods;
use crate::contact::solution::{slip_regime, ContactSolution, SlipRegime};
use crate::contact::{ContactProblem, NormalControl, TangentialControl};
use crate::contact::{NewtonSettings, SolveReport, SolverSettings};
use crate::error::Error;
use crate::grid::ContactGrid;
use crate::material::{self, Elastic};
use crate::mesh::BoundaryMesh;
use crate::output::{self, Summary};
use serde::Serialize;
use std::path::{Path, PathBuf};
use std::time::Instant;

pub mod finite;
pub mod preflight;

/// Hertz-type estimates of a scene (also what `rollbem check` prints).
#[derive(Debug, Clone, Serialize)]
pub struct Estimates {
    /// Contact modulus E* [stress].
    pub e_star: f64,
    /// Dundurs' β with A first (κ = 2β in Bentall–Johnson / paper Eq. 78).
    pub dundurs_beta: f64,
    /// Effective radius R, 1/R = 1/R_A + 1/R_B [length].
    pub effective_radius: f64,
    /// Normal force P used for the estimates (given, or estimated from the overlap) [force/length].
    pub normal_force: f64,
    /// Hertz half-width a [length].
    pub hertz_half_width: f64,
    /// Hertz peak pressure p0 [stress].
    pub hertz_peak_pressure: f64,
    /// a / R.
    pub half_width_over_radius: f64,
    /// Carter stick-zone width 2a√(1 − |Q|/μP) (similar bodies), if Q/μP is known [length].
    pub carter_stick_width: Option<f64>,
    /// Grid half-length [length].
    pub grid_half_length: f64,
    /// Node spacing of the grid [length].
    pub grid_spacing: f64,
}

/// A boundary mesh loaded for a `bem` body.
#[derive(Debug, Clone)]
pub struct LoadedMesh {
    /// The mesh file.
    pub path: PathBuf,
    /// The checked and oriented mesh.
    pub mesh: BoundaryMesh,
    /// One notice per loop that was turned round.
    pub notices: Vec<String>,
    /// Index of the contact group.
    pub contact_group: usize,
}

impl LoadedMesh {
    /// x-range [x_min, x_max] of the contact segment [length].
    pub fn contact_range(&self) -> [f64; 2] {
        let xs = self.contact_nodes().map(|p| p[0]);
        xs.fold([f64::INFINITY, f64::NEG_INFINITY], |[lo, hi], x| [lo.min(x), hi.max(x)])
    }

    /// The nodes of the contact group's elements [length].
    pub fn contact_nodes(&self) -> impl Iterator<Item = [f64; 2]> + '_ {
        self.mesh
            .elements
            .iter()
            .filter(|e| e.group == self.contact_group)
            .flat_map(|e| e.nodes.iter().map(|&n| self.mesh.nodes[n]))
    }

    /// Radius of the contact segment's profile [length]: the algebraic least-squares circle
    /// (Kåsa fit: x² + y² + Dx + Ey + F = 0), exact for nodes on a circle; infinite when the
    /// segment is straight (the fit's centre then runs away: R > 1e6 times the segment length).
    pub fn contact_radius(&self) -> f64 {
        let pts: Vec<[f64; 2]> = self.contact_nodes().collect();
        // Normal equations of min Σ (D x + E y + F + x² + y²)², centred for conditioning.
        let n = pts.len() as f64;
        let (cx, cy) = (
            pts.iter().map(|p| p[0]).sum::<f64>() / n,
            pts.iter().map(|p| p[1]).sum::<f64>() / n,
        );
        let mut a = nalgebra::Matrix3::<f64>::zeros();
        let mut b = nalgebra::Vector3::<f64>::zeros();
        for p in &pts {
            let (x, y) = (p[0] - cx, p[1] - cy);
            let row = nalgebra::Vector3::new(x, y, 1.0);
            a += row * row.transpose();
            b -= row * (x * x + y * y);
        }
        let [x0, x1] = self.contact_range();
        let span = (x1 - x0).max(f64::MIN_POSITIVE);
        match a.lu().solve(&b) {
            Some(s) => {
                let r2 = 0.25 * (s[0] * s[0] + s[1] * s[1]) - s[2];
                let r = r2.max(0.0).sqrt();
                if r.is_finite() && r < 1e6 * span {
                    r
                } else {
                    f64::INFINITY
                }
            }
            None => f64::INFINITY,
        }
    }

    /// The contact grid of the mesh's own contact elements: their end points in x, with
    /// discontinuous quadratic interpolation (the BEM contact elements' field nodes).
    pub fn contact_grid(&self) -> ContactGrid {
        let mut edges: Vec<f64> = self
            .mesh
            .elements
            .iter()
            .filter(|e| e.group == self.contact_group)
            .flat_map(|e| {
                let (a, b) = e.ends();
                [self.mesh.nodes[a][0], self.mesh.nodes[b][0]]
            })
            .collect();
        edges.sort_by(f64::total_cmp);
        let tol = 1e-9 * self.mesh.size();
        edges.dedup_by(|a, b| (*a - *b).abs() <= tol);
        ContactGrid::from_edges(crate::grid::ElementKind::DiscontinuousQuadratic, edges)
    }

    /// Total length of the elements of a group (polyline through end, mid, end nodes) [length].
    pub fn group_length(&self, group: usize) -> f64 {
        let d = |a: [f64; 2], b: [f64; 2]| ((a[0] - b[0]).powi(2) + (a[1] - b[1]).powi(2)).sqrt();
        self.mesh
            .elements
            .iter()
            .filter(|e| e.group == group)
            .map(|e| match e.nodes.as_slice() {
                [a, b, m] => d(self.mesh.nodes[*a], self.mesh.nodes[*m]) + d(self.mesh.nodes[*m], self.mesh.nodes[*b]),
                [a, b] => d(self.mesh.nodes[*a], self.mesh.nodes[*b]),
                _ => 0.0,
            })
            .sum()
    }
}

/// A body spec resolved against the case: material, profile radius, and mesh for `bem`.
#[derive(Debug, Clone)]
pub struct PreparedBody {
    /// Elastic constants, None for a rigid body.
    pub material: Option<Elastic>,
    /// Profile radius [length] (infinite for a flat profile).
    pub radius: f64,
    /// The mesh of a `bem` body.
    pub mesh: Option<LoadedMesh>,
}

/// Resolves a body spec: loads and checks the mesh of a `bem` body (paths relative to the case).
pub fn prepare_body(case: &LoadedCase, spec: &BodySpec) -> Result<PreparedBody, Error> {
    Ok(match spec {
        BodySpec::HalfSpace { material, radius } => PreparedBody {
            material: Some(case.material(material)),
            radius: *radius,
            mesh: None,
        },
        BodySpec::Rigid { radius, mesh, contact } => PreparedBody {
            material: None,
            radius: match (radius, mesh) {
                (Some(r), _) => *r,
                (None, Some(mesh)) => rigid_profile_radius(case, mesh, contact)?,
                (None, None) => unreachable!("validated: a rigid body has a radius or a mesh"),
            },
            mesh: None,
        },
        BodySpec::Bem {
            mesh,
            material,
            contact,
            boundaries,
            radius,
        } => {
            let path = case.base_dir().join(mesh);
            let (m, notices) = crate::mesh::load(&path)?;
            let contact_group = m.group_index(contact)?;
            for name in m.group_names() {
                if name != *contact && !boundaries.contains_key(&name) {
                    return Err(Error::MissingBoundary {
                        case: case.path.clone(),
                        mesh: path.clone(),
                        group: name,
                    });
                }
            }
            for name in boundaries.keys() {
                m.group_index(name)?;
            }
            let loaded = LoadedMesh {
                path,
                mesh: m,
                notices,
                contact_group,
            };
            PreparedBody {
                material: Some(case.material(material)),
                radius: radius.unwrap_or_else(|| loaded.contact_radius()),
                mesh: Some(loaded),
            }
        }
    })
}

/// Profile radius of a rigid body given by a mesh: the circle fitted to its contact group
/// ([`LoadedMesh::contact_radius`]). The mesh is read only for its outline; it does not set the
/// contact grid.
fn rigid_profile_radius(case: &LoadedCase, mesh: &str, contact: &str) -> Result<f64, Error> {
    let path = case.base_dir().join(mesh);
    let (m, _) = crate::mesh::load(&path)?;
    let contact_group = m.group_index(contact)?;
    let loaded = LoadedMesh {
        path,
        mesh: m,
        notices: Vec::new(),
        contact_group,
    };
    Ok(loaded.contact_radius())
}

/// Both bodies of a case, prepared.
pub fn prepare_bodies(case: &LoadedCase) -> Result<[PreparedBody; 2], Error> {
    Ok([
        prepare_body(case, &case.case.bodies.a)?,
        prepare_body(case, &case.case.bodies.b)?,
    ])
}

/// The BEM boundary condition of a case's boundary spec.
fn boundary_condition(spec: &BoundarySpec) -> BoundaryCondition {
    match spec {
        BoundarySpec::Keyword(BoundaryKeyword::Fixed) => BoundaryCondition::Fixed,
        BoundarySpec::Keyword(BoundaryKeyword::Free) => BoundaryCondition::Free,
        BoundarySpec::Prescribed(p) => match (p.displacement, p.traction, p.pressure) {
            (Some(u), _, _) => BoundaryCondition::Displacement(u),
            (_, Some(t), _) => BoundaryCondition::Traction(t),
            (_, _, Some(pr)) => BoundaryCondition::Pressure(pr),
            _ => BoundaryCondition::Free,
        },
    }
}

/// Builds the body model of a prepared spec, seen on the contact `grid` from `side`.
///
/// A `bem` body is condensed to its own contact nodes; if those differ from the grid's, its
/// flexibility is carried over by [`Transferred`].
pub fn body_model(
    spec: &BodySpec,
    prepared: &PreparedBody,
    grid: &ContactGrid,
    side: Side,
) -> Result<Box<dyn Body>, Error> {
    match spec {
        BodySpec::HalfSpace { .. } => Ok(Box::new(HalfSpace {
            material: prepared.material.expect("half-space bodies have a material"),
            radius: prepared.radius,
        })),
        BodySpec::Rigid { .. } => Ok(Box::new(Rigid {
            radius: prepared.radius,
        })),
        BodySpec::Bem {
            contact,
            boundaries,
            radius,
            ..
        } => {
            let lm = prepared.mesh.as_ref().expect("bem bodies have a mesh");
            let mut conditions: Vec<(String, BoundaryCondition)> = boundaries
                .iter()
                .map(|(g, b)| (g.clone(), boundary_condition(b)))
                .collect();
            conditions.push((contact.clone(), BoundaryCondition::Contact));
            let material = prepared.material.expect("bem bodies have a material");
            let model = BemModel::new(lm.mesh.clone(), material, conditions, BemOptions::default())?;
            let own = lm.contact_grid();
            let body = BemBody::new(model, contact, &own, side)?;
            let on_grid: Box<dyn Body> = if own.coincides_with(grid) {
                Box::new(body)
            } else {
                let t = Transferred {
                    inner: Box::new(body),
                    own_grid: own,
                    side,
                };
                t.check(grid)?;
                Box::new(t)
            };
            Ok(match radius {
                Some(r) => Box::new(WithCircularProfile {
                    inner: on_grid,
                    radius: *r,
                }),
                None => on_grid,
            })
        }
    }
}

/// The contact grid: a `bem` body's own contact elements (A's first), else the uniform grid of
/// the case around the Hertz contact.
pub fn contact_grid(case: &LoadedCase, est: &Estimates, bodies: &[PreparedBody; 2]) -> ContactGrid {
    match bodies.iter().find_map(|b| b.mesh.as_ref()) {
        Some(lm) => lm.contact_grid(),
        None => ContactGrid::uniform(
            case.case.contact.grid.element,
            case.case.contact.grid.elements,
            -est.grid_half_length,
            est.grid_half_length,
        ),
    }
}

/// Normal force that gives the overlap δ0 between two half-planes measured from their datums:
/// δ0 = Σ_b (2(1−ν_b²)/(πE_b))·P·(ln(4R_b/a) − ½), a the Hertz half-width of P
/// (reference sheet §6b; the datum of [`HalfSpace`]). Used only to size the grid.
fn load_from_overlap(overlap: f64, bodies: [(Option<Elastic>, f64); 2], radius: f64, e_star: f64) -> f64 {
    let approach = |p: f64| {
        let a = analytic::hertz_half_width(p, radius, e_star);
        bodies
            .iter()
            .filter_map(|(m, r)| m.map(|m| m.halfplane_log_coefficient() * p * ((4.0 * r / a).ln() - 0.5)))
            .sum::<f64>()
    };
    // Bisection in log P: the approach grows with P while a ≪ R.
    let (mut lo, mut hi) = (1e-12 * e_star * radius, 1e-2 * e_star * radius);
    for _ in 0..200 {
        let mid = (lo * hi).sqrt();
        if approach(mid) < overlap {
            lo = mid;
        } else {
            hi = mid;
        }
    }
    (lo * hi).sqrt()
}

/// Half-length L ≈ extent·a of a grid of `elements` equal elements on [−L, L] such that ±a are
/// element boundaries: with k elements outside the contact on each side, L = a·n/(n − 2k).
pub fn aligned_half_length(a: f64, extent: f64, elements: usize) -> f64 {
    let n = elements as f64;
    let k = (0.5 * n * (1.0 - 1.0 / extent)).round().max(1.0);
    if n - 2.0 * k >= 1.0 {
        a * n / (n - 2.0 * k)
    } else {
        extent * a
    }
}

/// Hertz estimates and the grid half-length of a case.
pub fn estimates(case: &LoadedCase, bodies: &[PreparedBody; 2]) -> Estimates {
    let c = &case.case;
    let [ba, bb] = bodies;
    let (ma, mb) = (ba.material, bb.material);
    let e_star = material::contact_modulus(ma.as_ref(), mb.as_ref());
    let dundurs_beta = material::dundurs_beta(ma.as_ref(), mb.as_ref());
    let radius = material::effective_radius(ba.radius, bb.radius);
    let normal_force = match c.load.normal() {
        NormalSpec::Force(p) => p,
        NormalSpec::Overlap(d) => load_from_overlap(d, [(ma, ba.radius), (mb, bb.radius)], radius, e_star),
    };
    let a = analytic::hertz_half_width(normal_force, radius, e_star);
    let ratio = match c.load.tangential() {
        TangentialSpec::Ratio(r) => Some(r),
        TangentialSpec::Force(q) if c.contact.friction > 0.0 => Some(q / (c.contact.friction * normal_force)),
        _ => None,
    };
    let g = &c.contact.grid;
    let grid_half_length = match g.half_length {
        Some(h) => h,
        None if g.align_edges => aligned_half_length(a, g.extent, g.elements),
        None => g.extent * a,
    };
    // Node intervals per element: shared end nodes count once.
    let npe = c.contact.grid.element.node_stride();
    Estimates {
        e_star,
        dundurs_beta,
        effective_radius: radius,
        normal_force,
        hertz_half_width: a,
        hertz_peak_pressure: analytic::hertz_peak_pressure(normal_force, a),
        half_width_over_radius: a / radius,
        carter_stick_width: ratio
            .filter(|r| r.abs() < 1.0)
            .map(|r| 2.0 * a * (1.0 - r.abs()).sqrt()),
        grid_half_length,
        grid_spacing: 2.0 * grid_half_length / (c.contact.grid.elements * npe) as f64,
    }
}

/// The solver settings of a case.
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

/// Assembles the contact problem of a case.
/// Returns the seconds spent condensing BEM bodies (included in the build time), the two body
/// models and the problem.
pub fn build_problem(
    case: &LoadedCase,
    est: &Estimates,
    bodies: &[PreparedBody; 2],
) -> Result<(f64, BodyModels, ContactProblem), Error> {
    let c = &case.case;
    let grid = contact_grid(case, est, bodies);
    let normal = match c.load.normal() {
        NormalSpec::Force(p) => NormalControl::Force(p),
        NormalSpec::Overlap(d) => NormalControl::Overlap(d),
    };
    let tangential = match c.load.tangential() {
        TangentialSpec::Ratio(r) => TangentialControl::Ratio(r),
        TangentialSpec::Force(q) => TangentialControl::Force(q),
        TangentialSpec::Creep(x) => TangentialControl::Creep(x),
    };
    let a = body_model(&c.bodies.a, &bodies[0], &grid, Side::A)?;
    let b = body_model(&c.bodies.b, &bodies[1], &grid, Side::B)?;
    let condense_s = a.stage_seconds().1 + b.stage_seconds().1;
    let problem = ContactProblem::assemble(
        grid,
        a.model(),
        b.model(),
        c.contact.slip_derivative,
        c.contact.friction,
        c.contact.rolling_direction,
        normal,
        tangential,
    );
    Ok((condense_s, [a, b], problem))
}

/// The built body models of A and B.
pub type BodyModels = [Box<dyn Body>; 2];

/// Wall-clock time of each stage [s].
#[derive(Debug, Clone, Copy, Default, Serialize)]
pub struct Timings {
    /// Influence coefficients / BEM assembly.
    pub assembly_s: f64,
    /// Condensation to the contact nodes (zero for closed-form models).
    pub condense_s: f64,
    /// Contact solve.
    pub solve_s: f64,
    /// Interior fields of `output.interior` (post-processing; 0 when not asked).
    pub interior_s: f64,
    /// Whole run including output.
    pub total_s: f64,
}

/// Everything a run produced.
#[derive(Debug, Clone)]
pub struct RunReport {
    /// The summary written to summary.json.
    pub summary: Summary,
    /// The solution (also for a non-converged run: the last iterate, not written as a result).
    pub solution: ContactSolution,
    /// The assembled problem.
    pub problem: ContactProblem,
    /// Solver report.
    pub report: SolveReport,
    /// Where the outputs were written.
    pub output_dir: PathBuf,
}

/// A solved case, before anything is written.
#[derive(Debug, Clone)]
pub struct Solved {
    /// Hertz estimates.
    pub estimates: Estimates,
    /// The assembled problem.
    pub problem: ContactProblem,
    /// The solution (for a non-converged run: the last iterate).
    pub solution: ContactSolution,
    /// Solver report.
    pub report: SolveReport,
    /// Stage timings (total excludes output).
    pub timings: Timings,
    /// Slip regime 1–4 (paper §5.2), 0 for none.
    pub regime: SlipRegime,
    /// Whole-boundary fields of A and B (bem bodies, when VTK output is on).
    pub boundary: [Option<BoundaryField>; 2],
    /// Notices for the user (e.g. mesh loops turned round).
    pub notices: Vec<String>,
    /// Interior displacements and stresses, when `output.interior` asks for them.
    pub interior: Option<crate::interior::InteriorField>,
}

/// Assembles and solves a loaded case; checks that the grid contains the contact.
pub fn solve(case: &LoadedCase) -> Result<Solved, Error> {
    let start = Instant::now();
    let bodies = prepare_bodies(case)?;
    solve_prepared(case, &bodies, start)
}

/// [`solve`] with the bodies already prepared (e.g. with procedural meshes, as the accuracy
/// study builds them); `start` is when the run began, for the timings.
pub fn solve_prepared(case: &LoadedCase, bodies: &[PreparedBody; 2], start: Instant) -> Result<Solved, Error> {
    let estimates = estimates(case, bodies);
    preflight::check(case, &estimates, bodies)?;
    let (condense_s, models, problem) = build_problem(case, &estimates, bodies)?;
    let mut timings = Timings {
        assembly_s: start.elapsed().as_secs_f64() - condense_s,
        condense_s,
        ..Timings::default()
    };
    let t_solve = Instant::now();
    let (state, report) = methods::solve(&problem, &solver_settings(case));
    timings.solve_s = t_solve.elapsed().as_secs_f64();
    timings.total_s = start.elapsed().as_secs_f64();
    let solution = ContactSolution::from_state(&problem, &state);
    finite::check(&case.path, "the solver's residual history", &report.history)?;
    finite::check(&case.path, "the contact solution", &solution)?;
    if report.converged {
        check_grid_contains_contact(case, &solution)?;
    }
    let leading = -case.case.contact.rolling_direction.flow_sign();
    let regime = slip_regime(&solution, leading, 1);
    let boundary = if report.converged && case.case.output.vtk {
        let load = ContactLoad {
            grid: &problem.grid,
            pressure: &solution.pressure,
            shear: &solution.shear,
        };
        let field = |m: &dyn Body| {
            m.boundary_field(&load)
                .transpose()
                .map_err(|e| Error::BoundaryField(Box::new(e)))
        };
        [field(models[0].as_ref())?, field(models[1].as_ref())?]
    } else {
        [None, None]
    };
    let mut notices: Vec<String> = bodies
        .iter()
        .filter_map(|b| b.mesh.as_ref())
        .flat_map(|m| m.notices.clone())
        .collect();
    let t_interior = Instant::now();
    let interior = match (&case.case.output.interior, report.converged) {
        (Some(spec), true) => Some(interior_field(case, spec, &models, &problem, &solution)?),
        _ => None,
    };
    timings.interior_s = t_interior.elapsed().as_secs_f64();
    finite::check_fields(&case.path, interior.as_ref(), &boundary)?;
    if let Some(f) = &interior {
        let [_, outside, boundary] = f.counts();
        if outside + boundary > 0 {
            notices.push(format!(
                "output.interior: of {} points of body {}, {outside} lie outside the body and \
                 {boundary} on its boundary (closer than {} element lengths); they are not \
                 evaluated: status `outside`/`boundary`, fields written as 0",
                f.points.len(),
                f.body,
                crate::interior::InteriorOptions::default().boundary_layer
            ));
        }
    }
    Ok(Solved {
        interior,
        notices,
        boundary,
        estimates,
        problem,
        solution,
        report,
        timings,
        regime,
    })
}

/// The interior fields that `output.interior` asks for, from the body's own model (Somigliana
/// for a bem body, Flamant superposition for a half-space) under the solved contact tractions.
fn interior_field(
    case: &LoadedCase,
    spec: &crate::case::InteriorSpec,
    models: &BodyModels,
    problem: &ContactProblem,
    solution: &ContactSolution,
) -> Result<crate::interior::InteriorField, Error> {
    let (k, side) = if spec.body == "B" { (1, Side::B) } else { (0, Side::A) };
    let model = models[k].as_ref();
    let points = crate::interior::grid_points(spec.x, spec.y);
    let query = InteriorQuery {
        side,
        load: ContactLoad {
            grid: &problem.grid,
            pressure: &solution.pressure,
            shear: &solution.shear,
        },
        points: &points,
        options: crate::interior::InteriorOptions::default(),
    };
    let samples = model.interior(&query).map_err(|source| Error::Interior {
        case: case.path.clone(),
        body: spec.body.clone(),
        source: Box::new(source),
    })?;
    let shape = [spec.x[2] as usize, spec.y[2] as usize];
    Ok(crate::interior::InteriorField::from_samples(
        &spec.body,
        model.model_name(),
        shape,
        points,
        &samples,
    ))
}

/// Loads a case, solves it and writes its outputs (DESIGN §5). A run that does not converge
/// writes only summary.json (with `converged: false` and the residual history) and returns
/// `Ok` with `summary.converged == false`.
pub fn run(case_path: &Path, overrides: &[String], out: Option<&Path>) -> Result<RunReport, Error> {
    let start = Instant::now();
    let case = case::load(case_path, overrides)?;
    let output_dir = out.map(Path::to_path_buf).unwrap_or_else(|| case.output_dir());
    // Lock and check the output folder before solving: a foreign or busy folder fails at once.
    let _claim = output::folder::Claim::acquire(
        &output_dir,
        output::folder::Kind::Run,
        output::folder::Access::Exclusive,
    )?;
    let s = solve(&case)?;
    let mut summary = output::summary(
        &case,
        &s.estimates,
        &s.problem,
        &s.solution,
        &s.report,
        s.regime,
        s.timings,
    );
    summary.notices = s.notices.clone();
    summary.interior = s.interior.as_ref().map(crate::interior::InteriorField::summary);
    finite::check(&case.path, "summary.json", &summary)?;
    output::write_run(
        &output_dir,
        &mut summary,
        &s.solution,
        &s.problem,
        &s.boundary,
        s.interior.as_ref(),
        start,
    )?;
    Ok(RunReport {
        summary,
        solution: s.solution,
        problem: s.problem,
        report: s.report,
        output_dir,
    })
}

fn check_grid_contains_contact(case: &LoadedCase, sol: &ContactSolution) -> Result<(), Error> {
    let m = sol.x.len();
    for (i, end) in [(0, "left"), (m - 1, "right")] {
        if sol.pressure[i] > 0.0 {
            return Err(Error::GridTooShort {
                case: case.path.clone(),
                end,
                x: sol.x[i],
                extent: case.case.contact.grid.extent,
                advice: preflight::grid_too_short_advice(case),
            });
        }
    }
    Ok(())
}

/// Carter's solution for the case's similar-body estimates (used by `check` and the tests).
pub fn carter_reference(case: &LoadedCase, est: &Estimates) -> Option<Carter> {
    let ratio = match case.case.load.tangential() {
        TangentialSpec::Ratio(r) => r,
        _ => return None,
    };
    Some(Carter {
        half_width: est.hertz_half_width,
        peak_pressure: est.hertz_peak_pressure,
        friction: case.case.contact.friction,
        ratio,
        leading_edge_sign: -case.case.contact.rolling_direction.flow_sign(),
    })
}

/// The text printed by `rollbem check`: the case as understood, with Hertz estimates.
/// `tolerance` is the accuracy the user needs (a fraction of p0 and μp0), for the model advice.
pub fn check_report(case_path: &Path, overrides: &[String], tolerance: f64) -> Result<String, Error> {
    let case = case::load(case_path, overrides)?;
    let bodies = prepare_bodies(&case)?;
    let est = estimates(&case, &bodies);
    let memory = preflight::check(&case, &est, &bodies)?;
    let grid = contact_grid(&case, &est, &bodies);
    let c = &case.case;
    let mut t = format!("rollbem check {}: valid\n", case_path.display());
    let mut line = |k: &str, v: String| t.push_str(&format!("  {k:<26} {v}\n"));
    line("title", c.title.clone());
    for (side, spec) in [("A", &c.bodies.a), ("B", &c.bodies.b)] {
        let text = match spec {
            BodySpec::HalfSpace { material, radius } => {
                let m = case.material(material);
                format!(
                    "half_space, R = {radius}, material `{material}` (E = {:.6}, G = {:.6}, nu = {})",
                    m.young,
                    m.shear(),
                    m.poisson
                )
            }
            BodySpec::Rigid { radius: Some(r), .. } => format!("rigid, R = {r}"),
            BodySpec::Rigid { mesh, contact, .. } => format!(
                "rigid, R = {:.6} (circle fitted to group `{contact}` of {})",
                bodies[if side == "A" { 0 } else { 1 }].radius,
                mesh.as_deref().unwrap_or("")
            ),
            BodySpec::Bem { mesh, material, .. } => {
                let m = case.material(material);
                format!(
                    "bem, mesh {mesh}, material `{material}` (E = {:.6}, G = {:.6}, nu = {})",
                    m.young,
                    m.shear(),
                    m.poisson
                )
            }
        };
        line(&format!("body {side}"), text);
    }
    let mut ranges = Vec::new();
    for (side, body) in ["A", "B"].iter().zip(&bodies) {
        let Some(lm) = &body.mesh else { continue };
        for (g, group) in lm.mesh.groups.iter().enumerate() {
            line(
                &format!("  {side}: group `{}`", group.name),
                format!(
                    "{} elements, length {:.6}",
                    lm.mesh.count_in_group(g),
                    lm.group_length(g)
                ),
            );
        }
        let loops = crate::mesh::check::boundary_loops(&lm.mesh)?;
        let holes = loops.iter().filter(|l| l.is_hole()).count();
        line(
            &format!("  {side}: loops"),
            format!("{} ({} outer, {holes} holes)", loops.len(), loops.len() - holes),
        );
        for n in &lm.notices {
            line(&format!("  {side}: notice"), n.clone());
        }
        let [x0, x1] = lm.contact_range();
        ranges.push([x0, x1]);
        line(
            &format!("  {side}: contact segment"),
            format!("x in [{x0:.6}, {x1:.6}], profile radius {:.6}", body.radius),
        );
    }
    for (side, body) in ["A", "B"].iter().zip(&bodies) {
        let Some(lm) = &body.mesh else { continue };
        let own = lm.contact_grid();
        if own.coincides_with(&grid) {
            line(
                &format!("  {side}: contact nodes"),
                "paired node to node with the contact grid".into(),
            );
        } else {
            let ratio = own.element_length() / grid.element_length();
            let advice = if ratio <= 0.5 {
                "fine enough"
            } else {
                "coarser than half the grid's elements: the transferred slip loses accuracy (about 8 % of the creepage at equal size); mesh the contact group at most half the grid's element length, or match the nodes"
            };
            line(
                &format!("  {side}: contact nodes"),
                format!("transferred to the grid by interpolation (element length ratio {ratio:.2}: {advice})"),
            );
        }
    }
    if let [[a0, a1], [b0, b1]] = ranges.as_slice() {
        let overlap = a1.min(*b1) - a0.max(*b0);
        line(
            "contact segments",
            if overlap > 0.0 {
                format!("A and B overlap on [{:.6}, {:.6}]", a0.max(*b0), a1.min(*b1))
            } else {
                "A and B DO NOT overlap in x: the bodies cannot touch there".to_string()
            },
        );
    }
    let (l, f) = (&c.units.length, &c.units.force);
    line("effective radius R", format!("{:.6} {l}", est.effective_radius));
    line("contact modulus E*", format!("{:.6} {f}/{l}^2", est.e_star));
    line(
        "Dundurs beta (kappa=2beta)",
        format!(
            "{:.6} ({:.6}); beta/mu = {:.4}",
            est.dundurs_beta,
            2.0 * est.dundurs_beta,
            est.dundurs_beta / c.contact.friction.max(f64::MIN_POSITIVE)
        ),
    );
    let given = matches!(c.load.normal(), NormalSpec::Force(_));
    line(
        "normal force P",
        format!(
            "{:.6} {f}/{l}{}",
            est.normal_force,
            if given { "" } else { " (estimated from the overlap)" }
        ),
    );
    line(
        "Hertz half-width a",
        format!(
            "{:.6} {l}  (a/R = {:.3e})",
            est.hertz_half_width, est.half_width_over_radius
        ),
    );
    line(
        "Hertz peak pressure p0",
        format!("{:.6} {f}/{l}^2", est.hertz_peak_pressure),
    );
    let from_mesh = if bodies.iter().any(|b| b.mesh.is_some()) {
        " (from the bem mesh)"
    } else {
        ""
    };
    line(
        "contact grid",
        format!(
            "{} {} elements on [{:.6}, {:.6}] {l}{from_mesh}; node spacing {:.4e} {l} ({:.4} a)",
            grid.n_elements(),
            grid.kind.name(),
            grid.edges[0],
            grid.edges[grid.n_elements()],
            grid.node_spacing(),
            grid.node_spacing() / est.hertz_half_width
        ),
    );
    if let Some(w) = est.carter_stick_width {
        line(
            "stick zone (Carter)",
            format!(
                "width {:.6} {l} = {:.4} a, at the leading edge (similar bodies; beta shifts it)",
                w,
                w / est.hertz_half_width
            ),
        );
    }
    // The half-space error of the scene: a layer's if a bem body is held fixed closer under
    // its contact than half its radius (a cover layer on a core), else the rollers'.
    let layer = [(&c.bodies.a, &bodies[0]), (&c.bodies.b, &bodies[1])]
        .into_iter()
        .filter_map(|(spec, body)| layer_thickness(spec, body))
        .fold(f64::INFINITY, f64::min);
    let error = if layer.is_finite() {
        // Under overlap control the half-plane estimate of a means nothing for a layer; the
        // thin-layer chord a² = 2Rδ0 (compressible) or 6Rδ0 (ν = 0.5) does (reference sheet §5).
        let a = match c.load.normal() {
            NormalSpec::Overlap(d) => {
                let incompressible = bodies.iter().any(|b| b.material.is_some_and(|m| m.poisson > 0.45));
                ((if incompressible { 6.0 } else { 2.0 }) * est.effective_radius * d).sqrt()
            }
            NormalSpec::Force(_) => est.hertz_half_width,
        };
        line(
            "layer thickness b",
            format!("{layer:.6} {l} (b/a = {:.4}, a = {a:.4} {l})", layer / a),
        );
        crate::advice::layer_error(layer / a)
    } else {
        crate::advice::roller_error(est.half_width_over_radius)
    };
    line("model advice", crate::advice::advise(&error, tolerance));
    line(
        "memory estimate",
        format!(
            "{} (peak; {} available)",
            crate::limits::human_bytes(memory.bytes()),
            crate::limits::available_memory().map_or("unknown".into(), crate::limits::human_bytes)
        ),
    );
    Ok(t)
}

/// Depth of a `bem` body's material under its contact when a fixed boundary lies closer below
/// it than half the body's radius (a cover layer on a rigid core): the distance from the
/// contact node nearest x = 0 to the nearest node of a `fixed` group [length].
fn layer_thickness(spec: &BodySpec, body: &PreparedBody) -> Option<f64> {
    let (BodySpec::Bem { boundaries, .. }, Some(lm)) = (spec, &body.mesh) else {
        return None;
    };
    let m = &lm.mesh;
    let centre = lm.contact_nodes().min_by(|p, q| p[0].abs().total_cmp(&q[0].abs()))?;
    let fixed: Vec<usize> = boundaries
        .iter()
        .filter(|(_, b)| matches!(b, BoundarySpec::Keyword(BoundaryKeyword::Fixed)))
        .filter_map(|(g, _)| m.group_index(g).ok())
        .collect();
    let depth = m
        .elements
        .iter()
        .filter(|e| fixed.contains(&e.group))
        .flat_map(|e| e.nodes.iter().map(|&n| m.nodes[n]))
        .map(|p| (p[0] - centre[0]).hypot(p[1] - centre[1]))
        .fold(f64::INFINITY, f64::min);
    (depth < 0.5 * body.radius).then_some(depth)
}
