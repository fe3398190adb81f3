//! What a case will cost: wall time and peak memory of `rollbem run` on the case's own grid and
//! meshes, and of the alternative model (BEM rollers for a half-space scene, the half-space for
//! a BEM scene), estimated from the problem sizes before anything is built.
//!
//! **Time** (the 2-core development machine of docs/performance.md, release build; another
//! machine scales all terms alike, and a loaded one is slower): the half-space influence
//! coefficients fill m² matrix entries ([`SECONDS_PER_CONTACT_NODE_SQUARED`]); each of about
//! [`NEWTON_STEPS`] Newton steps factors a reduced system of about 1.3 m unknowns (dense LU,
//! [`SECONDS_PER_LU_UNKNOWN_CUBED`]) and multiplies m × m matrices; a `bem` body integrates
//! every element at every field node ([`SECONDS_PER_NODE_ELEMENT`]) and factors its 2N unknowns.
//! The constants reproduce docs/performance.md's measured carter2d and speed–accuracy tables
//! within a factor 1.5.
//!
//! **Memory** is the estimate that refuses oversized cases before a run,
//! [`crate::limits::MemoryEstimate`], so that `check` and `run` never disagree.

use crate::limits::{MemoryEstimate, ProblemSizes};

/// Seconds per squared contact node of the contact-problem assembly (block-Toeplitz fill).
pub const SECONDS_PER_CONTACT_NODE_SQUARED: f64 = 1.0e-7;
/// Seconds per cubed unknown of a dense LU (faer, 2 cores: ≈ 22 GFLOP/s on (2/3)n³).
pub const SECONDS_PER_LU_UNKNOWN_CUBED: f64 = 3.0e-11;
/// Seconds per squared contact node of one Newton step's matrix products and residuals.
pub const SECONDS_PER_STEP_NODE_SQUARED: f64 = 1.5e-8;
/// Newton steps of a typical run (7–14 on the shipped cases and the carter2d ladder).
pub const NEWTON_STEPS: f64 = 10.0;
/// Seconds per (field node × boundary element) pair of a BEM body's assembly (adaptive
/// quadrature of the H and G kernels): 1.3e-6–1.9e-6 from the speed–accuracy table's rollers,
/// 3.3e-6 from the HBEM benchmark's condensation (a loaded machine, the strain included).
pub const SECONDS_PER_NODE_ELEMENT: f64 = 2.0e-6;
/// Seconds per kernel evaluation of a layer cover's tables (a wavenumber node at a table
/// point, the tables built by the estimate and by the run): 2.7e-8–1.1e-7 measured on
/// cases/covered_roller_v_peak.yaml with b = 0.117–1 mm on a loaded 2-core machine.
pub const SECONDS_PER_KERNEL_EVALUATION: f64 = 5.0e-8;
/// The sizes a run's cost depends on.
#[derive(Debug, Clone, PartialEq)]
pub struct Sizes {
    /// Contact nodes m.
    pub contact_nodes: usize,
    /// (field nodes, boundary elements) of each `bem` body.
    pub bem_bodies: Vec<(usize, usize)>,
    /// Interior points asked for.
    pub interior_points: usize,
    /// Whether VTK files are written.
    pub vtk: bool,
    /// Kernel evaluations of the bodies' own tables (a layer cover's,
    /// [`crate::body::BodySetup::kernel_table_evaluations`]).
    pub kernel_evaluations: f64,
}

/// Estimated wall time [s] and peak memory [bytes] of a run.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Cost {
    /// Wall time [s].
    pub seconds: f64,
    /// Peak resident memory [bytes].
    pub bytes: f64,
}

impl Cost {
    /// The estimate for `sizes` (module docs).
    pub fn of(sizes: &Sizes) -> Self {
        let m = sizes.contact_nodes as f64;
        let reduced = 1.3 * m;
        let step = SECONDS_PER_LU_UNKNOWN_CUBED * reduced.powi(3) + SECONDS_PER_STEP_NODE_SQUARED * m * m;
        let mut seconds = SECONDS_PER_CONTACT_NODE_SQUARED * m * m
            + NEWTON_STEPS * step
            + SECONDS_PER_KERNEL_EVALUATION * sizes.kernel_evaluations;
        for &(nodes, elements) in &sizes.bem_bodies {
            let n = 2.0 * nodes as f64;
            // The LU's rate per flop ((2/3)n³ flops) applied to the 1 + 2m solves of 2n² flops
            // each that condense the body to the contact nodes.
            let per_flop = 1.5 * SECONDS_PER_LU_UNKNOWN_CUBED;
            seconds += SECONDS_PER_NODE_ELEMENT * (nodes * elements) as f64
                + SECONDS_PER_LU_UNKNOWN_CUBED * n.powi(3)
                + per_flop * 2.0 * (1.0 + 2.0 * m) * n * n;
        }
        let memory = MemoryEstimate::of(&ProblemSizes {
            contact_nodes: sizes.contact_nodes,
            bem_nodes: [sizes.bem_bodies.iter().map(|&(nodes, _)| nodes).max(), None],
            interior_points: sizes.interior_points,
            vtk: sizes.vtk,
        });
        Self {
            seconds,
            bytes: memory.bytes(),
        }
    }

    /// "0.3 s, 45 MB": rounded to two figures, as an estimate should be.
    pub fn describe(&self) -> String {
        format!("≈ {}, {}", human_seconds(self.seconds), human_bytes(self.bytes))
    }
}

/// (field nodes, boundary elements) of a BEM roller on a shaft meshed for `contact_elements`
/// contact elements the way the accuracy study meshes them (docs/performance.md: 97 boundary
/// elements at 41 contact elements, 505 at 321, ≈ 1100 field nodes).
pub fn roller_mesh(contact_elements: usize) -> (usize, usize) {
    let elements = (1.5 * contact_elements as f64 + 30.0).round() as usize;
    ((2.2 * elements as f64).round() as usize, elements)
}

/// A time for people: "40 ms", "3.2 s", "4 min", "2.5 h".
pub fn human_seconds(s: f64) -> String {
    if s < 1.0 {
        format!("{} ms", two_figures((1e3 * s).max(1.0)))
    } else if s < 120.0 {
        format!("{} s", two_figures(s))
    } else if s < 7200.0 {
        format!("{} min", two_figures(s / 60.0))
    } else {
        format!("{} h", two_figures(s / 3600.0))
    }
}

/// A byte count for people: "45 MB", "1.2 GB".
pub fn human_bytes(b: f64) -> String {
    let units = ["bytes", "kB", "MB", "GB", "TB"];
    let mut v = b;
    let mut u = 0;
    while v >= 1000.0 && u + 1 < units.len() {
        v /= 1000.0;
        u += 1;
    }
    format!("{} {}", two_figures(v), units[u])
}

/// `v` ≥ 0 to two significant figures, without trailing zeros: 1.2, 38, 370.
fn two_figures(v: f64) -> String {
    if v <= 0.0 || !v.is_finite() {
        return "0".into();
    }
    let exponent = v.log10().floor() as i32;
    let decimals = (1 - exponent).max(0) as usize;
    let scale = 10f64.powi(exponent - 1);
    format!("{:.decimals$}", (v / scale).round() * scale)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn half_space(elements: usize) -> Sizes {
        Sizes {
            contact_nodes: 3 * elements,
            bem_bodies: Vec::new(),
            interior_points: 0,
            vtk: true,
            kernel_evaluations: 0.0,
        }
    }

    /// docs/performance.md, carter2d: assembly + solve of 81, 161, 321 elements measured
    /// 33 ms, 122 ms, 604 ms; the speed–accuracy table's true-geometry rollers at 161 and 321
    /// contact elements 0.90 s and 5.5 s (a loaded machine). Within a factor 1.5 (the constants
    /// are round numbers fitted to those tables).
    #[test]
    fn reproduces_the_measured_tables() {
        for (elements, measured) in [(81, 0.0334), (161, 0.1217), (321, 0.6037)] {
            let t = Cost::of(&half_space(elements)).seconds;
            assert!(
                t / measured < 1.5 && measured / t < 1.5,
                "{elements}: {t} s against {measured} s"
            );
        }
        for (elements, measured) in [(161, 0.90), (321, 5.5)] {
            let mut sizes = half_space(elements);
            sizes.bem_bodies = vec![roller_mesh(elements); 2];
            let t = Cost::of(&sizes).seconds;
            assert!(
                t / measured < 1.5 && measured / t < 1.5,
                "bem {elements}: {t} s against {measured} s"
            );
        }
    }

    /// `check` prints the memory estimate that `run` refuses cases by (tests/input/memory.rs
    /// measures that one against the peak RSS): the largest `bem` body's field nodes count, and
    /// 16 MB + 180·m² + 28·(2N)² for 321 contact elements and rollers of 1100 and 900 nodes.
    #[test]
    fn memory_is_the_runs_estimate() {
        let mut sizes = half_space(321);
        sizes.vtk = false;
        sizes.interior_points = 0;
        sizes.bem_bodies = vec![(1100, 500), (900, 400)];
        let m = 3.0 * 321.0;
        let expected = 16e6 + 180.0 * m * m + 28.0 * 2200.0 * 2200.0;
        let b = Cost::of(&sizes).bytes;
        assert!((b - expected).abs() < 1.0, "{b} bytes against {expected}");
    }

    #[test]
    fn people_read_the_numbers() {
        assert_eq!(human_seconds(0.0432), "43 ms");
        assert_eq!(human_seconds(3.24), "3.2 s");
        assert_eq!(human_seconds(600.0), "10 min");
        assert_eq!(human_bytes(45.3e6), "45 MB");
        assert_eq!(human_bytes(1.234e9), "1.2 GB");
        assert_eq!(human_seconds(0.0012), "1.2 ms");
        assert_eq!(human_seconds(0.37), "370 ms");
    }
}
