//! Which body model a scene needs ("model no more than the scene needs").
//!
//! The half-space model is the classical semi-analytic model: exact for massive bodies with
//! a ≪ R, and the cheapest by far. Its error on a user's scene is estimated from measured
//! tables of its error on two families of scenes, interpolated in log–log:
//!
//! * [`ROLLER_ERROR`] — rollers on rigid shafts (shaft radius 0.1 R), against the BEM true
//!   geometry, as a function of a/R (R the effective radius);
//! * [`INTERNAL_ERROR`] — a roller in a ring bore (internal contact, bore 1.25 × the roller's
//!   radius R1), against the BEM true geometry, as a function of a/R1;
//! * [`LAYER_ERROR`] — a cover layer of thickness b bonded to a rigid core, against the BEM
//!   layer, as a function of b/a.
//!
//! All three come from `cargo run --release --example model_error_table` (examples/model_error_table.rs;
//! docs/choosing-a-model.md shows the tables and the rule). Errors are the largest nodal
//! differences in units of p0 (pressure) and μp0 (shear), p0 the Hertz peak pressure.

/// (a/R, max |Δp|/p0, max |Δq|/(μp0)) of the half-space model against true-geometry rollers on
/// shafts (similar steel, μ = 0.1, Q/μP = 0.5, 41 contact elements). Below a/R ≈ 0.01 the
/// values are the two discretizations' difference (~5e-4), not model error.
pub const ROLLER_ERROR: [(f64, f64, f64); 7] = [
    (2e-3, 5.340e-4, 7.050e-4),
    (5e-3, 5.259e-4, 8.985e-4),
    (1e-2, 4.969e-4, 1.799e-3),
    (2e-2, 7.241e-4, 5.397e-3),
    (5e-2, 2.743e-3, 3.057e-2),
    (1e-1, 9.951e-3, 7.751e-2),
    (2e-1, 3.876e-2, 2.597e-1),
];

/// (a/R1, max |Δp|/p0, max |Δq|/(μp0)) of the half-space model (R* from the signed radii)
/// against the true geometry of a steel roller R1 = 40 mm on a rigid shaft of 5 mm in the bore
/// R2 = 50 mm of a steel ring with its rim (65 mm) fixed (μ = 0.1, Q/μP = 0.5, 41 contact
/// elements). R* = 5 R1 here: the contact is conformal long before a/R* is large.
pub const INTERNAL_ERROR: [(f64, f64, f64); 6] = [
    (5e-3, 3.806e-3, 3.806e-3),
    (1e-2, 6.635e-3, 6.635e-3),
    (2e-2, 1.312e-2, 1.312e-2),
    (5e-2, 4.459e-2, 4.459e-2),
    (1e-1, 1.028e-1, 1.028e-1),
    (2e-1, 2.850e-1, 2.850e-1),
];

/// (b/a, max |Δp|/p0) of the half-space model against a layer of thickness b bonded to a
/// rigid core (ν = 0.3, frictionless, rigid indenter R = 100 a).
pub const LAYER_ERROR: [(f64, f64); 6] = [
    (1e0, 5.337e-1),
    (2e0, 3.076e-1),
    (5e0, 9.311e-2),
    (1e1, 2.119e-2),
    (2e1, 6.410e-3),
    (5e1, 1.749e-3),
];

/// Log–log interpolation of `table` (x increasing) at x; beyond the ends the end segments
/// are extended (flagged by the second return value).
pub fn interpolate(table: &[(f64, f64)], x: f64) -> (f64, bool) {
    let n = table.len();
    let k = table.partition_point(|&(t, _)| t < x).clamp(1, n - 1);
    let ((x0, y0), (x1, y1)) = (table[k - 1], table[k]);
    let slope = (y1 / y0).ln() / (x1 / x0).ln();
    let y = y0 * (x / x0).powf(slope);
    (y, x < table[0].0 || x > table[n - 1].0)
}

/// What the half-space model would get wrong on a scene.
#[derive(Debug, Clone, PartialEq)]
pub struct HalfSpaceError {
    /// Estimated max pressure error [p0].
    pub pressure: f64,
    /// Estimated max shear error [μp0] (None when not measured for this family).
    pub shear: Option<f64>,
    /// Which family and parameter the estimate comes from, e.g. "rollers, a/R = 0.01".
    pub basis: String,
    /// The parameter lies outside the measured range (extrapolated).
    pub extrapolated: bool,
}

/// Half-space error for a roller scene of a/R (effective radius).
pub fn roller_error(a_over_r: f64) -> HalfSpaceError {
    let p: Vec<(f64, f64)> = ROLLER_ERROR.iter().map(|r| (r.0, r.1)).collect();
    let q: Vec<(f64, f64)> = ROLLER_ERROR.iter().map(|r| (r.0, r.2)).collect();
    // Below the table the error is the discretization floor: hold the first value.
    let x = a_over_r.max(ROLLER_ERROR[0].0);
    let (ep, out_p) = interpolate(&p, x);
    let (eq, _) = interpolate(&q, x);
    HalfSpaceError {
        pressure: ep,
        shear: Some(eq),
        basis: format!("rollers on shafts, a/R = {a_over_r:.3e}"),
        extrapolated: out_p && a_over_r > ROLLER_ERROR[0].0,
    }
}

/// Half-space error for a roller of radius R1 in a ring bore (internal contact), Hertz
/// half-width a, at a/R1.
pub fn internal_error(a_over_r1: f64) -> HalfSpaceError {
    let p: Vec<(f64, f64)> = INTERNAL_ERROR.iter().map(|r| (r.0, r.1)).collect();
    let q: Vec<(f64, f64)> = INTERNAL_ERROR.iter().map(|r| (r.0, r.2)).collect();
    let (ep, out) = interpolate(&p, a_over_r1);
    let (eq, _) = interpolate(&q, a_over_r1);
    HalfSpaceError {
        pressure: ep.min(1.0),
        shear: Some(eq),
        basis: format!("roller in a ring bore (internal contact), a/R1 = {a_over_r1:.3e}"),
        extrapolated: out,
    }
}

/// Half-space error for a layer of thickness b over a Hertz half-width a.
pub fn layer_error(b_over_a: f64) -> HalfSpaceError {
    let (ep, out) = interpolate(&LAYER_ERROR, b_over_a);
    HalfSpaceError {
        pressure: ep.min(1.0),
        shear: None,
        basis: format!("layer bonded to a rigid core, b/a = {b_over_a:.3}"),
        extrapolated: out,
    }
}

/// The advice line of `rollbem check` for a relative `tolerance` (fraction of p0 and μp0).
pub fn advise(error: &HalfSpaceError, tolerance: f64) -> String {
    let worst = error.shear.map_or(error.pressure, |q| q.max(error.pressure));
    let estimate = match error.shear {
        Some(q) => format!(
            "half-space error ≈ {:.2} % of p0 in pressure, {:.2} % of μp0 in shear",
            100.0 * error.pressure,
            100.0 * q
        ),
        None => format!("half-space error ≈ {:.1} % of p0 in pressure", 100.0 * error.pressure),
    };
    let verdict = if worst <= tolerance {
        format!("half_space is enough for a tolerance of {:.2} %", 100.0 * tolerance)
    } else {
        format!(
            "use bem (the true geometry): half_space misses a tolerance of {:.2} %",
            100.0 * tolerance
        )
    };
    format!(
        "{verdict} ({estimate}; {}{}; docs/choosing-a-model.md)",
        error.basis,
        if error.extrapolated {
            ", extrapolated beyond the measured range"
        } else {
            ""
        }
    )
}

/// The advice line when no true-geometry model of the scene's physics exists (a viscoelastic
/// body): the half-space's estimated error, said as what it is.
pub fn advise_without_alternative(error: &HalfSpaceError) -> String {
    format!(
        "half_space is the only model of this material (bem is elastic); its estimated error against the true \
         geometry: {:.2} % of p0 in pressure{} ({}; docs/choosing-a-model.md)",
        100.0 * error.pressure,
        error
            .shear
            .map_or(String::new(), |q| format!(", {:.2} % of μp0 in shear", 100.0 * q)),
        error.basis
    )
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn interpolation_hits_the_table_and_is_monotone_between() {
        let (y, out) = interpolate(&LAYER_ERROR, 5.0);
        assert!((y - 9.311e-2).abs() < 1e-12 && !out);
        let (y, _) = interpolate(&LAYER_ERROR, 7.0);
        assert!(y < 9.311e-2 && y > 2.119e-2);
        let (_, out) = interpolate(&LAYER_ERROR, 100.0);
        assert!(out);
    }

    #[test]
    fn advice_follows_the_tolerance() {
        // The paper's rollers (a/R = 0.01): half-space good to 0.2 %.
        let e = roller_error(0.01);
        assert!(advise(&e, 0.01).starts_with("half_space is enough"));
        assert!(advise(&e, 0.001).starts_with("use bem"));
        // A thin layer: the half-space is far off.
        assert!(advise(&layer_error(1.0), 0.05).starts_with("use bem"));
        // A roller in a bore at the same a/R1 needs the BEM much earlier.
        assert!(advise(&internal_error(0.01), 0.01).starts_with("half_space is enough"));
        assert!(advise(&internal_error(0.05), 0.01).starts_with("use bem"));
        assert!(internal_error(0.05).pressure > roller_error(0.05).pressure);
        // Tiny a/R holds the discretization floor rather than extrapolating to zero.
        assert_eq!(roller_error(1e-5).pressure, ROLLER_ERROR[0].1);
    }
}
