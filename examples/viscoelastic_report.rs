//! Prints the measured tables of docs/viscoelastic.md (the `docs` test compares them with the
//! page): CONTACT's `visc_cylindr`, Hunter's rigid cylinder on a standard linear solid against
//! the exact solution of tools/viscoelastic_reference.py, the convergence of one case, and the
//! covered rollers' dissipated power against their dissipation in Fourier space.
//!
//! Run: `cargo run --release --example viscoelastic_report` (about half a minute).

pub mod common;

use common::{root, solve, Table};
use rollbem::app::Solved;

fn peak(s: &Solved) -> f64 {
    s.solution.pressure.iter().fold(0.0_f64, |m, &p| m.max(p))
}

fn resistance(s: &Solved) -> rollbem::post::rolling_resistance::RollingResistance {
    rollbem::output::summary::summary(s)
        .rolling_resistance
        .expect("a converged run is in contact")
}

/// CONTACT's published `visc_cylindr` (reference output rev 2707, grid spacing 0.16 mm) against
/// rollbem at tolerance 1e-4; creepages as magnitudes (the two programs sign them oppositely).
pub fn contact_comparison() -> Table {
    let mut t = Table::new(&[
        "τc [s]",
        "creepage rollbem",
        "creepage CONTACT",
        "p_max rollbem",
        "p_max CONTACT",
        "2a rollbem [mm]",
        "2a CONTACT [mm]",
        "x_p [mm]",
        "F_r/P",
    ]);
    let reference = [
        ("visc_cylindr_tc0", "0", 1.378e-2, 60.32, 12.8),
        ("visc_cylindr_tc0009", "0.009", 1.365e-2, 78.74, 9.9),
        ("visc_cylindr_tc0045", "0.045", 1.152e-2, 84.72, 9.1),
        ("visc_cylindr_tc2", "2.0", 9.932e-3, 85.31, 9.0),
    ];
    for (case, tc, creep, p_max, width) in reference {
        let s = solve(case, &["contact.grid.tolerance=1e-4"]);
        let [x0, x1] = s.solution.contact_extent().unwrap();
        let r = resistance(&s);
        t.push(vec![
            tc.to_string(),
            format!("{:.4e}", s.solution.creep.abs()),
            format!("{creep:.4e}"),
            format!("{:.3}", peak(&s)),
            format!("{p_max:.2}"),
            format!("{:.3}", x1 - x0),
            format!("{width:.1}"),
            if r.pressure_centre.abs() < 5e-5 {
                "0".to_string()
            } else {
                format!("{:.4}", r.pressure_centre)
            },
            // τc = 0 is symmetric: its round-off (1e-12) printed as 0.
            if r.coefficient.abs() < 1e-10 {
                "0".to_string()
            } else {
                format!("{:.4e}", r.coefficient)
            },
        ]);
    }
    t
}

/// One row of tests/data/viscoelastic_reference.csv's `rigid_on_sls` group.
pub struct Exact {
    /// f = E_g/E_r − 1.
    pub f: f64,
    /// E_g [N/mm²].
    pub e_g: f64,
    /// P [N/mm].
    pub load: f64,
    /// Vτc [mm].
    pub v_tau: f64,
    /// Vτc/a_r.
    pub v_tau_over_a_r: f64,
    /// Leading and trailing edges [mm].
    pub edges: [f64; 2],
    /// p_max [N/mm²].
    pub p_max: f64,
    /// x_p [mm].
    pub x_p: f64,
    /// F_r/P.
    pub fr_over_p: f64,
}

/// The exact solutions of the independent reference (Hunter 1961).
pub fn exact_rows() -> Vec<Exact> {
    let text = std::fs::read_to_string(root().join("tests/data/viscoelastic_reference.csv")).unwrap();
    let mut lines = text.lines().filter(|l| !l.starts_with('#'));
    let header: Vec<&str> = lines.next().unwrap().split(',').collect();
    let col = |name: &str| header.iter().position(|h| *h == name).unwrap();
    lines
        .map(|l| l.split(',').collect::<Vec<_>>())
        .filter(|v| v[col("group")] == "rigid_on_sls")
        .map(|v| {
            let x = |name: &str| v[col(name)].parse::<f64>().unwrap();
            Exact {
                f: x("f"),
                e_g: x("E_g"),
                load: x("P"),
                v_tau: x("V_tau_c"),
                v_tau_over_a_r: x("V_tau_c_over_a_r"),
                edges: [x("x_lead"), x("x_trail")],
                p_max: x("p_max"),
                x_p: x("x_p"),
                fr_over_p: x("Fr_over_P"),
            }
        })
        .collect()
}

/// How much larger than the reference's R = 100 mm the radius of the compared runs is, with
/// the load smaller by as much (P·R, and so a, kept): the reference's profile is Hunter's
/// parabola x²/2R, rollbem's the exact circle, which differs by (a/2R)² ≈ 1e-4 at R = 100 mm
/// and by 1e-12 at R = 1e6 mm. Pressures then scale by 1/[`RADIUS_SCALE`], F_r/P = x_p/R too.
pub const RADIUS_SCALE: f64 = 1e4;

/// The `hunter_rigid_on_sls` case set to an exact row (its radius scaled by [`RADIUS_SCALE`]),
/// with more overrides.
pub fn solve_exact_row(row: &Exact, more: &[&str]) -> Solved {
    let mut set = vec![
        format!("materials.rubber.E={}", row.e_g),
        format!("materials.rubber.viscoelastic.E_rubbery={}", row.e_g / (1.0 + row.f)),
        format!("materials.rubber.viscoelastic.creep_time={}", row.v_tau),
        format!("load.normal.force={}", row.load / RADIUS_SCALE),
        format!("bodies.A.radius={}", 100.0 * RADIUS_SCALE),
    ];
    set.extend(more.iter().map(|s| s.to_string()));
    solve("hunter_rigid_on_sls", &set)
}

/// Hunter's rigid cylinder on an SLS half-plane (a_r = 2 mm): rollbem at tolerance 1e-3
/// against the exact solution.
pub fn hunter() -> Table {
    let mut t = Table::new(&[
        "f",
        "Vτc/a_r",
        "F_r/P exact",
        "F_r/P rollbem",
        "x_p error (a_r)",
        "edge error (a_r)",
        "p_max error",
        "elements",
    ]);
    let a_r = 2.0;
    for row in exact_rows() {
        let s = solve_exact_row(&row, &["contact.grid.tolerance=1e-3"]);
        let r = resistance(&s);
        let edge = (r.leading_edge - row.edges[0])
            .abs()
            .max((r.trailing_edge - row.edges[1]).abs());
        t.push(vec![
            format!("{}", row.f),
            format!("{}", row.v_tau_over_a_r),
            format!("{:.4e}", row.fr_over_p),
            format!("{:.4e}", r.coefficient * RADIUS_SCALE),
            format!("{:.0e}", (r.pressure_centre - row.x_p).abs() / a_r),
            format!("{:.0e}", edge / a_r),
            format!("{:.0e}", (peak(&s) * RADIUS_SCALE / row.p_max - 1.0).abs()),
            s.problem.grid.n_elements().to_string(),
        ]);
    }
    t
}

/// Convergence for f = 9, Vτc/a_r = 0.1 (a leading-edge layer of width Vτc/(1+f) = 0.01·a_r):
/// uniform grids against error-controlled ones.
pub fn convergence() -> Table {
    let mut t = Table::new(&[
        "grid",
        "elements",
        "min spacing (a_r)",
        "x_p error (a_r)",
        "edge error (a_r)",
        "p_max error",
        "estimate (p0)",
    ]);
    let a_r = 2.0;
    let rows = exact_rows();
    let row = rows
        .iter()
        .find(|r| r.f == 9.0 && r.v_tau_over_a_r == 0.1)
        .expect("the row f = 9, Vτc/a_r = 0.1");
    let grids: Vec<(String, String)> = [20, 40, 80, 160, 320]
        .iter()
        .map(|n| (format!("uniform {n}"), format!("contact.grid.elements={n}")))
        .chain(
            ["1e-2", "1e-3", "1e-4", "1e-5"]
                .iter()
                .map(|tol| (format!("tolerance {tol}"), format!("contact.grid.tolerance={tol}"))),
        )
        .collect();
    for (label, set) in grids {
        let s = solve_exact_row(row, &[set.as_str()]);
        let r = resistance(&s);
        let edge = (r.leading_edge - row.edges[0])
            .abs()
            .max((r.trailing_edge - row.edges[1]).abs());
        let estimate = s
            .adaptation
            .as_ref()
            .and_then(|a| a.estimate)
            .map_or("-".to_string(), |e| format!("{:.0e}", e.pressure_rms));
        t.push(vec![
            label,
            s.problem.grid.n_elements().to_string(),
            format!("{:.0e}", s.problem.grid.node_spacing() / a_r),
            format!("{:.0e}", (r.pressure_centre - row.x_p).abs() / a_r),
            format!("{:.0e}", edge / a_r),
            format!("{:.0e}", (peak(&s) * RADIUS_SCALE / row.p_max - 1.0).abs()),
            estimate,
        ]);
    }
    t
}

/// The power a viscoelastic cover dissipates under the steady pressure p of a solved run,
/// from its Fourier transform P̂(k) = ∫ p e^(−ikx) dx and the cover's complex compliance.
///
/// The material flows through the contact at V, so a wavenumber k loads it harmonically at
/// ω = kV. With the unit-modulus layer compliance C₁(k) (tests of src/body/layer/compliance.rs)
/// and the SLS compliance J*(k) = 1/G_g + (1/G_r − 1/G_g)/(1 − i d kL), L = Vτc (the ageing of
/// src/body/viscoelastic/aged_kernels.rs in Fourier space), the surface moves by
/// ŵ = C₁ J* P̂, and the pressure's power on the flowing material, D = −dV ∫ p ∂w/∂x dx, is by
/// Parseval (only Im J* survives)
///
/// ```text
/// D = V (1/G_r − 1/G_g) (1/π) ∫_0^∞ C₁(k) k²L/(1 + k²L²) |P̂(k)|² dk.
/// ```
pub fn layer_fourier_dissipation(s: &Solved, thickness: f64, nu: f64, shear: [f64; 2], length: f64, speed: f64) -> f64 {
    use rollbem::body::layer::compliance::layer_compliance;
    use rollbem::quadrature::gauss_legendre;
    let grid = &s.problem.grid;
    let (gx, gw) = gauss_legendre(8);
    // Gauss points of the grid's elements and the weighted pressure there.
    let mut points = Vec::new();
    for e in 0..grid.n_elements() {
        let (s1, s2) = (grid.edges[e], grid.edges[e + 1]);
        for (t, w) in gx.iter().zip(&gw) {
            let x = 0.5 * (s1 + s2) + 0.5 * (s2 - s1) * t;
            points.push((x, 0.5 * (s2 - s1) * w * grid.interpolate(&s.solution.pressure, x)));
        }
    }
    let [x0, x1] = s.solution.contact_extent().expect("a converged run is in contact");
    let a = 0.5 * (x1 - x0);
    let (h, panels) = (0.05 / a, 8000);
    let mut integral = 0.0;
    for panel in 0..panels {
        let k0 = panel as f64 * h;
        for (t, w) in gx.iter().zip(&gw) {
            let k = k0 + 0.5 * h * (1.0 + t);
            let (re, im) = points.iter().fold((0.0, 0.0), |(re, im), &(x, f)| {
                let (sin, cos) = (k * x).sin_cos();
                (re + f * cos, im - f * sin)
            });
            let c1 = layer_compliance(k, thickness, 1.0, nu).nn;
            integral += 0.5 * h * w * c1 * k * k * length / (1.0 + (k * length).powi(2)) * (re * re + im * im);
        }
    }
    speed * (1.0 / shear[1] - 1.0 / shear[0]) * integral / std::f64::consts::PI
}

/// The shipped covered rollers (cases/covered_roller_v_{slow,peak,fast}.yaml: R 50 mm each,
/// a ≈ 6 mm, a cover b = 5 mm of E 50 → 10 MPa, ν 0.45, τc 0.01 s), frictionless, on 80 (their
/// own), 160 and 320 elements: summary.json's dissipated power V ∫ p h0′ dx and the parabolic
/// P·x_p·V/R*, each over the cover's dissipation D in Fourier space
/// ([`layer_fourier_dissipation`]), less one.
pub fn covered_roller_energy() -> Table {
    let mut t = Table::new(&[
        "case",
        "elements",
        "V [mm/s]",
        "V∫p h0′ dx / D − 1",
        "P·x_p·V/R* / D − 1",
    ]);
    let (g_glassy, g_rubbery, creep_time) = (50.0 / 2.9, 10.0 / 2.9, 0.01);
    for case in [
        "covered_roller_v_slow",
        "covered_roller_v_peak",
        "covered_roller_v_fast",
    ] {
        for n in [80, 160, 320] {
            let elements = format!("contact.grid.elements={n}");
            let s = solve(
                case,
                &[
                    "contact.friction=0",
                    "load.tangential.ratio=null",
                    "load.tangential.creep=0",
                    &elements,
                ],
            );
            let speed = s.scene.case.case.load.speed.expect("the case gives a speed");
            let r = resistance(&s);
            let power = r.dissipated_power.expect("the case gives a speed");
            let parabolic = r.moment * speed / s.scene.estimates.effective_radius;
            let dissipated = layer_fourier_dissipation(&s, 5.0, 0.45, [g_glassy, g_rubbery], speed * creep_time, speed);
            t.push(vec![
                case.to_string(),
                n.to_string(),
                format!("{speed}"),
                format!("{:+.1e}", power / dissipated - 1.0),
                format!("{:+.1e}", parabolic / dissipated - 1.0),
            ]);
        }
    }
    t
}

fn main() {
    println!("{}", contact_comparison().markdown());
    println!("{}", hunter().markdown());
    println!("{}", convergence().markdown());
    println!("{}", covered_roller_energy().markdown());
}
