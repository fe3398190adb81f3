//! What a run says about itself: the units of every number (console table, summary.json), the
//! version and command line that made it, `rollbem --version`, and CSV numbers that read back
//! exactly.

use crate::common::{rollbem, rollbem_with};
use std::path::Path;

/// Runs `rollbem run` on the fast Carter case with the extra case text `extra` appended and
/// `args` after the case; (stdout, summary.json, contact.csv text).
fn run(dir: &Path, extra: &str, args: &[&str]) -> (String, serde_json::Value, String) {
    let case = dir.join("case.yaml");
    std::fs::write(&case, format!("{}{extra}", crate::common::CARTER_CASE)).unwrap();
    let out = dir.join("out");
    let mut all = vec!["run", case.to_str().unwrap(), "--out", out.to_str().unwrap()];
    all.extend(args);
    let (code, stdout, stderr) = rollbem(&all);
    assert_eq!(code, 0, "{stderr}");
    let summary = serde_json::from_str(&std::fs::read_to_string(out.join("summary.json")).unwrap()).unwrap();
    (
        stdout,
        summary,
        std::fs::read_to_string(out.join("contact.csv")).unwrap(),
    )
}

/// Every number of a JSON value, by path (`.` between keys, `[]` for array items).
fn number_paths(v: &serde_json::Value, path: &str, out: &mut Vec<String>) {
    match v {
        serde_json::Value::Number(_) => out.push(path.to_string()),
        serde_json::Value::Array(items) => items.iter().for_each(|i| number_paths(i, &format!("{path}[]"), out)),
        serde_json::Value::Object(map) => {
            for (k, v) in map {
                let p = if path.is_empty() {
                    k.clone()
                } else {
                    format!("{path}.{k}")
                };
                number_paths(v, &p, out);
            }
        }
        _ => {}
    }
}

/// The numbers of summary.json outside the units block and the resolved case (whose keys
/// cases/README.md documents) that the units block does not name.
fn numbers_without_unit(summary: &serde_json::Value) -> Vec<String> {
    let mut paths = Vec::new();
    for (k, v) in summary.as_object().unwrap() {
        if k != "units" && k != "case" {
            number_paths(v, k, &mut paths);
        }
    }
    paths.sort();
    paths.dedup();
    let units = summary["units"].as_object().expect("a units block");
    paths.into_iter().filter(|p| !units.contains_key(p)).collect()
}

#[test]
fn the_table_and_summary_json_name_the_units_of_the_case() {
    let dir = tempfile::tempdir().unwrap();
    // An interior grid and VTK, so that those keys are there too.
    let interior = "output: {interior: {body: A, x: [-1.0, 1.0, 5], y: [0.1, 0.5, 3]}}\n";
    let (stdout, summary, _) = run(dir.path(), interior, &[]);
    for row in [
        "normal force P [N/mm]",
        "tangential force Q [N/mm]",
        "overlap delta0 [mm]",
        "creepage xi [-]",
        "contact [mm]",
        "max pressure [N/mm^2]",
        "stick zones [mm]",
        "slip zones [mm]",
        "time [s]",
    ] {
        assert!(
            stdout.lines().any(|l| l.trim_start().starts_with(row)),
            "no row `{row}` in\n{stdout}"
        );
    }
    assert!(stdout.contains("spacing 3.9216e-2 mm"), "{stdout}");
    assert!(stdout.contains(" N/mm^2 at ("), "interior peaks with units: {stdout}");
    let units = &summary["units"];
    assert_eq!(units["normal_force"], "N/mm");
    assert_eq!(units["tangential_force"], "N/mm");
    assert_eq!(units["max_pressure"], "N/mm^2");
    assert_eq!(units["overlap"], "mm");
    assert_eq!(units["creep"], "-");
    assert_eq!(units["solver.penalty_normal"], "N/mm^3");
    assert_eq!(units["interior.max_von_mises.value"], "N/mm^2");
    let missing = numbers_without_unit(&summary);
    assert!(
        missing.is_empty(),
        "numbers of summary.json without a unit: {missing:?}"
    );
}

#[test]
fn other_units_follow_the_case() {
    let dir = tempfile::tempdir().unwrap();
    let (stdout, summary, _) = run(
        dir.path(),
        "",
        &["--set", "units.length=in", "--set", "units.force=lbf"],
    );
    assert!(stdout.contains("normal force P [lbf/in]"), "{stdout}");
    assert!(stdout.contains("max pressure [lbf/in^2]"), "{stdout}");
    assert_eq!(summary["units"]["normal_force"], "lbf/in");
    assert_eq!(summary["units"]["contact.x_min"], "in");
}

#[test]
fn summary_json_records_version_command_and_resolved_case() {
    let dir = tempfile::tempdir().unwrap();
    let (_, summary, _) = run(dir.path(), "", &["--set", "contact.friction=0.2"]);
    assert_eq!(summary["version"], env!("CARGO_PKG_VERSION"));
    let command = summary["command"].as_str().unwrap();
    assert!(command.starts_with("rollbem run "), "{command}");
    assert!(command.ends_with(" --set contact.friction=0.2"), "{command}");
    assert!(command.contains("case.yaml --out "), "{command}");
    // The resolved case holds the override.
    assert_eq!(summary["case"]["contact"]["friction"], 0.2);
}

#[test]
fn version_flag_prints_the_version() {
    let (code, stdout, stderr) = rollbem(&["--version"]);
    assert_eq!(code, 0, "{stderr}");
    assert_eq!(stdout.trim(), format!("rollbem {}", env!("CARGO_PKG_VERSION")));
    let (code, short, _) = rollbem_with(None, &[], &["-V"]);
    assert_eq!((code, short), (0, stdout));
}

/// contact.csv: the shortest digits that read back to the same number, no `0e0`, no long
/// `…0000003e2` tails where a plain number is shorter.
#[test]
fn csv_numbers_are_shortest_round_trip() {
    let dir = tempfile::tempdir().unwrap();
    let (_, summary, csv) = run(dir.path(), "", &[]);
    let mut rows = csv
        .lines()
        .skip(1)
        .map(|l| l.split(',').map(str::to_string).collect::<Vec<_>>());
    let first = rows.next().unwrap();
    assert_eq!(first[1], "0", "pressure at the open first node: {first:?}");
    for row in rows.chain(std::iter::once(first)) {
        for cell in row
            .iter()
            .filter(|c| !c.is_empty() && !["open", "stick", "slip"].contains(&c.as_str()))
        {
            let v: f64 = cell.parse().unwrap_or_else(|_| panic!("`{cell}` is no number"));
            let (mantissa, exponent) = cell.split_once('e').unwrap_or((cell, ""));
            let digits = mantissa.trim_start_matches('-').replace('.', "");
            let significant = digits.trim_start_matches('0').len();
            assert!(significant <= 17, "`{cell}`: more digits than an f64 needs");
            // Plain where that is short, an exponent only for very small or large numbers.
            let plain_range = (1e-4..1e16).contains(&v.abs());
            assert_eq!(exponent.is_empty(), plain_range || v == 0.0, "`{cell}`");
        }
    }
    // Read back exactly: the largest pressure equals summary.json's.
    let max_p = csv
        .lines()
        .skip(1)
        .map(|l| l.split(',').nth(1).unwrap().parse::<f64>().unwrap())
        .fold(0.0, f64::max);
    assert_eq!(max_p, summary["max_pressure"].as_f64().unwrap());
}

/// contact.svg: units on every axis, the zones and the rolling direction named, the slip axis
/// with a tick at 0.
#[test]
fn contact_svg_labels_its_axes_zones_and_rolling_direction() {
    let dir = tempfile::tempdir().unwrap();
    run(dir.path(), "", &[]);
    let svg = std::fs::read_to_string(dir.path().join("out/contact.svg")).unwrap();
    for text in [
        "x [mm]",
        "pressure p [N/mm²]",
        "shear q, ±μp [N/mm²]",
        "/ |V| [-]",
        "rolling direction →",
        "leading edge",
        "stick",
        "← slip",
        "P = 1812.45730 N/mm",
    ] {
        assert!(svg.contains(text), "contact.svg lacks `{text}`");
    }
    // Tick labels are the text elements that hold only a number: the slip panel's include 0
    // among negative ones (Carter's slip is ≤ 0).
    let numbers: Vec<f64> = svg
        .split("</text>")
        .filter_map(|t| t.rsplit('>').next())
        .filter_map(|t| t.trim().parse::<f64>().ok())
        .collect();
    assert!(
        numbers.iter().any(|v| *v < 0.0 && v.abs() < 1e-2),
        "no slip ticks: {numbers:?}"
    );
    assert!(numbers.contains(&0.0));
}

/// A run with the tractions along the contact (a roller in a ring bore) writes `forces` and
/// `contact_frame`, every number of them with its unit.
#[test]
fn the_contact_frame_of_a_bore_case_has_its_units() {
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("bore");
    let case = crate::common::case_path("bore_a001_tractive");
    let (code, _, stderr) = rollbem(&["run", case.to_str().unwrap(), "--out", out.to_str().unwrap()]);
    assert_eq!(code, 0, "{stderr}");
    let summary: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(out.join("summary.json")).unwrap()).unwrap();
    assert_eq!(summary["traction_axes"], "contact");
    assert!(summary["contact_frame"]["normal_angle"]
        .as_array()
        .is_some_and(|a| !a.is_empty()));
    let missing = numbers_without_unit(&summary);
    assert!(
        missing.is_empty(),
        "numbers of summary.json without a unit: {missing:?}"
    );
}
