//! The uniform-stress patch (docs/references.md §8.3): a plane-strain stress SIGMA, its linear
//! displacement and its constant traction, exact for any BEM mesh.

use rollbem::bem::{BemModel, BemOptions, BoundaryCondition};
use rollbem::material::Elastic;
use rollbem::mesh::build::rectangle;
use rollbem::mesh::BoundaryMesh;
use std::sync::Arc;

/// The uniform stress σ⁰ [MPa].
pub const SIGMA: [[f64; 2]; 2] = [[50.0, 20.0], [20.0, -30.0]];

/// Plane-strain strain of the uniform stress SIGMA (docs/references.md §8 Hooke's law).
pub fn strain(m: &Elastic) -> [[f64; 2]; 2] {
    let (e, nu) = (m.young, m.poisson);
    let exx = ((1.0 - nu * nu) * SIGMA[0][0] - nu * (1.0 + nu) * SIGMA[1][1]) / e;
    let eyy = ((1.0 - nu * nu) * SIGMA[1][1] - nu * (1.0 + nu) * SIGMA[0][0]) / e;
    let exy = SIGMA[0][1] / (2.0 * m.shear());
    [[exx, exy], [exy, eyy]]
}

/// Displacement u = ε·x of the patch (no rigid motion) [mm].
pub fn exact_u(eps: [[f64; 2]; 2], x: [f64; 2]) -> [f64; 2] {
    [eps[0][0] * x[0] + eps[0][1] * x[1], eps[1][0] * x[0] + eps[1][1] * x[1]]
}

/// Traction σ⁰·n on a boundary of outward normal n [MPa].
pub fn exact_t(n: [f64; 2]) -> [f64; 2] {
    [
        SIGMA[0][0] * n[0] + SIGMA[0][1] * n[1],
        SIGMA[1][0] * n[0] + SIGMA[1][1] * n[1],
    ]
}

/// The 4 × 2 rectangle at (−1, −0.5) with sides bottom, right, top, left (3, 2, 4, 2 elements:
/// lengths 4/3 on the bottom, 1 elsewhere).
pub fn rectangle_mesh(quadratic: bool) -> BoundaryMesh {
    rectangle(
        [-1.0, -0.5],
        4.0,
        2.0,
        [3, 2, 4, 2],
        ["bottom", "right", "top", "left"],
        quadratic,
    )
}

/// The patch problem on a mesh with sides bottom, right, top, left: the exact displacements on
/// bottom and left, the exact tractions σ⁰·n on right and on top, unless `top` says otherwise
/// (e.g. [`BoundaryCondition::Contact`], loaded later).
pub fn model(mesh: BoundaryMesh, material: Elastic, top: Option<BoundaryCondition>) -> BemModel {
    let eps = strain(&material);
    let u = BoundaryCondition::DisplacementField(Arc::new(move |x, _| exact_u(eps, x)));
    let t = BoundaryCondition::TractionField(Arc::new(|_, n| exact_t(n)));
    let top = top.unwrap_or_else(|| t.clone());
    BemModel::new(
        mesh,
        material,
        vec![
            ("bottom".into(), u.clone()),
            ("left".into(), u),
            ("right".into(), t),
            ("top".into(), top),
        ],
        BemOptions::default(),
    )
    .unwrap()
}
