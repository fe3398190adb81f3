//! docs/outputs.md describes every output: each number of summary.json and each column of
//! contact.csv with the unit rollbem writes for it (for the default units mm and N), and every
//! column of the other tables by name.

use crate::markdown::page;
use rollbem::case::Units;
use rollbem::output::units::{CONTACT_CSV_UNITS, SUMMARY_KEYS};

/// The page has a table row `| `name` | unit |`.
fn has_row(text: &str, name: &str, unit: &str) -> bool {
    let wanted = format!("| `{name}` | {unit} |");
    text.lines()
        .any(|l| l.split_whitespace().collect::<Vec<_>>().join(" ").starts_with(&wanted))
}

#[test]
fn every_summary_number_and_contact_column_is_documented_with_its_unit() {
    let text = page("outputs.md");
    let units = Units::default();
    let missing: Vec<String> = SUMMARY_KEYS
        .iter()
        .map(|(key, dim)| (key.to_string(), dim.unit(&units)))
        .chain(
            CONTACT_CSV_UNITS
                .iter()
                .map(|(c, dim)| (c.to_string(), dim.map_or("-".into(), |d| d.unit(&units)))),
        )
        .filter(|(key, unit)| !has_row(&text, key, unit))
        .map(|(key, unit)| format!("| `{key}` | {unit} |"))
        .collect();
    assert!(
        missing.is_empty(),
        "docs/outputs.md lacks the rows\n  {}",
        missing.join("\n  ")
    );
}

#[test]
fn every_column_of_transient_csv_is_documented_with_its_unit() {
    let text = page("outputs.md");
    let units = Units::default();
    let missing: Vec<String> = rollbem::output::transient::TRANSIENT_CSV_UNITS
        .iter()
        .map(|(c, dim)| (c.to_string(), dim.unit(&units)))
        .filter(|(key, unit)| !has_row(&text, key, unit))
        .map(|(key, unit)| format!("| `{key}` | {unit} |"))
        .collect();
    assert!(
        missing.is_empty(),
        "docs/outputs.md lacks the rows\n  {}",
        missing.join("\n  ")
    );
}

#[test]
fn every_column_of_the_other_tables_is_named() {
    let text = page("outputs.md");
    let interior = [
        "x",
        "y",
        "sxx",
        "syy",
        "szz",
        "txy",
        "von_mises",
        "max_shear",
        "ux",
        "uy",
        "status",
    ];
    let missing: Vec<&str> = interior
        .iter()
        .chain(&rollbem::sweep::RESULT_COLUMNS)
        .chain(&rollbem::study::stability::CSV_COLUMNS)
        .copied()
        .filter(|c| !text.contains(&format!("`{c}`")))
        .collect();
    assert!(
        missing.is_empty(),
        "docs/outputs.md does not name the columns {missing:?}"
    );
}
