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
            .map_or(String::new(), |s| number(s[i]));
        w.write_record([
            number(sol.x[i]),
            number(sol.pressure[i]),
            number(sol.shear[i]),
            number(sol.gap[i]),
            number(sol.slip[i]),
            hbem,
            sol.state[i].name().to_string(),
            number(disp.normal_a[i]),
            number(disp.tangential_a[i]),
            number(disp.normal_b[i]),
            number(disp.tangential_b[i]),
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
            .map(number)
            .to_vec();
        row.push(f.status[k].name().to_string());
        w.write_record(&row).map_err(|e| io(&e))?;
    }
    w.flush().map_err(|e| io(&e))
}

/// Writes residual_stress_<body>.csv: per depth row of a strength assessment, the depth z,
/// the row's own shakedown factor λ_sd(z) and the residual stresses (σx^r, σy^r) that keep the
/// stresses times λ_sd within yield (docs/strength.md).
pub fn write_residual_stress_csv(path: &Path, b: &crate::post::strength::assess::BodyStrength) -> Result<(), Error> {
    let io = |e: csv::Error| Error::Output {
        path: path.to_path_buf(),
        message: e.to_string(),
    };
    let mut w = csv::Writer::from_path(path).map_err(io)?;
    w.write_record(["z", "row_factor", "residual_sxx", "residual_szz_out_of_plane"])
        .map_err(io)?;
    for r in &b.shakedown.rows {
        w.write_record([
            number(r.z),
            number(r.factor),
            number(r.residual[0]),
            number(r.residual[1]),
        ])
        .map_err(io)?;
    }
    w.flush().map_err(|e| Error::Output {
        path: path.to_path_buf(),
        message: e.to_string(),
    })
}

/// A number as the CSV files write it: the shortest digits that read back to the same f64
/// (Rust's formatting of f64 is shortest round-trip), plainly written where that is short
/// (`470.805575`, `0.0123`) and with an exponent otherwise (`1.25e-7`, `3e20`), as Python's
/// `repr` does; zero is `0` (also −0).
pub fn number(v: f64) -> String {
    let a = v.abs();
    if v == 0.0 {
        "0".to_string()
    } else if (1e-4..1e16).contains(&a) {
        format!("{v}")
    } else {
        format!("{v:e}")
    }
}

#[cfg(test)]
mod tests {
    use super::number;

    #[test]
    fn numbers_are_short_and_read_back_exactly() {
        assert_eq!(number(470.805575), "470.805575");
        assert_eq!(number(0.0), "0");
        assert_eq!(number(-0.0), "0");
        assert_eq!(number(1.25e-7), "1.25e-7");
        assert_eq!(number(-3e20), "-3e20");
        assert_eq!(number(0.1 + 0.2), "0.30000000000000004");
        assert_eq!(number(1e-4), "0.0001");
        for v in [
            std::f64::consts::PI,
            -1.0 / 3.0,
            6.030373e-4,
            1.7976931348623157e308,
            5e-324,
            1812.4573,
            9.999_999_999_999_998e15,
        ] {
            assert_eq!(number(v).parse::<f64>().unwrap(), v, "{v:e} reads back");
        }
    }
}
