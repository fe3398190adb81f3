//! Free-rolling creepage of unequal rollers on shafts at second order in a/R
//! (src/analytic/creepage.rs): its limits, its scaling, the solid-roller closed form derived in
//! docs/conformal.md §4, and a scene with an outside estimate (steel R 60 on shaft 8, R 90 on shaft 12,
//! a = 0.5 mm). The numbers of docs/conformal.md come from
//! `cargo test --release --test validation free_rolling_creepage:: -- --nocapture --test-threads 1`.

use rollbem::analytic::creepage::{
    free_rolling_creepage, free_rolling_creepage_solid_rollers, CreepageError, ShaftRoller,
};
use rollbem::material::Elastic;

fn steel() -> Elastic {
    Elastic::new(210_000.0, 0.3)
}

fn roller(radius: f64, shaft: f64) -> ShaftRoller {
    ShaftRoller {
        radius,
        shaft_radius: shaft,
        material: steel(),
    }
}

#[test]
fn unequal_rollers_on_shafts_match_the_outside_estimate() {
    // An estimate made outside this code for this scene: −1.34e−5 with tractions along
    // the global axes, −3.7e−6 along the local normal; agreement to its quoted digits.
    let c = free_rolling_creepage(&roller(60.0, 8.0), &roller(90.0, 12.0), 0.5).unwrap();
    let solid = free_rolling_creepage_solid_rollers(60.0, 90.0, 0.5, &steel());
    println!(
        "\n| steel R 60 on shaft 8, R 90 on shaft 12, a = 0.5 mm (P = {:.3} N/mm) | ξ |",
        c.load
    );
    println!("|---|---|");
    println!("| local normal (hoop strain) | {:.4e} |", c.local_normal);
    println!(
        "| global axes (∂u_x/∂x, uniform rigid speeds) | {:.4e} |",
        c.global_axes
    );
    println!(
        "| global-axes tractions, hoop strain | {:.4e} |",
        c.global_tractions_hoop_strain
    );
    println!(
        "| solid rollers, closed form: local / global | {:.4e} / {:.4e} |",
        solid[1], solid[0]
    );
    assert!((c.local_normal + 3.7e-6).abs() < 0.05e-6, "{}", c.local_normal);
    assert!((c.global_axes + 1.34e-5).abs() < 0.005e-5, "{}", c.global_axes);
    assert_eq!(c.as_array(), [c.global_axes, c.local_normal]);
}

#[test]
fn equal_rollers_do_not_creep() {
    let c = free_rolling_creepage(&roller(60.0, 8.0), &roller(60.0, 8.0), 0.5).unwrap();
    assert_eq!(c.local_normal, 0.0);
    assert_eq!(c.global_axes, 0.0);
}

#[test]
fn creepage_vanishes_as_the_square_of_a_over_r() {
    // Scaling both rollers (and shafts) by λ at fixed a: ξ = c (a/R)² (1 + O(a/R)), so λ²ξ tends
    // to a constant and ξ → 0 as R → ∞. Between λ = 4 and 8 the O(a/R) term changes λ²ξ by
    // 3.5e−6 (local) and 3.7e−6 (global) of its value: tolerance 1e−4.
    let mut last = [0.0; 2];
    println!("\n| λ (R_A = 60λ, R_B = 90λ) | λ²ξ local | λ²ξ global |");
    println!("|---|---|---|");
    for lambda in [1.0, 2.0, 4.0, 8.0] {
        let c = free_rolling_creepage(
            &roller(60.0 * lambda, 8.0 * lambda),
            &roller(90.0 * lambda, 12.0 * lambda),
            0.5,
        )
        .unwrap();
        let scaled = [c.local_normal * lambda * lambda, c.global_axes * lambda * lambda];
        println!("| {lambda} | {:.6e} | {:.6e} |", scaled[0], scaled[1]);
        if lambda == 8.0 {
            for i in 0..2 {
                assert!(
                    (scaled[i] / last[i] - 1.0).abs() < 1e-4,
                    "λ = 8: {scaled:?} vs {last:?}"
                );
            }
            assert!(c.local_normal.abs() < 1e-7 && c.global_axes.abs() < 3e-7);
        }
        last = scaled;
    }
}

#[test]
fn creepage_scales_with_a_squared() {
    // At fixed radii ξ/a² → constant as a → 0, the deviation O(a/R): between a = 0.125 and
    // 0.5 mm within 3·(0.5/60) of the value.
    let (ra, rb) = (roller(60.0, 8.0), roller(90.0, 12.0));
    let r = |a: f64| {
        let c = free_rolling_creepage(&ra, &rb, a).unwrap();
        [c.local_normal / (a * a), c.global_axes / (a * a)]
    };
    let (small, large) = (r(0.125), r(0.5));
    for i in 0..2 {
        assert!(
            (large[i] / small[i] - 1.0).abs() < 3.0 * 0.5 / 60.0,
            "{small:?} {large:?}"
        );
    }
}

#[test]
fn solid_rollers_match_the_closed_form() {
    // Shafts of 1e−3 R: the series must reach eq. R6–R7 (solid discs reacted at the centre) up
    // to O(a/R) (third order) and O((r/R)²): measured 5e−5 at a/R_A = 1/120.
    for a in [0.25, 0.5] {
        let c = free_rolling_creepage(&roller(60.0, 0.06), &roller(90.0, 0.09), a).unwrap();
        let [global, local] = free_rolling_creepage_solid_rollers(60.0, 90.0, a, &steel());
        let tol = a / 60.0;
        assert!(
            (c.local_normal / local - 1.0).abs() < tol,
            "a = {a}: {} vs {local}",
            c.local_normal
        );
        assert!(
            (c.global_axes / global - 1.0).abs() < tol,
            "a = {a}: {} vs {global}",
            c.global_axes
        );
    }
}

#[test]
fn traction_direction_alone_is_third_order() {
    // Global-axes tractions with the hoop strain differ from the local normal by O(a/R) of ξ:
    // halving a halves the relative difference (within 10 %).
    let (ra, rb) = (roller(60.0, 8.0), roller(90.0, 12.0));
    let rel = |a: f64| {
        let c = free_rolling_creepage(&ra, &rb, a).unwrap();
        c.global_tractions_hoop_strain / c.local_normal - 1.0
    };
    let (r1, r2) = (rel(1.0), rel(0.5));
    assert!(r1.abs() < 0.02, "{r1}");
    assert!((r1 / r2 - 2.0).abs() < 0.2, "{r1} {r2}");
}

#[test]
fn dissimilar_rollers_are_refused() {
    let mut b = roller(90.0, 12.0);
    b.material = Elastic::new(70_000.0, 0.33);
    assert_eq!(
        free_rolling_creepage(&roller(60.0, 8.0), &b, 0.5).unwrap_err(),
        CreepageError::Dissimilar
    );
}
