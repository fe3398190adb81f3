//! The cost of a transient history against one steady solve of the same scene: 100 steps
//! (pressed, shifted to the case's tangential load, then 98 rolling steps of one node spacing)
//! on CONTACT's Carter scene at 100 elements (cases/carter2d_contact.yaml) and on the true
//! geometry (cases/fig14_true_geometry.yaml, BEM rollers on shafts). The steady solve is the
//! whole solve of the library (scene, assembly, Newton; nothing written), as is the history
//! (scene, assembly once, 100 warm-started steps). Best of `--repeat N` (default 3), both
//! measured one after the other in one process, so their ratio shares the machine's load.
//!
//! Run: `cargo run --release --example transient_cost [-- --repeat 5] [--only <scene>]`. The ratios are in
//! docs/performance.md ("Transient rolling").

pub mod common;

use common::{case_path, Table};
use rollbem::contact::methods;
use rollbem::scene::Scene;
use rollbem::transient::{History, Step};
use std::time::Instant;

/// The scenes: case and overrides.
const SCENES: [(&str, &[&str]); 2] = [
    ("carter2d_contact", &["contact.grid.elements=100"]),
    ("fig14_true_geometry", &[]),
];

/// The scene of a shipped case with overrides.
fn scene(name: &str, overrides: &[&str]) -> Scene {
    let overrides: Vec<String> = overrides.iter().map(|s| s.to_string()).collect();
    let case = rollbem::case::load(&case_path(name), &overrides).expect("loads");
    Scene::from_case(&case).expect("scene")
}

/// One steady solve, whole.
fn steady(name: &str, overrides: &[&str]) -> f64 {
    let t = Instant::now();
    let s = scene(name, overrides);
    let (_, problem) = s.assemble().expect("assembles");
    let (_, report) = methods::solve(&problem, &s.solver);
    assert!(report.converged, "{name}: steady");
    t.elapsed().as_secs_f64()
}

/// 100 steps, whole; their mean Newton iterations; the Newton systems factored anew and those
/// solved with the kept factors of an equal matrix.
fn history(name: &str, overrides: &[&str]) -> (f64, f64, (usize, usize)) {
    let t = Instant::now();
    let s = scene(name, overrides);
    let mut h = History::new(&s).expect("a history");
    let mut step = Step {
        distance: 0.0,
        normal: s.normal,
        tangential: rollbem::contact::TangentialControl::Ratio(0.0),
    };
    let mut iterations = h.advance(step).expect("pressed").iterations;
    step.tangential = s.tangential;
    iterations += h.advance(step).expect("shifted").iterations;
    step.distance = s.grid.node_spacing();
    for _ in 0..98 {
        iterations += h.advance(step).expect("rolls").iterations;
    }
    (t.elapsed().as_secs_f64(), iterations as f64 / 100.0, h.factorisations())
}

/// The table: one row per scene (those named `only`, if given).
pub fn table(repeat: usize, only: Option<&str>) -> Table {
    let mut t = Table::new(&[
        "scene",
        "nodes",
        "steady solve [s]",
        "100 steps [s]",
        "ratio",
        "Newton iterations a step",
        "LU factored / reused",
    ]);
    for (name, overrides) in SCENES.into_iter().filter(|(n, _)| only.is_none_or(|o| o == *n)) {
        let nodes = scene(name, overrides).grid.n_nodes();
        let mut best = (f64::INFINITY, f64::INFINITY, 0.0, (0, 0));
        for _ in 0..repeat.max(1) {
            let one = steady(name, overrides);
            let (all, iterations, lu) = history(name, overrides);
            best = (best.0.min(one), best.1.min(all), iterations, lu);
        }
        t.push(vec![
            name.to_string(),
            nodes.to_string(),
            format!("{:.4}", best.0),
            format!("{:.4}", best.1),
            format!("{:.1}", best.1 / best.0),
            format!("{:.2}", best.2),
            format!("{} / {}", best.3 .0, best.3 .1),
        ]);
    }
    t
}

fn main() {
    let args: Vec<String> = std::env::args().collect();
    let repeat = args
        .iter()
        .position(|a| a == "--repeat")
        .and_then(|i| args.get(i + 1))
        .map_or(3, |v| v.parse().expect("--repeat N"));
    let only = args.iter().position(|a| a == "--only").and_then(|i| args.get(i + 1));
    print!("{}", table(repeat, only.map(String::as_str)).markdown());
}
