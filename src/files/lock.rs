//! Advisory locks on lock files: exclusive for one writer, shared for the shards of a sweep.

use super::{io_err, FolderError};
use std::fs::{self, File, OpenOptions};
use std::path::{Path, PathBuf};

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
