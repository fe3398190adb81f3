//! The terminal table of a run.

use super::summary::Summary;
use std::path::Path;

/// The terminal summary table of a run: one row per quantity, its unit in the label (or after
/// each value where a row holds several kinds), from the summary's `units` block.
pub fn render_table(s: &Summary, output_dir: &Path) -> String {
    let unit = |key: &str| s.units.get(key).map_or("?", String::as_str).to_string();
    let (len, force, stress) = (unit("overlap"), unit("normal_force"), unit("max_pressure"));
    let mut rows: Vec<(String, String)> = Vec::new();
    let mut line = |k: &str, v: String| rows.push((k.to_string(), v));
    let status = if s.converged { "converged" } else { "NOT CONVERGED" };
    line("title", s.title.clone());
    line("models (A / B)", format!("{} / {}", s.models.a, s.models.b));
    let restarts = match s
        .solver
        .fallbacks
        .iter()
        .filter(|f| crate::contact::falling::is_restart(f))
        .count()
    {
        0 => String::new(),
        n => format!(" after {n} restart{}", if n == 1 { "" } else { "s" }),
    };
    line(
        "solver",
        format!(
            "{status} in {} iteration{}{restarts}, residual {:.2e}",
            s.iterations,
            if s.iterations == 1 { "" } else { "s" },
            s.residual
        ),
    );
    line(&format!("normal force P [{force}]"), format!("{:.6}", s.normal_force));
    line(
        &format!("tangential force Q [{force}]"),
        format!(
            "{}{}",
            unsigned_zero(format!("{:.6}", s.tangential_force)),
            s.load_ratio.map_or(String::new(), |r| format!(
                "  (Q/muP = {})",
                unsigned_zero(format!("{r:.4}"))
            ))
        ),
    );
    if s.traction_axes == crate::contact::TractionAxes::Contact {
        let f = &s.forces;
        line(
            &format!("forces on A [{force}]"),
            format!(
                "global (x, y) = ({:.6}, {:.6}); along the contact (normal, tangential) = ({:.6}, {:.6})",
                f.global_x, f.global_y, f.normal, f.tangential
            ),
        );
    }
    line(&format!("overlap delta0 [{len}]"), format!("{:.6e}", s.overlap));
    line("creepage xi [-]", format!("{:.6e}", s.creep));
    // Hertz comparisons only mean something when both bodies are elastic half-planes.
    let hertzian = s.models.hertzian;
    if let Some(c) = &s.contact {
        let hertz = if hertzian {
            format!(" (Hertz {:.5})", s.estimates.hertz_half_width)
        } else {
            String::new()
        };
        line(
            &format!("contact [{len}]"),
            format!(
                "[{:.5}, {:.5}]  half-width {:.5}, centre {:+.5}{hertz}",
                c.x_min,
                c.x_max,
                c.half_width,
                // A centre that rounds to zero is printed +0.00000, whatever the sign of its
                // round-off.
                if (c.centre * 1e5).round() == 0.0 { 0.0 } else { c.centre }
            ),
        );
    }
    let hertz = if hertzian {
        format!(" (Hertz p0 {:.6})", s.estimates.hertz_peak_pressure)
    } else {
        String::new()
    };
    line(
        &format!("max pressure [{stress}]"),
        format!("{:.6}{hertz}", s.max_pressure),
    );
    if let Some(r) = s.rolling_resistance.as_ref().filter(|r| r.speed.is_some()) {
        line(
            &format!("asymmetry [{len}]"),
            format!(
                "leading edge {:+.5}, trailing edge {:+.5}, pressure centre {:+.5e} towards the leading edge",
                r.leading_edge, r.trailing_edge, r.pressure_centre
            ),
        );
        line(
            &format!("rolling resistance [{force}]"),
            format!(
                "F_r = {:.6e}  (F_r/P = {:.6e}, moment {:.6e} {})",
                r.force,
                r.coefficient,
                r.moment,
                unit("rolling_resistance.moment")
            ),
        );
        if let (Some(power), Some(v)) = (r.dissipated_power, r.speed) {
            line(
                &format!("dissipated power [{}]", unit("rolling_resistance.dissipated_power")),
                format!("{power:.6e} at V = {v} {}", unit("rolling_resistance.speed")),
            );
        }
    }
    let zones = |z: &[[f64; 2]]| {
        z.iter()
            .map(|[a, b]| format!("[{a:.4}, {b:.4}]"))
            .collect::<Vec<_>>()
            .join(" ")
    };
    line(&format!("stick zones [{len}]"), zones(&s.stick_zones));
    let slip = if s.slip_zones.is_empty() {
        format!("none (full stick)  regime {}", s.slip_regime)
    } else {
        format!(
            "{}  directions {:?}  regime {}",
            zones(&s.slip_zones),
            s.slip_directions.iter().map(|d| d.sign()).collect::<Vec<_>>(),
            s.slip_regime
        )
    };
    line(&format!("slip zones [{len}]"), slip);
    if let Some(check) = s.hbem_check.as_ref().and_then(|c| c.summary_line()) {
        line("HBEM slip check", check);
    }
    grid_rows(s, [&len, &stress], &mut rows);
    rows.push(("results".into(), output_dir.display().to_string()));
    // The label column is as wide as the widest label (units make some long), at least 22,
    // and two spaces apart from the values.
    let width = rows.iter().map(|(k, _)| k.chars().count()).max().unwrap_or(0).max(22);
    rows.iter().map(|(k, v)| format!("  {k:<width$}  {v}\n")).collect()
}

/// A printed number that rounds to zero without its sign: free rolling's Q of −1e-12 prints
/// 0.000000, not −0.000000.
fn unsigned_zero(printed: String) -> String {
    match printed.strip_prefix('-') {
        Some(rest) if rest.chars().all(|c| c == '0' || c == '.') => rest.to_string(),
        _ => printed,
    }
}

/// The rows of the grid, its error estimate and control, the interior field and the times.
fn grid_rows(s: &Summary, [len, stress]: [&str; 2], rows: &mut Vec<(String, String)>) {
    let mut line = |k: &str, v: String| rows.push((k.to_string(), v));
    let grid = if s.grid.tolerance.is_some() {
        format!(
            "{} {} elements, {} nodes, spacing {:.4e} to {:.4e} {len}, {} refinements",
            s.grid.elements,
            s.grid.element.name(),
            s.grid.nodes,
            s.grid.min_spacing,
            s.grid.max_spacing,
            s.grid.refinements
        )
    } else {
        format!(
            "{} {} elements, {} nodes, spacing {:.4e} {len}",
            s.grid.elements,
            s.grid.element.name(),
            s.grid.nodes,
            s.grid.spacing
        )
    };
    line("grid", grid);
    if let (Some(e), Some(tol)) = (s.error_estimate, s.grid.tolerance) {
        line(
            "estimated error",
            format!(
                "pressure {:.2e} p0, shear {:.2e} mu p0, creepage {:.2e}{} (relative); tolerance {tol:.0e}{}",
                e.pressure_rms,
                e.shear_rms,
                e.creep_rel,
                e.overlap_rel.map_or(String::new(), |o| format!(", overlap {o:.2e}")),
                if s.grid.results_from_stand_ins {
                    "; results from the BEM bodies' stand-ins"
                } else {
                    ""
                }
            ),
        );
        if let Some(b) = e.body_mesh {
            line(
                "body mesh error",
                format!(
                    "pressure {:.2e} p0, shear {:.2e} mu p0, creepage {:.2e}{} (relative); {} bisections; \
                     against the meshes {} outside the contact",
                    b.pressure,
                    b.shear,
                    b.creepage_rel,
                    b.overlap_rel.map_or(String::new(), |o| format!(", overlap {o:.2e}")),
                    b.bisections,
                    b.compared_with.as_str()
                ),
            );
        }
    }
    if let (Some(e), None) = (s.error_estimate, s.grid.tolerance) {
        line(
            "estimated error",
            format!(
                "pressure {:.2e} p0, shear {:.2e} mu p0, creepage {:.2e}{} (relative); fixed grid, \
                 against its halving{}",
                e.pressure_rms,
                e.shear_rms,
                e.creep_rel,
                e.overlap_rel.map_or(String::new(), |o| format!(", overlap {o:.2e}")),
                if e.largest() > crate::post::adaptation::FIXED_GRID_WARNING {
                    "; above 1 %: set contact.grid.tolerance (e.g. 1e-4) for an error-controlled grid"
                } else {
                    ""
                }
            ),
        );
    }
    if let Some(i) = &s.interior {
        let peak = |p: &Option<crate::interior::Peak>| {
            p.map_or("-".to_string(), |p| {
                format!("{:.6} {stress} at ({:.4}, {:.4}) {len}", p.value, p.x, p.y)
            })
        };
        line(
            &format!("interior {} ({})", i.body, i.model),
            format!(
                "{} of {} points evaluated; max shear {}; max von Mises {}",
                i.inside,
                i.points,
                peak(&i.max_shear),
                peak(&i.max_von_mises)
            ),
        );
    }
    for b in &s.strength {
        line(
            &format!("strength {} ({})", b.body, b.model),
            format!(
                "{}, k = {:.6} {stress}: first yield at {:.4} x the stresses, at ({:.4}, {:.4}) {len} ({}); \
                 shakedown limit {:.4} x, governed at depth {:.4} {len} ({})",
                b.criterion,
                b.shear_yield,
                b.first_yield.factor,
                b.first_yield.x,
                b.first_yield.z,
                b.first_yield.site,
                b.shakedown.factor,
                b.shakedown.z,
                b.shakedown.mode
            ),
        );
    }
    let strength = if s.strength.is_empty() {
        String::new()
    } else {
        format!("  strength {:.4}", s.timings.strength_s)
    };
    line(
        "time [s]",
        format!(
            "assembly {:.4}  condense {:.4}  solve {:.4}  interior {:.4}{strength}  total {:.4}",
            s.timings.assembly_s, s.timings.condense_s, s.timings.solve_s, s.timings.interior_s, s.timings.total_s
        ),
    );
}

#[cfg(test)]
mod tests {
    use super::unsigned_zero;

    /// Only a number that rounds to zero loses its minus sign.
    #[test]
    fn a_negative_zero_prints_without_its_sign() {
        assert_eq!(unsigned_zero(format!("{:.6}", -1e-12)), "0.000000");
        assert_eq!(unsigned_zero(format!("{:.4}", -0.0)), "0.0000");
        assert_eq!(unsigned_zero(format!("{:.6}", -1e-3)), "-0.001000");
        assert_eq!(unsigned_zero(format!("{:.6}", 2.5)), "2.500000");
    }
}
