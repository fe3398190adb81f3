//! Tyred cylinder (paper §5.4, Figs 10–13): a rigid cylinder rolling on a cover layer
//! bonded to a rigid core, the layer a BEM strip (`meshes/tyre_layer_b*.geo`), load by overlap.
//! References: the thin-layer limits of the docs/references.md §5 (derived there from the exact
//! layer compliance C(k), whose BEM reproduction is tested in `tests/bem/layer.rs`).

use crate::common::solve;

/// Frictionless normal contact (μ = 0, ξ = 0 prescribed) of the rigid R = 100 mm cylinder on a
/// layer of thickness b [mm] (mesh `tyre_layer_b<tag>.msh`), Poisson's ratio ν, overlap δ0 of
/// the thin-layer limit for a = 1 mm. Returns (a, P, max |p − p_thin| / p_max), p_thin the
/// thin-layer pressure shape with the measured P, a and contact centre.
fn thin_layer_run(tag: &str, nu: f64) -> (f64, f64, f64) {
    frictionless_thin_layer(
        "tyre_b01_incompressible",
        nu,
        &format!("bodies.B.mesh=../meshes/tyre_layer_b{tag}.msh"),
        None,
    )
}

/// `load.normal.overlap=…` of the thin-layer limit for a = 1 mm under R = 100 mm (sheet §5:
/// δ = a²/(2R) compressible, Winkler; a²/(6R) incompressible).
fn thin_layer_overlap(nu: f64) -> String {
    let radius = 100.0;
    let overlap = if nu < 0.5 { 0.5 / radius } else { 1.0 / (6.0 * radius) };
    format!("load.normal.overlap={overlap}")
}

/// The same contact on the exact layer model (`model: layer`, the plane-strain Fourier
/// compliance of a layer bonded to a rigid base, docs/viscoelastic.md "The layer"), on the
/// contact grid of the BEM strip's mesh (`elements` equal elements on |x| ≤ 1.3 mm):
/// (a, P, shape error) as [`thin_layer_run`].
fn exact_layer_run(b: f64, elements: usize, nu: f64) -> (f64, f64, f64) {
    frictionless_thin_layer(
        "tyre_b05_layer",
        nu,
        &format!("bodies.B.thickness={b}"),
        Some(&format!("contact.grid.elements={elements}")),
    )
}

/// Frictionless normal contact (μ = 0, ξ = 0) of `case` with `layer` (its mesh or thickness),
/// Poisson's ratio ν, the thin-layer overlap for a = 1 mm and `grid` if given, fitted by
/// [`crate::common::thin_layer_fit`].
fn frictionless_thin_layer(case: &str, nu: f64, layer: &str, grid: Option<&str>) -> (f64, f64, f64) {
    let (nu_set, overlap) = (format!("materials.rubber.nu={nu}"), thin_layer_overlap(nu));
    let mut set = vec![
        layer,
        nu_set.as_str(),
        overlap.as_str(),
        "contact.friction=0",
        "load.tangential.ratio=null",
        "load.tangential.creep=0",
    ];
    set.extend(grid);
    let s = solve(case, &set);
    crate::common::thin_layer_fit(&s.solution, nu)
}

/// The BEM strips of the tyre meshes against the exact layer model on the same grid, normal
/// contact at b/a from 0.5 to 0.05, ν = 0.3 and 0.5: P within 1e-3 (measured at most 8e-5),
/// the contact half-width within 2e-3 mm (a fifteenth of the node spacing: the edge lies between
/// the same nodes; measured 2e-4) and the same pressure shape within 5e-3 of p_max (measured
/// 6e-4). The strips' bonded face is as fine as the contact under it: with elements of
/// 0.5 mm there (5 to 10 thicknesses, as the strips once had) P was 2 % low at b/a = 0.1 and 7 %
/// low at 0.05 for ν = 0.5.
#[test]
fn the_bem_strips_reproduce_the_exact_layer() {
    let tags = [("05", 0.5, 31), ("025", 0.25, 31), ("01", 0.1, 31), ("005", 0.05, 61)];
    for nu in [0.3, 0.5] {
        for (tag, b, elements) in tags {
            let (a, p, shape) = thin_layer_run(tag, nu);
            let (a_x, p_x, shape_x) = exact_layer_run(b, elements, nu);
            println!("nu = {nu} b = {b}: BEM a {a:.4} P {p:.5} shape {shape:.4}; exact a {a_x:.4} P {p_x:.5} shape {shape_x:.4}");
            assert!((p / p_x - 1.0).abs() < 1e-3, "nu = {nu} b = {b}: P {p} against {p_x}");
            assert!((a - a_x).abs() < 2e-3, "nu = {nu} b = {b}: a {a} against {a_x}");
            assert!(
                (shape - shape_x).abs() < 5e-3,
                "nu = {nu} b = {b}: shape {shape} against {shape_x}"
            );
        }
    }
}

/// As b/a → 0 the half-width and the pressure shape approach the thin-layer limits (docs/references.md §5):
/// compressible p = (3P/4a)(1 − x²/a²) with a² = 2Rδ and P = 4G(1−ν)a³/(3(1−2ν)bR);
/// incompressible p = (15P/16a)(1 − x²/a²)² with a² = 6Rδ. The leading correction is O(b/a)
/// (edge zones of width ~b where the local operator fails), so halving b/a from 0.1 to 0.05
/// must nearly halve the shape error (ratio ≥ 1.7; measured 2.6 for ν = 0.3 and 1.8 for
/// ν = 0.5, whose next term is larger: the exact layer model above gives the same), and at
/// b/a = 0.05 the error is a few per cent (limits 2.5 % and 9 %; measured 1.4 % and 7.4 %).
#[test]
fn thin_layer_limits_are_approached_as_the_layer_thins() {
    let tags = [("05", 0.5), ("025", 0.25), ("01", 0.1), ("005", 0.05)];
    for (nu, final_shape, final_a) in [(0.3, 0.025, 0.01), (0.5, 0.09, 0.08)] {
        let runs: Vec<(f64, f64, f64, f64)> = tags
            .iter()
            .map(|&(tag, b)| {
                let (a, p, shape) = thin_layer_run(tag, nu);
                println!(
                    "nu = {nu} b/a = {b}: a = {a:.4}, P = {p:.5}, shape error {:.1} %",
                    100.0 * shape
                );
                (b, a, p, shape)
            })
            .collect();
        for w in runs.windows(2) {
            assert!(w[1].3 < w[0].3, "nu = {nu}: shape error not decreasing: {runs:?}");
            assert!(w[1].1 > w[0].1, "nu = {nu}: half-width not approaching a = 1: {runs:?}");
        }
        let (last, prev) = (runs[3], runs[2]);
        assert!(
            prev.3 / last.3 >= 1.7,
            "nu = {nu}: shape error ratio {}",
            prev.3 / last.3
        );
        assert!(last.3 < final_shape, "nu = {nu}: shape error {} at b/a = 0.05", last.3);
        assert!(
            (last.1 - 1.0).abs() < final_a,
            "nu = {nu}: a = {} at b/a = 0.05",
            last.1
        );
        if nu < 0.5 {
            // Winkler load P = 4G(1−ν)a³/(3(1−2ν)bR) with G = 1, a = 1, R = 100, b = 0.05.
            let winkler = 4.0 * (1.0 - nu) / (3.0 * (1.0 - 2.0 * nu) * 0.05 * 100.0);
            assert!((last.2 / winkler - 1.0).abs() < 0.01, "P = {} vs {winkler}", last.2);
        }
    }
}

/// The normal force the scene's estimates derive from the overlap (to size grids, and what
/// `rollbem check` prints) has the layer's datum at the layer's own extent, not infinitely far
/// (its profile radius is ∞): on the compressible layer of b/a = 0.5 it is a tenth of the solved
/// force (the half-plane formula does not know the layer's core), where an infinite datum gave
/// 5e-9 of it. (On the thin incompressible layer, b/a = 0.1, it is 1e-3 of it: the volume
/// constraint stiffens the layer far beyond any half-plane. The error control takes its units
/// from the solved force for that reason, src/adapt.rs.)
#[test]
fn the_force_estimated_from_the_overlap_of_a_layer_is_of_the_solved_order() {
    let s = solve("tyre_b05_compressible", &[]);
    let ratio = s.scene.estimates.normal_force / s.solution.normal_force;
    assert!((0.05..=2.0).contains(&ratio), "estimated P / solved P = {ratio:.3e}");
}

/// Paper Fig. 12 (b/a = 0.1, ν = 0.5, μ = 0.1): converges for Q/μP = −0.74, 0.05, 0.41 with
/// the contact inside the contact segment and its centre moving against Q (the shift the paper
/// removes before plotting; measured +0.117, −0.000, −0.070 mm for a ≈ 1.0 mm).
#[test]
fn incompressible_tyre_converges_and_its_contact_shifts_against_the_tangential_load() {
    let mut centres = Vec::new();
    for ratio in [-0.74, 0.05, 0.41] {
        let s = solve("tyre_b01_incompressible", &[&format!("load.tangential.ratio={ratio}")]);
        let q = s.solution.tangential_force / (0.1 * s.solution.normal_force);
        assert!((q - ratio).abs() < 1e-9, "Q/muP = {q}");
        let [x0, x1] = s.solution.contact_extent().unwrap();
        assert!(x0 > -1.3 && x1 < 1.3, "contact [{x0}, {x1}] reaches the segment end");
        // b/a = 0.1 as in the paper: half-width within 3 % of 1 mm.
        assert!((0.5 * (x1 - x0) - 1.0).abs() < 0.03, "half-width {}", 0.5 * (x1 - x0));
        centres.push(0.5 * (x0 + x1));
    }
    println!("contact centres for Q/muP = -0.74, 0.05, 0.41: {centres:?}");
    assert!(centres[0] > 0.05 && centres[2] < -0.03, "centres {centres:?}");
    assert!(
        centres[0] > centres[1] && centres[1] > centres[2],
        "centres {centres:?}"
    );
}

/// Paper Fig. 13 (b/a = 0.5, ν = 0.3, μ = 0.1): converges for the same three load ratios, with
/// a ≈ 1 mm; a thick compressible layer barely shifts its contact (< 0.01 mm).
#[test]
fn compressible_thick_tyre_converges_for_the_three_load_ratios() {
    for ratio in [-0.74, 0.05, 0.41] {
        let s = solve("tyre_b05_compressible", &[&format!("load.tangential.ratio={ratio}")]);
        let [x0, x1] = s.solution.contact_extent().unwrap();
        assert!((0.5 * (x1 - x0) - 1.0).abs() < 0.03, "half-width {}", 0.5 * (x1 - x0));
        assert!((0.5 * (x0 + x1)).abs() < 0.01, "centre {}", 0.5 * (x0 + x1));
    }
}

/// Regression: on a thick incompressible layer the all-contact start solves for tension
/// everywhere (the layer's volume constraint), the next iterate has every node open, and the
/// Newton matrix of the overlap-controlled, ratio-controlled problem used to be singular there
/// (the run stopped after one iteration). The solver now keeps the node closest to contact in
/// the active set (newton.rs, `ensure_contact_row`).
#[test]
fn incompressible_thick_layer_converges_from_the_paper_start_vector() {
    for ratio in [0.0, 0.41] {
        let s = solve(
            "tyre_b01_incompressible",
            &[
                "bodies.B.mesh=../meshes/tyre_layer_b05.msh",
                "load.normal.overlap=1.6667e-3",
                &format!("load.tangential.ratio={ratio}"),
            ],
        );
        assert!(s.solution.normal_force > 0.0);
    }
}

/// The rigid model: zero flexibility and a circular profile, given by its
/// radius or fitted to the contact group of a mesh. A rigid R = 100 cylinder on a steel
/// half-space body of profile radius 100 at Q = 0 is Hertz with 1/E* = (1 − ν²)/E and
/// 1/R = 1/100 + 1/100 (docs/references.md §1): a = √(4PR/(πE*)).
/// The mesh-fitted radius reproduces the given one (the contact nodes lie on the circle to the
/// mesh's 1e-9 print precision), so the two runs agree to round-off.
#[test]
fn rigid_cylinder_on_a_half_space_is_hertz_and_takes_its_radius_from_a_mesh() {
    let mut runs = Vec::new();
    for body in [
        "{model: rigid, radius: 100.0}",
        "{model: rigid, mesh: ../meshes/roller_r100_shaft10_A.msh}",
    ] {
        let s = solve(
            "hertz",
            &[
                &format!("bodies.A={body}"),
                "output.interior=null",
                "contact.grid.elements=81",
            ],
        );
        runs.push(s.solution);
    }
    let (e, nu, radius) = (210_000.0, 0.3, 50.0);
    let e_star = e / (1.0 - nu * nu);
    let p_total = runs[0].normal_force;
    let a = (4.0 * p_total * radius / (std::f64::consts::PI * e_star)).sqrt();
    let [x0, x1] = runs[0].contact_extent().unwrap();
    // 81 elements: the half-width is found to a fraction of an element (docs/validation.md, Hertz).
    assert!(
        (0.5 * (x1 - x0) / a - 1.0).abs() < 0.01,
        "a = {} vs Hertz {a}",
        0.5 * (x1 - x0)
    );
    let dp = runs[0]
        .pressure
        .iter()
        .zip(&runs[1].pressure)
        .fold(0.0_f64, |m, (p, q)| m.max((p - q).abs()));
    assert!(dp < 1e-6 * p_total, "mesh-fitted radius changes the pressure by {dp}");
}
