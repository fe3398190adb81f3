//! What rollbem wrote into a file: its size and a hash of its bytes, recorded in the manifest,
//! so that a file the user edited since is not replaced without a word.

use super::contents::{is_dir, is_file, list, sweep_owns, SweepEntry};
use super::{io_err, read_manifest, FolderError, Kind, Manifest};
use serde::{Deserialize, Serialize};
use std::collections::BTreeMap;
use std::fs::{self, File};
use std::io::Read;
use std::path::Path;

/// The size and hash of a file as rollbem wrote it.
#[derive(Debug, Clone, PartialEq, Eq, Serialize, Deserialize)]
pub struct Stamp {
    /// Size [bytes].
    pub size: u64,
    /// [`fnv1a64`] of the bytes: `fnv1a64:` and 16 hex digits.
    pub hash: String,
}

const FNV_OFFSET: u64 = 0xcbf2_9ce4_8422_2325;
const FNV_PRIME: u64 = 0x0000_0100_0000_01b3;

/// FNV-1a, 64 bits (Fowler, Noll, Vo): a fast content hash to tell files apart (not a
/// cryptographic one: it guards against mistakes, not against forgery).
pub fn fnv1a64(bytes: &[u8]) -> u64 {
    fnv1a64_more(FNV_OFFSET, bytes)
}

/// [`fnv1a64`] continued from the state `h` over more bytes.
fn fnv1a64_more(h: u64, bytes: &[u8]) -> u64 {
    bytes.iter().fold(h, |h, &b| (h ^ u64::from(b)).wrapping_mul(FNV_PRIME))
}

/// The stamp of the regular file at `path`, read in pieces.
pub(super) fn stamp_of(path: &Path) -> Result<Stamp, FolderError> {
    let mut file = File::open(path).map_err(|e| io_err(path, e))?;
    let mut buf = vec![0u8; 1 << 16];
    let (mut size, mut h) = (0u64, FNV_OFFSET);
    loop {
        let n = file.read(&mut buf).map_err(|e| io_err(path, e))?;
        if n == 0 {
            break;
        }
        size += n as u64;
        h = fnv1a64_more(h, &buf[..n]);
    }
    Ok(Stamp {
        size,
        hash: format!("fnv1a64:{h:016x}"),
    })
}

/// The stamps of the files (not the sub-folders, which end in `/`) among `files`, relative to
/// `dir`.
pub(super) fn stamps_of(dir: &Path, files: &[String]) -> Result<BTreeMap<String, Stamp>, FolderError> {
    files
        .iter()
        .filter(|f| !f.ends_with('/'))
        .map(|f| Ok((f.clone(), stamp_of(&dir.join(f))?)))
        .collect()
}

/// Whether the files of the result in `dir` are still as rollbem wrote them: `Err(Changed)` names
/// the first whose size or hash differs from its manifest's stamp (the size compared first, so an
/// edit that changes it costs no reading). A file that is gone loses nothing and passes; so does
/// a manifest of an older rollbem, which records no stamps. The run folders of a sweep are
/// checked each against its own manifest.
pub fn check_unchanged(dir: &Path) -> Result<(), FolderError> {
    let Some(manifest) = read_manifest(dir) else {
        return Ok(());
    };
    if manifest.kind == Kind::Sweep {
        for name in list(dir)? {
            let path = dir.join(&name);
            if sweep_owns(&name) == Some(SweepEntry::Run) && is_dir(&path) {
                check_unchanged(&path)?;
            }
        }
        return Ok(());
    }
    for (name, stamp) in &manifest.stamps {
        let path = dir.join(name);
        let Ok(meta) = fs::symlink_metadata(&path) else {
            continue;
        };
        let same = is_file(&path) && meta.len() == stamp.size && stamp_of(&path)? == *stamp;
        if !same {
            return Err(FolderError::Changed { path });
        }
    }
    Ok(())
}

/// Whether the manifest lists files without stamps (written by a rollbem before they were
/// recorded): their edits cannot be told.
pub(super) fn unstamped(manifest: &Manifest) -> bool {
    manifest.stamps.is_empty() && manifest.files.iter().any(|f| !f.ends_with('/'))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_stamp_of_a_file_is_its_size_and_the_hash_of_its_bytes() {
        let dir = tempfile::tempdir().unwrap();
        let bytes: Vec<u8> = (0..200_000u32).map(|i| (i % 251) as u8).collect();
        fs::write(dir.path().join("f"), &bytes).unwrap();
        let s = stamp_of(&dir.path().join("f")).unwrap();
        assert_eq!(s.size, 200_000);
        assert_eq!(s.hash, format!("fnv1a64:{:016x}", fnv1a64(&bytes)));
        // The reference value of FNV-1a 64 for "a".
        assert_eq!(fnv1a64(b"a"), 0xaf63_dc4c_8601_ec8c);
    }
}
