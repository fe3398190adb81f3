//! summary.json: what a run found, in one JSON document.

use crate::contact::IterationRecord;
use crate::post::friction_check::FrictionCheck;
use crate::post::rolling_resistance::{rolling_resistance, RollingResistance};
use crate::post::{NodeState, SlipDirection, SlipRegime, Solved, Timings, Zone};
use crate::scene::Estimates;
use serde::Serialize;

/// Contact extent in summary.json.
#[derive(Debug, Clone, Serialize)]
pub struct ContactExtent {
    /// Left end of the contact [length].
    pub x_min: f64,
    /// Right end [length].
    pub x_max: f64,
    /// Half the contact length [length].
    pub half_width: f64,
    /// Centre of the contact [length].
    pub centre: f64,
}

/// Grid description in summary.json.
#[derive(Debug, Clone, Serialize)]
pub struct GridSummary {
    /// Number of elements.
    pub elements: usize,
    /// Element interpolation.
    pub element: crate::grid::ElementKind,
    /// Number of contact nodes.
    pub nodes: usize,
    /// Left end [length].
    pub x_min: f64,
    /// Right end [length].
    pub x_max: f64,
    /// Node spacing [length]: the smallest distance between neighbouring nodes.
    pub spacing: f64,
    /// Smallest distance between neighbouring nodes [length] (= `spacing`).
    pub min_spacing: f64,
    /// Largest distance between neighbouring nodes [length].
    pub max_spacing: f64,
    /// Refinements of an error-controlled grid after its start grid (0 for a fixed grid).
    pub refinements: usize,
    /// `contact.grid.tolerance` of an error-controlled grid (null for a fixed grid).
    pub tolerance: Option<f64>,
    /// Whether the results on the final grid are the BEM bodies' stand-ins' (the half-plane
    /// plus the smooth remainder fitted on coarser grids, their own error included in
    /// `error_estimate`) rather than the full BEM bodies cut along the grid.
    pub results_from_stand_ins: bool,
    /// Slip derivative scheme.
    pub slip_derivative: crate::contact::SlipDerivative,
}

/// summary.json (docs/outputs.md describes every key, its unit and sign).
#[derive(Debug, Clone, Serialize)]
pub struct Summary {
    /// The rollbem version that wrote it (Cargo.toml's `version`).
    pub version: String,
    /// The command line of the process that wrote it (program name, then the arguments,
    /// shell-quoted where needed).
    pub command: String,
    /// Case title.
    pub title: String,
    /// Whether the solver converged.
    pub converged: bool,
    /// Newton iterations.
    pub iterations: usize,
    /// Final scaled residual.
    pub residual: f64,
    /// Estimated discretisation errors of an error-controlled grid's solution (null for a fixed
    /// grid, or when a solve did not converge).
    pub error_estimate: Option<crate::post::adaptation::ErrorEstimate>,
    /// P [force/length].
    pub normal_force: f64,
    /// Q [force/length].
    pub tangential_force: f64,
    /// Q/(μP) (null when μ = 0).
    pub load_ratio: Option<f64>,
    /// The axes the tractions act along: `contact` (the interface's normal and tangent) or
    /// `global` (x and y; always for half-space bodies).
    pub traction_axes: crate::contact::TractionAxes,
    /// The forces on A globally (x, y) and along the contact (normal, tangential)
    /// [force/length]; with global axes the y force and the normal force are P, the x and
    /// tangential force Q.
    pub forces: crate::contact::ContactForces,
    /// The contact's directions at the grid's nodes when the tractions act along the contact
    /// (null along the global axes): `normal_angle` ψ [rad] of the interface's tangent from
    /// +x, `arc_scale` [A, B] the interface length per body surface length, `rigid_slip` k
    /// [-] (docs/theory.md, "Tractions along the contact"). Body b carries, per unit length of
    /// its own surface, the global traction ±s_b(p sin(−ψ) + q cos ψ, p cos ψ + q sin ψ) (+ on A).
    pub contact_frame: Option<crate::contact::ContactFrame>,
    /// δ0 [length] (half-space bodies: relative to the datum ℓ = 2R/e, see docs/theory.md).
    pub overlap: f64,
    /// ξ = (V_A − V_B)/V.
    pub creep: f64,
    /// Contact extent (null if nothing is in contact).
    pub contact: Option<ContactExtent>,
    /// Stick zones [[x0, x1], …].
    pub stick_zones: Vec<[f64; 2]>,
    /// Slip zones [[x0, x1], …].
    pub slip_zones: Vec<[f64; 2]>,
    /// Direction of the slip in each slip zone (written ±1), in the order of `slip_zones`.
    pub slip_directions: Vec<SlipDirection>,
    /// All zones in increasing x, with node counts.
    pub zones: Vec<Zone>,
    /// Slip regime 1–4 of González & Abascal §5.2 (written 0 for none of them, e.g. full stick).
    pub slip_regime: SlipRegime,
    /// Peak pressure [stress]: the largest value of the pressure's interpolant on the contact
    /// grid ([`crate::grid::ContactGrid::interpolant_max`]), between nodes too.
    pub max_pressure: f64,
    /// The pressure's asymmetry and the rolling resistance it gives (null when nothing is in
    /// contact; [`crate::post::rolling_resistance`]).
    pub rolling_resistance: Option<RollingResistance>,
    /// Stage timings [s].
    pub timings: Timings,
    /// Model of each body.
    pub models: Models,
    /// Hertz estimates and derived constants.
    pub estimates: Estimates,
    /// The contact grid.
    pub grid: GridSummary,
    /// Solver diagnostics (penalties, residual history).
    pub solver: SolverSummary,
    /// Where the boundary-integral (HBEM) slip contradicts the friction law, with the
    /// threshold used (null when no HBEM slip exists or μ = 0; see
    /// [`crate::post::friction_check`]).
    pub hbem_check: Option<FrictionCheck>,
    /// Notices for the user (requested features not available, adjustments made).
    pub notices: Vec<String>,
    /// Where the inputs leave what the models are valid for (small strain, the half-space's
    /// a ≪ R, first-order meshes; [`crate::scene::validity`]); empty when none.
    pub warnings: Vec<String>,
    /// The interior grid of `output.interior` (null when not asked): body, model, point
    /// counts by status, and the maxima of the principal shear and von Mises stress.
    pub interior: Option<crate::interior::InteriorSummary>,
    /// First yield and shakedown of each body `output.strength` assesses (empty when not
    /// asked; docs/strength.md).
    pub strength: Vec<crate::post::strength::assess::StrengthSummary>,
    /// Whether VTK files (contact.vtu, result.pvd) were requested.
    pub vtk: bool,
    /// The unit of every number above, by key path (`.` between keys, `[]` for array items),
    /// from the case's `units` ([`super::units::SUMMARY_KEYS`]).
    pub units: std::collections::BTreeMap<String, String>,
    /// The history of a transient case (`transient:`; absent for a steady run): the last step
    /// is the solution above.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub transient: Option<super::transient::TransientSummary>,
    /// The case as resolved after `--set` overrides.
    pub case: serde_json::Value,
}

/// Models of A and B.
#[derive(Debug, Clone, Serialize)]
pub struct Models {
    /// Model of A.
    #[serde(rename = "A")]
    pub a: String,
    /// Model of B.
    #[serde(rename = "B")]
    pub b: String,
    /// Whether both bodies are the elastic half-planes the Hertz estimates describe
    /// ([`crate::body::BodySetup::hertz_applies`]): the run's table then sets Hertz's
    /// half-width and p0 beside the solved ones. Not written to summary.json.
    #[serde(skip)]
    pub hertzian: bool,
}

/// Solver diagnostics.
#[derive(Debug, Clone, Serialize)]
pub struct SolverSummary {
    /// Solution method used.
    pub method: crate::contact::Method,
    /// Formulation used.
    pub formulation: crate::contact::Formulation,
    /// Normal penalty r_n [stress/length].
    pub penalty_normal: f64,
    /// Tangential penalty r_t [stress].
    pub penalty_tangential: f64,
    /// Traction scale of the convergence test [stress].
    pub traction_scale: f64,
    /// Residual, step length and system size per iteration.
    pub history: Vec<IterationRecord>,
    /// Restarts the default method needed (empty when its first attempt converged).
    pub fallbacks: Vec<String>,
}

/// Builds the summary of a solved run (timings as measured so far; [`super::write_run`] fills
/// in the total).
pub fn summary(s: &Solved) -> Summary {
    let (scene, pb, sol, report) = (&s.scene, &s.problem, &s.solution, &s.report);
    let case = &scene.case;
    let mu = scene.friction();
    Summary {
        version: env!("CARGO_PKG_VERSION").to_string(),
        command: command_line(),
        title: case.case.title.clone(),
        converged: report.converged,
        iterations: report.iterations,
        residual: report.residual,
        error_estimate: match &s.adaptation {
            Some(a) => a.estimate,
            None => s.fixed_grid_estimate,
        },
        normal_force: sol.normal_force,
        tangential_force: sol.tangential_force,
        load_ratio: (mu > 0.0 && sol.normal_force > 0.0).then(|| sol.tangential_force / (mu * sol.normal_force)),
        traction_axes: if pb.frame.is_global() {
            crate::contact::TractionAxes::Global
        } else {
            crate::contact::TractionAxes::Contact
        },
        forces: sol.forces,
        contact_frame: (!pb.frame.is_global()).then(|| pb.frame.clone()),
        overlap: sol.overlap,
        creep: sol.creep,
        contact: sol.contact_extent().map(|[x0, x1]| ContactExtent {
            x_min: x0,
            x_max: x1,
            half_width: 0.5 * (x1 - x0),
            centre: 0.5 * (x0 + x1),
        }),
        stick_zones: sol.zones_of(NodeState::Stick),
        slip_zones: sol.zones_of(NodeState::Slip),
        slip_directions: sol.slip_directions(),
        zones: sol.zones.clone(),
        slip_regime: s.regime,
        max_pressure: pb.grid.interpolant_max(&sol.pressure).max(0.0),
        rolling_resistance: rolling_resistance(
            &pb.grid,
            &sol.pressure,
            sol.contact_extent(),
            scene.leading_edge_sign(),
            &pb.gap_slope,
            case.case.load.speed,
        ),
        timings: s.timings,
        models: Models {
            a: scene.bodies[0].model_name().to_string(),
            b: scene.bodies[1].model_name().to_string(),
            hertzian: scene.bodies.iter().all(|b| b.hertz_applies()),
        },
        estimates: scene.estimates.clone(),
        grid: GridSummary {
            elements: pb.grid.n_elements(),
            element: pb.grid.kind,
            nodes: pb.grid.n_nodes(),
            x_min: pb.grid.edges[0],
            x_max: pb.grid.edges[pb.grid.n_elements()],
            spacing: pb.grid.node_spacing(),
            min_spacing: pb.grid.node_spacing(),
            max_spacing: pb.grid.nodes.windows(2).map(|w| w[1] - w[0]).fold(0.0, f64::max),
            refinements: s.adaptation.as_ref().map_or(0, |a| a.refinements),
            tolerance: s.adaptation.as_ref().map(|a| a.tolerance),
            results_from_stand_ins: s.adaptation.as_ref().is_some_and(|a| a.results_from_stand_ins),
            slip_derivative: pb.slip_operator.scheme,
        },
        solver: SolverSummary {
            method: report.method,
            formulation: case.case.solver.formulation,
            penalty_normal: report.penalty_normal,
            penalty_tangential: report.penalty_tangential,
            traction_scale: report.traction_scale,
            history: report.history.clone(),
            fallbacks: report.fallbacks.clone(),
        },
        hbem_check: s.friction_check.clone(),
        notices: s.notices.clone(),
        warnings: s.warnings.clone(),
        interior: s.interior.as_ref().map(crate::interior::InteriorField::summary),
        strength: s.strength.iter().map(|b| b.summary()).collect(),
        vtk: case.case.output.vtk,
        units: super::units::summary_units(&case.case.units),
        transient: None,
        case: case.resolved.clone(),
    }
}

/// The command line of this process: the program's file name and its arguments, each quoted
/// for a POSIX shell when it holds anything but letters, digits and `-_./=,:+@%`.
pub fn command_line() -> String {
    let mut args = std::env::args_os().map(|a| a.to_string_lossy().into_owned());
    let program = args
        .next()
        .map(|p| {
            std::path::Path::new(&p)
                .file_name()
                .map_or(p.clone(), |n| n.to_string_lossy().into_owned())
        })
        .unwrap_or_else(|| "rollbem".into());
    std::iter::once(program)
        .chain(args.map(|a| shell_quoted(&a)))
        .collect::<Vec<_>>()
        .join(" ")
}

/// `arg` as a POSIX shell reads it back: unchanged when plain, else in single quotes.
fn shell_quoted(arg: &str) -> String {
    let plain = !arg.is_empty()
        && arg
            .chars()
            .all(|c| c.is_ascii_alphanumeric() || "-_./=,:+@%".contains(c));
    if plain {
        arg.to_string()
    } else {
        format!("'{}'", arg.replace('\'', r"'\''"))
    }
}

#[cfg(test)]
mod tests {
    use super::shell_quoted;

    #[test]
    fn arguments_are_quoted_only_when_needed() {
        assert_eq!(shell_quoted("--set"), "--set");
        assert_eq!(shell_quoted("contact.friction=0.2"), "contact.friction=0.2");
        assert_eq!(shell_quoted("a b"), "'a b'");
        assert_eq!(shell_quoted("it's"), r"'it'\''s'");
        assert_eq!(shell_quoted(""), "''");
        assert_eq!(
            shell_quoted("materials.x={E: 1, nu: 0.3}"),
            "'materials.x={E: 1, nu: 0.3}'"
        );
    }
}
