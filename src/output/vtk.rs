//! VTK XML output (vtkio): the contact line as an unstructured grid of line cells, and `.pvd`
//! collections that tie a run's (or a sweep's) datasets together for ParaView.
//!
//! Point data of `contact.vtu` (one point per contact node, at (x, 0, 0) in the contact frame):
//! every column of contact.csv — `pressure`, `shear`, `gap`, `slip`, `slip_hbem` (only when the
//! models provide it), `state` (integer: 0 open, 1 stick, 2 slip), `u_n_A`, `u_t_A`, `u_n_B`,
//! `u_t_B` — plus the 3-vectors `traction` = (q, p, 0) (on A; B receives the opposite) and
//! `displacement_A` = (u_t_A, u_n_A, 0), `displacement_B` = (u_t_B, −u_n_B, 0) in x, y, z of the
//! contact frame (u_n is positive into each body, and B lies at y < 0). Displacements are real,
//! not scaled: use ParaView's Warp By Vector.

use crate::contact::ContactProblem;
use crate::error::Error;
use crate::post::{ContactSolution, NodeState};
use std::path::Path;
use vtkio::model::{
    Attribute, Attributes, ByteOrder, CellType, Cells, DataArray, DataSet, ElementType, UnstructuredGridPiece, Version,
    VertexNumbers, Vtk,
};

/// Integer code of a node state in VTK files (documented legend: 0 open, 1 stick, 2 slip).
pub fn state_code(state: NodeState) -> i32 {
    match state {
        NodeState::Open => 0,
        NodeState::Stick => 1,
        NodeState::Slip => 2,
    }
}

fn scalar(name: &str, values: Vec<f64>) -> Attribute {
    Attribute::DataArray(DataArray {
        name: name.into(),
        elem: ElementType::Scalars {
            num_comp: 1,
            lookup_table: None,
        },
        data: values.into(),
    })
}

fn vector(name: &str, x: &[f64], y: &[f64]) -> Attribute {
    let data: Vec<f64> = x.iter().zip(y).flat_map(|(a, b)| [*a, *b, 0.0]).collect();
    Attribute::DataArray(DataArray {
        name: name.into(),
        elem: ElementType::Vectors,
        data: data.into(),
    })
}

/// Writes the contact line of a solved run as `contact.vtu`.
pub fn write_contact_line(path: &Path, sol: &ContactSolution, pb: &ContactProblem) -> Result<(), Error> {
    let m = sol.x.len();
    let points: Vec<f64> = sol.x.iter().flat_map(|&x| [x, 0.0, 0.0]).collect();
    let connectivity: Vec<u64> = (0..m.saturating_sub(1) as u64).flat_map(|i| [i, i + 1]).collect();
    let offsets: Vec<u64> = (1..m as u64).map(|k| 2 * k).collect();
    let disp = pb.surface_displacements(&sol.pressure, &sol.shear);
    let mut point = vec![
        scalar("pressure", sol.pressure.clone()),
        scalar("shear", sol.shear.clone()),
        scalar("gap", sol.gap.clone()),
        scalar("slip", sol.slip.clone()),
    ];
    if let Some(s) = &sol.slip_strain {
        point.push(scalar("slip_hbem", s.clone()));
    }
    point.push(Attribute::DataArray(DataArray {
        name: "state".into(),
        elem: ElementType::Scalars {
            num_comp: 1,
            lookup_table: None,
        },
        data: sol.state.iter().map(|&s| state_code(s)).collect::<Vec<i32>>().into(),
    }));
    point.extend([
        scalar("u_n_A", disp.normal_a.clone()),
        scalar("u_t_A", disp.tangential_a.clone()),
        scalar("u_n_B", disp.normal_b.clone()),
        scalar("u_t_B", disp.tangential_b.clone()),
        vector("traction", &sol.shear, &sol.pressure),
        vector("displacement_A", &disp.tangential_a, &disp.normal_a),
        vector(
            "displacement_B",
            &disp.tangential_b,
            &disp.normal_b.iter().map(|v| -v).collect::<Vec<_>>(),
        ),
    ]);
    let cell_types = vec![CellType::Line; m.saturating_sub(1)];
    export_unstructured(
        path,
        "rollbem contact line".into(),
        points,
        connectivity,
        offsets,
        cell_types,
        point,
        Vec::new(),
    )
}

/// Writes a body's boundary as quadratic edges (VTK type 21) with point data `displacement`
/// and `traction` (3-vectors, z = 0) and cell data `group` (the physical group's index; the
/// names are in the field data `group_names` order of the mesh, also listed in summary.json).
pub fn write_boundary(path: &Path, field: &crate::body::BoundaryField) -> Result<(), Error> {
    let n = field.points.len();
    let cells = n / 3;
    let points: Vec<f64> = field.points.iter().flat_map(|p| [p[0], p[1], 0.0]).collect();
    let connectivity: Vec<u64> = (0..n as u64).collect();
    let offsets: Vec<u64> = (1..=cells as u64).map(|k| 3 * k).collect();
    let split = |v: &[[f64; 2]]| {
        (
            v.iter().map(|a| a[0]).collect::<Vec<_>>(),
            v.iter().map(|a| a[1]).collect::<Vec<_>>(),
        )
    };
    let (ux, uy) = split(&field.displacement);
    let (tx, ty) = split(&field.traction);
    let group = Attribute::DataArray(DataArray {
        name: "group".into(),
        elem: ElementType::Scalars {
            num_comp: 1,
            lookup_table: None,
        },
        data: field.group.clone().into(),
    });
    export_unstructured(
        path,
        format!("rollbem boundary; groups: {}", field.group_names.join(", ")),
        points,
        connectivity,
        offsets,
        vec![CellType::QuadraticEdge; cells],
        vec![vector("displacement", &ux, &uy), vector("traction", &tx, &ty)],
        vec![group],
    )
}

/// Writes interior fields as a grid of quadrilaterals: point data `stress` (4 components
/// σxx, σyy, σzz, τxy), `von_mises`, `max_shear`, `displacement` (3-vector, z = 0) and `status`
/// (0 outside the body, 1 inside, 2 within the boundary layer; fields are 0 where not inside).
/// Only quadrilaterals whose four corners are inside are written as cells, so ParaView never
/// interpolates across points that were not evaluated; every point is kept.
pub fn write_interior(path: &Path, f: &crate::interior::InteriorField) -> Result<(), Error> {
    use crate::interior::PointStatus;
    let [nx, ny] = f.shape;
    let points: Vec<f64> = f.points.iter().flat_map(|p| [p[0], p[1], 0.0]).collect();
    let inside = |k: usize| f.status[k] == PointStatus::Inside;
    let mut connectivity = Vec::new();
    for j in 0..ny - 1 {
        for i in 0..nx - 1 {
            let k = j * nx + i;
            let quad = [k, k + 1, k + 1 + nx, k + nx];
            if quad.iter().all(|&c| inside(c)) {
                connectivity.extend(quad.map(|c| c as u64));
            }
        }
    }
    let cells = connectivity.len() / 4;
    let offsets: Vec<u64> = (1..=cells as u64).map(|c| 4 * c).collect();
    let (vm, ms): (Vec<f64>, Vec<f64>) = f.stress.iter().map(crate::interior::invariants).unzip();
    let stress = Attribute::DataArray(DataArray {
        name: "stress".into(),
        elem: ElementType::Scalars {
            num_comp: 4,
            lookup_table: None,
        },
        data: f.stress.iter().flatten().copied().collect::<Vec<f64>>().into(),
    });
    let (ux, uy): (Vec<f64>, Vec<f64>) = f.displacement.iter().map(|u| (u[0], u[1])).unzip();
    let status = Attribute::DataArray(DataArray {
        name: "status".into(),
        elem: ElementType::Scalars {
            num_comp: 1,
            lookup_table: None,
        },
        data: f.status.iter().map(|s| s.code()).collect::<Vec<i32>>().into(),
    });
    export_unstructured(
        path,
        format!(
            "rollbem interior of body {} ({} model): stress (sxx, syy, szz, txy), displacement; status 0 outside, 1 inside, 2 boundary",
            f.body, f.model
        ),
        points,
        connectivity,
        offsets,
        vec![CellType::Quad; cells],
        vec![
            stress,
            scalar("von_mises", vm),
            scalar("max_shear", ms),
            vector("displacement", &ux, &uy),
            status,
        ],
        Vec::new(),
    )
}

/// Writes an unstructured grid (XML `.vtu`) from flat points (x, y, z per point), XML-style
/// connectivity/offsets, one cell type per cell, and point and cell data.
#[allow(clippy::too_many_arguments)]
fn export_unstructured(
    path: &Path,
    title: String,
    points: Vec<f64>,
    connectivity: Vec<u64>,
    offsets: Vec<u64>,
    types: Vec<CellType>,
    point: Vec<Attribute>,
    cell: Vec<Attribute>,
) -> Result<(), Error> {
    let vtk = Vtk {
        version: Version::new_xml(1, 0),
        title,
        byte_order: ByteOrder::LittleEndian,
        file_path: None,
        data: DataSet::inline(UnstructuredGridPiece {
            points: points.into(),
            cells: Cells {
                cell_verts: VertexNumbers::XML { connectivity, offsets },
                types,
            },
            data: Attributes { point, cell },
        }),
    };
    vtk.export(path).map_err(|e| Error::Output {
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

/// Writes a ParaView collection file (`.pvd`).
pub fn write_collection(path: &Path, entries: &[CollectionEntry]) -> Result<(), Error> {
    let mut text = String::from(
        "<?xml version=\"1.0\"?>\n<VTKFile type=\"Collection\" version=\"0.1\" byte_order=\"LittleEndian\">\n  <Collection>\n",
    );
    for e in entries {
        text.push_str(&format!(
            "    <DataSet timestep=\"{}\" group=\"\" part=\"{}\" file=\"{}\" name=\"{}\"/>\n",
            e.timestep, e.part, e.file, e.name
        ));
    }
    text.push_str("  </Collection>\n</VTKFile>\n");
    std::fs::write(path, text).map_err(|e| Error::Output {
        path: path.to_path_buf(),
        message: e.to_string(),
    })
}
