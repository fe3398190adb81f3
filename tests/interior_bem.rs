//! Interior displacement and stress by Somigliana's identity (issue 4, part 4): patch test,
//! Lamé thick cylinder, Hertz/McEwen stresses from a BEM block against the half-space model.
//!
//! Tolerances are justified where they are asserted; the measured numbers are printed
//! (`cargo test --release --test interior_bem -- --nocapture`) and recorded in
//! docs/validation.md, "Interior stresses (issue 4)".

use rollbem::bem::somigliana::interior_fields;
use rollbem::bem::{BemModel, BemOptions, BoundaryCondition};
use rollbem::interior::{InteriorOptions, InteriorSample, InteriorValue};
use rollbem::material::Elastic;
use rollbem::mesh::build::rectangle;
use std::sync::Arc;

// ---------------------------------------------------------------------------------------------
// Uniform stress (reference sheet §8.3)

const SIGMA: [[f64; 2]; 2] = [[50.0, 20.0], [20.0, -30.0]];

fn strain(m: &Elastic) -> [[f64; 2]; 2] {
    let (e, nu) = (m.young, m.poisson);
    let exx = ((1.0 - nu * nu) * SIGMA[0][0] - nu * (1.0 + nu) * SIGMA[1][1]) / e;
    let eyy = ((1.0 - nu * nu) * SIGMA[1][1] - nu * (1.0 + nu) * SIGMA[0][0]) / e;
    let exy = SIGMA[0][1] / (2.0 * m.shear());
    [[exx, exy], [exy, eyy]]
}

fn exact_u(eps: [[f64; 2]; 2], x: [f64; 2]) -> [f64; 2] {
    [eps[0][0] * x[0] + eps[0][1] * x[1], eps[1][0] * x[0] + eps[1][1] * x[1]]
}

/// The 4 × 2 rectangle of tests/bem_patch.rs: displacements on bottom and left, tractions σ⁰·n
/// on right and top; element lengths 4/3 (bottom), 1 (others).
fn patch_model(nu: f64) -> BemModel {
    let material = Elastic::new(210_000.0, nu);
    let eps = strain(&material);
    let u = BoundaryCondition::DisplacementField(Arc::new(move |x, _| exact_u(eps, x)));
    let t = BoundaryCondition::TractionField(Arc::new(|_, n| {
        [
            SIGMA[0][0] * n[0] + SIGMA[0][1] * n[1],
            SIGMA[1][0] * n[0] + SIGMA[1][1] * n[1],
        ]
    }));
    BemModel::new(
        rectangle(
            [-1.0, -0.5],
            4.0,
            2.0,
            [3, 2, 4, 2],
            ["bottom", "right", "top", "left"],
            true,
        ),
        material,
        vec![
            ("bottom".into(), u.clone()),
            ("left".into(), u),
            ("right".into(), t.clone()),
            ("top".into(), t),
        ],
        BemOptions::default(),
    )
    .unwrap()
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
/// BEM solve's (≤ 1e-12, tests/bem_patch.rs) and the interior quadrature's (tolerance 1e-12):
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
        points.extend([[1.0, -0.4], [2.9, 0.5], [0.3, 1.4], [-0.9, 0.0], [-0.9, -0.4], [2.9, 1.4]]);
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
            for c in 0..4 {
                es = es.max((v.stress[c] - exact[c]).abs() / 50.0);
            }
            let ue = exact_u(eps, *x);
            for c in 0..2 {
                eu = eu.max((v.displacement[c] - ue[c]).abs() / u_scale);
            }
        }
        println!("interior patch nu={nu}: max rel error sigma {es:.2e}, u {eu:.2e}");
        assert!(es < 1e-9 && eu < 1e-9, "nu={nu}: sigma {es:e}, u {eu:e}");
    }
}

/// Points outside the body, on its boundary and within the boundary layer are reported as such
/// and never evaluated.
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
