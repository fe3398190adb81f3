//! Hypersingular BEM (HBEM) boundary strains (issue 4 part 3): the displacement gradient at
//! boundary points from the boundary displacements and tractions (paper Eq. 79, reference
//! sheet §9), checked on exact fields, under mesh refinement, and as the slip of a rolling
//! contact against Carter.

mod common;

use rollbem::bem::hypersingular::{GradientEvaluator, GradientPoint, GradientRows};
use rollbem::bem::{BemModel, BemOptions, BoundaryCondition};
use rollbem::material::Elastic;
use rollbem::mesh::build::{annulus, rectangle};
use std::sync::Arc;

// ---------------------------------------------------------------------------------------------
// Exact fields on straight and curved meshes.

const SIGMA: [[f64; 2]; 2] = [[50.0, 20.0], [20.0, -30.0]];

/// Plane-strain strain of the uniform stress SIGMA (reference sheet §8 Hooke's law).
fn strain(m: &Elastic) -> [[f64; 2]; 2] {
    let (e, nu) = (m.young, m.poisson);
    let exx = ((1.0 - nu * nu) * SIGMA[0][0] - nu * (1.0 + nu) * SIGMA[1][1]) / e;
    let eyy = ((1.0 - nu * nu) * SIGMA[1][1] - nu * (1.0 + nu) * SIGMA[0][0]) / e;
    let exy = SIGMA[0][1] / (2.0 * m.shear());
    [[exx, exy], [exy, eyy]]
}

fn patch_u(eps: [[f64; 2]; 2], x: [f64; 2]) -> [f64; 2] {
    [eps[0][0] * x[0] + eps[0][1] * x[1], eps[1][0] * x[0] + eps[1][1] * x[1]]
}

fn patch_t(n: [f64; 2]) -> [f64; 2] {
    [
        SIGMA[0][0] * n[0] + SIGMA[0][1] * n[1],
        SIGMA[1][0] * n[0] + SIGMA[1][1] * n[1],
    ]
}

/// 4 × 2 rectangle at (−1, −0.5); the top is a contact group (fully discontinuous elements),
/// the other sides have partially discontinuous elements at the corners.
fn patch_model(nu: f64) -> BemModel {
    let material = Elastic::new(210_000.0, nu);
    let eps = strain(&material);
    let u = BoundaryCondition::DisplacementField(Arc::new(move |x, _| patch_u(eps, x)));
    let t = BoundaryCondition::TractionField(Arc::new(|_, n| patch_t(n)));
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
            ("top".into(), BoundaryCondition::Contact),
        ],
        BemOptions::default(),
    )
    .unwrap()
}

/// Max |∇u − exact| / max |exact| over 2 × 2 components.
fn gradient_error(got: [[f64; 2]; 2], exact: [[f64; 2]; 2]) -> f64 {
    let scale = exact.iter().flatten().fold(0.0f64, |a, b| a.max(b.abs()));
    let mut e = 0.0f64;
    for i in 0..2 {
        for k in 0..2 {
            e = e.max((got[i][k] - exact[i][k]).abs());
        }
    }
    e / scale
}

/// Every element of the model at several ξ, including the field-node positions ±2/3 and 0 of
/// discontinuous elements and points close to an element end.
fn boundary_points(model: &BemModel) -> Vec<GradientPoint> {
    (0..model.mesh.elements.len())
        .flat_map(|element| {
            [-0.93, -2.0 / 3.0, -0.2, 0.0, 0.45, 2.0 / 3.0]
                .into_iter()
                .map(move |xi| GradientPoint::Boundary { element, xi })
        })
        .collect()
}

/// Exact nodal u and t of the uniform stress field. Every element of the patch is straight,
/// so u (linear) and t (constant per side) are interpolated exactly and the identity holds
/// exactly for the nodal data: the only error is the quadrature (tolerance 1e-12 for the
/// regular and nearly singular parts, converged Gauss remainders on the element containing X),
/// amplified by the 1/r² kernel near element ends (X at ξ = −0.93 lies 0.035 element lengths
/// from the neighbour). Target 1e-8 relative, four orders above the integration tolerance
/// (measured 6.2e-10 at ν = 0.3, 8.6e-10 at ν = 0.5, worst at ξ = −0.93, where the bounded
/// remainder of the singular element still loses a few digits to cancellation).
#[test]
fn uniform_stress_gradient_is_exact_from_exact_nodal_values() {
    for nu in [0.3, 0.5] {
        let model = patch_model(nu);
        let eps = strain(&model.material);
        let u: Vec<[f64; 2]> = model.field_nodes().iter().map(|n| patch_u(eps, n.position)).collect();
        let t: Vec<[f64; 2]> = model.field_nodes().iter().map(|n| patch_t(n.normal)).collect();
        let evaluator = GradientEvaluator::new(&model);
        let mut worst = 0.0f64;
        for point in boundary_points(&model) {
            let rows = evaluator.rows(point).unwrap();
            worst = worst.max(gradient_error(rows.apply(&u, &t), eps));
        }
        // Interior points, near and far from the boundary (free term 1, no singular element).
        for p in [[1.0, 0.5], [-0.9, -0.45], [2.95, 1.4], [0.3, 1.49]] {
            let rows = evaluator.rows(GradientPoint::Interior(p)).unwrap();
            worst = worst.max(gradient_error(rows.apply(&u, &t), eps));
        }
        println!("patch nu={nu}: HBEM gradient from exact nodal data, max rel error {worst:.2e}");
        assert!(worst < 1e-8, "nu={nu}: {worst:e}");
    }
}

/// The same from a BEM solve of the patch problem (contact side traction-loaded with σ⁰·n):
/// the solve is exact to ~1e-12 (tests/bem_patch.rs asserts 1e-9), so the HBEM gradient must
/// still be exact to 1e-8.
#[test]
fn uniform_stress_gradient_is_exact_from_the_bem_solution() {
    for nu in [0.3, 0.5] {
        let mut model = patch_model(nu);
        let top = model.mesh.group_index("top").unwrap();
        model.conditions[top] = BoundaryCondition::TractionField(Arc::new(|_, n| patch_t(n)));
        let sol = model.solve().unwrap();
        let eps = strain(&model.material);
        let evaluator = GradientEvaluator::new(&model);
        let worst = boundary_points(&model)
            .into_iter()
            .map(|p| gradient_error(evaluator.rows(p).unwrap().apply(&sol.displacement, &sol.traction), eps))
            .fold(0.0f64, f64::max);
        println!("patch nu={nu}: HBEM gradient from the BEM solution, max rel error {worst:.2e}");
        assert!(worst < 1e-8, "nu={nu}: {worst:e}");
    }
}

/// Rigid motions on a curved mesh (continuous quadratic arcs of an annulus, 45° per element):
/// a translation or a rotation is interpolated exactly on curved quadratic elements (u linear
/// in x, x quadratic in ξ), with zero traction, so the finite-part V integrals alone must give
/// ∇u = 0 and ∇u = [[0, −1], [1, 0]] to quadrature accuracy (bound 1e-8 of the unit gradient)
/// at points strictly inside the elements. This is the one exact test of the curved-element
/// Laurent terms (c, n1 and the Jacobian slope).
#[test]
fn rigid_motions_have_the_exact_gradient_on_curved_elements() {
    let model = BemModel::new(
        annulus(10.0, 20.0, 8, 8, ["inner", "outer"], true),
        Elastic::new(210_000.0, 0.3),
        vec![
            ("inner".into(), BoundaryCondition::Fixed),
            ("outer".into(), BoundaryCondition::Free),
        ],
        BemOptions::default(),
    )
    .unwrap();
    let evaluator = GradientEvaluator::new(&model);
    let t = vec![[0.0; 2]; model.field_nodes().len()];
    let motions: [(fn([f64; 2]) -> [f64; 2], [[f64; 2]; 2]); 3] = [
        (|_| [1.0, 0.0], [[0.0, 0.0], [0.0, 0.0]]),
        (|_| [0.0, 1.0], [[0.0, 0.0], [0.0, 0.0]]),
        (|x| [-x[1], x[0]], [[0.0, -1.0], [1.0, 0.0]]),
    ];
    let points: Vec<GradientPoint> = (0..model.mesh.elements.len())
        .flat_map(|element| [-0.7, 0.0, 0.55].map(|xi| GradientPoint::Boundary { element, xi }))
        .collect();
    let rows: Vec<GradientRows> = points.iter().map(|&p| evaluator.rows(p).unwrap()).collect();
    for (motion, exact) in motions {
        let u: Vec<[f64; 2]> = model.field_nodes().iter().map(|n| motion(n.position)).collect();
        let worst = rows
            .iter()
            .map(|r| {
                let g = r.apply(&u, &t);
                let mut e = 0.0f64;
                for i in 0..2 {
                    for k in 0..2 {
                        e = e.max((g[i][k] - exact[i][k]).abs());
                    }
                }
                e
            })
            .fold(0.0f64, f64::max);
        println!("rigid motion on 45° arcs: max |∇u − exact| = {worst:.2e}");
        assert!(worst < 1e-8, "{worst:e}");
    }
}

#[test]
fn points_outside_an_element_are_refused() {
    let model = patch_model(0.3);
    let evaluator = GradientEvaluator::new(&model);
    for (element, xi) in [(0, 1.0), (0, -1.0), (0, f64::NAN), (10_000, 0.0)] {
        let err = evaluator.rows(GradientPoint::Boundary { element, xi }).unwrap_err();
        assert!(err.to_string().contains("strictly inside an element"), "{err}");
    }
}

// ---------------------------------------------------------------------------------------------
// Rolling contact: the HBEM slip against Carter.

#[test]
fn carter_true_rollers_hbem_slip() {
    let (loaded, s) = common::solve("carter_051_true", &[]);
    let c = rollbem::app::carter_reference(&loaded, &s.estimates).unwrap();
    let r = s.estimates.effective_radius;
    let sol = &s.solution;
    let hbem = sol.slip_strain.as_ref().expect("bem bodies have the HBEM strain");
    for i in 0..sol.x.len() {
        println!(
            "{:+.4} {:>5} fd {:+.4e} hbem {:+.4e} carter {:+.4e}",
            sol.x[i],
            sol.state[i].name(),
            sol.slip[i],
            hbem[i],
            c.slip(sol.x[i], r)
        );
    }
}
