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
//!   did not write;
//! * so is an earlier result with a file changed since rollbem wrote it: the manifest records
//!   each file's size and hash ([`Stamp`]), and a file that differs stops the write
//!   ([`FolderError::Changed`]) unless the writer was given `--force`
//!   ([`WriteOptions::force`]). A manifest of an older rollbem lists names only: its folder is
//!   replaced as before, with a warning;
//! * and, `--force` or not, a folder that holds an input of the case being written (the case
//!   file, a mesh it reads: [`WriteOptions::inputs`]; [`FolderError::Input`]), and a run folder
//!   `run_NNNN` of a sweep folder claimed by anything but its sweep ([`FolderError::SweepRun`]:
//!   the sweep's table describes it).
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
//! the temporary folder and before it is renamed into place; `intrude@NAME` puts a file into
//! NAME's earlier result after it was checked, so that its removal stops (and is reported).
//! Nothing else reads it.

use serde::{Deserialize, Serialize};
use std::collections::BTreeMap;
use std::fs;
use std::io;
use std::path::{Component, Path, PathBuf};

mod claim;
mod contents;
mod lock;
mod stamp;

pub use claim::{inject_fault, write_atomically, write_atomically_with, Claim, WriteOptions};
pub use contents::{check_run_folder, clean_stale_siblings, remove_owned, shard_file_name, sweep_owns, SweepEntry};
pub use lock::{Access, FileLock};
pub use stamp::{check_unchanged, fnv1a64, xxh64, Stamp};

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
    /// `rollbem mesh`: the generated meshes of a case's `geometry:` bodies.
    #[serde(rename = "mesh")]
    Mesh,
    /// `rollbem study shakedown`.
    #[serde(rename = "study shakedown")]
    StudyShakedown,
}

impl Kind {
    /// The name used in the manifest and in messages.
    pub fn name(self) -> &'static str {
        match self {
            Kind::Run => "run",
            Kind::Sweep => "sweep",
            Kind::StudyAccuracy => "study accuracy",
            Kind::StudyStability => "study stability",
            Kind::Mesh => "mesh",
            Kind::StudyShakedown => "study shakedown",
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
    /// The size and hash of every file of `files` as written, by name, so that a file edited
    /// since is not replaced without a word ([`check_unchanged`]). Absent from the manifests of
    /// sweep folders and of an older rollbem, which did not record them: such files are replaced
    /// as before, their edits cannot be told.
    #[serde(default, skip_serializing_if = "BTreeMap::is_empty")]
    pub stamps: BTreeMap<String, Stamp>,
}

impl Manifest {
    fn new(kind: Kind, partial: bool, files: Vec<String>, stamps: BTreeMap<String, Stamp>) -> Self {
        Self {
            written_by: format!("rollbem {}", env!("CARGO_PKG_VERSION")),
            kind,
            partial,
            files,
            stamps,
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
    /// A file at a lock file's path that rollbem did not create (no marker, a symbolic link).
    #[error(
        "{path} is named like a rollbem lock file but is {what} (rollbem's lock files start with \
         `rollbem lock file`); rollbem neither locks through it nor removes it: move it away (an empty \
         one, left by a rollbem process that could not write it, is taken over)"
    )]
    NotALock {
        /// The file.
        path: PathBuf,
        /// What it is.
        what: &'static str,
    },
    /// A file rollbem wrote was changed since (its size or hash differs from the manifest).
    #[error(
        "{path} was changed since rollbem wrote it (its size or contents differ from what the \
         folder's manifest records), and replacing the folder would lose that; move it away or \
         pass --force to replace it (rollbem run, rollbem mesh). Nothing was solved or written"
    )]
    Changed {
        /// The file.
        path: PathBuf,
    },
    /// An input of the case (the case file, a mesh it reads) lies in the folder to be replaced.
    #[error(
        "{file} is an input of the case (the case file or a mesh it reads), and it lies in the \
         output folder {dir}, which this command would replace; rollbem never removes or replaces a case's own inputs (not \
         even with --force): write to another folder (--out NEW_FOLDER). Nothing was solved or \
         written"
    )]
    Input {
        /// The input file.
        file: PathBuf,
        /// The output folder.
        dir: PathBuf,
    },
    /// A run folder of a sweep folder, claimed by something other than that sweep.
    #[error(
        "{dir} is a run folder of the sweep in {sweep}: the sweep's table (sweep.csv) describes \
         what it holds, so only the sweep writes it (rollbem sweep --resume re-runs its failed \
         runs), not even with --force; give another folder (--out NEW_FOLDER). Nothing was \
         solved or written"
    )]
    SweepRun {
        /// The run folder.
        dir: PathBuf,
        /// The sweep folder holding it.
        sweep: PathBuf,
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

/// Removes `.` and `name/..` pairs lexically (`cases/../out/x` → `out/x`; a path that
/// cancels out entirely becomes empty).
pub fn normalize(path: &Path) -> PathBuf {
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

#[cfg(test)]
mod tests {
    use super::claim::*;
    use super::contents::*;
    use super::*;
    use crate::error::Error;

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
    fn a_second_writer_refused_leaves_the_holders_write_to_it() {
        // Two threads of one process (Python's): the one refused as busy must not unlist the
        // folder the other holds, whose write then locks it a second time and fails.
        let dir = tempfile::tempdir().unwrap();
        let out = dir.path().join("out");
        let first = Claim::acquire(&out, Kind::Run, Access::Exclusive).unwrap();
        assert!(matches!(
            Claim::acquire(&out, Kind::Run, Access::Exclusive),
            Err(FolderError::Busy { .. })
        ));
        write_atomically(&out, Kind::Run, |tmp: &Path| {
            fs::write(tmp.join("summary.json"), "{}").map_err(|e| FolderError::Io {
                path: tmp.to_path_buf(),
                message: e.to_string(),
            })
        })
        .unwrap();
        drop(first);
        assert!(out.join("summary.json").is_file());
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
    fn an_edited_file_stops_the_write_unless_forced_and_old_manifests_are_read() {
        let dir = tempfile::tempdir().unwrap();
        let out = dir.path().join("out");
        let write = |text: &'static str| {
            move |tmp: &Path| {
                fs::write(tmp.join("summary.json"), text).unwrap();
                Ok::<(), Error>(())
            }
        };
        write_atomically(&out, Kind::Run, write("one")).unwrap();
        let stamp = Stamp {
            size: 3,
            hash: format!("xxh64:{:016x}", xxh64(b"one")),
        };
        assert_eq!(read_manifest(&out).unwrap().stamps["summary.json"], stamp);
        fs::write(out.join("summary.json"), "two").unwrap();
        assert!(matches!(
            write_atomically(&out, Kind::Run, write("three")),
            Err(Error::Folder(FolderError::Changed { .. }))
        ));
        assert_eq!(fs::read_to_string(out.join("summary.json")).unwrap(), "two");
        let force = WriteOptions {
            force: true,
            inputs: Vec::new(),
        };
        write_atomically_with(&out, Kind::Run, force, write("four")).unwrap();
        assert_eq!(fs::read_to_string(out.join("summary.json")).unwrap(), "four");
        // The manifest of an older rollbem lists names only: replaced as before.
        let old = r#"{"written_by": "rollbem 0.1.0", "kind": "run", "partial": false, "files": ["summary.json"]}"#;
        fs::write(out.join(MANIFEST), old).unwrap();
        fs::write(out.join("summary.json"), "edited").unwrap();
        write_atomically(&out, Kind::Run, write("five")).unwrap();
        assert_eq!(fs::read_to_string(out.join("summary.json")).unwrap(), "five");
    }

    #[test]
    fn a_failed_write_leaves_the_earlier_result() {
        let dir = tempfile::tempdir().unwrap();
        let out = dir.path().join("out");
        write_atomically(&out, Kind::Run, |t| {
            fs::write(t.join("summary.json"), "one").unwrap();
            Ok::<(), Error>(())
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
