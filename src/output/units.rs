//! The units of the numbers rollbem writes, from the case's `units` (labels only: the numbers
//! are in whatever consistent units the case uses). summary.json carries them in its `units`
//! block, the run table in its labels; docs/outputs.md lists every file and column.

use crate::case::Units;
use std::collections::BTreeMap;

/// What a number measures.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Dimension {
    /// A length (coordinates, overlap, half-widths) [length].
    Length,
    /// A force per unit length of the cylinders (P, Q) [force/length].
    ForcePerLength,
    /// A stress (tractions, moduli, interior stresses) [force/length²].
    Stress,
    /// A stress per length (the normal penalty r_n) [force/length³].
    StressPerLength,
    /// A moment per unit length of the cylinders [force·length/length = force].
    MomentPerLength,
    /// An energy per unit length of the cylinders [force·length/length = force].
    EnergyPerLength,
    /// A speed [length/time].
    Speed,
    /// A power per unit length of the cylinders [force/length · length/time].
    PowerPerLength,
    /// A ratio or a velocity divided by |V| (creepage, slip, residuals) [-].
    Dimensionless,
    /// Wall-clock time [s].
    Seconds,
    /// A time of the case's rolling (its `units.time`).
    Time,
    /// A count (iterations, nodes, points).
    Count,
    /// A direction, +1 or −1 (0 where none).
    Sign,
}

impl Dimension {
    /// The unit's label in the case's units: `mm`, `N/mm`, `N/mm^2`, `N/mm^3`, `-`, `s`,
    /// `count`, `sign`.
    pub fn unit(self, u: &Units) -> String {
        match self {
            Dimension::Length => u.length.clone(),
            Dimension::ForcePerLength => u.force_per_length(),
            Dimension::Stress => u.stress(),
            Dimension::StressPerLength => u.stress_per_length(),
            Dimension::MomentPerLength | Dimension::EnergyPerLength => {
                format!("{}*{}/{}", u.force, u.length, u.length)
            }
            Dimension::Speed => u.speed(),
            Dimension::PowerPerLength => u.power_per_length(),
            Dimension::Dimensionless => "-".into(),
            Dimension::Seconds => "s".into(),
            Dimension::Time => u.time.clone(),
            Dimension::Count => "count".into(),
            Dimension::Sign => "sign".into(),
        }
    }
}

use Dimension::*;

/// Every number of summary.json outside the resolved `case` (whose keys cases/README.md
/// documents), by its path: keys joined by `.`, `[]` for the items of an array.
pub const SUMMARY_KEYS: &[(&str, Dimension)] = &[
    ("iterations", Count),
    ("residual", Dimensionless),
    ("normal_force", ForcePerLength),
    ("tangential_force", ForcePerLength),
    ("load_ratio", Dimensionless),
    ("overlap", Length),
    ("creep", Dimensionless),
    ("forces.global_x", ForcePerLength),
    ("forces.global_y", ForcePerLength),
    ("forces.normal", ForcePerLength),
    ("forces.tangential", ForcePerLength),
    ("contact_frame.normal_angle[]", Dimensionless),
    ("contact_frame.arc_scale[][]", Dimensionless),
    ("contact_frame.rigid_slip[]", Dimensionless),
    ("contact.x_min", Length),
    ("contact.x_max", Length),
    ("contact.half_width", Length),
    ("contact.centre", Length),
    ("stick_zones[][]", Length),
    ("slip_zones[][]", Length),
    ("slip_directions[]", Sign),
    ("zones[].x0", Length),
    ("zones[].x1", Length),
    ("zones[].direction", Sign),
    ("zones[].nodes", Count),
    ("slip_regime", Dimensionless),
    ("max_pressure", Stress),
    ("rolling_resistance.leading_edge", Length),
    ("rolling_resistance.trailing_edge", Length),
    ("rolling_resistance.pressure_centre", Length),
    ("rolling_resistance.moment", MomentPerLength),
    ("rolling_resistance.force", ForcePerLength),
    ("rolling_resistance.coefficient", Dimensionless),
    ("rolling_resistance.speed", Speed),
    ("rolling_resistance.dissipated_power", PowerPerLength),
    ("timings.assembly_s", Seconds),
    ("timings.condense_s", Seconds),
    ("timings.solve_s", Seconds),
    ("timings.interior_s", Seconds),
    ("timings.strength_s", Seconds),
    ("timings.total_s", Seconds),
    ("estimates.e_star", Stress),
    ("estimates.dundurs_beta", Dimensionless),
    ("estimates.effective_radius", Length),
    ("estimates.normal_force", ForcePerLength),
    ("estimates.hertz_half_width", Length),
    ("estimates.hertz_peak_pressure", Stress),
    ("estimates.half_width_over_radius", Dimensionless),
    ("estimates.carter_stick_width", Length),
    ("estimates.grid_half_length", Length),
    ("estimates.grid_spacing", Length),
    ("grid.elements", Count),
    ("grid.nodes", Count),
    ("grid.x_min", Length),
    ("grid.x_max", Length),
    ("grid.spacing", Length),
    ("grid.min_spacing", Length),
    ("grid.max_spacing", Length),
    ("grid.refinements", Count),
    ("grid.tolerance", Dimensionless),
    ("error_estimate.pressure_rms", Dimensionless),
    ("error_estimate.shear_rms", Dimensionless),
    ("error_estimate.creep_rel", Dimensionless),
    ("error_estimate.overlap_rel", Dimensionless),
    ("error_estimate.body_mesh.creepage_rel", Dimensionless),
    ("error_estimate.body_mesh.overlap_rel", Dimensionless),
    ("error_estimate.body_mesh.pressure", Dimensionless),
    ("error_estimate.body_mesh.shear", Dimensionless),
    ("error_estimate.body_mesh.bisections", Count),
    ("solver.penalty_normal", StressPerLength),
    ("solver.penalty_tangential", Stress),
    ("solver.traction_scale", Stress),
    ("solver.history[].residual", Dimensionless),
    ("solver.history[].step", Dimensionless),
    ("solver.history[].system_size", Count),
    ("solver.history[].inner_iterations", Count),
    ("hbem_check.threshold", Dimensionless),
    ("hbem_check.threshold_floor", Dimensionless),
    ("hbem_check.threshold_fraction", Dimensionless),
    ("hbem_check.slip_scale", Dimensionless),
    ("hbem_check.max_difference_slip_nodes", Dimensionless),
    ("hbem_check.max_hbem_slip_stick_nodes", Dimensionless),
    ("hbem_check.violations[].x", Length),
    ("hbem_check.violations[].slip", Dimensionless),
    ("hbem_check.violations[].slip_hbem", Dimensionless),
    ("hbem_check.violations[].shear_ratio", Dimensionless),
    ("interior.points", Count),
    ("interior.inside", Count),
    ("interior.outside", Count),
    ("interior.boundary", Count),
    ("interior.max_shear.value", Stress),
    ("interior.max_shear.x", Length),
    ("interior.max_shear.y", Length),
    ("interior.max_von_mises.value", Stress),
    ("interior.max_von_mises.x", Length),
    ("interior.max_von_mises.y", Length),
    ("strength[].shear_yield", Stress),
    ("strength[].first_yield.factor", Dimensionless),
    ("strength[].first_yield.x", Length),
    ("strength[].first_yield.z", Length),
    ("strength[].shakedown.factor", Dimensionless),
    ("strength[].shakedown.z", Length),
    ("strength[].grid.spacing_x", Length),
    ("strength[].grid.spacing_z", Length),
    ("strength[].grid.half_length", Length),
    ("transient.steps", Count),
    ("transient.step", Length),
    ("transient.rolled", Length),
    ("transient.shift", Length),
    ("transient.iterations", Count),
    ("transient.mean_iterations", Count),
    ("transient.change", Dimensionless),
    ("transient.settled_distance", Length),
];

/// The `units` block of summary.json: the unit of every number of [`SUMMARY_KEYS`].
pub fn summary_units(u: &Units) -> BTreeMap<String, String> {
    SUMMARY_KEYS
        .iter()
        .map(|(key, dim)| (key.to_string(), dim.unit(u)))
        .collect()
}

/// Columns of contact.csv and what each measures (`state` is a word: open, stick, slip).
pub const CONTACT_CSV_UNITS: [(&str, Option<Dimension>); 11] = [
    ("x", Some(Length)),
    ("pressure", Some(Stress)),
    ("shear", Some(Stress)),
    ("gap", Some(Length)),
    ("slip", Some(Dimensionless)),
    ("slip_hbem", Some(Dimensionless)),
    ("state", None),
    ("u_n_A", Some(Length)),
    ("u_t_A", Some(Length)),
    ("u_n_B", Some(Length)),
    ("u_t_B", Some(Length)),
];

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn units_follow_the_case() {
        let u = Units {
            length: "m".into(),
            force: "kN".into(),
            time: "s".into(),
        };
        let block = summary_units(&u);
        assert_eq!(block["normal_force"], "kN/m");
        assert_eq!(block["max_pressure"], "kN/m^2");
        assert_eq!(block["solver.penalty_normal"], "kN/m^3");
        assert_eq!(block["overlap"], "m");
        assert_eq!(block["creep"], "-");
        assert_eq!(block.len(), SUMMARY_KEYS.len(), "no key twice");
    }

    #[test]
    fn the_csv_table_names_the_written_columns() {
        let names: Vec<&str> = CONTACT_CSV_UNITS.iter().map(|c| c.0).collect();
        assert_eq!(names, super::super::CSV_COLUMNS);
    }
}
