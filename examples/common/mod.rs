//! What the report programs share: solving a shipped case and printing markdown tables.
//!
//! The reports are also compiled into the `docs` test (tests/docs/), which compares every
//! table they print with the table of the same header in docs/*.md, so a report's functions
//! return [`Table`]s and `main` only prints them.
#![allow(dead_code)]

use rollbem::app::{self, Solved};
use std::path::PathBuf;

/// The repository's root folder.
pub fn root() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
}

/// Where a report draws its figures: `--update-docs` writes docs/img/ (the figures the docs
/// show, tracked by git), `--figures DIR` writes DIR, and by default a folder of the system's
/// temporary folder (`rollbem-figures`), so that running a report to reproduce its numbers
/// leaves the repository as it was. The folder is created.
pub fn figure_dir() -> PathBuf {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let dir = if args.iter().any(|a| a == "--update-docs") {
        root().join("docs/img")
    } else if let Some(i) = args.iter().position(|a| a == "--figures") {
        PathBuf::from(args.get(i + 1).expect("--figures DIR: a folder"))
    } else {
        std::env::temp_dir().join("rollbem-figures")
    };
    std::fs::create_dir_all(&dir).expect("create the figure folder");
    dir
}

/// Path of a shipped case by its stem.
pub fn case_path(name: &str) -> PathBuf {
    root().join("cases").join(format!("{name}.yaml"))
}

/// Solves a shipped case with `key.path=value` overrides; panics with the case's name if it
/// is rejected or does not converge (a report must not print an unconverged number).
pub fn solve<S: AsRef<str>>(name: &str, overrides: &[S]) -> Solved {
    let s = app::solve_case(&case_path(name), overrides).unwrap_or_else(|e| panic!("{name}: {e}"));
    assert!(s.report.converged, "{name} did not converge");
    s
}

/// The stems of every shipped case, sorted.
pub fn shipped_cases() -> Vec<String> {
    let mut names: Vec<String> = std::fs::read_dir(root().join("cases"))
        .expect("cases/ is readable")
        .filter_map(|e| e.ok().map(|e| e.path()))
        .filter(|p| p.extension().is_some_and(|e| e == "yaml"))
        .filter_map(|p| p.file_stem().map(|s| s.to_string_lossy().into_owned()))
        .collect();
    names.sort();
    names
}

/// A markdown table as printed: header cells and rows of cells.
#[derive(Debug, Clone, PartialEq)]
pub struct Table {
    /// Header cells.
    pub header: Vec<String>,
    /// Rows, each as many cells as the header.
    pub rows: Vec<Vec<String>>,
}

impl Table {
    /// An empty table with this header.
    pub fn new(header: &[&str]) -> Self {
        Self {
            header: header.iter().map(|h| h.to_string()).collect(),
            rows: Vec::new(),
        }
    }

    /// Appends a row.
    pub fn push(&mut self, row: Vec<String>) {
        assert_eq!(row.len(), self.header.len(), "row {row:?} of table {:?}", self.header);
        self.rows.push(row);
    }

    /// The table in markdown.
    pub fn markdown(&self) -> String {
        let line = |cells: &[String]| format!("| {} |\n", cells.join(" | "));
        let mut t = line(&self.header);
        t.push_str(&format!("|{}\n", "---|".repeat(self.header.len())));
        for r in &self.rows {
            t.push_str(&line(r));
        }
        t
    }
}

/// A signed number with the typographic minus of the docs (−0.5, +0.5).
pub fn signed(v: f64, decimals: usize) -> String {
    let s = format!("{v:+.decimals$}");
    s.replacen('-', "−", 1)
}

/// The sign of a slip direction as the zone labels write it.
pub fn direction_mark(sign: i8) -> &'static str {
    match sign {
        1 => "+",
        -1 => "−",
        _ => "",
    }
}
