//! Strength through a run (`output.strength`, src/post/strength) against McEwen's closed-form
//! stresses (examples/strength_report.rs, which evaluates them independently of the body
//! models): cases/hertz.yaml with k = p0, frictionless and sliding at μ = 0.1 … 0.5, the
//! literature values (Johnson, *Contact Mechanics*, 1985, §4.2, §9.4, Fig. 9.12), the
//! convergence with the interior grid, and each body's own factors in partial slip.

use crate::strength_report::{hertz_run, sliding_rows, P0};
use rollbem::post::strength::Criterion;

/// Relative difference.
fn rel(a: f64, b: f64) -> f64 {
    (a / b - 1.0).abs()
}

/// Every row of docs/strength.md's sliding table within its bound. Subsurface limits: the
/// interior grid (0.02a apart at the critical depths) and the error-controlled contact grid
/// (1e-4) leave 1.3e-4 (measured); bound 3e-4. Surface limits: the stick zone of steady
/// rolling at Q/μP = 0.999999 (2c = 0.002a) perturbs the surface tractions by O(c/a) = 1e-3
/// of μp0 against full sliding (measured 0.95e-3, Tresca μ = 0.5, where τ_eq = μp0 along the
/// whole contact); bound 1.5e-3. Body B, which carries the opposite shear, mirrors A.
#[test]
fn sliding_limits_match_mcewen() {
    for r in sliding_rows() {
        let surface = r.where_.map(|w| w == "surface");
        for k in 0..2 {
            let bound = if surface[k] { 1.5e-3 } else { 3e-4 };
            let what = ["first yield", "shakedown"][k];
            let e = rel(r.run[k], r.closed_form[k]);
            assert!(
                e <= bound,
                "{} μ {}: {what} {} against {}: {e:.1e}",
                r.criterion.name(),
                r.mu,
                r.run[k],
                r.closed_form[k]
            );
            assert!(
                rel(r.run_b[k], r.run[k]) <= 2e-3,
                "B mirrors A: {:?} {:?}",
                r.run_b,
                r.run
            );
        }
        // Johnson's map: subsurface limits up to μ = 0.3, the surface above.
        assert_eq!(r.where_[1] == "surface", r.mu >= 0.4, "shakedown mode at μ {}", r.mu);
        if r.criterion == Criterion::Tresca && r.mu >= 0.4 {
            assert!(
                (r.run[1] * r.mu - 1.0).abs() < 2e-3,
                "surface branch 1/μ at μ {}: {}",
                r.mu,
                r.run[1]
            );
        }
        if r.mu == 0.0 {
            // Tresca p0 = 3.3k (τ1max = 0.300 p0), von Mises p0 = 1.79Y = 3.10k, both 4.0k.
            let first = if r.criterion == Criterion::Tresca {
                1.0 / 0.300
            } else {
                1.79 * 3f64.sqrt()
            };
            assert!(rel(r.run[0], first) < 3e-3, "{} {}", r.criterion.name(), r.run[0]);
            assert!(rel(r.run[1], 4.0) < 3e-4, "{} {}", r.criterion.name(), r.run[1]);
        }
    }
}

/// The frictionless shakedown limit converges with the interior grid on an error-controlled
/// contact grid (1e-5): |4.0 − λ_sd| shrinks as the rows and columns double (the rows' maxima
/// of |τxz| near x = ±0.87a, z = 0.5a are sampled): 8.1e-3, 1.2e-3, 2.2e-4 on the default
/// grid, 1.9e-5 on [401, 200] (measured); bounds 5e-4 and 5e-5 on the last two.
#[test]
fn the_shakedown_limit_converges_with_the_interior_grid() {
    let err = |grid: &str| {
        let s = hertz_run(
            0.0,
            Criterion::VonMises,
            &[
                &format!("output.strength.grid={grid}"),
                "output.strength.bodies=[A]",
                "contact.grid.tolerance=1e-5",
            ],
        );
        (s[0].shakedown.factor - 4.0).abs()
    };
    let e = [err("[51, 25]"), err("[101, 50]"), err("[201, 100]"), err("[401, 200]")];
    assert!(
        e[0] > e[1] && e[1] > e[2] && e[2] > e[3] && e[2] < 5e-4 && e[3] < 5e-5,
        "{e:?}"
    );
}

/// Carter's surface stresses on body A at Q/μP = `ratio`, p0 = a = 1 (Johnson 1985 §8.2):
/// q = μp in the slip zone, q = μp − μ(c/a)√(1 − ((x − d)/c)²) in the stick zone [a − 2c, a]
/// (c/a = √(1 − Q/μP), d = a − c, rolling towards +x), and σx = −p − (2/π) PV∫ q/(x − s) ds =
/// −p − 2μx + 2μ(c/a) g((x − d)/c) with g(u) = u inside |u| ≤ 1, u − sgn(u)√(u² − 1) outside;
/// σz = −p, τxz = −q. `sign` −1 gives body B, which carries the opposite shear.
fn carter_surface(x: f64, mu: f64, ratio: f64, sign: f64) -> rollbem::interior::PlaneStress {
    let c = (1.0 - ratio).sqrt();
    let d = 1.0 - c;
    let p = (1.0 - x * x).max(0.0).sqrt();
    let u = (x - d) / c;
    let stick = if u.abs() <= 1.0 { c * (1.0 - u * u).sqrt() } else { 0.0 };
    let g = if u.abs() <= 1.0 {
        u
    } else {
        u - u.signum() * (u * u - 1.0).sqrt()
    };
    let q = sign * mu * (p - stick);
    let sxx = -p - sign * 2.0 * mu * (x - c * g);
    rollbem::interior::PlaneStress {
        sxx,
        szz: -p,
        txz: -q,
        syy: 0.3 * (sxx - p),
    }
}

/// The surface maximum of Carter's partial slip sits on the square-root cusp of σx at the
/// stick–slip point x = a − 2c: the run locates it (a surface row ten times finer than the
/// interior rows, then refined) and its first-yield factor converges to the closed form's
/// maximum over the surface (sampled every 1e-5 a with the cusp itself among the points).
/// What limits it is the contact grid's traction at the cusp: the error falls like √h, from
/// 3.2 % (A) on the shipped 21 elements to 1.6 % on 81 and 0.48 % at `contact.grid.tolerance`
/// 1e-4, which refines there, to 0.016 % at 1e-6 (measured); bounds 4 %, 2 %, 0.6 %, 0.05 %.
/// The run under-reads the stress (its factor is high), so docs/strength.md and the run's
/// notice ask for an error-controlled grid where the surface governs in partial slip.
#[test]
fn the_partial_slip_cusp_is_located() {
    let (mu, ratio): (f64, f64) = (0.3, 0.9);
    let cusp = 1.0 - 2.0 * (1.0 - ratio).sqrt();
    let closed_form = |sign: f64| {
        let mut xs: Vec<f64> = (0..=200_000).map(|i| -1.0 + 1e-5 * i as f64).collect();
        xs.push(cusp);
        let worst = xs
            .iter()
            .map(|&x| Criterion::VonMises.equivalent_shear(&carter_surface(x, mu, ratio, sign)))
            .fold(0.0, f64::max);
        1.0 / worst
    };
    let run = |extra: &str| {
        let o = [
            format!("materials.steel.yield.shear={P0}"),
            "output.strength.criterion=von_mises".to_string(),
            format!("contact.friction={mu}"),
            format!("load.tangential.ratio={ratio}"),
            "output.interior=null".to_string(),
            extra.to_string(),
        ];
        crate::common::solve("hertz", &o.iter().map(String::as_str).collect::<Vec<_>>()).strength
    };
    let (a, b) = (closed_form(1.0), closed_form(-1.0));
    let grids = [
        ("contact.grid.elements=21", 4e-2),
        ("contact.grid.elements=81", 2e-2),
        ("contact.grid.tolerance=1e-4", 6e-3),
        ("contact.grid.tolerance=1e-6", 5e-4),
    ];
    for (extra, bound) in grids {
        let s = run(extra);
        let (ea, eb) = (rel(s[0].first_yield.factor, a), rel(s[1].first_yield.factor, b));
        assert!(ea < bound && eb < bound, "{extra}: A {ea:.1e}, B {eb:.1e}");
        assert!(
            s[0].first_yield.factor >= a * (1.0 - 1e-4),
            "{extra}: the cusp is under-read, not over-read"
        );
        assert!(
            (s[0].first_yield.x - cusp).abs() < 5e-3,
            "{extra}: A yields at the cusp"
        );
    }
}

/// In partial slip the two bodies of an identical pair carry opposite shear on a traction that
/// is not symmetric about the centre, so their fields and factors differ; both lie below the
/// frictionless limits.
#[test]
fn each_body_has_its_own_factors_in_partial_slip() {
    let o = [
        format!("materials.steel.yield.shear={P0}"),
        "output.strength.criterion=von_mises".to_string(),
        "contact.friction=0.3".to_string(),
        "load.tangential.ratio=0.6".to_string(),
        "output.interior=null".to_string(),
    ];
    let s = crate::common::solve("hertz", &o.iter().map(String::as_str).collect::<Vec<_>>()).strength;
    let frictionless = hertz_run(0.0, Criterion::VonMises, &[]);
    assert!(rel(s[0].first_yield.factor, s[1].first_yield.factor) > 1e-3, "{s:?}");
    for b in &s {
        assert!(b.first_yield.factor < frictionless[0].first_yield.factor, "{b:?}");
        assert!(b.shakedown.factor < frictionless[0].shakedown.factor, "{b:?}");
    }
}
