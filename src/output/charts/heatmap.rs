//! Heat maps of a study slice (plotters, SVG): one coloured, labelled cell per (x, y) value.
//!
//! Iteration maps: converged cells in green, darker for more iterations (log scale over the
//! panel), with the count written in the cell; cells where the method did not converge in red
//! (`x`); cells outside the problem's domain (|Q| ≥ μP) in grey (`n/a`); rejected cases in
//! orange (`err`). Ripple maps: the ripple / (μp0) of converged cells, white (≤ 1e-4) to purple
//! (≥ 1, log scale), written in per cent.

use crate::error::Error;
use plotters::prelude::*;
use plotters::style::text_anchor::{HPos, Pos, VPos};
use std::path::Path;

/// How a cell's run ended, as drawn.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Status {
    /// Converged: drawn green (iterations) or by its ripple.
    Converged,
    /// Did not converge: red, `x`.
    NotConverged,
    /// Outside the problem's domain, not solved: grey, `n/a`.
    OutOfDomain,
    /// The run was rejected: orange, `err`.
    Error,
}

/// One axis of a panel: its label and the values of its rows or columns.
#[derive(Debug, Clone, Copy)]
pub struct Axis<'a> {
    /// Axis label.
    pub label: &'a str,
    /// The values, as written.
    pub values: &'a [String],
}

/// One cell as drawn.
#[derive(Debug, Clone, Copy)]
pub struct CellView {
    /// Column (x value index).
    pub ix: usize,
    /// Row (y value index, drawn bottom-up).
    pub iy: usize,
    /// Outcome.
    pub status: Status,
    /// Iterations or ripple of a converged cell.
    pub value: Option<f64>,
}

/// One panel: a method's cells of a slice.
#[derive(Debug, Clone)]
pub struct Panel<'a> {
    /// Panel title.
    pub title: String,
    /// Horizontal axis.
    pub x: Axis<'a>,
    /// Vertical axis.
    pub y: Axis<'a>,
    /// The cells.
    pub cells: Vec<CellView>,
    /// Ripple map (else iterations).
    pub ripple: bool,
}

const CELL_W: i32 = 58;
const CELL_H: i32 = 26;
const LEFT: i32 = 110;
const TOP: i32 = 56;
const BOTTOM: i32 = 58;
const RIGHT: i32 = 20;

fn panel_size(p: &Panel) -> (i32, i32) {
    (
        LEFT + CELL_W * p.x.values.len() as i32 + RIGHT,
        TOP + CELL_H * p.y.values.len() as i32 + BOTTOM,
    )
}

/// Writes the panels (one column when the x axis is long, else three) under a common title.
pub fn write(path: &Path, title: &str, panels: &[&Panel]) -> Result<(), Error> {
    super::written(path, draw(path, title, panels))
}

fn mix(a: (u8, u8, u8), b: (u8, u8, u8), t: f64) -> RGBColor {
    let t = t.clamp(0.0, 1.0);
    let f = |x: u8, y: u8| (x as f64 + (y as f64 - x as f64) * t).round() as u8;
    RGBColor(f(a.0, b.0), f(a.1, b.1), f(a.2, b.2))
}

/// Fill colour and text of a cell; `range` = (min, max) of log10 of the panel's values.
fn cell_style(c: &CellView, ripple: bool, range: (f64, f64)) -> (RGBColor, String, bool) {
    match (c.status, c.value) {
        (Status::OutOfDomain, _) => (RGBColor(215, 215, 215), "n/a".into(), false),
        (Status::Error, _) => (RGBColor(255, 165, 70), "err".into(), false),
        (Status::NotConverged, _) => (RGBColor(214, 39, 40), "x".into(), true),
        (Status::Converged, Some(v)) if ripple => {
            let t = (v.max(1e-12).log10() + 4.0) / 4.0;
            let text = format!("{:.2}%", 100.0 * v);
            (mix((255, 255, 255), (106, 27, 154), t), text, t > 0.55)
        }
        (Status::Converged, Some(v)) => {
            let (lo, hi) = range;
            let t = if hi > lo {
                (v.max(1.0).log10() - lo) / (hi - lo)
            } else {
                0.3
            };
            (mix((199, 233, 192), (0, 90, 50), t), format!("{v:.0}"), t > 0.55)
        }
        (Status::Converged, None) => (RGBColor(199, 233, 192), "ok".into(), false),
    }
}

fn draw(path: &Path, title: &str, panels: &[&Panel]) -> Result<(), Box<dyn std::error::Error>> {
    let (pw, ph) = panels.first().map_or((400, 200), |p| panel_size(p));
    let ncols = if panels.len() == 1 || panels[0].x.values.len() > 6 {
        1
    } else {
        3
    };
    let nrows = panels.len().div_ceil(ncols);
    // Wide enough for the title (about 9 px per character at 18 px).
    let (w, h) = (
        (pw * ncols as i32).max(9 * title.len() as i32 + 40),
        40 + ph * nrows as i32,
    );
    let root = SVGBackend::new(path, (w as u32, h as u32)).into_drawing_area();
    root.fill(&WHITE)?;
    let font = |size: f64| ("sans-serif", size).into_font();
    let centred = |size: f64, color: &RGBColor| TextStyle {
        font: font(size),
        color: color.to_backend_color(),
        pos: Pos::new(HPos::Center, VPos::Center),
    };
    root.draw(&Text::new(title.to_string(), (w / 2, 20), centred(18.0, &BLACK)))?;
    for (k, p) in panels.iter().enumerate() {
        let (ox, oy) = ((k % ncols) as i32 * pw, 40 + (k / ncols) as i32 * ph);
        let (nx, ny) = (p.x.values.len() as i32, p.y.values.len() as i32);
        root.draw(&Text::new(
            p.title.clone(),
            (ox + LEFT + CELL_W * nx / 2, oy + 16),
            centred(15.0, &BLACK),
        ))?;
        let logs: Vec<f64> = p
            .cells
            .iter()
            .filter(|c| c.status == Status::Converged)
            .filter_map(|c| c.value.map(|v| v.max(1.0).log10()))
            .collect();
        let range = (
            logs.iter().copied().fold(f64::INFINITY, f64::min),
            logs.iter().copied().fold(f64::NEG_INFINITY, f64::max),
        );
        for c in &p.cells {
            let x0 = ox + LEFT + CELL_W * c.ix as i32;
            // Row 0 at the bottom, as on a plot.
            let y0 = oy + TOP + CELL_H * (ny - 1 - c.iy as i32);
            let (fill, text, dark) = cell_style(c, p.ripple, range);
            root.draw(&Rectangle::new([(x0, y0), (x0 + CELL_W, y0 + CELL_H)], fill.filled()))?;
            root.draw(&Rectangle::new(
                [(x0, y0), (x0 + CELL_W, y0 + CELL_H)],
                WHITE.stroke_width(1),
            ))?;
            let color = if dark { WHITE } else { BLACK };
            root.draw(&Text::new(
                text,
                (x0 + CELL_W / 2, y0 + CELL_H / 2),
                centred(12.0, &color),
            ))?;
        }
        let right = TextStyle::from(font(12.0)).pos(Pos::new(HPos::Right, VPos::Center));
        for (iy, v) in p.y.values.iter().enumerate() {
            let y = oy + TOP + CELL_H * (ny - 1 - iy as i32) + CELL_H / 2;
            root.draw(&Text::new(v.clone(), (ox + LEFT - 8, y), right.clone()))?;
        }
        for (ix, v) in p.x.values.iter().enumerate() {
            let label = v
                .replace("discontinuous_quadratic", "disc. quad.")
                .replace("continuous_quadratic", "cont. quad.");
            let x = ox + LEFT + CELL_W * ix as i32 + CELL_W / 2;
            root.draw(&Text::new(
                label,
                (x, oy + TOP + CELL_H * ny + 12),
                centred(11.0, &BLACK),
            ))?;
        }
        root.draw(&Text::new(
            p.x.label.to_string(),
            (ox + LEFT + CELL_W * nx / 2, oy + TOP + CELL_H * ny + 34),
            centred(13.0, &BLACK),
        ))?;
        root.draw(&Text::new(
            p.y.label.to_string(),
            (ox + 8, oy + TOP - 12),
            TextStyle::from(font(13.0)).pos(Pos::new(HPos::Left, VPos::Center)),
        ))?;
    }
    root.present()?;
    Ok(())
}
