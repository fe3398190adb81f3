//! The Michell/Fourier series solution of a roller in a ring bore (src/analytic/conformal.rs)
//! against independent results: Hertz at small load, the closed form of a pin in an infinite
//! plate (Persson 1964; derived in docs/conformal.md §2), the zero-clearance angle; and its own
//! convergence, admissibility and equilibrium. The tables of docs/conformal.md come from
//! `cargo test --release --test validation conformal_series:: -- --nocapture --test-threads 1`.
//!
//! Scene of the product's cases: steel roller R1 = 40 mm on a rigid shaft r0 = 5 mm in the bore
//! R2 = 50 mm of a ring whose rim R3 = 65 mm is fixed (1/R* = 1/R1 − 1/R2, R* = 200 mm).

use rollbem::analytic::conformal::{
    pin_in_plate_load, pin_in_plate_pressure, pin_in_plate_zero_clearance_angle, ConformalSolution, DiscInBore,
    RigidGap, Ring, Roller, TractionDirection,
};
use rollbem::analytic::{hertz_load, hertz_peak_pressure};
use rollbem::material::Elastic;
use std::f64::consts::PI;

fn steel() -> Elastic {
    Elastic::new(210_000.0, 0.3)
}

fn bronze() -> Elastic {
    Elastic::new(110_000.0, 0.34)
}

/// The product's scene with the ring of `ring` material.
fn bore(ring: Elastic) -> DiscInBore {
    DiscInBore::new(
        Roller {
            radius: 40.0,
            shaft_radius: 5.0,
            material: steel(),
        },
        Ring {
            bore_radius: 50.0,
            rim_radius: 65.0,
            material: ring,
        },
    )
}

/// Pin R = 10 mm on a shaft of 1e−3 mm in a plate with a rim at 1e4 mm: the pin-in-infinite-
/// plate limit up to (r0/R)² = 1e−8 and (R/R3)² = 1e−6.
fn pin(clearance: f64) -> DiscInBore {
    DiscInBore::new(
        Roller {
            radius: 10.0,
            shaft_radius: 1e-3,
            material: steel(),
        },
        Ring {
            bore_radius: 10.0 + clearance,
            rim_radius: 1e4,
            material: steel(),
        },
    )
}

/// The Hertz load of half-width a for the scene.
fn load_for(scene: &DiscInBore, a: f64) -> f64 {
    hertz_load(a, scene.effective_radius(), scene.contact_modulus())
}

/// max |p − p_ref| over the ring angles [0, 1.2 θc_ref] (600 midpoints: not on the edge, where
/// an arc difference Δθ alone gives √Δθ), relative to p_max of the reference.
fn pressure_difference(s: &ConformalSolution, reference: &ConformalSolution) -> f64 {
    (0..600)
        .map(|i| {
            let th = 1.2 * reference.half_angle * (i as f64 + 0.5) / 600.0;
            (s.pressure(th) - reference.pressure(th)).abs()
        })
        .fold(0.0, f64::max)
        / reference.peak_pressure
}

/// max |p(tθc) − p_ref(tθc_ref)| over t ∈ [0, 1]: the shapes at the same fraction of each arc.
fn shape_difference(s: &ConformalSolution, reference: &ConformalSolution) -> f64 {
    (0..=400)
        .map(|i| {
            let t = i as f64 / 400.0;
            (s.pressure(t * s.half_angle) - reference.pressure(t * reference.half_angle)).abs()
        })
        .fold(0.0, f64::max)
        / reference.peak_pressure
}

/// Checks p ≥ 0 on the arc, g = 0 on it (to `gap_tol`) and g > 0 outside it up to `outside`.
fn assert_admissible(s: &ConformalSolution, outside: f64, gap_tol: f64, what: &str) {
    for i in 0..=200 {
        let th = s.half_angle * i as f64 / 200.0;
        assert!(s.pressure(th) >= -1e-9 * s.peak_pressure, "{what}: p({th}) < 0");
        let g = s.gap(0.999 * th);
        assert!(g.abs() < gap_tol, "{what}: gap {g:e} on the arc at {th}");
        let out = s.half_angle + (outside - s.half_angle) * (i as f64 + 0.5) / 200.0;
        assert!(
            s.gap(out) > 0.0,
            "{what}: gap {} ≤ 0 at {out} outside the arc",
            s.gap(out)
        );
    }
}

#[test]
fn small_load_is_hertz_with_an_error_of_order_a_over_r_squared() {
    // Hertz is the leading term of the arc problem in a/R: the curvature of the arc and the
    // finite bodies enter at O((a/R)²) (the problem is even in θ, no O(a/R) term for similar
    // materials). Tolerance 3(a/R1)² for a = R1θ1(θc) and p_max; measured 2.2 and 2.3.
    let scene = bore(steel());
    println!("\n| a/R1 | a_Hertz [mm] | a_series/a_Hertz − 1 | p_max/p0 − 1 | approach δ [mm] | time |");
    println!("|---|---|---|---|---|---|");
    let mut errors = vec![];
    for ratio in [0.005, 0.01, 0.02, 0.05, 0.1, 0.2] {
        let a = ratio * scene.roller.radius;
        let p = load_for(&scene, a);
        let t = std::time::Instant::now();
        let s = scene.solve(p).unwrap();
        let elapsed = t.elapsed();
        let (ea, ep) = (
            s.half_width / a - 1.0,
            s.peak_pressure / hertz_peak_pressure(p, a) - 1.0,
        );
        println!(
            "| {ratio} | {a} | {ea:+.4e} | {ep:+.4e} | {:.6e} | {:.0} ms |",
            s.approach,
            elapsed.as_secs_f64() * 1e3
        );
        if ratio <= 0.05 {
            assert!(
                ea.abs() < 3.0 * ratio * ratio && ep.abs() < 3.0 * ratio * ratio,
                "a/R = {ratio}: {ea} {ep}"
            );
        }
        errors.push((ea, ep));
    }
    // Quadratic: halving a/R divides the errors by 4 (within 5 %).
    for w in errors.windows(2).take(2) {
        let (ra, rp) = (w[1].0 / w[0].0, w[1].1 / w[0].1);
        assert!((ra - 4.0).abs() < 0.2 && (rp - 4.0).abs() < 0.2, "ratios {ra} {rp}");
    }
}

#[test]
fn dissimilar_materials_at_small_load_are_hertz() {
    // Bronze ring on the steel roller (Dundurs β ≠ 0). The traction along the common normal
    // has a component p·w(θ1 − θ) ~ p·s/R* along each body's own surface; with β ≠ 0 it moves
    // the surfaces normally at first order in a/R, so the error has an O(a/R) part (measured
    // +0.023 a/R1) besides the O((a/R)²) one (−2.8 (a/R1)²): tolerance 0.05 a/R1 + 3 (a/R1)².
    let scene = bore(bronze());
    println!("\n| a/R1 (bronze ring) | a_series/a_Hertz − 1 | p_max/p0 − 1 |");
    println!("|---|---|---|");
    for ratio in [0.0025, 0.005, 0.01, 0.02, 0.05] {
        let a = ratio * scene.roller.radius;
        let p = load_for(&scene, a);
        let s = scene.solve(p).unwrap();
        let (ea, ep) = (
            s.half_width / a - 1.0,
            s.peak_pressure / hertz_peak_pressure(p, a) - 1.0,
        );
        println!("| {ratio} | {ea:+.4e} | {ep:+.4e} |");
        let tol = 0.05 * ratio + 3.0 * ratio * ratio;
        assert!(ea.abs() < tol && ep.abs() < tol, "a/R = {ratio}: {ea} {ep}");
    }
}

#[test]
fn pin_in_plate_limit_matches_the_closed_form() {
    // The closed form (docs/conformal.md eq. C13–C14) takes pin and hole at the same radius:
    // exact to O(ΔR/R). The series differs from it by c·ΔR/R with c ≤ 1.6 (angle) and c ≤ 10
    // (pressure shape, in p_max) over 5°–84°, plus the shaft and rim terms (≲ 1e−7).
    let e_star = pin(0.0).contact_modulus();
    println!("\n| α [°] | P/(E*ΔR) | θc/α − 1 (ΔR/R = 1e−6) | max Δp/p_max | θc/α − 1 (ΔR/R = 1e−4) |");
    println!("|---|---|---|---|---|");
    for deg in [5.0, 20.0, 45.0, 70.0, 80.0, 84.0] {
        let alpha = f64::to_radians(deg);
        let mut row = vec![];
        for rel in [1e-6, 1e-4] {
            let dr = 10.0 * rel;
            let p = pin_in_plate_load(alpha, dr, e_star);
            let s = pin(dr).solve(p).unwrap();
            let dtheta = s.half_angle / alpha - 1.0;
            // Shapes compared at the same fraction of each one's arc (the arcs differ above).
            let dp = (0..=400)
                .map(|i| {
                    let t = i as f64 / 400.0;
                    (s.pressure(t * s.half_angle) - pin_in_plate_pressure(t * alpha, alpha, p, 10.0)).abs()
                })
                .fold(0.0, f64::max)
                / s.peak_pressure;
            assert!(dtheta.abs() < 3.0 * rel + 2e-7, "α = {deg}°, ΔR/R = {rel}: {dtheta:e}");
            assert!(dp < 10.0 * rel + 1e-6, "α = {deg}°, ΔR/R = {rel}: Δp {dp:e}");
            row.push((p / (e_star * dr), dtheta, dp));
        }
        // The difference is the closed form's O(ΔR/R): ×100 from ΔR/R = 1e−6 to 1e−4.
        let scale = row[1].1 / row[0].1;
        assert!((50.0..200.0).contains(&scale), "α = {deg}°: scaling {scale}");
        println!(
            "| {deg} | {:.6} | {:+.3e} | {:.2e} | {:+.3e} |",
            row[0].0, row[0].1, row[0].2, row[1].1
        );
    }
}

#[test]
fn zero_clearance_arc_does_not_depend_on_the_load() {
    // Linear theory with zero clearance has no length scale: the arc is the same for every
    // load (Persson 1964). For the pin in the plate it is the root of eq. C15, 84.83°.
    let alpha0 = pin_in_plate_zero_clearance_angle();
    let pin0 = pin(0.0);
    let (s1, s2) = (pin0.solve(1.0).unwrap(), pin0.solve(1e4).unwrap());
    assert!(
        (s1.half_angle - s2.half_angle).abs() < 1e-12,
        "{} {}",
        s1.half_angle,
        s2.half_angle
    );
    assert!((s2.approach / s1.approach / 1e4 - 1.0).abs() < 1e-10);
    let rel = s1.half_angle / alpha0 - 1.0;
    assert!(
        rel.abs() < 1e-6,
        "θc = {}°, closed form {}°",
        s1.half_angle.to_degrees(),
        alpha0.to_degrees()
    );
    // The product's ring with zero clearance: roller R1 = R2 = 50 mm on the shaft of 5 mm.
    let mut tight = bore(steel());
    tight.roller.radius = 50.0;
    let (t1, t2) = (tight.solve(100.0).unwrap(), tight.solve(10_000.0).unwrap());
    assert!((t1.half_angle - t2.half_angle).abs() < 1e-12);
    assert_admissible(&t2, 2.5, 1e-9 * t2.approach, "zero clearance");
    println!(
        "\nzero clearance: pin in plate θc = {:.6}° (closed form {:.6}°, {rel:+.1e}); roller R1 = R2 = 50 on shaft 5 in the ring with rim 65: θc = {:.4}° for every load, δ/P = {:.6e} mm per N/mm",
        s1.half_angle.to_degrees(),
        alpha0.to_degrees(),
        t1.half_angle.to_degrees(),
        t1.approach / 100.0
    );
}

#[test]
fn pressure_terms_converge_spectrally() {
    // Chebyshev terms against the closed-form kernels: spectral for similar materials; for the
    // bronze ring algebraic (the tangential components of the traction couple through β).
    println!("\n| K | steel: Δa/a | steel: max Δp/p_max | bronze: Δa/a | bronze: max Δp/p_max |");
    println!("|---|---|---|---|---|");
    let mut rows = vec![];
    for ring in [steel(), bronze()] {
        let mut scene = bore(ring);
        let p = load_for(&scene, 8.0);
        scene.resolution.pressure_terms = 32;
        let reference = scene.solve(p).unwrap();
        let mut errs = vec![];
        for k in [4, 6, 8, 12, 16] {
            scene.resolution.pressure_terms = k;
            let s = scene.solve(p).unwrap();
            errs.push((
                (s.half_width / reference.half_width - 1.0).abs(),
                pressure_difference(&s, &reference),
            ));
        }
        rows.push(errs);
    }
    for (i, k) in [4, 6, 8, 12, 16].iter().enumerate() {
        println!(
            "| {k} | {:.1e} | {:.1e} | {:.1e} | {:.1e} |",
            rows[0][i].0, rows[0][i].1, rows[1][i].0, rows[1][i].1
        );
    }
    assert!(
        rows[0][2].0 < 1e-10 && rows[0][2].1 < 1e-9,
        "steel K = 8: {:?}",
        rows[0][2]
    );
    assert!(
        rows[1][3].0 < 1e-6 && rows[1][3].1 < 1e-6,
        "bronze K = 12: {:?}",
        rows[1][3]
    );
    for r in &rows {
        assert!(r[1].1 < r[0].1 && r[3].1 < r[1].1, "not converging: {r:?}");
    }
}

#[test]
fn truncated_fourier_series_converges_to_the_closed_form_kernels() {
    // The plain series to mode M is the independent path (its traction amplitudes come from
    // quadrature, its displacements from Σ C_n amplitudes, no closed forms). It resolves the
    // roller's arc (θ1c = 0.19 rad) with Mθ1c modes across it: the difference in a falls 6.6×
    // and 57× per doubling of M (measured 7e−3, 1e−3, 2e−5 at M = 1024, 2048, 4096), the
    // pressure's likewise (its largest difference sits next to the edges).
    let scene = bore(steel());
    let p = load_for(&scene, 8.0);
    let reference = scene.solve(p).unwrap();
    println!("\n| M | Δa/a | max Δp/p_max |");
    println!("|---|---|---|");
    let mut errs = vec![];
    for m in [1024, 2048, 4096] {
        let mut s = scene;
        s.resolution.truncation = Some(m);
        let sol = s.solve(p).unwrap();
        let e = (
            (sol.half_width / reference.half_width - 1.0).abs(),
            pressure_difference(&sol, &reference),
        );
        println!("| {m} | {:.2e} | {:.2e} |", e.0, e.1);
        errs.push(e);
    }
    assert!(errs[1].0 < errs[0].0 / 4.0 && errs[2].0 < errs[1].0 / 4.0, "{errs:?}");
    assert!(errs[1].1 < errs[0].1 / 4.0 && errs[2].1 < errs[1].1 / 4.0, "{errs:?}");
    assert!(errs[2].0 < 1e-4 && errs[2].1 < 1e-3, "{errs:?}");
}

#[test]
fn solution_is_admissible_and_in_equilibrium() {
    // Signorini on the arc and outside it, and the load: ∫ p cos ψ R2 dθ = P over the bore and
    // ∫ p_roller cos ψ d(R1θ1) = P over the roller, by trapezoids in θ = θc sin φ (smooth
    // integrands) on 4000 samples: to 1e−7 (the trapezoid's error here is ~1e−9).
    let mut cases = vec![];
    for ring in [steel(), bronze()] {
        let s = bore(ring);
        cases.push((s, load_for(&s, 8.0), "a/R = 0.2"));
    }
    let p60 = pin_in_plate_load(f64::to_radians(60.0), 1e-5, pin(0.0).contact_modulus());
    cases.push((pin(1e-5), p60, "pin 60°"));
    for (scene, p, what) in cases {
        let s = scene.solve(p).unwrap();
        let rigid_scale = scene.roller.radius * (1.0 - s.half_angle.cos()) * 1e-3 + s.approach;
        assert_admissible(&s, (2.5 * s.half_angle).min(3.0), 1e-9 * rigid_scale, what);
        let n = 4000;
        let (mut ring_force, mut roller_force) = (0.0, 0.0);
        let mut prev: Option<(f64, f64, f64)> = None;
        for i in 0..=n {
            let phi = -0.5 * PI + PI * i as f64 / n as f64;
            let smp = s.sample(s.half_angle * phi.sin());
            let dth = s.half_angle * phi.cos() * PI / n as f64;
            let w = if i == 0 || i == n { 0.5 } else { 1.0 };
            ring_force += w * smp.pressure * smp.direction.cos() * scene.ring.bore_radius * dth;
            if let Some((arc0, q0, c0)) = prev {
                roller_force += 0.5 * (q0 * c0 + smp.roller_pressure * smp.direction.cos()) * (smp.roller_arc - arc0);
            }
            prev = Some((smp.roller_arc, smp.roller_pressure, smp.direction.cos()));
        }
        assert!((ring_force / p - 1.0).abs() < 1e-7, "{what}: ring {ring_force} vs {p}");
        // The roller side uses the paired arc lengths (a trapezoid in R1θ1): O(h²) = 1e−6.
        assert!(
            (roller_force / p - 1.0).abs() < 1e-5,
            "{what}: roller {roller_force} vs {p}"
        );
    }
}

#[test]
fn traction_direction_and_rigid_gap_choices_at_a_over_r_0_2() {
    // Not a verification: what the modelling choices change in the conformal scene (docs
    // table). The common-normal, linear-gap solution is the reference; the others must still
    // be admissible, and the exact gap may move the arc only at O(δ/R1).
    println!("\n| ring | variant | ring arc R2θc [mm] | roller arc R1θ1c [mm] | p_max [MPa] | max Δp/p_max at the same θ | same fraction of the arc |");
    println!("|---|---|---|---|---|---|---|");
    for (name, ring) in [("steel", steel()), ("bronze", bronze())] {
        let base = bore(ring);
        let p = load_for(&base, 8.0);
        let reference = base.solve(p).unwrap();
        let mut load_line = base;
        load_line.direction = TractionDirection::LoadLine;
        let mut exact = base;
        exact.rigid_gap = RigidGap::Exact;
        for (label, sc) in [
            ("common normal, linear gap", base),
            ("load line", load_line),
            ("exact gap", exact),
        ] {
            let s = sc.solve(p).unwrap();
            assert_admissible(&s, 2.5 * s.half_angle, 1e-9, label);
            println!(
                "| {name} | {label} | {:.5} | {:.5} | {:.2} | {:.2e} | {:.2e} |",
                50.0 * s.half_angle,
                s.half_width,
                s.peak_pressure,
                pressure_difference(&s, &reference),
                shape_difference(&s, &reference)
            );
            if label == "exact gap" {
                let moved = (s.half_angle / reference.half_angle - 1.0).abs();
                assert!(
                    moved < 2.0 * reference.approach / 40.0,
                    "exact gap moved the arc by {moved}"
                );
            }
        }
    }
}

#[test]
fn prescribed_approach_gives_back_the_load() {
    // solve_approach inverts solve: δ(P) → P to the root search's tolerance.
    for scene in [bore(steel()), pin(0.0)] {
        let p = if scene.effective_radius().is_finite() {
            load_for(&scene, 4.0)
        } else {
            1000.0
        };
        let s = scene.solve(p).unwrap();
        let back = scene.solve_approach(s.approach).unwrap();
        assert!((back.load / p - 1.0).abs() < 1e-9, "{} vs {p}", back.load);
        assert!((back.half_angle / s.half_angle - 1.0).abs() < 1e-9);
    }
}
