//! The files of `rollbem study accuracy`: accuracy.csv, accuracy.json and the chart.

use super::{AccuracyReport, SceneModel};
use crate::error::Error;
use crate::output::charts::accuracy::{self as chart, Curve, Point};
use std::path::Path;

/// Writes accuracy.csv, accuracy.svg and accuracy.json into `dir` (through a temporary folder,
/// renamed on success: [`crate::output::write_atomically`]).
pub fn write(dir: &Path, report: &AccuracyReport, title: &str) -> Result<(), Error> {
    let io = |path: &Path, e: &dyn std::fmt::Display| Error::Output {
        path: path.to_path_buf(),
        message: e.to_string(),
    };
    crate::output::write_atomically(dir, crate::output::folder::Kind::StudyAccuracy, |tmp| {
        let csv_path = tmp.join("accuracy.csv");
        let mut w = csv::Writer::from_path(&csv_path).map_err(|e| io(&csv_path, &e))?;
        w.write_record([
            "model",
            "contact_elements",
            "tolerance",
            "boundary_elements",
            "converged",
            "iterations",
            "error_rms",
            "error_max",
            "creep_error",
            "build_s",
            "solve_s",
            "total_s",
            "message",
        ])
        .map_err(|e| io(&csv_path, &e))?;
        let num = |v: f64| {
            if v.is_finite() {
                crate::output::number(v)
            } else {
                String::new()
            }
        };
        for r in &report.rows {
            w.write_record([
                r.model.name().to_string(),
                r.contact_elements.to_string(),
                r.tolerance.map_or(String::new(), num),
                r.boundary_elements.to_string(),
                r.converged.to_string(),
                r.iterations.to_string(),
                num(r.error),
                num(r.error_max),
                r.creep_error.map_or(String::new(), num),
                num(r.build_s),
                num(r.solve_s),
                num(r.total_s),
                r.message.clone(),
            ])
            .map_err(|e| io(&csv_path, &e))?;
        }
        w.flush().map_err(|e| io(&csv_path, &e))?;
        drop(w);
        let json_path = tmp.join("accuracy.json");
        let json = serde_json::to_string_pretty(&report).map_err(|e| io(&json_path, &e))?;
        std::fs::write(&json_path, json).map_err(|e| io(&json_path, &e))?;
        write_chart(&tmp.join("accuracy.svg"), report, title)
    })
}

/// The points (time, error) of the converged runs that no other run beats in both.
pub fn pareto_front(report: &AccuracyReport) -> Vec<(f64, f64)> {
    let mut pts: Vec<(f64, f64)> = report
        .rows
        .iter()
        .filter(|r| r.converged && r.error.is_finite() && r.total_s > 0.0)
        .map(|r| (r.total_s, r.error))
        .collect();
    pts.sort_by(|a, b| a.0.total_cmp(&b.0));
    let mut front: Vec<(f64, f64)> = Vec::new();
    for p in pts {
        if front.last().is_none_or(|l| p.1 < l.1) {
            front.push(p);
        }
    }
    front
}

/// The error–time chart: the converged runs of each model with a positive error and time.
fn write_chart(path: &Path, report: &AccuracyReport, title: &str) -> Result<(), Error> {
    let mut curves: Vec<Curve> = SceneModel::ALL
        .iter()
        .map(|&model| Curve {
            name: model.name().to_string(),
            points: report
                .rows
                .iter()
                .filter(|r| r.model == model && r.converged && r.error.is_finite() && r.error > 0.0 && r.total_s > 0.0)
                .map(|r| Point {
                    time_s: r.total_s,
                    error: r.error,
                    label: r.contact_elements.to_string(),
                })
                .collect(),
        })
        .collect();
    if let Some((name, points)) = &report.reference_curve {
        curves.push(Curve {
            name: name.clone(),
            points: points
                .iter()
                .filter(|(t, e, _)| *t > 0.0 && *e > 0.0)
                .map(|(t, e, label)| Point {
                    time_s: *t,
                    error: *e,
                    label: label.clone(),
                })
                .collect(),
        });
    }
    let short = report.reference.split(':').next().unwrap_or(&report.reference);
    let caption = format!("error against {short}");
    chart::write(path, title, &caption, &curves, &pareto_front(report))
}

/// A measured curve for the chart: its legend and its points (time [s], error, label).
pub type ReferenceCurve = (String, Vec<(f64, f64, String)>);

/// Reads a measured error–time curve for the chart (`--reference-curve FILE`): a CSV file with
/// the columns `elements,rms_shear_error,time_s` (other names allowed, that order), `#` lines
/// for its provenance. The legend is the first `#` line's text up to its first parenthesis or
/// comma (else the file's name). docs/data/contact_carter2d.csv is CONTACT's curve on
/// cases/carter2d_contact.yaml.
pub fn read_reference_curve(path: &Path) -> Result<ReferenceCurve, Error> {
    let bad = |message: String| Error::Study {
        message: format!("--reference-curve {}: {message}", path.display()),
    };
    let text = std::fs::read_to_string(path).map_err(|e| bad(e.to_string()))?;
    let legend = text
        .lines()
        .find_map(|l| l.strip_prefix('#'))
        .map(|l| l.split(['(', ',']).next().unwrap_or(l).trim().to_string())
        .filter(|l| !l.is_empty())
        .unwrap_or_else(|| {
            path.file_stem()
                .map_or("reference".into(), |s| s.to_string_lossy().into_owned())
        });
    let mut points = Vec::new();
    for (k, line) in text
        .lines()
        .enumerate()
        .filter(|(_, l)| !l.starts_with('#') && !l.trim().is_empty())
    {
        let f: Vec<&str> = line.split(',').map(str::trim).collect();
        let parsed = (f.len() == 3).then(|| (f[1].parse::<f64>(), f[2].parse::<f64>()));
        match parsed {
            Some((Ok(e), Ok(t))) if e.is_finite() && t.is_finite() && e > 0.0 && t > 0.0 => {
                points.push((t, e, f[0].to_string()))
            }
            // The header line.
            Some((Err(_), Err(_))) if points.is_empty() => {}
            _ => {
                return Err(bad(format!(
                    "line {}: expected `label,error,time_s` with a positive error and time, found `{line}`",
                    k + 1
                )))
            }
        }
    }
    if points.is_empty() {
        return Err(bad("no points".into()));
    }
    Ok((legend, points))
}
