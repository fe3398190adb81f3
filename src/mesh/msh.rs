//! Reader for Gmsh MSH 4.1 files (ASCII and binary), built on the `mshio` crate.
//!
//! `mshio` parses `$Entities`, `$Nodes` and `$Elements` but skips `$PhysicalNames`, so that
//! section is read here from the raw bytes (it is ASCII text in binary files too). Elements are
//! attached to their physical curve group through their curve entity's physical tags.
//! Point and surface elements are ignored: the BEM needs the boundary only.
//!
//! **Node tags.** When a file's node tags are contiguous, `mshio` does not keep them, and the
//! tags are taken as consecutive in file order starting at the minimum tag. Gmsh always writes
//! contiguous tags in this order; a hand-edited file that breaks the assumption shows up as an
//! open or branching loop in [`super::check::validate_and_orient`].
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
    let bytes = std::fs::read(path).map_err(|source| {
        if source.kind() == std::io::ErrorKind::NotFound {
            MeshError::NotFound { path: label.clone() }
        } else {
            MeshError::Io {
                path: label.clone(),
                source,
            }
        }
    })?;
    parse_msh_bytes(&bytes, &label)
}

/// Parses the bytes of an MSH 4.1 file (ASCII or binary); `source` labels the messages.
pub fn parse_msh_bytes(bytes: &[u8], source: &str) -> Result<BoundaryMesh, MeshError> {
    check_version(bytes, source)?;
    let names = physical_names(bytes);
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

    // All node coordinates by tag.
    let mut coordinates: HashMap<u64, [f64; 3]> = HashMap::new();
    if let Some(nodes) = &msh.data.nodes {
        let mut dense_tag = nodes.min_node_tag;
        for block in &nodes.node_blocks {
            match &block.node_tags {
                Some(tags) => {
                    for (&tag, &i) in tags {
                        let n = &block.nodes[i];
                        coordinates.insert(tag, [n.x, n.y, n.z]);
                    }
                }
                None => {
                    for n in &block.nodes {
                        coordinates.insert(dense_tag, [n.x, n.y, n.z]);
                        dense_tag += 1;
                    }
                }
            }
        }
    }

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

/// Checks the `$MeshFormat` header: version 4.1, ASCII or binary.
fn check_version(bytes: &[u8], source: &str) -> Result<(), MeshError> {
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
    let version = line.split_whitespace().next().unwrap_or("");
    if version.parse::<f64>().ok() != Some(4.1) {
        return Err(not_msh(format!("MSH version {version:?}")));
    }
    Ok(())
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
