//! A small writer of VTK XML unstructured grids (`.vtu`, VTK file format version 1.0, as read
//! by VTK ≥ 6, ParaView, pyvista and meshio): one piece, every array inline in the `binary`
//! format, that is base64 of a little-endian UInt64 byte count followed by the little-endian
//! values (the VTK User's Guide, "VTK File Formats", XML formats). Binary keeps every double
//! exact. The optional `RangeMin`/`RangeMax` hints are not written: readers compute the ranges.
//!
//! The document is streamed to the writer array by array: nothing but the arrays the caller
//! built is held in memory.

use std::borrow::Cow;
use std::io::{self, Write};

/// VTK cell types rollbem writes (the numbers of VTK's `vtkCellType.h`). All cells of a grid
/// have the same type.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum CellType {
    /// Two-point line (VTK_LINE = 3).
    Line,
    /// Four-point quadrilateral, corners in counter-clockwise order (VTK_QUAD = 9).
    Quad,
    /// Three-point quadratic edge: start, end, mid (VTK_QUADRATIC_EDGE = 21).
    QuadraticEdge,
}

impl CellType {
    /// The VTK type number.
    fn code(self) -> u8 {
        match self {
            CellType::Line => 3,
            CellType::Quad => 9,
            CellType::QuadraticEdge => 21,
        }
    }

    /// Points per cell.
    pub fn points(self) -> usize {
        match self {
            CellType::Line => 2,
            CellType::Quad => 4,
            CellType::QuadraticEdge => 3,
        }
    }
}

/// The values of a data array: doubles (VTK `Float64`) or integer codes (VTK `Int32`).
#[derive(Debug, Clone, PartialEq)]
pub enum Values {
    /// Written as `Float64`.
    F64(Vec<f64>),
    /// Written as `Int32`.
    I32(Vec<i32>),
}

impl Values {
    fn len(&self) -> usize {
        match self {
            Values::F64(v) => v.len(),
            Values::I32(v) => v.len(),
        }
    }
}

/// How ParaView may use an array by default: the first `Scalars` and the first `Vectors` array
/// of a point or cell data block are named as its active scalars and vectors.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Role {
    /// Scalars (1 to 4 components).
    Scalars,
    /// 3-vectors.
    Vectors,
}

/// One named array of point or cell data, `components` values per point (or cell), point after
/// point.
#[derive(Debug, Clone, PartialEq)]
pub struct DataArray {
    /// Name shown in ParaView.
    pub name: String,
    /// Values per point or cell.
    pub components: usize,
    /// Scalars or vectors.
    pub role: Role,
    /// The values, `components` × the number of points (or cells).
    pub values: Values,
}

impl DataArray {
    /// A scalar array of doubles.
    pub fn scalar(name: &str, values: Vec<f64>) -> Self {
        Self::scalars(name, 1, Values::F64(values))
    }

    /// A scalar array of `components` values per point (doubles or integers).
    pub fn scalars(name: &str, components: usize, values: Values) -> Self {
        DataArray {
            name: name.into(),
            components,
            role: Role::Scalars,
            values,
        }
    }

    /// The 3-vector (x, y, 0) at each point.
    pub fn vector_xy(name: &str, x: &[f64], y: &[f64]) -> Self {
        DataArray {
            name: name.into(),
            components: 3,
            role: Role::Vectors,
            values: Values::F64(x.iter().zip(y).flat_map(|(a, b)| [*a, *b, 0.0]).collect()),
        }
    }
}

/// An unstructured grid of one cell type.
#[derive(Debug, Clone, PartialEq)]
pub struct UnstructuredGrid {
    /// Point coordinates (x, y, z).
    pub points: Vec<[f64; 3]>,
    /// The type of every cell.
    pub cell_type: CellType,
    /// Point indices, `cell_type.points()` per cell, cell after cell.
    pub connectivity: Vec<u64>,
    /// Arrays with a value (tuple) per point.
    pub point_data: Vec<DataArray>,
    /// Arrays with a value (tuple) per cell.
    pub cell_data: Vec<DataArray>,
}

impl UnstructuredGrid {
    /// Number of cells.
    pub fn cells(&self) -> usize {
        self.connectivity.len() / self.cell_type.points()
    }

    /// Writes the grid as a `.vtu` document. The sizes are checked first: a connectivity that
    /// is not whole cells, a point index out of range or an array of the wrong length is an
    /// `InvalidInput` error and nothing is written.
    pub fn write(&self, out: &mut dyn Write) -> io::Result<()> {
        self.check()?;
        let (n, cells) = (self.points.len(), self.cells());
        out.write_all(b"<?xml version=\"1.0\"?>\n")?;
        out.write_all(
            b"<VTKFile type=\"UnstructuredGrid\" version=\"1.0\" byte_order=\"LittleEndian\" header_type=\"UInt64\">\n",
        )?;
        writeln!(
            out,
            "<UnstructuredGrid>\n<Piece NumberOfPoints=\"{n}\" NumberOfCells=\"{cells}\">"
        )?;
        write_data_block(out, "PointData", &self.point_data)?;
        write_data_block(out, "CellData", &self.cell_data)?;
        out.write_all(b"<Points>\n")?;
        write_array(out, "Points", FLOAT64, 3, 3 * n, |e| {
            self.points.iter().flatten().try_for_each(|v| e.push(&v.to_le_bytes()))
        })?;
        out.write_all(b"</Points>\n<Cells>\n")?;
        write_array(out, "connectivity", UINT64, 1, self.connectivity.len(), |e| {
            self.connectivity.iter().try_for_each(|v| e.push(&v.to_le_bytes()))
        })?;
        let per_cell = self.cell_type.points() as u64;
        write_array(out, "offsets", UINT64, 1, cells, |e| {
            (1..=cells as u64).try_for_each(|c| e.push(&(c * per_cell).to_le_bytes()))
        })?;
        write_array(out, "types", UINT8, 1, cells, |e| {
            (0..cells).try_for_each(|_| e.push(&[self.cell_type.code()]))
        })?;
        out.write_all(b"</Cells>\n</Piece>\n</UnstructuredGrid>\n</VTKFile>\n")
    }

    fn check(&self) -> io::Result<()> {
        let invalid = |m: String| Err(io::Error::new(io::ErrorKind::InvalidInput, m));
        let n = self.points.len();
        if !self.connectivity.len().is_multiple_of(self.cell_type.points()) {
            return invalid(format!(
                "{} point indices are not whole cells of {} points",
                self.connectivity.len(),
                self.cell_type.points()
            ));
        }
        if let Some(k) = self.connectivity.iter().find(|&&k| k >= n as u64) {
            return invalid(format!("point index {k} of a cell is beyond the {n} points"));
        }
        let blocks = [(&self.point_data, n, "point"), (&self.cell_data, self.cells(), "cell")];
        for (arrays, count, kind) in blocks {
            for a in arrays {
                if a.components == 0 || a.values.len() != a.components * count {
                    return invalid(format!(
                        "{kind} data `{}` has {} values, not {} × {count}",
                        a.name,
                        a.values.len(),
                        a.components
                    ));
                }
            }
        }
        Ok(())
    }
}

/// `<PointData>` or `<CellData>` with its arrays, naming the first scalars and the first vectors
/// as the active ones; nothing when there are no arrays.
fn write_data_block(out: &mut dyn Write, tag: &str, arrays: &[DataArray]) -> io::Result<()> {
    if arrays.is_empty() {
        return Ok(());
    }
    write!(out, "<{tag}")?;
    for (role, attribute) in [(Role::Scalars, "Scalars"), (Role::Vectors, "Vectors")] {
        if let Some(a) = arrays.iter().find(|a| a.role == role) {
            write!(out, " {attribute}=\"{}\"", escape(&a.name))?;
        }
    }
    out.write_all(b">\n")?;
    for a in arrays {
        let count = a.values.len();
        match &a.values {
            Values::F64(v) => write_array(out, &a.name, FLOAT64, a.components, count, |e| {
                v.iter().try_for_each(|x| e.push(&x.to_le_bytes()))
            })?,
            Values::I32(v) => write_array(out, &a.name, INT32, a.components, count, |e| {
                v.iter().try_for_each(|x| e.push(&x.to_le_bytes()))
            })?,
        }
    }
    writeln!(out, "</{tag}>")
}

/// One `<DataArray>` of `count` values of `size` bytes in the binary format: the UInt64 byte
/// count, then the bytes that `values` pushes (little-endian), in one base64 text.
fn write_array(
    out: &mut dyn Write,
    name: &str,
    (vtk_type, size): (&str, usize),
    components: usize,
    count: usize,
    values: impl FnOnce(&mut Base64) -> io::Result<()>,
) -> io::Result<()> {
    write!(out, "<DataArray type=\"{vtk_type}\" Name=\"{}\"", escape(name))?;
    if components != 1 {
        write!(out, " NumberOfComponents=\"{components}\"")?;
    }
    out.write_all(b" format=\"binary\">")?;
    let mut e = Base64::new(out);
    e.push(&((count * size) as u64).to_le_bytes())?;
    values(&mut e)?;
    debug_assert_eq!(e.bytes, 8 + count * size, "`{name}`: bytes pushed and announced differ");
    e.finish()?;
    out.write_all(b"</DataArray>\n")
}

const FLOAT64: (&str, usize) = ("Float64", 8);
const INT32: (&str, usize) = ("Int32", 4);
const UINT64: (&str, usize) = ("UInt64", 8);
const UINT8: (&str, usize) = ("UInt8", 1);

/// Streaming base64 (RFC 4648, standard alphabet, `=` padding) into a writer.
struct Base64<'a> {
    out: &'a mut dyn Write,
    /// Bytes not yet encoded (fewer than 3).
    pending: [u8; 3],
    held: usize,
    /// Bytes pushed so far.
    bytes: usize,
    /// Encoded text waiting to be written.
    text: Vec<u8>,
}

const ALPHABET: &[u8; 64] = b"ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";

impl<'a> Base64<'a> {
    fn new(out: &'a mut dyn Write) -> Self {
        Base64 {
            out,
            pending: [0; 3],
            held: 0,
            bytes: 0,
            text: Vec::with_capacity(4096),
        }
    }

    /// Appends bytes.
    fn push(&mut self, bytes: &[u8]) -> io::Result<()> {
        self.bytes += bytes.len();
        for &b in bytes {
            self.pending[self.held] = b;
            self.held += 1;
            if self.held == 3 {
                let [a, b, c] = self.pending;
                self.text.extend(quad(a, b, c));
                self.held = 0;
                if self.text.len() >= 4096 {
                    self.out.write_all(&self.text)?;
                    self.text.clear();
                }
            }
        }
        Ok(())
    }

    /// Encodes the last one or two bytes with `=` padding and writes out the text.
    fn finish(mut self) -> io::Result<()> {
        let [a, b, _] = self.pending;
        match self.held {
            1 => {
                let q = quad(a, 0, 0);
                self.text.extend_from_slice(&[q[0], q[1], b'=', b'=']);
            }
            2 => {
                let q = quad(a, b, 0);
                self.text.extend_from_slice(&[q[0], q[1], q[2], b'=']);
            }
            _ => {}
        }
        self.out.write_all(&self.text)
    }
}

/// `bytes` in base64, pushed in two pieces to cross the encoder's 3-byte groups.
#[cfg(test)]
pub(super) fn base64(bytes: &[u8]) -> String {
    let mut out = Vec::new();
    let mut e = Base64::new(&mut out);
    let (a, b) = bytes.split_at(bytes.len() / 2);
    e.push(a).unwrap();
    e.push(b).unwrap();
    e.finish().unwrap();
    String::from_utf8(out).unwrap()
}

/// The four base64 characters of three bytes.
fn quad(a: u8, b: u8, c: u8) -> [u8; 4] {
    let n = (u32::from(a) << 16) | (u32::from(b) << 8) | u32::from(c);
    [18, 12, 6, 0].map(|shift| ALPHABET[(n >> shift & 63) as usize])
}

/// `text` as XML character data or attribute value: the five special characters as entities,
/// tab, newline and carriage return as character references (an attribute keeps them so), and
/// the other control characters below U+0020, which XML 1.0 cannot represent at all, as U+FFFD.
pub fn escape(text: &str) -> Cow<'_, str> {
    let plain = |c: char| c >= ' ' && !matches!(c, '&' | '<' | '>' | '"' | '\'');
    if text.chars().all(plain) {
        return text.into();
    }
    let mut s = String::with_capacity(text.len() + 16);
    for c in text.chars() {
        match c {
            '&' => s.push_str("&amp;"),
            '<' => s.push_str("&lt;"),
            '>' => s.push_str("&gt;"),
            '"' => s.push_str("&quot;"),
            '\'' => s.push_str("&apos;"),
            '\t' | '\n' | '\r' => s.push_str(&format!("&#{};", c as u32)),
            c if c < ' ' => s.push('\u{FFFD}'),
            c => s.push(c),
        }
    }
    s.into()
}
