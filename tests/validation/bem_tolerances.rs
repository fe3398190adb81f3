//! BEM cases at tolerances down to 1e-5 (the rows of examples/bem_tolerance_matrix.rs that the
//! test suite repeats; the example runs every shipped case with a `bem` body at 1e-3, 1e-4,
//! 3e-5 and 1e-5): each run meets its tolerance or stops at `contact.grid.max_elements` with
//! its estimate (exit code 2), never with an error of rollbem's own making (a cut of a body's
//! mesh that does not fit the grid it was cut along). fig14_true_geometry at 1e-4 and
//! carter_051_true at 3e-5 were refused that way before the cuts snapped their nodes.

use crate::bem_tolerance_matrix::{run, Outcome, MAX_ELEMENTS, TESTED};

/// The run of `TESTED[k]` meets its tolerance (the estimate and the body meshes' within it), or
/// stops at the element limit with an estimate above it.
fn meets_or_stops_at_the_limit(k: usize, capped: bool) {
    let (name, tolerance) = TESTED[k];
    let (outcome, _) = run(name, tolerance);
    match outcome {
        Outcome::Met(elements, estimate, body_mesh) => {
            assert!(
                !capped,
                "{name} at {tolerance:e}: met on {elements} elements, expected the limit"
            );
            assert!(estimate <= tolerance, "{name} at {tolerance:e}: estimate {estimate:e}");
            assert!(elements <= MAX_ELEMENTS, "{name} at {tolerance:e}: {elements} elements");
            let b = body_mesh.expect("bem bodies have a body-mesh estimate");
            assert!(b <= tolerance, "{name} at {tolerance:e}: body mesh {b:e}");
        }
        Outcome::Capped(elements, estimate) => {
            assert!(
                capped,
                "{name} at {tolerance:e}: stopped at {elements} elements, expected to meet it"
            );
            assert!(estimate > tolerance, "{name} at {tolerance:e}: stopped at {estimate:e}");
            assert!(
                2 * elements > MAX_ELEMENTS / 2,
                "{name} at {tolerance:e}: {elements} elements"
            );
        }
        Outcome::BodyMeshTooCoarse(b) => panic!("{name} at {tolerance:e}: body mesh too coarse ({b:e})"),
        Outcome::Failed(message) => panic!("{name} at {tolerance:e}: {message}"),
    }
}

#[test]
fn fig14_true_geometry_meets_1e_4() {
    meets_or_stops_at_the_limit(0, false);
}

#[test]
fn carter_051_true_meets_3e_5() {
    meets_or_stops_at_the_limit(1, false);
}

#[test]
fn non_matching_meshes_meet_1e_3() {
    meets_or_stops_at_the_limit(2, false);
}

#[test]
fn the_braking_bore_stops_at_the_element_limit_at_3e_5() {
    meets_or_stops_at_the_limit(3, true);
}
