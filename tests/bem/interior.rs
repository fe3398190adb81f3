//! Interior displacement and stress by Somigliana's identity: patch test,
//! Lamé thick cylinder, Hertz/McEwen stresses from a BEM block against the half-space model.
//!
//! Tolerances are justified where they are asserted; the measured numbers are printed
//! (`cargo test --release --test bem interior:: -- --nocapture`) and recorded in
//! docs/validation.md, "Interior stresses".

use crate::common::patch::{exact_u, strain, SIGMA};
use rollbem::bem::somigliana::interior_fields;
use rollbem::bem::{BemModel, BemOptions, BoundaryCondition};
use rollbem::interior::{InteriorOptions, InteriorSample, InteriorValue};
use rollbem::material::Elastic;
use std::sync::Arc;

// ---------------------------------------------------------------------------------------------
// Uniform stress (docs/references.md §8.3)

/// The 4 × 2 rectangle of tests/bem/patch.rs: displacements on bottom and left, tractions σ⁰·n
/// on right and top; element lengths 4/3 (bottom), 1 (others).
fn patch_model(nu: f64) -> BemModel {
    crate::common::patch::model(
        crate::common::patch::rectangle_mesh(true),
        Elastic::new(210_000.0, nu),
        None,
    )
}

fn inside(s: &InteriorSample) -> InteriorValue {
    match s {
        InteriorSample::Inside(v) => *v,
        other => panic!("expected an evaluated point, got {other:?}"),
    }
}

/// Uniform stress is reproduced exactly at interior points (both u and σ), down to a tenth of an
/// element from the boundary, for ν = 0.3 and the incompressible ν = 0.5 (where D and S must
/// stay finite). The exact boundary data lie in the quadratic space, so the only errors are the
/// BEM solve's (≤ 1e-12, tests/bem/patch.rs) and the interior quadrature's (tolerance 1e-12):
/// bound 1e-9 of the largest exact value, as for the boundary patch test.
#[test]
fn uniform_stress_is_exact_at_interior_points() {
    for nu in [0.3, 0.5] {
        let m = patch_model(nu);
        let sol = m.solve().unwrap();
        let eps = strain(&m.material);
        // A 9 × 7 grid strictly inside, plus points at 0.1 element length (0.1) from each side
        // and from a corner.
        let mut points: Vec<[f64; 2]> = (0..9)
            .flat_map(|i| (0..7).map(move |j| [-0.8 + 3.6 * i as f64 / 8.0, -0.3 + 1.6 * j as f64 / 6.0]))
            .collect();
        points.extend([
            [1.0, -0.4],
            [2.9, 0.5],
            [0.3, 1.4],
            [-0.9, 0.0],
            [-0.9, -0.4],
            [2.9, 1.4],
        ]);
        let samples = interior_fields(&m, &sol, &points, &InteriorOptions::default());
        let sigma_zz = nu * (SIGMA[0][0] + SIGMA[1][1]);
        let (mut es, mut eu) = (0.0f64, 0.0f64);
        let u_scale = points
            .iter()
            .map(|&x| exact_u(eps, x))
            .fold(0.0f64, |a, u| a.max(u[0].abs()).max(u[1].abs()));
        for (x, s) in points.iter().zip(&samples) {
            let v = inside(s);
            let exact = [SIGMA[0][0], SIGMA[1][1], sigma_zz, SIGMA[0][1]];
            es = v
                .stress
                .iter()
                .zip(exact)
                .fold(es, |m, (a, b)| m.max((a - b).abs() / 50.0));
            let ue = exact_u(eps, *x);
            eu = v
                .displacement
                .iter()
                .zip(ue)
                .fold(eu, |m, (a, b)| m.max((a - b).abs() / u_scale));
        }
        println!("interior patch nu={nu}: max rel error sigma {es:.2e}, u {eu:.2e}");
        assert!(es < 1e-9 && eu < 1e-9, "nu={nu}: sigma {es:e}, u {eu:e}");
    }
}

/// Points outside the body, on its boundary and inside within the boundary layer (0.05 element
/// lengths) are reported as such and never evaluated; outside points stay `outside` however
/// close they are, unless exactly on the boundary.
#[test]
fn points_outside_or_on_the_boundary_are_flagged() {
    let m = patch_model(0.3);
    let sol = m.solve().unwrap();
    let options = InteriorOptions::default();
    // Element length 1 on the right side: layer 0.05.
    let cases = [
        ([-1.5, 0.0], "outside"),
        ([3.2, 0.5], "outside"),
        ([1.0, -0.5], "boundary"),
        ([3.0, 0.5], "boundary"),
        ([2.96, 0.5], "boundary"),
        ([2.94, 0.5], "inside"),
        ([-1.0, -0.5], "boundary"),
        ([1.0, 1.5], "boundary"),
        ([1.0, 1.6], "outside"),
        // Outside but within the layer's distance: still outside.
        ([1.0, 1.52], "outside"),
        ([3.02, 0.5], "outside"),
        ([1.0, 0.5], "inside"),
    ];
    let points: Vec<[f64; 2]> = cases.iter().map(|c| c.0).collect();
    let samples = interior_fields(&m, &sol, &points, &options);
    for ((x, want), s) in cases.iter().zip(&samples) {
        let got = match s {
            InteriorSample::Inside(v) => {
                assert!(v.stress.iter().chain(&v.displacement).all(|a| a.is_finite()));
                "inside"
            }
            InteriorSample::Outside => "outside",
            InteriorSample::Boundary => "boundary",
        };
        assert_eq!(got, *want, "point {x:?}");
    }
}

// ---------------------------------------------------------------------------------------------
// Lamé thick cylinder (docs/references.md §8.1)

use crate::common::lame::{self, A_IN, B_OUT};

/// The pressure-loaded Lamé cylinder with `n` elements per circle, its rigid motion removed by
/// the exact displacement at three components (as tests/bem/lame.rs), solved.
fn lame_solution(nu: f64, n: usize) -> (BemModel, rollbem::bem::BemSolution) {
    let model = lame::pressure_loaded_lame(nu, n);
    let sol = model.solve_pinned(&lame::lame_pins(&model)).unwrap();
    (model, sol)
}

/// Max relative stress and displacement errors at points `fraction` element lengths inside the
/// bore and inside the outer surface, at 7 angles (on element end nodes, mid nodes, quarter
/// points and a generic angle); a distance beyond half the wall thickness (the outer circle's
/// h at 16 elements) is left out on that side. Stress errors relative to the largest exact stress (p_i = 100),
/// displacement errors to the largest exact |u|.
fn lame_errors_at(model: &BemModel, sol: &rollbem::bem::BemSolution, n: usize, fraction: f64) -> (f64, f64) {
    let pi = std::f64::consts::PI;
    let step = 2.0 * pi / n as f64;
    let angles = [0.0, 0.5 * step, 0.25 * step, 0.75 * step, 0.37, 2.0, 4.0 + 0.5 * step];
    let (h_in, h_out) = (A_IN * step, B_OUT * step);
    let mut points = Vec::new();
    for &t in &angles {
        // Only points in the half of the wall next to their boundary.
        for (r, ok) in [
            (A_IN + fraction * h_in, fraction * h_in <= 0.5 * (B_OUT - A_IN)),
            (B_OUT - fraction * h_out, fraction * h_out <= 0.5 * (B_OUT - A_IN)),
        ] {
            if ok {
                points.push([r * t.cos(), r * t.sin()]);
            }
        }
    }
    let samples = interior_fields(
        model,
        sol,
        &points,
        &InteriorOptions {
            boundary_layer: 0.01,
            ..Default::default()
        },
    );
    let (mut es, mut eu) = (0.0f64, 0.0f64);
    let u_scale = lame::u_scale(&model.material);
    for (x, s) in points.iter().zip(&samples) {
        let v = inside(s);
        let exact = lame::stress(&model.material, *x);
        es = v
            .stress
            .iter()
            .zip(exact)
            .fold(es, |m, (a, b)| m.max((a - b).abs() / lame::P_IN));
        let ue = lame::displacement(&model.material, *x);
        eu = eu.max((v.displacement[0] - ue[0]).hypot(v.displacement[1] - ue[1]) / u_scale);
    }
    (es, eu)
}

/// Lamé interior stresses and displacements against the exact solution, by mesh (elements per
/// circle) and distance from the boundary (in element lengths h of the nearer circle).
///
/// * at d = h, 32 elements per circle are the mesh "fine enough" for the 1e-4 target
///   (measured 8.4e-6; 16 elements give 1.0e-4, just above it);
/// * down to d = h/10 the stresses stay accurate: below 1e-4 from 32 elements on (measured
///   2.7e-5 there), and they converge: the fitted rate over 16–128 elements must lie in the band
///   2.5–4.5 of tests/bem/lame.rs (quadratic elements: h³, nodal superconvergence up to h⁴;
///   measured 3.8 at d = h and 3.1 at d = h/10), so a lost order or an under-integrated
///   near-singular element would fail;
/// * interior displacements converge like the boundary ones (rate in the same band).
#[test]
fn lame_interior_stresses_converge_and_stay_accurate_near_the_boundary() {
    let ns = [16, 32, 64, 128];
    let distances = [1.0, 0.5, 0.2, 0.1, 0.05];
    // errors[d][n] = (stress, displacement)
    let mut errors = vec![Vec::new(); distances.len()];
    for &n in &ns {
        let (model, sol) = lame_solution(0.3, n);
        for (k, &f) in distances.iter().enumerate() {
            errors[k].push(lame_errors_at(&model, &sol, n, f));
        }
    }
    println!(
        "| d / h | {} |",
        ns.map(|n| format!("n = {n}: σ error, u error")).join(" | ")
    );
    for (k, f) in distances.iter().enumerate() {
        let row: Vec<String> = errors[k].iter().map(|(s, u)| format!("{s:.2e}, {u:.2e}")).collect();
        println!("| {f} | {} |", row.join(" | "));
    }
    let at = |f: f64| &errors[distances.iter().position(|&d| d == f).unwrap()];
    let stress = |f: f64| at(f).iter().map(|e| e.0).collect::<Vec<_>>();
    let disp = |f: f64| at(f).iter().map(|e| e.1).collect::<Vec<_>>();
    assert!(stress(1.0)[1] < 1e-4, "d = h, 32 elements: {:?}", stress(1.0));
    assert!(
        stress(0.1)[1..].iter().all(|&e| e < 1e-4),
        "d = h/10: {:?}",
        stress(0.1)
    );
    for (label, e) in [
        ("stress at d = h", stress(1.0)),
        ("stress at d = h/10", stress(0.1)),
        ("displacement at d = h", disp(1.0)),
    ] {
        let rate = crate::common::fitted_rate(&ns, &e);
        println!("Lamé interior {label}: fitted rate {rate:.2}");
        assert!((2.5..=4.5).contains(&rate), "{label}: rate {rate}, errors {e:?}");
    }
}

// ---------------------------------------------------------------------------------------------
// Hertz pressure with a sliding traction q = μp (docs/references.md §7): BEM blocks and half-space

use rollbem::body::bem::BemBody;
use rollbem::body::half_space::HalfSpace;
use rollbem::body::{Body, BodyFields, ContactLoad, InteriorQuery, Side};
use rollbem::grid::ContactGrid;

/// McEwen's maxima (docs/references.md §7, ν = 0.3): (μ, max τ1/p0, x/a, z/a, max σ_VM/p0, x/a, z/a).
const MCEWEN: [(f64, f64, f64, f64, f64, f64, f64); 2] = [
    (0.0, 0.300283, 0.0, 0.786151, 0.557516, 0.0, 0.704292),
    (0.2, 0.318989, 0.625169, 0.601318, 0.589993, 0.553341, 0.565980),
];

/// Body `side` of cases/carter_051_block.yaml (an 80 × 40 mm steel block, far face fixed, 21
/// contact elements of 0.118 mm whose edges include ±a = ±1 mm) as the application builds it,
/// and its contact grid.
fn shipped_block(side: Side) -> (Box<dyn Body>, ContactGrid) {
    let case = rollbem::case::load(&crate::common::case_path("carter_051_block"), &[]).unwrap();
    let scene = rollbem::scene::Scene::from_case(&case).unwrap();
    let [a, b] = scene.body_models().unwrap();
    (if side == Side::A { a } else { b }, scene.grid)
}

/// A block of half-width `w` and depth `h` [mm] standing in for a half-plane on `side`, its
/// contact face on y = 0 with the 21 elements of the contact grid on |x| ≤ 21/17, the face
/// elements growing by 1.25 from the contact's 0.118 mm, about 10 elements per side.
fn block_mesh(w: f64, h: f64, side: Side) -> rollbem::mesh::BoundaryMesh {
    let n_side = ((h / (0.1 * w)).ceil() as usize).max(4);
    rollbem::mesh::build::half_plane_block(w, h, 21.0 / 17.0, 21, 1.25, n_side, side == Side::A)
}

/// A steel block body on the contact grid with the given conditions on `free` and `far`.
fn block_body(
    w: f64,
    h: f64,
    side: Side,
    grid: &ContactGrid,
    free: BoundaryCondition,
    far: BoundaryCondition,
) -> BemBody {
    let model = BemModel::new(
        block_mesh(w, h, side),
        Elastic::new(210_000.0, 0.3),
        vec![
            ("contact".into(), BoundaryCondition::Contact),
            ("free".into(), free),
            ("far".into(), far),
        ],
        BemOptions::default(),
    )
    .unwrap();
    BemBody::new(model, "contact", grid, side).unwrap()
}

/// Nodal Hertz pressure p0·√(1 − x²/a²) (p0 = 1 MPa, a = 1 mm) and the shear q = μp.
fn hertz_tractions(grid: &ContactGrid, mu: f64) -> (Vec<f64>, Vec<f64>) {
    let p: Vec<f64> = grid.nodes.iter().map(|x| (1.0 - x * x).max(0.0).sqrt()).collect();
    let q = p.iter().map(|v| mu * v).collect();
    (p, q)
}

/// A maximum of an interior criterion: value [p0] and where, (x, z) with z the depth [a].
#[derive(Debug, Clone, Copy)]
struct Peak {
    value: f64,
    x: f64,
    z: f64,
}

/// Maximum of `criterion` over body `side` (depth z = ±y into it): a 0.05a grid over
/// |x| ≤ 1.5a, 0.025a ≤ z ≤ 2a, then two refinements (steps 0.005a and 0.0005a) around the
/// best point; the position is thus resolved to 0.0005a and the value to round-off.
fn maximum(
    model: &dyn BodyFields,
    grid: &ContactGrid,
    side: Side,
    (p, q): (&[f64], &[f64]),
    criterion: fn(&[f64; 4]) -> f64,
) -> Peak {
    let best = |points: Vec<[f64; 2]>| -> Peak {
        let query = InteriorQuery {
            side,
            load: ContactLoad {
                grid,
                pressure: p,
                shear: q,
            },
            points: &points,
            options: InteriorOptions::default(),
        };
        let samples = model.interior(&query).unwrap();
        points
            .iter()
            .zip(&samples)
            .filter_map(|(x, s)| match s {
                InteriorSample::Inside(v) => Some(Peak {
                    value: criterion(&v.stress),
                    x: x[0],
                    z: side.sign() * x[1],
                }),
                _ => None,
            })
            .max_by(|a, b| a.value.total_cmp(&b.value))
            .unwrap()
    };
    let around = |x0: f64, z0: f64, step: f64, n: i32| -> Vec<[f64; 2]> {
        (-n..=n)
            .flat_map(|i| (-n..=n).map(move |j| (x0 + step * i as f64, z0 + step * j as f64)))
            .filter(|&(_, z)| z > 0.0 && z <= 2.0)
            .map(|(x, z)| [x, side.sign() * z])
            .collect()
    };
    let mut b = best(around(0.0, 1.025, 0.05, 30));
    for step in [0.005, 0.0005] {
        b = best(around(b.x, b.z, step, 12));
    }
    b
}

fn max_shear(s: &[f64; 4]) -> f64 {
    rollbem::interior::invariants(s).1
}

fn von_mises(s: &[f64; 4]) -> f64 {
    rollbem::interior::invariants(s).0
}

/// Both maxima (τ1, von Mises) of a model under the Hertz pressure and q = μp.
fn peaks(model: &dyn BodyFields, grid: &ContactGrid, side: Side, mu: f64) -> [Peak; 2] {
    let (p, q) = hertz_tractions(grid, mu);
    [max_shear, von_mises].map(|c| maximum(model, grid, side, (&p, &q), c))
}

/// Checks peaks against McEwen: values within `value_tol` relative, positions within
/// `position_tol` [a]. On B the traction acts on the body in −x (pair convention: B receives
/// −q) where the sheet's acts in +x, so B's maxima are the mirror images (x → −x).
fn assert_mcewen(label: &str, side: Side, mu: f64, found: [Peak; 2], value_tol: f64, position_tol: f64) {
    let m = MCEWEN.iter().find(|m| m.0 == mu).unwrap();
    let expected = [(m.1, m.2, m.3), (m.4, m.5, m.6)];
    for (name, peak, (v, x, z)) in [("tau1", found[0], expected[0]), ("von Mises", found[1], expected[1])] {
        let xs = side.sign() * x;
        println!(
            "{label} {side:?} mu={mu}: max {name} {:.6} p0 at ({:+.4}, {:.4})a; McEwen {v:.6} at ({xs:+.4}, {z:.4})a",
            peak.value, peak.x, peak.z
        );
        assert!(
            (peak.value / v - 1.0).abs() < value_tol,
            "{label} {side:?} mu={mu} {name}: {peak:?} vs {v}"
        );
        assert!(
            (peak.x - xs).abs() < position_tol && (peak.z - z).abs() < position_tol,
            "{label} {side:?} mu={mu} {name}: {peak:?} vs ({xs}, {z})"
        );
    }
}

/// The half-space model and a BEM block whose far faces carry the exact half-plane data give
/// McEwen's maxima, in both bodies, with and without friction.
///
/// The only approximation left is the contact grid's interpolation of the Hertz pressure (17
/// quadratic elements over the contact; √ near the edges): 0.2 % on the values and 0.01a on the
/// positions (measured: 8e-5 and 2e-4 relative, 0.002a; the maxima are flat, so their
/// positions move more than their values). The block (80 × 40 mm, its sides loaded by the
/// Flamant tractions and its far face displaced as the half-plane, Eq. H1–H2 of
/// `rollbem::interior`) must then agree with the half-space model itself to 1e-4 p0 and 0.002a:
/// that is the BEM's own error (measured 3e-6 p0).
#[test]
fn hertz_maxima_from_the_half_space_and_from_a_block_with_half_plane_data() {
    let (_, grid) = shipped_block(Side::A);
    let half_space = HalfSpace::new(Elastic::new(210_000.0, 0.3), 100.0);
    for mu in [0.0, 0.2] {
        for side in [Side::A, Side::B] {
            let hs = peaks(&half_space, &grid, side, mu);
            assert_mcewen("half-space", side, mu, hs, 2e-3, 0.01);
        }
        // Exact half-plane data on the block's free faces and far face (side A).
        let side = Side::A;
        let (p, q) = hertz_tractions(&grid, mu);
        let (g, nu) = (half_space.material.shear(), 0.3);
        let datum = half_space.datum_length();
        let (pp, qq, gr) = (p.clone(), q.clone(), grid.clone());
        let flamant_traction = BoundaryCondition::TractionField(Arc::new(move |x: [f64; 2], n: [f64; 2]| {
            if x[1] == 0.0 {
                return [0.0, 0.0]; // the unloaded surface
            }
            let s = rollbem::body::flamant::halfplane_stress(&gr, &pp, &qq, nu, x[0], x[1]);
            [s.sxx * n[0] + s.txz * n[1], s.txz * n[0] + s.szz * n[1]]
        }));
        let (pp, qq, gr) = (p.clone(), q.clone(), grid.clone());
        let flamant_displacement = BoundaryCondition::DisplacementField(Arc::new(move |x: [f64; 2], _| {
            rollbem::body::flamant::halfplane_displacement(&gr, &pp, &qq, g, nu, datum, x[0], x[1])
        }));
        let block = block_body(40.0, 40.0, side, &grid, flamant_traction, flamant_displacement);
        let bem = peaks(&block, &grid, side, mu);
        assert_mcewen("block with half-plane data", side, mu, bem, 2e-3, 0.01);
        let hs = peaks(&half_space, &grid, side, mu);
        for (b, h) in bem.iter().zip(&hs) {
            assert!(
                (b.value - h.value).abs() < 1e-4 && (b.x - h.x).abs() < 2e-3 && (b.z - h.z).abs() < 2e-3,
                "mu={mu}: block {b:?} vs half-space {h:?}"
            );
        }
    }
}

/// The shipped block case (cases/carter_051_block.yaml: 80 × 40 mm, far face fixed, sides free)
/// is a *finite* body: its maximum shear under the Hertz pressure is 0.30896 p0, 2.9 % above
/// the half-plane's 0.30028, which misses the asked-for 2 % — by physics, not numerics. The
/// block carries the load P = πa p0/2 to its fixed face 40a away, and the correction to the
/// half-plane field near the contact is a smooth stress of order P/(πH) ≈ 0.012 p0
/// (H the depth), which raises τ1 = |σx − σz|/2 on the axis. This test shows it:
/// * the application's block (Gmsh mesh) and the procedural 40 × 40 block agree to 1e-5 p0
///   (the BEM is converged on the mesh);
/// * the excess over the half-space shrinks like 1/H: blocks 4× and 10× larger reduce it by
///   factors in [3, 5] and [7, 13] (measured 3.9 and 9.6), and the 400 × 400 mm block meets
///   McEwen's maxima within 2 % (value) and 0.02a (position) for μ = 0 and 0.2;
/// * both shipped bodies (A above, B below) give the same maxima, mirrored in x on B.
#[test]
fn hertz_maxima_of_the_shipped_block_differ_from_the_half_plane_by_its_finite_size() {
    let half_space = HalfSpace::new(Elastic::new(210_000.0, 0.3), 100.0);
    for mu in [0.0, 0.2] {
        let (shipped_a, grid) = shipped_block(Side::A);
        let (shipped_b, _) = shipped_block(Side::B);
        let a = peaks(shipped_a.fields(), &grid, Side::A, mu);
        let b = peaks(shipped_b.fields(), &grid, Side::B, mu);
        let hs = peaks(&half_space, &grid, Side::A, mu);
        for (k, name) in ["tau1", "von Mises"].iter().enumerate() {
            println!(
                "shipped block mu={mu}: max {name} A {:.6} at ({:+.4}, {:.4}), B {:.6} at ({:+.4}, {:.4}); half-space {:.6}",
                a[k].value, a[k].x, a[k].z, b[k].value, b[k].x, b[k].z, hs[k].value
            );
            assert!(
                (a[k].value - b[k].value).abs() < 1e-9
                    && (a[k].x + b[k].x).abs() < 1e-9
                    && (a[k].z - b[k].z).abs() < 1e-9,
                "mu={mu} {name}: A {:?} vs B {:?}",
                a[k],
                b[k]
            );
        }
        let mut excess = Vec::new();
        for size in [40.0, 160.0, 400.0] {
            let block = block_body(
                size,
                size,
                Side::A,
                &grid,
                BoundaryCondition::Free,
                BoundaryCondition::Fixed,
            );
            let found = peaks(&block, &grid, Side::A, mu);
            println!(
                "fixed block {size} x {size} mm, mu={mu}: max tau1 {:.6} at ({:+.4}, {:.4}), max VM {:.6} at ({:+.4}, {:.4})",
                found[0].value, found[0].x, found[0].z, found[1].value, found[1].x, found[1].z
            );
            if size == 40.0 {
                assert!((found[0].value - a[0].value).abs() < 1e-5, "{found:?} vs {a:?}");
            }
            if size == 400.0 {
                assert_mcewen("fixed block 400 x 400", Side::A, mu, found, 0.02, 0.02);
            }
            excess.push(found[0].value - hs[0].value);
        }
        let (r4, r10) = (excess[0] / excess[1], excess[0] / excess[2]);
        println!("mu={mu}: tau1 excess over the half-space {excess:?}, ratios {r4:.2} (4x) and {r10:.2} (10x)");
        assert!((3.0..=5.0).contains(&r4) && (7.0..=13.0).contains(&r10), "{excess:?}");
    }
}
