//! `rollbem study stability CASE`: a convergence map of every solution method.
//!
//! The full Cartesian product of friction, load ratio, Dundurs β, penalty, grid and element type
//! is too large, so the map is a set of two-dimensional **slices** through the base case, each
//! solved by every **method variant** ([`method_variants`]):
//!
//! | slice | x | y | fixed |
//! |---|---|---|---|
//! | `friction_load_betaB` (one per β) | Q/μP | μ | Dundurs β = B (A's material, [`crate::material::material_for_beta`]); grid ±4a, 65 elements |
//! | `penalty_load` | Q/μP | penalty scale c | β = 0.288; grid ±4a, 65 elements |
//! | `grid_element` | element type | elements | the base case |
//! | `ripple_friction_element` | element type | μ | β = 0.288, Q/μP = 0.5; grid ±4a, 65 elements |
//!
//! Every other value is the base case's (with `--set` applied). A cell whose load ratio has
//! |Q/μP| ≥ 1 is outside the problem's domain (no steady rolling exists: the contact slides as a
//! whole) and is marked `out_of_domain`, not solved and not counted as a failure. Each solved
//! cell records the common convergence measure (converged, iterations, residual, solve time)
//! and, when converged, the traction ripple ([`crate::post::traction_ripple`],
//! relative to μp0).
//!
//! Outputs (written to a temporary folder, then renamed): `stability.csv` (one row per cell
//! and method), `summary.txt` (the table printed at the end) and `img/`: one SVG heat map per
//! slice and method (`SLICE__METHOD.svg`: iterations per cell, failures in red, out-of-domain
//! cells grey), one overview per slice with every method (`SLICE.svg`), and ripple maps of the
//! element slices (`SLICE__METHOD__ripple.svg`).

mod files;

use super::run_parallel;
use crate::app;
use crate::case;
use crate::contact::Formulation;
use crate::contact::Method;
use crate::error::Error;
use crate::material::material_for_beta;
use crate::output::charts::heatmap;
use crate::output::folder::{Access, Claim, Kind};
use crate::output::write_atomically;
use crate::post::traction_ripple;
pub use files::{render_summary, CSV_COLUMNS};
use serde::Serialize;
use std::path::{Path, PathBuf};
use std::time::Instant;

/// Size of the map.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Preset {
    /// The full ladder of docs/stability.md (a few minutes on 2 cores).
    Default,
    /// A small ladder for CI (well under a minute).
    Quick,
}

/// A method with its formulation and iteration budget, as compared in the study.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct MethodVariant {
    /// Label in files and tables.
    pub label: &'static str,
    /// The method.
    pub method: Method,
    /// The formulation (Newton family).
    pub formulation: Formulation,
    /// Iteration budget in the method's own unit.
    pub max_iterations: usize,
}

/// The method variants of the study, the default method (`newton`, Φ) first. Budgets: 100
/// Newton steps, 100 NORM/TANG alternations (each with up to 2 × 50 Newton steps), 20 000
/// Gauss–Seidel sweeps (each O(m²), like a matrix–vector product).
pub fn method_variants() -> Vec<MethodVariant> {
    let v = |label, method, formulation, max_iterations| MethodVariant {
        label,
        method,
        formulation,
        max_iterations,
    };
    vec![
        v("newton", Method::Newton, Formulation::Phi, 100),
        v("newton_psi", Method::Newton, Formulation::Psi, 100),
        v("newton_plain", Method::NewtonPlain, Formulation::Phi, 100),
        v("norm_tang", Method::NormTang, Formulation::Phi, 100),
        v("gauss_seidel", Method::GaussSeidel, Formulation::Phi, 20_000),
    ]
}

/// What an axis of a slice varies.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum AxisKey {
    /// Friction coefficient μ (`contact.friction`).
    Friction,
    /// Load ratio Q/(μP) (`load.tangential.ratio`).
    LoadRatio,
    /// Penalty scale c (`solver.penalty`).
    PenaltyScale,
    /// Number of contact elements (`contact.grid.elements`).
    Elements,
    /// Contact element type (`contact.grid.element`).
    ElementKind,
    /// Grid half-length in Hertz half-widths (`contact.grid.extent`).
    Extent,
}

impl AxisKey {
    /// Short label for files and plots.
    pub fn label(self) -> &'static str {
        match self {
            AxisKey::Friction => "friction mu",
            AxisKey::LoadRatio => "Q/(mu P)",
            AxisKey::PenaltyScale => "penalty scale c",
            AxisKey::Elements => "contact elements",
            AxisKey::ElementKind => "element type",
            AxisKey::Extent => "grid extent / a",
        }
    }

    /// The case override that sets this key to `value`.
    pub fn set(self, value: &str) -> String {
        match self {
            AxisKey::Friction => format!("contact.friction={value}"),
            // Replace the whole mapping: a base case controlling Q or ξ becomes ratio-controlled.
            AxisKey::LoadRatio => format!("load.tangential={{ratio: {value}}}"),
            AxisKey::PenaltyScale => format!("solver.penalty={value}"),
            AxisKey::Elements => format!("contact.grid.elements={value}"),
            AxisKey::ElementKind => format!("contact.grid.element={value}"),
            AxisKey::Extent => format!("contact.grid.extent={value}"),
        }
    }
}

/// One axis: a key and its values (as written in a case).
#[derive(Debug, Clone, PartialEq)]
pub struct Axis {
    /// What varies.
    pub key: AxisKey,
    /// The values.
    pub values: Vec<String>,
}

impl Axis {
    /// The axis as a heat map draws it.
    pub fn drawn(&self) -> heatmap::Axis<'_> {
        heatmap::Axis {
            label: self.key.label(),
            values: &self.values,
        }
    }
}

fn axis(key: AxisKey, values: &[&str]) -> Axis {
    Axis {
        key,
        values: values.iter().map(|v| v.to_string()).collect(),
    }
}

/// A two-dimensional slice of the map.
#[derive(Debug, Clone, PartialEq)]
pub struct Slice {
    /// File-name stem.
    pub name: String,
    /// Plot title.
    pub title: String,
    /// Horizontal axis.
    pub x: Axis,
    /// Vertical axis.
    pub y: Axis,
    /// Dundurs β set through A's material, if any.
    pub beta: Option<f64>,
    /// Other keys fixed for the slice.
    pub fixed: Vec<(AxisKey, String)>,
    /// Whether to draw ripple maps of this slice.
    pub ripple_maps: bool,
}

/// A grid of ±4 Hertz half-widths at the node spacing of the paper's 21 elements over ±1.3a:
/// with large μ and β the shear shifts and widens the contact (at μ = 10, β = 0.45,
/// Q/μP = ±0.99 it spans about [−3.6a, 0.3a]), which must stay inside the grid.
fn wide_grid() -> Vec<(AxisKey, String)> {
    vec![(AxisKey::Extent, "4".into()), (AxisKey::Elements, "65".into())]
}

/// The slices of a preset (module docs).
pub fn ladder(preset: Preset) -> Vec<Slice> {
    let quick = preset == Preset::Quick;
    let ratios: &[&str] = if quick {
        &["-1", "-0.99", "-0.5", "0", "0.5", "0.99", "1"]
    } else {
        &[
            "-1", "-0.99", "-0.9", "-0.75", "-0.5", "-0.25", "0", "0.25", "0.5", "0.75", "0.9", "0.99", "1",
        ]
    };
    let frictions: &[&str] = if quick {
        &["0.1", "1", "10"]
    } else {
        &["0.05", "0.1", "0.2", "0.5", "1", "2", "5", "10"]
    };
    let betas: &[f64] = if quick {
        &[0.0, 0.288]
    } else {
        &[0.0, 0.144, 0.288, 0.45]
    };
    let kinds = ["constant", "continuous_quadratic", "discontinuous_quadratic"];
    let mut slices: Vec<Slice> = betas
        .iter()
        .map(|&beta| Slice {
            name: format!("friction_load_beta{}", format!("{beta}").replace('.', "")),
            title: format!("friction x load, Dundurs beta = {beta} (grid +-4a, 65 elements)"),
            x: axis(AxisKey::LoadRatio, ratios),
            y: axis(AxisKey::Friction, frictions),
            beta: Some(beta),
            fixed: wide_grid(),
            ripple_maps: false,
        })
        .collect();
    let (penalty_ratios, penalties): (&[&str], &[&str]) = if quick {
        (&["-0.5", "0.5", "0.99"], &["0.01", "1", "100"])
    } else {
        (ratios, &["0.001", "0.01", "0.1", "1", "10", "100", "1000"])
    };
    slices.push(Slice {
        name: "penalty_load".into(),
        title: "penalty scale x load, beta = 0.288".into(),
        x: axis(AxisKey::LoadRatio, penalty_ratios),
        y: axis(AxisKey::PenaltyScale, penalties),
        beta: Some(0.288),
        fixed: wide_grid(),
        ripple_maps: false,
    });
    let elements: &[&str] = if quick {
        &["11", "21"]
    } else {
        &["11", "21", "41", "81", "161"]
    };
    slices.push(Slice {
        name: "grid_element".into(),
        title: "grid x element type (base case)".into(),
        x: axis(AxisKey::ElementKind, &kinds),
        y: axis(AxisKey::Elements, elements),
        beta: None,
        fixed: Vec::new(),
        ripple_maps: true,
    });
    let ripple_frictions: &[&str] = if quick {
        &["0.1", "1", "10"]
    } else {
        &["0.05", "0.1", "0.2", "0.4", "0.8", "1.6", "3.2", "10"]
    };
    // The wide grid: at μ = 10 with β = 0.288 the contact leaves a ±1.3a grid.
    let mut ripple_fixed = vec![(AxisKey::LoadRatio, "0.5".to_string())];
    ripple_fixed.extend(wide_grid());
    slices.push(Slice {
        name: "ripple_friction_element".into(),
        title: "friction x element type, beta = 0.288, Q/muP = 0.5 (grid +-4a, 65 elements)".into(),
        x: axis(AxisKey::ElementKind, &kinds),
        y: axis(AxisKey::Friction, ripple_frictions),
        beta: Some(0.288),
        fixed: ripple_fixed,
        ripple_maps: true,
    });
    slices
}

/// How a cell ended.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum Status {
    /// The common measure reached the tolerance.
    Converged,
    /// The method stopped (budget, singular matrix, divergence) above the tolerance.
    NotConverged,
    /// |Q/μP| ≥ 1: no steady rolling solution exists; not solved.
    OutOfDomain,
    /// The case was rejected or the solution left the grid.
    Error,
}

impl Status {
    /// How a heat map draws the cell.
    pub fn drawn(self) -> heatmap::Status {
        match self {
            Status::Converged => heatmap::Status::Converged,
            Status::NotConverged => heatmap::Status::NotConverged,
            Status::OutOfDomain => heatmap::Status::OutOfDomain,
            Status::Error => heatmap::Status::Error,
        }
    }

    /// Name in the CSV.
    pub fn name(self) -> &'static str {
        match self {
            Status::Converged => "converged",
            Status::NotConverged => "not_converged",
            Status::OutOfDomain => "out_of_domain",
            Status::Error => "error",
        }
    }
}

/// One solved (or marked) cell.
#[derive(Debug, Clone)]
pub struct CellResult {
    /// Slice index into [`StabilityReport::slices`].
    pub slice: usize,
    /// Method index into [`StabilityReport::methods`].
    pub method: usize,
    /// Index of the x value.
    pub ix: usize,
    /// Index of the y value.
    pub iy: usize,
    /// Outcome.
    pub status: Status,
    /// The method's iterations (its own unit).
    pub iterations: usize,
    /// Inner iterations (NORM/TANG Newton steps; else = iterations).
    pub inner_iterations: usize,
    /// Final common scaled residual.
    pub residual: f64,
    /// Solve wall time [s].
    pub solve_s: f64,
    /// Traction ripple / (μ p0), converged cells only.
    pub ripple: Option<f64>,
    /// Creepage ξ of a converged cell.
    pub creep: Option<f64>,
    /// Slip regime 1–4 of a converged cell.
    pub regime: Option<u8>,
    /// Error message of an `error` cell.
    pub message: String,
    /// Restarts the default method needed (see [`crate::contact::SolveReport::fallbacks`]).
    pub fallbacks: String,
}

/// What the study did.
#[derive(Debug, Clone)]
pub struct StabilityReport {
    /// Output folder.
    pub dir: PathBuf,
    /// The slices.
    pub slices: Vec<Slice>,
    /// The method variants.
    pub methods: Vec<MethodVariant>,
    /// Every cell of every slice and method.
    pub cells: Vec<CellResult>,
    /// Wall time of the whole study [s].
    pub wall_s: f64,
}

impl StabilityReport {
    /// In-domain cells where the default method (the first variant) did not converge.
    pub fn default_failures(&self) -> Vec<&CellResult> {
        self.cells
            .iter()
            .filter(|c| c.method == 0 && matches!(c.status, Status::NotConverged | Status::Error))
            .collect()
    }

    /// Value label of a cell's axes: (x, y).
    pub fn coordinates(&self, c: &CellResult) -> (&str, &str) {
        let s = &self.slices[c.slice];
        (&s.x.values[c.ix], &s.y.values[c.iy])
    }
}

/// One cell to solve.
struct Job {
    slice: usize,
    method: usize,
    ix: usize,
    iy: usize,
    overrides: Vec<String>,
    out_of_domain: bool,
}

/// The overrides giving A the material of Dundurs β against the base case's B.
fn beta_overrides(case_path: &Path, base_set: &[String], beta: f64) -> Result<Vec<String>, Error> {
    let loaded = case::load(case_path, base_set)?;
    let c = &loaded.case;
    let material_b = match c.bodies.b.material_name() {
        Some(material) => loaded.material(material),
        None => {
            return Err(Error::Study {
                message: format!(
                    "{}: the stability study sets Dundurs beta through body A's material against body B's; \
                     body B is rigid, so beta cannot be varied. Use a case with an elastic body B.",
                    case_path.display()
                ),
            })
        }
    };
    if c.bodies.a.material_name().is_none() {
        return Err(Error::Study {
            message: format!(
                "{}: the stability study sets Dundurs beta through body A's material; body A is rigid. \
                 Use a case with an elastic body A.",
                case_path.display()
            ),
        });
    }
    let a = material_for_beta(&material_b, beta).ok_or_else(|| Error::Study {
        message: format!(
            "Dundurs beta = {beta} cannot be reached against body B's material (nu = {}): see material_for_beta",
            material_b.poisson
        ),
    })?;
    Ok(vec![
        format!("materials.study_beta_A={{E: {:e}, nu: {:e}}}", a.young, a.poisson),
        "bodies.A.material=study_beta_A".into(),
    ])
}

fn ratio_out_of_domain(key: AxisKey, value: &str) -> bool {
    key == AxisKey::LoadRatio && value.parse::<f64>().is_ok_and(|r| r.abs() >= 1.0)
}

fn jobs(case_path: &Path, base_set: &[String], slices: &[Slice], methods: &[MethodVariant]) -> Result<Vec<Job>, Error> {
    let mut out = Vec::new();
    for (si, s) in slices.iter().enumerate() {
        let beta = match s.beta {
            Some(b) => beta_overrides(case_path, base_set, b)?,
            None => Vec::new(),
        };
        for (mi, m) in methods.iter().enumerate() {
            for (iy, y) in s.y.values.iter().enumerate() {
                for (ix, x) in s.x.values.iter().enumerate() {
                    let mut o = beta.clone();
                    o.extend(s.fixed.iter().map(|(k, v)| k.set(v)));
                    o.push(format!("solver.method={}", m.method.name()));
                    o.push(format!(
                        "solver.formulation={}",
                        match m.formulation {
                            Formulation::Phi => "phi",
                            Formulation::Psi => "psi",
                        }
                    ));
                    o.push(format!("solver.max_iterations={}", m.max_iterations));
                    // The map measures the solver: no post-processing inside the bodies.
                    o.push("output.vtk=false".into());
                    o.push("output.interior=null".into());
                    o.push("output.strength=null".into());
                    o.push(s.x.key.set(x));
                    o.push(s.y.key.set(y));
                    let out_of_domain = ratio_out_of_domain(s.x.key, x)
                        || ratio_out_of_domain(s.y.key, y)
                        || s.fixed.iter().any(|(k, v)| ratio_out_of_domain(*k, v));
                    out.push(Job {
                        slice: si,
                        method: mi,
                        ix,
                        iy,
                        overrides: o,
                        out_of_domain,
                    });
                }
            }
        }
    }
    Ok(out)
}

fn solve_cell(case_path: &Path, base_set: &[String], job: &Job) -> CellResult {
    let mut cell = CellResult {
        slice: job.slice,
        method: job.method,
        ix: job.ix,
        iy: job.iy,
        status: Status::OutOfDomain,
        iterations: 0,
        inner_iterations: 0,
        residual: 0.0,
        solve_s: 0.0,
        ripple: None,
        creep: None,
        regime: None,
        message: String::new(),
        fallbacks: String::new(),
    };
    if job.out_of_domain {
        return cell;
    }
    let overrides: Vec<&String> = base_set.iter().chain(&job.overrides).collect();
    match app::solve_case(case_path, &overrides) {
        Ok(s) => {
            let r = &s.report;
            cell.iterations = r.iterations;
            cell.inner_iterations = r.inner_iterations;
            cell.residual = r.residual;
            cell.solve_s = r.wall_time_s;
            cell.fallbacks = r.fallbacks.join("; ");
            cell.status = if r.converged {
                Status::Converged
            } else {
                Status::NotConverged
            };
            if r.converged {
                let mu_p0 = s.scene.friction() * s.scene.estimates.hertz_peak_pressure;
                cell.ripple = (mu_p0 > 0.0).then(|| traction_ripple(&s.solution) / mu_p0);
                cell.creep = Some(s.solution.creep);
                cell.regime = Some(s.regime.number());
            }
        }
        Err(e) => {
            cell.status = Status::Error;
            cell.message = e.to_string().replace('\n', " ");
        }
    }
    cell
}

/// Runs the stability study of `case_path` (with `base_set` overrides) into `out`.
pub fn run(case_path: &Path, base_set: &[String], preset: Preset, out: &Path) -> Result<StabilityReport, Error> {
    let start = Instant::now();
    case::load(case_path, base_set)?.steady_only("`rollbem study stability`")?;
    // Lock and check the output folder before the study runs.
    let _claim = Claim::acquire(out, Kind::StudyStability, Access::Exclusive)?;
    let slices = ladder(preset);
    let methods = method_variants();
    let jobs = jobs(case_path, base_set, &slices, &methods)?;
    let cells = run_parallel(&jobs, "cells", true, |job| solve_cell(case_path, base_set, job));
    let mut report = StabilityReport {
        dir: out.to_path_buf(),
        slices,
        methods,
        cells,
        wall_s: 0.0,
    };
    report.wall_s = start.elapsed().as_secs_f64();
    write_atomically(out, Kind::StudyStability, |tmp| files::write_outputs(tmp, &report))?;
    Ok(report)
}
