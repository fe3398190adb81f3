//! The VTK writer read back by a minimal XML reader written here (well-formedness, the counts
//! against `NumberOfPoints`/`NumberOfCells`, the decoded values); meshio and pyvista read the
//! files of real runs in CI (tools/check_outputs.py).

use super::xml::{escape, CellType, DataArray, UnstructuredGrid, Values};
use super::{write_collection, CollectionEntry};
use std::collections::BTreeMap;

/// An element of a parsed document: its name, attributes and character data (entities kept).
#[derive(Debug)]
struct Element {
    name: String,
    attributes: BTreeMap<String, String>,
    text: String,
}

/// Character data or an attribute value is well-formed: no `<`, and `&` only in the entities
/// of XML 1.0 or a character reference.
fn check_text(text: &str) -> Result<(), String> {
    if text.contains('<') {
        return Err(format!("`<` in {text:?}"));
    }
    for (k, _) in text.match_indices('&') {
        let rest = &text[k + 1..];
        let end = rest.find(';').ok_or_else(|| format!("`&` without `;` in {text:?}"))?;
        let entity = &rest[..end];
        let numeric = entity.strip_prefix('#').is_some_and(|d| d.parse::<u32>().is_ok());
        if !numeric && !matches!(entity, "amp" | "lt" | "gt" | "quot" | "apos") {
            return Err(format!("unknown entity `&{entity};`"));
        }
    }
    if let Some(c) = text.chars().find(|&c| c < ' ' && !matches!(c, '\t' | '\n' | '\r')) {
        return Err(format!("control character {:?} in {text:?}", c));
    }
    Ok(())
}

/// Parses the document (an optional `<?xml …?>` prolog, then one root element) and returns its
/// elements in document order, or why it is not well-formed.
fn parse(doc: &str) -> Result<Vec<Element>, String> {
    let mut rest = doc;
    if let Some(after) = rest.strip_prefix("<?xml") {
        rest = &after[after.find("?>").ok_or("unterminated prolog")? + 2..];
    }
    let (mut elements, mut open): (Vec<Element>, Vec<(String, usize)>) = (Vec::new(), Vec::new());
    let mut roots = 0;
    loop {
        let lt = rest.find('<');
        let text = &rest[..lt.unwrap_or(rest.len())];
        check_text(text)?;
        match open.last() {
            Some(&(_, i)) => elements[i].text.push_str(text),
            None if !text.trim().is_empty() => return Err(format!("text outside the root: {text:?}")),
            None => {}
        }
        let Some(lt) = lt else { break };
        let gt = rest[lt..].find('>').ok_or("unterminated tag")? + lt;
        let tag = &rest[lt + 1..gt];
        rest = &rest[gt + 1..];
        if let Some(name) = tag.strip_prefix('/') {
            let (top, _) = open.pop().ok_or_else(|| format!("`</{name}>` closes nothing"))?;
            if top != name {
                return Err(format!("`</{name}>` closes `<{top}>`"));
            }
            continue;
        }
        let (tag, empty) = match tag.strip_suffix('/') {
            Some(t) => (t, true),
            None => (tag, false),
        };
        let name_end = tag.find(char::is_whitespace).unwrap_or(tag.len());
        let name = &tag[..name_end];
        if name.is_empty() || !name.chars().all(|c| c.is_ascii_alphanumeric() || c == '_') {
            return Err(format!("bad element name in `<{tag}>`"));
        }
        let mut attributes = BTreeMap::new();
        let mut a = tag[name_end..].trim_start();
        while !a.is_empty() {
            let eq = a.find("=\"").ok_or_else(|| format!("bad attribute in `<{tag}>`"))?;
            let key = &a[..eq];
            let close = a[eq + 2..].find('"').ok_or("unterminated attribute value")? + eq + 2;
            let value = &a[eq + 2..close];
            check_text(value)?;
            if attributes.insert(key.to_string(), value.to_string()).is_some() {
                return Err(format!("attribute `{key}` twice in `<{name}>`"));
            }
            let next = &a[close + 1..];
            if !next.is_empty() && !next.starts_with(char::is_whitespace) {
                return Err(format!("no space after attribute `{key}`"));
            }
            a = next.trim_start();
        }
        if open.is_empty() {
            roots += 1;
        }
        elements.push(Element {
            name: name.to_string(),
            attributes,
            text: String::new(),
        });
        if !empty {
            open.push((name.to_string(), elements.len() - 1));
        }
    }
    match (open.last(), roots) {
        (Some((name, _)), _) => Err(format!("`<{name}>` not closed")),
        (None, 1) => Ok(elements),
        (None, n) => Err(format!("{n} root elements")),
    }
}

/// Decodes base64 (RFC 4648, padded), independently of the writer's encoder.
fn decode_base64(text: &str) -> Vec<u8> {
    let value = |c: u8| match c {
        b'A'..=b'Z' => c - b'A',
        b'a'..=b'z' => c - b'a' + 26,
        b'0'..=b'9' => c - b'0' + 52,
        b'+' => 62,
        b'/' => 63,
        _ => panic!("not base64: {c}"),
    };
    let bytes = text.trim().as_bytes();
    assert_eq!(bytes.len() % 4, 0, "base64 length {}", bytes.len());
    let mut out = Vec::new();
    for chunk in bytes.chunks(4) {
        let pad = chunk.iter().filter(|&&c| c == b'=').count();
        let n = chunk[..4 - pad]
            .iter()
            .enumerate()
            .fold(0u32, |n, (i, &c)| n | u32::from(value(c)) << (18 - 6 * i));
        out.extend(&n.to_be_bytes()[1..4 - pad]);
    }
    out
}

/// The bytes of a binary `<DataArray>` after checking that its UInt64 header counts them.
fn array_bytes(e: &Element) -> Vec<u8> {
    let raw = decode_base64(&e.text);
    let (header, data) = raw.split_at(8);
    assert_eq!(u64::from_le_bytes(header.try_into().unwrap()) as usize, data.len());
    data.to_vec()
}

fn f64s(bytes: &[u8]) -> Vec<f64> {
    bytes
        .chunks(8)
        .map(|c| f64::from_le_bytes(c.try_into().unwrap()))
        .collect()
}

fn ints<const N: usize>(bytes: &[u8], to_i64: fn([u8; N]) -> i64) -> Vec<i64> {
    bytes.chunks(N).map(|c| to_i64(c.try_into().unwrap())).collect()
}

/// Two lines over three points with point data (doubles, integers, vectors) and cell data.
fn tiny_grid() -> UnstructuredGrid {
    UnstructuredGrid {
        points: vec![[0.0, 0.0, 0.0], [0.5, -1.25e-7, 0.0], [1.0, 3.0, 0.0]],
        cell_type: CellType::Line,
        connectivity: vec![0, 1, 1, 2],
        point_data: vec![
            DataArray::scalar("pressure", vec![0.0, 1153.8264411529303, f64::MIN_POSITIVE]),
            DataArray::scalars("state", 1, Values::I32(vec![0, 1, -2])),
            DataArray::vector_xy("traction", &[1.0, 2.0, 3.0], &[-1.0, -2.0, -3.0]),
        ],
        cell_data: vec![DataArray::scalars("group", 1, Values::I32(vec![7, 8]))],
    }
}

#[test]
fn a_tiny_grid_reads_back_with_counts_matching_points_and_cells() {
    let grid = tiny_grid();
    let mut out = Vec::new();
    grid.write(&mut out).unwrap();
    let doc = String::from_utf8(out).unwrap();
    let elements = parse(&doc).unwrap_or_else(|e| panic!("{e}\n{doc}"));
    let find = |name: &str| elements.iter().find(|e| e.name == name).unwrap();
    assert_eq!(find("VTKFile").attributes["type"], "UnstructuredGrid");
    assert_eq!(find("VTKFile").attributes["header_type"], "UInt64");
    let piece = &find("Piece").attributes;
    let points: usize = piece["NumberOfPoints"].parse().unwrap();
    let cells: usize = piece["NumberOfCells"].parse().unwrap();
    assert_eq!((points, cells), (3, 2));
    assert_eq!(find("PointData").attributes["Scalars"], "pressure");
    assert_eq!(find("PointData").attributes["Vectors"], "traction");
    assert_eq!(find("CellData").attributes["Scalars"], "group");

    // Every array holds components × (points or cells) values of its type.
    let arrays: BTreeMap<&str, &Element> = elements
        .iter()
        .filter(|e| e.name == "DataArray")
        .map(|e| (e.attributes["Name"].as_str(), e))
        .collect();
    let expected = [
        ("pressure", "Float64", 1, points),
        ("state", "Int32", 1, points),
        ("traction", "Float64", 3, points),
        ("group", "Int32", 1, cells),
        ("Points", "Float64", 3, points),
        ("connectivity", "UInt64", 1, 2 * cells),
        ("offsets", "UInt64", 1, cells),
        ("types", "UInt8", 1, cells),
    ];
    assert_eq!(arrays.len(), expected.len());
    for (name, vtk_type, components, count) in expected {
        let a = arrays[name];
        assert_eq!(a.attributes["type"], vtk_type, "{name}");
        assert_eq!(a.attributes["format"], "binary", "{name}");
        let n: usize = a.attributes.get("NumberOfComponents").map_or(1, |c| c.parse().unwrap());
        assert_eq!(n, components, "{name}");
        let size = match vtk_type {
            "Float64" | "UInt64" => 8,
            "Int32" => 4,
            _ => 1,
        };
        assert_eq!(array_bytes(a).len(), components * count * size, "{name}");
    }

    // The values come back exactly.
    let bytes = |name: &str| array_bytes(arrays[name]);
    let f64_bits = |v: Vec<f64>| v.into_iter().map(f64::to_bits).collect::<Vec<_>>();
    assert_eq!(
        f64_bits(f64s(&bytes("pressure"))),
        f64_bits(vec![0.0, 1153.8264411529303, f64::MIN_POSITIVE])
    );
    assert_eq!(
        f64s(&bytes("Points")),
        [0.0, 0.0, 0.0, 0.5, -1.25e-7, 0.0, 1.0, 3.0, 0.0]
    );
    assert_eq!(
        f64s(&bytes("traction")),
        [1.0, -1.0, 0.0, 2.0, -2.0, 0.0, 3.0, -3.0, 0.0]
    );
    let i32s = |b: &[u8]| ints::<4>(b, |c| i32::from_le_bytes(c).into());
    let u64s = |b: &[u8]| ints::<8>(b, |c| u64::from_le_bytes(c) as i64);
    assert_eq!(i32s(&bytes("state")), [0, 1, -2]);
    assert_eq!(i32s(&bytes("group")), [7, 8]);
    assert_eq!(u64s(&bytes("connectivity")), [0, 1, 1, 2]);
    assert_eq!(u64s(&bytes("offsets")), [2, 4]);
    assert_eq!(bytes("types"), [3, 3]);
}

#[test]
fn cell_types_carry_vtk_numbers_and_offsets_step_by_their_points() {
    for (cell_type, code, per_cell) in [
        (CellType::Line, 3, 2),
        (CellType::Quad, 9, 4),
        (CellType::QuadraticEdge, 21, 3),
    ] {
        let grid = UnstructuredGrid {
            points: vec![[0.0; 3]; 2 * per_cell],
            cell_type,
            connectivity: (0..2 * per_cell as u64).collect(),
            point_data: Vec::new(),
            cell_data: Vec::new(),
        };
        let mut out = Vec::new();
        grid.write(&mut out).unwrap();
        let elements = parse(std::str::from_utf8(&out).unwrap()).unwrap();
        assert!(!elements.iter().any(|e| e.name == "PointData" || e.name == "CellData"));
        let array = |name: &str| {
            array_bytes(
                elements
                    .iter()
                    .find(|e| e.attributes.get("Name").is_some_and(|n| n == name))
                    .unwrap(),
            )
        };
        assert_eq!(array("types"), [code, code]);
        let offsets = ints::<8>(&array("offsets"), |c| u64::from_le_bytes(c) as i64);
        assert_eq!(offsets, [per_cell as i64, 2 * per_cell as i64]);
    }
}

#[test]
fn inconsistent_sizes_are_refused_before_anything_is_written() {
    let mut short = tiny_grid();
    short.point_data[0].values = Values::F64(vec![1.0, 2.0]);
    let mut cells = tiny_grid();
    cells.cell_data[0].values = Values::I32(vec![1]);
    let mut partial = tiny_grid();
    partial.connectivity.push(0);
    let mut beyond = tiny_grid();
    beyond.connectivity[3] = 3;
    for (grid, message) in [
        (short, "point data `pressure` has 2 values"),
        (cells, "cell data `group` has 1 values"),
        (partial, "5 point indices are not whole cells"),
        (beyond, "point index 3"),
    ] {
        let mut out = Vec::new();
        let e = grid.write(&mut out).unwrap_err();
        assert_eq!(e.kind(), std::io::ErrorKind::InvalidInput);
        assert!(e.to_string().contains(message), "{e}");
        assert!(out.is_empty());
    }
}

#[test]
fn base64_matches_the_rfc_4648_test_vectors() {
    // RFC 4648 §10: the writer's streaming encoder (fed in two pieces), and this file's decoder.
    for (plain, encoded) in [
        ("", ""),
        ("f", "Zg=="),
        ("fo", "Zm8="),
        ("foo", "Zm9v"),
        ("foob", "Zm9vYg=="),
        ("fooba", "Zm9vYmE="),
        ("foobar", "Zm9vYmFy"),
    ] {
        assert_eq!(super::xml::base64(plain.as_bytes()), encoded);
        assert_eq!(decode_base64(encoded), plain.as_bytes());
    }
}

#[test]
fn escape_makes_any_text_well_formed() {
    assert_eq!(escape("contact run_0001"), "contact run_0001");
    assert_eq!(
        escape("a&b <c> \"d\" 'e'\tf\ng\u{1}"),
        "a&amp;b &lt;c&gt; &quot;d&quot; &apos;e&apos;&#9;f&#10;g\u{FFFD}"
    );
}

/// Folder names with XML's special characters (a sweep merged from `../a&b "1"/`) used to be
/// written into the .pvd as they were, which no XML reader accepts.
#[test]
fn a_collection_with_special_characters_stays_well_formed() {
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("sweep.pvd");
    let entries = [
        CollectionEntry {
            file: "../a&b \"1\"/run_0000/contact.vtu".into(),
            timestep: 0.0,
            part: 0,
            name: "contact <run_0000>".into(),
        },
        CollectionEntry {
            file: "run_0001/contact.vtu".into(),
            timestep: 1.0,
            part: 0,
            name: "contact run_0001".into(),
        },
    ];
    write_collection(&path, &entries).unwrap();
    let doc = std::fs::read_to_string(&path).unwrap();
    let elements = parse(&doc).unwrap_or_else(|e| panic!("{e}\n{doc}"));
    let datasets: Vec<_> = elements.iter().filter(|e| e.name == "DataSet").collect();
    assert_eq!(datasets.len(), 2);
    assert_eq!(
        datasets[0].attributes["file"],
        "../a&amp;b &quot;1&quot;/run_0000/contact.vtu"
    );
    assert_eq!(datasets[0].attributes["name"], "contact &lt;run_0000&gt;");
    assert_eq!(datasets[1].attributes["timestep"], "1");
}

#[test]
fn the_reader_of_these_tests_refuses_what_is_not_well_formed() {
    for bad in [
        "<a><b></a></b>",
        "<a x=\"1\" x=\"2\"/>",
        "<a x=\"&\"/>",
        "<a>1 < 2</a>",
        "<a/><b/>",
        "<a>",
        "<a x=\"1\"y=\"2\"/>",
    ] {
        assert!(parse(bad).is_err(), "{bad}");
    }
    assert!(parse("<?xml version=\"1.0\"?>\n<a x=\"&amp;\"><b/>t&#9;</a>\n").is_ok());
}
