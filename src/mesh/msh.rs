//! Reader for Gmsh MSH 4.1 files, ASCII and binary (Gmsh reference manual, "MSH file format
//! version 4.1"), written for rollbem: it reads `$MeshFormat`, `$PhysicalNames`, `$Entities`,
//! `$Nodes` and `$Elements` in file order and skips any other section (`msh/sections.rs`).
//! Elements are attached to their physical curve group through their curve entity's physical
//! tags. Point and surface elements are read past: the BEM needs the boundary only.
//!
//! **Node tags.** Every node is kept with its own tag, and elements find their nodes by tag,
//! so a file whose tags are not in file order (a relabelled mesh) reads as the same mesh;
//! duplicate tags and non-finite coordinates are refused, and an element that names a tag the
//! `$Nodes` section does not define is refused too.
//!
//! **Bad input.** Every malformed file is a [`MeshError::Parse`] naming the section and what
//! is wrong; every count read from the file is checked against the bytes left before anything
//! is allocated from it (`msh/cursor.rs`).
//!
//! The result is the raw mesh, in file order; call [`super::validate_and_orient`] (or use
//! [`super::load`]) before using it.

mod cursor;
mod sections;
mod writer;

use super::{BoundaryElement, BoundaryMesh, MeshError, PhysicalGroup};
use cursor::{Cursor, Format};
use sections::element_name;
use std::collections::HashMap;
use std::path::Path;
pub use writer::write_msh41_ascii;

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
    let (format, body) = check_version(bytes, source)?;
    let file = sections::read_sections(bytes, body, format).map_err(|message| MeshError::Parse {
        path: source.to_string(),
        message,
    })?;
    let coordinates = coordinates_by_tag(&file.nodes, source)?;

    let mut builder = MeshBuilder::default();
    for block in &file.curve_blocks {
        // Only curve elements make the boundary of a plane body.
        let expected = match block.element_type {
            1 => 2,
            8 => 3,
            other => {
                return Err(MeshError::UnknownElementType {
                    path: source.to_string(),
                    element: block.elements().next().map_or(0, |(tag, _)| tag),
                    curve: block.curve,
                    kind: element_name(other),
                })
            }
        };
        let group_tag = curve_group(&file.curve_groups, &file.names, block.curve, source)?;
        let group = builder.group(group_tag, &file.names, source)?;
        for (element, tags) in block.elements() {
            debug_assert_eq!(tags.len(), expected);
            let mut nodes = Vec::with_capacity(expected);
            for &tag in tags {
                let xyz = coordinates.get(&tag).ok_or_else(|| MeshError::UnknownNode {
                    path: source.to_string(),
                    element,
                    node: tag,
                })?;
                nodes.push(builder.node(tag, *xyz));
            }
            builder.elements.push(BoundaryElement { nodes, group });
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

/// Checks the `$MeshFormat` section (version 4.1, ASCII or binary with 8-byte `size_t`) and
/// returns how the numbers are stored and where the next section starts.
fn check_version(bytes: &[u8], source: &str) -> Result<(Format, usize), MeshError> {
    let not_msh = |found: String| MeshError::NotMsh4 {
        path: source.to_string(),
        found,
    };
    let start = bytes
        .iter()
        .position(|b| !b.is_ascii_whitespace())
        .unwrap_or(bytes.len());
    let header = b"$MeshFormat";
    let after = bytes.get(start + header.len());
    if !bytes[start..].starts_with(header) || !after.is_some_and(u8::is_ascii_whitespace) {
        return Err(not_msh("no $MeshFormat header".to_string()));
    }
    // The version line: `version file-type data-size`.
    let line_start = bytes[start + header.len()..]
        .iter()
        .position(|b| !b.is_ascii_whitespace())
        .map_or(bytes.len(), |p| start + header.len() + p);
    let line_end = bytes[line_start..]
        .iter()
        .position(|&b| b == b'\n')
        .map_or(bytes.len(), |p| line_start + p);
    let line: String = bytes[line_start..line_end]
        .iter()
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
    let (format, data_end) = match file_type {
        "0" => (Format::Ascii, line_end),
        "1" => {
            // The integer 1, written in the file's byte order, follows the version line.
            let one = bytes
                .get(line_end + 1..line_end + 5)
                .ok_or_else(|| parse_error("$MeshFormat is cut short".into()))?;
            let little_endian = match one {
                [1, 0, 0, 0] => true,
                [0, 0, 0, 1] => false,
                _ => {
                    return Err(parse_error(
                        "the byte-order mark of the binary $MeshFormat is not the integer 1".into(),
                    ))
                }
            };
            (Format::Binary { little_endian }, line_end + 5)
        }
        other => {
            return Err(parse_error(format!(
                "$MeshFormat gives file type {other:?}; expected 0 (ASCII) or 1 (binary)"
            )))
        }
    };
    let mut r = Cursor::new(bytes, data_end, format);
    r.end_marker("MeshFormat")
        .map_err(|e| parse_error(format!("$MeshFormat section: {e} (near byte {})", r.pos)))?;
    Ok((format, r.pos))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn physical_names_are_read_with_spaces_and_only_for_curves() {
        let text = b"$MeshFormat\n4.1 0 8\n$EndMeshFormat\n$PhysicalNames\n3\n1 2 \"contact\"\n\
                     1 5 \"outer free\"\n2 9 \"body\"\n$EndPhysicalNames\n";
        let (format, body) = check_version(text, "m.msh").unwrap();
        assert_eq!(format, Format::Ascii);
        let names = sections::read_sections(text, body, format).unwrap().names;
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
