//! VTK XML output: the contact line, `bem` boundaries and interior grids as unstructured grids
//! (`.vtu`, written by [`xml`], rollbem's own writer), and `.pvd` collections that tie a run's
//! (or a sweep's) datasets together for ParaView.
//!
//! Point data of `contact.vtu` (one point per contact node, at (x, 0, 0) in the contact frame):
//! every column of contact.csv — `pressure`, `shear`, `gap`, `slip`, `slip_hbem` (only when the
//! models provide it), `state` (integer: 0 open, 1 stick, 2 slip), `u_n_A`, `u_t_A`, `u_n_B`,
//! `u_t_B` — plus the 3-vectors `traction` = (q, p, 0) (on A; B receives the opposite) and
//! `displacement_A` = (u_t_A, u_n_A, 0), `displacement_B` = (u_t_B, −u_n_B, 0) in x, y, z of the
//! contact frame (u_n is positive into each body, and B lies at y < 0). Displacements are real,
//! not scaled: use ParaView's Warp By Vector.

pub mod xml;

#[cfg(test)]
mod tests;

use crate::contact::ContactProblem;
use crate::error::Error;
use crate::post::{ContactSolution, NodeState};
use std::io::Write;
use std::path::Path;
use xml::{escape, CellType, DataArray, UnstructuredGrid, Values};

/// Integer code of a node state in VTK files (documented legend: 0 open, 1 stick, 2 slip).
pub fn state_code(state: NodeState) -> i32 {
    match state {
        NodeState::Open => 0,
        NodeState::Stick => 1,
        NodeState::Slip => 2,
    }
}

/// Writes the contact line of a solved run as `contact.vtu`.
pub fn write_contact_line(path: &Path, sol: &ContactSolution, pb: &ContactProblem) -> Result<(), Error> {
    let m = sol.x.len();
    let disp = pb.surface_displacements(&sol.pressure, &sol.shear);
    let mut point = vec![
        DataArray::scalar("pressure", sol.pressure.clone()),
        DataArray::scalar("shear", sol.shear.clone()),
        DataArray::scalar("gap", sol.gap.clone()),
        DataArray::scalar("slip", sol.slip.clone()),
    ];
    if let Some(s) = &sol.slip_strain {
        point.push(DataArray::scalar("slip_hbem", s.clone()));
    }
    let state = sol.state.iter().map(|&s| state_code(s)).collect();
    let minus_u_n_b: Vec<f64> = disp.normal_b.iter().map(|v| -v).collect();
    point.extend([
        DataArray::scalars("state", 1, Values::I32(state)),
        DataArray::scalar("u_n_A", disp.normal_a.clone()),
        DataArray::scalar("u_t_A", disp.tangential_a.clone()),
        DataArray::scalar("u_n_B", disp.normal_b.clone()),
        DataArray::scalar("u_t_B", disp.tangential_b.clone()),
        DataArray::vector_xy("traction", &sol.shear, &sol.pressure),
        DataArray::vector_xy("displacement_A", &disp.tangential_a, &disp.normal_a),
        DataArray::vector_xy("displacement_B", &disp.tangential_b, &minus_u_n_b),
    ]);
    let grid = UnstructuredGrid {
        points: sol.x.iter().map(|&x| [x, 0.0, 0.0]).collect(),
        cell_type: CellType::Line,
        connectivity: (0..m.saturating_sub(1) as u64).flat_map(|i| [i, i + 1]).collect(),
        point_data: point,
        cell_data: Vec::new(),
    };
    write_file(path, |out| grid.write(out))
}

/// Writes a body's boundary as quadratic edges (VTK type 21) with point data `displacement`
/// [length] and `traction` [stress] (3-vectors, z = 0) and cell data `group` (the index of the
/// element's physical group in the mesh, in the order of `BoundaryField::group_names`).
pub fn write_boundary(path: &Path, field: &crate::body::BoundaryField) -> Result<(), Error> {
    let (ux, uy): (Vec<f64>, Vec<f64>) = field.displacement.iter().map(|u| (u[0], u[1])).unzip();
    let (tx, ty): (Vec<f64>, Vec<f64>) = field.traction.iter().map(|t| (t[0], t[1])).unzip();
    let grid = UnstructuredGrid {
        points: field.points.iter().map(|p| [p[0], p[1], 0.0]).collect(),
        cell_type: CellType::QuadraticEdge,
        // Every element has its own three points, in VTK's order (start, end, mid).
        connectivity: (0..field.points.len() as u64).collect(),
        point_data: vec![
            DataArray::vector_xy("displacement", &ux, &uy),
            DataArray::vector_xy("traction", &tx, &ty),
        ],
        cell_data: vec![DataArray::scalars("group", 1, Values::I32(field.group.clone()))],
    };
    write_file(path, |out| grid.write(out))
}

/// Writes interior fields as a grid of quadrilaterals: point data `stress` (4 components
/// σxx, σyy, σzz, τxy), `von_mises`, `max_shear`, `displacement` (3-vector, z = 0) and `status`
/// (0 outside the body, 1 inside, 2 within the boundary layer; fields are 0 where not inside).
/// Only quadrilaterals whose four corners are inside are written as cells, so ParaView never
/// interpolates across points that were not evaluated; every point is kept.
pub fn write_interior(path: &Path, f: &crate::interior::InteriorField) -> Result<(), Error> {
    use crate::interior::PointStatus;
    let [nx, ny] = f.shape;
    let inside = |k: usize| f.status[k] == PointStatus::Inside;
    let mut connectivity = Vec::new();
    for j in 0..ny.saturating_sub(1) {
        for i in 0..nx.saturating_sub(1) {
            let k = j * nx + i;
            let quad = [k, k + 1, k + 1 + nx, k + nx];
            if quad.iter().all(|&c| inside(c)) {
                connectivity.extend(quad.map(|c| c as u64));
            }
        }
    }
    let (vm, ms): (Vec<f64>, Vec<f64>) = f.stress.iter().map(crate::interior::invariants).unzip();
    let (ux, uy): (Vec<f64>, Vec<f64>) = f.displacement.iter().map(|u| (u[0], u[1])).unzip();
    let stress = f.stress.iter().flatten().copied().collect();
    let status = f.status.iter().map(|s| s.code()).collect();
    let grid = UnstructuredGrid {
        points: f.points.iter().map(|p| [p[0], p[1], 0.0]).collect(),
        cell_type: CellType::Quad,
        connectivity,
        point_data: vec![
            DataArray::scalars("stress", 4, Values::F64(stress)),
            DataArray::scalar("von_mises", vm),
            DataArray::scalar("max_shear", ms),
            DataArray::vector_xy("displacement", &ux, &uy),
            DataArray::scalars("status", 1, Values::I32(status)),
        ],
        cell_data: Vec::new(),
    };
    write_file(path, |out| grid.write(out))
}

/// Creates `path` and writes it through a buffer; any failure is an [`Error::Output`] naming it.
fn write_file(path: &Path, write: impl FnOnce(&mut dyn Write) -> std::io::Result<()>) -> Result<(), Error> {
    let written = std::fs::File::create(path).and_then(|file| {
        let mut out = std::io::BufWriter::new(file);
        write(&mut out)?;
        out.flush()
    });
    written.map_err(|e| Error::Output {
        path: path.to_path_buf(),
        message: e.to_string(),
    })
}

/// One dataset of a `.pvd` collection.
#[derive(Debug, Clone)]
pub struct CollectionEntry {
    /// File, relative to the `.pvd`.
    pub file: String,
    /// Step number (ParaView's time axis).
    pub timestep: f64,
    /// Part index within a step.
    pub part: usize,
    /// Name shown in ParaView.
    pub name: String,
}

/// Writes a ParaView collection file (`.pvd`). File names and dataset names are escaped, so a
/// folder named `a&b` or `"q"` still gives a well-formed file.
pub fn write_collection(path: &Path, entries: &[CollectionEntry]) -> Result<(), Error> {
    write_file(path, |out| {
        out.write_all(
            b"<?xml version=\"1.0\"?>\n<VTKFile type=\"Collection\" version=\"0.1\" byte_order=\"LittleEndian\">\n  <Collection>\n",
        )?;
        for e in entries {
            writeln!(
                out,
                "    <DataSet timestep=\"{}\" group=\"\" part=\"{}\" file=\"{}\" name=\"{}\"/>",
                e.timestep,
                e.part,
                escape(&e.file),
                escape(&e.name)
            )?;
        }
        out.write_all(b"  </Collection>\n</VTKFile>\n")
    })
}
