//! `rollbem check`: the case as understood — bodies, meshes, the contact grid, Hertz
//! estimates and the model advice — without solving.

pub mod cost;

use crate::case::{self, LoadedCase, NormalSpec};
use crate::error::Error;
use crate::scene::Scene;
use std::path::Path;

/// The text printed by `rollbem check`: the case as understood, with Hertz estimates.
/// `tolerance` is the accuracy the user needs (a fraction of p0 and μp0), for the model advice.
pub fn check_report(case_path: &Path, overrides: &[String], tolerance: f64) -> Result<String, Error> {
    let case = case::load(case_path, overrides)?;
    Ok(report(&case, tolerance)? + &grid_error_lines(&case, tolerance, false)?)
}

/// `rollbem check --estimate`: [`check_report`] with the grid's estimated error (see
/// [`grid_error_lines`]).
pub fn check_report_estimated(case_path: &Path, overrides: &[String], tolerance: f64) -> Result<String, Error> {
    let case = case::load(case_path, overrides)?;
    Ok(report(&case, tolerance)? + &grid_error_lines(&case, tolerance, true)?)
}

/// The lines on the grid's error that end `rollbem check`'s report. With `estimate`
/// (`--estimate`), the error from solving the case's steady problem on its grid and on the
/// grid halved (what `rollbem run` reports as `error_estimate`, docs/validation.md "Fixed
/// grids"), with a warning when it exceeds `tolerance` (the accuracy asked); without, a line
/// that says how to get it. An error-controlled grid (`contact.grid.tolerance`) is not solved:
/// its tolerance bounds the estimate.
pub fn grid_error_lines(case: &LoadedCase, tolerance: f64, estimate: bool) -> Result<String, Error> {
    if !estimate {
        if case.case.contact.grid.tolerance.is_some() {
            return Ok(String::new());
        }
        return Ok(format!(
            "  {:<26} not estimated: `rollbem check --estimate` solves the grid and its halving \
             (`rollbem run` reports it as error_estimate)\n",
            "grid error"
        ));
    }
    let label = "grid error (estimated)";
    if let Some(control) = case.case.contact.grid.tolerance {
        return Ok(format!(
            "  {label:<26} at most {control:e} (relative): contact.grid.tolerance controls it; not solved here\n"
        ));
    }
    let start = std::time::Instant::now();
    let solved = crate::app::solve_estimated(case)?;
    let seconds = start.elapsed().as_secs_f64();
    let Some(e) = solved.fixed_grid_estimate else {
        return Ok(format!(
            "  {label:<26} none: the grid's solve or its halving's did not converge (`rollbem run` says why)\n"
        ));
    };
    let mut t = format!(
        "  {label:<26} pressure {:.2e} p0, shear {:.2e} mu p0, creepage {:.2e}{} (relative); the grid \
         and its halving solved in {seconds:.2} s\n",
        e.pressure_rms,
        e.shear_rms,
        e.creep_rel,
        e.overlap_rel.map_or(String::new(), |o| format!(", overlap {o:.2e}")),
    );
    if e.largest() > tolerance {
        t.push_str(&format!(
            "  warning: the grid's estimated error {:.2e} exceeds the accuracy asked (--tolerance, {}): \
             set contact.grid.tolerance (e.g. 1e-4) for an error-controlled grid, or refine \
             contact.grid.elements\n",
            e.largest(),
            percent(tolerance)
        ));
    }
    Ok(t)
}

/// A fraction as a percentage for messages: 0.01 → "1 %".
fn percent(fraction: f64) -> String {
    format!("{} %", (fraction * 100.0 * 1e9).round() / 1e9)
}

/// The text of `rollbem check` for a case already loaded (from a file or from text in memory,
/// as the Python module's `rollbem.check` loads a case given as a dict); its first line names
/// `case.path`.
pub fn report(case: &LoadedCase, tolerance: f64) -> Result<String, Error> {
    let scene = Scene::from_case(case)?;
    if case.case.transient.as_ref().is_some_and(|t| t.datum_length.is_some()) {
        crate::app::check_datum_bodies(case, &scene)?;
    }
    let mut t = format!("rollbem check {}: valid\n", case.path.display());
    t.push_str(&format!("  {:<26} {}\n", "title", case.case.title));
    mesh_lines(case, &scene, &mut t)?;
    estimate_lines(case, &scene, &mut t);
    transient_lines(case, &scene, &mut t);
    advice_lines(case, &scene, tolerance, &mut t);
    cost_lines(case, &scene, &mut t)?;
    Ok(t)
}

/// A transient case's history as planned (cases/README.md, "Transient rolling"): the steps,
/// the step against the grid's node spacing and the Hertz half-width a, the distance rolled,
/// how many steps' files steps/ will hold, and a note when the history ends before about 4a,
/// the distance over which a change of load settles (docs/transient.md: Cattaneo to Carter
/// within 1e-3 μp0 from about 4.5a, the BEM braking step from about 3.8a). The rest of the
/// report is the history's steady problem: `rollbem run` alone solves the history.
fn transient_lines(case: &LoadedCase, scene: &Scene, t: &mut String) {
    let Some(spec) = &case.case.transient else { return };
    let c = &case.case;
    let l = &c.units.length;
    let spacing = scene.grid.node_spacing();
    let step = spec.step_length(c.load.speed, spacing);
    let a = scene.estimates.hertz_half_width;
    let rolled = step * spec.steps as f64;
    let written = (0..=spec.steps).filter(|&k| spec.writes_step(k, spec.steps)).count();
    let mut line = |k: &str, v: String| t.push_str(&format!("  {k:<26} {v}\n"));
    line(
        "transient history",
        format!(
            "{} rolling steps of {step:.6} {l} ({:.3} node spacings, {:.4}a) after step 0, rolled {rolled:.4} {l} \
             = {:.2}a; steps/ will hold {written} steps' files; `rollbem run` solves the history, the rest \
             of this report is its steady problem",
            spec.steps,
            step / spacing,
            step / a,
            rolled / a
        ),
    );
    if let Some(length) = spec.datum_length {
        line(
            "",
            format!(
                "displacement datum: a half-plane pair's from the datum length L = {length} {l} (a strip of \
                 width b of a 3D half-space has L = b·e^(ν/(1−ν))), not the grid's upstream end"
            ),
        );
    }
    if let Some(side) = spec.initial_slip {
        use crate::case::transient::InitialSlipKey;
        let start = match side {
            InitialSlipKey::Warm => "from the last step's state",
            InitialSlipKey::Below => "from below (mu = mu_s at every node)",
            InitialSlipKey::Above => "from above (mu = mu_k at every node)",
        };
        line(
            "",
            format!("each rolling step's solve under the falling law starts {start}"),
        );
    }
    if rolled < 4.0 * a {
        line(
            "",
            format!(
                "note: the history ends after {:.2}a; a change of load settles over about 4a to 5a \
                 (docs/transient.md), so its last step may not be steady yet (summary.json says)",
                rolled / a
            ),
        );
    }
}

/// The bodies as understood, their meshes' groups, loops and contact segments, and how their contact nodes meet the grid.
fn mesh_lines(case: &LoadedCase, scene: &Scene, t: &mut String) -> Result<(), Error> {
    let (bodies, grid) = (&scene.bodies, &scene.grid);
    let c = &case.case;
    let mut line = |k: &str, v: String| t.push_str(&format!("  {k:<26} {v}\n"));
    for (side, spec) in [("A", &c.bodies.a), ("B", &c.bodies.b)] {
        let text = crate::scene::registry::describe(case, spec, bodies[if side == "A" { 0 } else { 1 }].as_ref());
        line(&format!("body {side}"), text);
    }
    let mut ranges = Vec::new();
    for (side, body) in ["A", "B"].iter().zip(bodies) {
        let Some(own) = body.contact_mesh() else { continue };
        let lm = own.mesh;
        for (g, group) in lm.mesh.groups.iter().enumerate() {
            line(
                &format!("  {side}: group `{}`", group.name),
                format!(
                    "{} elements, length {:.6} {}",
                    lm.mesh.count_in_group(g),
                    lm.group_length(g),
                    c.units.length
                ),
            );
        }
        let loops = crate::mesh::check::boundary_loops(&lm.mesh)?;
        let holes = loops.iter().filter(|l| l.is_hole()).count();
        line(
            &format!("  {side}: loops"),
            format!("{} ({} outer, {holes} holes)", loops.len(), loops.len() - holes),
        );
        for n in &lm.notices {
            line(&format!("  {side}: notice"), n.clone());
        }
        let [x0, x1] = lm.contact_range();
        ranges.push([x0, x1]);
        line(
            &format!("  {side}: contact segment"),
            format!(
                "x in [{x0:.6}, {x1:.6}] {l}, profile radius {:.6} {l}",
                body.radius(),
                l = c.units.length
            ),
        );
    }
    for ((side, body), spec) in ["A", "B"].iter().zip(bodies).zip([&c.bodies.a, &c.bodies.b]) {
        let Some(own) = body.contact_mesh() else { continue };
        let own = own.mesh.contact_grid();
        // A body rollbem meshes itself (`geometry:`) has its contact nodes on the exact circle,
        // and the mesh is not the user's to refine: the advice about the mesh does not apply.
        let generated = crate::scene::registry::is_generated(spec);
        if own.coincides_with(grid) {
            line(
                &format!("  {side}: contact nodes"),
                "paired node to node with the contact grid".into(),
            );
        } else {
            let ratio = own.element_length() / grid.element_length();
            let advice = if ratio <= 0.5 {
                "fine enough"
            } else if generated {
                "meshed by rollbem from `geometry:`, its nodes on the exact circle, so the transfer adds nothing beyond the grid's own error (a roller of radius 40 in a ring of bore 50 at a/R = 0.2: the creepage on its 21-element grid within 0.26 % of the grid refined to contact.grid.tolerance 1e-4); for more accuracy set contact.grid.tolerance"
            } else {
                "coarser than half the grid's elements: the transferred slip loses accuracy (about 8 % of the creepage at equal size); mesh the contact group at most half the grid's element length, or match the nodes"
            };
            line(
                &format!("  {side}: contact nodes"),
                format!("transferred to the grid by interpolation (element length ratio {ratio:.2}: {advice})"),
            );
        }
    }
    if let [[a0, a1], [b0, b1]] = ranges.as_slice() {
        let overlap = a1.min(*b1) - a0.max(*b0);
        line(
            "contact segments",
            if overlap > 0.0 {
                format!("A and B overlap on [{:.6}, {:.6}]", a0.max(*b0), a1.min(*b1))
            } else {
                "A and B DO NOT overlap in x: the bodies cannot touch there".to_string()
            },
        );
    }
    Ok(())
}

/// The estimates of the contact (Hertz's, or a body's own) and the grid around it.
fn estimate_lines(case: &LoadedCase, scene: &Scene, t: &mut String) {
    let (est, grid) = (&scene.estimates, &scene.grid);
    let c = &case.case;
    let mut line = |k: &str, v: String| t.push_str(&format!("  {k:<26} {v}\n"));
    let (l, f) = (&c.units.length, &c.units.force);
    line("effective radius R", format!("{:.6} {l}", est.effective_radius));
    line("contact modulus E*", format!("{:.6} {f}/{l}^2", est.e_star));
    // β/μ orders the coupling's effect; without friction the tangential problem is empty and
    // the ratio says nothing (an infinity printed in full would be 300 digits).
    let per_friction = match c.contact.friction > 0.0 {
        true => format!("beta/mu = {:.4}", est.dundurs_beta / c.contact.friction),
        false => "beta/mu undefined (frictionless)".to_string(),
    };
    line(
        "Dundurs beta (kappa=2beta)",
        format!(
            "{:.6} ({:.6}); {per_friction}",
            est.dundurs_beta,
            2.0 * est.dundurs_beta
        ),
    );
    let given = matches!(c.load.normal(), NormalSpec::Force(_));
    line(
        "normal force P",
        format!(
            "{:.6} {f}/{l}{}",
            est.normal_force,
            if given { "" } else { " (estimated from the overlap)" }
        ),
    );
    // A body's own scales (a cover on its core) replace Hertz's, said as such.
    let (name, by) = match est.scales_from {
        Some(model) => ("contact", format!("; frictionless, from the {model}'s own compliance")),
        None => ("Hertz", String::new()),
    };
    line(
        &format!("{name} half-width a"),
        format!(
            "{:.6} {l}  (a/R = {:.3e}{by})",
            est.hertz_half_width, est.half_width_over_radius
        ),
    );
    line(
        &format!("{name} peak pressure p0"),
        format!("{:.6} {f}/{l}^2", est.hertz_peak_pressure),
    );
    let from_mesh = if scene.grid_from_mesh() {
        " (from the bem mesh)"
    } else {
        ""
    };
    line(
        "contact grid",
        format!(
            "{} {} elements on [{:.6}, {:.6}] {l}{from_mesh}; node spacing {:.4e} {l} ({:.4} a)",
            grid.n_elements(),
            grid.kind.name(),
            grid.edges[0],
            grid.edges[grid.n_elements()],
            grid.node_spacing(),
            grid.node_spacing() / est.hertz_half_width
        ),
    );
    if let Some(w) = est.carter_stick_width {
        line(
            "stick zone (Carter)",
            format!(
                "width {:.6} {l} = {:.4} a, at the leading edge (similar bodies; beta shifts it)",
                w,
                w / est.hertz_half_width
            ),
        );
    }
}

/// The model advice (the half-space's estimated error against the true geometry) and the validity warnings.
fn advice_lines(case: &LoadedCase, scene: &Scene, tolerance: f64, t: &mut String) {
    let (bodies, est) = (&scene.bodies, &scene.estimates);
    let c = &case.case;
    let l = &c.units.length;
    let mut line = |k: &str, v: String| t.push_str(&format!("  {k:<26} {v}\n"));
    // The half-space error of the scene: a roller in a bore's if a body is concave (the
    // family's ring has its rim fixed 0.3 bore radii under the contact, so its error includes
    // that wall's), a layer's if a bem body is held fixed closer under its contact than half its
    // radius (a cover layer on a core), else the rollers'.
    let layer = bodies
        .iter()
        .filter_map(|b| b.layer_thickness())
        .fold(f64::INFINITY, f64::min);
    let error = if crate::scene::validity::convex_radius_in_a_bore(bodies).is_some() {
        crate::scene::validity::half_space_error(bodies, est)
    } else if layer.is_finite() {
        // Under overlap control the half-plane estimate of a means nothing for a layer; the
        // thin-layer chord a² = 2Rδ0 (compressible) or 6Rδ0 (ν = 0.5) does (the thin-layer limit of docs/tyre.md).
        let a = match c.load.normal() {
            NormalSpec::Overlap(d) => {
                let incompressible = bodies
                    .iter()
                    .any(|b| b.hertz_material().is_some_and(|m| m.poisson > 0.45));
                ((if incompressible { 6.0 } else { 2.0 }) * est.effective_radius * d).sqrt()
            }
            NormalSpec::Force(_) => est.hertz_half_width,
        };
        line(
            "layer thickness b",
            format!("{layer:.6} {l} (b/a = {:.4}, a = {a:.4} {l})", layer / a),
        );
        crate::advice::layer_error(layer / a)
    } else {
        crate::scene::validity::half_space_error(bodies, est)
    };
    // The advice weighs half-space against true geometry for the bodies it concerns; a
    // layer's own idealisation or a rigid body's is not that question.
    let concerned: Vec<_> = bodies.iter().filter(|b| b.shares_half_space_error()).collect();
    let advice = if crate::scene::validity::half_plane_share(bodies) == 0.0 {
        format!(
            "no compliant body is a half-space or a true geometry a half-space could replace ({} / {}): \
             the half-space advice does not apply (docs/choosing-a-model.md)",
            bodies[0].model_name(),
            bodies[1].model_name()
        )
    } else if concerned.iter().all(|b| b.has_true_geometry_model()) {
        crate::advice::advise(&error, tolerance)
    } else {
        crate::advice::advise_without_alternative(&error)
    };
    line("model advice", advice);
    for w in crate::scene::validity::warnings(bodies, est, None) {
        line("warning", w);
    }
}

/// The error control, and the cost and memory of the run and of the other model.
fn cost_lines(case: &LoadedCase, scene: &Scene, t: &mut String) -> Result<(), Error> {
    let c = &case.case;
    let mut line = |k: &str, v: String| t.push_str(&format!("  {k:<26} {v}\n"));
    if let Some(tol) = c.contact.grid.tolerance {
        line(
            "error control",
            format!(
                "contact.grid.tolerance {tol:e}: the grid above is the start, refined towards the contact \
                 edges and stick/slip points until the estimated RMS errors of p/p0 and q/(mu p0) and \
                 the creepage's relative error are below it, at most {} elements (docs/theory.md)",
                c.contact.grid.max_elements
            ),
        );
    }
    let (this, other) = costs(scene);
    let this = if c.contact.grid.tolerance.is_some() {
        format!("{this} for the start grid; the refined grids cost more (docs/performance.md)")
    } else {
        this
    };
    line("cost of this run", this);
    line("cost with the other model", other);
    let memory = crate::scene::preflight::check_memory(&scene.case, &scene.bodies)?;
    let available = crate::limits::available_memory().map_or("unknown".into(), crate::limits::human_bytes);
    let grid = &scene.case.case.contact.grid;
    line(
        "memory estimate",
        match grid.tolerance {
            None => format!(
                "{} at most (the bound that refuses cases larger than the memory available: {available})",
                crate::limits::human_bytes(memory.bytes()),
            ),
            Some(tolerance) => format!(
                "{} for the grid of about {} elements the tolerance is expected to need (the bound that \
                 refuses cases; the run stops refining before a grid larger than the memory available: \
                 {available})",
                crate::limits::human_bytes(memory.bytes()),
                crate::scene::preflight::expected_elements(tolerance, grid.max_elements)
            ),
        },
    );
    Ok(())
}

/// The estimated cost of the case as it stands and with the other model: BEM rollers on shafts
/// in place of half-spaces, or half-spaces in place of `bem` bodies ([`cost`]).
fn costs(scene: &Scene) -> (String, String) {
    let output = &scene.fields;
    let sizes = cost::Sizes {
        contact_nodes: scene.grid.n_nodes(),
        bem_bodies: scene
            .bodies
            .iter()
            .filter_map(|b| b.contact_mesh())
            .map(|own| (own.mesh.mesh.nodes.len(), own.mesh.mesh.elements.len()))
            .collect(),
        interior_points: output.interior.as_ref().map_or(0, |i| (i.x[2] * i.y[2]) as usize),
        vtk: output.vtk,
        kernel_evaluations: [crate::body::Side::A, crate::body::Side::B]
            .into_iter()
            .zip(&scene.bodies)
            .map(|(side, b)| {
                b.kernel_table_evaluations(&crate::body::BuildContext {
                    grid: &scene.grid,
                    side,
                    rolling: scene.rolling(),
                    pair: None,
                    responses_only: false,
                    run: None,
                })
            })
            .sum(),
    };
    let elements = scene.grid.n_elements();
    let bodies = match sizes.bem_bodies.as_slice() {
        [] => String::new(),
        b => format!(
            ", bem bodies of {} boundary elements",
            b.iter().map(|(_, e)| e.to_string()).collect::<Vec<_>>().join(" and ")
        ),
    };
    let this = format!(
        "{} ({} contact nodes{bodies}; estimated for the 2-core development machine of docs/performance.md)",
        cost::Cost::of(&sizes).describe(),
        sizes.contact_nodes
    );
    let other = if sizes.bem_bodies.is_empty() {
        let roller = cost::roller_mesh(elements);
        let rollers = cost::Sizes {
            bem_bodies: vec![roller; 2],
            kernel_evaluations: 0.0,
            ..sizes.clone()
        };
        format!(
            "{} with bem rollers on shafts ({} boundary elements each)",
            cost::Cost::of(&rollers).describe(),
            roller.1
        )
    } else {
        let half = cost::Sizes {
            bem_bodies: Vec::new(),
            ..sizes.clone()
        };
        format!("{} with half_space bodies", cost::Cost::of(&half).describe())
    };
    (this, other)
}
