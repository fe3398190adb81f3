//! Reader for Gmsh MSH 4.1 files (ASCII and binary), built on the `mshio` crate.
//!
//! `mshio` parses `$Entities`, `$Nodes` and `$Elements` but skips `$PhysicalNames`, so that
//! section is read here from the raw bytes (it is ASCII text in binary files too). Elements are
//! attached to their physical curve group through their curve entity's physical tags.
//! Point and surface elements are ignored: the BEM needs the boundary only.
//!
//! **Node tags.** `mshio` keeps a block's node tags only when the file's tags are sparse, and
//! then in a map that silently merges duplicates; with contiguous tags it assumes file order. A
//! file whose tags are contiguous but not in file order (a relabelled mesh) would then connect
//! the elements to the wrong nodes. So the `$Nodes` section is read here again ([`node_records`]),
//! every node by its own tag: duplicate tags and non-finite coordinates are refused, and an
//! element that names a tag the section does not define is refused too.
//!
//! The result is the raw mesh, in file order; call [`super::validate_and_orient`] (or use
//! [`super::load`]) before using it.

use super::{BoundaryElement, BoundaryMesh, MeshError, PhysicalGroup};
use mshio::ElementType;
use std::collections::HashMap;
use std::path::Path;

/// Reads the MSH 4.1 file at `path` (ASCII or binary) into a raw [`BoundaryMesh`].
pub fn read_msh(path: &Path) -> Result<BoundaryMesh, MeshError> {
    let label = path.display().to_string();
    let io_error = |source: std::io::Error| {
        if source.kind() == std::io::ErrorKind::NotFound {
            MeshError::NotFound { path: label.clone() }
        } else {
            MeshError::Io {
                path: label.clone(),
                source,
            }
        }
    };
    // Checked before opening: reading a FIFO would block for ever.
    if let Some(kind) = crate::limits::input_file_problem(path, crate::limits::MAX_MESH_BYTES).map_err(io_error)? {
        return Err(MeshError::NotRegularFile { path: label, kind });
    }
    let bytes = std::fs::read(path).map_err(io_error)?;
    parse_msh_bytes(&bytes, &label)
}

/// Parses the bytes of an MSH 4.1 file (ASCII or binary); `source` labels the messages.
pub fn parse_msh_bytes(bytes: &[u8], source: &str) -> Result<BoundaryMesh, MeshError> {
    let format = check_version(bytes, source)?;
    let names = physical_names(bytes);
    // Checked before `mshio` sees them: it computes `count - 1` in unsigned arithmetic, which
    // overflows on an empty section.
    check_section_counts(bytes, format).map_err(|message| MeshError::Parse {
        path: source.to_string(),
        message,
    })?;
    let records = node_records(bytes, format).map_err(|message| MeshError::Parse {
        path: source.to_string(),
        message: format!("$Nodes section: {message}"),
    })?;
    let msh = parse_with_mshio(bytes, source)?;

    // Physical tags of every curve entity.
    let curve_groups: HashMap<i32, Vec<i32>> = msh
        .data
        .entities
        .as_ref()
        .map(|ent| {
            ent.curves
                .iter()
                .map(|c| (c.tag, c.physical_tags.iter().map(|t| t.abs()).collect()))
                .collect()
        })
        .unwrap_or_default();

    // Both readers must have seen the same section.
    let counted: usize = msh
        .data
        .nodes
        .as_ref()
        .map_or(0, |n| n.node_blocks.iter().map(|b| b.nodes.len()).sum());
    if counted != records.len() {
        return Err(MeshError::Parse {
            path: source.to_string(),
            message: format!(
                "the $Nodes section holds {} nodes by one reading and {counted} by another; the file is corrupt",
                records.len()
            ),
        });
    }
    let coordinates = coordinates_by_tag(&records, source)?;

    let mut builder = MeshBuilder::default();
    if let Some(elements) = &msh.data.elements {
        for block in &elements.element_blocks {
            // Only curve elements make the boundary of a plane body.
            if block.entity_dim != 1 {
                continue;
            }
            let expected = match block.element_type {
                ElementType::Lin2 => 2,
                ElementType::Lin3 => 3,
                other => {
                    return Err(MeshError::UnknownElementType {
                        path: source.to_string(),
                        element: block.elements.first().map_or(0, |e| e.element_tag),
                        curve: block.entity_tag,
                        kind: format!("{other:?}"),
                    })
                }
            };
            let group_tag = curve_group(&curve_groups, &names, block.entity_tag, source)?;
            let group = builder.group(group_tag, &names, source)?;
            for element in &block.elements {
                if element.nodes.len() != expected {
                    return Err(MeshError::Parse {
                        path: source.to_string(),
                        message: format!(
                            "element {} has {} nodes, expected {expected}",
                            element.element_tag,
                            element.nodes.len()
                        ),
                    });
                }
                let mut nodes = Vec::with_capacity(expected);
                for &tag in &element.nodes {
                    let xyz = coordinates.get(&tag).ok_or_else(|| MeshError::UnknownNode {
                        path: source.to_string(),
                        element: element.element_tag,
                        node: tag,
                    })?;
                    nodes.push(builder.node(tag, *xyz));
                }
                builder.elements.push(BoundaryElement { nodes, group });
            }
        }
    }
    if builder.elements.is_empty() {
        return Err(MeshError::NoBoundaryElements {
            path: source.to_string(),
        });
    }
    builder.finish(source)
}

/// Node coordinates by tag; a tag given twice or a coordinate that is not finite is refused.
fn coordinates_by_tag(records: &[(u64, [f64; 3])], source: &str) -> Result<HashMap<u64, [f64; 3]>, MeshError> {
    let mut coordinates = HashMap::with_capacity(records.len());
    for &(tag, xyz) in records {
        if xyz.iter().any(|v| !v.is_finite()) {
            return Err(MeshError::NonFiniteNode {
                path: source.to_string(),
                node: tag,
                xyz,
            });
        }
        if let Some(first) = coordinates.insert(tag, xyz) {
            return Err(MeshError::DuplicateNode {
                path: source.to_string(),
                node: tag,
                first,
                second: xyz,
            });
        }
    }
    Ok(coordinates)
}

/// How the numbers of a file are stored.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) enum Format {
    /// Text.
    Ascii,
    /// Binary, little-endian if `true`.
    Binary {
        /// Byte order of the numbers.
        little_endian: bool,
    },
}

/// A cursor over the numbers of a section, ASCII tokens or binary values alike. Never allocates
/// from a count read in the file: every count is checked against the bytes left.
struct Numbers<'a> {
    bytes: &'a [u8],
    pos: usize,
    format: Format,
}

impl<'a> Numbers<'a> {
    fn bytes_left(&self) -> usize {
        self.bytes.len().saturating_sub(self.pos)
    }

    /// The next whitespace-separated ASCII token.
    fn token(&mut self) -> Result<&'a str, String> {
        let rest = &self.bytes[self.pos.min(self.bytes.len())..];
        let start = rest
            .iter()
            .position(|b| !b.is_ascii_whitespace())
            .ok_or("the section ends early")?;
        let len = rest[start..]
            .iter()
            .position(|b| b.is_ascii_whitespace())
            .unwrap_or(rest.len() - start);
        self.pos += start + len;
        std::str::from_utf8(&rest[start..start + len]).map_err(|_| "a number is not text".to_string())
    }

    fn raw<const N: usize>(&mut self) -> Result<[u8; N], String> {
        let end = self.pos.checked_add(N).filter(|&e| e <= self.bytes.len());
        let end = end.ok_or("the section ends early")?;
        let mut out = [0; N];
        out.copy_from_slice(&self.bytes[self.pos..end]);
        self.pos = end;
        Ok(out)
    }

    /// One number: a token in ASCII files, `N` bytes in the file's byte order in binary ones;
    /// `kind` says what the token must be.
    fn number<T: std::str::FromStr, const N: usize>(
        &mut self,
        what: &str,
        kind: &str,
        from_le: fn([u8; N]) -> T,
        from_be: fn([u8; N]) -> T,
    ) -> Result<T, String> {
        match self.format {
            Format::Ascii => {
                let t = self.token()?;
                t.parse().map_err(|_| format!("{what}: `{t}` is not {kind}"))
            }
            Format::Binary { little_endian } => {
                let b = self.raw::<N>()?;
                Ok(if little_endian { from_le(b) } else { from_be(b) })
            }
        }
    }

    /// A `size_t` (8 bytes in binary files).
    fn size(&mut self, what: &str) -> Result<u64, String> {
        self.number(what, "a non-negative integer", u64::from_le_bytes, u64::from_be_bytes)
    }

    /// An `int` (4 bytes in binary files).
    fn int(&mut self, what: &str) -> Result<i32, String> {
        self.number(what, "an integer", i32::from_le_bytes, i32::from_be_bytes)
    }

    /// A `double`.
    fn double(&mut self, what: &str) -> Result<f64, String> {
        self.number(what, "a number", f64::from_le_bytes, f64::from_be_bytes)
    }

    /// A count of items of at least `item_bytes` bytes each, refused if the rest of the file
    /// cannot hold that many.
    fn count(&mut self, what: &str, item_bytes: usize) -> Result<usize, String> {
        let n = self.size(what)?;
        let fits = usize::try_from(n)
            .ok()
            .filter(|&n| n.saturating_mul(item_bytes) <= self.bytes_left());
        fits.ok_or_else(|| format!("{what} = {n}, more than the rest of the file can hold"))
    }
}

/// Start of the body of section `name`: just after its `$Name` line, which opens a line.
fn section_body(bytes: &[u8], name: &str) -> Option<usize> {
    let key = name.as_bytes();
    let mut from = 0;
    while let Some(p) = bytes[from..].windows(key.len()).position(|w| w == key) {
        let at = from + p;
        let after = &bytes[at + key.len()..];
        let line_start = at == 0 || matches!(bytes[at - 1], b'\n' | b'\r' | b' ' | b'\t');
        let eol = if after.starts_with(b"\r\n") {
            Some(2)
        } else if after.starts_with(b"\n") {
            Some(1)
        } else {
            None
        };
        if let (true, Some(eol)) = (line_start, eol) {
            return Some(at + key.len() + eol);
        }
        from = at + 1;
    }
    None
}

/// Every node of the `$Nodes` section as (tag, [x, y, z]), in file order, with the tags as
/// written (MSH 4.1: a header `numEntityBlocks numNodes minNodeTag maxNodeTag`, then per block
/// `entityDim entityTag parametric numNodesInBlock`, its tags, then its coordinates).
/// Parametric coordinates (one per dimension of the entity) are skipped.
pub(crate) fn node_records(bytes: &[u8], format: Format) -> Result<Vec<(u64, [f64; 3])>, String> {
    let Some(pos) = section_body(bytes, "$Nodes") else {
        return Ok(Vec::new());
    };
    let mut r = Numbers { bytes, pos, format };
    // Smallest size of a block header and of a node (tag and three coordinates) in either format.
    let (block_bytes, node_bytes) = match format {
        Format::Ascii => (8, 8),
        Format::Binary { .. } => (20, 32),
    };
    let blocks = r.count("number of node blocks", block_bytes)?;
    let total = r.count("number of nodes", 0)?;
    if total == 0 {
        return Err("the header announces no nodes".into());
    }
    let _min_tag = r.size("minimum node tag")?;
    let _max_tag = r.size("maximum node tag")?;
    let mut records = Vec::new();
    for b in 0..blocks {
        let dim = r.int("entity dimension")?;
        let _entity = r.int("entity tag")?;
        let parametric = r.int("parametric flag")?;
        let n = r.count("number of nodes in block", node_bytes)?;
        let parameters = match (parametric, dim) {
            (0, _) => 0,
            (1, d @ 0..=3) => d as usize,
            _ => {
                return Err(format!(
                    "block {}: parametric flag {parametric} on dimension {dim}",
                    b + 1
                ))
            }
        };
        let mut tags = Vec::with_capacity(n);
        for _ in 0..n {
            let tag = r.size("node tag")?;
            if tag == 0 {
                return Err(format!("block {}: node tag 0 (tags start at 1)", b + 1));
            }
            tags.push(tag);
        }
        for tag in tags {
            let xyz = [r.double("x")?, r.double("y")?, r.double("z")?];
            for _ in 0..parameters {
                r.double("parametric coordinate")?;
            }
            records.push((tag, xyz));
        }
    }
    if records.len() != total {
        return Err(format!(
            "the header announces {total} nodes but the blocks hold {}",
            records.len()
        ));
    }
    Ok(records)
}

/// Every `$Nodes` and `$Elements` header (`numEntityBlocks count minTag maxTag`) must announce
/// at least one node or element. All of them: `mshio` parses every section it meets (and only
/// then refuses a second one), wherever the previous section ended.
fn check_section_counts(bytes: &[u8], format: Format) -> Result<(), String> {
    for (name, what) in [("$Nodes", "nodes"), ("$Elements", "elements")] {
        let key = name.as_bytes();
        for (at, _) in bytes.windows(key.len()).enumerate().filter(|(_, w)| *w == key) {
            let after = &bytes[at + key.len()..];
            let eol = match after {
                [b'\r', b'\n', ..] => 2,
                [b'\n', ..] => 1,
                _ => continue,
            };
            let mut r = Numbers {
                bytes,
                pos: at + key.len() + eol,
                format,
            };
            // A header that cannot be read is left to the parsers, which say where.
            if let (Ok(_), Ok(0)) = (r.size("blocks"), r.size(what)) {
                return Err(format!("{name} section: the header announces no {what}"));
            }
        }
    }
    Ok(())
}

/// Accumulates the boundary part of the file: only nodes used by curve elements are kept.
#[derive(Default)]
struct MeshBuilder {
    index_of_tag: HashMap<u64, usize>,
    tags: Vec<u64>,
    xyz: Vec<[f64; 3]>,
    elements: Vec<BoundaryElement>,
    groups: Vec<PhysicalGroup>,
}

impl MeshBuilder {
    fn node(&mut self, tag: u64, xyz: [f64; 3]) -> usize {
        *self.index_of_tag.entry(tag).or_insert_with(|| {
            self.tags.push(tag);
            self.xyz.push(xyz);
            self.xyz.len() - 1
        })
    }

    fn group(&mut self, tag: i32, names: &HashMap<i32, String>, source: &str) -> Result<usize, MeshError> {
        if let Some(i) = self.groups.iter().position(|g| g.tag == tag) {
            return Ok(i);
        }
        let name = names.get(&tag).ok_or_else(|| MeshError::MissingPhysicalName {
            path: source.to_string(),
            tag,
        })?;
        self.groups.push(PhysicalGroup {
            tag,
            name: name.clone(),
        });
        Ok(self.groups.len() - 1)
    }

    fn finish(mut self, source: &str) -> Result<BoundaryMesh, MeshError> {
        let nodes: Vec<[f64; 2]> = self.xyz.iter().map(|p| [p[0], p[1]]).collect();
        let mut mesh = BoundaryMesh::new(nodes, Vec::new(), Vec::new(), source);
        let tolerance = 1e-9 * mesh.size().max(f64::MIN_POSITIVE);
        for (p, tag) in self.xyz.iter().zip(&self.tags) {
            if p[2].abs() > tolerance {
                return Err(MeshError::NotPlanar {
                    path: source.to_string(),
                    node: *tag,
                    z: p[2],
                });
            }
        }
        // Groups in increasing tag order, so that the order does not depend on the file layout.
        let mut order: Vec<usize> = (0..self.groups.len()).collect();
        order.sort_by_key(|&g| self.groups[g].tag);
        let mut new_index = vec![0; order.len()];
        for (new, &old) in order.iter().enumerate() {
            new_index[old] = new;
        }
        for e in &mut self.elements {
            e.group = new_index[e.group];
        }
        mesh.groups = order.iter().map(|&g| self.groups[g].clone()).collect();
        mesh.elements = self.elements;
        Ok(mesh)
    }
}

/// The one physical group of curve `curve`, or the reason why there is not exactly one.
fn curve_group(
    curve_groups: &HashMap<i32, Vec<i32>>,
    names: &HashMap<i32, String>,
    curve: i32,
    source: &str,
) -> Result<i32, MeshError> {
    let tags = curve_groups.get(&curve).map(Vec::as_slice).unwrap_or(&[]);
    match tags {
        [] => Err(MeshError::UntaggedCurve {
            path: source.to_string(),
            curve,
        }),
        [one] => Ok(*one),
        many => Err(MeshError::AmbiguousGroup {
            path: source.to_string(),
            curve,
            groups: many
                .iter()
                .map(|t| names.get(t).cloned().unwrap_or_else(|| format!("tag {t}")))
                .collect::<Vec<_>>()
                .join(", "),
        }),
    }
}

/// Checks the `$MeshFormat` header (version 4.1, ASCII or binary with 8-byte `size_t`) and
/// returns how the numbers are stored.
fn check_version(bytes: &[u8], source: &str) -> Result<Format, MeshError> {
    let not_msh = |found: String| MeshError::NotMsh4 {
        path: source.to_string(),
        found,
    };
    let start = bytes
        .iter()
        .position(|b| !b.is_ascii_whitespace())
        .unwrap_or(bytes.len());
    let rest = &bytes[start..];
    let header = b"$MeshFormat";
    if !rest.starts_with(header) {
        return Err(not_msh("no $MeshFormat header".to_string()));
    }
    let line: String = rest[header.len()..]
        .iter()
        .skip_while(|b| b.is_ascii_whitespace())
        .take_while(|&&b| b != b'\n' && b != b'\r')
        .take(80)
        .map(|&b| b as char)
        .collect();
    let mut words = line.split_whitespace();
    let version = words.next().unwrap_or("");
    if version.parse::<f64>().ok() != Some(4.1) {
        return Err(not_msh(format!("MSH version {version:?}")));
    }
    let parse_error = |message: String| MeshError::Parse {
        path: source.to_string(),
        message,
    };
    let (file_type, data_size) = (words.next().unwrap_or(""), words.next().unwrap_or(""));
    if data_size != "8" {
        return Err(parse_error(format!(
            "$MeshFormat gives a data size of {data_size:?}; rollbem reads Gmsh's default 8-byte size_t"
        )));
    }
    match file_type {
        "0" => Ok(Format::Ascii),
        "1" => {
            // The integer 1, written in the file's byte order, follows the header line.
            let version_line = rest.iter().position(|&b| b == b'\n').map(|p| p + 1);
            let line_end = version_line
                .and_then(|v| rest[v..].iter().position(|&b| b == b'\n').map(|p| v + p))
                .ok_or_else(|| parse_error("$MeshFormat is cut short".into()))?;
            let one = rest
                .get(line_end + 1..line_end + 5)
                .ok_or_else(|| parse_error("$MeshFormat is cut short".into()))?;
            match one {
                [1, 0, 0, 0] => Ok(Format::Binary { little_endian: true }),
                [0, 0, 0, 1] => Ok(Format::Binary { little_endian: false }),
                _ => Err(parse_error(
                    "the byte-order mark of the binary $MeshFormat is not the integer 1".into(),
                )),
            }
        }
        other => Err(parse_error(format!(
            "$MeshFormat gives file type {other:?}; expected 0 (ASCII) or 1 (binary)"
        ))),
    }
}

/// Parses with `mshio`, turning its errors (and the panics it still has for unsupported binary
/// type sizes) into [`MeshError::Parse`] without its hex dump.
fn parse_with_mshio(bytes: &[u8], source: &str) -> Result<mshio::MshFile<u64, i32, f64>, MeshError> {
    let parse_error = |message: String| MeshError::Parse {
        path: source.to_string(),
        message,
    };
    let result = std::panic::catch_unwind(|| {
        mshio::parse_msh_bytes(bytes).map_err(|e| {
            let trace = e.filtered_backtrace();
            let offset = trace.first().map_or(0, |(rest, _)| bytes.len() - rest.len());
            let mut parts: Vec<String> = trace.iter().rev().map(|(_, kind)| kind.to_string()).collect();
            parts.dedup();
            format!("{} (near byte {offset})", parts.join(": "))
        })
    });
    match result {
        Ok(Ok(file)) => Ok(file),
        Ok(Err(message)) => Err(parse_error(message)),
        Err(_) => Err(parse_error(
            "unsupported MSH data sizes (rollbem reads Gmsh's default 8-byte size_t, 4-byte int, \
             8-byte double)"
                .to_string(),
        )),
    }
}

/// Physical names of dimension 1 (curves) by tag, from the `$PhysicalNames` section.
///
/// Format (ASCII in both ASCII and binary files):
/// ```text
/// $PhysicalNames
/// 2
/// 1 3 "contact"
/// 2 7 "body"
/// $EndPhysicalNames
/// ```
fn physical_names(bytes: &[u8]) -> HashMap<i32, String> {
    let mut names = HashMap::new();
    let key = b"$PhysicalNames";
    let Some(start) = bytes
        .windows(key.len())
        .enumerate()
        .find(|(i, w)| *w == key && (*i == 0 || bytes[i - 1] == b'\n'))
        .map(|(i, _)| i + key.len())
    else {
        return names;
    };
    let end_key = b"$EndPhysicalNames";
    let end = bytes[start..]
        .windows(end_key.len())
        .position(|w| w == end_key)
        .map_or(bytes.len(), |p| start + p);
    let text = String::from_utf8_lossy(&bytes[start..end]);
    // Skip the count line; each following line is `dim tag "name"`.
    for line in text.lines().map(str::trim).filter(|l| !l.is_empty()).skip(1) {
        let mut parts = line.splitn(3, char::is_whitespace);
        let (Some(dim), Some(tag), Some(name)) = (parts.next(), parts.next(), parts.next()) else {
            continue;
        };
        let (Ok(dim), Ok(tag)) = (dim.parse::<i32>(), tag.parse::<i32>()) else {
            continue;
        };
        if dim == 1 {
            names.insert(tag, name.trim().trim_matches('"').to_string());
        }
    }
    names
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn physical_names_are_read_with_spaces_and_only_for_curves() {
        let text = b"$MeshFormat\n4.1 0 8\n$EndMeshFormat\n$PhysicalNames\n3\n1 2 \"contact\"\n\
                     1 5 \"outer free\"\n2 9 \"body\"\n$EndPhysicalNames\n";
        let names = physical_names(text);
        assert_eq!(names.len(), 2);
        assert_eq!(names[&2], "contact");
        assert_eq!(names[&5], "outer free");
    }

    #[test]
    fn version_2_files_are_rejected_with_the_version() {
        let err = check_version(b"$MeshFormat\n2.2 0 8\n$EndMeshFormat\n", "m.msh").unwrap_err();
        assert!(matches!(err, MeshError::NotMsh4 { .. }));
        assert!(err.to_string().contains("2.2"), "{err}");
        let err = check_version(b"solid cube\n", "m.stl").unwrap_err();
        assert!(err.to_string().contains("no $MeshFormat"), "{err}");
    }
}

#[cfg(test)]
mod compare_with_new {
    use std::path::Path;

    fn files() -> Vec<(String, Vec<u8>)> {
        let root = Path::new(env!("CARGO_MANIFEST_DIR"));
        let mut out = Vec::new();
        for dir in ["meshes", "tests/data/msh"] {
            for e in std::fs::read_dir(root.join(dir)).unwrap() {
                let p = e.unwrap().path();
                if p.extension().is_some_and(|x| x == "msh") {
                    out.push((p.display().to_string(), std::fs::read(&p).unwrap()));
                }
            }
        }
        let ascii = b"$MeshFormat\n4.1 0 8\n$EndMeshFormat\n".as_slice();
        let binary = b"$MeshFormat\n4.1 1 8\n\x01\x00\x00\x00\n$EndMeshFormat\n".as_slice();
        for e in std::fs::read_dir(root.join("tests/data/msh/fuzz")).unwrap() {
            let p = e.unwrap().path();
            let mut b = if p.to_string_lossy().contains("ascii") { ascii } else { binary }.to_vec();
            b.extend(std::fs::read(&p).unwrap());
            out.push((p.display().to_string(), b));
        }
        out.sort();
        out
    }

    #[test]
    fn old_and_new_readers_agree() {
        let mut report = String::new();
        let mut same = 0;
        for (name, bytes) in files() {
            let old = super::parse_msh_bytes(&bytes, &name);
            let new = crate::mesh::msh::parse_msh_bytes(&bytes, &name);
            // Also through validation, as mesh::load does.
            let checked = |r: &Result<crate::mesh::BoundaryMesh, crate::mesh::MeshError>| match r {
                Ok(m) => {
                    let mut m = m.clone();
                    format!("{:?}", crate::mesh::validate_and_orient(&mut m).map(|n| (n, m)))
                }
                Err(e) => format!("ERR {e}"),
            };
            let (o, n) = (checked(&old), checked(&new));
            match (&old, &new) {
                (Ok(a), Ok(b)) if a == b && o == n => same += 1,
                _ => {
                    report += &format!("{name}\n  old: {}\n  new: {}\n", &o[..o.len().min(300)], &n[..n.len().min(300)]);
                }
            }
        }
        std::fs::write("/tmp/compare_files.txt", format!("{same} identical Ok\n{report}")).unwrap();
    }

    #[test]
    fn old_and_new_readers_agree_on_mutations() {
        let mut state: u64 = 0x1234_5678;
        let mut next = move || {
            state = state.wrapping_mul(6364136223846793005).wrapping_add(1442695040888963407);
            state >> 33
        };
        let files = files();
        let (mut both_ok, mut both_err, mut differ) = (0, 0, Vec::new());
        for round in 0..20000 {
            let (name, orig) = &files[next() as usize % files.len()];
            let mut bytes = orig.clone();
            for _ in 0..1 + next() % 3 {
                let i = next() as usize % bytes.len();
                match next() % 4 {
                    0 => bytes[i] = next() as u8,
                    1 => {
                        bytes.remove(i);
                    }
                    2 => bytes.insert(i, b"0123456789 \n-.e$"[next() as usize % 16]),
                    _ => bytes.truncate(i),
                }
            }
            let old = std::panic::catch_unwind(|| super::parse_msh_bytes(&bytes, name));
            let new = crate::mesh::msh::parse_msh_bytes(&bytes, name);
            match (old, &new) {
                (Ok(Ok(a)), Ok(b)) if a == *b => both_ok += 1,
                (Ok(Err(_)), Err(_)) | (Err(_), Err(_)) => both_err += 1,
                (o, n) => differ.push(format!(
                    "{}{}",
                    if n.is_ok() {
                        std::fs::write(format!("/tmp/mut_{round}.msh"), &bytes).unwrap();
                        ""
                    } else {
                        ""
                    },
                    format!(
                    "round {round} {name}:\n  old: {}\n  new: {}",
                    match o {
                        Ok(Ok(_)) => "Ok".to_string(),
                        Ok(Err(e)) => format!("ERR {e}"),
                        Err(_) => "PANIC".into(),
                    },
                    match n {
                        Ok(_) => "Ok".to_string(),
                        Err(e) => format!("ERR {e}"),
                    }
                ))),
            }
        }
        std::fs::write(
            "/tmp/compare_mutations.txt",
            format!("both ok {both_ok}, both err {both_err}, differ {}\n{}", differ.len(), differ.join("\n")),
        )
        .unwrap();
    }
}
