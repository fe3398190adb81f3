//! Measures the error of the half-space model on two families of scenes and prints the tables
//! that `rollbem check --tolerance` interpolates (src/advice.rs) and docs/choosing-a-model.md
//! shows.
//!
//! * Rollers: similar steel rollers R_A = R_B on rigid shafts (radius 0.1 R), μ = 0.1,
//!   Q/μP = 0.5, at a/R = 0.002 … 0.2 (R the effective radius): half-space against true
//!   geometry, both on the same 41-element contact grid.
//! * Layers: a rigid R = 100 mm cylinder on a layer of thickness b bonded to a rigid core
//!   (ν = 0.3, frictionless, P for a Hertz half-width of 1 mm on the half-space), b/a = 1 … 50:
//!   half-space against the BEM layer (a flat strip of half-width max(20b, 20a)).
//!
//! Errors are max over the nodes of |p_hs − p_true| / p0 and |q_hs − q_true| / (μp0) (p0 the
//! Hertz peak pressure), and the relative creepage difference.
//!
//! Run: `cargo run --release --example model_error_table` (about a minute).

use rollbem::app::{self, LoadedMesh};
use rollbem::case::{self, LoadedCase};
use rollbem::contact::solution::ContactSolution;
use rollbem::mesh::build::layer_strip;
use rollbem::mesh::validate_and_orient;
use rollbem::study::accuracy::{solve_scene, SceneModel};
use std::path::PathBuf;
use std::time::Instant;

fn load(name: &str, set: &[String]) -> LoadedCase {
    let path = PathBuf::from(env!("CARGO_MANIFEST_DIR"))
        .join("cases")
        .join(format!("{name}.yaml"));
    case::load(&path, set).expect("case loads")
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

fn rollers() {
    println!("## Rollers on shafts (rho = 0.1), similar steel, mu = 0.1, Q/muP = 0.5, 41 elements\n");
    println!(
        "| a/R | p error (p0) | q error (mu p0) | creep difference | half-space time [s] | true geometry time [s] |"
    );
    println!("|---|---|---|---|---|---|");
    let (e, nu, r_each) = (210_000.0_f64, 0.3_f64, 100.0_f64);
    let e_star = e / (2.0 * (1.0 - nu * nu));
    let r = r_each / 2.0;
    let mut rust = Vec::new();
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
        let hs = solve_scene(&c, SceneModel::HalfSpace, 41, 0.1).expect("half-space");
        let tg = solve_scene(&c, SceneModel::TrueGeometry, 41, 0.1).expect("true geometry");
        assert!(hs.solution_converged && tg.solution_converged, "a/R = {a_over_r}");
        let p0 = 2.0 * p_total / (std::f64::consts::PI * a);
        let ep = max_diff(&hs.solution.pressure, &tg.solution.pressure, p0);
        let eq = max_diff(&hs.solution.shear, &tg.solution.shear, 0.1 * p0);
        let ec = hs.solution.creep / tg.solution.creep - 1.0;
        println!(
            "| {a_over_r} | {ep:.2e} | {eq:.2e} | {ec:+.2e} | {:.4} | {:.4} |",
            hs.build_s + hs.solve_s,
            tg.build_s + tg.solve_s
        );
        rust.push(format!("    ({a_over_r:e}, {ep:.3e}, {eq:.3e}),"));
    }
    println!("\n```rust\n{}\n```\n", rust.join("\n"));
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
    let mut bodies = app::prepare_bodies(&c).expect("bodies");
    if let Some(b) = b {
        let half_width = (20.0 * b).max(20.0 * a);
        let mut mesh = layer_strip(b, half_width, 1.3 * a, 41, (b / 2.0).max(a / 2.0));
        let notices = validate_and_orient(&mut mesh).expect("layer mesh");
        let contact_group = mesh.group_index("contact").expect("contact group");
        bodies[1].mesh = Some(LoadedMesh {
            path: PathBuf::from("<procedural layer>"),
            mesh,
            notices,
            contact_group,
        });
    }
    let s = app::solve_prepared(&c, &bodies, Instant::now()).expect("layer solve");
    assert!(s.report.converged, "layer b = {b:?}");
    s.solution
}

fn layers() {
    println!("## Layers bonded to a rigid core (nu = 0.3), rigid R = 100 mm indenter, frictionless\n");
    println!("| b/a | p error (p0) | half-width layer / half-space |");
    println!("|---|---|---|");
    let (g, nu, r, a) = (1.0_f64, 0.3_f64, 100.0_f64, 1.0_f64);
    let e_star = 2.0 * g / (1.0 - nu);
    let p_total = std::f64::consts::PI * a * a * e_star / (4.0 * r);
    let p0 = 2.0 * p_total / (std::f64::consts::PI * a);
    let hs = layer_solution(None, p_total, a);
    let mut rust = Vec::new();
    for b_over_a in [1.0, 2.0, 5.0, 10.0, 20.0, 50.0] {
        let layer = layer_solution(Some(b_over_a * a), p_total, a);
        let ep = layer
            .x
            .iter()
            .zip(&layer.pressure)
            .map(|(&x, &p)| (p - linear(&hs.x, &hs.pressure, x)).abs())
            .fold(0.0_f64, f64::max)
            / p0;
        let w = |s: &ContactSolution| {
            let [x0, x1] = s.contact_extent().expect("contact");
            0.5 * (x1 - x0)
        };
        println!("| {b_over_a} | {ep:.2e} | {:.4} |", w(&layer) / w(&hs));
        rust.push(format!("    ({b_over_a:e}, {ep:.3e}),"));
    }
    println!("\n```rust\n{}\n```\n", rust.join("\n"));
}

fn main() {
    rollers();
    layers();
}
