//! contact.csv and interior_<body>.csv: one row per contact node or interior point.

use crate::contact::ContactProblem;
use crate::error::Error;
use crate::interior::InteriorField;
use crate::post::ContactSolution;
use std::path::Path;

/// Column names of contact.csv, in order (cases/README.md; with the surface displacements).
pub const CSV_COLUMNS: [&str; 11] = [
    "x",
    "pressure",
    "shear",
    "gap",
    "slip",
    "slip_hbem",
    "state",
    "u_n_A",
    "u_t_A",
    "u_n_B",
    "u_t_B",
];

/// Writes contact.csv. `slip_hbem` is left empty when no boundary-integral derivative exists
/// (and, defensively, for a non-finite value: no NaN is ever written).
/// Surface displacements: u_n positive into the body, u_t along +x of the contact frame.
pub fn write_csv(path: &Path, sol: &ContactSolution, pb: &ContactProblem) -> Result<(), Error> {
    let io = |e: csv::Error| Error::Output {
        path: path.to_path_buf(),
        message: e.to_string(),
    };
    let mut w = csv::Writer::from_path(path).map_err(io)?;
    w.write_record(CSV_COLUMNS).map_err(io)?;
    let disp = pb.surface_displacements(&sol.pressure, &sol.shear);
    for i in 0..sol.x.len() {
        let hbem = sol
            .slip_strain
            .as_ref()
            .filter(|s| s[i].is_finite())
            .map_or(String::new(), |s| fmt(s[i]));
        w.write_record([
            fmt(sol.x[i]),
            fmt(sol.pressure[i]),
            fmt(sol.shear[i]),
            fmt(sol.gap[i]),
            fmt(sol.slip[i]),
            hbem,
            sol.state[i].name().to_string(),
            fmt(disp.normal_a[i]),
            fmt(disp.tangential_a[i]),
            fmt(disp.normal_b[i]),
            fmt(disp.tangential_b[i]),
        ])
        .map_err(io)?;
    }
    w.flush().map_err(|e| Error::Output {
        path: path.to_path_buf(),
        message: e.to_string(),
    })
}

/// Writes interior_<body>.csv, one row per grid point (x fastest): `x, y, sxx, syy, szz, txy,
/// von_mises, max_shear, ux, uy, status` in the contact frame (σzz out of plane, tension
/// positive; ux, uy the displacement). `status` is `inside` where the body's model evaluated the
/// point, `outside` (not in the body) or `boundary` (within the boundary layer): those rows
/// carry zeros.
pub fn write_interior_csv(path: &Path, f: &InteriorField) -> Result<(), Error> {
    let io = |e: &dyn std::fmt::Display| Error::Output {
        path: path.to_path_buf(),
        message: e.to_string(),
    };
    let mut w = csv::Writer::from_path(path).map_err(|e| io(&e))?;
    w.write_record([
        "x",
        "y",
        "sxx",
        "syy",
        "szz",
        "txy",
        "von_mises",
        "max_shear",
        "ux",
        "uy",
        "status",
    ])
    .map_err(|e| io(&e))?;
    for (k, (p, s)) in f.points.iter().zip(&f.stress).enumerate() {
        let (vm, ms) = crate::interior::invariants(s);
        let u = f.displacement[k];
        let mut row: Vec<String> = [p[0], p[1], s[0], s[1], s[2], s[3], vm, ms, u[0], u[1]]
            .map(fmt)
            .to_vec();
        row.push(f.status[k].name().to_string());
        w.write_record(&row).map_err(|e| io(&e))?;
    }
    w.flush().map_err(|e| io(&e))
}

/// Full-precision, round-trippable number formatting.
fn fmt(v: f64) -> String {
    format!("{v:e}")
}
