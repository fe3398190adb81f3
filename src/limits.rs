//! Limits on what a run may ask of the machine, checked before anything large is read or
//! allocated: input files must be regular files of a bounded size, and the memory a case needs is
//! estimated from its problem sizes and compared with the memory available.

use std::path::Path;

/// Largest case file read [bytes]: a case is a page of YAML.
pub const MAX_CASE_BYTES: u64 = 16 << 20;

/// Largest mesh file read [bytes]: the boundary mesh of a plane body with a million nodes takes
/// about 100 MB as ASCII MSH.
pub const MAX_MESH_BYTES: u64 = 1 << 30;

/// Why `path` cannot be read as an input file of at most `max_bytes`, checked without opening it:
/// a FIFO or a device would block or never end, a folder is not a file. `Ok(None)` when it is a
/// regular file of an acceptable size; `Err` when its metadata cannot be read (it does not exist).
pub fn input_file_problem(path: &Path, max_bytes: u64) -> std::io::Result<Option<String>> {
    let meta = std::fs::metadata(path)?;
    let kind = meta.file_type();
    if kind.is_file() {
        return Ok((meta.len() > max_bytes).then(|| {
            format!(
                "it holds {} bytes, more than the {} bytes an input of this kind may have",
                meta.len(),
                max_bytes
            )
        }));
    }
    let what = if kind.is_dir() {
        "a folder"
    } else {
        special_file_kind(&kind)
    };
    Ok(Some(format!("it is {what}, not a regular file")))
}

#[cfg(unix)]
fn special_file_kind(kind: &std::fs::FileType) -> &'static str {
    use std::os::unix::fs::FileTypeExt;
    if kind.is_fifo() {
        "a FIFO (named pipe)"
    } else if kind.is_socket() {
        "a socket"
    } else if kind.is_block_device() || kind.is_char_device() {
        "a device"
    } else {
        "a special file"
    }
}

#[cfg(not(unix))]
fn special_file_kind(_kind: &std::fs::FileType) -> &'static str {
    "a special file"
}
