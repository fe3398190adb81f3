//! Parametric bodies (`geometry:`) against their Gmsh twins: the same geometry meshed by
//! rollbem and by Gmsh (the shipped meshes) gives the same creepage, overlap and peak pressure
//! to within the far field's discretisation error, which the generated mesh twice as fine
//! measures (examples/parametric_report.rs prints the table of docs/validation.md).

use crate::parametric_report::{numbers, relative, solve_generated, twins, Twin};
use rollbem::app::Solved;

/// The generated run, the Gmsh twin's and the refined run's relative differences.
fn differences(twin: &Twin) -> ([f64; 3], [f64; 3]) {
    let gmsh: Solved = crate::common::solve(twin.twin, &[]);
    let generated = solve_generated(twin, 1);
    let refined = solve_generated(twin, 2);
    (
        relative(numbers(&generated), numbers(&gmsh)),
        relative(numbers(&generated), numbers(&refined)),
    )
}

/// Measured (`cargo run --release --example parametric_report`): the twins differ by at most
/// 2.2e-7 (creepage, overlap and p_max, relative), the far field twice as fine moves them by
/// at most 2.3e-5 (the ring's creepage), so the twin's difference is within the
/// discretisation error of the far field. Bounds: 5e-7 and 5e-5.
fn assert_twin(family: &str) {
    let twin = twins().into_iter().find(|t| t.family == family).unwrap();
    let (d_twin, d_ref) = differences(&twin);
    for (k, what) in ["creepage", "overlap", "p_max"].iter().enumerate() {
        assert!(
            d_twin[k] < 5e-7,
            "{family}: {what} differs from the Gmsh twin by {:e}",
            d_twin[k]
        );
        assert!(
            d_ref[k] < 5e-5,
            "{family}: {what} moves by {:e} on the far field twice as fine",
            d_ref[k]
        );
    }
}

#[test]
fn a_generated_roller_matches_its_gmsh_twin() {
    assert_twin("roller");
}

#[test]
fn a_generated_ring_matches_its_gmsh_twin() {
    assert_twin("ring");
}

#[test]
fn a_generated_block_matches_its_gmsh_twin() {
    assert_twin("block");
}

#[test]
fn a_generated_covered_roller_matches_its_gmsh_twin() {
    assert_twin("covered_roller");
}

/// cases/fig14_geometry.yaml reproduces cases/fig14_true_geometry.yaml's summary: the same
/// contact grid, the same slip zones and regime, creepage, overlap and p_max within 5e-7
/// (measured 2.2e-7, 8.3e-8, 2.8e-8), tractions within 1e-6 of p0.
#[test]
fn fig14_geometry_reproduces_fig14_true_geometry() {
    let gmsh = crate::common::solve("fig14_true_geometry", &[]);
    let generated = crate::common::solve("fig14_geometry", &[]);
    let (g, m) = (&generated.solution, &gmsh.solution);
    assert_eq!(g.x.len(), m.x.len());
    for (a, b) in g.x.iter().zip(&m.x) {
        assert!((a - b).abs() < 1e-8, "grid nodes {a} and {b}");
    }
    for (k, d) in relative(numbers(&generated), numbers(&gmsh)).iter().enumerate() {
        assert!(*d < 5e-7, "number {k} differs by {d:e}");
    }
    let p0 = gmsh.scene.estimates.hertz_peak_pressure;
    for (a, b) in g.pressure.iter().zip(&m.pressure).chain(g.shear.iter().zip(&m.shear)) {
        assert!((a - b).abs() < 1e-6 * p0, "tractions {a} and {b}");
    }
    assert_eq!(generated.regime, gmsh.regime);
    assert_eq!(g.zones.len(), m.zones.len());
    assert_eq!(generated.report.iterations, gmsh.report.iterations);
}

/// An error-controlled grid cuts a generated mesh as it cuts a Gmsh one: fig14_geometry with
/// contact.grid.tolerance reaches it, like fig14_true_geometry.
#[test]
fn a_generated_body_follows_an_error_controlled_grid() {
    let s = crate::common::solve("fig14_geometry", &["contact.grid.tolerance=1e-3"]);
    let a = s.adaptation.as_ref().expect("an error-controlled run");
    assert!(a.reached, "the tolerance is reached");
    assert!(s.problem.grid.n_elements() > 21, "the grid was refined");
}
