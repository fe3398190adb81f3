//! The a-posteriori error estimate of a solution on a grid from the solution on its bisection.
//!
//! With u_G the solution on a grid G and u_H that on H = G with every element halved, the nodal
//! differences d_i = u_H(x_i) − u_G(x_i) at H's nodes (u_G interpolated by its own shape
//! functions) estimate the error of u_H. The tractions have square-root behaviour at the
//! contact edges and at the stick/slip points, so the nodal error next to such a point is
//! ∝ √h and the length-weighted RMS error over the contact is ∝ h (first order, as measured on
//! uniform grids): then e_G ≈ 2 e_H and d = e_G − e_H ≈ e_H. On the grids the error control
//! builds, graded towards those points, the error falls as h² to h³ under bisection (measured:
//! docs/validation.md), e_H ≈ d/3 to d/7. The estimates are [`PRESSURE_ESTIMATE_FACTOR`]·d for
//! the pressure and [`SHEAR_ESTIMATE_FACTOR`]·d for the shear, the errors of convergence as
//! h^2.3 and h² (why these two: at the constants). The creepage, an integral of the slip over
//! the stick zone whose end is a square-root point, converges at first order (measured): its
//! estimate is the difference itself, and with a body of true geometry at least the geometry's
//! share of the shear's estimate (src/adapt/geometry_share.rs: in a conformal bore the
//! creepage's error changes sign under refinement and a grid and its bisection agree by chance). The effectivity (estimate over true error) is measured
//! against Carter's and Hertz's solutions in tests/validation and docs/validation.md: over the
//! matrix of examples/effectivity_matrix.rs (Q/μP 0.05 to 0.99, braking, rolling in −x,
//! creepage control, μ 0.02 and 0.8, continuous elements, extents 1.05 and 3, Hertz; tolerances
//! 1e-3 to 1e-5) the pressure's lies within 0.69–3.94, the shear's within 0.36–3.34 and the
//! creepage's within 0.78–2.05 but for one 24.75 (Q/μP 0.99 at 1e-5, where the creepage's true
//! error, 6.8e-9, nearly cancels); every true error meets the tolerance. The values above 3 are
//! over-estimates of errors well below the tolerance. The spread is that of the observed order
//! under bisection (about 1 to 3.5 for the shear), which fixed factors cannot follow.
//!
//! The estimate is one implementation, [`BisectionEstimator`], of [`ErrorEstimator`]: the
//! driver decides convergence and marks elements from its [`Comparison`] alone.
//!
//! The norm is that of every accuracy figure of rollbem ([`crate::post::norms`]): the RMS over
//! the contact of nodal errors, each node weighted by the length it stands for (half the
//! distance to each neighbour), p in units of the Hertz peak pressure p0, q in units of μp0.

use crate::contact::residual::State;
use crate::grid::ContactGrid;
use crate::post::adaptation::ErrorEstimate;
use crate::post::norms::node_lengths;

/// The shear's estimate is this factor times the RMS difference of the two solutions: the error
/// of the bisected grid's solution when the error falls as h² under bisection, 1/(2² − 1)
/// (module docs). Where square-root points still dominate (first order) it under-estimates by
/// up to 3; where the error falls as h³ it over-estimates by up to 2. On the runs of
/// docs/validation.md its effectivity lies between 0.36 (near complete slip, Q/μP 0.95) and 2.2:
/// the lowest leaves no room for a smaller factor.
pub const SHEAR_ESTIMATE_FACTOR: f64 = 1.0 / 3.0;

/// The pressure's estimate is this factor times the RMS difference: the error of convergence as
/// h^2.3 under bisection, 1/(2^2.3 − 1). With 1/3, the pressure's effectivity on the carter2d
/// and Hertz runs of docs/validation.md had a geometric mean of 1.4 (an observed order near
/// 2.4: e_G/e_H = 1 + d/e_H) and spread over 0.93–3.06; with 1/4 it lies within 0.70–2.3,
/// centred a little on the safe side (0.66 and 0.69 for the BEM rollers and the regime-4 pair).
pub const PRESSURE_ESTIMATE_FACTOR: f64 = 1.0 / 4.0;

/// The relative creepage error is taken of max(|ξ|, this × μa/R*), μa/R* being Carter's
/// creepage at complete slip [-]. A creepage that nearly vanishes — free rolling of similar
/// bodies (round-off), braking in a conformal bore (a small difference of two larger parts) —
/// has no meaningful relative error; below 5 % of μa/R* (|Q| below about 0.1 μP in Carter's
/// theory, ξ ≈ (μa/R*)·Q/(2μP)) the tolerance then bounds its error as a fraction of that.
pub const CREEP_FLOOR: f64 = 0.05;

/// The estimate and where the error sits.
#[derive(Debug, Clone)]
pub struct Comparison {
    /// The estimated errors of the bisected grid's solution.
    pub estimate: ErrorEstimate,
    /// Local indicator of each coarse element: how far the bisected grid's solution over the
    /// element departs from one polynomial of the element's degree (least squares through its
    /// nodes there), as a share of the squared RMS over the contact [-]. It sees the
    /// square-root points and not the smooth error spread from them, which refining them
    /// removes (the refinement marks by it; the estimate counts both).
    pub detail: Vec<f64>,
    /// Whether every node of the bisected grid in each coarse element is open (p = 0).
    pub open: Vec<bool>,
}

/// The scales of the errors: p0 [stress] and μ [-].
#[derive(Debug, Clone, Copy)]
pub struct Scales {
    /// Hertz peak pressure p0 [stress].
    pub peak_pressure: f64,
    /// Coulomb friction coefficient μ.
    pub friction: f64,
    /// Whether the creepage is prescribed (then it has no error; nor without friction, where it
    /// is not determined by the tractions).
    pub creep_prescribed: bool,
    /// Carter's complete-slip creepage μa/R* [-]: the creepage a shear error of μp0 over the
    /// contact moves, the unit of the creepage's estimate from the shear's, and of its floor.
    pub complete_slip_creep: f64,
    /// The share of the creepage the bodies' true geometry sets, w ∈ [0, 1]
    /// (src/adapt/geometry_share.rs): the creepage's estimate is at least w times the shear's
    /// estimate times μa/R*, relative; 0 for half-plane models.
    pub geometry_share: f64,
}

impl Scales {
    /// The smallest creepage the relative creepage error is taken of [-]: [`CREEP_FLOOR`] times
    /// Carter's complete-slip creepage μa/R*.
    pub fn creep_floor(&self) -> f64 {
        CREEP_FLOOR * self.complete_slip_creep
    }
}

/// The two solutions of one pass that an estimator compares: a grid's and its bisection's.
#[derive(Debug, Clone, Copy)]
pub struct Pass<'a> {
    /// The pass's grid G.
    pub coarse_grid: &'a ContactGrid,
    /// The solution on G.
    pub coarse: &'a State,
    /// G with every element halved, H.
    pub fine_grid: &'a ContactGrid,
    /// The solution on H, the one whose error is estimated.
    pub fine: &'a State,
    /// Where H's tractions have square-root points [length]: the contact edges, the ends of the
    /// stick zones and the slip reversals (the driver marks by them too; [`BisectionEstimator`]
    /// does not read them, an estimator that treats those elements apart may).
    pub singular: &'a [f64],
    /// The units of the errors.
    pub scales: Scales,
}

/// An a-posteriori error estimator: from one pass's two solutions, the estimated errors of the
/// bisected grid's solution and the local indicators the refinement marks by. The driver
/// ([`crate::adapt::solve_with`]) reads nothing else of the solutions to decide whether the
/// tolerance is met or which elements to refine, so another estimator can take this one's place.
/// It is called once per pass, in the order of the passes (an estimator may keep what earlier
/// passes showed).
pub trait ErrorEstimator {
    /// The estimate and indicators of the pass (the fields of [`Comparison`]: `detail` and `open`
    /// one per element of `pass.coarse_grid`).
    fn estimate(&mut self, pass: &Pass<'_>) -> Comparison;
}

/// The estimator of the module docs: the RMS difference of the two solutions times
/// [`PRESSURE_ESTIMATE_FACTOR`] and [`SHEAR_ESTIMATE_FACTOR`], the creepage's difference itself,
/// and the polynomial-fit indicators ([`compare`]).
#[derive(Debug, Clone, Copy, Default)]
pub struct BisectionEstimator;

impl ErrorEstimator for BisectionEstimator {
    fn estimate(&mut self, pass: &Pass<'_>) -> Comparison {
        compare(pass.coarse_grid, pass.coarse, pass.fine_grid, pass.fine, pass.scales)
    }
}

/// Compares the solution `coarse` on `coarse_grid` with `fine` on its bisection `fine_grid`
/// (module docs).
pub fn compare(
    coarse_grid: &ContactGrid,
    coarse: &State,
    fine_grid: &ContactGrid,
    fine: &State,
    scales: Scales,
) -> Comparison {
    assert_eq!(
        fine_grid.n_elements(),
        2 * coarse_grid.n_elements(),
        "the fine grid bisects the coarse one"
    );
    let x = &fine_grid.nodes;
    let w = node_lengths(x);
    let shear_scale = scales.friction * scales.peak_pressure;
    let scaled = |v: f64, scale: f64| if scale > 0.0 { v / scale } else { 0.0 };
    let dp: Vec<f64> = (0..x.len())
        .map(|i| {
            scaled(
                fine.pressure[i] - coarse_grid.interpolate(&coarse.pressure, x[i]),
                scales.peak_pressure,
            )
        })
        .collect();
    let dq: Vec<f64> = (0..x.len())
        .map(|i| {
            scaled(
                fine.shear[i] - coarse_grid.interpolate(&coarse.shear, x[i]),
                shear_scale,
            )
        })
        .collect();
    // The contact: from the first to the last loaded node of the fine solution.
    let loaded = |i: &usize| fine.pressure[*i] > 0.0;
    let first = (0..x.len()).find(loaded);
    let last = (0..x.len()).rev().find(loaded);
    let in_contact = |i: usize| matches!((first, last), (Some(a), Some(b)) if (a..=b).contains(&i));
    let contact_length: f64 = (0..x.len()).filter(|&i| in_contact(i)).map(|i| w[i]).sum();
    let rms = |d: &[f64]| {
        if contact_length > 0.0 {
            let sum: f64 = (0..x.len())
                .filter(|&i| in_contact(i))
                .map(|i| w[i] * d[i] * d[i])
                .sum();
            (sum / contact_length).sqrt()
        } else {
            0.0
        }
    };
    let n_coarse = coarse_grid.n_elements();
    let kind = fine_grid.kind;
    // A coarse element is open when every node of its two halves is.
    let open: Vec<bool> = (0..n_coarse)
        .map(|e| {
            (2 * e..2 * e + 2)
                .flat_map(|ef| (0..kind.nodes_per_element()).map(move |a| (ef, a)))
                .all(|(ef, a)| fine.pressure[fine_grid.global_node(ef, a)] <= 0.0)
        })
        .collect();
    let fields = [
        fine.pressure
            .iter()
            .map(|v| scaled(*v, scales.peak_pressure))
            .collect::<Vec<_>>(),
        fine.shear.iter().map(|v| scaled(*v, shear_scale)).collect::<Vec<_>>(),
    ];
    let detail = (0..n_coarse)
        .map(|e| {
            if contact_length <= 0.0 {
                return 0.0;
            }
            // Every node of the element's two halves, when one is in the contact: a contact
            // edge inside the element shows as the kink between loaded and open nodes.
            let nodes: Vec<usize> = (0..2)
                .flat_map(|c| (0..kind.nodes_per_element()).map(move |a| (2 * e + c, a)))
                .map(|(ef, a)| fine_grid.global_node(ef, a))
                .collect();
            if !nodes.iter().any(|&i| in_contact(i)) {
                return 0.0;
            }
            let t: Vec<f64> = nodes.iter().map(|&i| x[i]).collect();
            let weights: Vec<f64> = nodes.iter().map(|&i| w[i]).collect();
            fields
                .iter()
                .map(|v| {
                    let values: Vec<f64> = nodes.iter().map(|&i| v[i]).collect();
                    fit_residual(&t, &values, &weights, kind.nodes_per_element() - 1)
                })
                .sum::<f64>()
                / contact_length
        })
        .collect();
    let shear_rms = SHEAR_ESTIMATE_FACTOR * rms(&dq);
    Comparison {
        estimate: ErrorEstimate {
            pressure_rms: PRESSURE_ESTIMATE_FACTOR * rms(&dp),
            shear_rms,
            creep_rel: creep_estimate(coarse.creep, fine.creep, shear_rms, scales),
            // Set by the driver, which knows the controls and the bodies (`super::overlap`).
            overlap_rel: None,
            body_mesh: None,
        },
        detail,
        open,
    }
}

/// The relative creepage error of the bisected grid's solution: the difference of the two
/// grids' creepages `coarse` and `fine` [-], and at least the geometry's share of the shear's
/// estimate `shear_rms` [μp0] times μa/R* (src/adapt/geometry_share.rs), each relative to
/// max(|ξ|, the floor). Zero with a prescribed creepage, and without friction, where the
/// creepage does not act on the tractions.
fn creep_estimate(coarse: f64, fine: f64, shear_rms: f64, scales: Scales) -> f64 {
    if scales.creep_prescribed || scales.friction == 0.0 {
        return 0.0;
    }
    let of = fine.abs().max(scales.creep_floor()).max(f64::MIN_POSITIVE);
    let bisection = if fine == coarse {
        0.0
    } else {
        (fine - coarse).abs() / of
    };
    let geometry = scales.geometry_share * shear_rms * scales.complete_slip_creep / of;
    bisection.max(geometry)
}

/// Σ w_k r_k² of the weighted least-squares fit of a polynomial of `degree` to (t_k, v_k):
/// zero when the values lie on such a polynomial (and when there are no more points than
/// coefficients).
fn fit_residual(t: &[f64], v: &[f64], w: &[f64], degree: usize) -> f64 {
    let n = degree + 1;
    if t.len() <= n {
        return 0.0;
    }
    // Centred and scaled abscissae keep the normal equations well conditioned.
    let (lo, hi) = (t[0], t[t.len() - 1]);
    let (c, h) = (0.5 * (lo + hi), 0.5 * (hi - lo).max(f64::MIN_POSITIVE));
    let basis = |tk: f64| -> Vec<f64> { (0..n).map(|j| ((tk - c) / h).powi(j as i32)).collect() };
    let mut a = faer::Mat::<f64>::zeros(n, n);
    let mut b = faer::Mat::<f64>::zeros(n, 1);
    for k in 0..t.len() {
        let phi = basis(t[k]);
        for i in 0..n {
            b[(i, 0)] += w[k] * phi[i] * v[k];
            for j in 0..n {
                a[(i, j)] += w[k] * phi[i] * phi[j];
            }
        }
    }
    faer::linalg::solvers::Solve::solve_in_place(&a.partial_piv_lu(), b.as_mut());
    let coef = b;
    if (0..n).any(|j| !coef[(j, 0)].is_finite()) {
        return 0.0;
    }
    t.iter()
        .zip(v)
        .zip(w)
        .map(|((&tk, &vk), &wk)| {
            let fit: f64 = basis(tk).iter().enumerate().map(|(j, p)| p * coef[(j, 0)]).sum();
            wk * (vk - fit).powi(2)
        })
        .sum()
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::grid::ElementKind;

    fn state_of(grid: &ContactGrid, p: impl Fn(f64) -> f64, q: impl Fn(f64) -> f64, creep: f64) -> State {
        let m = grid.n_nodes();
        State {
            gap: vec![0.0; m],
            slip: vec![0.0; m],
            pressure: grid.nodes.iter().map(|&x| p(x)).collect(),
            shear: grid.nodes.iter().map(|&x| q(x)).collect(),
            overlap: 0.0,
            creep,
        }
    }

    #[test]
    fn fields_the_coarse_elements_reproduce_give_a_zero_estimate() {
        // A quadratic pressure is what both grids represent exactly.
        let coarse = ContactGrid::uniform(ElementKind::DiscontinuousQuadratic, 5, -1.5, 1.5);
        let fine = ContactGrid::uniform(ElementKind::DiscontinuousQuadratic, 10, -1.5, 1.5);
        let p = |x: f64| 2.0 - x * x;
        let c = compare(
            &coarse,
            &state_of(&coarse, p, |x| 0.1 * p(x), 1e-3),
            &fine,
            &state_of(&fine, p, |x| 0.1 * p(x), 1e-3),
            Scales {
                peak_pressure: 2.0,
                friction: 0.2,
                creep_prescribed: false,
                complete_slip_creep: 0.0,
                geometry_share: 0.0,
            },
        );
        assert!(c.estimate.largest() < 1e-14, "{:?}", c.estimate);
        assert!(c.detail.iter().all(|d| *d < 1e-26), "{:?}", c.detail);
    }

    #[test]
    fn the_local_indicator_singles_out_the_element_with_a_square_root_edge() {
        let coarse = ContactGrid::uniform(ElementKind::DiscontinuousQuadratic, 6, -1.2, 1.2);
        let fine = ContactGrid::uniform(ElementKind::DiscontinuousQuadratic, 12, -1.2, 1.2);
        // Hertz's pressure: square-root edges at ±1, in coarse elements 0 and 5.
        let p = |x: f64| (1.0 - x * x).max(0.0).sqrt();
        let c = compare(
            &coarse,
            &state_of(&coarse, p, |_| 0.0, 0.0),
            &fine,
            &state_of(&fine, p, |_| 0.0, 0.0),
            Scales {
                peak_pressure: 1.0,
                friction: 0.2,
                creep_prescribed: true,
                complete_slip_creep: 0.0,
                geometry_share: 0.0,
            },
        );
        let edge = c.detail[0].max(c.detail[5]);
        for e in 1..5 {
            assert!(c.detail[e] < 0.1 * edge, "{:?}", c.detail);
        }
    }

    #[test]
    fn a_known_difference_gives_its_weighted_rms() {
        let coarse = ContactGrid::uniform(ElementKind::DiscontinuousQuadratic, 5, -1.5, 1.5);
        let fine = ContactGrid::uniform(ElementKind::DiscontinuousQuadratic, 10, -1.5, 1.5);
        // The fine pressure is the coarse one plus 0.01 everywhere (every fine node loaded):
        // the RMS difference is 0.01/p0 = 0.005.
        let c = compare(
            &coarse,
            &state_of(&coarse, |_| 1.0, |_| 0.0, 1e-3),
            &fine,
            &state_of(&fine, |_| 1.01, |_| 0.0, 1.1e-3),
            Scales {
                peak_pressure: 2.0,
                friction: 0.2,
                creep_prescribed: false,
                complete_slip_creep: 0.0,
                geometry_share: 0.0,
            },
        );
        assert_eq!(c.estimate.shear_rms, 0.0);
        assert!((c.estimate.creep_rel - 0.1 / 1.1).abs() < 1e-12);
        // The estimate is the difference times the pressure's factor.
        assert!((c.estimate.pressure_rms - PRESSURE_ESTIMATE_FACTOR * 0.005).abs() < 1e-12);
        assert!(c.open.iter().all(|o| !o));
    }

    /// A creepage below the floor (free rolling of similar bodies leaves round-off) has its
    /// difference measured against the floor, not against itself; above it, relatively.
    #[test]
    fn a_vanishing_creepage_is_measured_against_the_floor() {
        let coarse = ContactGrid::uniform(ElementKind::DiscontinuousQuadratic, 5, -1.5, 1.5);
        let fine = ContactGrid::uniform(ElementKind::DiscontinuousQuadratic, 10, -1.5, 1.5);
        let scales = Scales {
            peak_pressure: 2.0,
            friction: 0.2,
            creep_prescribed: false,
            complete_slip_creep: 2e-3,
            geometry_share: 0.0,
        };
        let creep_error = |xi_coarse: f64, xi_fine: f64| {
            compare(
                &coarse,
                &state_of(&coarse, |_| 1.0, |_| 0.0, xi_coarse),
                &fine,
                &state_of(&fine, |_| 1.0, |_| 0.0, xi_fine),
                scales,
            )
            .estimate
            .creep_rel
        };
        // Round-off creepages: their relative difference would be 2; against the floor, 3e-13.
        assert!((creep_error(1e-17, -2e-17) - 3e-13).abs() < 1e-25);
        // Above the floor the error stays relative.
        assert!((creep_error(1.1e-3, 1e-3) - 0.1).abs() < 1e-12);
    }

    /// With a share w of true geometry, the creepage's estimate is at least w·e_q·μa/R* over
    /// max(|ξ|, floor), whichever grids' creepages agree; the larger of the two otherwise.
    #[test]
    fn the_geometry_s_share_bounds_the_creepage_estimate_from_below() {
        let scales = Scales {
            peak_pressure: 1.0,
            friction: 0.2,
            creep_prescribed: false,
            complete_slip_creep: 2e-3,
            geometry_share: 0.5,
        };
        // Two grids that agree: the geometry's term alone, 0.5·1e-3·2e-3/1e-3.
        assert!((creep_estimate(1e-3, 1e-3, 1e-3, scales) - 1e-3).abs() < 1e-15);
        // A difference above it: the difference.
        assert!((creep_estimate(1.1e-3, 1e-3, 1e-3, scales) - 0.1).abs() < 1e-12);
        // Half-planes (w = 0) and a prescribed creepage: as before.
        let half_planes = Scales {
            geometry_share: 0.0,
            ..scales
        };
        assert_eq!(creep_estimate(1e-3, 1e-3, 1e-3, half_planes), 0.0);
        let prescribed = Scales {
            creep_prescribed: true,
            ..scales
        };
        assert_eq!(creep_estimate(1.1e-3, 1e-3, 1e-3, prescribed), 0.0);
    }
}
