//! Prints the measured validation tables of docs/validation.md.
//!
//! Run: `cargo run --release --example validation_report` (about a minute).

use rollbem::analytic::{self, hertz_pressure};
use rollbem::app::{self, Solved};
use rollbem::case::{self, LoadedCase};
use rollbem::contact::solution::{slip_regime, ContactSolution, NodeState, SlipDirection};
use std::path::PathBuf;

fn solve(name: &str, set: &[String]) -> (LoadedCase, Solved) {
    let path = PathBuf::from(env!("CARGO_MANIFEST_DIR"))
        .join("cases")
        .join(format!("{name}.yaml"));
    let case = case::load(&path, set).expect("case loads");
    let s = app::solve(&case).expect("case solves");
    (case, s)
}

fn errs(x: &[f64], v: &[f64], f: impl Fn(f64) -> f64, limit: f64, scale: f64) -> (f64, f64) {
    let e: Vec<f64> = x
        .iter()
        .zip(v)
        .filter(|(x, _)| x.abs() < limit)
        .map(|(x, v)| (v - f(*x)).abs() / scale)
        .collect();
    (
        e.iter().fold(0.0_f64, |a, &b| a.max(b)),
        (e.iter().map(|e| e * e).sum::<f64>() / e.len() as f64).sqrt(),
    )
}

fn max_abs_diff(a: &[f64], b: &[f64]) -> f64 {
    a.iter().zip(b).fold(0.0_f64, |m, (x, y)| m.max((x - y).abs()))
}

fn half_width(sol: &ContactSolution) -> f64 {
    let [a, b] = sol.contact_extent().unwrap();
    0.5 * (b - a)
}

fn set(v: &[&str]) -> Vec<String> {
    v.iter().map(|s| s.to_string()).collect()
}

fn main() {
    println!("## Hertz (cases/hertz.yaml)\n");
    println!("| elements | a error | p0 error | RMS p error (p0) | max p error (p0) | iterations |");
    println!("|---|---|---|---|---|---|");
    for n in [11, 21, 41, 81, 161] {
        let (_, s) = solve("hertz", &set(&[&format!("contact.grid.elements={n}")]));
        let (a, p0) = (s.estimates.hertz_half_width, s.estimates.hertz_peak_pressure);
        let pmax = s.solution.pressure.iter().fold(0.0_f64, |m, &p| m.max(p));
        let (mx, rms) = errs(
            &s.solution.x,
            &s.solution.pressure,
            |x| hertz_pressure(x, a, p0),
            f64::INFINITY,
            p0,
        );
        println!(
            "| {n} | {:+.3e} | {:+.3e} | {:.3e} | {:.3e} | {} |",
            half_width(&s.solution) / a - 1.0,
            pmax / p0 - 1.0,
            rms,
            mx,
            s.report.iterations
        );
    }

    println!("\n## Carter (cases/carter_051.yaml, carter_084.yaml)\n");
    println!("| case | elements | slip derivative | max q error (μp0) | RMS q error in contact (μp0) | stick width − Carter (elements) | creep error | iterations Φ |");
    println!("|---|---|---|---|---|---|---|---|");
    for name in ["carter_051", "carter_084"] {
        for der in ["first_order", "second_order"] {
            for n in [21, 41, 81, 161, 321] {
                let (case, s) = solve(
                    name,
                    &set(&[
                        &format!("contact.grid.elements={n}"),
                        &format!("contact.slip_derivative={der}"),
                    ]),
                );
                let c = app::carter_reference(&case, &s.estimates).unwrap();
                let mu_p0 = c.friction * c.peak_pressure;
                let (mx, _) = errs(&s.solution.x, &s.solution.shear, |x| c.shear(x), f64::INFINITY, mu_p0);
                let (_, rms) = errs(&s.solution.x, &s.solution.shear, |x| c.shear(x), c.half_width, mu_p0);
                let stick = s.solution.zones_of(NodeState::Stick);
                let width: f64 = stick.iter().map(|[a, b]| b - a).sum();
                let [c0, c1] = c.stick_zone();
                let xi = c.creep(s.estimates.effective_radius);
                println!(
                    "| {name} | {n} | {der} | {mx:.4} | {rms:.2e} | {:+.3} | {:+.3e} | {} |",
                    (width - (c1 - c0)) / s.problem.grid.element_length(),
                    s.solution.creep / xi - 1.0,
                    s.report.iterations
                );
            }
        }
    }

    println!("\n## Φ versus Ψ on every shipped case (21 elements)\n");
    println!(
        "| case | it Φ | it Ψ | P | Q | ξ (Φ) | ξ (Ψ) | max |p_Φ − p_Ψ|/p_max | max |q_Φ − q_Ψ|/max|q| | regime |"
    );
    println!("|---|---|---|---|---|---|---|---|---|---|");
    let mut names: Vec<String> = std::fs::read_dir(PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("cases"))
        .unwrap()
        .filter_map(|e| e.ok())
        .map(|e| e.path())
        .filter(|p| p.extension().is_some_and(|e| e == "yaml"))
        .map(|p| p.file_stem().unwrap().to_string_lossy().into_owned())
        .collect();
    names.sort();
    for name in &names {
        let (_, phi) = solve(name, &set(&["solver.formulation=phi"]));
        let (_, psi) = solve(name, &set(&["solver.formulation=psi"]));
        let pmax = phi.solution.pressure.iter().fold(0.0_f64, |m, &p| m.max(p));
        let qmax = phi.solution.shear.iter().fold(1e-300_f64, |m, &q| m.max(q.abs()));
        let dp = max_abs_diff(&phi.solution.pressure, &psi.solution.pressure) / pmax;
        let dq = max_abs_diff(&phi.solution.shear, &psi.solution.shear) / qmax;
        println!(
            "| {name} | {} | {} | {:.6} | {:.6} | {:.6e} | {:.6e} | {dp:.1e} | {dq:.1e} | {} |",
            phi.report.iterations,
            psi.report.iterations,
            phi.solution.normal_force,
            phi.solution.tangential_force,
            phi.solution.creep,
            psi.solution.creep,
            phi.regime
        );
    }

    println!("\n## Dissimilar regimes (21 and 161 elements)\n");
    println!("| case | elements | ξR/(μa) | regime | slip directions | zones (x/a: state[x0, x1]) |");
    println!("|---|---|---|---|---|---|");
    for name in names.iter().filter(|n| n.starts_with("dissimilar")) {
        for n in [21, 161] {
            let (case, s) = solve(name, &set(&[&format!("contact.grid.elements={n}")]));
            let (a, r, mu) = (
                s.estimates.hertz_half_width,
                s.estimates.effective_radius,
                case.case.contact.friction,
            );
            let zones: Vec<String> = s
                .solution
                .zones
                .iter()
                .filter(|z| z.state != NodeState::Open)
                .map(|z| {
                    format!(
                        "{}{}[{:.3}, {:.3}]",
                        z.state.name(),
                        match z.direction {
                            Some(SlipDirection::PlusX) => "+",
                            Some(SlipDirection::MinusX) => "−",
                            None => "",
                        },
                        z.x0 / a,
                        z.x1 / a
                    )
                })
                .collect();
            println!(
                "| {name} | {n} | {:.5} | {} | {:?} | {} |",
                s.solution.creep * r / (mu * a),
                s.regime,
                s.solution
                    .slip_directions()
                    .iter()
                    .map(|d| d.sign())
                    .collect::<Vec<_>>(),
                zones.join(" ")
            );
        }
    }

    println!("\n## Free rolling of aluminium on steel (cases/free_rolling_al_steel.yaml)\n");
    println!("| μ | elements | ξ | limit | error | p(0) / limit |");
    println!("|---|---|---|---|---|---|");
    for (mu, n) in [(1e-4, 81), (1e-4, 161), (1e-4, 321), (1e3, 81), (1e3, 161), (1e3, 321)] {
        let (_, s) = solve(
            "free_rolling_al_steel",
            &set(&[&format!("contact.friction={mu}"), &format!("contact.grid.elements={n}")]),
        );
        let e = &s.estimates;
        let (limit, p_centre) = if mu < 1.0 {
            (
                analytic::free_rolling_creep_complete_slip(e.dundurs_beta, e.hertz_half_width, e.effective_radius),
                None,
            )
        } else {
            let (xi, _, p) =
                analytic::free_rolling_no_slip(e.dundurs_beta, e.normal_force, e.effective_radius, e.e_star);
            (xi, Some(p))
        };
        let p0 = s.problem.grid.interpolate(&s.solution.pressure, 0.0);
        println!(
            "| {mu:e} | {n} | {:.6e} | {limit:.6e} | {:+.3e} | {} |",
            s.solution.creep,
            s.solution.creep / limit - 1.0,
            p_centre.map_or("—".into(), |p| format!("{:.5}", p0 / p))
        );
    }

    println!("\n## Variable friction (Figs 7–9), 21 and 81 elements\n");
    println!("| case | μ | elements | Q/μP | β/μ | regime | zones (x/a, nodes) | ripple (μp0) | iterations |");
    println!("|---|---|---|---|---|---|---|---|---|");
    for name in ["variable_mu_qp_0075", "variable_mu_qp_m0083", "variable_mu_qp_0004"] {
        for mu in [0.1, 0.2, 0.3, 0.4, 0.8] {
            for n in [21, 81] {
                let (_, s) = solve(
                    name,
                    &set(&[&format!("contact.friction={mu}"), &format!("contact.grid.elements={n}")]),
                );
                let e = &s.estimates;
                let a = e.hertz_half_width;
                let ripple = rollbem::contact::solution::traction_ripple(&s.solution) / (mu * e.hertz_peak_pressure);
                let zones: Vec<String> = s
                    .solution
                    .zones
                    .iter()
                    .filter(|z| z.state != NodeState::Open)
                    .map(|z| {
                        let sign = match z.direction {
                            Some(SlipDirection::PlusX) => "+",
                            Some(SlipDirection::MinusX) => "−",
                            None => "",
                        };
                        format!(
                            "{}{sign}[{:.2}, {:.2}]({})",
                            &z.state.name()[..2],
                            z.x0 / a,
                            z.x1 / a,
                            z.nodes
                        )
                    })
                    .collect();
                println!(
                    "| {name} | {mu} | {n} | {:.4} | {:.3} | {} | {} | {ripple:.1e} | {} |",
                    s.solution.tangential_force / (mu * s.solution.normal_force),
                    e.dundurs_beta / mu,
                    slip_regime(&s.solution, 1.0, 1),
                    zones.join(" "),
                    s.report.iterations
                );
            }
        }
    }
}
