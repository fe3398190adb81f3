//! Strength through a run (`output.strength`) against McEwen's closed-form stresses of a Hertz
//! line contact under q = μp (Johnson, *Contact Mechanics*, 1985, §7.1 eq. 7.23–7.26), evaluated
//! here independently of the body models, and the strength of Carter's partial slip on the
//! half-space and on the true geometry (BEM rollers on shafts).
//!
//! Prints the tables of docs/strength.md; tests/docs compares the two and
//! tests/validation/strength.rs checks the bounds.
//!
//! Run: cargo run --release --example strength_report

mod common;

use common::{solve, Table};
use rollbem::interior::PlaneStress;
use rollbem::post::strength::assess::BodyStrength;
use rollbem::post::strength::{shakedown, Criterion};

/// Hertz p0 of cases/hertz.yaml [N/mm²]: the shear yield stress of the runs, so that their
/// factors read as Johnson's p0/k.
pub const P0: f64 = 1153.846154;
const NU: f64 = 0.3;

/// The friction coefficients of the full-sliding table.
pub const FRICTIONS: [f64; 6] = [0.0, 0.1, 0.2, 0.3, 0.4, 0.5];

/// McEwen's stresses under p0 = 1, a = 1 and q = μp at (x, z), z ≥ 0 into the body.
pub fn mcewen(x: f64, z: f64, mu: f64) -> PlaneStress {
    let b = 1.0 - x * x + z * z;
    let r = (b * b + 4.0 * x * x * z * z).sqrt();
    let m = (0.5 * (r + b)).max(0.0).sqrt();
    let n = (0.5 * (r - b)).max(0.0).sqrt().copysign(x);
    // At the contact's edges on the surface m = n = 0: the ratios' limit there is 0.
    let d = (m * m + n * n).max(1e-300);
    let sx = -(m * (1.0 + (z * z + n * n) / d) - 2.0 * z) + mu * (n * (2.0 - (z * z - m * m) / d) - 2.0 * x);
    let sz = -m * (1.0 - (z * z + n * n) / d) - mu * n * (m * m - z * z) / d;
    let t = -n * (m * m - z * z) / d - mu * (m * (1.0 + (z * z + n * n) / d) - 2.0 * z);
    PlaneStress {
        sxx: sx,
        szz: sz,
        txz: t,
        syy: NU * (sx + sz),
    }
}

/// The closed form's first-yield factor p0/k: 1 / max τ_eq sampled every 0.0025a over
/// x ∈ [−1.5a, 1.5a], z ∈ [0, 1.2a] (the grid holds x = ±a and z = 0, where the surface
/// maxima of high friction sit).
pub fn closed_form_first_yield(mu: f64, c: Criterion) -> f64 {
    let mut worst = 0.0f64;
    for i in 0..=1200 {
        for j in 0..=480 {
            let (x, z) = (-1.5 + 0.0025 * i as f64, 0.0025 * j as f64);
            worst = worst.max(c.equivalent_shear(&mcewen(x, z, mu)));
        }
    }
    1.0 / worst
}

/// The closed form's shakedown factor p0/k over rows every 0.01a from the surface to 1.2a,
/// x ∈ [−4a, 4a] every 0.005a (Melan's row search of src/post/strength, itself checked
/// against the literature values 4.0 and 1/μ in its unit tests).
pub fn closed_form_shakedown(mu: f64, c: Criterion) -> f64 {
    let rows: Vec<(f64, Vec<PlaneStress>)> = (0..=120)
        .map(|j| {
            let z = 0.01 * j as f64;
            (z, (0..=1600).map(|i| mcewen(-4.0 + 0.005 * i as f64, z, mu)).collect())
        })
        .collect();
    shakedown(&rows, 1.0, c).expect("stressed").factor
}

/// cases/hertz.yaml with k = p0 under `criterion`, sliding at friction μ or frictionless at
/// μ = 0, with `extra` overrides. Steady rolling needs |Q| < μP: Q/μP = 0.999999 leaves a stick
/// zone of 2c = 0.002a (Carter's c/a = √(1 − Q/μP)), whose traction differs from μp by
/// O(c/a) μp0 (at Q/μP = 0.9999 the Tresca factors at μ = 0.5, where τ_eq = μp0 all along the
/// contact, are 1 % lower; at 0.99999, 0.33 %; at 0.999999, 0.1 %).
pub fn hertz_run(mu: f64, c: Criterion, extra: &[&str]) -> Vec<BodyStrength> {
    let ratio = if mu == 0.0 { 0.0 } else { 0.999_999 };
    let mut o = vec![
        format!("materials.steel.yield.shear={P0}"),
        format!("output.strength.criterion={}", c.name()),
        format!("contact.friction={}", mu.max(0.1)),
        format!("load.tangential.ratio={ratio}"),
        "output.interior=null".to_string(),
    ];
    o.extend(extra.iter().map(|s| s.to_string()));
    solve("hertz", &o).strength
}

/// The error-controlled grid of the full-sliding runs: the contact edges, where the surface
/// stresses have their cusps, are refined.
pub const SLIDING_GRID: &str = "contact.grid.tolerance=1e-4";

/// One row of the full-sliding table: (criterion, μ, closed-form and run factors).
pub struct SlidingRow {
    /// The criterion.
    pub criterion: Criterion,
    /// Friction coefficient.
    pub mu: f64,
    /// Closed-form first yield and shakedown p0/k.
    pub closed_form: [f64; 2],
    /// The run's, body A.
    pub run: [f64; 2],
    /// The run's, body B.
    pub run_b: [f64; 2],
    /// The run's first-yield site and shakedown mode.
    pub where_: [&'static str; 2],
}

/// Every (criterion, μ) of the full-sliding table.
pub fn sliding_rows() -> Vec<SlidingRow> {
    let mut out = Vec::new();
    for criterion in [Criterion::Tresca, Criterion::VonMises] {
        for mu in FRICTIONS {
            let s = hertz_run(mu, criterion, &[SLIDING_GRID]);
            out.push(SlidingRow {
                criterion,
                mu,
                closed_form: [
                    closed_form_first_yield(mu, criterion),
                    closed_form_shakedown(mu, criterion),
                ],
                run: [s[0].first_yield.factor, s[0].shakedown.factor],
                run_b: [s[1].first_yield.factor, s[1].shakedown.factor],
                where_: [s[0].first_yield_site.name(), s[0].shakedown.mode.name()],
            });
        }
    }
    out
}

/// docs/strength.md, "Hertz contact under sliding": the rows as a table.
pub fn sliding_table(rows: &[SlidingRow]) -> Table {
    let mut t = Table::new(&[
        "criterion",
        "μ",
        "first yield p0/k, McEwen",
        "rollbem",
        "site",
        "shakedown p0/k, McEwen",
        "rollbem ",
        "mode",
    ]);
    for r in rows {
        t.push(vec![
            r.criterion.name().to_string(),
            format!("{:.1}", r.mu),
            format!("{:.4}", r.closed_form[0]),
            format!("{:.4}", r.run[0]),
            r.where_[0].to_string(),
            format!("{:.4}", r.closed_form[1]),
            format!("{:.4}", r.run[1]),
            r.where_[1].to_string(),
        ]);
    }
    t
}

/// The partial-slip scenes: Q/μP at μ = 0.3.
pub const RATIOS: [f64; 3] = [0.3, 0.6, 0.9];

/// The yield stresses of the fig14 scene's materials [N/mm²]: aluminium alloy k = 170
/// (Y ≈ 295), bearing steel k = 900 (Y ≈ 1560).
const FIG14_YIELD: [&str; 2] = [
    "materials.aluminium.yield.shear=170",
    "materials.steel_bj.yield.shear=900",
];

/// One scene of Carter's partial slip on the fig14 rollers: each body's factors on the
/// half-space and on the true geometry.
pub fn partial_slip(case: &str, ratio: f64) -> Vec<BodyStrength> {
    let o = [
        FIG14_YIELD[0].to_string(),
        FIG14_YIELD[1].to_string(),
        "contact.friction=0.3".to_string(),
        format!("load.tangential.ratio={ratio}"),
        "output.strength.criterion=von_mises".to_string(),
    ];
    solve(case, &o).strength
}

/// docs/strength.md, "Carter's partial slip": fig14_half_space against fig14_true_geometry.
pub fn partial_slip_table() -> Table {
    let mut t = Table::new(&[
        "Q/μP",
        "body",
        "first yield, half-space",
        "true geometry",
        "shakedown, half-space",
        "true geometry ",
    ]);
    for ratio in RATIOS {
        let (h, b) = (
            partial_slip("fig14_half_space", ratio),
            partial_slip("fig14_true_geometry", ratio),
        );
        for (x, y) in h.iter().zip(&b) {
            let f = |s: &BodyStrength| format!("{:.3} ({})", s.first_yield.factor, s.first_yield_site.name());
            let g = |s: &BodyStrength| format!("{:.3} ({})", s.shakedown.factor, s.shakedown.mode.name());
            t.push(vec![format!("{ratio:.1}"), x.body.clone(), f(x), f(y), g(x), g(y)]);
        }
    }
    t
}

/// docs/strength.md, "Tresca: in-plane or three principal stresses": the closed form's
/// first-yield p0/k with the in-plane principal shear τ1 alone and with all three principal
/// stresses (σy = ν(σx + σz) out of plane), and where each maximum lies.
pub fn tresca_table() -> Table {
    let mut t = Table::new(&[
        "μ",
        "p0/k, in-plane τ1",
        "at (x/a, z/a)",
        "p0/k, three principal",
        "at (x/a, z/a) ",
    ]);
    for mu in [0.0, 0.2, 0.25, 0.3, 0.4, 0.5] {
        let worst = |f: &dyn Fn(&PlaneStress) -> f64| {
            let mut best = (0.0f64, 0.0, 0.0);
            for i in 0..=1200 {
                for j in 0..=480 {
                    let (x, z) = (-1.5 + 0.0025 * i as f64, 0.0025 * j as f64);
                    let v = f(&mcewen(x, z, mu));
                    if v > best.0 {
                        best = (v, x, z);
                    }
                }
            }
            best
        };
        let (a, b) = (
            worst(&|s| s.max_shear()),
            worst(&|s| Criterion::Tresca.equivalent_shear(s)),
        );
        t.push(vec![
            format!("{mu:.2}"),
            format!("{:.4}", 1.0 / a.0),
            format!("({:.3}, {:.3})", a.1, a.2),
            format!("{:.4}", 1.0 / b.0),
            format!("({:.3}, {:.3})", b.1, b.2),
        ]);
    }
    t
}

fn main() {
    println!("{}", sliding_table(&sliding_rows()).markdown());
    println!("{}", tresca_table().markdown());
    println!("{}", partial_slip_table().markdown());
}
