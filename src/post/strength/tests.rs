//! Checks against McEwen's closed-form stresses of a Hertz line contact with full sliding
//! traction q = μp (Johnson, *Contact Mechanics*, 1985, §7.1 eq. 7.23–7.26;
//! [`crate::analytic::mcewen`], independent of the interior fields of the body models);
//! literature values from Johnson 1985 §4.2, §9.4, Fig. 9.12, Johnson & Jefferis 1963.

use super::*;

const NU: f64 = 0.3;

/// McEwen's stresses under p0 = 1, a = 1 and q = μp at (x, z), z ≥ 0 into the body.
fn mcewen(x: f64, z: f64, mu: f64) -> PlaneStress {
    crate::analytic::mcewen::sliding_hertz_stress(x, z, mu, NU)
}

/// Points x ∈ [−4a, 4a] (nx) × z ∈ (0, 2a] (nz), and their McEwen stresses.
fn grid(nx: usize, nz: usize, mu: f64, surface: bool) -> (Vec<[f64; 2]>, Rows) {
    let xs: Vec<f64> = (0..nx).map(|i| -4.0 + 8.0 * i as f64 / (nx - 1) as f64).collect();
    let z0 = usize::from(!surface);
    let zs: Vec<f64> = (z0..=nz).map(|j| 2.0 * j as f64 / nz as f64).collect();
    let mut pts = Vec::new();
    let rows = zs
        .iter()
        .map(|&z| {
            let row: Vec<PlaneStress> = xs.iter().map(|&x| mcewen(x, z, mu)).collect();
            pts.extend(xs.iter().map(|&x| [x, z]));
            (z, row)
        })
        .collect();
    (pts, rows)
}

fn flat(rows: &[(f64, Vec<PlaneStress>)]) -> Vec<PlaneStress> {
    rows.iter().flat_map(|r| r.1.iter().copied()).collect()
}

#[test]
fn frictionless_first_yield_matches_johnson() {
    // Tresca p0 = 3.3k (τ1max = 0.300 p0 at z = 0.78a); von Mises p0 = 1.79Y = 3.10k.
    let (pts, rows) = grid(81, 400, 0.0, false);
    let s = flat(&rows);
    let t = first_yield(&pts, &s, 1.0, Criterion::Tresca).unwrap();
    assert!((1.0 / t.factor - 0.300).abs() < 0.001, "{t:?}");
    assert!((t.z - 0.78).abs() < 0.02 && t.x.abs() < 1e-9, "{t:?}");
    let v = first_yield(&pts, &s, 1.0, Criterion::VonMises).unwrap();
    assert!((v.factor - 3.10).abs() < 0.01, "{v:?}");
    assert!((v.factor / 3f64.sqrt() - 1.79).abs() < 0.01, "{v:?}");
}

#[test]
fn frictionless_shakedown_is_four_k() {
    // p0 = 4.0k for both criteria, governed by |τxz|max = 0.250 p0 at z = 0.50a.
    let (_, rows) = grid(401, 40, 0.0, false);
    for c in [Criterion::Tresca, Criterion::VonMises] {
        let sd = shakedown(&rows, 1.0, c).unwrap();
        assert!((sd.factor - 4.0).abs() < 0.02, "{c:?} {}", sd.factor);
        assert!((sd.z - 0.5).abs() < 0.051, "{c:?} {}", sd.z);
        assert_eq!(sd.mode, ShakedownMode::Subsurface);
    }
}

#[test]
fn shakedown_error_shrinks_with_the_x_spacing() {
    // The row z = 0.5a alone: |τxz| peaks at x = ±0.87a; a coarse grid misses the peak.
    let err = |nx: usize| {
        let (_, rows) = grid(nx, 4, 0.0, false);
        let r = rows.iter().find(|r| (r.0 - 0.5).abs() < 1e-12).unwrap();
        (row_shakedown(0.5, &r.1, 1.0, Criterion::VonMises).unwrap().factor - 4.0).abs()
    };
    let (e1, e2) = (err(41), err(401));
    assert!(e2 < 0.01 && e2 <= e1, "{e1} {e2}");
}

#[test]
fn sliding_shakedown_at_the_surface_is_one_over_mu() {
    // Full sliding, μ above ≈ 0.3: the surface governs, p0/k → 1/μ.
    for mu in [0.4, 0.5] {
        let (_, rows) = grid(801, 40, mu, true);
        let sd = shakedown(&rows, 1.0, Criterion::Tresca).unwrap();
        assert_eq!(sd.mode, ShakedownMode::Surface, "μ = {mu}");
        assert!((sd.factor * mu - 1.0).abs() < 0.01, "μ = {mu}: {}", sd.factor);
    }
}

#[test]
fn sliding_first_yield_moves_to_the_surface() {
    let at = |mu: f64| {
        let (pts, rows) = grid(161, 200, mu, true);
        first_yield(&pts, &flat(&rows), 1.0, Criterion::Tresca).unwrap()
    };
    assert!(at(0.1).z > 0.3, "{:?}", at(0.1));
    assert!(at(0.4).z < 1e-12, "{:?}", at(0.4));
}

#[test]
fn the_residual_keeps_the_rows_within_yield() {
    // The closed forms of the row search (von Mises' common quadratic, Tresca's mid-range)
    // against the criterion evaluated point by point: λ_sd σ^e + r within yield everywhere,
    // and at yield somewhere in the governing row.
    let (_, rows) = grid(201, 20, 0.2, true);
    for c in [Criterion::VonMises, Criterion::Tresca] {
        let sd = shakedown(&rows, 1.0, c).unwrap();
        let mut worst = 0.0f64;
        for (r, (_, row)) in sd.rows.iter().zip(&rows) {
            for s in row {
                let t = PlaneStress {
                    sxx: sd.factor * s.sxx + r.residual[0],
                    syy: sd.factor * s.syy + r.residual[1],
                    szz: sd.factor * s.szz,
                    txz: sd.factor * s.txz,
                };
                let e = c.equivalent_shear(&t);
                assert!(e <= 1.0 + 1e-9, "{c:?}: {e} z {} {:?} {}", r.z, r.residual, sd.factor);
                worst = worst.max(e);
            }
        }
        assert!(worst > 1.0 - 1e-9, "{c:?}: {worst}");
    }
}
