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

/// A thin cover (b = 0.5 mm on a rigid core, R = 100 mm) under the rigid roller of
/// cases/tyre_b05_compressible.yaml, which has no Gmsh twin (the shipped layer is a flat strip):
/// its far field twice as fine moves the creepage by 1.3e-5, the overlap-controlled load P and
/// p_max by 2e-7 (bound 5e-5). The bond's elements under the contact subtend the contact
/// elements' angle: with elements of one thickness there (0.5 mm against the contact's
/// 0.084 mm), the refined far field moved the creepage by 3.2e-3.
#[test]
fn a_thin_covered_roller_converges_with_its_far_field() {
    let twin = Twin {
        family: "covered_roller (thin)",
        twin: "tyre_b05_compressible",
        generated: "tyre_b05_compressible",
        overrides: [
            "bodies.B.mesh=null",
            "bodies.B.geometry={covered_roller: {radius: 100, cover_thickness: 0.5}}",
            "bodies.B.boundaries={bonded: fixed}",
            "contact.grid.elements=31",
            "contact.grid.half_length=1.3",
        ]
        .map(String::from)
        .to_vec(),
    };
    let (g, r) = (solve_generated(&twin, 1), solve_generated(&twin, 2));
    let d = relative(numbers(&g), numbers(&r));
    let dp = (g.solution.normal_force / r.solution.normal_force - 1.0).abs();
    println!(
        "thin cover, far field refined: creepage {:e}, p_max {:e}, P {dp:e}",
        d[0], d[2]
    );
    for (what, v) in [("creepage", d[0]), ("p_max", d[2]), ("P", dp)] {
        assert!(v < 5e-5, "{what} moves by {v:e}");
    }
}

/// A generated body follows a refined grid with its new contact nodes on the exact circle (not
/// on each element's quadratic, as a mesh file's cuts are): fig14_geometry's rollers (R = 150
/// above the contact, 300 below, both touching at the origin) on a coarse start grid of 3
/// elements after two bisections: every contact node within 1e-13·R of its circle (measured
/// 2e-16; the element's quadratic would leave it by 4.6e-11·R).
#[test]
fn a_generated_body_cuts_its_contact_on_the_exact_circle() {
    use rollbem::adapt::cells::DyadicGrid;
    let set = ["contact.grid.elements=3".to_string()];
    let loaded = rollbem::case::load(&crate::common::case_path("fig14_geometry"), &set).unwrap();
    let scene = rollbem::scene::Scene::from_case(&loaded).unwrap();
    let finer = DyadicGrid::new(&scene.grid).bisected().bisected().grid();
    for (setup, centre_y, radius) in [(&scene.bodies[0], 150.0, 150.0), (&scene.bodies[1], -300.0, 300.0)] {
        let followed = setup.follow_grid(&finer).expect("a bem body follows the grid");
        let own = followed.contact_mesh().expect("a contact mesh");
        let mut count = 0;
        for p in own.mesh.contact_nodes() {
            let distance = (p[0] * p[0] + (p[1] - centre_y) * (p[1] - centre_y)).sqrt();
            assert!(
                (distance - radius).abs() < 1e-13 * radius,
                "node {p:?}: {distance} from the centre"
            );
            count += 1;
        }
        assert!(
            count > 3 * scene.grid.n_elements(),
            "the contact was cut: {count} node entries"
        );
    }
}
