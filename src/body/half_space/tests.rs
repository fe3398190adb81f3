//! Tests of the half-plane's influence matrices, flexibility and strain.

use super::*;

fn close(a: f64, b: f64) -> bool {
    (a - b).abs() < 5e-9
}

/// docs/references.md §3.2 table: quadratic element s ∈ [−0.4, 0.25] with nodes at its ends and
/// midpoint. Our elements place nodes at ξ = ±2/3, so rebuild the end-node shape functions
/// from ours by the change of basis N_end = Σ_b N_end(ξ_b) N_b (exact for quadratics).
fn end_node_integrals(kernel: Kernel, x: f64) -> [f64; 3] {
    let ours = element_integrals_exact(ElementKind::DiscontinuousQuadratic, kernel, -0.4, 0.25, x);
    let xi_b = ElementKind::DiscontinuousQuadratic.node_coordinates();
    let end = |xi: f64, target: f64| {
        // Lagrange basis through −1, 0, 1, evaluated at ξ.
        match target as i32 {
            -1 => 0.5 * xi * (xi - 1.0),
            0 => 1.0 - xi * xi,
            _ => 0.5 * xi * (xi + 1.0),
        }
    };
    [-1.0, 0.0, 1.0].map(|t| (0..3).map(|b| end(xi_b[b], t) * ours[b]).sum())
}

#[test]
fn quadratic_element_integrals_match_the_references() {
    let cases = [
        (
            -0.9,
            [-0.070286223, -0.090323505, 0.017909553],
            [-0.108333333, -0.433333333, -0.108333333],
        ),
        (
            -0.1,
            [-0.183779527, -1.060971795, -0.133878263],
            [0.161489152, -0.049901381, -0.161587771],
        ),
        (
            0.25,
            [-0.028612594, -0.547783708, -0.353612594],
            [0.108333333, 0.433333333, 0.108333333],
        ),
        (
            0.8,
            [0.022231732, -0.064028242, -0.060607271],
            [0.108333333, 0.433333333, 0.108333333],
        ),
    ];
    for (x, log_ref, sgn_ref) in cases {
        let log = end_node_integrals(Kernel::Log, x);
        let sgn = end_node_integrals(Kernel::Sign, x);
        for a in 0..3 {
            assert!(
                close(log[a], log_ref[a]),
                "log x={x} a={a}: {} vs {}",
                log[a],
                log_ref[a]
            );
            assert!(
                close(sgn[a], sgn_ref[a]),
                "sgn x={x} a={a}: {} vs {}",
                sgn[a],
                sgn_ref[a]
            );
        }
    }
    let cau = end_node_integrals(Kernel::Cauchy, 0.03);
    for (c, r) in cau.iter().zip([0.603641931, 1.246361324, -1.179845593]) {
        assert!(close(*c, r), "cauchy {c} vs {r}");
    }
    let cau = end_node_integrals(Kernel::Cauchy, -0.9);
    for (c, r) in cau.iter().zip([-0.202236830, -0.542743236, -0.087929057]) {
        assert!(close(*c, r), "cauchy {c} vs {r}");
    }
}

#[test]
fn constant_element_integrals_match_the_references() {
    let k = ElementKind::Constant;
    for (x, refs) in [
        (0.0, [-2.0, 0.0, 0.0]),
        (0.5, [-1.738375928, 1.0, 3f64.ln()]),
        (2.0, [1.295836866, 2.0, 3f64.ln()]),
    ] {
        let got =
            [Kernel::Log, Kernel::Sign, Kernel::Cauchy].map(|kern| element_integrals_exact(k, kern, -1.0, 1.0, x)[0]);
        for (g, r) in got.iter().zip(refs) {
            assert!(close(*g, r), "x={x}: {g} vs {r}");
        }
    }
}

/// The block-Toeplitz fill equals integrating every node–element pair directly.
#[test]
fn toeplitz_fill_equals_direct_integration() {
    for kind in [ElementKind::DiscontinuousQuadratic, ElementKind::Constant] {
        let grid = ContactGrid::uniform(kind, 9, -1.7, 1.3);
        for kernel in [Kernel::Log, Kernel::Sign, Kernel::Cauchy] {
            let k = influence_matrix(&grid, kernel);
            let npe = kind.nodes_per_element();
            for (i, &x) in grid.nodes.iter().enumerate() {
                for e in 0..grid.n_elements() {
                    let direct = element_integrals_exact(kind, kernel, grid.edges[e], grid.edges[e + 1], x);
                    for (a, v) in direct.iter().take(npe).enumerate() {
                        let got = k[(i, e * npe + a)];
                        assert!(
                            (got - v).abs() < 1e-12 * (1.0 + v.abs()),
                            "{kernel:?} i={i} e={e}: {got} vs {v}"
                        );
                    }
                }
            }
        }
    }
}

#[test]
fn far_field_series_of_graded_grids_match_the_twelve_point_rule() {
    let twelve = gauss_legendre(12);
    for kernel in [Kernel::Log, Kernel::Sign, Kernel::Cauchy] {
        for kind in [
            ElementKind::DiscontinuousQuadratic,
            ElementKind::ContinuousQuadratic,
            ElementKind::Constant,
        ] {
            // Field points from the switch (2.5 lengths) to 1e6 lengths away, both sides.
            for d in [2.51, 4.0, 10.0, 100.0, 1e4, 1e6, -3.0, -1e3] {
                let (s1, s2) = (0.3, 0.3 + 1e-3);
                let x = 0.3005 + d * 1e-3;
                let got = FarField::new(kind).integrals(kernel, s1, s2, x);
                let want = element_integrals_gauss(kind, kernel, s1, s2, x, &twelve);
                // The integrand's own size: |K| (≥ 1) times the element length.
                let k = kernel.eval(x, 0.3005).abs().max(1.0);
                let scale = k * 1e-3;
                for (g, w) in got.iter().zip(&want) {
                    assert!((g - w).abs() <= 1e-13 * scale, "{kernel:?} {kind:?} d {d}: {g} vs {w}");
                }
            }
        }
    }
}

#[test]
fn far_field_quadrature_agrees_with_closed_form_at_the_switch() {
    let rule = gauss_legendre(12);
    let kind = ElementKind::DiscontinuousQuadratic;
    for kernel in [Kernel::Log, Kernel::Sign, Kernel::Cauchy] {
        for x in [2.6, -2.7, 3.5] {
            let exact = element_integrals_exact(kind, kernel, -0.5, 0.5, x);
            let gauss = element_integrals_gauss(kind, kernel, -0.5, 0.5, x, &rule);
            let series = FarField::new(kind).integrals(kernel, -0.5, 0.5, x);
            for ((e, g), s) in exact.iter().zip(&gauss).zip(&series) {
                assert!((e - g).abs() < 1e-13, "{kernel:?} x={x}: {e} vs {g}");
                assert!((e - s).abs() < 1e-13, "{kernel:?} x={x}: {e} vs series {s}");
            }
        }
    }
}

/// At a small depth the interior displacement meets the half-space model's surface
/// displacement (same datum), for a Hertz pressure and a Carter-like shear, on both sides:
/// h = u_z (into the body) and w = ±u_x of the pair convention. The depth z = 1e-3 of an
/// element moves u by about z·|∂u/∂z| ~ 1e-4 of its range.
#[test]
fn interior_displacement_meets_the_half_space_surface_displacement() {
    use crate::body::flamant::halfplane_interior;
    use crate::body::ContactLoad;
    use crate::interior::{InteriorOptions, InteriorSample};
    let grid = ContactGrid::uniform(ElementKind::DiscontinuousQuadratic, 21, -1.3, 1.3);
    let hs = HalfSpace::new(Elastic::new(210_000.0, 0.3), 100.0);
    let p: Vec<f64> = grid
        .nodes
        .iter()
        .map(|x| 1000.0 * (1.0 - x * x).max(0.0).sqrt())
        .collect();
    let q: Vec<f64> = grid.nodes.iter().zip(&p).map(|(x, p)| 0.1 * p * x).collect();
    let z = 1e-3 * grid.element_length();
    for side in [Side::A, Side::B] {
        let f = hs.flexibility(&grid, side);
        let (h, w) = (f.normal(&p, &q), f.tangential(&p, &q));
        let range = h.iter().chain(&w).fold(0.0f64, |m, v| m.max(v.abs()));
        let points: Vec<[f64; 2]> = grid.nodes.iter().map(|&x| [x, side.sign() * z]).collect();
        let load = ContactLoad {
            grid: &grid,
            pressure: &p,
            shear: &q,
        };
        let samples = halfplane_interior(
            &load,
            hs.material.shear(),
            0.3,
            hs.datum_length(),
            side,
            &points,
            &InteriorOptions {
                boundary_layer: 1e-4,
                ..Default::default()
            },
        );
        for (i, s) in samples.iter().enumerate() {
            let InteriorSample::Inside(v) = s else {
                panic!("{side:?} node {i}: {s:?}")
            };
            // Contact frame → pair convention: h = ±u_y into the body, w = ±u_x.
            let (hi, wi) = (side.sign() * v.displacement[1], side.sign() * v.displacement[0]);
            assert!((hi - h[i]).abs() < 1e-3 * range, "{side:?} h[{i}]: {hi} vs {}", h[i]);
            assert!((wi - w[i]).abs() < 1e-3 * range, "{side:?} w[{i}]: {wi} vs {}", w[i]);
        }
    }
}

/// The half-plane's displacements and strain under a few loads, integrated row by row without
/// the blocks (`BodyModel::displacements`, `BodyModel::strain_at`), are the products of its
/// flexibility and strain operator on a graded grid, on either side, to rounding.
#[test]
fn the_loads_applied_without_the_blocks_are_the_blocks_products() {
    let grid = ContactGrid::from_edges(
        ElementKind::DiscontinuousQuadratic,
        vec![-1.0, -0.6, -0.3, -0.1, 0.0, 0.05, 0.2, 0.5, 1.0],
    );
    let body = HalfSpace::new(Elastic::new(70_000.0, 0.33), 40.0);
    let m = grid.n_nodes();
    let p = Mat::from_fn(m, 2, |i, c| 100.0 * (1.0 + (0.7 * i as f64 + c as f64).sin()));
    let q = Mat::from_fn(m, 2, |i, c| 20.0 * (0.4 * i as f64 - c as f64).cos());
    for side in [Side::A, Side::B] {
        let f = body.flexibility(&grid, side);
        let want = [&f.hp * &p + &f.hq * &q, &f.wp * &p + &f.wq * &q];
        let got = body.displacements(&grid, side, p.as_ref(), q.as_ref());
        let s = body.strain_operator(&grid, side).unwrap();
        let want_strain = &s.p * &p + &s.q * &q;
        let got_strain = body.strain_at(&grid, side, p.as_ref(), q.as_ref()).unwrap();
        for (g, w) in got.iter().zip(&want).chain([(&got_strain, &want_strain)]) {
            let scale = w.norm_max();
            assert!(
                (g - w).norm_max() <= 1e-12 * scale,
                "{:.2e} of {scale:.2e}",
                (g - w).norm_max()
            );
        }
    }
}
