//! cases/veldep_fric.yaml (friction falling with the slip velocity) under error control:
//! where the estimate sits pass by pass, how far each pass's result is from the last one, and
//! the exponent of the tractions at the stick/slip point. Reproduces the numbers of
//! docs/validation.md, "Falling friction at tolerance 1e-5: measured (2026-12-06)":
//!
//! ```text
//! cargo run --release --example veldep_probe -- exponent        # 641 elements, ~1 min
//! cargo run --release --example veldep_probe -- passes 1e-5     # several minutes
//! cargo run --release --example veldep_probe -- passes 1e-4 1e-5 # the same, then 1e-4
//! cargo run --release --example veldep_probe -- against 1e-5 1e-4 3e-5
//! ```
//!
//! `against REF TOL…` solves the case at tolerance REF, then at each TOL, and prints the RMS
//! distances of each result from REF's. `passes` and `against` take further overrides as
//! `--set key=value` (as `rollbem run --set`), e.g.
//! `--set contact.falling_friction.slip_velocity=144.2695` for CONTACT's law.
//!
//! `exponent` solves the case on a uniform grid of 641 elements, with the law and with constant
//! μ = 0.30, and fits s ∝ d^λ to the slip on the slip side and μ_s p − |q| ∝ d^λ on the stick
//! side, d the distance from the stick/slip point, over 0.01 ≤ d ≤ 0.1 mm (from the point's
//! location on the error-controlled grid, −0.362297 mm, located there to 4e-6 mm between passes
//! 3 and 4; for constant μ from the grid's own transition). It prints the exponent of the
//! Riemann–Hilbert problem linearised at the point, λ = 1/2 − arctan(kA)/π with
//! k = (μ_s − μ_k)(V/s_h) p(x_s) the law's slope in traction per unit slip and A = 2(1 − ν)/G the
//! slip per unit Hilbert transform of the shear of the two steel half-spaces.
//!
//! `passes TOL` runs the error control at tolerance TOL and prints, per pass: the shear
//! estimate, the shares of its squared sum in bands of distance from the stick/slip point, the
//! largest indicators; at the end each pass's RMS differences of p/p0 and q/(μ_s p0) from the
//! reference (over |x| < a, at the pass's nodes), the pass's estimate beside them. The reference
//! is the run's own final result, or with a second tolerance the result of a run at that one
//! (solved first).
use rollbem::adapt::estimate::{BisectionEstimator, Comparison, ErrorEstimator, Pass};
use rollbem::contact::residual::State;
use rollbem::grid::ContactGrid;
use rollbem::post::norms::{nodal_error, node_lengths};
use rollbem::post::NodeState;
use std::path::Path;

/// The estimator of the runs, recording each pass's bisected grid and solution.
struct Probe {
    passes: Vec<(ContactGrid, State, f64)>,
}

impl ErrorEstimator for Probe {
    fn estimate(&mut self, pass: &Pass<'_>) -> Comparison {
        let c = BisectionEstimator.estimate(pass);
        let x = &pass.fine_grid.nodes;
        let w = node_lengths(x);
        let mu_p0 = pass.scales.friction * pass.scales.peak_pressure;
        let dq: Vec<f64> = (0..x.len())
            .map(|i| (pass.fine.shear[i] - pass.coarse_grid.interpolate(&pass.coarse.shear, x[i])) / mu_p0)
            .collect();
        // The stick/slip point: the middle one of edge, transition, edge.
        let xs = pass.singular.get(1).copied().unwrap_or(0.0);
        let loaded: Vec<usize> = (0..x.len()).filter(|&i| pass.fine.pressure[i] > 0.0).collect();
        let total: f64 = loaded.iter().map(|&i| w[i] * dq[i] * dq[i]).sum();
        let hmin = x.windows(2).map(|v| v[1] - v[0]).fold(f64::INFINITY, f64::min);
        println!(
            "pass {}: {} elements, shear estimate {:.3e}, x_s {:.6} mm, shortest spacing {:.2e} mm",
            self.passes.len() + 1,
            pass.fine_grid.n_elements(),
            c.estimate.shear_rms,
            xs,
            hmin
        );
        let edges = [0.0, 1e-6, 1e-5, 1e-4, 1e-3, 1e-2, 1e-1, f64::INFINITY];
        for b in edges.windows(2) {
            let inb: Vec<usize> = loaded
                .iter()
                .copied()
                .filter(|&i| (x[i] - xs).abs() >= b[0] && (x[i] - xs).abs() < b[1])
                .collect();
            if inb.is_empty() {
                continue;
            }
            let share: f64 = inb.iter().map(|&i| w[i] * dq[i] * dq[i]).sum::<f64>() / total;
            let largest = inb.iter().map(|&i| dq[i].abs()).fold(0.0, f64::max);
            println!(
                "  |x - x_s| in [{:.0e}, {:.0e}) mm: {:4} nodes, share {:.3}, largest |dq| {:.2e} mu p0",
                b[0],
                b[1],
                inb.len(),
                share,
                largest
            );
        }
        let mut order: Vec<usize> = (0..c.detail.len()).collect();
        order.sort_by(|&a, &b| c.detail[b].total_cmp(&c.detail[a]));
        let largest: Vec<String> = order.iter().take(3).map(|&k| format!("{:.1e}", c.detail[k])).collect();
        println!("  largest indicators {}", largest.join(", "));
        self.passes
            .push((pass.fine_grid.clone(), pass.fine.clone(), c.estimate.shear_rms));
        c
    }
}

/// The `--set` overrides of the command line.
static OVERRIDES: std::sync::OnceLock<Vec<String>> = std::sync::OnceLock::new();

/// The case with `set`, after the command line's `--set` overrides.
fn scene(set: &[String]) -> rollbem::scene::Scene {
    let mut all: Vec<String> = OVERRIDES.get().cloned().unwrap_or_default();
    all.extend_from_slice(set);
    let loaded = rollbem::app::load_case(Path::new("cases/veldep_fric.yaml"), &all).expect("the case");
    rollbem::scene::Scene::from_case(&loaded).expect("its scene")
}

/// Least-squares slope of log v over log d for the points (d, v).
fn slope(points: &[(f64, f64)]) -> f64 {
    let n = points.len() as f64;
    let (mx, my) = points
        .iter()
        .fold((0.0, 0.0), |(a, b), &(d, v)| (a + d.ln() / n, b + v.ln() / n));
    let sxy: f64 = points.iter().map(|&(d, v)| (d.ln() - mx) * (v.ln() - my)).sum();
    let sxx: f64 = points.iter().map(|&(d, _)| (d.ln() - mx).powi(2)).sum();
    sxy / sxx
}

fn exponent() {
    let (g, nu, mu_s, mu_k, speed, s_h) = (82_000.0, 0.28, 0.30, 0.18, 45_000.0, 100.0);
    for (label, extra) in [
        ("falling law", None),
        ("constant mu = 0.30", Some("contact.falling_friction=null")),
    ] {
        let mut set = vec![
            "contact.grid.elements=641".to_string(),
            "contact.grid.estimate=false".to_string(),
        ];
        set.extend(extra.map(String::from));
        let s = rollbem::app::solve_case(Path::new("cases/veldep_fric.yaml"), &set).expect("solved");
        let sol = &s.solution;
        let xs = match extra {
            None => -0.362297,
            Some(_) => {
                let i = (1..sol.x.len())
                    .find(|&i| sol.state[i - 1] == NodeState::Slip && sol.state[i] == NodeState::Stick)
                    .expect("a transition");
                0.5 * (sol.x[i - 1] + sol.x[i])
            }
        };
        let window = |d: f64| (0.01..=0.1).contains(&d);
        let slip: Vec<(f64, f64)> = (0..sol.x.len())
            .filter(|&i| sol.state[i] == NodeState::Slip && window(xs - sol.x[i]))
            .map(|i| (xs - sol.x[i], sol.slip[i].abs()))
            .collect();
        let stick: Vec<(f64, f64)> = (0..sol.x.len())
            .filter(|&i| sol.state[i] == NodeState::Stick && window(sol.x[i] - xs))
            .map(|i| (sol.x[i] - xs, mu_s * sol.pressure[i] - sol.shear[i].abs()))
            .collect();
        println!(
            "{label}: Q {:.6} N/mm, x_s {xs:.6} mm, slip exponent {:.3} ({} nodes), stick exponent {:.3} ({} nodes)",
            sol.tangential_force,
            slope(&slip),
            slip.len(),
            slope(&stick),
            stick.len()
        );
        if extra.is_none() {
            let i = (0..sol.x.len())
                .min_by(|&a, &b| (sol.x[a] - xs).abs().total_cmp(&(sol.x[b] - xs).abs()))
                .expect("nodes");
            let k = (mu_s - mu_k) * speed / s_h * sol.pressure[i];
            let ka = k * 2.0 * (1.0 - nu) / g;
            println!(
                "  p(x_s) {:.1} MPa, kA {ka:.3}: lambda = 1/2 - arctan(kA)/pi = {:.3}",
                sol.pressure[i],
                0.5 - ka.atan() / std::f64::consts::PI
            );
        }
    }
}

fn passes(tolerance: &str, reference: Option<&str>) {
    // The reference: the run's own last pass, or a run at the tolerance `reference`.
    let referenced = reference.map(|r| {
        let done = rollbem::adapt::solve(&scene(&[format!("contact.grid.tolerance={r}")])).expect("solved");
        let est = done.adaptation.as_ref().and_then(|a| a.estimate).expect("an estimate");
        println!(
            "reference at {r}: {} elements, shear estimate {:.2e}",
            done.problem.grid.n_elements(),
            est.shear_rms
        );
        done
    });
    let sc = scene(&[format!("contact.grid.tolerance={tolerance}")]);
    let mut probe = Probe { passes: Vec::new() };
    let t = std::time::Instant::now();
    let done = rollbem::adapt::solve_with(&sc, &mut probe).expect("solved");
    let a = done.adaptation.as_ref().expect("error-controlled");
    println!(
        "reached {} in {} passes, {} elements, {:.0} s",
        a.reached,
        a.steps.len(),
        done.problem.grid.n_elements(),
        t.elapsed().as_secs_f64()
    );
    let (half_width, p0) = (sc.estimates.hertz_half_width, sc.estimates.hertz_peak_pressure);
    let mu_p0 = sc.friction() * p0;
    let reference = referenced.as_ref().unwrap_or(&done);
    let last = &reference.problem.grid;
    for (k, (grid, z, est)) in probe.passes.iter().enumerate() {
        let x = &grid.nodes;
        let p = nodal_error(x, half_width, |i| {
            (z.pressure[i] - last.interpolate(&reference.state.pressure, x[i])).abs() / p0
        })
        .rms;
        let q = nodal_error(x, half_width, |i| {
            (z.shear[i] - last.interpolate(&reference.state.shear, x[i])).abs() / mu_p0
        })
        .rms;
        println!(
            "pass {}: from the reference p {p:.2e}, q {q:.2e}; shear estimate {est:.2e}",
            k + 1
        );
    }
}

/// The RMS distances of p/p0 and q/(μ_s p0) of `run`'s result from `reference`'s (over |x| < a,
/// at `run`'s nodes).
fn distance(run: &rollbem::adapt::Adapted, reference: &rollbem::adapt::Adapted) -> (f64, f64) {
    let sc = &reference.scene;
    let (half_width, p0) = (sc.estimates.hertz_half_width, sc.estimates.hertz_peak_pressure);
    let (x, g) = (&run.problem.grid.nodes, &reference.problem.grid);
    let p = nodal_error(x, half_width, |i| {
        (run.state.pressure[i] - g.interpolate(&reference.state.pressure, x[i])).abs() / p0
    })
    .rms;
    let q = nodal_error(x, half_width, |i| {
        (run.state.shear[i] - g.interpolate(&reference.state.shear, x[i])).abs() / (sc.friction() * p0)
    })
    .rms;
    (p, q)
}

/// The results at `tolerances` against the result at `reference`.
fn against(reference: &str, tolerances: &[String]) {
    let solve = |t: &str| rollbem::adapt::solve(&scene(&[format!("contact.grid.tolerance={t}")])).expect("solved");
    let r = solve(reference);
    let shear = |a: &rollbem::adapt::Adapted| {
        a.adaptation
            .as_ref()
            .and_then(|a| a.estimate)
            .map_or(0.0, |e| e.shear_rms)
    };
    println!(
        "reference at {reference}: {} elements, shear estimate {:.2e}",
        r.problem.grid.n_elements(),
        shear(&r)
    );
    for t in tolerances {
        let run = solve(t);
        let (p, q) = distance(&run, &r);
        println!(
            "at {t}: {} passes, {} elements, shear estimate {:.2e}; from the reference p {p:.2e}, q {q:.2e}",
            run.adaptation.as_ref().map_or(0, |a| a.steps.len()),
            run.problem.grid.n_elements(),
            shear(&run)
        );
    }
}

fn main() {
    let mut args: Vec<String> = Vec::new();
    let mut sets: Vec<String> = Vec::new();
    let mut given = std::env::args().skip(1);
    while let Some(a) = given.next() {
        if a == "--set" {
            sets.extend(given.next());
        } else {
            args.push(a);
        }
    }
    OVERRIDES.set(sets).expect("set once");
    match args.first().map(String::as_str) {
        Some("exponent") => exponent(),
        Some("passes") => passes(
            args.get(1).map_or("1e-5", String::as_str),
            args.get(2).map(String::as_str),
        ),
        Some("against") => against(args.get(1).map_or("1e-5", String::as_str), &args[2.min(args.len())..]),
        _ => eprintln!(
            "usage: veldep_probe exponent | passes [TOLERANCE [REFERENCE_TOLERANCE]] | against REFERENCE TOLERANCE... [--set KEY=VALUE]..."
        ),
    }
}
