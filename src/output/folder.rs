//! Output folders: what rollbem may write, replace and remove.
//!
//! The rule: **rollbem never deletes or overwrites a file it did not write.** Every folder of
//! results carries a manifest, `.rollbem-manifest` (JSON: the kind of result and every file and
//! sub-folder written), so that a later run can tell its own earlier result from anything else:
//!
//! * a new or empty folder is written;
//! * a folder holding an earlier rollbem result of the same kind, and nothing else, is replaced
//!   atomically: the new result is written into a hidden sibling `.NAME.partial-PID`, the old
//!   one is renamed to `.NAME.old-PID`, the new one renamed onto NAME, and the old one removed
//!   file by file as its manifest lists them;
//! * any other folder is refused before anything is solved ([`FolderError::Foreign`],
//!   [`FolderError::OtherKind`]; exit code 1), naming the folder and the first entry rollbem
//!   did not write.
//!
//! A sweep folder is written in place, run by run, and its manifest lists no files: it owns the
//! names of a sweep's layout ([`sweep_owns`]): `run_NNNN/` folders (each a run result with its
//! own manifest), `sweep.csv`, `sweep.json`, `sweep.pvd`, the shard files, and the hidden lock
//! and temporary names below. Anything else in it is foreign.
//!
//! Writers lock a folder before they solve: an advisory lock (fs4: `flock` on Unix,
//! `LockFileEx` on Windows) on a hidden sibling `.NAME.rollbem-lock`, taken without waiting, so a
//! second writer gets [`FolderError::Busy`] at once. Shards of one sweep share the folder lock
//! ([`Access::Shared`]) and each holds its own shard lock inside the folder. A temporary folder
//! left by a killed writer (`.NAME.partial-PID`, `.NAME.old-PID`, recognised by the manifest
//! rollbem writes into it first) is removed by the next writer that holds the lock.
//!
//! For the tests, `ROLLBEM_TEST_FAULT=panic` or `=abort` (optionally `panic@NAME`, `abort@NAME`
//! for the folder NAME only) makes the writer panic or abort after the results are written into
//! the temporary folder and before it is renamed into place; nothing else reads it.

use crate::error::Error;
use serde::{Deserialize, Serialize};
use std::fs::{self, File, OpenOptions};
use std::io;
use std::path::{Component, Path, PathBuf};
use std::sync::Mutex;

/// File name of the manifest in every folder rollbem writes.
pub const MANIFEST: &str = ".rollbem-manifest";

/// Longest file or folder name most file systems accept [bytes].
pub const MAX_NAME_BYTES: usize = 255;

/// Longest name of an output folder [bytes]: [`MAX_NAME_BYTES`] less what the temporary
/// sibling's name adds (`.NAME.partial-PID`: 10 bytes and a process id of up to 10 digits).
pub const MAX_FOLDER_NAME_BYTES: usize = MAX_NAME_BYTES - 20;

/// Longest path rollbem will create [bytes] (Linux's PATH_MAX, 4096, less the terminator).
pub const MAX_PATH_BYTES: usize = 4095;

/// Environment variable of the fault injection used by the tests (see the module docs).
pub const FAULT_ENV: &str = "ROLLBEM_TEST_FAULT";

/// What a folder of results holds.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
pub enum Kind {
    /// The outputs of `rollbem run` (summary.json, contact.csv, ...).
    #[serde(rename = "run")]
    Run,
    /// A sweep (`rollbem sweep`): run folders, sweep.csv, shard files.
    #[serde(rename = "sweep")]
    Sweep,
    /// `rollbem study accuracy`.
    #[serde(rename = "study accuracy")]
    StudyAccuracy,
    /// `rollbem study stability`.
    #[serde(rename = "study stability")]
    StudyStability,
}

impl Kind {
    /// The name used in the manifest and in messages.
    pub fn name(self) -> &'static str {
        match self {
            Kind::Run => "run",
            Kind::Sweep => "sweep",
            Kind::StudyAccuracy => "study accuracy",
            Kind::StudyStability => "study stability",
        }
    }
}

/// The manifest `.rollbem-manifest` of a folder rollbem wrote.
#[derive(Debug, Clone, Serialize, Deserialize)]
pub struct Manifest {
    /// `rollbem VERSION`.
    pub written_by: String,
    /// What the folder holds.
    pub kind: Kind,
    /// True while the folder is a temporary one being filled (its files are not listed yet).
    #[serde(default)]
    pub partial: bool,
    /// Files and sub-folders written, relative to the folder, `/`-separated; sub-folders end in
    /// `/`. Empty for sweep folders, which own names by their layout ([`sweep_owns`]).
    #[serde(default)]
    pub files: Vec<String>,
}

impl Manifest {
    fn new(kind: Kind, partial: bool, files: Vec<String>) -> Self {
        Self {
            written_by: format!("rollbem {}", env!("CARGO_PKG_VERSION")),
            kind,
            partial,
            files,
        }
    }
}

/// Why a folder cannot be written.
#[derive(Debug, thiserror::Error)]
pub enum FolderError {
    /// The path cannot name a folder (NUL byte, overlong name, the root).
    #[error("output folder `{path}` (--out, or output.dir of the case): {reason}; nothing was written")]
    BadPath {
        /// The path as given (lossy).
        path: String,
        /// What is wrong with it.
        reason: String,
    },
    /// The folder holds something rollbem did not write.
    #[error(
        "{dir} holds `{entry}`, which rollbem did not write. rollbem never deletes or overwrites \
         files it did not write, so it leaves this folder as it is and writes nothing: give an \
         empty or new folder (--out NEW_FOLDER or output.dir), or move `{entry}` away"
    )]
    Foreign {
        /// The output folder.
        dir: PathBuf,
        /// The first entry (relative to `dir`) that rollbem did not write.
        entry: String,
    },
    /// The folder holds a rollbem result of another kind.
    #[error(
        "{dir} holds the result of a rollbem {found}; a {kind} does not replace it (that could \
         discard hours of computing by a typo). Give another folder (--out), or remove it yourself"
    )]
    OtherKind {
        /// The output folder.
        dir: PathBuf,
        /// What it holds.
        found: &'static str,
        /// What was to be written.
        kind: &'static str,
    },
    /// Another process is writing the folder.
    #[error(
        "{dir} is being written by another rollbem process (it holds the lock {lock}); wait for \
         it to finish or give another folder (--out). Nothing was solved or written"
    )]
    Busy {
        /// The output folder.
        dir: PathBuf,
        /// The lock file.
        lock: PathBuf,
    },
    /// The path exists and is not a folder.
    #[error("{path} exists and is not a folder; give a folder for the results (--out)")]
    NotAFolder {
        /// The path.
        path: PathBuf,
    },
    /// A file-system operation failed.
    #[error("{path}: {message}")]
    Io {
        /// File or folder.
        path: PathBuf,
        /// What failed.
        message: String,
    },
}

fn io_err(path: &Path, e: impl std::fmt::Display) -> FolderError {
    FolderError::Io {
        path: path.to_path_buf(),
        message: e.to_string(),
    }
}

// ---------------------------------------------------------------------------------------------
// Paths

/// Refuses a path that cannot name a folder on common file systems: a NUL byte, a name longer
/// than [`MAX_NAME_BYTES`], a path longer than [`MAX_PATH_BYTES`], an empty path. Checked before
/// anything is created, so a bad `output.dir` leaves no folder behind.
pub fn check_path(dir: &Path) -> Result<(), FolderError> {
    // Shown with control characters escaped and long paths cut.
    let shown: String = dir.to_string_lossy().escape_debug().collect();
    let bad = |reason: String| FolderError::BadPath {
        path: if shown.chars().count() > 80 {
            format!("{}…", shown.chars().take(80).collect::<String>())
        } else {
            shown.clone()
        },
        reason,
    };
    let bytes = dir.as_os_str().as_encoded_bytes();
    if bytes.is_empty() {
        return Err(bad("the path is empty".into()));
    }
    if bytes.contains(&0) {
        return Err(bad("it contains a NUL character, which no file name may hold".into()));
    }
    if bytes.len() > MAX_PATH_BYTES {
        return Err(bad(format!(
            "the path is {} bytes long; file systems allow {MAX_PATH_BYTES}",
            bytes.len()
        )));
    }
    for c in dir.components() {
        if let Component::Normal(name) = c {
            let n = name.as_encoded_bytes().len();
            if n > MAX_NAME_BYTES {
                return Err(bad(format!(
                    "a folder name is {n} bytes long; file systems allow {MAX_NAME_BYTES}"
                )));
            }
        }
    }
    if let Some(name) = dir.file_name() {
        let n = name.as_encoded_bytes().len();
        if n > MAX_FOLDER_NAME_BYTES {
            return Err(bad(format!(
                "the folder name is {n} bytes long; rollbem allows {MAX_FOLDER_NAME_BYTES} (file systems \
                 allow {MAX_NAME_BYTES}, and the name of the temporary folder it writes first is 20 longer)"
            )));
        }
    }
    Ok(())
}

/// Removes `.` and `name/..` pairs lexically.
fn normalize(path: &Path) -> PathBuf {
    let mut out = PathBuf::new();
    for c in path.components() {
        match c {
            Component::CurDir => {}
            Component::ParentDir if matches!(out.components().next_back(), Some(Component::Normal(_))) => {
                out.pop();
            }
            other => out.push(other),
        }
    }
    out
}

/// The absolute path of the folder `dir` names: the longest part that exists resolved as the
/// operating system resolves it (symbolic links and `..`, so `--out link` writes where the link
/// points), the rest (`..` and `.` included) taken lexically.
pub fn resolve(dir: &Path) -> Result<PathBuf, FolderError> {
    check_path(dir)?;
    let abs = std::path::absolute(dir).map_err(|e| io_err(dir, e))?;
    let existing = abs
        .ancestors()
        .find(|a| fs::symlink_metadata(a).is_ok())
        .unwrap_or(Path::new("/"));
    let rest = abs.strip_prefix(existing).unwrap_or(Path::new(""));
    let base = fs::canonicalize(existing).unwrap_or_else(|_| existing.to_path_buf());
    let target = normalize(&base.join(rest));
    if target.file_name().is_none() || target.parent().is_none() {
        return Err(FolderError::BadPath {
            path: dir.to_string_lossy().into_owned(),
            reason: "the root folder cannot hold results".into(),
        });
    }
    Ok(target)
}

fn name_of(target: &Path) -> String {
    target
        .file_name()
        .map_or_else(String::new, |n| n.to_string_lossy().into_owned())
}

fn parent_of(target: &Path) -> &Path {
    target.parent().unwrap_or(Path::new("/"))
}

/// The hidden sibling that locks the folder `target`: `.NAME.rollbem-lock`.
pub fn lock_path(target: &Path) -> PathBuf {
    parent_of(target).join(format!(".{}.rollbem-lock", name_of(target)))
}

/// The temporary sibling a writer fills: `.NAME.partial-PID`.
fn partial_path(target: &Path) -> PathBuf {
    parent_of(target).join(format!(".{}.partial-{}", name_of(target), std::process::id()))
}

/// Where the replaced result waits for removal: `.NAME.old-PID`.
fn old_path(target: &Path) -> PathBuf {
    parent_of(target).join(format!(".{}.old-{}", name_of(target), std::process::id()))
}

/// Creates the missing ancestors of `dir` (and `dir`), returning those it created, outermost
/// first, so that a writer that fails can remove them again.
fn create_dirs(dir: &Path) -> Result<Vec<PathBuf>, FolderError> {
    let mut missing = Vec::new();
    let mut p = dir;
    while fs::symlink_metadata(p).is_err() {
        missing.push(p.to_path_buf());
        match p.parent() {
            Some(parent) => p = parent,
            None => break,
        }
    }
    let mut created = Vec::new();
    for d in missing.into_iter().rev() {
        match fs::create_dir(&d) {
            Ok(()) => created.push(d),
            Err(e) if e.kind() == io::ErrorKind::AlreadyExists => {}
            Err(e) => {
                remove_empty_dirs(&created);
                return Err(io_err(&d, e));
            }
        }
    }
    Ok(created)
}

/// Removes folders this process created, innermost first, if they are (still) empty.
fn remove_empty_dirs(created: &[PathBuf]) {
    for d in created.iter().rev() {
        let _ = fs::remove_dir(d);
    }
}

// ---------------------------------------------------------------------------------------------
// Locks

/// Exclusive (one writer) or shared (the shards of one sweep) access to a folder.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Access {
    /// One writer.
    Exclusive,
    /// Several writers that each hold a finer lock (sweep shards).
    Shared,
}

/// An advisory lock on a lock file, released when dropped. An exclusive holder removes the lock
/// file before releasing it; a process that opened the file before that finds, once it holds the
/// lock, that the path no longer names its file, and starts again.
#[derive(Debug)]
pub struct FileLock {
    file: File,
    path: PathBuf,
    remove: bool,
}

impl FileLock {
    /// Takes the lock on `path` without waiting: `Ok(None)` when another process holds it.
    pub fn try_acquire(path: &Path, access: Access) -> Result<Option<FileLock>, FolderError> {
        for _ in 0..16 {
            let file = OpenOptions::new()
                .read(true)
                .write(true)
                .create(true)
                .truncate(false)
                .open(path)
                .map_err(|e| io_err(path, e))?;
            // Fully qualified: std's inherent File::try_lock (Rust 1.89) has another error type.
            let taken = match access {
                Access::Exclusive => fs4::FileExt::try_lock(&file),
                Access::Shared => fs4::FileExt::try_lock_shared(&file),
            };
            match taken {
                Ok(()) => {}
                Err(fs4::TryLockError::WouldBlock) => return Ok(None),
                Err(fs4::TryLockError::Error(e)) => return Err(io_err(path, e)),
            }
            if names_file(path, &file) {
                return Ok(Some(FileLock {
                    file,
                    path: path.to_path_buf(),
                    remove: access == Access::Exclusive,
                }));
            }
        }
        Err(io_err(path, "the lock file keeps being replaced by other processes"))
    }

    /// The lock file.
    pub fn path(&self) -> &Path {
        &self.path
    }
}

impl Drop for FileLock {
    fn drop(&mut self) {
        if self.remove {
            let _ = fs::remove_file(&self.path);
        }
        let _ = fs4::FileExt::unlock(&self.file);
    }
}

/// Whether `path` still names the open `file` (the lock file was not removed meanwhile).
#[cfg(unix)]
fn names_file(path: &Path, file: &File) -> bool {
    use std::os::unix::fs::MetadataExt;
    match (fs::metadata(path), file.metadata()) {
        (Ok(a), Ok(b)) => a.dev() == b.dev() && a.ino() == b.ino(),
        _ => false,
    }
}

/// Windows does not remove a file that another process holds open: the path still names it.
#[cfg(not(unix))]
fn names_file(path: &Path, _file: &File) -> bool {
    path.exists()
}

// ---------------------------------------------------------------------------------------------
// Manifests and ownership

/// Reads the manifest of `dir` (`None` when it has none or it cannot be read as one).
pub fn read_manifest(dir: &Path) -> Option<Manifest> {
    let text = fs::read_to_string(dir.join(MANIFEST)).ok()?;
    serde_json::from_str(&text).ok()
}

/// Writes the manifest of `dir` atomically.
fn write_manifest(dir: &Path, manifest: &Manifest) -> Result<(), FolderError> {
    let json = serde_json::to_string_pretty(manifest).map_err(|e| io_err(dir, e))?;
    write_file_atomically(&dir.join(MANIFEST), json.as_bytes())
}

/// Writes `bytes` to `path` through a hidden temporary sibling `.NAME.partial-PID` renamed onto
/// it, so that a reader (or a killed writer) never leaves a half-written file.
pub fn write_file_atomically(path: &Path, bytes: &[u8]) -> Result<(), FolderError> {
    let tmp = temp_file_path(path);
    fs::write(&tmp, bytes).map_err(|e| io_err(&tmp, e))?;
    fs::rename(&tmp, path).map_err(|e| {
        let _ = fs::remove_file(&tmp);
        io_err(path, e)
    })
}

/// The temporary sibling of a file written atomically: `.NAME.partial-PID`.
pub fn temp_file_path(path: &Path) -> PathBuf {
    parent_of(path).join(format!(".{}.partial-{}", name_of(path), std::process::id()))
}

/// What a name in a sweep folder is, by the sweep's layout.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum SweepEntry {
    /// A file of the sweep (sweep.csv, a shard file, the manifest, a lock file).
    File,
    /// A run folder `run_NNNN` (a run result with its own manifest).
    Run,
    /// A temporary file or folder of a writer (`.NAME.partial-PID`, `.NAME.old-PID`).
    Temporary,
}

/// Whether `name` belongs to a sweep folder's layout, and as what: `sweep.csv`, `sweep.json`,
/// `sweep.pvd`, `sweep_shard_K_of_N.csv` and `.json`, `run_NNNN`, the manifest, and the hidden
/// lock and temporary names of these (`.NAME.rollbem-lock`, `.NAME.partial-PID`,
/// `.NAME.old-PID`).
pub fn sweep_owns(name: &str) -> Option<SweepEntry> {
    let is_run = |n: &str| {
        n.strip_prefix("run_")
            .is_some_and(|d| d.len() >= 4 && d.bytes().all(|b| b.is_ascii_digit()))
    };
    let is_file =
        |n: &str| matches!(n, "sweep.csv" | "sweep.json" | "sweep.pvd" | MANIFEST) || shard_file_name(n).is_some();
    if is_run(name) {
        return Some(SweepEntry::Run);
    }
    if is_file(name) {
        return Some(SweepEntry::File);
    }
    let hidden = name.strip_prefix('.')?;
    if let Some(base) = hidden.strip_suffix(".rollbem-lock") {
        return (is_run(base) || is_file(base)).then_some(SweepEntry::File);
    }
    for mark in [".partial-", ".old-"] {
        if let Some((base, pid)) = hidden.rsplit_once(mark) {
            if !pid.is_empty() && pid.bytes().all(|b| b.is_ascii_digit()) && (is_run(base) || is_file(base)) {
                return Some(SweepEntry::Temporary);
            }
        }
    }
    None
}

/// `(K, N, extension)` of a shard file name `sweep_shard_K_of_N.csv` or `.json`.
pub fn shard_file_name(name: &str) -> Option<(usize, usize, &str)> {
    let (stem, ext) = name.rsplit_once('.')?;
    if ext != "csv" && ext != "json" {
        return None;
    }
    let (k, n) = stem.strip_prefix("sweep_shard_")?.split_once("_of_")?;
    let digits = |s: &str| !s.is_empty() && s.bytes().all(|b| b.is_ascii_digit());
    if !digits(k) || !digits(n) {
        return None;
    }
    Some((k.parse().ok()?, n.parse().ok()?, ext))
}

/// One entry rollbem wrote, to remove.
#[derive(Debug, Clone)]
enum Owned {
    File(PathBuf),
    Dir(PathBuf),
    /// A temporary folder of a writer: removed whole.
    Temporary(PathBuf),
}

/// What a folder holds.
#[derive(Debug)]
enum Contents {
    /// Nothing.
    Empty,
    /// A result of `kind`, every entry written by rollbem (deepest first, the manifest last).
    Result { kind: Kind, entries: Vec<Owned> },
}

/// Reads `dir` and decides whether rollbem wrote all of it: `Err(Foreign)` names the first
/// entry that is not in its manifest (or not of a sweep's layout).
fn contents(dir: &Path) -> Result<Contents, FolderError> {
    let mut names = list(dir)?;
    if names.is_empty() {
        return Ok(Contents::Empty);
    }
    names.sort();
    let foreign = |entry: String| FolderError::Foreign {
        dir: dir.to_path_buf(),
        entry,
    };
    let Some(manifest) = read_manifest(dir) else {
        let shown = names
            .iter()
            .find(|n| n.as_str() != MANIFEST)
            .cloned()
            .unwrap_or_else(|| MANIFEST.to_string());
        return Err(foreign(shown));
    };
    if manifest.partial {
        return Err(foreign(format!("{MANIFEST} (a result still being written)")));
    }
    let mut entries = Vec::new();
    if manifest.kind == Kind::Sweep {
        for name in &names {
            let path = dir.join(name);
            match sweep_owns(name) {
                Some(SweepEntry::File) if is_file(&path) => entries.push(Owned::File(path)),
                Some(SweepEntry::Run) if is_dir(&path) => match contents(&path) {
                    Ok(Contents::Result {
                        kind: Kind::Run,
                        entries: inner,
                    }) => {
                        entries.extend(inner);
                        entries.push(Owned::Dir(path));
                    }
                    Ok(Contents::Empty) => entries.push(Owned::Dir(path)),
                    Ok(Contents::Result { .. }) => return Err(foreign(format!("{name}/{MANIFEST}"))),
                    Err(FolderError::Foreign { entry, .. }) => return Err(foreign(format!("{name}/{entry}"))),
                    Err(e) => return Err(e),
                },
                Some(SweepEntry::Temporary) if is_dir(&path) && read_manifest(&path).is_some() => {
                    entries.push(Owned::Temporary(path))
                }
                Some(SweepEntry::Temporary) if is_file(&path) => entries.push(Owned::File(path)),
                _ => return Err(foreign(name.clone())),
            }
        }
    } else {
        let listed: std::collections::HashSet<&str> = manifest.files.iter().map(String::as_str).collect();
        walk_listed(dir, "", &listed, &mut entries).map_err(|e| match e {
            WalkError::Foreign(entry) => foreign(entry),
            WalkError::Io(e) => e,
        })?;
    }
    // The manifest goes last, so that a removal that stops half-way still marks the folder.
    entries.retain(|e| !matches!(e, Owned::File(p) if p == &dir.join(MANIFEST)));
    entries.push(Owned::File(dir.join(MANIFEST)));
    Ok(Contents::Result {
        kind: manifest.kind,
        entries,
    })
}

enum WalkError {
    Foreign(String),
    Io(FolderError),
}

/// Checks every entry under `dir/prefix` against the manifest's list, collecting them deepest
/// first.
fn walk_listed(
    root: &Path,
    prefix: &str,
    listed: &std::collections::HashSet<&str>,
    out: &mut Vec<Owned>,
) -> Result<(), WalkError> {
    let dir = root.join(prefix);
    let mut names = list(&dir).map_err(WalkError::Io)?;
    names.sort();
    for name in names {
        let rel = format!("{prefix}{name}");
        let path = root.join(&rel);
        if prefix.is_empty() && name == MANIFEST && is_file(&path) {
            continue;
        }
        if is_dir(&path) && listed.contains(format!("{rel}/").as_str()) {
            walk_listed(root, &format!("{rel}/"), listed, out)?;
            out.push(Owned::Dir(path));
        } else if is_file(&path) && listed.contains(rel.as_str()) {
            out.push(Owned::File(path));
        } else {
            return Err(WalkError::Foreign(rel));
        }
    }
    Ok(())
}

/// Names in `dir` (a name that is not valid Unicode is returned lossily: it is foreign anyway,
/// rollbem writes none).
fn list(dir: &Path) -> Result<Vec<String>, FolderError> {
    fs::read_dir(dir)
        .map_err(|e| io_err(dir, e))?
        .map(|e| {
            e.map(|e| e.file_name().to_string_lossy().into_owned())
                .map_err(|e| io_err(dir, e))
        })
        .collect()
}

/// A regular file (not a link to one).
fn is_file(p: &Path) -> bool {
    fs::symlink_metadata(p).is_ok_and(|m| m.file_type().is_file())
}

/// A folder (not a link to one).
fn is_dir(p: &Path) -> bool {
    fs::symlink_metadata(p).is_ok_and(|m| m.file_type().is_dir())
}

/// Files and sub-folders under `dir`, relative and `/`-separated (sub-folders end in `/`),
/// without the manifest: what a writer put into its temporary folder.
fn written_entries(dir: &Path, prefix: &str, out: &mut Vec<String>) -> Result<(), FolderError> {
    let mut names = list(&dir.join(prefix))?;
    names.sort();
    for name in names {
        let rel = format!("{prefix}{name}");
        if prefix.is_empty() && name == MANIFEST {
            continue;
        }
        if is_dir(&dir.join(&rel)) {
            out.push(format!("{rel}/"));
            written_entries(dir, &format!("{rel}/"), out)?;
        } else {
            out.push(rel);
        }
    }
    Ok(())
}

/// Removes what rollbem wrote in `dir`, entry by entry from its manifest, then `dir` if it is
/// empty. A folder that holds anything else is left as it is (`Err(Foreign)`).
pub fn remove_owned(dir: &Path) -> Result<(), FolderError> {
    if read_manifest(dir).is_some_and(|m| m.partial) {
        // A temporary folder: rollbem created it, wrote its manifest first, then filled it.
        return fs::remove_dir_all(dir).map_err(|e| io_err(dir, e));
    }
    if let Contents::Result { entries, .. } = contents(dir)? {
        remove_entries(&entries)?;
    }
    fs::remove_dir(dir).map_err(|e| io_err(dir, e))
}

fn remove_entries(entries: &[Owned]) -> Result<(), FolderError> {
    for e in entries {
        match e {
            Owned::File(p) => fs::remove_file(p).map_err(|e| io_err(p, e))?,
            Owned::Dir(p) => fs::remove_dir(p).map_err(|e| io_err(p, e))?,
            Owned::Temporary(p) => remove_owned(p)?,
        }
    }
    Ok(())
}

/// Removes temporary siblings of `target` left by killed writers (`.NAME.partial-PID`,
/// `.NAME.old-PID` holding a rollbem manifest); call only while holding `target`'s lock
/// exclusively, when no other writer can be filling them.
pub fn clean_stale_siblings(target: &Path) {
    let parent = parent_of(target);
    let name = name_of(target);
    let Ok(names) = list(parent) else { return };
    for n in names {
        let Some(rest) = n.strip_prefix(&format!(".{name}.")) else {
            continue;
        };
        let stale = ["partial-", "old-"].iter().any(|m| {
            rest.strip_prefix(m)
                .is_some_and(|pid| !pid.is_empty() && pid.bytes().all(|b| b.is_ascii_digit()))
        });
        let path = parent.join(&n);
        if stale && is_dir(&path) && read_manifest(&path).is_some() {
            let _ = remove_owned(&path);
        } else if stale && is_dir(&path) {
            // Killed before its manifest was written: removed only if empty.
            let _ = fs::remove_dir(&path);
        }
    }
}

// ---------------------------------------------------------------------------------------------
// Claims

/// Folders this process holds the lock of (so that the writer does not lock them twice).
static HELD: Mutex<Vec<PathBuf>> = Mutex::new(Vec::new());

fn held(target: &Path) -> bool {
    HELD.lock().map(|h| h.iter().any(|p| p == target)).unwrap_or(false)
}

/// The right to write one output folder: locked, checked (empty, new, or an earlier rollbem
/// result of the same kind), stale temporaries removed. Taken before solving; released when
/// dropped, with the lock file and any folder it created that stayed empty.
#[derive(Debug)]
pub struct Claim {
    target: PathBuf,
    kind: Kind,
    lock: Option<FileLock>,
    created: Vec<PathBuf>,
}

impl Claim {
    /// Claims `dir` for a result of `kind`: checks the path, creates its parent folders, locks
    /// it (exclusively, or shared for the shards of one sweep) without waiting, and checks that
    /// it holds nothing but an earlier rollbem result of the same kind.
    pub fn acquire(dir: &Path, kind: Kind, access: Access) -> Result<Claim, FolderError> {
        let target = resolve(dir)?;
        // Refuse a foreign folder before creating anything (the lock's parent, the lock).
        check_replaceable(&target, kind)?;
        let created = create_dirs(parent_of(&target))?;
        let mut claim = Claim {
            target,
            kind,
            lock: None,
            created,
        };
        let lock_file = lock_path(&claim.target);
        match FileLock::try_acquire(&lock_file, access)? {
            Some(lock) => claim.lock = Some(lock),
            None => {
                return Err(FolderError::Busy {
                    dir: claim.target.clone(),
                    lock: lock_file,
                })
            }
        }
        // Again under the lock: the folder may have changed since the first look.
        check_replaceable(&claim.target, kind)?;
        if access == Access::Exclusive {
            clean_stale_siblings(&claim.target);
        }
        if let Ok(mut h) = HELD.lock() {
            h.push(claim.target.clone());
        }
        Ok(claim)
    }

    /// The folder (absolute).
    pub fn path(&self) -> &Path {
        &self.target
    }

    /// What it is claimed for.
    pub fn kind(&self) -> Kind {
        self.kind
    }

    /// Creates the folder to be written in place (a sweep), with its manifest, if it does not
    /// hold one yet.
    pub fn create_in_place(&self) -> Result<(), FolderError> {
        if !self.target.exists() {
            fs::create_dir(&self.target)
                .or_else(|e| {
                    if e.kind() == io::ErrorKind::AlreadyExists {
                        Ok(())
                    } else {
                        Err(e)
                    }
                })
                .map_err(|e| io_err(&self.target, e))?;
        }
        match read_manifest(&self.target) {
            Some(m) if m.kind == self.kind && !m.partial => Ok(()),
            _ => write_manifest(&self.target, &Manifest::new(self.kind, false, Vec::new())),
        }
    }

    /// Writes the result through [`write_atomically`] (the lock is already held).
    pub fn write(&self, write: impl FnOnce(&Path) -> Result<(), Error>) -> Result<(), Error> {
        swap_in(&self.target, self.kind, write)
    }
}

impl Drop for Claim {
    fn drop(&mut self) {
        if let Ok(mut h) = HELD.lock() {
            if let Some(i) = h.iter().position(|p| p == &self.target) {
                h.swap_remove(i);
            }
        }
        // Release the lock (removing its file) before the folders it sits in.
        self.lock.take();
        remove_empty_dirs(&self.created);
    }
}

/// Whether `target` may receive a result of `kind`: absent, empty, or holding only an earlier
/// rollbem result of that kind.
fn check_replaceable(target: &Path, kind: Kind) -> Result<(), FolderError> {
    // Not followed: [`resolve`] resolved a link that points somewhere; one that is left points
    // nowhere, and renaming onto it would replace the user's link.
    match fs::symlink_metadata(target) {
        Err(e) if e.kind() == io::ErrorKind::NotFound => return Ok(()),
        Err(e) => return Err(io_err(target, e)),
        Ok(m) if !m.is_dir() => {
            return Err(FolderError::NotAFolder {
                path: target.to_path_buf(),
            })
        }
        Ok(_) => {}
    }
    match contents(target)? {
        Contents::Empty => Ok(()),
        Contents::Result { kind: found, .. } if found == kind => Ok(()),
        Contents::Result { kind: found, .. } => Err(FolderError::OtherKind {
            dir: target.to_path_buf(),
            found: found.name(),
            kind: kind.name(),
        }),
    }
}

/// Writes a result of `kind` into the folder `dir`: `write` fills a fresh temporary sibling,
/// which then replaces `dir` (see the module docs). Without a [`Claim`] on `dir` held by this
/// process, one is taken for the write. On failure the temporary folder is removed and `dir` is
/// left as it was.
pub fn write_atomically(dir: &Path, kind: Kind, write: impl FnOnce(&Path) -> Result<(), Error>) -> Result<(), Error> {
    let target = resolve(dir)?;
    if held(&target) {
        swap_in(&target, kind, write)
    } else {
        Claim::acquire(dir, kind, Access::Exclusive)?.write(write)
    }
}

fn swap_in(target: &Path, kind: Kind, write: impl FnOnce(&Path) -> Result<(), Error>) -> Result<(), Error> {
    let tmp = partial_path(target);
    if is_dir(&tmp) {
        // Left by an earlier process with our process id (ids are reused).
        remove_owned(&tmp)?;
    }
    fs::create_dir(&tmp).map_err(|e| io_err(&tmp, e))?;
    // Removes the temporary folder on every way out but success, a panic included.
    let guard = TempFolder(tmp.clone());
    write_manifest(&tmp, &Manifest::new(kind, true, Vec::new()))?;
    write(&tmp)?;
    inject_fault(&name_of(target));
    let mut files = Vec::new();
    if kind != Kind::Sweep {
        // A sweep folder owns the names of its layout, and its run folders list their own files.
        written_entries(&tmp, "", &mut files)?;
    }
    write_manifest(&tmp, &Manifest::new(kind, false, files))?;
    replace(target, kind, &tmp)?;
    // Renamed into place: the guard finds nothing left to remove.
    drop(guard);
    Ok(())
}

/// A temporary folder this process created and fills: removed when dropped (if still there).
struct TempFolder(PathBuf);

impl Drop for TempFolder {
    fn drop(&mut self) {
        if is_dir(&self.0) {
            let _ = fs::remove_dir_all(&self.0);
        }
    }
}

/// Renames the complete `tmp` onto `target`, replacing an earlier result (checked again: only
/// rollbem's files) that is then removed file by file.
fn replace(target: &Path, kind: Kind, tmp: &Path) -> Result<(), FolderError> {
    check_replaceable(target, kind)?;
    if !target.exists() {
        return fs::rename(tmp, target).map_err(|e| io_err(target, e));
    }
    if list(target)?.is_empty() {
        fs::remove_dir(target).map_err(|e| io_err(target, e))?;
        return fs::rename(tmp, target).map_err(|e| io_err(target, e));
    }
    let old = old_path(target);
    fs::rename(target, &old).map_err(|e| io_err(target, e))?;
    if let Err(e) = fs::rename(tmp, target) {
        let _ = fs::rename(&old, target);
        return Err(io_err(target, e));
    }
    // The old result holds only what rollbem wrote (checked above, under the lock); anything
    // that appeared since stays in `.NAME.old-PID`.
    let _ = remove_owned(&old);
    Ok(())
}

/// The fault injection of the tests (`ROLLBEM_TEST_FAULT`, see the module docs).
pub fn inject_fault(name: &str) {
    let Ok(spec) = std::env::var(FAULT_ENV) else {
        return;
    };
    let (what, only) = spec
        .split_once('@')
        .map_or((spec.as_str(), None), |(w, n)| (w, Some(n)));
    if only.is_some_and(|n| n != name) {
        return;
    }
    match what {
        "panic" => panic!("{FAULT_ENV}={spec}: injected panic while writing {name}"),
        "abort" => std::process::abort(),
        _ => {}
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn sweep_layout_names() {
        assert_eq!(sweep_owns("run_0012"), Some(SweepEntry::Run));
        assert_eq!(sweep_owns("run_12"), None);
        assert_eq!(sweep_owns("sweep.csv"), Some(SweepEntry::File));
        assert_eq!(sweep_owns("sweep_shard_2_of_4.json"), Some(SweepEntry::File));
        assert_eq!(sweep_owns(".run_0003.partial-4242"), Some(SweepEntry::Temporary));
        assert_eq!(sweep_owns(".sweep.csv.partial-17"), Some(SweepEntry::Temporary));
        assert_eq!(
            sweep_owns(".sweep_shard_1_of_2.csv.rollbem-lock"),
            Some(SweepEntry::File)
        );
        assert_eq!(sweep_owns(".run_0003.partial-x"), None);
        assert_eq!(sweep_owns("notes.txt"), None);
        assert_eq!(shard_file_name("sweep_shard_3_of_16.csv"), Some((3, 16, "csv")));
        assert_eq!(shard_file_name("sweep_shard_a_of_16.csv"), None);
    }

    #[test]
    fn paths_that_name_no_folder_are_refused() {
        assert!(check_path(Path::new("out/a\0b")).is_err());
        assert!(check_path(Path::new(&"x".repeat(256))).is_err());
        assert!(check_path(Path::new(&"x/".repeat(2100))).is_err());
        assert!(check_path(Path::new("out/carter")).is_ok());
        assert!(resolve(Path::new("/")).is_err());
    }

    #[cfg(unix)]
    #[test]
    fn links_are_followed_where_they_point_and_a_dangling_one_is_refused() {
        let dir = tempfile::tempdir().unwrap();
        let real = dir.path().join("real");
        fs::create_dir(&real).unwrap();
        std::os::unix::fs::symlink(&real, dir.path().join("link")).unwrap();
        let canon = real.canonicalize().unwrap();
        assert_eq!(resolve(&dir.path().join("link/out")).unwrap(), canon.join("out"));
        // `link/..` is the folder holding `real` (as the system resolves it), not `dir`'s.
        assert_eq!(
            resolve(&dir.path().join("link/../x")).unwrap(),
            canon.parent().unwrap().join("x")
        );
        assert_eq!(
            resolve(&dir.path().join("new/../y")).unwrap(),
            canon.parent().unwrap().join("y")
        );
        std::os::unix::fs::symlink(dir.path().join("gone"), dir.path().join("dangling")).unwrap();
        assert!(matches!(
            Claim::acquire(&dir.path().join("dangling"), Kind::Run, Access::Exclusive),
            Err(FolderError::NotAFolder { .. })
        ));
        assert!(fs::symlink_metadata(dir.path().join("dangling")).is_ok());
    }

    #[test]
    fn a_claimed_folder_is_busy_for_a_second_writer_and_free_after() {
        let dir = tempfile::tempdir().unwrap();
        let out = dir.path().join("a/b/out");
        let first = Claim::acquire(&out, Kind::Run, Access::Exclusive).unwrap();
        assert!(matches!(
            Claim::acquire(&out, Kind::Run, Access::Exclusive),
            Err(FolderError::Busy { .. })
        ));
        drop(first);
        // The lock file and the folders the claim created are gone.
        assert!(!dir.path().join("a").exists());
        let shared = Claim::acquire(&out, Kind::Sweep, Access::Shared).unwrap();
        let other = Claim::acquire(&out, Kind::Sweep, Access::Shared).unwrap();
        assert!(Claim::acquire(&out, Kind::Sweep, Access::Exclusive).is_err());
        drop((shared, other));
    }

    #[test]
    fn results_replace_results_and_nothing_else() {
        let dir = tempfile::tempdir().unwrap();
        let out = dir.path().join("out");
        let write = |text: &'static str| {
            move |tmp: &Path| {
                fs::create_dir(tmp.join("img")).unwrap();
                fs::write(tmp.join("img/a.svg"), text).unwrap();
                fs::write(tmp.join("summary.json"), text).unwrap();
                Ok(())
            }
        };
        write_atomically(&out, Kind::Run, write("one")).unwrap();
        write_atomically(&out, Kind::Run, write("two")).unwrap();
        assert_eq!(fs::read_to_string(out.join("img/a.svg")).unwrap(), "two");
        let m = read_manifest(&out).unwrap();
        assert_eq!(m.files, ["img/", "img/a.svg", "summary.json"]);
        // Nothing but the folder and its manifest-listed files was left around it.
        assert_eq!(list(dir.path()).unwrap(), ["out"]);
        // Another kind does not replace it; a foreign file blocks it and stays.
        assert!(matches!(
            write_atomically(&out, Kind::StudyAccuracy, write("x")),
            Err(Error::Folder(FolderError::OtherKind { .. }))
        ));
        fs::write(out.join("img/notes.txt"), "mine").unwrap();
        match write_atomically(&out, Kind::Run, write("three")) {
            Err(Error::Folder(FolderError::Foreign { entry, .. })) => assert_eq!(entry, "img/notes.txt"),
            other => panic!("{other:?}"),
        }
        assert_eq!(fs::read_to_string(out.join("img/notes.txt")).unwrap(), "mine");
        assert_eq!(fs::read_to_string(out.join("summary.json")).unwrap(), "two");
        // remove_owned leaves the foreign file and the folders that hold it.
        assert!(remove_owned(&out).is_err());
        fs::remove_file(out.join("img/notes.txt")).unwrap();
        remove_owned(&out).unwrap();
        assert!(!out.exists());
    }

    #[test]
    fn a_failed_write_leaves_the_earlier_result() {
        let dir = tempfile::tempdir().unwrap();
        let out = dir.path().join("out");
        write_atomically(&out, Kind::Run, |t| {
            fs::write(t.join("summary.json"), "one").unwrap();
            Ok(())
        })
        .unwrap();
        let failed = write_atomically(&out, Kind::Run, |t| {
            fs::write(t.join("summary.json"), "two").unwrap();
            Err(Error::Output {
                path: t.to_path_buf(),
                message: "disk full".into(),
            })
        });
        assert!(failed.is_err());
        assert_eq!(fs::read_to_string(out.join("summary.json")).unwrap(), "one");
        assert_eq!(list(dir.path()).unwrap(), ["out"]);
    }
}
