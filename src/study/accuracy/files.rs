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
    let curves: Vec<Curve> = SceneModel::ALL
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
    let short = report.reference.split(':').next().unwrap_or(&report.reference);
    let caption = format!("error against {short}");
    chart::write(path, title, &caption, &curves, &pareto_front(report))
}
