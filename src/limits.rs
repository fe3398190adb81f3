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

/// What a case asks of the dense linear algebra and the post-processing, from which
/// [`MemoryEstimate::bytes`] follows.
#[derive(Debug, Clone, PartialEq)]
pub struct ProblemSizes {
    /// Nodes m of the contact grid (unknowns p and q at each).
    pub contact_nodes: usize,
    /// Boundary field nodes of each `bem` body (A, B); `None` for other models.
    pub bem_nodes: [Option<usize>; 2],
    /// Interior points asked by `output.interior` (0 when none).
    pub interior_points: usize,
    /// Whether VTK files are written (they hold every interior point a second time, as XML).
    pub vtk: bool,
}

/// Peak memory per squared contact node [bytes]: about 18 dense m×m matrices of doubles live at
/// once (the flexibility of the pair and of body B, the slip operators, the half-space kernels
/// while they are built, the Newton matrix factored in place, the strain operators). The peak
/// RSS of half-space pairs at m = 300–1800 gives 110–150 bytes per m² (see [`MemoryEstimate`]).
pub const BYTES_PER_CONTACT_NODE_SQUARED: f64 = 180.0;

/// Peak memory per squared boundary unknown n = 2 × field nodes of the largest `bem` body
/// [bytes]: the BEM matrices H and G, two n × n matrices of doubles at the assembly's end (their
/// rows are gathered a chunk of collocation points at a time, the system matrix is made in H's
/// place and G is freed before the LU; only a body's condensed flexibility is kept; two bodies
/// are built side by side only when both fit in a quarter of the memory,
/// [`bem_builds_fit_side_by_side`], else one after the other). The peak RSS of rollers of
/// 490–2090 nodes gives 10–16 bytes per n² (the calibration table of docs/reliability.md), an
/// error-controlled run on a bore with its bisected free boundary up to 20 (its contact
/// problem beside them).
pub const BYTES_PER_BEM_UNKNOWN_SQUARED: f64 = 28.0;

/// Memory per interior point with VTK output [bytes]: the fields, the CSV rows and the arrays
/// of interior_<body>.vtu (src/output/vtk.rs streams the file from them). Measured 215–230 bytes
/// (grids of 300² and 600² points).
pub const BYTES_PER_INTERIOR_POINT_VTK: f64 = 260.0;

/// Memory per interior point without VTK output [bytes]. Measured 50–100 bytes.
pub const BYTES_PER_INTERIOR_POINT: f64 = 130.0;

/// Memory of the program itself, its small tables and thread stacks [bytes].
pub const BASE_BYTES: f64 = 16e6;

/// Memory a case will need at its peak, term by term [bytes].
///
/// Calibrated against the peak resident set size (`/usr/bin/time -v`, "Maximum resident set
/// size") of `rollbem run` on grids and meshes of several sizes; tests/input/memory.rs checks
/// again that the estimate stays above the measured peak and within a factor 2 of it.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct MemoryEstimate {
    /// Dense contact matrices [bytes].
    pub contact: f64,
    /// BEM matrices of the largest `bem` body [bytes].
    pub bem: f64,
    /// Interior fields and their files [bytes].
    pub interior: f64,
}

impl MemoryEstimate {
    /// The estimate of the sizes of a case.
    pub fn of(sizes: &ProblemSizes) -> Self {
        let m = sizes.contact_nodes as f64;
        let largest_bem = sizes.bem_nodes.iter().flatten().copied().max().unwrap_or(0);
        let n = 2.0 * largest_bem as f64;
        let per_point = if sizes.vtk {
            BYTES_PER_INTERIOR_POINT_VTK
        } else {
            BYTES_PER_INTERIOR_POINT
        };
        Self {
            contact: BYTES_PER_CONTACT_NODE_SQUARED * m * m,
            bem: BYTES_PER_BEM_UNKNOWN_SQUARED * n * n,
            interior: per_point * sizes.interior_points as f64,
        }
    }

    /// The whole estimate [bytes].
    pub fn bytes(&self) -> f64 {
        BASE_BYTES + self.contact + self.bem + self.interior
    }
}

/// Whether two bodies of `nodes` boundary nodes each (None: a closed-form model, no BEM
/// matrices) may be built side by side, on a thread each: unless both are BEM bodies whose
/// matrices together would take more than a quarter of the memory available. The estimate
/// ([`MemoryEstimate`]) counts the larger body only, as one after the other; a side-by-side
/// build stays far below the memory it is checked against.
pub fn bem_builds_fit_side_by_side(nodes: [Option<usize>; 2]) -> bool {
    let [Some(a), Some(b)] = nodes else {
        return true;
    };
    let bytes = |n: usize| BYTES_PER_BEM_UNKNOWN_SQUARED * (2.0 * n as f64).powi(2);
    let available = available_memory().unwrap_or(FALLBACK_AVAILABLE_BYTES);
    bytes(a) + bytes(b) <= 0.25 * available
}

/// Memory the run may use [bytes]: `MemAvailable` of /proc/meminfo, lowered to what the control
/// group (a container, a batch job) still allows and to the address space the process may
/// still reserve under its own limit (`ulimit -v`, [`address_space_left`]). `None` where none
/// can be read.
pub fn available_memory() -> Option<f64> {
    let system = system_memory_available();
    match (system, address_space_left()) {
        (Some(a), Some(b)) => Some(a.min(b)),
        (a, b) => a.or(b),
    }
}

/// What the process may still reserve under its address-space limit [bytes]: the soft limit of
/// /proc/self/limits ("Max address space", `ulimit -v`, as batch schedulers set it) less the
/// address space it holds now (`VmSize` of /proc/self/status). Reserved address space is what
/// the limit counts, not resident memory: a matrix is refused by the allocator the moment it
/// does not fit, touched or not. `None` without a limit (or where the files cannot be read).
pub fn address_space_left() -> Option<f64> {
    let limits = std::fs::read_to_string("/proc/self/limits").ok()?;
    let status = std::fs::read_to_string("/proc/self/status").ok()?;
    let limit = address_space_limit(&limits)?;
    let held = status_kilobytes(&status, "VmSize:")? * 1024.0;
    Some((limit - held).max(0.0))
}

/// The soft "Max address space" limit of a /proc/self/limits text [bytes]; `None` when it is
/// "unlimited" or absent.
fn address_space_limit(limits: &str) -> Option<f64> {
    let line = limits.lines().find(|l| l.starts_with("Max address space"))?;
    let soft = line.trim_start_matches("Max address space").split_whitespace().next()?;
    soft.parse::<f64>().ok()
}

/// A "Name:   123 kB" field of a /proc status text [kB].
fn status_kilobytes(status: &str, field: &str) -> Option<f64> {
    status
        .lines()
        .find_map(|l| l.strip_prefix(field))
        .and_then(|v| v.trim().trim_end_matches("kB").trim().parse::<f64>().ok())
}

/// `MemAvailable` of /proc/meminfo, lowered to what the control group allows [bytes].
fn system_memory_available() -> Option<f64> {
    let meminfo = std::fs::read_to_string("/proc/meminfo").ok();
    let available = meminfo
        .as_deref()
        .and_then(|text| status_kilobytes(text, "MemAvailable:"))
        .map(|kb| kb * 1024.0);
    let read = |p: &str| {
        std::fs::read_to_string(p)
            .ok()
            .and_then(|s| s.trim().parse::<f64>().ok())
    };
    // cgroup v2: the limit (or "max") less what is in use.
    let cgroup = read("/sys/fs/cgroup/memory.max")
        .zip(read("/sys/fs/cgroup/memory.current"))
        .map(|(max, current)| (max - current).max(0.0));
    match (available, cgroup) {
        (Some(a), Some(c)) => Some(a.min(c)),
        (a, c) => a.or(c),
    }
}

/// Memory assumed available where the system does not say [bytes]: a small workstation.
pub const FALLBACK_AVAILABLE_BYTES: f64 = 8.0 * (1u64 << 30) as f64;

/// A byte count for people: "887 MB", "22.5 TB".
pub fn human_bytes(bytes: f64) -> String {
    let units = ["bytes", "kB", "MB", "GB", "TB", "PB", "EB"];
    let mut v = bytes;
    let mut u = 0;
    while v >= 1000.0 && u + 1 < units.len() {
        v /= 1000.0;
        u += 1;
    }
    if u == 0 {
        format!("{v:.0} {}", units[u])
    } else if v < 10.0 {
        format!("{v:.1} {}", units[u])
    } else {
        format!("{v:.0} {}", units[u])
    }
}

/// A case that needs more memory than the machine has.
#[derive(Debug, thiserror::Error)]
#[error(
    "{case}: this case needs about {} of memory ({breakdown}), more than the {} available; {advice}",
    human_bytes(*needed),
    human_bytes(*available)
)]
pub struct MemoryError {
    /// Case file.
    pub case: std::path::PathBuf,
    /// The estimate [bytes].
    pub needed: f64,
    /// What is available [bytes].
    pub available: f64,
    /// The estimate term by term, with the sizes behind it.
    pub breakdown: String,
    /// The key (or mesh) to change, and to what.
    pub advice: String,
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A closed-form body never holds the other's build back; two small BEM bodies go side by
    /// side; two of a million nodes (1.9e14 bytes of matrices together) never do.
    #[test]
    fn bem_builds_go_side_by_side_only_when_both_fit_in_a_quarter_of_the_memory() {
        assert!(bem_builds_fit_side_by_side([None, Some(1_000_000)]));
        assert!(bem_builds_fit_side_by_side([None, None]));
        assert!(bem_builds_fit_side_by_side([Some(400), Some(500)]));
        assert!(!bem_builds_fit_side_by_side([Some(1_000_000), Some(1_000_000)]));
    }

    /// The limit is read from the soft column of /proc/self/limits, "unlimited" is no limit,
    /// and the kB fields of /proc texts parse (texts as Linux 6 writes them).
    #[test]
    fn the_address_space_limit_and_the_held_size_are_read_from_proc() {
        let header = "Limit                     Soft Limit           Hard Limit           Units     \n";
        let limited =
            format!("{header}Max address space         2048000000           unlimited            bytes     \n");
        assert_eq!(address_space_limit(&limited), Some(2.048e9));
        let unlimited =
            format!("{header}Max address space         unlimited            unlimited            bytes     \n");
        assert_eq!(address_space_limit(&unlimited), None);
        let status = "Name:\trollbem\nVmPeak:\t  123456 kB\nVmSize:\t   98304 kB\n";
        assert_eq!(status_kilobytes(status, "VmSize:"), Some(98304.0));
        assert_eq!(status_kilobytes(status, "VmRSS:"), None);
    }
}
