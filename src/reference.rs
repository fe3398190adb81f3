//! `rollbem validate`: built-in reference problems, each solved and compared with its closed
//! form (Hertz, Carter, Bentall–Johnson regimes, free-rolling limits). The case files are the
//! shipped ones, compiled into the binary, so the command needs nothing on disk.

use crate::analytic;
use crate::app::{self, CaseSource, Solved};
use crate::error::Error;
use crate::post::NodeState;
use std::path::PathBuf;

/// One reference comparison.
#[derive(Debug, Clone)]
pub struct Check {
    /// What is compared.
    pub name: String,
    /// rollbem's value.
    pub measured: f64,
    /// The closed form's value.
    pub reference: f64,
    /// The error measure (relative, or in the unit stated in `name`).
    pub error: f64,
    /// The acceptance limit of that error.
    pub limit: f64,
}

impl Check {
    /// Whether the error is within the limit.
    pub fn passed(&self) -> bool {
        self.error.abs() <= self.limit
    }
}

const CASES: [(&str, &str); 4] = [
    ("hertz", include_str!("../cases/hertz.yaml")),
    ("carter_051", include_str!("../cases/carter_051.yaml")),
    (
        "dissimilar_beta0288_004",
        include_str!("../cases/dissimilar_beta0288_004.yaml"),
    ),
    (
        "free_rolling_al_steel",
        include_str!("../cases/free_rolling_al_steel.yaml"),
    ),
];

fn solve(name: &str, set: &[&str]) -> Result<Solved, Error> {
    let text = CASES.iter().find(|(n, _)| *n == name).expect("built-in case").1;
    let path = PathBuf::from(format!("cases/{name}.yaml"));
    app::solve_case(CaseSource::Text { text, path: &path }, set)
}

fn relative(name: &str, measured: f64, reference: f64, limit: f64) -> Check {
    Check {
        name: name.into(),
        measured,
        reference,
        error: measured / reference - 1.0,
        limit,
    }
}

/// Runs every reference problem.
pub fn run() -> Result<Vec<Check>, Error> {
    let mut out = Vec::new();
    // Hertz, 41 elements.
    let s = solve("hertz", &["contact.grid.elements=41"])?;
    let [x0, x1] = s.solution.contact_extent().unwrap_or([0.0, 0.0]);
    out.push(relative(
        "Hertz half-width a [mm] (41 elements)",
        0.5 * (x1 - x0),
        s.scene.estimates.hertz_half_width,
        0.01,
    ));
    let pmax = s.solution.pressure.iter().fold(0.0_f64, |a, &b| a.max(b));
    out.push(relative(
        "Hertz peak pressure p0 [N/mm^2] (41 elements)",
        pmax,
        s.scene.estimates.hertz_peak_pressure,
        0.01,
    ));
    // Carter, 81 elements.
    let s = solve("carter_051", &["contact.grid.elements=81"])?;
    let c = analytic::Carter {
        half_width: s.scene.estimates.hertz_half_width,
        peak_pressure: s.scene.estimates.hertz_peak_pressure,
        friction: 0.1,
        ratio: 0.51,
        leading_edge_sign: 1.0,
    };
    let q_err = s
        .solution
        .x
        .iter()
        .zip(&s.solution.shear)
        .map(|(x, q)| (q - c.shear(*x)).abs())
        .fold(0.0, f64::max)
        / (c.friction * c.peak_pressure);
    out.push(Check {
        name: "Carter Q/muP = 0.51: max |q - q_Carter| / (mu p0) (81 elements)".into(),
        measured: q_err,
        reference: 0.0,
        error: q_err,
        limit: 0.02,
    });
    let stick: f64 = s.solution.zones_of(NodeState::Stick).iter().map(|[a, b]| b - a).sum();
    let [c0, c1] = c.stick_zone();
    // Value, closed form and error all in element lengths h: the limit is one element.
    let h = s.problem.grid.element_length();
    out.push(Check {
        name: format!("Carter stick-zone width [elements, h = {h:.4} mm] (81 elements)"),
        measured: stick / h,
        reference: (c1 - c0) / h,
        error: (stick - (c1 - c0)) / h,
        limit: 1.0,
    });
    out.push(relative(
        "Carter creepage [-] (81 elements)",
        s.solution.creep,
        c.creep(s.scene.estimates.effective_radius),
        0.01,
    ));
    // Dissimilar, Dundurs beta/mu = 2.88, Q/muP = 0.04: regime 4 (three slip zones).
    let s = solve("dissimilar_beta0288_004", &[])?;
    out.push(Check {
        name: "Dundurs beta/mu = 2.88, Q/muP = 0.04: slip regime (paper: 4)".into(),
        measured: s.regime.number() as f64,
        reference: 4.0,
        error: s.regime.number() as f64 - 4.0,
        limit: 0.0,
    });
    // Free rolling of aluminium on steel, 321 elements.
    let s = solve(
        "free_rolling_al_steel",
        &["contact.friction=1e-4", "contact.grid.elements=321"],
    )?;
    let e = &s.scene.estimates;
    let limit = analytic::free_rolling_creep_complete_slip(e.dundurs_beta, e.hertz_half_width, e.effective_radius);
    out.push(relative(
        "free rolling, mu -> 0: creepage [-] vs 0.9148 beta a/R",
        s.solution.creep,
        limit,
        0.01,
    ));
    let s = solve(
        "free_rolling_al_steel",
        &["contact.friction=1e3", "contact.grid.elements=321"],
    )?;
    let (xi, _, p_centre) =
        analytic::free_rolling_no_slip(e.dundurs_beta, e.normal_force, e.effective_radius, e.e_star);
    out.push(relative(
        "free rolling, mu -> inf: creepage [-] vs 2 eps a/R (Bufler)",
        s.solution.creep,
        xi,
        0.01,
    ));
    let p0 = s.problem.grid.interpolate(&s.solution.pressure, 0.0);
    out.push(relative(
        "free rolling, mu -> inf: p(0) [N/mm^2] vs cosh(pi eps) E* a/2R",
        p0,
        p_centre,
        0.001,
    ));
    Ok(out)
}

/// The table printed by `rollbem validate`.
pub fn render(checks: &[Check]) -> String {
    let mut t = format!(
        "{:<66} {:>14} {:>14} {:>11} {:>8}  result\n",
        "reference problem", "rollbem", "closed form", "error", "limit"
    );
    for c in checks {
        t.push_str(&format!(
            "{:<66} {:>14.6e} {:>14.6e} {:>+11.3e} {:>8.1e}  {}\n",
            c.name,
            c.measured,
            c.reference,
            c.error,
            c.limit,
            if c.passed() { "ok" } else { "FAILED" }
        ));
    }
    t.push_str(
        "error: relative (rollbem / closed form - 1), except the shear (in mu p0), the stick-zone\n\
         width (in elements, like its values) and the regime (a difference)\n",
    );
    let failed = checks.iter().filter(|c| !c.passed()).count();
    t.push_str(&format!("{} passed, {} failed\n", checks.len() - failed, failed));
    t
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The stick-zone row gives rollbem's width, Carter's and their difference in one unit (element
    /// lengths, named in the row): Carter's 1.4 mm on the 81-element grid is about 44 elements,
    /// and the error is the difference of the two printed values.
    #[test]
    fn stick_zone_width_value_closed_form_and_error_share_one_unit() {
        let checks = run().unwrap();
        let stick = checks
            .iter()
            .find(|c| c.name.starts_with("Carter stick-zone width [elements"))
            .expect("stick-zone row");
        assert!(stick.reference > 40.0 && stick.reference < 48.0, "{stick:?}");
        assert!(
            (stick.error - (stick.measured - stick.reference)).abs() < 1e-9,
            "{stick:?}"
        );
        let table = render(&checks);
        assert!(
            table.contains("mm] (81 elements)") && table.contains("9 passed"),
            "{table}"
        );
        for unit in ["a [mm]", "p0 [N/mm^2]", "creepage [-]"] {
            assert!(table.contains(unit), "{unit} missing:\n{table}");
        }
    }
}
