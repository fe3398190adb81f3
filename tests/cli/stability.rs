//! `rollbem study stability`: the quick map, its outputs and its acceptance criterion.

use crate::common::case_path;
use rollbem::study::stability::{self, Preset, Status};

/// Acceptance on the quick map of Carter's case (the map CI runs): the default method
/// (Newton with line search, Φ) converges in every cell where a steady rolling solution exists;
/// the cells with |Q/μP| ≥ 1, and only those, are marked out of domain and not solved; every
/// failure of another method is a row of stability.csv and is named in summary.txt.
#[test]
fn quick_map_default_converges_everywhere_failures_of_others_are_shown() {
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("stability");
    let r = stability::run(&case_path("carter_051"), &[], Preset::Quick, &out).unwrap();
    let failures: Vec<String> = r
        .default_failures()
        .iter()
        .map(|c| format!("{} {:?} {}", r.slices[c.slice].name, r.coordinates(c), c.message))
        .collect();
    assert!(failures.is_empty(), "default method failed in {failures:?}");
    assert_eq!(r.methods[0].label, "newton");
    for c in &r.cells {
        let s = &r.slices[c.slice];
        let ratio = [(s.x.key, &s.x.values[c.ix]), (s.y.key, &s.y.values[c.iy])]
            .into_iter()
            .chain(s.fixed.iter().map(|(k, v)| (*k, v)))
            .find(|(k, _)| *k == stability::AxisKey::LoadRatio)
            .map(|(_, v)| v.parse::<f64>().unwrap());
        let outside = ratio.is_some_and(|r| r.abs() >= 1.0);
        assert_eq!(
            c.status == Status::OutOfDomain,
            outside,
            "{} {:?}",
            s.name,
            r.coordinates(c)
        );
        if c.status == Status::Converged {
            assert!(c.residual <= 1e-10 && c.ripple.is_some_and(|v| v.is_finite() && v >= 0.0));
        }
    }
    let csv = std::fs::read_to_string(out.join("stability.csv")).unwrap();
    let mut lines = csv.lines();
    assert_eq!(lines.next().unwrap(), stability::CSV_COLUMNS.join(","));
    let rows: Vec<&str> = lines.collect();
    assert_eq!(rows.len(), r.cells.len());
    assert!(!csv.contains("NaN") && !csv.contains("inf"));
    let others_failed = r
        .cells
        .iter()
        .filter(|c| c.method > 0 && c.status == Status::NotConverged)
        .count();
    assert!(others_failed > 0, "the quick map shows no failure of any other method");
    assert_eq!(
        rows.iter().filter(|l| l.contains(",not_converged,")).count(),
        others_failed
    );
    let summary = std::fs::read_to_string(out.join("summary.txt")).unwrap();
    for m in &r.methods {
        assert!(summary.contains(m.label));
    }
    for s in &r.slices {
        assert!(out.join("img").join(format!("{}.svg", s.name)).exists());
        for m in &r.methods {
            let svg = std::fs::read_to_string(out.join("img").join(format!("{}__{}.svg", s.name, m.label))).unwrap();
            assert!(svg.starts_with("<svg") && svg.contains(s.y.key.label()));
            if s.ripple_maps {
                assert!(out
                    .join("img")
                    .join(format!("{}__{}__ripple.svg", s.name, m.label))
                    .exists());
            }
        }
    }
    let leftovers = std::fs::read_dir(dir.path())
        .unwrap()
        .filter(|e| e.as_ref().unwrap().file_name().to_string_lossy().contains("partial"))
        .count();
    assert_eq!(leftovers, 0);
}

/// A base case the study cannot vary β on (a rigid body B) is an input error naming the body.
#[test]
fn rigid_partner_is_rejected_with_a_message() {
    let dir = tempfile::tempdir().unwrap();
    let err = stability::run(
        &case_path("carter_051"),
        &["bodies.B={model: rigid, radius: 100.0}".into()],
        Preset::Quick,
        &dir.path().join("s"),
    )
    .unwrap_err();
    assert!(err.to_string().contains("body B is rigid"), "{err}");
    assert!(!dir.path().join("s").exists());
}
