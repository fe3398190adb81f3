//! Measures the error of the half-space model on two families of scenes and prints the tables
//! that `rollbem check --tolerance` interpolates (src/advice.rs) and docs/choosing-a-model.md
//! shows.
//!
//! * Rollers: similar steel rollers R_A = R_B on rigid shafts (radius 0.1 R), μ = 0.1,
//!   Q/μP = 0.5, at a/R = 0.002 … 0.2 (R the effective radius): half-space against true
//!   geometry, both on the same 41-element contact grid.
//! * Internal contact: a steel roller R1 = 40 mm on a rigid shaft (5 mm) in the bore R2 = 50 mm
//!   of a steel ring with its rim (65 mm) fixed, μ = 0.1, Q/μP = 0.5, a/R1 = 0.005 … 0.2:
//!   half-space (R* from the signed radii) against the true geometry on the same 41-element grid.
//! * Layers: a rigid R = 100 mm cylinder on a layer of thickness b bonded to a rigid core
//!   (ν = 0.3, frictionless, P for a Hertz half-width of 1 mm on the half-space), b/a = 1 … 50:
//!   half-space against the BEM layer (a flat strip of half-width max(20b, 20a)).
//!
//! Errors are max over the nodes of |p_hs − p_true| / p0 and |q_hs − q_true| / (μp0) (p0 the
//! Hertz peak pressure), and the relative creepage difference.
//!
//! Run: `cargo run --release --example model_error_table` (about a minute). The `docs` test
//! compares the tables with docs/choosing-a-model.md and the constants of src/advice.rs.

pub mod common;

use common::Table;
use rollbem::app;
use rollbem::bem::BoundaryCondition;
use rollbem::case::LoadedCase;
use rollbem::mesh::build::layer_strip;
use rollbem::mesh::validate_and_orient;
use rollbem::post::ContactSolution;
use rollbem::scene::{BemSetup, LoadedMesh, Scene};
use rollbem::study::accuracy::{solve_model, SceneModel};
use std::sync::Arc;
use std::time::Instant;

fn load<S: AsRef<str>>(name: &str, set: &[S]) -> LoadedCase {
    app::load_case(&common::case_path(name), set).expect("case loads")
}

/// Max nodal |a − b| / scale (both on the same grid).
fn max_diff(a: &[f64], b: &[f64], scale: f64) -> f64 {
    a.iter().zip(b).fold(0.0_f64, |m, (x, y)| m.max((x - y).abs())) / scale
}

/// Piecewise-linear interpolation of (xs, v) at x, zero outside.
fn linear(xs: &[f64], v: &[f64], x: f64) -> f64 {
    let k = xs.partition_point(|&t| t < x);
    if k == 0 || k == xs.len() {
        return 0.0;
    }
    let t = (x - xs[k - 1]) / (xs[k] - xs[k - 1]);
    v[k - 1] + t * (v[k] - v[k - 1])
}

/// Two significant figures, in decimals from 0.1 on (0.53, 9.3e-2).
fn two_figures(v: f64) -> String {
    if v >= 0.1 {
        format!("{v:.2}")
    } else {
        format!("{v:.1e}")
    }
}

/// One a/R of the roller family: the half-space model's errors and both models' times.
#[derive(Debug, Clone, Copy)]
pub struct RollerRow {
    /// a/R.
    pub a_over_r: f64,
    /// max |Δp| / p0.
    pub pressure: f64,
    /// max |Δq| / (μp0).
    pub shear: f64,
    /// Relative creepage difference, half-space against true geometry.
    pub creep: f64,
    /// Wall time of the half-space run [s].
    pub half_space_s: f64,
    /// Wall time of the true-geometry run [s].
    pub true_geometry_s: f64,
}

/// Similar steel rollers on shafts, a/R = 0.002 … 0.2: half-space against true geometry.
pub fn rollers() -> Vec<RollerRow> {
    let (e, nu, r_each) = (210_000.0_f64, 0.3_f64, 100.0_f64);
    let e_star = e / (2.0 * (1.0 - nu * nu));
    let r = r_each / 2.0;
    let mut rows = Vec::new();
    for a_over_r in [0.002, 0.005, 0.01, 0.02, 0.05, 0.1, 0.2] {
        let a = a_over_r * r;
        let p_total = std::f64::consts::PI * a * a * e_star / (4.0 * r);
        let c = load(
            "carter_051",
            &[
                format!("load.normal.force={p_total}"),
                "load.tangential.ratio=0.5".into(),
                "contact.grid.elements=41".into(),
            ],
        );
        let hs = solve_model(&c, SceneModel::HalfSpace, 41, 0.1).expect("half-space");
        let tg = solve_model(&c, SceneModel::TrueGeometry, 41, 0.1).expect("true geometry");
        assert!(hs.solution_converged && tg.solution_converged, "a/R = {a_over_r}");
        let p0 = 2.0 * p_total / (std::f64::consts::PI * a);
        rows.push(RollerRow {
            a_over_r,
            pressure: max_diff(&hs.solution.pressure, &tg.solution.pressure, p0),
            shear: max_diff(&hs.solution.shear, &tg.solution.shear, 0.1 * p0),
            creep: hs.solution.creep / tg.solution.creep - 1.0,
            half_space_s: hs.build_s + hs.solve_s,
            true_geometry_s: tg.build_s + tg.solve_s,
        });
    }
    rows
}

/// The roller table of docs/choosing-a-model.md.
pub fn roller_table(rows: &[RollerRow]) -> Table {
    let mut t = Table::new(&["a/R", "pressure (p0)", "shear (μp0)", "creepage"]);
    for r in rows {
        let creep = format!("{:+.1e}", r.creep).replacen('-', "−", 1).replacen('+', "", 1);
        t.push(vec![
            r.a_over_r.to_string(),
            format!("{:.1e}", r.pressure),
            format!("{:.1e}", r.shear),
            creep,
        ]);
    }
    t
}

/// One a/R1 of the internal-contact family.
#[derive(Debug, Clone, Copy)]
pub struct InternalRow {
    /// a/R1, R1 the roller's radius.
    pub a_over_r: f64,
    /// max |Δp| / p0.
    pub pressure: f64,
    /// max |Δq| / (μp0).
    pub shear: f64,
    /// Relative creepage difference, half-space against true geometry.
    pub creep: f64,
}

/// A steel roller R1 = 40 mm on a rigid shaft of 5 mm in the bore R2 = 50 mm of a steel ring
/// whose rim (65 mm) is fixed, R* = 200 mm, μ = 0.1, Q/μP = 0.5, a/R1 = 0.005 … 0.2 (a the
/// Hertz half-width): half-space against true geometry on the same 41-element grid.
pub fn internal() -> Vec<InternalRow> {
    let (e, nu, r1, r2) = (210_000.0_f64, 0.3_f64, 40.0_f64, 50.0_f64);
    let e_star = e / (2.0 * (1.0 - nu * nu));
    let r_star = 1.0 / (1.0 / r1 - 1.0 / r2);
    let mut rows = Vec::new();
    for a_over_r in [0.005, 0.01, 0.02, 0.05, 0.1, 0.2] {
        let a = a_over_r * r1;
        let p_total = std::f64::consts::PI * a * a * e_star / (4.0 * r_star);
        let c = load(
            "carter_051",
            &[
                format!("bodies.A.radius={r1}"),
                format!("bodies.B.radius=-{r2}"),
                format!("load.normal.force={p_total}"),
                "load.tangential.ratio=0.5".into(),
                "contact.grid.elements=41".into(),
            ],
        );
        let hs = solve_model(&c, SceneModel::HalfSpace, 41, 5.0 / r1).expect("half-space");
        let tg = solve_model(&c, SceneModel::TrueGeometry, 41, 5.0 / r1).expect("true geometry");
        assert!(hs.solution_converged && tg.solution_converged, "a/R1 = {a_over_r}");
        let p0 = 2.0 * p_total / (std::f64::consts::PI * a);
        rows.push(InternalRow {
            a_over_r,
            pressure: max_diff(&hs.solution.pressure, &tg.solution.pressure, p0),
            shear: max_diff(&hs.solution.shear, &tg.solution.shear, 0.1 * p0),
            creep: hs.solution.creep / tg.solution.creep - 1.0,
        });
    }
    rows
}

/// The internal-contact table of docs/choosing-a-model.md.
pub fn internal_table(rows: &[InternalRow]) -> Table {
    let mut t = Table::new(&["a/R1", "pressure (p0)", "shear (μp0)", "creepage"]);
    for r in rows {
        let creep = format!("{:+.1e}", r.creep).replacen('-', "−", 1).replacen('+', "", 1);
        t.push(vec![
            r.a_over_r.to_string(),
            format!("{:.1e}", r.pressure),
            format!("{:.1e}", r.shear),
            creep,
        ]);
    }
    t
}

/// The layer scene with body B either the BEM layer of thickness b or a half-space.
fn layer_solution(b: Option<f64>, p_total: f64, a: f64) -> ContactSolution {
    let mut set = vec![
        "materials.rubber.nu=0.3".to_string(),
        "load.normal.overlap=null".into(),
        format!("load.normal.force={p_total}"),
        "contact.friction=0".into(),
        "load.tangential.ratio=null".into(),
        "load.tangential.creep=0".into(),
    ];
    if b.is_none() {
        set.push("bodies.B={model: half_space, material: rubber, radius: 1.0e9}".into());
        set.push("contact.grid.elements=41".into());
        set.push(format!("contact.grid.half_length={}", 1.3 * a));
    }
    let c = load("tyre_b01_incompressible", &set);
    let mut scene = Scene::from_case(&c).expect("bodies");
    if let Some(b) = b {
        let half_width = (20.0 * b).max(20.0 * a);
        let mut mesh = layer_strip(b, half_width, 1.3 * a, 41, (b / 2.0).max(a / 2.0));
        let notices = validate_and_orient(&mut mesh).expect("layer mesh");
        let mut bodies = scene.bodies.clone();
        let layer = &scene.bodies[1];
        let material = layer
            .hertz_material()
            .expect("body B of the tyre case is an elastic layer");
        // The case's boundaries, the other groups in name order and the contact group last.
        let conditions = [
            ("bonded", BoundaryCondition::Fixed),
            ("ends", BoundaryCondition::Fixed),
            ("free", BoundaryCondition::Free),
            ("contact", BoundaryCondition::Contact),
        ];
        let mesh = LoadedMesh::new("<procedural layer>", mesh, notices, "contact").expect("contact group");
        let conditions = conditions.iter().map(|(g, c)| (g.to_string(), c.clone())).collect();
        bodies[1] = Arc::new(BemSetup {
            radius: layer.radius(),
            ..BemSetup::on_start_mesh(mesh, material, "contact".into(), conditions, None, None)
        });
        scene = Scene::new(c, bodies);
    }
    let s = app::solve_scene(scene, Instant::now()).expect("layer solve");
    assert!(s.report.converged, "layer b = {b:?}");
    s.solution
}

/// One b/a of the layer family.
#[derive(Debug, Clone, Copy)]
pub struct LayerRow {
    /// b/a.
    pub b_over_a: f64,
    /// max |Δp| / p0.
    pub pressure: f64,
    /// Contact half-width of the layer over that of the half-space.
    pub half_width_ratio: f64,
}

/// Layers of thickness b bonded to a rigid core, b/a = 1 … 50, against the half-space.
pub fn layers() -> Vec<LayerRow> {
    let (g, nu, r, a) = (1.0_f64, 0.3_f64, 100.0_f64, 1.0_f64);
    let e_star = 2.0 * g / (1.0 - nu);
    let p_total = std::f64::consts::PI * a * a * e_star / (4.0 * r);
    let p0 = 2.0 * p_total / (std::f64::consts::PI * a);
    let hs = layer_solution(None, p_total, a);
    let w = |s: &ContactSolution| {
        let [x0, x1] = s.contact_extent().expect("contact");
        0.5 * (x1 - x0)
    };
    [1.0, 2.0, 5.0, 10.0, 20.0, 50.0]
        .into_iter()
        .map(|b_over_a| {
            let layer = layer_solution(Some(b_over_a * a), p_total, a);
            let pressure = layer
                .x
                .iter()
                .zip(&layer.pressure)
                .map(|(&x, &p)| (p - linear(&hs.x, &hs.pressure, x)).abs())
                .fold(0.0_f64, f64::max)
                / p0;
            LayerRow {
                b_over_a,
                pressure,
                half_width_ratio: w(&layer) / w(&hs),
            }
        })
        .collect()
}

/// The layer table of docs/choosing-a-model.md.
pub fn layer_table(rows: &[LayerRow]) -> Table {
    let mut t = Table::new(&["b/a", "pressure (p0)", "contact half-width, layer / half-space"]);
    for r in rows {
        t.push(vec![
            r.b_over_a.to_string(),
            two_figures(r.pressure),
            format!("{:.3}", r.half_width_ratio),
        ]);
    }
    t
}

fn main() {
    let rollers = rollers();
    println!("## Rollers on shafts (rho = 0.1), similar steel, mu = 0.1, Q/muP = 0.5, 41 elements\n");
    println!("{}", roller_table(&rollers).markdown());
    let mut times = Table::new(&["a/R", "half-space time [s]", "true geometry time [s]"]);
    for r in &rollers {
        times.push(vec![
            r.a_over_r.to_string(),
            format!("{:.4}", r.half_space_s),
            format!("{:.4}", r.true_geometry_s),
        ]);
    }
    println!("{}", times.markdown());
    let constants: Vec<String> = rollers
        .iter()
        .map(|r| format!("    ({:e}, {:.3e}, {:.3e}),", r.a_over_r, r.pressure, r.shear))
        .collect();
    println!(
        "`ROLLER_ERROR` of src/advice.rs:\n\n```rust\n{}\n```\n",
        constants.join("\n")
    );

    let internal = internal();
    println!("## Internal contact: roller R1 = 40 (shaft 5) in a ring bore R2 = 50 (rim 65 fixed), mu = 0.1, Q/muP = 0.5, 41 elements\n");
    println!("{}", internal_table(&internal).markdown());
    let constants: Vec<String> = internal
        .iter()
        .map(|r| format!("    ({:e}, {:.3e}, {:.3e}),", r.a_over_r, r.pressure, r.shear))
        .collect();
    println!(
        "`INTERNAL_ERROR` of src/advice.rs:\n\n```rust\n{}\n```\n",
        constants.join("\n")
    );

    let layers = layers();
    println!("## Layers bonded to a rigid core (nu = 0.3), rigid R = 100 mm indenter, frictionless\n");
    println!("{}", layer_table(&layers).markdown());
    let constants: Vec<String> = layers
        .iter()
        .map(|r| format!("    ({:e}, {:.3e}),", r.b_over_a, r.pressure))
        .collect();
    println!(
        "`LAYER_ERROR` of src/advice.rs:\n\n```rust\n{}\n```",
        constants.join("\n")
    );
}
