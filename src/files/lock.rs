//! Advisory locks on lock files: exclusive for one writer, shared for the shards of a sweep.
//!
//! A lock file holds [`MARKER`], written by the process that created it: a file of that name
//! that holds something else (the user's file, a symbolic link, a folder) is not rollbem's, and
//! is neither locked through nor removed ([`FolderError::NotALock`]). An empty one (or one
//! holding a beginning of the marker) is a lock file whose creator could not write it (a full
//! disk) or was killed first: once locked, it is taken over with a warning (the advisory lock
//! tells whether a process holds it; the kernel releases it when its holder dies).

use super::{io_err, FolderError};
use std::fs::{self, File, OpenOptions};
use std::io::{ErrorKind, Read, Seek, Write};
use std::path::{Path, PathBuf};

/// The first line of every lock file rollbem creates.
pub const MARKER: &str = "rollbem lock file\n";

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

/// The error for a file at a lock's path that rollbem did not create.
fn not_ours(path: &Path, what: &'static str) -> FolderError {
    FolderError::NotALock {
        path: path.to_path_buf(),
        what,
    }
}

/// Opens the lock file at `path`, creating it (never through a symbolic link) if it is absent:
/// the file and whether this call created it.
fn open_lock_file(path: &Path) -> Result<(File, bool), FolderError> {
    for _ in 0..16 {
        match fs::symlink_metadata(path) {
            Ok(m) if !m.file_type().is_file() => {
                let what = if m.file_type().is_symlink() {
                    "a symbolic link"
                } else {
                    "not a regular file"
                };
                return Err(not_ours(path, what));
            }
            Ok(_) => match OpenOptions::new().read(true).write(true).open(path) {
                Ok(f) => return Ok((f, false)),
                Err(e) if e.kind() == ErrorKind::NotFound => continue,
                Err(e) => return Err(io_err(path, e)),
            },
            Err(e) if e.kind() == ErrorKind::NotFound => {
                // O_EXCL: fails on anything at the path, a dangling symbolic link included.
                match OpenOptions::new().read(true).write(true).create_new(true).open(path) {
                    Ok(f) => return Ok((f, true)),
                    Err(e) if e.kind() == ErrorKind::AlreadyExists => continue,
                    Err(e) => return Err(io_err(path, e)),
                }
            }
            Err(e) => return Err(io_err(path, e)),
        }
    }
    Err(io_err(path, "the lock file keeps being replaced by other processes"))
}

/// What an existing lock file holds.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum LockText {
    /// [`MARKER`]: rollbem's.
    Marker,
    /// Nothing, or a beginning of [`MARKER`]: a lock file whose creator could not write its
    /// marker (a full disk) or was killed before it did.
    Stale,
    /// Anything else: not rollbem's.
    Foreign,
}

/// What the open lock file holds. Its creator writes [`MARKER`] right after creating and
/// locking the file, so an empty (or partly written) file is read again for a moment before it
/// counts as stale.
fn read_lock_text(mut file: &File) -> LockText {
    for _ in 0..20 {
        let mut text = Vec::new();
        let read = file
            .rewind()
            .and_then(|()| file.take(MARKER.len() as u64 + 1).read_to_end(&mut text));
        match read {
            Ok(_) if text.starts_with(MARKER.as_bytes()) => return LockText::Marker,
            Ok(_) if MARKER.as_bytes().starts_with(&text) => std::thread::sleep(std::time::Duration::from_millis(10)),
            _ => return LockText::Foreign,
        }
    }
    LockText::Stale
}

/// Writes [`MARKER`] as the whole content of the lock file (created, or stale and taken over).
fn write_marker(mut file: &File) -> std::io::Result<()> {
    file.set_len(0)?;
    file.rewind()?;
    file.write_all(MARKER.as_bytes())
}

impl FileLock {
    /// Takes the lock on `path` without waiting: `Ok(None)` when another process holds it;
    /// `Err(NotALock)` when something at `path` is not a lock file rollbem created.
    pub fn try_acquire(path: &Path, access: Access) -> Result<Option<FileLock>, FolderError> {
        for _ in 0..16 {
            let (file, created) = open_lock_file(path)?;
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
            if !names_file(path, &file) {
                continue;
            }
            let text = if created {
                LockText::Stale
            } else {
                read_lock_text(&file)
            };
            if text == LockText::Foreign {
                let _ = fs4::FileExt::unlock(&file);
                return Err(not_ours(path, "a file rollbem did not create"));
            }
            if text == LockText::Stale {
                if let Err(e) = write_marker(&file) {
                    // A full disk: the lock file this call created goes, or it would block the
                    // folder once space is freed.
                    if created && names_file(path, &file) {
                        let _ = fs::remove_file(path);
                    }
                    let _ = fs4::FileExt::unlock(&file);
                    return Err(io_err(path, e));
                }
                if !created {
                    log::warn!(
                        "{} was an empty (or partly written) rollbem lock file, left behind by a rollbem \
                         process that could not write it (a full disk) or was killed while creating it, \
                         and no process holds it: taken over",
                        path.display()
                    );
                }
            }
            return Ok(Some(FileLock {
                file,
                path: path.to_path_buf(),
                remove: access == Access::Exclusive,
            }));
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
        // Only the file this lock holds (checked: rollbem's), not one put there since.
        if self.remove && names_file(&self.path, &self.file) {
            let _ = fs::remove_file(&self.path);
        }
        let _ = fs4::FileExt::unlock(&self.file);
    }
}

/// Whether `path` itself (not a symbolic link's target) still names the open `file` (the lock
/// file was not removed or replaced meanwhile).
#[cfg(unix)]
fn names_file(path: &Path, file: &File) -> bool {
    use std::os::unix::fs::MetadataExt;
    match (fs::symlink_metadata(path), file.metadata()) {
        (Ok(a), Ok(b)) => a.dev() == b.dev() && a.ino() == b.ino(),
        _ => false,
    }
}

/// Windows does not remove a file that another process holds open: the path still names it.
#[cfg(not(unix))]
fn names_file(path: &Path, _file: &File) -> bool {
    path.exists()
}
