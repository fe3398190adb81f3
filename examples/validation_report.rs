//! Prints the measured validation tables of docs/validation.md (the `docs` test compares them
//! with the page).
//!
//! Run: `cargo run --release --example validation_report` (about a minute).

pub mod common;

use common::{direction_mark, shipped_cases, solve, Table};
use rollbem::analytic::{self, hertz_pressure};
use rollbem::post::norms::nodal_error_against;
use rollbem::post::{slip_regime, traction_ripple, ContactSolution, NodeState, SlipDirection, Zone};

fn half_width(sol: &ContactSolution) -> f64 {
    let [a, b] = sol.contact_extent().expect("a converged run is in contact");
    0.5 * (b - a)
}

fn max_abs_diff(a: &[f64], b: &[f64]) -> f64 {
    a.iter().zip(b).fold(0.0_f64, |m, (x, y)| m.max((x - y).abs()))
}

fn max_pressure(sol: &ContactSolution) -> f64 {
    sol.pressure.iter().fold(0.0_f64, |m, &p| m.max(p))
}

/// The zones in contact as `state±[x0, x1]` in units of a, with `decimals` decimals; with
/// `nodes`, the state abbreviated to two letters and the node count appended.
fn zone_labels(zones: &[Zone], a: f64, decimals: usize, nodes: bool) -> String {
    zones
        .iter()
        .filter(|z| z.state != NodeState::Open)
        .map(|z| {
            let name = z.state.name();
            let state = if nodes { &name[..2] } else { name };
            let sign = direction_mark(z.direction.map_or(0, SlipDirection::sign));
            let count = if nodes { format!("({})", z.nodes) } else { String::new() };
            format!("{state}{sign}[{:.decimals$}, {:.decimals$}]{count}", z.x0 / a, z.x1 / a)
        })
        .collect::<Vec<_>>()
        .join(" ")
}

/// Hertz (cases/hertz.yaml) at 11 … 161 elements.
pub fn hertz() -> Table {
    let mut t = Table::new(&[
        "elements",
        "a error",
        "p0 error",
        "RMS p error (p0)",
        "max p error (p0)",
        "iterations",
    ]);
    for n in [11, 21, 41, 81, 161] {
        let s = solve("hertz", &[format!("contact.grid.elements={n}")]);
        let (a, p0) = (
            s.scene.estimates.hertz_half_width,
            s.scene.estimates.hertz_peak_pressure,
        );
        let e = nodal_error_against(
            &s.solution.x,
            &s.solution.pressure,
            |x| hertz_pressure(x, a, p0),
            f64::INFINITY,
            p0,
        );
        t.push(vec![
            n.to_string(),
            format!("{:+.3e}", half_width(&s.solution) / a - 1.0),
            format!("{:+.3e}", max_pressure(&s.solution) / p0 - 1.0),
            format!("{:.3e}", e.rms),
            format!("{:.3e}", e.max),
            s.report.iterations.to_string(),
        ]);
    }
    t
}

/// Carter at Q/μP = 0.51 and 0.84, both slip derivatives, 21 … 321 elements.
pub fn carter() -> Table {
    let mut t = Table::new(&[
        "case",
        "elements",
        "slip derivative",
        "max q error (μp0)",
        "RMS q error in contact (μp0)",
        "stick width − Carter (elements)",
        "creep error",
        "iterations Φ",
    ]);
    for name in ["carter_051", "carter_084"] {
        for der in ["first_order", "second_order"] {
            for n in [21, 41, 81, 161, 321] {
                let s = solve(
                    name,
                    &[
                        format!("contact.grid.elements={n}"),
                        format!("contact.slip_derivative={der}"),
                    ],
                );
                let c = s.scene.carter_reference().expect("Carter's cases prescribe Q/μP");
                let mu_p0 = c.friction * c.peak_pressure;
                let (x, q) = (&s.solution.x, &s.solution.shear);
                let all = nodal_error_against(x, q, |x| c.shear(x), f64::INFINITY, mu_p0);
                let inside = nodal_error_against(x, q, |x| c.shear(x), c.half_width, mu_p0);
                let width: f64 = s.solution.zones_of(NodeState::Stick).iter().map(|[a, b]| b - a).sum();
                let [c0, c1] = c.stick_zone();
                let xi = c.creep(s.scene.estimates.effective_radius);
                t.push(vec![
                    name.to_string(),
                    n.to_string(),
                    der.to_string(),
                    format!("{:.4}", all.max),
                    format!("{:.2e}", inside.rms),
                    format!("{:+.3}", (width - (c1 - c0)) / s.problem.grid.element_length()),
                    format!("{:+.3e}", s.solution.creep / xi - 1.0),
                    s.report.iterations.to_string(),
                ]);
            }
        }
    }
    t
}

/// Φ against Ψ on every shipped case at its own grid.
pub fn phi_psi() -> Table {
    let mut t = Table::new(&[
        "case",
        "it Φ",
        "it Ψ",
        "P",
        "Q",
        "ξ (Φ)",
        "ξ (Ψ)",
        "max |p_Φ − p_Ψ|/p_max",
        "max |q_Φ − q_Ψ|/max|q|",
        "regime",
    ]);
    for name in &shipped_cases() {
        let phi = solve(name, &["solver.formulation=phi"]);
        let psi = solve(name, &["solver.formulation=psi"]);
        let (sp, ss) = (&phi.solution, &psi.solution);
        let qmax = sp.shear.iter().fold(1e-300_f64, |m, &q| m.max(q.abs()));
        t.push(vec![
            name.clone(),
            phi.report.iterations.to_string(),
            psi.report.iterations.to_string(),
            format!("{:.6}", sp.normal_force),
            format!("{:.6}", sp.tangential_force),
            format!("{:.6e}", sp.creep),
            format!("{:.6e}", ss.creep),
            format!("{:.1e}", max_abs_diff(&sp.pressure, &ss.pressure) / max_pressure(sp)),
            // No shear beyond round-off (a frictionless case): nothing to compare.
            if qmax < 1e-12 * max_pressure(sp) {
                "0.0e0".to_string()
            } else {
                format!("{:.1e}", max_abs_diff(&sp.shear, &ss.shear) / qmax)
            },
            phi.regime.to_string(),
        ]);
    }
    t
}

/// The slip regimes of the dissimilar cases at 21 and 161 elements.
pub fn regimes() -> Table {
    let mut t = Table::new(&[
        "case",
        "elements",
        "ξR/(μa)",
        "regime",
        "slip directions",
        "zones (x/a: state[x0, x1])",
    ]);
    for name in shipped_cases().iter().filter(|n| n.starts_with("dissimilar")) {
        for n in [21, 161] {
            let s = solve(name, &[format!("contact.grid.elements={n}")]);
            let e = &s.scene.estimates;
            let (a, r, mu) = (e.hertz_half_width, e.effective_radius, s.scene.friction());
            t.push(vec![
                name.clone(),
                n.to_string(),
                format!("{:.5}", s.solution.creep * r / (mu * a)),
                s.regime.to_string(),
                format!(
                    "{:?}",
                    s.solution
                        .slip_directions()
                        .iter()
                        .map(|d| d.sign())
                        .collect::<Vec<_>>()
                ),
                zone_labels(&s.solution.zones, a, 3, false),
            ]);
        }
    }
    t
}

/// Free rolling of aluminium on steel at the friction limits.
pub fn free_rolling() -> Table {
    let mut t = Table::new(&["μ", "elements", "ξ", "limit", "error", "p(0) / limit"]);
    for (mu, n) in [(1e-4, 81), (1e-4, 161), (1e-4, 321), (1e3, 81), (1e3, 161), (1e3, 321)] {
        let s = solve(
            "free_rolling_al_steel",
            &[format!("contact.friction={mu}"), format!("contact.grid.elements={n}")],
        );
        let e = &s.scene.estimates;
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
        t.push(vec![
            format!("{mu:e}"),
            n.to_string(),
            format!("{:.6e}", s.solution.creep),
            format!("{limit:.6e}"),
            format!("{:+.3e}", s.solution.creep / limit - 1.0),
            p_centre.map_or("—".into(), |p| format!("{:.5}", p0 / p)),
        ]);
    }
    t
}

/// Variable friction at fixed Q/P (paper Figs 7–9).
pub fn variable_friction() -> Table {
    let mut t = Table::new(&[
        "case",
        "μ",
        "elements",
        "Q/μP",
        "β/μ",
        "regime",
        "zones (x/a, nodes)",
        "ripple (μp0)",
        "iterations",
    ]);
    for name in ["variable_mu_qp_0075", "variable_mu_qp_m0083", "variable_mu_qp_0004"] {
        for mu in [0.1, 0.2, 0.3, 0.4, 0.8] {
            for n in [21, 81] {
                let s = solve(
                    name,
                    &[format!("contact.friction={mu}"), format!("contact.grid.elements={n}")],
                );
                let e = &s.scene.estimates;
                let ripple = traction_ripple(&s.solution) / (mu * e.hertz_peak_pressure);
                t.push(vec![
                    name.to_string(),
                    mu.to_string(),
                    n.to_string(),
                    format!("{:.4}", s.solution.tangential_force / (mu * s.solution.normal_force)),
                    format!("{:.3}", e.dundurs_beta / mu),
                    slip_regime(&s.solution, 1.0, 1).to_string(),
                    zone_labels(&s.solution.zones, e.hertz_half_width, 2, true),
                    format!("{ripple:.1e}"),
                    s.report.iterations.to_string(),
                ]);
            }
        }
    }
    t
}

/// A section of the report: its title and the function that measures its table.
type Section = (&'static str, fn() -> Table);

/// Every solution method on Carter, Q/μP = 0.51, 21 elements (cases/carter_051.yaml): iterations
/// and the nodal differences from the default Newton (Φ), and the creepage against Carter.
pub fn methods() -> Table {
    let mut t = Table::new(&[
        "method",
        "formulation",
        "iterations",
        "max Δq / μp0",
        "max Δp / p0",
        "creepage vs Carter",
    ]);
    let reference = solve("carter_051", &[] as &[&str]);
    let c = reference
        .scene
        .carter_reference()
        .expect("Carter's case prescribes Q/μP");
    let (mu_p0, p0) = (c.friction * c.peak_pressure, c.peak_pressure);
    let xi = c.creep(reference.scene.estimates.effective_radius);
    let runs: [(&str, &str, &[&str]); 7] = [
        ("newton", "phi", &[]),
        ("newton", "psi", &["solver.formulation=psi"]),
        ("newton_plain", "phi", &["solver.method=newton_plain"]),
        (
            "newton_plain",
            "psi",
            &["solver.method=newton_plain", "solver.formulation=psi"],
        ),
        ("norm_tang", "phi", &["solver.method=norm_tang"]),
        (
            "norm_tang",
            "psi",
            &["solver.method=norm_tang", "solver.formulation=psi"],
        ),
        (
            "gauss_seidel",
            "—",
            &["solver.method=gauss_seidel", "solver.max_iterations=20000"],
        ),
    ];
    for (method, formulation, set) in runs {
        let s = solve("carter_051", set);
        t.push(vec![
            format!("`{method}`"),
            formulation.to_string(),
            s.report.iterations.to_string(),
            format!(
                "{:.1e}",
                max_abs_diff(&s.solution.shear, &reference.solution.shear) / mu_p0
            ),
            format!(
                "{:.1e}",
                max_abs_diff(&s.solution.pressure, &reference.solution.pressure) / p0
            ),
            format!("{:.2} %", 100.0 * (s.solution.creep / xi - 1.0).abs()),
        ]);
    }
    t
}

fn main() {
    let sections: [Section; 7] = [
        ("Hertz (cases/hertz.yaml)", hertz),
        ("Carter (cases/carter_051.yaml, carter_084.yaml)", carter),
        ("Φ versus Ψ on every shipped case", phi_psi),
        ("Dissimilar regimes (21 and 161 elements)", regimes),
        (
            "Free rolling of aluminium on steel (cases/free_rolling_al_steel.yaml)",
            free_rolling,
        ),
        ("Variable friction (Figs 7–9), 21 and 81 elements", variable_friction),
        ("Solution methods on Carter, Q/μP = 0.51, 21 elements", methods),
    ];
    for (title, table) in sections {
        println!("## {title}\n\n{}", table().markdown());
    }
}
