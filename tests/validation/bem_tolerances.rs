//! BEM cases at tolerances down to 1e-5 (the rows of examples/bem_tolerance_matrix.rs that the
//! test suite repeats; the example runs every shipped case with a `bem` body at 1e-3, 1e-4,
//! 3e-5 and 1e-5): each run meets its tolerance or stops at `contact.grid.max_elements` with
//! its estimate (exit code 2), never with an error of rollbem's own making (a cut of a body's
//! mesh that does not fit the grid it was cut along). fig14_true_geometry at 1e-4 and
//! carter_051_true at 3e-5 were refused that way before the cuts snapped their nodes.

use crate::adaptive::{assert_true_errors_within, errors_against};
use crate::bem_tolerance_matrix::{run, Outcome, MAX_ELEMENTS, TESTED};
use crate::common::solve;

/// The run of `TESTED[k]` meets its tolerance: its true errors (RMS p/p0 and q/(μp0) over the
/// Hertz contact, relative creepage) against the same case at a third of the tolerance are
/// within the tolerance, and its body meshes' estimate too. Measured: fig14_true_geometry at
/// 1e-4 4.0e-6, 6.4e-6, 2.0e-6; carter_051_true at 3e-5 6.6e-6, 8.4e-6, 4.8e-6;
/// carter_051_true_nonmatching at 1e-3 2.4e-5, 4.3e-5, 5.5e-5.
fn meets_its_tolerance(k: usize) {
    let (name, tolerance) = TESTED[k];
    let at = |t: f64| {
        let set = [
            format!("contact.grid.tolerance={t:e}"),
            format!("contact.grid.max_elements={MAX_ELEMENTS}"),
        ];
        solve(name, &set.iter().map(String::as_str).collect::<Vec<_>>())
    };
    let s = at(tolerance);
    let a = s.adaptation.as_ref().expect("an error-controlled run");
    assert!(a.reached, "{name} at {tolerance:e}: stopped at the element limit");
    let body_mesh = a
        .estimate
        .and_then(|e| e.body_mesh)
        .expect("bem bodies have a body-mesh estimate");
    assert!(
        body_mesh.largest() <= tolerance,
        "{name} at {tolerance:e}: {body_mesh:?}"
    );
    let reference = at(tolerance / 3.0);
    let errors = errors_against(&reference, &s);
    println!(
        "{name} at {tolerance:e}: true errors p, q, ξ {:.2e} {:.2e} {:.2e}",
        errors.0, errors.1, errors.2
    );
    assert_true_errors_within(name, tolerance, errors);
}

#[test]
fn fig14_true_geometry_meets_1e_4() {
    meets_its_tolerance(0);
}

#[test]
fn carter_051_true_meets_3e_5() {
    meets_its_tolerance(1);
}

#[test]
fn non_matching_meshes_meet_1e_3() {
    meets_its_tolerance(2);
}

/// The braking bore at 3e-5 stops at the element limit (exit code 2) with an estimate above the
/// tolerance, on a grid near the limit.
#[test]
fn the_braking_bore_stops_at_the_element_limit_at_3e_5() {
    let (name, tolerance) = TESTED[3];
    match run(name, tolerance).0 {
        Outcome::Capped(elements, estimate) => {
            assert!(estimate > tolerance, "{name} at {tolerance:e}: stopped at {estimate:e}");
            assert!(
                4 * elements > MAX_ELEMENTS,
                "{name} at {tolerance:e}: {elements} elements"
            );
        }
        other => panic!("{name} at {tolerance:e}: {other:?}, expected the element limit"),
    }
}
