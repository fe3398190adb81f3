//! The error–time chart of `rollbem study accuracy`: one curve per body model on log–log
//! axes, each point labelled with its contact elements, and the Pareto front as a staircase.

use crate::error::Error;
use plotters::prelude::*;
use std::path::Path;

/// One run on the chart.
#[derive(Debug, Clone)]
pub struct Point {
    /// Wall time of the run [s] (> 0).
    pub time_s: f64,
    /// Its error (> 0).
    pub error: f64,
    /// The label written next to the point (the contact elements).
    pub label: String,
}

/// One body model's runs, in the order they are joined.
#[derive(Debug, Clone)]
pub struct Curve {
    /// Legend entry.
    pub name: String,
    /// The points (an empty curve keeps its colour slot and draws nothing).
    pub points: Vec<Point>,
}

/// Writes the chart: `curves` take the colours blue, red, green in order; `front` is the
/// Pareto front (time, error) in increasing time, drawn when it has two points or more.
pub fn write(path: &Path, title: &str, caption: &str, curves: &[Curve], front: &[(f64, f64)]) -> Result<(), Error> {
    super::written(path, draw(path, title, caption, curves, front))
}

fn draw(
    path: &Path,
    title: &str,
    caption: &str,
    curves: &[Curve],
    front: &[(f64, f64)],
) -> Result<(), Box<dyn std::error::Error>> {
    let pts: Vec<&Point> = curves.iter().flat_map(|c| &c.points).collect();
    let root = SVGBackend::new(path, (900, 640)).into_drawing_area();
    root.fill(&WHITE)?;
    let root = root.titled(title, ("sans-serif", 18))?;
    if pts.is_empty() {
        root.draw(&Text::new("no converged run to plot", (300, 300), ("sans-serif", 20)))?;
        root.present()?;
        return Ok(());
    }
    let bounds = |f: &dyn Fn(&Point) -> f64| {
        let (lo, hi) = pts
            .iter()
            .fold((f64::INFINITY, 0.0_f64), |(l, h), r| (l.min(f(r)), h.max(f(r))));
        (lo / 2.0, hi * 2.0)
    };
    let (t0, t1) = bounds(&|p| p.time_s);
    let (e0, e1) = bounds(&|p| p.error);
    let mut chart = ChartBuilder::on(&root)
        .margin(15)
        .x_label_area_size(45)
        .y_label_area_size(70)
        .caption(caption, ("sans-serif", 14))
        .build_cartesian_2d((t0..t1).log_scale(), (e0..e1).log_scale())?;
    chart
        .configure_mesh()
        .x_desc("wall time of a run [s]")
        .y_desc("RMS error")
        .x_label_formatter(&|v| format!("{v:.0e}"))
        .y_label_formatter(&|v| format!("{v:.0e}"))
        .draw()?;
    let colours = [BLUE, RED, GREEN, MAGENTA, BLACK];
    for (k, curve) in curves.iter().enumerate() {
        let series: Vec<(f64, f64)> = curve.points.iter().map(|p| (p.time_s, p.error)).collect();
        if series.is_empty() {
            continue;
        }
        let colour = colours[k % colours.len()];
        chart
            .draw_series(LineSeries::new(series.clone(), colour.stroke_width(2)))?
            .label(curve.name.as_str())
            .legend(super::line_key(colour.stroke_width(2)));
        chart.draw_series(series.iter().map(|&p| Circle::new(p, 4, colour.filled())))?;
        chart.draw_series(curve.points.iter().map(|p| {
            Text::new(
                p.label.clone(),
                (p.time_s, p.error),
                ("sans-serif", 11).into_font().color(&colour),
            )
        }))?;
    }
    if front.len() > 1 {
        let mut steps = Vec::new();
        for w in front.windows(2) {
            steps.push(w[0]);
            steps.push((w[1].0, w[0].1));
        }
        steps.push(*front.last().expect("non-empty"));
        chart
            .draw_series(LineSeries::new(steps, BLACK.mix(0.6).stroke_width(1)))?
            .label("Pareto front")
            .legend(super::line_key(BLACK.mix(0.6)));
    }
    super::draw_legend(&mut chart, SeriesLabelPosition::UpperRight)?;
    root.present()?;
    Ok(())
}
