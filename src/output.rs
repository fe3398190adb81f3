//! Results on disk: summary.json, contact.csv, contact.svg, the VTK files, and the terminal
//! table (cases/README.md lists the files and their columns). This stage and its files are the
//! only places that name plotters and write VTK XML (output/vtk/xml.rs); they write what the
//! earlier stages computed and compute no physics.
//!
//! Everything is written to a temporary sibling folder and renamed onto the output folder only
//! when complete, so a failed run never leaves a half-written result; an output folder that
//! holds anything rollbem did not write is refused ([`folder`]).

pub mod charts;
mod csv_files;
pub mod summary;
pub mod svg;
mod table;
pub mod transient;
pub mod units;
pub mod vtk;

use crate::error::Error;
pub use crate::files as folder;
pub use csv_files::{number, write_csv, write_interior_csv, write_residual_stress_csv, CSV_COLUMNS};
use std::path::Path;
use std::time::Instant;
pub use summary::{summary, Summary};
pub use table::render_table;

/// Writes all outputs of a run atomically into `dir` and fills in the total time.
/// A non-converged run writes summary.json only.
pub fn write_run(dir: &Path, summary: &mut Summary, solved: &crate::post::Solved, start: Instant) -> Result<(), Error> {
    log::info!(target: crate::logging::PROGRESS, "writing the results to {}", dir.display());
    write_atomically(dir, folder::Kind::Run, |tmp| {
        write_run_files(tmp, summary, solved, start)
    })
}

/// Writes the files of a run into the folder `tmp` being filled (summary.json last, with the
/// total time): [`write_run`]'s, and a transient run's beside its own.
pub fn write_run_files(
    tmp: &Path,
    summary: &mut Summary,
    solved: &crate::post::Solved,
    start: Instant,
) -> Result<(), Error> {
    let (sol, pb, boundary) = (&solved.solution, &solved.problem, &solved.boundary);
    let interior = solved.interior.as_ref();
    {
        if summary.converged {
            write_csv(&tmp.join("contact.csv"), sol, pb)?;
            if let Some(f) = interior {
                write_interior_csv(&tmp.join(format!("interior_{}.csv", f.body)), f)?;
            }
            for b in &solved.strength {
                write_residual_stress_csv(&tmp.join(format!("residual_stress_{}.csv", b.body)), b)?;
                let units = ["overlap", "max_pressure"].map(|k| summary.units.get(k).cloned().unwrap_or_default());
                charts::residual::write(
                    &tmp.join(format!("strength_{}.svg", b.body)),
                    &residual_picture(b, units),
                )?;
            }
            let unit = |key: &str| summary.units.get(key).map_or("", String::as_str);
            let plot = svg::ContactPlot {
                solution: sol,
                friction: pb.friction,
                flow_sign: pb.flow_sign,
                title: &summary.title,
                length_unit: unit("overlap"),
                stress_unit: unit("max_pressure"),
                force_unit: unit("normal_force"),
                rolling_resistance: summary.rolling_resistance.as_ref().filter(|r| r.speed.is_some()),
            };
            svg::write_contact_plot(&tmp.join("contact.svg"), &plot)?;
            if summary.vtk {
                vtk::write_contact_line(&tmp.join("contact.vtu"), sol, pb)?;
                let mut entries = vec![vtk::CollectionEntry {
                    file: "contact.vtu".into(),
                    timestep: 0.0,
                    part: 0,
                    name: "contact".into(),
                }];
                for (side, field) in ["A", "B"].iter().zip(boundary) {
                    if let Some(f) = field {
                        let file = format!("boundary_{side}.vtu");
                        vtk::write_boundary(&tmp.join(&file), f)?;
                        entries.push(vtk::CollectionEntry {
                            file,
                            timestep: 0.0,
                            part: entries.len(),
                            name: format!("body {side}"),
                        });
                    }
                }
                if let Some(f) = interior {
                    let file = format!("interior_{}.vtu", f.body);
                    vtk::write_interior(&tmp.join(&file), f)?;
                    entries.push(vtk::CollectionEntry {
                        file,
                        timestep: 0.0,
                        part: entries.len(),
                        name: format!("interior {}", f.body),
                    });
                }
                vtk::write_collection(&tmp.join("result.pvd"), &entries)?;
            }
        }
        summary.timings.total_s = start.elapsed().as_secs_f64();
        let err = |path: &Path, e: &dyn std::fmt::Display| Error::Output {
            path: path.to_path_buf(),
            message: e.to_string(),
        };
        let json = serde_json::to_string_pretty(summary).map_err(|e| err(tmp, &e))?;
        std::fs::write(tmp.join("summary.json"), json).map_err(|e| err(tmp, &e))
    }
}

/// The strength picture of one body.
fn residual_picture(
    b: &crate::post::strength::assess::BodyStrength,
    units: [String; 2],
) -> charts::residual::ResidualPicture {
    charts::residual::ResidualPicture {
        title: format!(
            "body {} ({}), {}: shakedown limit {:.4} x the stresses at depth {:.4}",
            b.body,
            b.model,
            b.criterion.name(),
            b.shakedown.factor,
            b.shakedown.z
        ),
        factor: b.shakedown.factor,
        governing_depth: b.shakedown.z,
        units,
        rows: b
            .shakedown
            .rows
            .iter()
            .map(|r| charts::residual::Row {
                z: r.z,
                factor: r.factor,
                residual: r.residual,
            })
            .collect(),
    }
}

/// Writes a result of `kind` atomically into `dir` through a temporary sibling folder, replacing
/// an earlier rollbem result of the same kind and refusing a folder that holds anything else
/// (see [`folder`]: the manifest, the lock, the rules). On failure `dir` is left as it was.
pub fn write_atomically(
    dir: &Path,
    kind: folder::Kind,
    write: impl FnOnce(&Path) -> Result<(), Error>,
) -> Result<(), Error> {
    folder::write_atomically(dir, kind, write)
}
