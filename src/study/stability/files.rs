//! The files of `rollbem study stability`: stability.csv, the heat maps and summary.txt.

use super::{CellResult, StabilityReport, Status};
use crate::error::Error;
use crate::output::charts::heatmap::{self, CellView, Panel};
use std::path::Path;

/// Full-precision number or empty (never NaN in outputs).
fn num(v: Option<f64>) -> String {
    v.filter(|v| v.is_finite()).map_or(String::new(), crate::output::number)
}

/// Column names of stability.csv.
pub const CSV_COLUMNS: [&str; 19] = [
    "slice",
    "method",
    "x_key",
    "x",
    "y_key",
    "y",
    "beta",
    "status",
    "converged",
    "iterations",
    "inner_iterations",
    "residual",
    "solve_s",
    "ripple",
    "creep",
    "slip_regime",
    "iteration_unit",
    "fallbacks",
    "message",
];

fn write_csv(path: &Path, r: &StabilityReport) -> Result<(), Error> {
    let io = |e: &dyn std::fmt::Display| Error::Output {
        path: path.to_path_buf(),
        message: e.to_string(),
    };
    let mut w = csv::Writer::from_path(path).map_err(|e| io(&e))?;
    w.write_record(CSV_COLUMNS).map_err(|e| io(&e))?;
    for c in &r.cells {
        let s = &r.slices[c.slice];
        let m = &r.methods[c.method];
        let solved = !matches!(c.status, Status::OutOfDomain | Status::Error);
        w.write_record([
            s.name.clone(),
            m.label.to_string(),
            format!("{:?}", s.x.key).to_lowercase(),
            s.x.values[c.ix].clone(),
            format!("{:?}", s.y.key).to_lowercase(),
            s.y.values[c.iy].clone(),
            s.beta.map_or(String::new(), |b| b.to_string()),
            c.status.name().to_string(),
            (c.status == Status::Converged).to_string(),
            if solved {
                c.iterations.to_string()
            } else {
                String::new()
            },
            if solved {
                c.inner_iterations.to_string()
            } else {
                String::new()
            },
            num(solved.then_some(c.residual)),
            num(solved.then_some(c.solve_s)),
            num(c.ripple),
            num(c.creep),
            c.regime.map_or(String::new(), |g| g.to_string()),
            m.method.iteration_unit().to_string(),
            c.fallbacks.clone(),
            c.message.clone(),
        ])
        .map_err(|e| io(&e))?;
    }
    w.flush().map_err(|e| io(&e))
}

fn cell_views(r: &StabilityReport, slice: usize, method: usize, ripple: bool) -> Vec<CellView> {
    r.cells
        .iter()
        .filter(|c| c.slice == slice && c.method == method)
        .map(|c| CellView {
            ix: c.ix,
            iy: c.iy,
            status: c.status.drawn(),
            value: if ripple {
                c.ripple
            } else {
                (c.status == Status::Converged).then_some(c.iterations as f64)
            },
        })
        .collect()
}

/// Writes stability.csv, the heat maps under img/ and summary.txt into `dir`.
pub(super) fn write_outputs(dir: &Path, r: &StabilityReport) -> Result<(), Error> {
    write_csv(&dir.join("stability.csv"), r)?;
    let img = dir.join("img");
    std::fs::create_dir_all(&img).map_err(|e| Error::Output {
        path: img.clone(),
        message: e.to_string(),
    })?;
    for (si, s) in r.slices.iter().enumerate() {
        let mut panels = Vec::new();
        for (mi, m) in r.methods.iter().enumerate() {
            let panel = Panel {
                title: format!("{} ({})", m.label, m.method.iteration_unit()),
                x: s.x.drawn(),
                y: s.y.drawn(),
                cells: cell_views(r, si, mi, false),
                ripple: false,
            };
            heatmap::write(&img.join(format!("{}__{}.svg", s.name, m.label)), &s.title, &[&panel])?;
            if s.ripple_maps {
                let rp = Panel {
                    title: format!("{}: ripple / (mu p0)", m.label),
                    cells: cell_views(r, si, mi, true),
                    ripple: true,
                    ..panel.clone()
                };
                heatmap::write(
                    &img.join(format!("{}__{}__ripple.svg", s.name, m.label)),
                    &s.title,
                    &[&rp],
                )?;
            }
            panels.push(panel);
        }
        let refs: Vec<&Panel> = panels.iter().collect();
        heatmap::write(&img.join(format!("{}.svg", s.name)), &s.title, &refs)?;
    }
    std::fs::write(dir.join("summary.txt"), render_summary(r)).map_err(|e| Error::Output {
        path: dir.join("summary.txt"),
        message: e.to_string(),
    })
}

/// Median of a non-empty list (0 for an empty one).
fn median(mut v: Vec<usize>) -> usize {
    v.sort_unstable();
    v.get(v.len() / 2).copied().unwrap_or(0)
}

/// The per-slice, per-method table: converged / in-domain cells, median and max iterations,
/// total solve time, and every failure of the default method.
pub fn render_summary(r: &StabilityReport) -> String {
    let mut t = format!(
        "{:<28} {:<13} {:>10} {:>8} {:>8} {:>10}  failures (x, y)\n",
        "slice", "method", "converged", "median", "max it", "solve [s]"
    );
    for (si, s) in r.slices.iter().enumerate() {
        for (mi, m) in r.methods.iter().enumerate() {
            let cells: Vec<&CellResult> = r.cells.iter().filter(|c| c.slice == si && c.method == mi).collect();
            let domain: Vec<&&CellResult> = cells.iter().filter(|c| c.status != Status::OutOfDomain).collect();
            let ok: Vec<usize> = domain
                .iter()
                .filter(|c| c.status == Status::Converged)
                .map(|c| c.iterations)
                .collect();
            let failures: Vec<String> = domain
                .iter()
                .filter(|c| c.status != Status::Converged)
                .map(|c| {
                    let (x, y) = r.coordinates(c);
                    format!("({x}, {y})")
                })
                .collect();
            let shown = if failures.len() > 6 {
                format!("{} ... ({} cells)", failures[..6].join(" "), failures.len())
            } else {
                failures.join(" ")
            };
            t.push_str(&format!(
                "{:<28} {:<13} {:>4} / {:<3} {:>8} {:>8} {:>10.3}  {}\n",
                s.name,
                m.label,
                ok.len(),
                domain.len(),
                median(ok.clone()),
                ok.iter().max().copied().unwrap_or(0),
                domain.iter().map(|c| c.solve_s).sum::<f64>(),
                shown
            ));
        }
    }
    t.push_str(&format!("wall time {:.1} s\n", r.wall_s));
    t
}
