//! Results on disk (DESIGN §5): summary.json, contact.csv, contact.svg, and the terminal table.
//!
//! Everything is written to a temporary sibling folder and renamed onto the output folder only
//! when complete, so a failed run never leaves a half-written result; an output folder that
//! holds anything rollbem did not write is refused ([`folder`]).

pub mod folder;
pub mod svg;
pub mod vtk;

use crate::app::{Estimates, Timings};
use crate::case::LoadedCase;
use crate::contact::friction_check::{check_friction_law, FrictionCheck, DEFAULT_THRESHOLD_FRACTION};
use crate::contact::solution::{ContactSolution, NodeState, SlipDirection, SlipRegime, Zone};
use crate::contact::ContactProblem;
use crate::contact::{IterationRecord, SolveReport};
use crate::error::Error;
use serde::Serialize;
use std::path::Path;
use std::time::Instant;

/// Contact extent in summary.json.
#[derive(Debug, Clone, Serialize)]
pub struct ContactExtent {
    /// Left end of the contact [length].
    pub x_min: f64,
    /// Right end [length].
    pub x_max: f64,
    /// Half the contact length [length].
    pub half_width: f64,
    /// Centre of the contact [length].
    pub centre: f64,
}

/// Grid description in summary.json.
#[derive(Debug, Clone, Serialize)]
pub struct GridSummary {
    /// Number of elements.
    pub elements: usize,
    /// Element interpolation.
    pub element: crate::grid::ElementKind,
    /// Number of contact nodes.
    pub nodes: usize,
    /// Left end [length].
    pub x_min: f64,
    /// Right end [length].
    pub x_max: f64,
    /// Node spacing [length].
    pub spacing: f64,
    /// Slip derivative scheme.
    pub slip_derivative: crate::contact::SlipDerivative,
}

/// summary.json (DESIGN §5).
#[derive(Debug, Clone, Serialize)]
pub struct Summary {
    /// Case title.
    pub title: String,
    /// Whether the solver converged.
    pub converged: bool,
    /// Newton iterations.
    pub iterations: usize,
    /// Final scaled residual.
    pub residual: f64,
    /// P [force/length].
    pub normal_force: f64,
    /// Q [force/length].
    pub tangential_force: f64,
    /// Q/(μP) (null when μ = 0).
    pub load_ratio: Option<f64>,
    /// δ0 [length] (half-space bodies: relative to the datum ℓ = 2R/e, see docs/theory.md).
    pub overlap: f64,
    /// ξ = (V_A − V_B)/V.
    pub creep: f64,
    /// Contact extent (null if nothing is in contact).
    pub contact: Option<ContactExtent>,
    /// Stick zones [[x0, x1], …].
    pub stick_zones: Vec<[f64; 2]>,
    /// Slip zones [[x0, x1], …].
    pub slip_zones: Vec<[f64; 2]>,
    /// Sign of the slip in each slip zone, in the order of `slip_zones`.
    pub slip_directions: Vec<SlipDirection>,
    /// All zones in increasing x, with node counts.
    pub zones: Vec<Zone>,
    /// Slip regime 1–4 of paper §5.2 (0: none of them, e.g. full stick).
    pub slip_regime: SlipRegime,
    /// Peak pressure [stress].
    pub max_pressure: f64,
    /// Stage timings [s].
    pub timings: Timings,
    /// Model of each body.
    pub models: Models,
    /// Hertz estimates and derived constants.
    pub estimates: Estimates,
    /// The contact grid.
    pub grid: GridSummary,
    /// Solver diagnostics (penalties, residual history).
    pub solver: SolverSummary,
    /// Where the boundary-integral (HBEM) slip contradicts the friction law, with the
    /// threshold used (null when no HBEM slip exists or μ = 0; see
    /// [`crate::contact::friction_check`]).
    pub hbem_check: Option<FrictionCheck>,
    /// Notices for the user (requested features not available, adjustments made).
    pub notices: Vec<String>,
    /// The interior grid of `output.interior` (null when not asked): body, model, point
    /// counts by status, and the maxima of the principal shear and von Mises stress.
    pub interior: Option<crate::interior::InteriorSummary>,
    /// Whether VTK files (contact.vtu, result.pvd) were requested.
    pub vtk: bool,
    /// The case as resolved after `--set` overrides.
    pub case: serde_json::Value,
}

/// Models of A and B.
#[derive(Debug, Clone, Serialize)]
pub struct Models {
    /// Model of A.
    #[serde(rename = "A")]
    pub a: String,
    /// Model of B.
    #[serde(rename = "B")]
    pub b: String,
}

/// Solver diagnostics.
#[derive(Debug, Clone, Serialize)]
pub struct SolverSummary {
    /// Solution method used.
    pub method: crate::contact::Method,
    /// Formulation used.
    pub formulation: crate::contact::Formulation,
    /// Normal penalty r_n [stress/length].
    pub penalty_normal: f64,
    /// Tangential penalty r_t [stress].
    pub penalty_tangential: f64,
    /// Traction scale of the convergence test [stress].
    pub traction_scale: f64,
    /// Residual, step length and system size per iteration.
    pub history: Vec<IterationRecord>,
    /// Restarts the default method needed (empty when its first attempt converged).
    pub fallbacks: Vec<String>,
}

/// Builds the summary of a run.
pub fn summary(
    case: &LoadedCase,
    est: &Estimates,
    pb: &ContactProblem,
    sol: &ContactSolution,
    report: &SolveReport,
    regime: SlipRegime,
    timings: Timings,
) -> Summary {
    let mu = case.case.contact.friction;
    let model = |s: &crate::case::BodySpec| match s {
        crate::case::BodySpec::HalfSpace { .. } => "half_space".to_string(),
        crate::case::BodySpec::Rigid { .. } => "rigid".to_string(),
        crate::case::BodySpec::Bem { .. } => "bem".to_string(),
    };
    Summary {
        title: case.case.title.clone(),
        converged: report.converged,
        iterations: report.iterations,
        residual: report.residual,
        normal_force: sol.normal_force,
        tangential_force: sol.tangential_force,
        load_ratio: (mu > 0.0 && sol.normal_force > 0.0).then(|| sol.tangential_force / (mu * sol.normal_force)),
        overlap: sol.overlap,
        creep: sol.creep,
        contact: sol.contact_extent().map(|[x0, x1]| ContactExtent {
            x_min: x0,
            x_max: x1,
            half_width: 0.5 * (x1 - x0),
            centre: 0.5 * (x0 + x1),
        }),
        stick_zones: sol.zones_of(NodeState::Stick),
        slip_zones: sol.zones_of(NodeState::Slip),
        slip_directions: sol.slip_directions(),
        zones: sol.zones.clone(),
        slip_regime: regime,
        max_pressure: sol.pressure.iter().fold(0.0, |a, &b| a.max(b)),
        timings,
        models: Models {
            a: model(&case.case.bodies.a),
            b: model(&case.case.bodies.b),
        },
        estimates: est.clone(),
        grid: GridSummary {
            elements: pb.grid.n_elements(),
            element: pb.grid.kind,
            nodes: pb.grid.n_nodes(),
            x_min: pb.grid.edges[0],
            x_max: pb.grid.edges[pb.grid.n_elements()],
            spacing: pb.grid.node_spacing(),
            slip_derivative: pb.slip_operator.scheme,
        },
        solver: SolverSummary {
            method: report.method,
            formulation: case.case.solver.formulation,
            penalty_normal: report.penalty_normal,
            penalty_tangential: report.penalty_tangential,
            traction_scale: report.traction_scale,
            history: report.history.clone(),
            fallbacks: report.fallbacks.clone(),
        },
        hbem_check: check_friction_law(sol, mu, DEFAULT_THRESHOLD_FRACTION),
        notices: Vec::new(),
        interior: None,
        vtk: case.case.output.vtk,
        case: case.resolved.clone(),
    }
}

/// Column names of contact.csv, in order (DESIGN §5 plus the surface displacements).
pub const CSV_COLUMNS: [&str; 11] = [
    "x",
    "pressure",
    "shear",
    "gap",
    "slip",
    "slip_hbem",
    "state",
    "u_n_A",
    "u_t_A",
    "u_n_B",
    "u_t_B",
];

/// Writes contact.csv. `slip_hbem` is left empty when no boundary-integral derivative exists
/// (and, defensively, for a non-finite value: no NaN is ever written).
/// Surface displacements: u_n positive into the body, u_t along +x of the contact frame.
pub fn write_csv(path: &Path, sol: &ContactSolution, pb: &ContactProblem) -> Result<(), Error> {
    let io = |e: csv::Error| Error::Output {
        path: path.to_path_buf(),
        message: e.to_string(),
    };
    let mut w = csv::Writer::from_path(path).map_err(io)?;
    w.write_record(CSV_COLUMNS).map_err(io)?;
    let disp = pb.surface_displacements(&sol.pressure, &sol.shear);
    for i in 0..sol.x.len() {
        let hbem = sol
            .slip_strain
            .as_ref()
            .filter(|s| s[i].is_finite())
            .map_or(String::new(), |s| fmt(s[i]));
        w.write_record([
            fmt(sol.x[i]),
            fmt(sol.pressure[i]),
            fmt(sol.shear[i]),
            fmt(sol.gap[i]),
            fmt(sol.slip[i]),
            hbem,
            sol.state[i].name().to_string(),
            fmt(disp.normal_a[i]),
            fmt(disp.tangential_a[i]),
            fmt(disp.normal_b[i]),
            fmt(disp.tangential_b[i]),
        ])
        .map_err(io)?;
    }
    w.flush().map_err(|e| Error::Output {
        path: path.to_path_buf(),
        message: e.to_string(),
    })
}

/// Writes interior_<body>.csv, one row per grid point (x fastest): `x, y, sxx, syy, szz, txy,
/// von_mises, max_shear, ux, uy, status` in the contact frame (σzz out of plane, tension
/// positive; ux, uy the displacement). `status` is `inside` where the body's model evaluated the
/// point, `outside` (not in the body) or `boundary` (within the boundary layer): those rows
/// carry zeros.
pub fn write_interior_csv(path: &Path, f: &crate::interior::InteriorField) -> Result<(), Error> {
    let io = |e: &dyn std::fmt::Display| Error::Output {
        path: path.to_path_buf(),
        message: e.to_string(),
    };
    let mut w = csv::Writer::from_path(path).map_err(|e| io(&e))?;
    w.write_record([
        "x",
        "y",
        "sxx",
        "syy",
        "szz",
        "txy",
        "von_mises",
        "max_shear",
        "ux",
        "uy",
        "status",
    ])
    .map_err(|e| io(&e))?;
    for (k, (p, s)) in f.points.iter().zip(&f.stress).enumerate() {
        let (vm, ms) = crate::interior::invariants(s);
        let u = f.displacement[k];
        let mut row: Vec<String> = [p[0], p[1], s[0], s[1], s[2], s[3], vm, ms, u[0], u[1]]
            .map(fmt)
            .to_vec();
        row.push(f.status[k].name().to_string());
        w.write_record(&row).map_err(|e| io(&e))?;
    }
    w.flush().map_err(|e| io(&e))
}

/// Full-precision, round-trippable number formatting.
fn fmt(v: f64) -> String {
    format!("{v:e}")
}

/// Writes all outputs of a run atomically into `dir` and fills in the total time.
/// A non-converged run writes summary.json only.
pub fn write_run(
    dir: &Path,
    summary: &mut Summary,
    sol: &ContactSolution,
    pb: &ContactProblem,
    boundary: &[Option<crate::body::BoundaryField>; 2],
    interior: Option<&crate::interior::InteriorField>,
    start: Instant,
) -> Result<(), Error> {
    write_atomically(dir, folder::Kind::Run, |tmp| {
        if summary.converged {
            write_csv(&tmp.join("contact.csv"), sol, pb)?;
            if let Some(f) = interior {
                write_interior_csv(&tmp.join(format!("interior_{}.csv", f.body)), f)?;
            }
            svg::write_contact_plot(&tmp.join("contact.svg"), sol, pb.friction, &summary.title)?;
            if summary.vtk {
                vtk::write_contact_line(&tmp.join("contact.vtu"), sol, pb)?;
                let mut entries = vec![vtk::CollectionEntry {
                    file: "contact.vtu".into(),
                    timestep: 0.0,
                    part: 0,
                    name: "contact".into(),
                }];
                for (side, field) in ["A", "B"].iter().zip(boundary) {
                    if let Some(f) = field {
                        let file = format!("boundary_{side}.vtu");
                        vtk::write_boundary(&tmp.join(&file), f)?;
                        entries.push(vtk::CollectionEntry {
                            file,
                            timestep: 0.0,
                            part: entries.len(),
                            name: format!("body {side}"),
                        });
                    }
                }
                if let Some(f) = interior {
                    let file = format!("interior_{}.vtu", f.body);
                    vtk::write_interior(&tmp.join(&file), f)?;
                    entries.push(vtk::CollectionEntry {
                        file,
                        timestep: 0.0,
                        part: entries.len(),
                        name: format!("interior {}", f.body),
                    });
                }
                vtk::write_collection(&tmp.join("result.pvd"), &entries)?;
            }
        }
        summary.timings.total_s = start.elapsed().as_secs_f64();
        let err = |path: &Path, e: &dyn std::fmt::Display| Error::Output {
            path: path.to_path_buf(),
            message: e.to_string(),
        };
        let json = serde_json::to_string_pretty(summary).map_err(|e| err(tmp, &e))?;
        std::fs::write(tmp.join("summary.json"), json).map_err(|e| err(tmp, &e))
    })
}

/// Writes a result of `kind` atomically into `dir` through a temporary sibling folder, replacing
/// an earlier rollbem result of the same kind and refusing a folder that holds anything else
/// (see [`folder`]: the manifest, the lock, the rules). On failure `dir` is left as it was.
pub fn write_atomically(
    dir: &Path,
    kind: folder::Kind,
    write: impl FnOnce(&Path) -> Result<(), Error>,
) -> Result<(), Error> {
    folder::write_atomically(dir, kind, write)
}

/// The terminal summary table of a run.
pub fn render_table(s: &Summary, output_dir: &Path) -> String {
    let mut t = String::new();
    let mut line = |k: &str, v: String| t.push_str(&format!("  {k:<22} {v}\n"));
    let status = if s.converged { "converged" } else { "NOT CONVERGED" };
    line("title", s.title.clone());
    line("models (A / B)", format!("{} / {}", s.models.a, s.models.b));
    line(
        "solver",
        format!("{status} in {} iterations, residual {:.2e}", s.iterations, s.residual),
    );
    line("normal force P", format!("{:.6}", s.normal_force));
    line(
        "tangential force Q",
        format!(
            "{:.6}{}",
            s.tangential_force,
            s.load_ratio.map_or(String::new(), |r| format!("  (Q/muP = {r:.4})"))
        ),
    );
    line("overlap delta0", format!("{:.6e}", s.overlap));
    line("creepage xi", format!("{:.6e}", s.creep));
    // Hertz comparisons only mean something when both bodies are half-spaces.
    let hertzian = s.models.a == "half_space" && s.models.b == "half_space";
    if let Some(c) = &s.contact {
        let hertz = if hertzian {
            format!(" (Hertz {:.5})", s.estimates.hertz_half_width)
        } else {
            String::new()
        };
        line(
            "contact",
            format!(
                "[{:.5}, {:.5}]  half-width {:.5}, centre {:+.5}{hertz}",
                c.x_min, c.x_max, c.half_width, c.centre
            ),
        );
    }
    let hertz = if hertzian {
        format!(" (Hertz p0 {:.6})", s.estimates.hertz_peak_pressure)
    } else {
        String::new()
    };
    line("max pressure", format!("{:.6}{hertz}", s.max_pressure));
    let zones = |z: &[[f64; 2]]| {
        z.iter()
            .map(|[a, b]| format!("[{a:.4}, {b:.4}]"))
            .collect::<Vec<_>>()
            .join(" ")
    };
    line("stick zones", zones(&s.stick_zones));
    line(
        "slip zones",
        format!(
            "{}  directions {:?}  regime {}",
            zones(&s.slip_zones),
            s.slip_directions.iter().map(|d| d.sign()).collect::<Vec<_>>(),
            s.slip_regime
        ),
    );
    if let Some(check) = s.hbem_check.as_ref().and_then(|c| c.summary_line()) {
        line("HBEM slip check", check);
    }
    line(
        "grid",
        format!(
            "{} {} elements, {} nodes, spacing {:.4e}",
            s.grid.elements,
            s.grid.element.name(),
            s.grid.nodes,
            s.grid.spacing
        ),
    );
    if let Some(i) = &s.interior {
        let peak = |p: &Option<crate::interior::Peak>| {
            p.map_or("-".to_string(), |p| {
                format!("{:.6} at ({:.4}, {:.4})", p.value, p.x, p.y)
            })
        };
        line(
            &format!("interior {} ({})", i.body, i.model),
            format!(
                "{} of {} points evaluated; max shear {}; max von Mises {}",
                i.inside,
                i.points,
                peak(&i.max_shear),
                peak(&i.max_von_mises)
            ),
        );
    }
    line(
        "time [s]",
        format!(
            "assembly {:.4}  condense {:.4}  solve {:.4}  interior {:.4}  total {:.4}",
            s.timings.assembly_s, s.timings.condense_s, s.timings.solve_s, s.timings.interior_s, s.timings.total_s
        ),
    );
    line("results", output_dir.display().to_string());
    t
}
