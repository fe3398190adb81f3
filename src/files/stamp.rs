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
    /// [`xxh64`] of the bytes: `xxh64:` and 16 hex digits.
    pub hash: String,
}

const FNV_OFFSET: u64 = 0xcbf2_9ce4_8422_2325;
const FNV_PRIME: u64 = 0x0000_0100_0000_01b3;

/// FNV-1a, 64 bits (Fowler, Noll, Vo): a fast content hash to tell case files apart (not a
/// cryptographic one: it guards against mistakes, not against forgery).
pub fn fnv1a64(bytes: &[u8]) -> u64 {
    bytes
        .iter()
        .fold(FNV_OFFSET, |h, &b| (h ^ u64::from(b)).wrapping_mul(FNV_PRIME))
}

/// XXH64 (Yann Collet's xxHash, 64 bits, seed 0) of a file's bytes fed in pieces: four lanes of
/// 8-byte words, several times as fast as FNV-1a's one byte at a time on the results' megabytes
/// (not a cryptographic hash either).
struct Xxh64 {
    lanes: [u64; 4],
    /// Bytes not yet taken into the lanes (less than a 32-byte stripe).
    tail: Vec<u8>,
    len: u64,
}

const P1: u64 = 0x9E37_79B1_85EB_CA87;
const P2: u64 = 0xC2B2_AE3D_27D4_EB4F;
const P3: u64 = 0x1656_67B1_9E37_79F9;
const P4: u64 = 0x85EB_CA77_C2B2_AE63;
const P5: u64 = 0x27D4_EB2F_1656_67C5;

fn round(acc: u64, input: u64) -> u64 {
    acc.wrapping_add(input.wrapping_mul(P2))
        .rotate_left(31)
        .wrapping_mul(P1)
}

fn merge_round(h: u64, lane: u64) -> u64 {
    (h ^ round(0, lane)).wrapping_mul(P1).wrapping_add(P4)
}

fn word(b: &[u8]) -> u64 {
    u64::from_le_bytes(b[..8].try_into().unwrap_or_default())
}

impl Xxh64 {
    fn new() -> Self {
        Self {
            lanes: [P1.wrapping_add(P2), P2, 0, 0u64.wrapping_sub(P1)],
            tail: Vec::with_capacity(32),
            len: 0,
        }
    }

    fn update(&mut self, mut bytes: &[u8]) {
        self.len += bytes.len() as u64;
        if !self.tail.is_empty() {
            let take = (32 - self.tail.len()).min(bytes.len());
            self.tail.extend_from_slice(&bytes[..take]);
            bytes = &bytes[take..];
            if self.tail.len() < 32 {
                return;
            }
            let stripe = std::mem::take(&mut self.tail);
            self.stripe(&stripe);
        }
        let mut stripes = bytes.chunks_exact(32);
        for s in &mut stripes {
            self.stripe(s);
        }
        self.tail.extend_from_slice(stripes.remainder());
    }

    fn stripe(&mut self, s: &[u8]) {
        for (k, lane) in self.lanes.iter_mut().enumerate() {
            *lane = round(*lane, word(&s[8 * k..]));
        }
    }

    fn finish(&self) -> u64 {
        let [v1, v2, v3, v4] = self.lanes;
        let mut h = if self.len >= 32 {
            let h = v1
                .rotate_left(1)
                .wrapping_add(v2.rotate_left(7))
                .wrapping_add(v3.rotate_left(12))
                .wrapping_add(v4.rotate_left(18));
            self.lanes.iter().fold(h, |h, &v| merge_round(h, v))
        } else {
            v3.wrapping_add(P5)
        };
        h = h.wrapping_add(self.len);
        let mut rest = self.tail.as_slice();
        while rest.len() >= 8 {
            h = (h ^ round(0, word(rest)))
                .rotate_left(27)
                .wrapping_mul(P1)
                .wrapping_add(P4);
            rest = &rest[8..];
        }
        if rest.len() >= 4 {
            let w = u64::from(u32::from_le_bytes(rest[..4].try_into().unwrap_or_default()));
            h = (h ^ w.wrapping_mul(P1))
                .rotate_left(23)
                .wrapping_mul(P2)
                .wrapping_add(P3);
            rest = &rest[4..];
        }
        for &b in rest {
            h = (h ^ u64::from(b).wrapping_mul(P5)).rotate_left(11).wrapping_mul(P1);
        }
        h ^= h >> 33;
        h = h.wrapping_mul(P2);
        h ^= h >> 29;
        h = h.wrapping_mul(P3);
        h ^ (h >> 32)
    }
}

/// XXH64 (seed 0) of `bytes`.
pub fn xxh64(bytes: &[u8]) -> u64 {
    let mut h = Xxh64::new();
    h.update(bytes);
    h.finish()
}

/// The stamp of the regular file at `path`, read in pieces.
pub(super) fn stamp_of(path: &Path) -> Result<Stamp, FolderError> {
    let mut file = File::open(path).map_err(|e| io_err(path, e))?;
    let mut buf = vec![0u8; 1 << 16];
    let mut h = Xxh64::new();
    loop {
        let n = file.read(&mut buf).map_err(|e| io_err(path, e))?;
        if n == 0 {
            break;
        }
        h.update(&buf[..n]);
    }
    Ok(Stamp {
        size: h.len,
        hash: format!("xxh64:{:016x}", h.finish()),
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
        // Reference values of XXH64, seed 0 (libxxhash 0.8.3 gives the same).
        assert_eq!(xxh64(b""), 0xef46_db37_51d8_e999);
        assert_eq!(xxh64(b"abc"), 0x44bc_2cf5_ad77_0999);
        assert_eq!(xxh64(b"Nobody inspects the spammish repetition"), 0xfbce_a83c_8a37_8bf1);
        assert_eq!(fnv1a64(b"a"), 0xaf63_dc4c_8601_ec8c);
        // Fed in pieces that cut stripes, as a file is read: the same as at once.
        let dir = tempfile::tempdir().unwrap();
        let bytes: Vec<u8> = (0..200_003u32).map(|i| (i % 251) as u8).collect();
        let mut h = Xxh64::new();
        for piece in bytes.chunks(1000 + 7) {
            h.update(piece);
        }
        assert_eq!(h.finish(), xxh64(&bytes));
        assert_eq!(xxh64(&bytes), 0x54db_0390_c0e2_0415);
        fs::write(dir.path().join("f"), &bytes).unwrap();
        let s = stamp_of(&dir.path().join("f")).unwrap();
        assert_eq!(s.size, 200_003);
        assert_eq!(s.hash, format!("xxh64:{:016x}", xxh64(&bytes)));
    }
}
