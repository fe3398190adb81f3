//! transient.svg of a history (docs/outputs.md, "A transient run"): the pressure p and the
//! shear q over x/a at a few steps (the first, three evenly spaced, the last), and the force
//! ratio Q/(μP) (Q when μ = 0) and the creepage ξ against the rolled distance. The history is
//! the one of González & Abascal (2000), one Newton solve a step; the picture draws plain data.

use crate::error::Error;
use plotters::prelude::*;
use std::path::Path;

/// One step's tractions.
#[derive(Debug, Clone)]
pub struct Profile {
    /// The step (0: the press and shift).
    pub step: usize,
    /// Its label in the legend: the rolled distance as transient.csv writes it.
    pub rolled: String,
    /// Node x over the half-width `a` of the picture [-].
    pub x: Vec<f64>,
    /// Pressure p ≥ 0 [stress].
    pub pressure: Vec<f64>,
    /// Shear q, the traction of B on A along +x [stress].
    pub shear: Vec<f64>,
}

/// What the picture shows.
#[derive(Debug, Clone)]
pub struct TransientPicture {
    /// Title line.
    pub title: String,
    /// The half-width a of the x/a axis: half the last step's contact length [length].
    pub half_width: f64,
    /// Units of length and stress.
    pub units: [String; 2],
    /// The label of the force axis (`Q/μP [-]`, or `Q [N/mm]` when μ = 0).
    pub force_label: String,
    /// The profiles, first step first.
    pub profiles: Vec<Profile>,
    /// Each step's (rolled distance [length], force ratio or force).
    pub force: Vec<(f64, f64)>,
    /// Each rolling step's (rolled distance [length], creepage ξ [-]) (step 0 has none).
    pub creep: Vec<(f64, f64)>,
}

/// The steps a picture of `n` steps profiles: the first, three evenly spaced, the last.
pub fn profiled_steps(n: usize) -> Vec<usize> {
    let mut k: Vec<usize> = (0..=4).map(|j| (j * n.saturating_sub(1) + 2) / 4).collect();
    k.dedup();
    k
}

/// Writes the picture to `path`.
pub fn write(path: &Path, picture: &TransientPicture) -> Result<(), Error> {
    super::written(path, draw(path, picture))
}

/// [lo, hi] of `values` padded by 6 % (±1 around a flat or empty range).
fn range(values: impl Iterator<Item = f64>) -> std::ops::Range<f64> {
    let (lo, hi) = values
        .filter(|v| v.is_finite())
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(l, h), v| (l.min(v), h.max(v)));
    if hi > lo {
        let pad = 0.06 * (hi - lo);
        lo - pad..hi + pad
    } else {
        let v = if lo.is_finite() { lo } else { 0.0 };
        let d = if v != 0.0 { 0.1 * v.abs() } else { 1.0 };
        v - d..v + d
    }
}

type Area<'a> = DrawingArea<SVGBackend<'a>, plotters::coord::Shift>;

/// A chart of the profiles' `which` traction (0: p, 1: q) over x/a.
fn profiles(area: &Area, p: &TransientPicture, which: usize) -> Result<(), Box<dyn std::error::Error>> {
    let value = |f: &Profile| {
        if which == 0 {
            f.pressure.clone()
        } else {
            f.shear.clone()
        }
    };
    let xr = range(p.profiles.iter().flat_map(|f| f.x.clone()));
    let yr = range(p.profiles.iter().flat_map(value).chain([0.0]));
    let name = ["pressure p", "shear q"][which];
    let mut chart = ChartBuilder::on(area)
        .margin(15)
        .x_label_area_size(40)
        .y_label_area_size(60)
        .caption(format!("{name} at a few steps"), ("sans-serif", 14))
        .build_cartesian_2d(xr, yr)?;
    chart
        .configure_mesh()
        .x_desc(format!("x/a [-], a = {:.4} {}", p.half_width, p.units[0]))
        .y_desc(format!("{name} [{}]", p.units[1]))
        .draw()?;
    let n = p.profiles.len().max(2) - 1;
    for (k, f) in p.profiles.iter().enumerate() {
        // From light to dark blue: the later the step, the darker.
        let t = k as f64 / n as f64;
        let colour = RGBColor(
            (150.0 * (1.0 - t)) as u8,
            (170.0 * (1.0 - t)) as u8 + 30,
            230 - (60.0 * t) as u8,
        );
        let series = chart.draw_series(LineSeries::new(
            f.x.iter().zip(value(f)).map(|(&x, v)| (x, v)),
            colour.stroke_width(2),
        ))?;
        if which == 0 {
            series
                .label(format!("step {}, rolled = {} {}", f.step, f.rolled, p.units[0]))
                .legend(super::line_key(colour.stroke_width(2)));
        }
    }
    if which == 0 {
        super::draw_legend(&mut chart, SeriesLabelPosition::UpperRight)?;
    }
    Ok(())
}

/// A chart of `points` against the rolled distance.
fn history(
    area: &Area,
    p: &TransientPicture,
    points: &[(f64, f64)],
    label: &str,
    colour: RGBColor,
) -> Result<(), Box<dyn std::error::Error>> {
    let xr = range(p.force.iter().map(|f| f.0));
    let yr = range(points.iter().map(|f| f.1));
    let mut chart = ChartBuilder::on(area)
        .margin(15)
        .x_label_area_size(40)
        .y_label_area_size(70)
        .caption(format!("{label} against the rolled distance"), ("sans-serif", 14))
        .build_cartesian_2d(xr, yr)?;
    chart
        .configure_mesh()
        .x_desc(format!("rolled distance [{}]", p.units[0]))
        .y_desc(label)
        .draw()?;
    chart.draw_series(LineSeries::new(points.iter().copied(), colour.stroke_width(2)))?;
    Ok(())
}

fn draw(path: &Path, p: &TransientPicture) -> Result<(), Box<dyn std::error::Error>> {
    let root = SVGBackend::new(path, (1000, 800)).into_drawing_area();
    root.fill(&WHITE)?;
    let root = root.titled(&p.title, ("sans-serif", 17))?;
    let (top, bottom) = root.split_vertically(400);
    let (tl, tr) = top.split_horizontally(500);
    let (bl, br) = bottom.split_horizontally(500);
    profiles(&tl, p, 0)?;
    profiles(&tr, p, 1)?;
    history(&bl, p, &p.force, &p.force_label, RGBColor(200, 30, 30))?;
    history(&br, p, &p.creep, "creepage ξ [-]", RGBColor(20, 130, 60))?;
    root.present()?;
    Ok(())
}
