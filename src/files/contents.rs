//! What a folder holds: the names a sweep's layout owns, the entries a manifest lists, and the
//! removal of what rollbem wrote.

use super::{io_err, name_of, parent_of, read_manifest, FolderError, Kind, MANIFEST};
use std::fs;
use std::path::{Path, PathBuf};

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
pub(super) enum Owned {
    File(PathBuf),
    Dir(PathBuf),
    /// A temporary folder of a writer: removed whole.
    Temporary(PathBuf),
}

/// What a folder holds.
#[derive(Debug)]
pub(super) enum Contents {
    /// Nothing.
    Empty,
    /// A result of `kind`, every entry written by rollbem (deepest first, the manifest last).
    Result { kind: Kind, entries: Vec<Owned> },
}

/// Reads `dir` and decides whether rollbem wrote all of it: `Err(Foreign)` names the first
/// entry that is not in its manifest (or not of a sweep's layout).
pub(super) fn contents(dir: &Path) -> Result<Contents, FolderError> {
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
                // A writer's temporary folder in the instant between its creation and its
                // manifest (another shard's run, seen while it starts): empty, or holding only
                // the manifest's own temporary file.
                Some(SweepEntry::Temporary) if is_dir(&path) && being_created(&path) => {
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

/// Whether the folder `dir` holds nothing, or only the temporary file of its manifest being
/// written (`.rollbem-manifest.partial-PID`): a temporary folder a writer has just created.
fn being_created(dir: &Path) -> bool {
    let prefix = format!(".{MANIFEST}.partial-");
    list(dir).is_ok_and(|names| names.iter().all(|n| n.starts_with(&prefix)))
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
pub(super) fn list(dir: &Path) -> Result<Vec<String>, FolderError> {
    fs::read_dir(dir)
        .map_err(|e| io_err(dir, e))?
        .map(|e| {
            e.map(|e| e.file_name().to_string_lossy().into_owned())
                .map_err(|e| io_err(dir, e))
        })
        .collect()
}

/// A regular file (not a link to one).
pub(super) fn is_file(p: &Path) -> bool {
    fs::symlink_metadata(p).is_ok_and(|m| m.file_type().is_file())
}

/// A folder (not a link to one).
pub(super) fn is_dir(p: &Path) -> bool {
    fs::symlink_metadata(p).is_ok_and(|m| m.file_type().is_dir())
}

/// Files and sub-folders under `dir`, relative and `/`-separated (sub-folders end in `/`),
/// without the manifest: what a writer put into its temporary folder.
pub(super) fn written_entries(dir: &Path, prefix: &str, out: &mut Vec<String>) -> Result<(), FolderError> {
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

/// Whether `dir` holds a complete run result: a manifest of a finished run (not a temporary
/// folder's) and every file and sub-folder it lists. `Err` says what is missing (for a sweep's
/// `--resume` and `--merge`, which trust a run's row only with its folder whole).
pub fn check_run_folder(dir: &Path) -> Result<(), String> {
    if !is_dir(dir) {
        return Err(format!("its folder {} is missing", dir.display()));
    }
    let Some(manifest) = read_manifest(dir) else {
        return Err(format!("its folder {} has no manifest {MANIFEST}", dir.display()));
    };
    if manifest.kind != Kind::Run || manifest.partial {
        return Err(format!(
            "its folder {} does not hold a finished run (its manifest says {}{})",
            dir.display(),
            manifest.kind.name(),
            if manifest.partial { ", being written" } else { "" }
        ));
    }
    for entry in &manifest.files {
        let path = dir.join(entry.trim_end_matches('/'));
        let there = if entry.ends_with('/') {
            is_dir(&path)
        } else {
            is_file(&path)
        };
        if !there {
            return Err(format!(
                "its folder {} lacks {entry}, which its manifest lists",
                dir.display()
            ));
        }
    }
    Ok(())
}
