//! Flat layer bonded to a rigid base (the tyre's building block): the BEM surface
//! compliance under a pressure P cos kx against the exact C(k) of docs/references.md §5.
//!
//! One wavelength −λ/2 ≤ x ≤ λ/2 is modelled: for a cos kx load the planes x = ±λ/2 are planes of
//! symmetry (u_x = 0, zero shear), so the strip with those conditions is the infinite layer
//! exactly. The layer is thin against the elements at kb = 0.1 (element length 1.6 b): this
//! exercises the near-singular integration.

use rollbem::bem::{BemModel, BemOptions, BoundaryCondition, Component};
use rollbem::material::Elastic;
use rollbem::mesh::build::rectangle;
use std::f64::consts::PI;
use std::sync::Arc;

/// Exact compliance C(k): surface deflection (into the layer) per unit pressure amplitude.
fn layer_compliance(k: f64, b: f64, m: &Elastic) -> f64 {
    let nu = m.poisson;
    let kappa = 3.0 - 4.0 * nu;
    let t = k * b;
    (1.0 - nu) / (m.shear() * k) * (kappa * (2.0 * t).sinh() - 2.0 * t)
        / (kappa * (2.0 * t).cosh() + 2.0 * t * t + 0.5 * (1.0 + kappa * kappa))
}

/// BEM deflection at x = 0 per unit pressure amplitude.
fn bem_compliance(k: f64, b: f64, m: &Elastic, n_top: usize) -> f64 {
    let lambda = 2.0 * PI / k;
    let h = lambda / n_top as f64;
    let n_side = ((b / h).ceil() as usize).max(2);
    let mesh = rectangle(
        [-0.5 * lambda, 0.0],
        lambda,
        b,
        [n_top, n_side, n_top, n_side],
        ["base", "sym", "top", "sym"],
        true,
    );
    let pressure = 1.0;
    let load = Arc::new(move |x: [f64; 2], _n: [f64; 2]| [0.0, -pressure * (k * x[0]).cos()]);
    let conditions = vec![
        ("base".to_string(), BoundaryCondition::Fixed),
        (
            "sym".to_string(),
            BoundaryCondition::Components([Component::Displacement(0.0), Component::Traction(0.0)]),
        ),
        ("top".to_string(), BoundaryCondition::TractionField(load)),
    ];
    let model = BemModel::new(mesh, *m, conditions, BemOptions::default()).expect("layer model");
    let sol = model.solve().expect("layer solve");
    let top = model.mesh.group_index("top").unwrap();
    let (k0, _) = model
        .field_nodes()
        .iter()
        .enumerate()
        .filter(|(_, n)| n.group == top)
        .min_by(|a, b| a.1.position[0].abs().total_cmp(&b.1.position[0].abs()))
        .unwrap();
    assert!(
        model.field_nodes()[k0].position[0].abs() < 1e-12,
        "no field node at x = 0"
    );
    -sol.displacement[k0][1] / pressure
}

#[test]
fn bonded_layer_reproduces_the_exact_surface_compliance() {
    for nu in [0.3, 0.5] {
        let m = Elastic::new(2.6, nu);
        for kb in [0.1, 0.5, 1.0, 3.0] {
            let (k, b) = (1.0, kb);
            let exact = layer_compliance(k, b, &m);
            let bem = bem_compliance(k, b, &m, 40);
            let rel = bem / exact - 1.0;
            println!("nu = {nu}, kb = {kb}: C_BEM = {bem:.6e}, C_exact = {exact:.6e}, relative error {rel:+.2e}");
            // Issue 4 asks for 1 %; measured ≤ 4e-5 (40 quadratic elements per wavelength), so
            // 1e-3 keeps a margin without hiding a regression behind the acceptance floor.
            assert!(rel.abs() < 1e-3, "nu = {nu}, kb = {kb}: {bem} vs {exact}");
        }
    }
}

/// The compliance tends to the half-plane's (1−ν)/(Gk) for a thick layer (sanity of C(k) itself).
#[test]
fn thick_layer_limit_is_the_half_plane() {
    let m = Elastic::new(2.6, 0.3);
    let c = layer_compliance(1.0, 20.0, &m);
    assert!((c / ((1.0 - 0.3) / m.shear()) - 1.0).abs() < 1e-12);
}
