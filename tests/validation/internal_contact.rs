//! Internal contact: a convex roller inside a concave bore (a negative profile radius), with
//! half-space and rigid bodies, against Hertz and Carter with 1/R* = 1/R_A + 1/R_B from the
//! signed radii (docs/references.md §1–§2; Johnson, *Contact Mechanics*, §4.2: a concave
//! surface enters the relative curvature with a negative radius). Same tolerances as the
//! convex tests of `hertz_carter.rs`.

use crate::common::solve;
use rollbem::analytic::hertz_pressure;
use rollbem::post::norms::nodal_error_against;

/// A steel roller R_A = 40 mm inside a steel bore R_B = −50 mm: R* = 200 mm; P for a = 1 mm
/// (P = πa²E*/(4R*), a quarter of the Carter cases' load on R* = 50 mm).
const ROLLER_IN_BORE: [&str; 3] = [
    "bodies.A.radius=40",
    "bodies.B.radius=-50",
    "load.normal.force=453.114325",
];

fn with<'a>(extra: &[&'a str]) -> Vec<&'a str> {
    ROLLER_IN_BORE.iter().copied().chain(extra.iter().copied()).collect()
}

/// Hertz with R* = 200 mm from the signed radii: a and p0 within 1 % at 41 elements, and the
/// estimates use the signed R*.
#[test]
fn half_space_roller_in_a_bore_matches_hertz_with_the_signed_effective_radius() {
    let s = solve("hertz", &with(&["contact.grid.elements=41"]));
    let est = &s.scene.estimates;
    assert!(
        (est.effective_radius - 200.0).abs() < 1e-9,
        "R* = {}",
        est.effective_radius
    );
    assert!(
        (est.hertz_half_width - 1.0).abs() < 1e-6,
        "a = {}",
        est.hertz_half_width
    );
    let [x0, x1] = s.solution.contact_extent().unwrap();
    let a = 0.5 * (x1 - x0);
    let p0 = s.solution.pressure.iter().fold(0.0_f64, |m, &p| m.max(p));
    assert!((a / est.hertz_half_width - 1.0).abs() < 0.01, "a = {a}");
    assert!((p0 / est.hertz_peak_pressure - 1.0).abs() < 0.01, "p0 = {p0}");
    // The RMS pressure error is that of the convex Hertz case on the same grid (the bore only
    // changes the gap's curvature): below 0.5 % of p0 at 161 elements.
    let s = solve("hertz", &with(&["contact.grid.elements=161"]));
    let rms = nodal_error_against(
        &s.solution.x,
        &s.solution.pressure,
        |x| hertz_pressure(x, 1.0, est.hertz_peak_pressure),
        1.3,
        est.hertz_peak_pressure,
    )
    .rms;
    assert!(rms < 0.005, "RMS pressure error {rms}");
}

/// Carter at Q/μP = 0.51 and 0.84 in the bore: shear within 2 % of μp0 at every node, the
/// stick zone's width within one element, creepage within 1 % of Carter's with R* = 200 mm.
#[test]
fn half_space_roller_in_a_bore_matches_carter() {
    for (ratio, n) in [("0.51", 81), ("0.84", 81), ("0.51", 161)] {
        let set = format!("load.tangential.ratio={ratio}");
        let grid = format!("contact.grid.elements={n}");
        let s = solve("carter_051", &with(&[&set, &grid]));
        let carter = s.scene.carter_reference().unwrap();
        let mu_p0 = carter.friction * carter.peak_pressure;
        let max = nodal_error_against(
            &s.solution.x,
            &s.solution.shear,
            |x| carter.shear(x),
            f64::INFINITY,
            mu_p0,
        )
        .max;
        assert!(max < 0.02, "{ratio}/{n}: max |q − q_Carter| = {max} μp0");
        let stick = s.solution.zones_of(rollbem::post::NodeState::Stick);
        let [c0, c1] = carter.stick_zone();
        let [s0, s1] = stick[0];
        assert!(
            (s1 - s0 - (c1 - c0)).abs() < s.problem.grid.element_length(),
            "{ratio}/{n}: stick width {} vs Carter {}",
            s1 - s0,
            c1 - c0
        );
        let xi = carter.creep(s.scene.estimates.effective_radius);
        assert!(
            (s.solution.creep / xi - 1.0).abs() < 0.01,
            "{ratio}/{n}: creep {} vs Carter {xi}",
            s.solution.creep
        );
    }
}

/// A half-space roller R = 40 mm in a rigid bore R = −50 mm, frictionless (with friction the
/// rigid bore's β ≈ 0.29 would couple a shear into the pressure): Hertz with E* of the roller
/// alone (E/(1 − ν²)) and R* = 200 mm, a and p0 within 1 % at 41 elements.
#[test]
fn half_space_roller_in_a_rigid_bore_matches_hertz() {
    // E* = E/(1−ν²) = 230 769.23 MPa, twice the similar pair's: P = πa²E*/(4R*) for a = 1 mm.
    let s = solve(
        "hertz",
        &[
            "bodies.A.radius=40",
            "bodies.B={model: rigid, radius: -50}",
            "load.normal.force=906.22865",
            "contact.grid.elements=41",
            "contact.friction=0",
            "output.interior=null",
        ],
    );
    let est = &s.scene.estimates;
    assert!(
        (est.hertz_half_width - 1.0).abs() < 1e-5,
        "a = {}",
        est.hertz_half_width
    );
    let [x0, x1] = s.solution.contact_extent().unwrap();
    let p0 = s.solution.pressure.iter().fold(0.0_f64, |m, &p| m.max(p));
    assert!((0.5 * (x1 - x0) - 1.0).abs() < 0.01, "a = {}", 0.5 * (x1 - x0));
    assert!((p0 / est.hertz_peak_pressure - 1.0).abs() < 0.01, "p0 = {p0}");
}
