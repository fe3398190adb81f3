//! Error against time on CONTACT's carter2d problem (cases/carter2d_contact.yaml): uniform
//! grids, error-controlled grids (`contact.grid.tolerance`) and CONTACT's measured curve
//! (docs/data/contact_carter2d.csv). Prints the table of docs/performance.md and draws
//! error_vs_time.svg into a temporary folder (`--figures DIR`: into DIR; `--update-docs`: the
//! figure of the docs, docs/img/error_vs_time.svg). Times are the whole `rollbem run` process
//! (best of 3); the `docs` test compares the columns that are not times.
//!
//! Run: `cargo build --release && cargo run --release --example error_vs_time [-- --update-docs]`.

pub mod common;

use common::{case_path, figure_dir, root, solve, Table};
use rollbem::app::Solved;
use rollbem::output::charts::accuracy::{self, Curve, Point};
use rollbem::post::norms::nodal_error_against;
use std::process::Command;
use std::time::Instant;

/// The header of the table.
pub const HEADER: [&str; 6] = [
    "grid",
    "elements",
    "nodes",
    "RMS q error (μp0)",
    "creep error",
    "whole process [s]",
];

/// The uniform grids.
pub const ELEMENTS: [usize; 5] = [21, 41, 81, 161, 321];

/// The tolerances of the error-controlled grids.
pub const TOLERANCES: [f64; 4] = [1e-2, 1e-3, 1e-4, 1e-5];

/// RMS shear error (μp0) and relative creepage error against Carter.
pub fn errors(s: &Solved) -> (f64, f64) {
    let c = s.scene.carter_reference().expect("carter2d prescribes Q/μP");
    let mu_p0 = c.friction * c.peak_pressure;
    let rms = nodal_error_against(&s.solution.x, &s.solution.shear, |x| c.shear(x), c.half_width, mu_p0).rms;
    let xi = c.creep(s.scene.estimates.effective_radius);
    (rms, (s.solution.creep / xi - 1.0).abs())
}

/// The overrides of one row: uniform elements or a tolerance.
pub fn overrides(uniform: Option<usize>, tolerance: Option<f64>) -> Vec<String> {
    match (uniform, tolerance) {
        (Some(n), _) => vec![format!("contact.grid.elements={n}")],
        (_, Some(t)) => vec![format!("contact.grid.tolerance={t:e}")],
        _ => Vec::new(),
    }
}

/// One row (`process_s` None: not measured, written `-`).
pub fn row(label: &str, s: &Solved, process_s: Option<f64>) -> Vec<String> {
    let (q, xi) = errors(s);
    vec![
        label.to_string(),
        s.problem.grid.n_elements().to_string(),
        s.problem.n_nodes().to_string(),
        format!("{q:.2e}"),
        format!("{xi:.1e}"),
        process_s.map_or("-".into(), |t| format!("{t:.3}")),
    ]
}

/// The rows' labels and overrides, uniform grids first.
pub fn runs() -> Vec<(String, Vec<String>)> {
    ELEMENTS
        .iter()
        .map(|&n| (format!("uniform {n}"), overrides(Some(n), None)))
        .chain(
            TOLERANCES
                .iter()
                .map(|&t| (format!("tolerance {t:.0e}"), overrides(None, Some(t)))),
        )
        .collect()
}

/// Best of 3 wall times of `rollbem run` with the overrides [s].
fn process_time(set: &[String]) -> f64 {
    let exe = root().join("target/release/rollbem");
    let out = std::env::temp_dir().join("rollbem_error_vs_time");
    let mut args = vec![
        "run".to_string(),
        case_path("carter2d_contact").to_string_lossy().into_owned(),
        "--out".into(),
        out.to_string_lossy().into_owned(),
    ];
    for v in set {
        args.push("--set".into());
        args.push(v.clone());
    }
    (0..3)
        .map(|_| {
            let t = Instant::now();
            let status = Command::new(&exe)
                .args(&args)
                .output()
                .expect("run the release binary (cargo build --release first)");
            assert!(status.status.success(), "{args:?}");
            t.elapsed().as_secs_f64()
        })
        .fold(f64::INFINITY, f64::min)
}

/// CONTACT's measured points: (elements, RMS shear error, time [s]).
pub fn contact_points() -> Vec<(usize, f64, f64)> {
    let text = std::fs::read_to_string(root().join("docs/data/contact_carter2d.csv")).expect("the data file");
    text.lines()
        .filter(|l| !l.starts_with('#') && !l.starts_with("elements"))
        .map(|l| {
            let f: Vec<&str> = l.split(',').collect();
            (f[0].parse().unwrap(), f[1].parse().unwrap(), f[2].parse().unwrap())
        })
        .collect()
}

fn main() {
    let mut t = Table::new(&HEADER);
    let mut curves = vec![
        Curve {
            name: "rollbem, uniform grids".into(),
            points: Vec::new(),
        },
        Curve {
            name: "rollbem, contact.grid.tolerance".into(),
            points: Vec::new(),
        },
        Curve {
            name: "CONTACT (rev 2707, measured)".into(),
            points: Vec::new(),
        },
    ];
    for (k, (label, set)) in runs().into_iter().enumerate() {
        let s = solve("carter2d_contact", &set);
        let time = process_time(&set);
        let (q, _) = errors(&s);
        let curve = usize::from(k >= ELEMENTS.len());
        curves[curve].points.push(Point {
            time_s: time,
            error: q,
            label: s.problem.grid.n_elements().to_string(),
        });
        t.push(row(&label, &s, Some(time)));
    }
    for (n, e, time) in contact_points() {
        curves[2].points.push(Point {
            time_s: time,
            error: e,
            label: n.to_string(),
        });
    }
    print!("{}", t.markdown());
    let path = figure_dir().join("error_vs_time.svg");
    accuracy::write(
        &path,
        "carter2d: RMS shear error against whole-process time",
        "labels: contact elements; error in units of mu p0 against Carter; 2-core machine",
        &curves,
        &[],
    )
    .expect("write the chart");
    eprintln!("wrote {}", path.display());
}
