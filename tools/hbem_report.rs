//! Finite-difference against HBEM slip: the tables of docs/hbem.md and its two plots,
//! docs/img/hbem_carter.svg (Carter, true rollers) and docs/img/hbem_fig4.svg (paper Fig. 4,
//! true geometry, with the half-space model for reference).
//!
//! Run: `cargo run --release --example hbem_report` (a few seconds).

use plotters::prelude::*;
use rollbem::app::{self, Solved};
use rollbem::case::{self, LoadedCase};
use rollbem::contact::friction_check::{check_friction_law, DEFAULT_THRESHOLD_FRACTION};
use rollbem::contact::solution::{ContactSolution, NodeState};
use std::path::{Path, PathBuf};

fn root() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
}

fn solve(name: &str) -> (LoadedCase, Solved) {
    let path = root().join("cases").join(format!("{name}.yaml"));
    let case = case::load(&path, &[]).expect("case loads");
    let s = app::solve(&case).expect("case solves");
    assert!(s.report.converged, "{name} did not converge");
    (case, s)
}

/// Slip normalised as in the paper's figures: s·R/(μa).
struct Scales {
    slip: f64,
    length: f64,
    shear: f64,
}

fn scales(case: &LoadedCase, s: &Solved) -> Scales {
    let mu = case.case.contact.friction;
    let (a, r) = (s.estimates.hertz_half_width, s.estimates.effective_radius);
    Scales {
        slip: r / (mu * a),
        length: a,
        shear: mu * s.estimates.hertz_peak_pressure,
    }
}

fn loaded(sol: &ContactSolution) -> Vec<usize> {
    (0..sol.x.len()).filter(|&i| sol.state[i] != NodeState::Open).collect()
}

/// Prints the node table and the summary numbers of one run.
fn report(name: &str, case: &LoadedCase, s: &Solved, carter: bool) {
    let sc = scales(case, s);
    let sol = &s.solution;
    let hbem = sol.slip_strain.as_ref().expect("HBEM slip");
    let reference = carter.then(|| app::carter_reference(case, &s.estimates).unwrap());
    println!("### {name}: {}\n", case.case.title);
    println!(
        "| x/a | state | q/(μp0) | s_fd·R/(μa) | s_hbem·R/(μa) |{}",
        if carter { " Carter |" } else { "" }
    );
    println!("|---|---|---|---|---|{}", if carter { "---|" } else { "" });
    for i in loaded(sol) {
        let extra = reference.map_or(String::new(), |c| {
            format!(" {:+.4} |", c.slip(sol.x[i], s.estimates.effective_radius) * sc.slip)
        });
        println!(
            "| {:+.4} | {} | {:+.4} | {:+.4} | {:+.4} |{extra}",
            sol.x[i] / sc.length,
            sol.state[i].name(),
            sol.shear[i] / sc.shear,
            sol.slip[i] * sc.slip,
            hbem[i] * sc.slip
        );
    }
    let check = check_friction_law(sol, case.case.contact.friction, DEFAULT_THRESHOLD_FRACTION).unwrap();
    println!(
        "\nslip scale max|s| = {:.4e} ({:.4} in s·R/(μa)); threshold {:.4e}; max |s_hbem − s| over slip nodes {:.4e} \
         ({:.2} % of max|s|); max |s_hbem| over stick nodes {:.4e} ({:.2} %); violations: {}\n",
        check.slip_scale,
        check.slip_scale * sc.slip,
        check.threshold.unwrap_or(0.0),
        check.max_difference_slip_nodes.unwrap_or(0.0),
        100.0 * check.max_difference_slip_nodes.unwrap_or(0.0) / check.slip_scale,
        check.max_hbem_slip_stick_nodes.unwrap_or(0.0),
        100.0 * check.max_hbem_slip_stick_nodes.unwrap_or(0.0) / check.slip_scale,
        check.violations.len()
    );
    for v in &check.violations {
        println!("  violation {v:?}");
    }
    if let Some(c) = reference {
        let r = s.estimates.effective_radius;
        let exact: Vec<f64> = sol.x.iter().map(|&x| c.slip(x, r)).collect();
        let scale = exact.iter().fold(0.0f64, |m, v| m.max(v.abs()));
        let err = |v: &[f64]| {
            loaded(sol)
                .into_iter()
                .filter(|&i| sol.state[i] == NodeState::Slip && exact[i] != 0.0)
                .map(|i| (v[i] - exact[i]).abs())
                .fold(0.0, f64::max)
                / scale
        };
        println!(
            "against Carter's slip (slip nodes): HBEM {:.2} %, finite differences {:.2} % of max |s_Carter|\n",
            100.0 * err(hbem),
            100.0 * err(&sol.slip)
        );
    }
}

type Curve = (String, Vec<(f64, f64)>, RGBColor, bool);

/// A slip plot: lines (`false`) or markers (`true`) in s·R/(μa) against x/a.
fn plot(
    path: &Path,
    title: &str,
    curves: &[Curve],
    legend: SeriesLabelPosition,
) -> Result<(), Box<dyn std::error::Error>> {
    let root = SVGBackend::new(path, (900, 520)).into_drawing_area();
    root.fill(&WHITE)?;
    let root = root.titled(title, ("sans-serif", 17))?;
    let all = curves.iter().flat_map(|c| c.1.iter());
    let (mut x0, mut x1, mut y0, mut y1) = (f64::INFINITY, f64::NEG_INFINITY, 0.0f64, 0.0f64);
    for &(x, y) in all {
        x0 = x0.min(x);
        x1 = x1.max(x);
        y0 = y0.min(y);
        y1 = y1.max(y);
    }
    let pad = 0.06 * (y1 - y0);
    let mut chart = ChartBuilder::on(&root)
        .margin(12)
        .x_label_area_size(40)
        .y_label_area_size(60)
        .build_cartesian_2d((x0 - 0.05)..(x1 + 0.05), (y0 - pad)..(y1 + pad))?;
    chart
        .configure_mesh()
        .x_desc("x / a")
        .y_desc("slip · R / (μ a)")
        .draw()?;
    for (label, points, color, markers) in curves {
        let color = *color;
        if *markers {
            chart
                .draw_series(points.iter().map(|&p| Circle::new(p, 3, color.filled())))?
                .label(label.as_str())
                .legend(move |(x, y)| Circle::new((x + 10, y), 3, color.filled()));
        } else {
            chart
                .draw_series(LineSeries::new(points.clone(), color.stroke_width(2)))?
                .label(label.as_str())
                .legend(move |(x, y)| PathElement::new(vec![(x, y), (x + 20, y)], color.stroke_width(2)));
        }
    }
    chart
        .configure_series_labels()
        .position(legend)
        .border_style(BLACK)
        .background_style(WHITE.mix(0.9))
        .draw()?;
    root.present()?;
    Ok(())
}

fn series(sol: &ContactSolution, sc: &Scales, v: &[f64]) -> Vec<(f64, f64)> {
    loaded(sol)
        .into_iter()
        .map(|i| (sol.x[i] / sc.length, v[i] * sc.slip))
        .collect()
}

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let img = root().join("docs/img");
    std::fs::create_dir_all(&img)?;

    // Carter, true rollers R = 100 mm on shafts.
    let (case, s) = solve("carter_051_true");
    report("carter_051_true", &case, &s, true);
    let sc = scales(&case, &s);
    let sol = &s.solution;
    let c = app::carter_reference(&case, &s.estimates).unwrap();
    let r = s.estimates.effective_radius;
    let fine: Vec<(f64, f64)> = (0..=400)
        .map(|k| -1.0 + 2.0 * k as f64 / 400.0)
        .map(|t| (t, c.slip(t * sc.length, r) * sc.slip))
        .collect();
    plot(
        &img.join("hbem_carter.svg"),
        "Carter Q/(μP) = 0.51, true rollers R = 100 mm on shafts (21 elements)",
        &[
            ("Carter (half-space, exact)".into(), fine, BLACK, false),
            ("finite-difference slip".into(), series(sol, &sc, &sol.slip), BLUE, true),
            (
                "HBEM slip".into(),
                series(sol, &sc, sol.slip_strain.as_ref().unwrap()),
                RED,
                true,
            ),
        ],
        SeriesLabelPosition::LowerRight,
    )?;

    // Paper Fig. 4: true geometry, and the half-space model of the same materials.
    let (case, s) = solve("fig4_true_geometry");
    report("fig4_true_geometry", &case, &s, false);
    let (hs_case, hs) = solve("dissimilar_beta0288_075");
    report("dissimilar_beta0288_075", &hs_case, &hs, false);
    let sc = scales(&case, &s);
    let hs_sc = scales(&hs_case, &hs);
    let sol = &s.solution;
    plot(
        &img.join("hbem_fig4.svg"),
        "Paper Fig. 4 (β = 0.288, μ = 0.1, Q/(μP) = 0.75): finite-difference and HBEM slip",
        &[
            (
                "half-space, finite differences".into(),
                series(&hs.solution, &hs_sc, &hs.solution.slip),
                RGBColor(150, 150, 150),
                false,
            ),
            (
                "true rollers, finite differences".into(),
                series(sol, &sc, &sol.slip),
                BLUE,
                false,
            ),
            (
                "true rollers, HBEM (\"Hyp. Deriv.\")".into(),
                series(sol, &sc, sol.slip_strain.as_ref().unwrap()),
                RED,
                true,
            ),
        ],
        // Both slip zones are at the ends; the stick zone leaves the lower middle free.
        SeriesLabelPosition::LowerMiddle,
    )?;
    println!(
        "wrote {} and {}",
        img.join("hbem_carter.svg").display(),
        img.join("hbem_fig4.svg").display()
    );
    Ok(())
}
