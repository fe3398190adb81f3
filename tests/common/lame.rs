//! The Lamé thick cylinder of docs/references.md §8.1: a = 10, b = 20 mm, p_i = 100, p_o = 30 MPa.

use rollbem::bem::{BemModel, BemOptions, BoundaryCondition, Pin};
use rollbem::material::Elastic;
use rollbem::mesh::build::annulus;

/// Inner radius a [mm].
pub const A_IN: f64 = 10.0;
/// Outer radius b [mm].
pub const B_OUT: f64 = 20.0;
/// Bore pressure p_i [MPa].
pub const P_IN: f64 = 100.0;
/// Outer pressure p_o [MPa].
pub const P_OUT: f64 = 30.0;

/// The constants (A, B) of σ_rr = A − B/r², σ_θθ = A + B/r² [MPa, MPa·mm²].
fn constants() -> (f64, f64) {
    let (a2, b2) = (A_IN * A_IN, B_OUT * B_OUT);
    (
        (P_IN * a2 - P_OUT * b2) / (b2 - a2),
        (P_IN - P_OUT) * a2 * b2 / (b2 - a2),
    )
}

/// Radial displacement u_r(r) [mm].
pub fn radial_displacement(m: &Elastic, r: f64) -> f64 {
    let (ca, cb) = constants();
    (1.0 + m.poisson) / m.young * ((1.0 - 2.0 * m.poisson) * ca * r + cb / r)
}

/// Displacement vector at x [mm].
pub fn displacement(m: &Elastic, x: [f64; 2]) -> [f64; 2] {
    let r = x[0].hypot(x[1]);
    let ur = radial_displacement(m, r);
    [ur * x[0] / r, ur * x[1] / r]
}

/// Largest exact |u| on the boundary [mm], the scale of relative displacement errors.
pub fn u_scale(m: &Elastic) -> f64 {
    radial_displacement(m, A_IN)
        .abs()
        .max(radial_displacement(m, B_OUT).abs())
}

/// (σxx, σyy, σzz, τxy) at x [MPa]; σzz = 2νA (plane strain).
pub fn stress(m: &Elastic, x: [f64; 2]) -> [f64; 4] {
    let (ca, cb) = constants();
    let r2 = x[0] * x[0] + x[1] * x[1];
    let (srr, stt) = (ca - cb / r2, ca + cb / r2);
    let (c2, s2, cs) = (x[0] * x[0] / r2, x[1] * x[1] / r2, x[0] * x[1] / r2);
    [
        srr * c2 + stt * s2,
        srr * s2 + stt * c2,
        2.0 * m.poisson * ca,
        (srr - stt) * cs,
    ]
}

/// The pressure-loaded cylinder with `n` continuous quadratic elements per circle.
pub fn pressure_loaded_lame(nu: f64, n: usize) -> BemModel {
    BemModel::new(
        annulus(A_IN, B_OUT, n, n, ["inner", "outer"], true),
        Elastic::new(210_000.0, nu),
        vec![
            ("inner".into(), BoundaryCondition::Pressure(P_IN)),
            ("outer".into(), BoundaryCondition::Pressure(P_OUT)),
        ],
        BemOptions::default(),
    )
    .unwrap()
}

/// Pins: exact (u_x, u_y) at the outer node nearest (b, 0) and u_x at the one nearest (0, b).
pub fn lame_pins(model: &BemModel) -> [Pin; 3] {
    let nodes = model.field_nodes();
    let nearest = |target: [f64; 2]| {
        let d = |k: usize| (nodes[k].position[0] - target[0]).hypot(nodes[k].position[1] - target[1]);
        (0..nodes.len()).min_by(|&i, &j| d(i).total_cmp(&d(j))).unwrap()
    };
    let (pa, pb) = (nearest([B_OUT, 0.0]), nearest([0.0, B_OUT]));
    let (ua, ub) = (
        displacement(&model.material, nodes[pa].position),
        displacement(&model.material, nodes[pb].position),
    );
    [
        Pin {
            node: pa,
            component: 0,
            value: ua[0],
        },
        Pin {
            node: pa,
            component: 1,
            value: ua[1],
        },
        Pin {
            node: pb,
            component: 0,
            value: ub[0],
        },
    ]
}

/// The Lamé annulus with n elements per circle, held fixed inside and free outside: a body
/// with no load, for tests of what the BEM does to rigid motions (ν = 0.3, steel).
pub fn fixed_ring(n: usize) -> BemModel {
    BemModel::new(
        annulus(A_IN, B_OUT, n, n, ["inner", "outer"], true),
        Elastic::new(210_000.0, 0.3),
        vec![
            ("inner".into(), BoundaryCondition::Fixed),
            ("outer".into(), BoundaryCondition::Free),
        ],
        BemOptions::default(),
    )
    .expect("the fixed annulus is well posed")
}
