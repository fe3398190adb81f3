//! Claims on output folders and the atomic replacement of a result.

use super::contents::{
    clean_stale_siblings, contents, is_dir, list, remove_owned, sweep_owns, written_entries, Contents, SweepEntry,
};
use super::lock::{Access, FileLock};
use super::stamp::{check_unchanged, stamps_of, unstamped};
use super::{
    create_dirs, io_err, lock_path, name_of, old_path, parent_of, partial_path, read_manifest, remove_empty_dirs,
    resolve, write_manifest, FolderError, Kind, Manifest, FAULT_ENV,
};
use std::collections::BTreeMap;
use std::fs;
use std::io;
use std::path::{Path, PathBuf};
use std::sync::Mutex;

// ---------------------------------------------------------------------------------------------
// Claims

/// What a writer may replace, besides an earlier result of its kind that rollbem wrote and
/// nobody changed since.
#[derive(Debug, Clone, Default)]
pub struct WriteOptions {
    /// Replace files of the earlier result that were changed since rollbem wrote them
    /// (`--force`); without it such a file stops the write ([`FolderError::Changed`]).
    pub force: bool,
    /// The inputs of the case being written (the case file, the meshes it reads): never removed
    /// or replaced, `force` or not, so a folder that holds one is refused
    /// ([`FolderError::Input`]).
    pub inputs: Vec<PathBuf>,
}

/// Folders this process holds the lock of, with the claim's options (so that the writer does
/// not lock them twice, and writes under the claim's rules).
static HELD: Mutex<Vec<(PathBuf, WriteOptions)>> = Mutex::new(Vec::new());

/// The options of this process's claim on `target`, if it holds one.
fn held(target: &Path) -> Option<WriteOptions> {
    let h = HELD.lock().ok()?;
    h.iter().find(|(p, _)| p == target).map(|(_, o)| o.clone())
}

/// The right to write one output folder: locked, checked (empty, new, or an earlier rollbem
/// result of the same kind), stale temporaries removed. Taken before solving; released when
/// dropped, with the lock file and any folder it created that stayed empty.
#[derive(Debug)]
pub struct Claim {
    target: PathBuf,
    kind: Kind,
    options: WriteOptions,
    lock: Option<FileLock>,
    created: Vec<PathBuf>,
    /// Whether this claim is listed in [`HELD`]: only then does dropping it take its entry out
    /// (a claim refused as busy must not unlist the folder that another thread of this process
    /// holds, or that thread's write would try to lock it a second time, and fail).
    listed: bool,
}

impl Claim {
    /// Claims `dir` for a result of `kind`: checks the path, creates its parent folders, locks
    /// it (exclusively, or shared for the shards of one sweep) without waiting, and checks that
    /// it holds nothing but an earlier rollbem result of the same kind.
    pub fn acquire(dir: &Path, kind: Kind, access: Access) -> Result<Claim, FolderError> {
        Self::acquire_with(dir, kind, access, WriteOptions::default())
    }

    /// [`Claim::acquire`] with `options`: the case's inputs, which the folder must not hold,
    /// and whether files changed since rollbem wrote them may be replaced. A run folder of a
    /// sweep folder is refused to any claim but the sweep's ([`FolderError::SweepRun`]).
    pub fn acquire_with(dir: &Path, kind: Kind, access: Access, options: WriteOptions) -> Result<Claim, FolderError> {
        let target = resolve(dir)?;
        // Refuse a foreign folder before creating anything (the lock's parent, the lock).
        if let Err(e) = check_replaceable(&target, kind, &options) {
            // A folder that another process is writing changes under the look (a run's
            // temporary folder just created, its manifest not yet in it): busy, not foreign.
            let lock_file = lock_path(&target);
            if matches!(e, FolderError::Foreign { .. })
                && fs::symlink_metadata(&lock_file).is_ok()
                && matches!(FileLock::try_acquire(&lock_file, access), Ok(None))
            {
                return Err(FolderError::Busy {
                    dir: target,
                    lock: lock_file,
                });
            }
            return Err(e);
        }
        let created = create_dirs(parent_of(&target))?;
        let mut claim = Claim {
            target,
            kind,
            options,
            lock: None,
            created,
            listed: false,
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
        // Again under the lock: the folder may have changed since the first look. Its files
        // are read for their hashes only now, once (a sweep's when it is replaced).
        check_replaceable(&claim.target, kind, &claim.options)?;
        if kind != Kind::Sweep {
            check_edits(&claim.target, &claim.options)?;
        }
        if access == Access::Exclusive {
            clean_stale_siblings(&claim.target);
        }
        if let Ok(mut h) = HELD.lock() {
            h.push((claim.target.clone(), claim.options.clone()));
            claim.listed = true;
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
            _ => write_manifest(
                &self.target,
                &Manifest::new(self.kind, false, Vec::new(), BTreeMap::new()),
            ),
        }
    }

    /// Whether the earlier result in the folder may be replaced as far as edits go: its files
    /// are as rollbem wrote them, or the claim may replace changed ones. Checked on claiming for
    /// every kind but a sweep, which is written in place unless it is replaced: a sweep that
    /// replaces its folder asks before running.
    pub fn check_unchanged(&self) -> Result<(), FolderError> {
        check_edits(&self.target, &self.options)
    }

    /// Writes the result through [`write_atomically`] (the lock is already held).
    pub fn write<E: From<FolderError>>(&self, write: impl FnOnce(&Path) -> Result<(), E>) -> Result<(), E> {
        swap_in(&self.target, self.kind, &self.options, write)
    }
}

impl Drop for Claim {
    fn drop(&mut self) {
        if let Some(mut h) = HELD.lock().ok().filter(|_| self.listed) {
            if let Some(i) = h.iter().position(|(p, _)| p == &self.target) {
                h.swap_remove(i);
            }
        }
        // Release the lock (removing its file) before the folders it sits in.
        self.lock.take();
        remove_empty_dirs(&self.created);
    }
}

/// Whether `target` may receive a result of `kind`: absent, empty, or holding only an earlier
/// rollbem result of that kind; never a run folder of another's sweep, nor a folder holding an
/// input of the case. Whether the result's files were edited is [`check_edits`].
fn check_replaceable(target: &Path, kind: Kind, options: &WriteOptions) -> Result<(), FolderError> {
    check_not_a_sweeps_run(target, kind)?;
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
        Contents::Result { kind: found, .. } if found == kind => {
            // An input that rollbem did not write is foreign (refused above, by that name); one
            // that it wrote (a mesh of an earlier `rollbem mesh`) is refused here.
            check_inputs(target, &options.inputs)
        }
        Contents::Result { kind: found, .. } => Err(FolderError::OtherKind {
            dir: target.to_path_buf(),
            found: found.name(),
            kind: kind.name(),
        }),
    }
}

/// Whether the files of the earlier result in `target` are as rollbem wrote them
/// ([`check_unchanged`]), unless `options.force`.
fn check_edits(target: &Path, options: &WriteOptions) -> Result<(), FolderError> {
    if options.force {
        return Ok(());
    }
    check_unchanged(target)
}

/// Refuses a claim of kind run on a run folder `run_NNNN` of a sweep folder that this process
/// does not hold (the sweep's own runs are written while it holds it, or into its temporary
/// folder, whose manifest says it is still being written).
fn check_not_a_sweeps_run(target: &Path, kind: Kind) -> Result<(), FolderError> {
    if kind != Kind::Run || sweep_owns(&name_of(target)) != Some(SweepEntry::Run) {
        return Ok(());
    }
    let sweep = parent_of(target);
    match read_manifest(sweep) {
        Some(m) if m.kind == Kind::Sweep && !m.partial && held(sweep).is_none() => Err(FolderError::SweepRun {
            dir: target.to_path_buf(),
            sweep: sweep.to_path_buf(),
        }),
        _ => Ok(()),
    }
}

/// Refuses the folder `target` if one of the case's `inputs` lies in it.
fn check_inputs(target: &Path, inputs: &[PathBuf]) -> Result<(), FolderError> {
    for input in inputs {
        let file = fs::canonicalize(input).unwrap_or_else(|_| super::normalize(input));
        if file.starts_with(target) {
            return Err(FolderError::Input {
                file,
                dir: target.to_path_buf(),
            });
        }
    }
    Ok(())
}

/// Writes a result of `kind` into the folder `dir`: `write` fills a fresh temporary sibling,
/// which then replaces `dir` (see the module docs). Without a [`Claim`] on `dir` held by this
/// process, one is taken for the write. On failure the temporary folder is removed and `dir` is
/// left as it was.
pub fn write_atomically<E: From<FolderError>>(
    dir: &Path,
    kind: Kind,
    write: impl FnOnce(&Path) -> Result<(), E>,
) -> Result<(), E> {
    write_atomically_with(dir, kind, WriteOptions::default(), write)
}

/// [`write_atomically`] with `options` ([`Claim::acquire_with`]); under a claim this process
/// holds on `dir`, the claim's options apply instead.
pub fn write_atomically_with<E: From<FolderError>>(
    dir: &Path,
    kind: Kind,
    options: WriteOptions,
    write: impl FnOnce(&Path) -> Result<(), E>,
) -> Result<(), E> {
    let target = resolve(dir)?;
    match held(&target) {
        Some(held) => swap_in(&target, kind, &held, write),
        None => Claim::acquire_with(dir, kind, Access::Exclusive, options)?.write(write),
    }
}

fn swap_in<E: From<FolderError>>(
    target: &Path,
    kind: Kind,
    options: &WriteOptions,
    write: impl FnOnce(&Path) -> Result<(), E>,
) -> Result<(), E> {
    let tmp = partial_path(target);
    if is_dir(&tmp) {
        // Left by an earlier process with our process id (ids are reused).
        remove_owned(&tmp)?;
    }
    fs::create_dir(&tmp).map_err(|e| io_err(&tmp, e))?;
    // Removes the temporary folder on every way out but success, a panic included.
    let guard = TempFolder(tmp.clone());
    write_manifest(&tmp, &Manifest::new(kind, true, Vec::new(), BTreeMap::new()))?;
    write(&tmp)?;
    inject_fault(&name_of(target));
    let mut files = Vec::new();
    if kind != Kind::Sweep {
        // A sweep folder owns the names of its layout, and its run folders list their own files.
        written_entries(&tmp, "", &mut files)?;
    }
    let stamps = stamps_of(&tmp, &files)?;
    write_manifest(&tmp, &Manifest::new(kind, false, files, stamps))?;
    replace(target, kind, options, &tmp)?;
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
/// rollbem's files, unchanged unless `options.force`) that is then removed file by file.
fn replace(target: &Path, kind: Kind, options: &WriteOptions, tmp: &Path) -> Result<(), FolderError> {
    check_replaceable(target, kind, options)?;
    check_edits(target, options)?;
    if read_manifest(target).is_some_and(|m| unstamped(&m)) {
        log::warn!(
            "{}: its manifest was written by an older rollbem, which recorded no sizes or hashes, so \
             rollbem cannot tell whether its files were edited since; replacing it",
            target.display()
        );
    }
    if !target.exists() {
        return fs::rename(tmp, target).map_err(|e| io_err(target, e));
    }
    // The folder the user gave (or chmod-ed) keeps its permissions (0700 stays 0700).
    let permissions = fs::metadata(target).map_err(|e| io_err(target, e))?.permissions();
    let keep_mode = || fs::set_permissions(target, permissions.clone()).map_err(|e| io_err(target, e));
    if list(target)?.is_empty() {
        fs::remove_dir(target).map_err(|e| io_err(target, e))?;
        fs::rename(tmp, target).map_err(|e| io_err(target, e))?;
        return keep_mode();
    }
    let old = old_path(target);
    fs::rename(target, &old).map_err(|e| io_err(target, e))?;
    if let Err(e) = fs::rename(tmp, target) {
        let _ = fs::rename(&old, target);
        return Err(io_err(target, e));
    }
    keep_mode()?;
    inject_intruder(&name_of(target), &old);
    // The old result holds only what rollbem wrote (checked above, under the lock); what cannot
    // be removed (a read-only folder, a file that appeared since) stays, and the user is told.
    if let Err(e) = remove_owned(&old) {
        log::warn!(
            "{} now holds the new result, but the earlier one could not be removed completely ({e}); \
             what is left of it is in {}: remove it yourself",
            target.display(),
            old.display()
        );
    }
    Ok(())
}

/// The fault injection `intrude@NAME` of the tests: a file that rollbem did not write appears
/// in the earlier result of NAME after it was checked, so that its removal stops.
fn inject_intruder(name: &str, old: &Path) {
    if std::env::var(FAULT_ENV).is_ok_and(|spec| spec == format!("intrude@{name}")) {
        let _ = fs::write(old.join("intruder.txt"), "not rollbem's");
    }
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
