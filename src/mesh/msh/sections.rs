//! The sections of an MSH 4.1 file, read in file order after `$MeshFormat`: `$PhysicalNames`,
//! `$Entities`, `$Nodes` and `$Elements` (Gmsh reference manual, "MSH file format version
//! 4.1"); any other section is skipped to its `$End…` line. Only what a boundary mesh needs
//! is kept: the names of physical curve groups, the physical tags of curve entities, every
//! node, and the elements of curve (dimension 1) blocks. Everything else is read past by its
//! sizes, so that a wrong size is an error, not a silent misreading.
//!
//! Each error is a message that names the section and what is wrong, with the byte where the
//! reading stopped.

use super::cursor::{shown, Cursor, Format};
use std::collections::HashMap;

/// What the reader keeps of a file.
#[derive(Debug, Default)]
pub(crate) struct Sections {
    /// Names of physical groups of dimension 1 (curves) by tag.
    pub(crate) names: HashMap<i32, String>,
    /// Physical tags (made positive) of every curve entity, by curve tag.
    pub(crate) curve_groups: HashMap<i32, Vec<i32>>,
    /// Every node as (tag, [x, y, z]), in file order.
    pub(crate) nodes: Vec<(u64, [f64; 3])>,
    /// The element blocks of curve entities, in file order.
    pub(crate) curve_blocks: Vec<CurveBlock>,
}

/// One `$Elements` block on a curve entity.
#[derive(Debug)]
pub(crate) struct CurveBlock {
    /// Gmsh curve (entity) tag.
    pub(crate) curve: i32,
    /// Gmsh element type number.
    pub(crate) element_type: i32,
    /// Nodes per element.
    pub(crate) nodes_per_element: usize,
    /// Per element: its tag, then its node tags.
    pub(crate) elements: Vec<u64>,
}

impl CurveBlock {
    /// (element tag, node tags) of every element.
    pub(crate) fn elements(&self) -> impl Iterator<Item = (u64, &[u64])> {
        self.elements
            .chunks_exact(self.nodes_per_element + 1)
            .map(|e| (e[0], &e[1..]))
    }
}

/// Reads every section from `pos` (just after `$EndMeshFormat`) to the end of the file.
pub(crate) fn read_sections(bytes: &[u8], pos: usize, format: Format) -> Result<Sections, String> {
    let mut r = Cursor::new(bytes, pos, format);
    let mut out = Sections::default();
    let mut seen: Vec<String> = Vec::new();
    while !r.at_end() {
        let start = r.pos;
        let marker = r.token()?;
        let Some(name) = marker
            .strip_prefix(b"$")
            .filter(|n| !n.is_empty() && !n.starts_with(b"End"))
        else {
            return Err(format!(
                "expected a section (a `$Name` line) at byte {start}, found `{}`",
                shown(marker)
            ));
        };
        let name = String::from_utf8_lossy(name).into_owned();
        // The numbers start on the line after the section's name.
        r.line();
        let result = match name.as_str() {
            "PhysicalNames" => physical_names(&mut r).map(|names| out.names = names),
            "Entities" => curve_entities(&mut r).map(|groups| out.curve_groups = groups),
            "Nodes" => nodes(&mut r).map(|nodes| out.nodes = nodes),
            "Elements" => curve_blocks(&mut r).map(|blocks| out.curve_blocks = blocks),
            _ => {
                r.skip_section(&name).map_err(|e| format!("${name} section: {e}"))?;
                continue;
            }
        };
        result
            .and_then(|()| r.end_marker(&name))
            .map_err(|e| format!("${name} section: {e} (near byte {})", r.pos))?;
        // Checked after the section is read, so that an error inside it is named first.
        if seen.contains(&name) {
            return Err(format!(
                "a second ${name} section at byte {start}; a mesh file holds one"
            ));
        }
        seen.push(name);
    }
    Ok(out)
}

/// `$PhysicalNames`: a count, then per line `dimension tag "name"` (text in binary files too).
/// Names of dimension 1 only are kept; a name may hold spaces.
fn physical_names(r: &mut Cursor) -> Result<HashMap<i32, String>, String> {
    let n = r.text_int("number of names")?;
    // At least `1 1 ""` and a line break per entry.
    let n = u64::try_from(n).map_err(|_| format!("number of names: {n} is negative"))?;
    let n = r.fits("number of names", n, 7)?;
    let mut names = HashMap::with_capacity(n);
    for k in 1..=n {
        let dim = r.text_int(&format!("name {k}: dimension"))?;
        let tag = r.text_int(&format!("name {k}: physical tag"))?;
        let line = r.line();
        let name = line
            .trim()
            .strip_prefix('"')
            .and_then(|s| s.strip_suffix('"'))
            .ok_or_else(|| format!("name {k} (tag {tag}): `{}` is not a name in double quotes", line.trim()))?;
        if dim == 1 {
            names.insert(tag, name.to_string());
        }
    }
    Ok(names)
}

/// `$Entities`: the physical tags of every curve; points, surfaces and volumes are read past.
fn curve_entities(r: &mut Cursor) -> Result<HashMap<i32, Vec<i32>>, String> {
    let f = r.format;
    let (int, wide) = (f.int_bytes(), f.wide_bytes());
    // Smallest entity: its tag, its coordinates (3 for a point, a box of 6 otherwise) and its
    // counts of physical tags (and of bounding entities).
    let point_bytes = int + 4 * wide;
    let entity_bytes = int + 8 * wide;
    let counts = [
        r.size("number of points")?,
        r.size("number of curves")?,
        r.size("number of surfaces")?,
        r.size("number of volumes")?,
    ];
    let mut groups = HashMap::new();
    for (dim, (&n, what)) in counts.iter().zip(["point", "curve", "surface", "volume"]).enumerate() {
        let n = r.fits(
            &format!("number of {what}s"),
            n,
            if dim == 0 { point_bytes } else { entity_bytes },
        )?;
        for k in 1..=n {
            let at = |e: String| format!("{what} {k} of {n}: {e}");
            let tag = r.int("tag").map_err(at)?;
            let at = |e: String| format!("{what} {tag}: {e}");
            for _ in 0..if dim == 0 { 3 } else { 6 } {
                r.double("coordinate").map_err(at)?;
            }
            let n_physical = r.count("number of physical tags", int).map_err(at)?;
            let mut physical = Vec::with_capacity(n_physical);
            for _ in 0..n_physical {
                physical.push(r.int("physical tag").map_err(at)?.saturating_abs());
            }
            if dim > 0 {
                let n_bounding = r.count("number of bounding entities", int).map_err(at)?;
                for _ in 0..n_bounding {
                    r.int("bounding entity").map_err(at)?;
                }
            }
            if dim == 1 {
                // A curve listed twice is harmless if both entries give the same groups.
                if let Some(first) = groups.insert(tag, physical) {
                    if first != groups[&tag] {
                        return Err(format!(
                            "curve {tag} is listed twice, with physical tags {first:?} and {:?}",
                            groups[&tag]
                        ));
                    }
                }
            }
        }
    }
    Ok(groups)
}

/// `$Nodes`: a header `numEntityBlocks numNodes minNodeTag maxNodeTag`, then per block
/// `entityDim entityTag parametric numNodesInBlock`, its node tags, then their coordinates
/// (x, y, z, and one parametric coordinate per dimension of the entity if `parametric` is 1,
/// which are read past). Every node by its own tag, in file order.
fn nodes(r: &mut Cursor) -> Result<Vec<(u64, [f64; 3])>, String> {
    let f = r.format;
    let blocks = r.size("number of node blocks")?;
    let total = r.size("number of nodes")?;
    if total == 0 {
        return Err("the header announces no nodes".into());
    }
    let blocks = r.fits("number of node blocks", blocks, 3 * f.int_bytes() + f.wide_bytes())?;
    // A node is its tag and three coordinates.
    let node_bytes = 4 * f.wide_bytes();
    let total = r.fits("number of nodes", total, node_bytes)?;
    r.size("minimum node tag")?;
    r.size("maximum node tag")?;
    let mut records = Vec::with_capacity(total);
    for b in 1..=blocks {
        let at = |e: String| format!("node block {b} of {blocks}: {e}");
        let dim = r.int("entity dimension").map_err(at)?;
        r.int("entity tag").map_err(at)?;
        let parametric = r.int("parametric flag").map_err(at)?;
        let n = r.count("number of nodes in block", node_bytes).map_err(at)?;
        let parameters = match (parametric, dim) {
            (0, 0..=3) => 0,
            (1, d @ 0..=3) => d as usize,
            _ => return Err(at(format!("parametric flag {parametric} on dimension {dim}"))),
        };
        let first = records.len();
        for _ in 0..n {
            let tag = r.size("node tag").map_err(at)?;
            if tag == 0 {
                return Err(at("node tag 0 (tags start at 1)".into()));
            }
            records.push((tag, [0.0; 3]));
        }
        for (tag, xyz) in &mut records[first..] {
            let at = |e: String| format!("node block {b} of {blocks}: node {tag}: {e}");
            *xyz = [
                r.double("x").map_err(at)?,
                r.double("y").map_err(at)?,
                r.double("z").map_err(at)?,
            ];
            for _ in 0..parameters {
                r.double("parametric coordinate").map_err(at)?;
            }
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

/// `$Elements`: a header `numEntityBlocks numElements minElementTag maxElementTag`, then per
/// block `entityDim entityTag elementType numElementsInBlock` and its elements, each its tag
/// and its node tags (one element a line in ASCII files). Blocks on points and surfaces are
/// read past by the node count of their type.
fn curve_blocks(r: &mut Cursor) -> Result<Vec<CurveBlock>, String> {
    let f = r.format;
    let blocks = r.size("number of element blocks")?;
    let total = r.size("number of elements")?;
    if total == 0 {
        return Err("the header announces no elements".into());
    }
    let blocks = r.fits("number of element blocks", blocks, 3 * f.int_bytes() + f.wide_bytes())?;
    // The smallest element is a point: its tag and one node tag.
    let total = r.fits("number of elements", total, 2 * f.wide_bytes())?;
    r.size("minimum element tag")?;
    r.size("maximum element tag")?;
    let mut out = Vec::new();
    let mut counted = 0;
    for b in 1..=blocks {
        let at = |e: String| format!("element block {b} of {blocks}: {e}");
        let dim = r.int("entity dimension").map_err(at)?;
        let entity = r.int("entity tag").map_err(at)?;
        let element_type = r.int("element type").map_err(at)?;
        let nodes_per_element = element_nodes(element_type).ok_or_else(|| {
            at(format!(
                "element type {element_type} ({}) has no fixed number of nodes; rollbem cannot read it",
                element_name(element_type)
            ))
        })?;
        let n = r
            .count("number of elements in block", (nodes_per_element + 1) * f.wide_bytes())
            .map_err(at)?;
        r.end_line("the block header").map_err(at)?;
        counted += n;
        let keep = dim == 1;
        let mut elements = Vec::with_capacity(if keep { n * (nodes_per_element + 1) } else { 0 });
        for k in 1..=n {
            let tag = r
                .size("element tag")
                .map_err(|e| at(format!("element {k} of {n}: {e}")))?;
            let at = |e: String| at(format!("element {tag}: {e}"));
            if keep {
                elements.push(tag);
            }
            for _ in 0..nodes_per_element {
                let node = r.size("node tag").map_err(at)?;
                if keep {
                    elements.push(node);
                }
            }
            r.end_line(&format!(
                "a {} element of {nodes_per_element} nodes",
                element_name(element_type)
            ))
            .map_err(at)?;
        }
        if keep {
            out.push(CurveBlock {
                curve: entity,
                element_type,
                nodes_per_element,
                elements,
            });
        }
    }
    if counted != total {
        return Err(format!(
            "the header announces {total} elements but the blocks hold {counted}"
        ));
    }
    Ok(out)
}

/// Gmsh's names of its element types by number (GmshDefines.h; `MSH_LIN_2` is `Lin2`), from 1.
const ELEMENT_NAMES: [&str; 140] = [
    "Lin2", "Tri3", "Qua4", "Tet4", "Hex8", "Pri6", "Pyr5", "Lin3", "Tri6", "Qua9", "Tet10", "Hex27", "Pri18", "Pyr14",
    "Pnt", "Qua8", "Hex20", "Pri15", "Pyr13", "Tri9", "Tri10", "Tri12", "Tri15", "Tri15i", "Tri21", "Lin4", "Lin5",
    "Lin6", "Tet20", "Tet35", "Tet56", "Tet22", "Tet28", "Polyg", "Polyh", "Qua16", "Qua25", "Qua36", "Qua12",
    "Qua16i", "Qua20", "Tri28", "Tri36", "Tri45", "Tri55", "Tri66", "Qua49", "Qua64", "Qua81", "Qua100", "Qua121",
    "Tri18", "Tri21i", "Tri24", "Tri27", "Tri30", "Qua24", "Qua28", "Qua32", "Qua36i", "Qua40", "Lin7", "Lin8", "Lin9",
    "Lin10", "Lin11", "LinB", "TriB", "PolygB", "LinC", "Tet84", "Tet120", "Tet165", "Tet220", "Tet286", "", "", "",
    "Tet34", "Tet40", "Tet46", "Tet52", "Tet58", "Lin1", "Tri1", "Qua1", "Tet1", "Hex1", "Pri1", "Pri40", "Pri75",
    "Hex64", "Hex125", "Hex216", "Hex343", "Hex512", "Hex729", "Hex1000", "Hex32", "Hex44", "Hex56", "Hex68", "Hex80",
    "Hex92", "Hex104", "Pri126", "Pri196", "Pri288", "Pri405", "Pri550", "Pri24", "Pri33", "Pri42", "Pri51", "Pri60",
    "Pri69", "Pri78", "Pyr30", "Pyr55", "Pyr91", "Pyr140", "Pyr204", "Pyr285", "Pyr385", "Pyr21", "Pyr29", "Pyr37",
    "Pyr45", "Pyr53", "Pyr61", "Pyr69", "Pyr1", "PntSub", "LinSub", "TriSub", "TetSub", "Tet16", "TriMini", "TetMini",
    "Trih4",
];

/// Gmsh's name of element type `t` (`Lin4`), or `type t` for a number it does not define.
pub(crate) fn element_name(t: i32) -> String {
    usize::try_from(t)
        .ok()
        .and_then(|t| t.checked_sub(1))
        .and_then(|i| ELEMENT_NAMES.get(i))
        .filter(|n| !n.is_empty())
        .map_or_else(|| format!("type {t}"), |n| n.to_string())
}

/// Nodes of one element of type `t`: the number in its name (`Tri15i` has 15), but for the
/// point and the mini elements; `None` for types of variable size (polygons, Bézier and
/// sub-elements) and unknown numbers.
fn element_nodes(t: i32) -> Option<usize> {
    let name = element_name(t);
    match name.as_str() {
        "Pnt" => Some(1),
        "TriMini" => Some(4),
        "TetMini" => Some(5),
        _ => name
            .trim_end_matches('i')
            .trim_start_matches(char::is_alphabetic)
            .parse()
            .ok(),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn element_types_have_gmsh_names_and_node_counts() {
        for (t, name, nodes) in [
            (1, "Lin2", Some(2)),
            (8, "Lin3", Some(3)),
            (15, "Pnt", Some(1)),
            (2, "Tri3", Some(3)),
            (9, "Tri6", Some(6)),
            (13, "Pri18", Some(18)),
            (24, "Tri15i", Some(15)),
            (26, "Lin4", Some(4)),
            (34, "Polyg", None),
            (67, "LinB", None),
            (76, "type 76", None),
            (138, "TriMini", Some(4)),
            (139, "TetMini", Some(5)),
            (140, "Trih4", Some(4)),
            (141, "type 141", None),
            (0, "type 0", None),
            (-3, "type -3", None),
        ] {
            assert_eq!(element_name(t), name);
            assert_eq!(element_nodes(t), nodes, "{name}");
        }
    }

    fn ascii(text: &str) -> Result<Sections, String> {
        read_sections(text.as_bytes(), 0, Format::Ascii)
    }

    #[test]
    fn surface_and_point_blocks_are_read_past_by_their_node_counts() {
        let text = "$Elements\n3 4 1 4\n0 1 15 1\n1 1\n2 1 2 1\n2 1 2 3\n1 5 8 2\n3 1 2 4\n4 2 5 6\n$EndElements\n";
        let s = ascii(text).unwrap();
        assert_eq!(s.curve_blocks.len(), 1);
        let b = &s.curve_blocks[0];
        assert_eq!((b.curve, b.element_type), (5, 8));
        let elements: Vec<_> = b.elements().collect();
        assert_eq!(elements, vec![(3, &[1, 2, 4][..]), (4, &[2, 5, 6][..])]);
    }

    #[test]
    fn entities_keep_the_physical_tags_of_curves() {
        let text = "$Entities\n2 2 1 0\n1 0 0 0 0\n2 1 0 0 1 5\n\
                    3 0 0 0 1 0 0 2 4 -7 2 1 -2\n4 0 0 0 1 0 0 0 2 1 2\n\
                    1 0 0 0 1 1 0 1 9 2 3 4\n$EndEntities\n$Comments\nanything\n$EndComments\n";
        let s = ascii(text).unwrap();
        assert_eq!(s.curve_groups[&3], vec![4, 7]);
        assert_eq!(s.curve_groups[&4], Vec::<i32>::new());
        assert_eq!(s.curve_groups.len(), 2);
    }

    #[test]
    fn malformed_sections_are_named_with_what_is_wrong() {
        for (text, expected) in [
            (
                "$Elements\n1 1 1 1\n1 1 1 1\n1 1 2\n",
                "$Elements section: the file ends before $EndElements",
            ),
            ("$Elements\n1 1 1 1\n1 1 1 1\n1 1 2\n$EndNodes\n", "found `$EndNodes`"),
            (
                "$Elements\n1 1 1 1\n1 1 1 1\n1 1 2 3\n$EndElements\n",
                "followed by `3`",
            ),
            (
                "$Elements\n1 2 1 2\n1 1 1 1\n1 1 2\n$EndElements\n",
                "announces 2 elements but",
            ),
            (
                "$Elements\n1 1 1 1\n1 1 67 1\n1 1 2\n$EndElements\n",
                "LinB) has no fixed number",
            ),
            (
                "$Elements\n1 1 1 1\n1 1 1 99999\n1 1 2\n$EndElements\n",
                "more than the rest",
            ),
            (
                "$Nodes\n1 1 1 1\n1 1 0 1\n1\n0 0\n$EndNodes\n",
                "node 1: z: `$EndNodes` is not a number",
            ),
            ("$Nodes\n1 1 1 1\n1 1 2 1\n1\n0 0 0\n$EndNodes\n", "parametric flag 2"),
            (
                "$Nodes\n1 2 1 2\n1 1 0 1\n1\n0 0 0\n$EndNodes\n",
                "announces 2 nodes but",
            ),
            (
                "$PhysicalNames\n1\n1 2 contact\n$EndPhysicalNames\n",
                "not a name in double quotes",
            ),
            (
                "$PhysicalNames\n2\n1 2 \"a\"\n$EndPhysicalNames\n",
                "$PhysicalNames section",
            ),
            (
                "$PhysicalNames\n-1\n$EndPhysicalNames\n",
                "number of names: -1 is negative",
            ),
            (
                "$Entities\n0 2 0 0\n1 0 0 0 1 0 0 1 3 0\n1 0 0 0 1 0 0 0 0\n$EndEntities\n",
                "curve 1 is listed twice, with physical tags [3] and []",
            ),
            (
                "$Nodes\n1 1 1 1\n0 1 0 1\n1\n0 0 0\n$EndNodes\n$Nodes\n1 1 1 1\n0 1 0 1\n1\n0 0 0\n$EndNodes\n",
                "a second $Nodes",
            ),
            (
                "$Comments\nno end\n",
                "$Comments section: the file ends before $EndComments",
            ),
            ("junk\n", "expected a section"),
            ("$EndNodes\n", "expected a section"),
        ] {
            let err = ascii(text).unwrap_err();
            assert!(err.contains(expected), "{text:?}: {err}");
        }
    }
}
