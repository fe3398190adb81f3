//! Finite-difference against HBEM slip: the tables of docs/hbem.md (the `docs` test compares
//! them with the page) and its two plots, hbem_carter.svg (Carter, true rollers) and
//! hbem_fig4.svg (paper Fig. 4, true geometry, with the half-space model for reference), drawn
//! into a temporary folder (`--figures DIR`: into DIR; `--update-docs`: docs/img/, the figures
//! of the docs).
//!
//! Run: `cargo run --release --example hbem_report [-- --update-docs]` (a few seconds).

pub mod common;

use common::{figure_dir, signed, solve, Table};
use plotters::prelude::*;
use rollbem::app::Solved;
use rollbem::post::{ContactSolution, NodeState};
use std::path::Path;

/// Slip normalised as in the paper's figures: s·R/(μa).
struct Scales {
    slip: f64,
    length: f64,
    shear: f64,
}

fn scales(s: &Solved) -> Scales {
    let mu = s.scene.friction();
    let (a, r) = (s.scene.estimates.hertz_half_width, s.scene.estimates.effective_radius);
    Scales {
        slip: r / (mu * a),
        length: a,
        shear: mu * s.scene.estimates.hertz_peak_pressure,
    }
}

fn loaded(sol: &ContactSolution) -> Vec<usize> {
    (0..sol.x.len()).filter(|&i| sol.state[i] != NodeState::Open).collect()
}

/// A percentage with three significant figures (0.80, 6.83, 12.6).
fn percent(v: f64) -> String {
    let p = 100.0 * v;
    if p >= 10.0 {
        format!("{p:.1} %")
    } else {
        format!("{p:.2} %")
    }
}

/// The slip at every loaded node of a run, in s·R/(μa), with Carter's slip when `carter`
/// (similar bodies only).
pub fn node_table(s: &Solved, carter: bool) -> Table {
    let sc = scales(s);
    let sol = &s.solution;
    let hbem = sol.slip_strain.as_ref().expect("a bem run has the HBEM slip");
    let carter = s.scene.carter_reference().filter(|_| carter);
    let mut header = vec!["x/a", "state", "q/(μp0)", "finite differences", "HBEM"];
    if carter.is_some() {
        header.push("Carter");
    }
    let mut t = Table::new(&header);
    for i in loaded(sol) {
        let mut row = vec![
            signed(sol.x[i] / sc.length, 4),
            sol.state[i].name().to_string(),
            signed(sol.shear[i] / sc.shear, 4),
            signed(sol.slip[i] * sc.slip, 4),
            signed(hbem[i] * sc.slip, 4),
        ];
        if let Some(c) = carter {
            row.push(signed(
                c.slip(sol.x[i], s.scene.estimates.effective_radius) * sc.slip,
                4,
            ));
        }
        t.push(row);
    }
    t
}

/// Carter with true rollers: the HBEM and finite-difference slip against Carter's, in the
/// slip zone and in the stick zone, relative to max |s_Carter|.
pub fn carter_errors(s: &Solved) -> Table {
    let sol = &s.solution;
    let hbem = sol.slip_strain.as_ref().expect("a bem run has the HBEM slip");
    let c = s.scene.carter_reference().expect("Carter's case prescribes Q/μP");
    let r = s.scene.estimates.effective_radius;
    let exact: Vec<f64> = sol.x.iter().map(|&x| c.slip(x, r)).collect();
    let scale = exact.iter().fold(0.0f64, |m, v| m.max(v.abs()));
    let slip_error = |v: &[f64]| {
        loaded(sol)
            .into_iter()
            .filter(|&i| sol.state[i] == NodeState::Slip && exact[i] != 0.0)
            .map(|i| (v[i] - exact[i]).abs())
            .fold(0.0, f64::max)
            / scale
    };
    // The stick node next to the slip zone, and the node one element (three nodes) further in.
    let first_stick = (1..sol.x.len())
        .find(|&i| sol.state[i] == NodeState::Stick && sol.state[i - 1] == NodeState::Slip)
        .expect("Carter's solution has a stick zone after the slip zone");
    let stick = |i: usize| hbem[i].abs() / scale;
    let mut t = Table::new(&[
        "",
        r"slip zone: max error / max \|s_Carter\|",
        r"stick zone: max \|s\| / max \|s_Carter\|",
    ]);
    t.push(vec![
        "HBEM".into(),
        percent(slip_error(hbem)),
        format!(
            "{:.1} % (stick node next to the transition); {:.3} % one element inside",
            100.0 * stick(first_stick),
            100.0 * stick(first_stick + 3)
        ),
    ]);
    t.push(vec![
        "finite differences".into(),
        format!("{} (at the stick/slip transition)", percent(slip_error(&sol.slip))),
        "0 (imposed)".into(),
    ]);
    t
}

/// The shipped cases of the friction check table, with how their bodies are modelled.
const CHECKED: [(&str, &str, &str); 11] = [
    ("carter_051", "", "half-space"),
    ("carter_051_block", "", "bem blocks"),
    ("carter_051_true", "", "bem rollers"),
    ("carter_051_true_nonmatching", "", "bem rollers, transferred"),
    ("dissimilar_beta0288_075", " (Fig. 4)", "half-space"),
    ("fig4_true_geometry", "", "bem rollers"),
    ("dissimilar_beta0288_m083", " (Fig. 5)", "half-space"),
    ("dissimilar_beta0288_004", " (Fig. 6)", "half-space"),
    ("fig14_half_space", "", "half-space"),
    ("fig14_true_geometry", "", "bem rollers"),
    ("tyre_b01_incompressible", "", "rigid on a bem layer (ν = 0.5)"),
];

/// The friction-law check of the HBEM slip (summary.json `hbem_check`) on shipped cases, in
/// per cent of max |s| over the nodes in contact.
pub fn check_table() -> Table {
    let mut t = Table::new(&[
        "case",
        "models",
        r"max \|s_hbem\| at stick nodes",
        r"max \|s_hbem − s\| at slip nodes",
        "violations (5 %)",
    ]);
    for (name, figure, models) in CHECKED {
        let s = solve(name, &[] as &[&str]);
        let c = s
            .friction_check
            .expect("every checked case has the HBEM slip and friction");
        t.push(vec![
            format!("{name}{figure}"),
            models.to_string(),
            percent(c.max_hbem_slip_stick_nodes.unwrap_or(0.0) / c.slip_scale),
            percent(c.max_difference_slip_nodes.unwrap_or(0.0) / c.slip_scale),
            c.violations.len().to_string(),
        ]);
    }
    t
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
    let img = figure_dir();

    // Carter, true rollers R = 100 mm on shafts.
    let s = solve("carter_051_true", &[] as &[&str]);
    println!(
        "### carter_051_true: {}\n\n{}",
        s.scene.case.case.title,
        node_table(&s, true).markdown()
    );
    println!("{}", carter_errors(&s).markdown());
    let sc = scales(&s);
    let sol = &s.solution;
    let c = s.scene.carter_reference().expect("Carter's case prescribes Q/μP");
    let r = s.scene.estimates.effective_radius;
    let fine: Vec<(f64, f64)> = (0..=400)
        .map(|k| -1.0 + 2.0 * k as f64 / 400.0)
        .map(|t| (t, c.slip(t * sc.length, r) * sc.slip))
        .collect();
    let hbem = sol.slip_strain.as_ref().expect("a bem run has the HBEM slip");
    plot(
        &img.join("hbem_carter.svg"),
        "Carter Q/(μP) = 0.51, true rollers R = 100 mm on shafts (21 elements)",
        &[
            ("Carter (half-space, exact)".into(), fine, BLACK, false),
            ("finite-difference slip".into(), series(sol, &sc, &sol.slip), BLUE, true),
            ("HBEM slip".into(), series(sol, &sc, hbem), RED, true),
        ],
        SeriesLabelPosition::LowerRight,
    )?;

    // Paper Fig. 4: true geometry, and the half-space model of the same materials.
    let s = solve("fig4_true_geometry", &[] as &[&str]);
    println!(
        "### fig4_true_geometry: {}\n\n{}",
        s.scene.case.case.title,
        node_table(&s, false).markdown()
    );
    let hs = solve("dissimilar_beta0288_075", &[] as &[&str]);
    println!(
        "### The friction check on shipped cases\n\n{}",
        check_table().markdown()
    );
    let sc = scales(&s);
    let hs_sc = scales(&hs);
    let sol = &s.solution;
    let hbem = sol.slip_strain.as_ref().expect("a bem run has the HBEM slip");
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
                series(sol, &sc, hbem),
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
