//! Reading the tables and quoted numbers of docs/*.md, and comparing them with what a report
//! prints.
//!
//! **Tolerance.** A page and a report print the same quantity rounded, possibly to different
//! digits (0.037 against +0.0368). Two roundings of one value differ by at most half a unit of
//! the last printed digit of each, so a number of the page and the report's number match when
//! they differ by no more than the sum of those half units (an integer has no half unit:
//! iteration counts and node counts must be equal). Text between the numbers must be equal.

use std::path::PathBuf;

/// The text of a page of docs/.
pub fn page(name: &str) -> String {
    let path = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("docs").join(name);
    std::fs::read_to_string(&path).unwrap_or_else(|e| panic!("{}: {e}", path.display()))
}

/// A table as printed: header cells and rows (the report's `Table`, by value).
pub struct Printed<'a> {
    /// Header cells.
    pub header: &'a [String],
    /// Rows of cells.
    pub rows: &'a [Vec<String>],
}

/// Collapses runs of white space, so that `|  |` and `| |` compare equal.
fn squeeze(s: &str) -> String {
    s.split_whitespace().collect::<Vec<_>>().join(" ")
}

/// The rows of the table of `page` whose header line is `| h1 | h2 | … |`, split into cells
/// on ` | ` (header cells may contain `|`, row cells do not, except escaped `\|`).
pub fn table(page: &str, header: &[String]) -> Vec<Vec<String>> {
    let lines: Vec<&str> = page.lines().collect();
    let (start, end) = rows_span(&lines, header);
    lines[start..end]
        .iter()
        .map(|l| {
            let inner = l.trim().trim_start_matches('|').trim_end_matches('|');
            inner
                .replace(r"\|", "\u{1}")
                .split('|')
                .map(|c| c.trim().replace('\u{1}', r"\|"))
                .collect()
        })
        .collect()
}

/// The lines [start, end) of the rows of the table whose header line is `| h1 | h2 | … |`
/// (after its header and separator lines).
fn rows_span(lines: &[&str], header: &[String]) -> (usize, usize) {
    let wanted = squeeze(&format!("| {} |", header.join(" | ")));
    let at = lines
        .iter()
        .position(|l| squeeze(l) == wanted)
        .unwrap_or_else(|| panic!("no table with the header\n  {wanted}\nin the page"));
    let rows = lines[at + 2..]
        .iter()
        .take_while(|l| l.trim_start().starts_with('|'))
        .count();
    (at + 2, at + 2 + rows)
}

/// A number as printed, with the half unit of its last digit (0 for an integer).
#[derive(Debug, Clone, Copy)]
struct Number {
    value: f64,
    half_unit: f64,
}

/// Splits a cell into its text (numbers replaced by `#`) and its numbers. Signs (+, −, -)
/// belong to the number; `e` exponents are read.
fn tokens(cell: &str) -> (String, Vec<Number>) {
    let cell = cell.replace('−', "-");
    let chars: Vec<char> = cell.chars().collect();
    let (mut text, mut numbers) = (String::new(), Vec::new());
    let mut i = 0;
    while i < chars.len() {
        let starts_number = |k: usize| k < chars.len() && chars[k].is_ascii_digit();
        let signed = (chars[i] == '-' || chars[i] == '+') && starts_number(i + 1);
        if !(chars[i].is_ascii_digit() || signed) {
            text.push(chars[i]);
            i += 1;
            continue;
        }
        let start = i;
        i += 1;
        while i < chars.len() && chars[i].is_ascii_digit() {
            i += 1;
        }
        let mut decimals: i32 = 0;
        let mut integer = true;
        if i + 1 < chars.len() && chars[i] == '.' && chars[i + 1].is_ascii_digit() {
            integer = false;
            i += 1;
            while i < chars.len() && chars[i].is_ascii_digit() {
                i += 1;
                decimals += 1;
            }
        }
        let mut exponent: i32 = 0;
        if i + 1 < chars.len() && chars[i] == 'e' {
            let mut k = i + 1;
            if chars[k] == '-' || chars[k] == '+' {
                k += 1;
            }
            if starts_number(k) {
                let e_start = i + 1;
                i = k;
                while i < chars.len() && chars[i].is_ascii_digit() {
                    i += 1;
                }
                exponent = chars[e_start..i]
                    .iter()
                    .collect::<String>()
                    .parse()
                    .expect("an exponent");
                integer = false;
            }
        }
        let literal: String = chars[start..i].iter().collect();
        let value: f64 = literal.parse().unwrap_or_else(|_| panic!("a number: {literal}"));
        let half_unit = if integer {
            0.0
        } else {
            0.5 * 10f64.powi(exponent - decimals)
        };
        text.push('#');
        numbers.push(Number { value, half_unit });
    }
    (squeeze(&text), numbers)
}

/// Whether a cell of the page and a printed cell say the same (module docs); `None` when they
/// do, else why not.
pub fn cell_mismatch(page_cell: &str, printed: &str) -> Option<String> {
    let (t0, n0) = tokens(page_cell);
    let (t1, n1) = tokens(printed);
    if t0 != t1 || n0.len() != n1.len() {
        return Some(format!("`{page_cell}` (page) against `{printed}` (report)"));
    }
    for (a, b) in n0.iter().zip(&n1) {
        let tolerance = a.half_unit + b.half_unit + 1e-12 * a.value.abs();
        if (a.value - b.value).abs() > tolerance {
            return Some(format!(
                "`{page_cell}` (page) against `{printed}` (report): {} differs from {} by more than {tolerance:e}",
                a.value, b.value
            ));
        }
    }
    None
}

/// How the rows of a printed table must appear on the page.
pub enum Rows {
    /// The page has every printed row, and no other, in the same order.
    All,
    /// The page shows a selection of the printed rows, in order: each page row equals some
    /// printed row, matched on the first `key` cells (compared as cells).
    Selection {
        /// Cells that identify a row.
        key: usize,
    },
    /// The report printed a selection of the page's rows (the cheap ones of a long table):
    /// each printed row equals the page row with the same first `key` cells.
    Printed {
        /// Cells that identify a row.
        key: usize,
    },
}

/// Compares the table of `page` with the same header against a printed table; the columns
/// named in `skip` (times, which depend on the machine) are not compared, and a cell of a
/// `noise` column (a difference at round-off level) passes when it is below `noise_limit` on
/// both sides, else it is compared like any other.
///
/// With `ROLLBEM_DOCS_WRITE=1` a table whose rows the report prints in full ([`Rows::All`]) is
/// written into the page instead (the `skip` columns, times measured on another occasion, kept
/// from the page's row of the same first cell where there is one), so that
/// `ROLLBEM_DOCS_WRITE=1 cargo test --release --test docs` regenerates every such table in
/// docs/ (a new shipped case adds its rows); the other kinds are compared as always.
pub fn assert_table(page_name: &str, printed: Printed, rows: Rows, skip: &[&str], noise: (&[&str], f64)) {
    if matches!(rows, Rows::All) && std::env::var_os(WRITE_ENV).is_some_and(|v| v == "1") {
        write_table(page_name, &printed, skip, noise);
        return;
    }
    let page = &self::page(page_name);
    let on_page = table(page, printed.header);
    let compared: Vec<usize> = (0..printed.header.len())
        .filter(|&j| !skip.contains(&printed.header[j].as_str()))
        .collect();
    let (noise_columns, noise_limit) = noise;
    let mut failures = Vec::new();
    let compare = |page_row: &[String], row: &[String], failures: &mut Vec<String>| {
        for &j in &compared {
            let (p, r) = (&page_row[j], &row[j]);
            let below = |c: &str| tokens(c).1.iter().all(|n| n.value.abs() < noise_limit);
            let noise = noise_columns.contains(&printed.header[j].as_str()) && below(p) && below(r);
            if noise {
                continue;
            }
            if let Some(why) = cell_mismatch(p, r) {
                failures.push(format!("row {:?}, column `{}`: {why}", row[0], printed.header[j]));
            }
        }
    };
    match rows {
        Rows::All => {
            assert_eq!(
                on_page.len(),
                printed.rows.len(),
                "docs/{page_name}: the page's table {:?} has {} rows, the report prints {}: first column on the page {:?}, printed {:?}\n{REGENERATE}",
                printed.header,
                on_page.len(),
                printed.rows.len(),
                on_page.iter().map(|r| r[0].clone()).collect::<Vec<_>>(),
                printed.rows.iter().map(|r| r[0].clone()).collect::<Vec<_>>()
            );
            for (page_row, row) in on_page.iter().zip(printed.rows) {
                compare(page_row, row, &mut failures);
            }
        }
        Rows::Selection { key } => {
            let mut from = 0;
            for page_row in &on_page {
                let found = printed.rows[from..]
                    .iter()
                    .position(|row| (0..key).all(|j| cell_mismatch(&page_row[j], &row[j]).is_none()));
                match found {
                    Some(k) => {
                        compare(page_row, &printed.rows[from + k], &mut failures);
                        from += k + 1;
                    }
                    None => failures.push(format!("page row {page_row:?} is not printed by the report (in order)")),
                }
            }
        }
        Rows::Printed { key } => {
            for row in printed.rows {
                let found = on_page
                    .iter()
                    .find(|page_row| (0..key).all(|j| cell_mismatch(&page_row[j], &row[j]).is_none()));
                match found {
                    Some(page_row) => compare(page_row, row, &mut failures),
                    None => failures.push(format!("printed row {row:?} is not on the page")),
                }
            }
        }
    }
    assert!(
        failures.is_empty(),
        "docs/{page_name}: the page and the report disagree ({} cells):\n  {}\n{REGENERATE}",
        failures.len(),
        failures.join("\n  ")
    );
}

/// The variable that turns [`assert_table`] into the docs' writer.
pub const WRITE_ENV: &str = "ROLLBEM_DOCS_WRITE";

/// What a failure says to do when the report is right and the page is old.
const REGENERATE: &str = "if the report is right, regenerate the docs' tables: \
    ROLLBEM_DOCS_WRITE=1 cargo test --release --test docs (then review `git diff docs/`)";

/// Replaces the rows of the table of docs/`page_name` whose header is `printed`'s with the
/// printed rows, the cells of the `skip` columns kept from the page's row of the same first
/// cell (in the same place, or else the first), and so are the cells of the `noise` columns
/// that the comparison passes as round-off; the rest of the page stays as it was.
fn write_table(page_name: &str, printed: &Printed, skip: &[&str], noise: (&[&str], f64)) {
    let (noise_columns, noise_limit) = noise;
    let below = |c: &str| tokens(c).1.iter().all(|n| n.value.abs() < noise_limit);
    let path = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("docs").join(page_name);
    let text = page(page_name);
    let lines: Vec<&str> = text.lines().collect();
    let (start, end) = rows_span(&lines, printed.header);
    let mut out: Vec<String> = lines[..start].iter().map(|l| l.to_string()).collect();
    let on_page = table(&text, printed.header);
    for (i, row) in printed.rows.iter().enumerate() {
        // The row in the same place if it is the same case, else the first of that name.
        let same = |p: &&Vec<String>| p[0] == row[0];
        let old = on_page.get(i).filter(same).or_else(|| on_page.iter().find(same));
        let cells: Vec<&str> = (0..row.len())
            .map(|j| {
                let name = printed.header[j].as_str();
                match old {
                    Some(p) if skip.contains(&name) => p[j].as_str(),
                    // Round-off that the comparison passes is not churned either.
                    Some(p) if noise_columns.contains(&name) && below(&p[j]) && below(&row[j]) => p[j].as_str(),
                    _ => row[j].as_str(),
                }
            })
            .collect();
        out.push(format!("| {} |", cells.join(" | ")));
    }
    out.extend(lines[end..].iter().map(|l| l.to_string()));
    let mut written = out.join("\n");
    if text.ends_with('\n') {
        written.push('\n');
    }
    if written != text {
        std::fs::write(&path, written).unwrap_or_else(|e| panic!("{}: {e}", path.display()));
        eprintln!("wrote the table {:?} of docs/{page_name}", printed.header[0]);
    }
}

/// The number printed right after `before` on the page (the first occurrence).
pub fn number_after(page: &str, before: &str) -> String {
    let at = page
        .find(before)
        .unwrap_or_else(|| panic!("the page does not say `{before}`"))
        + before.len();
    let rest = page[at..].trim_start();
    let end = rest
        .find(|c: char| !(c.is_ascii_digit() || "+-−.e".contains(c)))
        .unwrap_or(rest.len());
    rest[..end].trim_end_matches(['.', 'e']).to_string()
}

#[test]
fn cells_match_within_their_printed_digits() {
    assert!(cell_mismatch("0.037", "+0.0368").is_none());
    assert!(cell_mismatch("−3.424", "-3.4236").is_none());
    assert!(cell_mismatch("0", "-0.0000").is_none());
    assert!(cell_mismatch("7.1e-4", "7.0e-4").is_none());
    assert!(cell_mismatch("slip−[-0.996, -0.961]", "slip−[-0.996, -0.961]").is_none());
    assert!(cell_mismatch("0.037", "+0.0390").is_some());
    assert!(cell_mismatch("5", "6").is_some());
    assert!(cell_mismatch("stick[0.1, 0.2]", "slip[0.1, 0.2]").is_some());
    assert!(cell_mismatch("2.2 % (a); 0.075 % b", "2.2 % (a); 0.075 % b").is_none());
    assert_eq!(number_after("HBEM slip 0.80 % in", "HBEM slip"), "0.80");
}
