//! The shakedown map of `rollbem study shakedown`: Johnson's regions of a sliding Hertz line
//! contact (first yield and shakedown limit p0/k against the traction coefficient Q/P) with the
//! case's points and their own limits.

use crate::error::Error;
use plotters::prelude::*;
use std::path::Path;

/// One traction coefficient of the map.
#[derive(Debug, Clone, Copy)]
pub struct MapPoint {
    /// Traction coefficient μ [-].
    pub mu: f64,
    /// p0/k at first yield [-].
    pub first_yield: f64,
    /// p0/k at the shakedown limit [-].
    pub shakedown: f64,
    /// Whether the limit is governed at the surface.
    pub surface: bool,
}

/// One body of one run.
#[derive(Debug, Clone)]
pub struct CasePoint {
    /// `A` or `B`.
    pub body: String,
    /// |Q|/P [-].
    pub traction: f64,
    /// p_max/k [-].
    pub load: f64,
    /// Its own first-yield load [-].
    pub first_yield: f64,
    /// Its own shakedown load [-].
    pub shakedown: f64,
}

/// What the chart draws.
#[derive(Debug, Clone)]
pub struct ShakedownChart {
    /// `von_mises` or `tresca`.
    pub criterion: &'static str,
    /// Poisson's ratio of the map.
    pub poisson: f64,
    /// The map, in increasing μ.
    pub map: Vec<MapPoint>,
    /// The case's points.
    pub points: Vec<CasePoint>,
}

/// Writes the chart to `path`.
pub fn write(path: &Path, study: &ShakedownChart) -> Result<(), Error> {
    super::written(path, draw(path, study))
}

fn draw(path: &Path, s: &ShakedownChart) -> Result<(), Box<dyn std::error::Error>> {
    let root = SVGBackend::new(path, (900, 640)).into_drawing_area();
    root.fill(&WHITE)?;
    let root = root.titled(
        &format!("Shakedown map, {} (Johnson 1985 Fig. 9.12)", s.criterion),
        ("sans-serif", 18),
    )?;
    let top = s
        .map
        .iter()
        .map(|m| m.shakedown)
        .chain(s.points.iter().flat_map(|p| [p.load, p.shakedown]))
        .filter(|v| v.is_finite())
        .fold(4.0f64, f64::max)
        * 1.15;
    let right = s.points.iter().map(|p| p.traction).fold(0.5f64, f64::max);
    let mut chart = ChartBuilder::on(&root)
        .margin(15)
        .x_label_area_size(45)
        .y_label_area_size(60)
        .caption(
            format!(
                "sliding Hertz line contact (McEwen), nu = {}; points: the case's bodies",
                s.poisson
            ),
            ("sans-serif", 14),
        )
        .build_cartesian_2d(0.0..right, 0.0..top)?;
    chart
        .configure_mesh()
        .x_desc("traction coefficient |Q|/P")
        .y_desc("load p0/k")
        .draw()?;
    let curve = |f: fn(&MapPoint) -> f64| -> Vec<(f64, f64)> {
        s.map.iter().map(|m| (m.mu, f(m))).filter(|p| p.1.is_finite()).collect()
    };
    chart
        .draw_series(LineSeries::new(curve(|m| m.first_yield), BLUE.stroke_width(2)))?
        .label("first yield")
        .legend(super::line_key(BLUE.stroke_width(2)));
    chart
        .draw_series(LineSeries::new(curve(|m| m.shakedown), RED.stroke_width(2)))?
        .label("shakedown limit (elastic-perfectly plastic)")
        .legend(super::line_key(RED.stroke_width(2)));
    let label = |text: &str, x: f64, y: f64| Text::new(text.to_string(), (x, y), ("sans-serif", 13).into_font());
    let at = |mu: f64| {
        s.map
            .iter()
            .min_by(|a, b| (a.mu - mu).abs().total_cmp(&(b.mu - mu).abs()))
    };
    if let Some(m) = at(0.05) {
        chart.draw_series([
            label("elastic", 0.02, 0.5 * m.first_yield),
            label("elastic shakedown", 0.02, 0.5 * (m.first_yield + m.shakedown)),
            label(
                "plastic shakedown or ratchetting (subsurface)",
                0.02,
                0.5 * (m.shakedown + top),
            ),
        ])?;
    }
    if let Some(m) = s.map.iter().find(|m| m.surface) {
        chart.draw_series([label("surface ratchetting", m.mu, 0.5 * (m.shakedown + top) * 0.8)])?;
    }
    for (k, body) in ["A", "B"].iter().enumerate() {
        let colour = [BLACK, MAGENTA][k];
        let pts: Vec<_> = s.points.iter().filter(|p| p.body == *body).collect();
        if pts.is_empty() {
            continue;
        }
        chart
            .draw_series(
                pts.iter()
                    .map(|p| Circle::new((p.traction, p.load), 5, colour.filled())),
            )?
            .label(format!("body {body}: the case (|Q|/P, p_max/k)"))
            .legend(move |(x, y)| Circle::new((x + 10, y), 4, colour.filled()));
        chart
            .draw_series(
                pts.iter()
                    .map(|p| TriangleMarker::new((p.traction, p.first_yield), 6, BLUE)),
            )?
            .label(format!("body {body}: its own first yield (blue), shakedown (red)"))
            .legend(move |(x, y)| TriangleMarker::new((x + 10, y), 5, colour));
        chart.draw_series(
            pts.iter()
                .map(|p| TriangleMarker::new((p.traction, p.shakedown), 6, RED)),
        )?;
    }
    super::draw_legend(&mut chart, SeriesLabelPosition::UpperRight)?;
    root.present()?;
    Ok(())
}
