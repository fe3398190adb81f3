//! Internal and conformal contact with the true geometry: the tables of docs/theory.md
//! ("Tractions along the contact": what the traction axes change on every shipped case) and
//! docs/conformal.md §6 (the roller-in-a-ring-bore cases against Hertz, Carter and the
//! half-space model), and the plot bore_a020.svg, drawn into a temporary folder (`--figures
//! DIR`: into DIR; `--update-docs`: docs/img/, the figure of docs/conformal.md). The `docs` test
//! compares the tables with the pages.
//!
//! Run: `cargo run --release --example conformal_report [-- --update-docs]` (a few seconds).

pub mod common;

use common::{figure_dir, shipped_cases, signed, solve, Table};
use plotters::prelude::*;
use rollbem::analytic::creepage::{free_rolling_creepage_in_a_bore, BoreRing, ShaftRoller};
use rollbem::analytic::Carter;
use rollbem::app::{self, Solved};
use rollbem::post::ContactSolution;
use rollbem::study::accuracy::{solve_model, SceneModel};

/// The roller-in-a-ring-bore cases, in the order of the page.
pub const BORE_CASES: [&str; 6] = [
    "bore_a001_tractive",
    "bore_a001_braking",
    "bore_a005_tractive",
    "bore_a005_braking",
    "bore_a020_tractive",
    "bore_a020_braking",
];

/// Shaft radius over roller radius of the bore cases (5 mm on R1 = 40 mm).
const BORE_SHAFT_RATIO: f64 = 5.0 / 40.0;

fn half_width(s: &ContactSolution) -> f64 {
    let [x0, x1] = s.contact_extent().expect("a converged run is in contact");
    0.5 * (x1 - x0)
}

fn max_of(v: &[f64]) -> f64 {
    v.iter().fold(0.0_f64, |m, &p| m.max(p))
}

fn max_diff(a: &[f64], b: &[f64]) -> f64 {
    a.iter().zip(b).fold(0.0_f64, |m, (x, y)| m.max((x - y).abs()))
}

/// Whether a case has a half-space body, elastic or viscoelastic (its frame is the global axes
/// whatever the key says).
fn has_half_space(s: &Solved) -> bool {
    s.scene.bodies.iter().any(|b| b.idealises_as_half_plane())
}

/// Two significant figures in exponent form with the docs' minus (−1.3e-2, +4.0e-6), `0` below
/// round-off (1e-12: a load the solver holds to its tolerance).
fn relative(v: f64) -> String {
    if v.abs() < 1e-12 {
        return "0".into();
    }
    let s = format!("{v:+.1e}");
    s.replacen("-", "−", if s.starts_with('-') { 1 } else { 0 })
}

/// Every shipped case solved with the tractions along the global axes and along the contact:
/// the relative changes of P (overlap control: the computed P), ξ and the contact half-width,
/// and the largest nodal changes of p and q (in units of the global run's peak pressure); the half-space cases in one row (their frame is
/// the global axes either way, so every change must be exactly zero).
pub fn traction_axes_effect() -> Table {
    let mut t = Table::new(&[
        "case",
        "models",
        "ξ global",
        "ξ contact",
        "Δξ/ξ",
        "ΔP/P",
        "Δa/a",
        "max \\|Δp\\|/p_max",
        "max \\|Δq\\|/μp_max",
    ]);
    // The cases' runs are independent: solved side by side, each reduced to its row (or its
    // half-space change) at once; the table keeps the cases' order.
    use rayon::prelude::*;
    let rows: Vec<Result<Vec<String>, f64>> = shipped_cases()
        .par_iter()
        .map(|name| {
            let g = solve(name, &["contact.traction_axes=global"]);
            let c = solve(name, &["contact.traction_axes=contact"]);
            let (sg, sc) = (&g.solution, &c.solution);
            // The peak pressure of the global-axes run (an overlap-controlled layer has no
            // meaningful Hertz p0).
            let p0 = max_of(&sg.pressure);
            let mu = g.scene.friction();
            let dp = max_diff(&sg.pressure, &sc.pressure) / p0;
            let dq = if mu > 0.0 {
                max_diff(&sg.shear, &sc.shear) / (mu * p0)
            } else {
                0.0
            };
            if has_half_space(&g) {
                return Err(dp
                    .max(dq)
                    .max((sc.creep - sg.creep).abs())
                    .max((sc.normal_force - sg.normal_force).abs()));
            }
            let models = format!(
                "{} / {}",
                g.scene.bodies[0].model_name(),
                g.scene.bodies[1].model_name()
            );
            Ok(vec![
                name.clone(),
                models,
                format!("{:.4e}", sg.creep),
                format!("{:.4e}", sc.creep),
                relative(sc.creep / sg.creep - 1.0),
                relative(sc.normal_force / sg.normal_force - 1.0),
                relative(half_width(sc) / half_width(sg) - 1.0),
                relative(dp).replace('+', ""),
                relative(dq).replace('+', ""),
            ])
        })
        .collect();
    let (mut half_space_cases, mut half_space_change) = (0, 0.0_f64);
    for row in rows {
        match row {
            Ok(row) => t.push(row),
            Err(change) => {
                half_space_cases += 1;
                half_space_change = half_space_change.max(change);
            }
        }
    }
    let zero = |v: f64| if v == 0.0 { "0".to_string() } else { format!("{v:.1e}") };
    t.push(vec![
        format!("the {half_space_cases} half-space cases"),
        "half-space models".into(),
        "–".into(),
        "–".into(),
        zero(half_space_change),
        zero(half_space_change),
        zero(half_space_change),
        zero(half_space_change),
        zero(half_space_change),
    ]);
    t
}

/// One bore case with the BEM (the shipped meshes) and with the half-space model on the same
/// grid (R* from the signed radii): contact half-width and peak pressure against Hertz, the
/// creepage against Carter's.
pub struct BoreRow {
    /// Case stem.
    pub name: String,
    /// The BEM run.
    pub bem: Solved,
    /// The half-space run's solution.
    pub half_space: ContactSolution,
}

/// The six bore cases.
pub fn bore_runs() -> Vec<BoreRow> {
    BORE_CASES
        .iter()
        .map(|&name| {
            let bem = solve(name, &[] as &[&str]);
            let case = app::load_case(&common::case_path(name), &[] as &[&str]).expect("case loads");
            let n = bem.scene.grid.n_elements();
            let hs = solve_model(&case, SceneModel::HalfSpace, n, BORE_SHAFT_RATIO).expect("half-space");
            assert!(hs.solution_converged, "{name}: half-space");
            BoreRow {
                name: name.to_string(),
                bem,
                half_space: hs.solution,
            }
        })
        .collect()
}

/// The table of docs/conformal.md §6.
pub fn bore_table(rows: &[BoreRow]) -> Table {
    let mut t = Table::new(&[
        "case",
        "Q/μP",
        "a_H [mm]",
        "BEM a/a_H",
        "BEM p_max/p0",
        "BEM ξ/ξ_Carter",
        "half-space a/a_H",
        "half-space p_max/p0",
        "half-space ξ/ξ_Carter",
        "BEM ξ",
        "ξ_Carter + ξ_free",
        "iterations",
    ]);
    for r in rows {
        let e = &r.bem.scene.estimates;
        let (a, p0) = (e.hertz_half_width, e.hertz_peak_pressure);
        let mu = r.bem.scene.friction();
        let ratio = r.bem.solution.tangential_force / (mu * r.bem.solution.normal_force);
        let carter = Carter {
            half_width: a,
            peak_pressure: p0,
            friction: mu,
            ratio,
            leading_edge_sign: 1.0,
        }
        .creep(e.effective_radius);
        let (b, h) = (&r.bem.solution, &r.half_space);
        t.push(vec![
            r.name.clone(),
            signed(ratio, 2),
            format!("{a:.4}"),
            format!("{:.4}", half_width(b) / a),
            format!("{:.4}", max_of(&b.pressure) / p0),
            format!("{:.4}", b.creep / carter),
            format!("{:.4}", half_width(h) / a),
            format!("{:.4}", max_of(&h.pressure) / p0),
            format!("{:.4}", h.creep / carter),
            format!("{:.4e}", b.creep),
            format!("{:.4e}", carter + bore_free_rolling(a)),
            r.bem.report.iterations.to_string(),
        ]);
    }
    t
}

/// The series' free-rolling creepage of the bore cases' roller (R1 = 40 on a shaft of 5) in
/// their ring (bore 50, rim 65), steel, at the Hertz half-width a.
fn bore_free_rolling(a: f64) -> f64 {
    let steel = rollbem::material::Elastic::new(210_000.0, 0.3);
    let roller = ShaftRoller {
        radius: 40.0,
        shaft_radius: 40.0 * BORE_SHAFT_RATIO,
        material: steel,
    };
    let ring = BoreRing {
        bore_radius: 50.0,
        rim_radius: 65.0,
        material: steel,
    };
    free_rolling_creepage_in_a_bore(&roller, &ring, a).expect("series").0
}

type Curve = (String, Vec<(f64, f64)>, RGBColor);

/// p/p0 and q/(μp0) against x/a of the tractive case at a/R1 = 0.2, BEM and half-space.
fn plot(row: &BoreRow, path: &std::path::Path) -> Result<(), Box<dyn std::error::Error>> {
    let e = &row.bem.scene.estimates;
    let (a, p0, mu) = (e.hertz_half_width, e.hertz_peak_pressure, row.bem.scene.friction());
    let curve = |s: &ContactSolution, v: &dyn Fn(usize) -> f64| -> Vec<(f64, f64)> {
        (0..s.x.len()).map(|i| (s.x[i] / a, v(i))).collect()
    };
    let (b, h) = (&row.bem.solution, &row.half_space);
    let curves: [Curve; 4] = [
        ("p/p0, BEM".into(), curve(b, &|i| b.pressure[i] / p0), BLUE),
        ("q/(μp0), BEM".into(), curve(b, &|i| b.shear[i] / (mu * p0)), RED),
        ("p/p0, half-space".into(), curve(h, &|i| h.pressure[i] / p0), CYAN),
        (
            "q/(μp0), half-space".into(),
            curve(h, &|i| h.shear[i] / (mu * p0)),
            MAGENTA,
        ),
    ];
    let area = SVGBackend::new(path, (900, 520)).into_drawing_area();
    area.fill(&WHITE)?;
    let area = area.titled(
        "Roller R1 = 40 in a bore R2 = 50, a/R1 = 0.2, Q/(μP) = 0.5: BEM against half-space",
        ("sans-serif", 17),
    )?;
    let mut chart = ChartBuilder::on(&area)
        .margin(12)
        .x_label_area_size(40)
        .y_label_area_size(60)
        .build_cartesian_2d(-1.35..1.35, -0.05..1.1)?;
    chart
        .configure_mesh()
        .x_desc("x / a_Hertz [-]")
        .y_desc("p / p0 and q / (μ p0) [-]  (p0: Hertz)")
        .draw()?;
    for (label, points, color) in curves {
        chart
            .draw_series(LineSeries::new(points, color.stroke_width(2)))?
            .label(label)
            .legend(move |(x, y)| PathElement::new(vec![(x, y), (x + 20, y)], color.stroke_width(2)));
    }
    chart
        .configure_series_labels()
        .position(SeriesLabelPosition::UpperRight)
        .border_style(BLACK)
        .background_style(WHITE.mix(0.9))
        .draw()?;
    area.present()?;
    Ok(())
}

fn main() -> Result<(), Box<dyn std::error::Error>> {
    println!("## docs/theory.md: traction axes, global against contact\n");
    println!("{}", traction_axes_effect().markdown());
    let rows = bore_runs();
    println!("## docs/conformal.md §6: a roller in a ring bore\n");
    println!("{}", bore_table(&rows).markdown());
    let img = figure_dir();
    plot(&rows[4], &img.join("bore_a020.svg"))?;
    Ok(())
}
