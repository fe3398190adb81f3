//! The strength picture of a body (`strength_<body>.svg`): the shakedown factor of each depth
//! and the residual stresses that prove it, against the depth (docs/strength.md).

use crate::error::Error;
use plotters::prelude::*;
use std::path::Path;

/// One depth row of the picture.
#[derive(Debug, Clone, Copy)]
pub struct Row {
    /// Depth below the surface [length].
    pub z: f64,
    /// The row's own shakedown factor λ_sd(z) [-].
    pub factor: f64,
    /// The residual (σx^r, σy^r) at the body's λ_sd [stress].
    pub residual: [f64; 2],
}

/// What the picture shows.
#[derive(Debug, Clone)]
pub struct ResidualPicture {
    /// Title line.
    pub title: String,
    /// The body's shakedown factor and its governing depth.
    pub factor: f64,
    /// The governing depth [length].
    pub governing_depth: f64,
    /// Units of length and stress.
    pub units: [String; 2],
    /// The rows, shallowest first.
    pub rows: Vec<Row>,
}

/// Writes the picture to `path`.
pub fn write(path: &Path, picture: &ResidualPicture) -> Result<(), Error> {
    super::written(path, draw(path, picture))
}

fn draw(path: &Path, p: &ResidualPicture) -> Result<(), Box<dyn std::error::Error>> {
    let root = SVGBackend::new(path, (1000, 560)).into_drawing_area();
    root.fill(&WHITE)?;
    let root = root.titled(&p.title, ("sans-serif", 17))?;
    let (left, right) = root.split_horizontally(500);
    let depth = p.rows.iter().map(|r| r.z).fold(0.0f64, f64::max).max(f64::MIN_POSITIVE);
    let [len, stress] = [&p.units[0], &p.units[1]];
    // Left: λ_sd(z), depth downwards.
    let fmax = p
        .rows
        .iter()
        .map(|r| r.factor)
        .filter(|f| f.is_finite())
        .fold(p.factor, f64::max);
    let mut chart = ChartBuilder::on(&left)
        .margin(15)
        .x_label_area_size(40)
        .y_label_area_size(60)
        .caption(
            format!("shakedown factor of each depth; body: {:.4}", p.factor),
            ("sans-serif", 14),
        )
        .build_cartesian_2d(0.0..fmax * 1.1, depth..0.0)?;
    chart
        .configure_mesh()
        .x_desc("λ_sd(z) [-]")
        .y_desc(format!("depth z [{len}]"))
        .draw()?;
    chart.draw_series(LineSeries::new(
        p.rows.iter().map(|r| (r.factor, r.z)),
        BLUE.stroke_width(2),
    ))?;
    chart.draw_series([Circle::new((p.factor, p.governing_depth), 5, RED.filled())])?;
    // Right: the residual stresses at λ_sd.
    let smax = p
        .rows
        .iter()
        .flat_map(|r| r.residual)
        .map(f64::abs)
        .fold(f64::MIN_POSITIVE, f64::max);
    let mut chart = ChartBuilder::on(&right)
        .margin(15)
        .x_label_area_size(40)
        .y_label_area_size(60)
        .caption("residual stresses at the body's factor", ("sans-serif", 14))
        .build_cartesian_2d(-smax * 1.1..smax * 1.1, depth..0.0)?;
    chart
        .configure_mesh()
        .x_desc(format!("residual stress [{stress}]"))
        .y_desc(format!("depth z [{len}]"))
        .draw()?;
    for (k, (name, colour)) in [("σx^r", RED), ("σy^r (out of plane)", GREEN)].into_iter().enumerate() {
        chart
            .draw_series(LineSeries::new(
                p.rows.iter().map(|r| (r.residual[k], r.z)),
                colour.stroke_width(2),
            ))?
            .label(name)
            .legend(super::line_key(colour.stroke_width(2)));
    }
    super::draw_legend(&mut chart, SeriesLabelPosition::LowerRight)?;
    root.present()?;
    Ok(())
}
