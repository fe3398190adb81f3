//! The sweep's tables: sweep.csv (or a shard's), written whole or appended row by row, read
//! back leniently on `--resume`, and the sweep.pvd collection of the runs' contact lines.

use super::{RunRow, Runs, RESULT_COLUMNS};
use crate::error::Error;
use crate::output::folder;
use crate::output::vtk::{write_collection, CollectionEntry};
use std::path::{Path, PathBuf};

/// The header of sweep.csv (and of the shard files).
pub(super) fn header(keys: &[String]) -> Vec<String> {
    let mut h: Vec<String> = ["run", "folder", "status"].map(String::from).to_vec();
    h.extend(keys.iter().cloned());
    h.push("message".into());
    h.extend(RESULT_COLUMNS.map(String::from));
    h
}

/// Writes the table (header and rows) atomically.
pub(super) fn write_rows(path: &Path, keys: &[String], rows: &[RunRow]) -> Result<(), Error> {
    let io = |e: &dyn std::fmt::Display| Error::Output {
        path: path.to_path_buf(),
        message: e.to_string(),
    };
    let mut w = csv::Writer::from_writer(Vec::new());
    w.write_record(header(keys)).map_err(|e| io(&e))?;
    for r in rows {
        w.write_record(r.record()).map_err(|e| io(&e))?;
    }
    let bytes = w.into_inner().map_err(|e| io(&e))?;
    Ok(folder::write_file_atomically(path, &bytes)?)
}

/// Appends rows to a table as runs finish, each flushed at once (a killed sweep keeps them).
pub(super) struct Appender {
    path: PathBuf,
    writer: csv::Writer<std::fs::File>,
}

impl Appender {
    pub(super) fn open(path: &Path) -> Result<Self, Error> {
        let file = std::fs::OpenOptions::new()
            .append(true)
            .open(path)
            .map_err(|e| Error::Output {
                path: path.to_path_buf(),
                message: e.to_string(),
            })?;
        Ok(Self {
            path: path.to_path_buf(),
            writer: csv::Writer::from_writer(file),
        })
    }

    pub(super) fn append(&mut self, row: &RunRow) -> Result<(), Error> {
        let io = |e: &dyn std::fmt::Display| Error::Output {
            path: self.path.clone(),
            message: e.to_string(),
        };
        self.writer.write_record(row.record()).map_err(|e| io(&e))?;
        self.writer.flush().map_err(|e| io(&e))
    }
}

/// Rows of a table written by a sweep that may have been killed: a row that does not parse (a
/// torn last line), does not fit the header or does not match its run's values is dropped, so
/// that its run is done again. A missing or unreadable table gives no rows.
pub(super) fn read_rows_leniently(path: &Path, keys: &[String], runs: &Runs) -> Vec<RunRow> {
    let Ok(mut reader) = csv::ReaderBuilder::new().flexible(true).from_path(path) else {
        return Vec::new();
    };
    let expected = header(keys);
    match reader.headers() {
        Ok(h) if h.iter().eq(expected.iter().map(String::as_str)) => {}
        _ => return Vec::new(),
    }
    reader
        .records()
        .filter_map(Result::ok)
        .filter_map(|rec| parse_row(&rec, keys.len(), runs).ok())
        .collect()
}

/// A table row as a [`RunRow`], checked against the sweep: field count, run number in range,
/// folder and values those of that run, a known status.
pub(super) fn parse_row(rec: &csv::StringRecord, n_keys: usize, runs: &Runs) -> Result<RunRow, String> {
    let width = 4 + n_keys + RESULT_COLUMNS.len();
    if rec.len() != width {
        return Err(format!("{} fields where the header has {width}", rec.len()));
    }
    let field = |i: usize| rec.get(i).unwrap_or_default().to_string();
    let run: usize = field(0)
        .parse()
        .map_err(|_| format!("run number `{}` is not a number", field(0)))?;
    if run >= runs.count() {
        return Err(format!(
            "run {run} is not a run of this sweep (it has {})",
            runs.count()
        ));
    }
    let values: Vec<String> = (0..n_keys).map(|i| field(3 + i)).collect();
    if values.iter().enumerate().any(|(k, v)| v != runs.value(run, k)) {
        return Err(format!("the values of run {run} are not those of the sweep"));
    }
    let status = field(2);
    if !matches!(status.as_str(), "ok" | "not_converged" | "failed") {
        return Err(format!("unknown status `{status}` of run {run}"));
    }
    Ok(RunRow {
        run,
        folder: field(1),
        status,
        values,
        message: field(3 + n_keys),
        results: (0..RESULT_COLUMNS.len()).map(|i| field(4 + n_keys + i)).collect(),
        has_vtk: false,
        internal_error: false,
    })
}

/// sweep.pvd: each successful run's contact line as one time step (the run number), with file
/// paths relative to `dir`; written atomically.
pub(super) fn write_pvd(path: &Path, dir: &Path, rows: &[RunRow]) -> Result<(), Error> {
    let entries: Vec<CollectionEntry> = rows
        .iter()
        .filter(|r| r.status == "ok" && (r.has_vtk || dir.join(&r.folder).join("contact.vtu").is_file()))
        .map(|r| {
            let file = Path::new(&r.folder).join("contact.vtu");
            let rel = pathdiff(dir, &file);
            CollectionEntry {
                file: rel,
                timestep: r.run as f64,
                part: 0,
                name: format!("contact {}", r.folder),
            }
        })
        .collect();
    write_collection_atomically(path, &entries)
}

pub(super) fn write_collection_atomically(path: &Path, entries: &[CollectionEntry]) -> Result<(), Error> {
    let tmp = folder::temp_file_path(path);
    write_collection(&tmp, entries)?;
    std::fs::rename(&tmp, path).map_err(|e| {
        let _ = std::fs::remove_file(&tmp);
        Error::Output {
            path: path.to_path_buf(),
            message: e.to_string(),
        }
    })
}

/// `file` as written relative to `dir` (files given relative to dir stay as they are).
fn pathdiff(dir: &Path, file: &Path) -> String {
    file.strip_prefix(dir)
        .unwrap_or(file)
        .to_string_lossy()
        .replace('\\', "/")
}
