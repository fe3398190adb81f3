//! Patch test of the BEM (docs/references.md §8.3): a uniform stress state on a rectangle with
//! corners. The exact boundary fields (u linear, t constant per side) lie in the quadratic
//! interpolation space, so the collocation equations are satisfied exactly by the exact nodal
//! values and the only error left is the quadrature error (target 1e-12 relative, see
//! `BemOptions::quadrature_tolerance`) amplified by the conditioning of the system (~10² for
//! these small meshes). Hence the 1e-9 bound: three orders of margin over the integration, yet
//! any wrong kernel sign, free term, corner treatment or near-singular rule gives errors of 1e-4
//! or more.

use rollbem::bem::{BemError, BemModel, BemOptions, BoundaryCondition, Pin};
use rollbem::material::Elastic;
use rollbem::mesh::build::rectangle;
use rollbem::mesh::BoundaryMesh;
use std::sync::Arc;

use crate::common::patch::{exact_t, exact_u, strain};

fn mesh(quadratic: bool) -> BoundaryMesh {
    crate::common::patch::rectangle_mesh(quadratic)
}

fn model(material: Elastic, quadratic: bool) -> BemModel {
    model_on(mesh(quadratic), material)
}

fn model_on(mesh: BoundaryMesh, material: Elastic) -> BemModel {
    crate::common::patch::model(mesh, material, None)
}

/// Max errors of u and t at the field nodes, relative to the largest exact value.
fn errors(model: &BemModel, u: &[[f64; 2]], t: &[[f64; 2]]) -> (f64, f64) {
    let eps = strain(&model.material);
    let (mut eu, mut et, mut su, mut st) = (0.0f64, 0.0f64, 0.0f64, 0.0f64);
    for (k, node) in model.field_nodes().iter().enumerate() {
        let ue = exact_u(eps, node.position);
        let te = exact_t(node.normal);
        for c in 0..2 {
            eu = eu.max((u[k][c] - ue[c]).abs());
            et = et.max((t[k][c] - te[c]).abs());
            su = su.max(ue[c].abs());
            st = st.max(te[c].abs());
        }
    }
    (eu / su, et / st)
}

#[test]
fn uniform_stress_is_reproduced_to_round_off_with_quadratic_elements() {
    for nu in [0.3, 0.5] {
        for quadratic in [true, false] {
            let m = model(Elastic::new(210_000.0, nu), quadratic);
            let sol = m.solve().unwrap();
            let (eu, et) = errors(&m, &sol.displacement, &sol.traction);
            println!("patch nu={nu} line3={quadratic}: max rel error u {eu:.2e}, t {et:.2e}");
            assert!(eu < 1e-9 && et < 1e-9, "nu={nu} line3={quadratic}: u {eu:e}, t {et:e}");
        }
    }
}

/// Thin strips (a layer thinner than its elements are long, as in the tyre's cover layer): the
/// patch solution is still exact in the element space, so any error is the nearly singular
/// integration between the two faces, whose distance b is a small fraction of the element
/// length h. Same 1e-9 bound as above, for h/b = 2, 10, 50 and ν = 0.3, 0.5.
#[test]
fn uniform_stress_in_a_strip_thinner_than_its_elements() {
    for nu in [0.3, 0.5] {
        for ratio in [2.0, 10.0, 50.0] {
            let (length, h) = (4.0, 0.5);
            let b = h / ratio;
            let strip = rectangle(
                [-2.0, -b],
                length,
                b,
                [8, 1, 8, 1],
                ["bottom", "right", "top", "left"],
                true,
            );
            let m = model_on(strip, Elastic::new(210_000.0, nu));
            let sol = m.solve().unwrap();
            let (eu, et) = errors(&m, &sol.displacement, &sol.traction);
            println!("strip nu={nu} h/b={ratio}: max rel error u {eu:.2e}, t {et:.2e}");
            assert!(eu < 1e-9 && et < 1e-9, "nu={nu} h/b={ratio}: u {eu:e}, t {et:e}");
        }
    }
}

/// max_r |Σ_c H_rc v_c| / (‖H‖∞ ‖v‖∞) for the rigid modes: x and y translation, rotation.
fn rigid_mode_residuals(m: &BemModel) -> [f64; 3] {
    let asm = m.assemble();
    let nodes = m.field_nodes();
    let n = nodes.len();
    let modes: [fn([f64; 2]) -> [f64; 2]; 3] = [|_| [1.0, 0.0], |_| [0.0, 1.0], |x| [-x[1], x[0]]];
    let h_norm = (0..2 * n)
        .map(|r| (0..2 * n).map(|c| asm.h[(r, c)].abs()).sum::<f64>())
        .fold(0.0f64, f64::max);
    modes.map(|mode| {
        let v: Vec<f64> = nodes.iter().flat_map(|p| mode(p.position)).collect();
        let v_norm = v.iter().fold(0.0f64, |a, b| a.max(b.abs()));
        let worst = (0..2 * n)
            .map(|r| (0..2 * n).map(|c| asm.h[(r, c)] * v[c]).sum::<f64>().abs())
            .fold(0.0f64, f64::max);
        worst / (h_norm * v_norm)
    })
}

#[test]
fn h_annihilates_rigid_body_modes() {
    // Translations vanish by construction (rigid-body diagonal); the rotation checks the
    // off-diagonal blocks against that diagonal. A rigid motion is interpolated exactly and
    // the BIE holds on the discrete (parabolic) geometry itself, so on curved elements too the
    // only error is the quadrature (tolerance 1e-12): bound 1e-11. (Contracted with the
    // rotation, T*(x−X) reduces to a multiple of the tangent, so this mostly checks loop
    // closure, orientation and the diagonal; the patch test checks the integrals.)
    let rectangle = model(Elastic::new(210_000.0, 0.3), true);
    let ring = crate::common::lame::fixed_ring(12);
    for (label, m) in [("rectangle", rectangle), ("curved ring", ring)] {
        let res = rigid_mode_residuals(&m);
        println!(
            "{label}: ‖Hv‖/(‖H‖‖v‖) for x, y, rotation = {:.2e} {:.2e} {:.2e}",
            res[0], res[1], res[2]
        );
        assert!(res.iter().all(|&r| r < 1e-11), "{label}: {res:?}");
    }
}

#[test]
fn traction_only_body_with_three_pins_is_exact_and_returns_the_pin_tractions() {
    // All four sides loaded by σ⁰·n; the rigid motion is removed by prescribing the exact
    // displacement on three components (x and y at one node, y at a distant one).
    let material = Elastic::new(210_000.0, 0.3);
    let eps = strain(&material);
    let t = BoundaryCondition::TractionField(Arc::new(|_, n| exact_t(n)));
    let m = BemModel::new(
        mesh(true),
        material,
        ["bottom", "right", "top", "left"]
            .iter()
            .map(|g| (g.to_string(), t.clone()))
            .collect(),
        BemOptions::default(),
    )
    .unwrap();
    assert!(matches!(m.solve(), Err(BemError::RigidBodyMotion { .. })));
    let nodes = m.field_nodes();
    let (a, b) = (0, nodes.len() / 2);
    let ua = exact_u(eps, nodes[a].position);
    let ub = exact_u(eps, nodes[b].position);
    let pins = [
        Pin {
            node: a,
            component: 0,
            value: ua[0],
        },
        Pin {
            node: a,
            component: 1,
            value: ua[1],
        },
        Pin {
            node: b,
            component: 1,
            value: ub[1],
        },
    ];
    let sol = m.solve_pinned(&pins).unwrap();
    let (eu, et) = errors(&m, &sol.displacement, &sol.traction);
    println!("pinned patch: u {eu:.2e}, t {et:.2e}");
    assert!(eu < 1e-9 && et < 1e-9, "u {eu:e}, t {et:e}");

    // Two pins at one node leave the rotation about it free: the model must refuse rather
    // than return garbage.
    let err = m.solve_pinned(&pins[..2]).unwrap_err();
    assert!(matches!(err, BemError::RigidBodyMotion { .. }), "{err}");
}

#[test]
fn missing_and_unknown_group_conditions_are_reported() {
    let material = Elastic::new(210_000.0, 0.3);
    let err = BemModel::new(
        mesh(true),
        material,
        vec![("bottom".into(), BoundaryCondition::Fixed)],
        BemOptions::default(),
    )
    .unwrap_err();
    assert!(
        matches!(err, BemError::MissingCondition { ref group, .. } if group == "right"),
        "{err}"
    );
    let err = BemModel::new(
        mesh(true),
        material,
        vec![("shaft".into(), BoundaryCondition::Fixed)],
        BemOptions::default(),
    )
    .unwrap_err();
    assert!(err.to_string().contains("`shaft`"), "{err}");
    let err = BemModel::new(mesh(true), Elastic::new(1.0, 0.6), vec![], BemOptions::default()).unwrap_err();
    assert!(matches!(err, BemError::InvalidMaterial { .. }), "{err}");
}

#[test]
fn uniform_stress_on_a_gmsh_plate_with_a_hole_and_a_contact_segment() {
    // End to end from tests/data/msh/plate.msh (reversed curves, a hole, four groups).
    // Displacements prescribed on the straight bottom and on the curved hole, tractions σ⁰·n on
    // the other straight sides. u (linear) is exact in the quadratic space; the unknown hole
    // traction σ⁰·n(ξ) is not (n varies non-polynomially along a parabolic arc), so there the
    // error is the interpolation error of the normal over 45° arcs (measured t 8e-4, and
    // through it u 1.6e-6).
    let path = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/data/msh/plate.msh");
    let (mesh, notices) = rollbem::mesh::load(&path).unwrap();
    assert!(!notices.is_empty());
    let material = Elastic::new(210_000.0, 0.3);
    let eps = strain(&material);
    let u = BoundaryCondition::DisplacementField(Arc::new(move |x, _| exact_u(eps, x)));
    let t = BoundaryCondition::TractionField(Arc::new(|_, n| exact_t(n)));
    let m = BemModel::new(
        mesh,
        material,
        vec![
            ("fixed".into(), u.clone()),
            ("shaft".into(), u),
            ("free".into(), t.clone()),
            ("contact".into(), t),
        ],
        BemOptions::default(),
    )
    .unwrap();
    let sol = m.solve().unwrap();
    let (eu, et) = errors(&m, &sol.displacement, &sol.traction);
    println!("gmsh plate patch: u {eu:.2e}, t {et:.2e}");
    assert!(eu < 1e-4 && et < 1e-2, "u {eu:e}, t {et:e}");
}
