//! The viscoelastic half-space (a standard linear solid in steady rolling) against its exact
//! limits, CONTACT's published `visc_cylindr` example (Wang & Knothe 1993) and the symmetry
//! of the rolling direction. docs/viscoelastic.md reports the numbers.

use crate::common::solve;
use crate::viscoelastic_report::{exact_rows, solve_exact_row, RADIUS_SCALE};
use rollbem::app::Solved;

fn peak(s: &Solved) -> f64 {
    s.solution.pressure.iter().fold(0.0_f64, |m, &p| m.max(p))
}

/// Largest nodal difference of p and q between two runs on the same grid, over the first's
/// peak pressure, and the relative creepage difference.
fn differences(a: &Solved, b: &Solved) -> (f64, f64, f64) {
    assert_eq!(a.solution.x, b.solution.x, "the same grid");
    let p0 = peak(a);
    let max = |u: &[f64], v: &[f64]| u.iter().zip(v).map(|(x, y)| (x - y).abs()).fold(0.0, f64::max) / p0;
    (
        max(&a.solution.pressure, &b.solution.pressure),
        max(&a.solution.shear, &b.solution.shear),
        (a.solution.creep / b.solution.creep - 1.0).abs(),
    )
}

/// τc → 0: all the creep happens at once, the rubbery elastic half-space. At τc = 1e-12 s the
/// creep length L = Vτc = 1e-9 mm is 1.6e-8 of an element, and the aged kernels differ from the
/// elastic ones by at most O((L/h)·ln(h/L)) ≈ 3e-7; measured 7e-10 of p0 in p and 1.4e-10 in
/// the creepage. We allow 1e-8, in partial slip (Q/μP = −0.6) and frictionless.
#[test]
fn vanishing_creep_time_gives_the_rubbery_elastic_solution() {
    for load in ["load.tangential.ratio=-0.6", "load.tangential.ratio=0"] {
        let visco = solve(
            "visc_cylindr_tc0009",
            &[load, "materials.pa6.viscoelastic.creep_time=1e-12"],
        );
        let elastic = solve(
            "visc_cylindr_tc0009",
            &[load, "materials.pa6.viscoelastic=null", "materials.pa6.G=571.5"],
        );
        let (dp, dq, dxi) = differences(&visco, &elastic);
        assert!(dp < 1e-8 && dq < 1e-8, "{load}: |Δp| = {dp:e} p0, |Δq| = {dq:e} p0");
        if elastic.solution.creep != 0.0 {
            assert!(dxi < 1e-8, "{load}: creepage differs by {dxi:e}");
        }
        assert!((visco.solution.overlap - elastic.solution.overlap).abs() < 1e-6 * elastic.solution.overlap);
    }
}

/// τc → ∞: the material has no time to creep, the glassy elastic half-space. The aged part of
/// each kernel tends to a constant (a rigid shift of the bodies, which moves the overlap only)
/// plus O(h/L) = 1e-13 at τc = 1e9 s; the large constant (ln L ≈ 28) costs digits: measured
/// 1e-9 of p0, 1.5e-11 in the creepage, allowed 1e-8. Compared on one grid (half_length fixed: the viscoelastic
/// body sizes its grid from the rubbery modulus, the glassy one from the glassy).
#[test]
fn unbounded_creep_time_gives_the_glassy_elastic_solution() {
    for load in ["load.tangential.ratio=-0.6", "load.tangential.ratio=0"] {
        let grid = "contact.grid.half_length=7.3";
        let visco = solve(
            "visc_cylindr_tc0009",
            &[load, grid, "materials.pa6.viscoelastic.creep_time=1e9"],
        );
        let elastic = solve("visc_cylindr_tc0009", &[load, grid, "materials.pa6.viscoelastic=null"]);
        let (dp, dq, dxi) = differences(&visco, &elastic);
        assert!(dp < 1e-8 && dq < 1e-8, "{load}: |Δp| = {dp:e} p0, |Δq| = {dq:e} p0");
        if elastic.solution.creep != 0.0 {
            assert!(dxi < 1e-8, "{load}: creepage differs by {dxi:e}");
        }
    }
}

/// CONTACT's `visc_cylindr` (its reference output, rev 2707; grid spacing 0.16 mm, piecewise
/// constant elements): for τc = 0 / 0.009 / 0.045 / 2.0 s, |creepage| 1.378e-2 / 1.365e-2 /
/// 1.152e-2 / 9.932e-3, p_max 60.32 / 78.74 / 84.72 / 85.31 N/mm², contact width 12.8 / 9.9 /
/// 9.1 / 9.0 mm. Ours at tolerance 1e-4 (its estimate bounds our own error far below CONTACT's).
/// * p_max within 0.1 % (CONTACT prints four digits; its elastic p_max is within 0.01 % of Hertz);
/// * width within two of CONTACT's cells (0.32 mm): it counts whole cells in contact;
/// * creepage within 2 %: CONTACT's elastic creepage (τc = 0) lies 1.3 % below Carter's exact
///   1.39651e-2 (its O(h) slip discretisation), so its viscoelastic ones carry errors of that
///   size too. The exact circle profile rollbem uses against CONTACT's parabola moves ours
///   by ≈ (a/2R)² ≈ 0.1 %.
#[test]
fn contact_visc_cylindr_reference_within_its_discretisation_error() {
    let reference = [
        ("visc_cylindr_tc0", 1.378e-2, 60.32, 12.8),
        ("visc_cylindr_tc0009", 1.365e-2, 78.74, 9.9),
        ("visc_cylindr_tc0045", 1.152e-2, 84.72, 9.1),
        ("visc_cylindr_tc2", 9.932e-3, 85.31, 9.0),
    ];
    let mut previous: Option<(f64, f64)> = None;
    for (case, creep, p_max, width) in reference {
        let s = solve(case, &["contact.grid.tolerance=1e-4"]);
        let [x0, x1] = s.solution.contact_extent().unwrap();
        let (xi, p) = (s.solution.creep.abs(), peak(&s));
        assert!((p / p_max - 1.0).abs() < 1e-3, "{case}: p_max {p} vs CONTACT {p_max}");
        assert!(
            ((x1 - x0) - width).abs() < 0.32,
            "{case}: width {} vs CONTACT {width}",
            x1 - x0
        );
        assert!((xi / creep - 1.0).abs() < 0.02, "{case}: |ξ| {xi} vs CONTACT {creep}");
        // Both agree on the trend: a slower material creeps less in the contact, the contact
        // narrows and stiffens, the creepage drops.
        if let Some((xi_prev, p_prev)) = previous {
            assert!(xi < xi_prev && p > p_prev, "{case}: trend");
        }
        previous = Some((xi, p));
    }
    // The elastic limit against Carter's exact creepage with the rubbery modulus (1.39651e-2).
    let s = solve("visc_cylindr_tc0", &["contact.grid.tolerance=1e-4"]);
    assert!(
        (s.solution.creep.abs() / 1.39651e-2 - 1.0).abs() < 2e-3,
        "ξ = {}",
        s.solution.creep
    );
}

/// Rolling the other way mirrors the solution: the pressure leans towards the new leading edge
/// (−x) by the same amount, and the rolling resistance keeps its value and sign.
#[test]
fn reversing_the_rolling_direction_mirrors_the_asymmetry() {
    let forward = solve("visc_cylindr_tc0009", &["load.tangential.ratio=0"]);
    let backward = solve(
        "visc_cylindr_tc0009",
        &["load.tangential.ratio=0", "contact.rolling_direction=-x"],
    );
    let r = |s: &Solved| {
        let summary = rollbem::output::summary::summary(s);
        summary.rolling_resistance.expect("in contact")
    };
    let (f, b) = (r(&forward), r(&backward));
    assert!(f.coefficient > 1e-3, "resistance {}", f.coefficient);
    assert!((f.coefficient / b.coefficient - 1.0).abs() < 1e-9, "{f:?} vs {b:?}");
    assert!((f.leading_edge + b.leading_edge).abs() < 1e-9 && (f.trailing_edge + b.trailing_edge).abs() < 1e-9);
    assert!(f.leading_edge > 0.0 && f.pressure_centre > 0.0);
}

/// Energy balance: the power F_r·V the rolling resistance costs equals the power the two
/// bodies' material dissipates, computed independently inside them from the stress history
/// along the material paths (frictionless, so that the pressure alone loads them).
///
/// The standard linear solid as a spring E_g in series with a Kelvin unit (E_k, η_k),
/// 1/E_k = 1/E_r − 1/E_g, τc = η_k/E_k: with ν constant its strain is S:σ/E_g + S:σ̄/E_k, with
/// S the unit-modulus compliance, ε_ij = (1+ν)σ_ij − ν δ_ij σ_kk, and σ̄ the stress filtered along
/// the path, σ̄(x) = ∫_0^∞ e^(−v) σ(x + L v) dv (L = Vτc, the material coming from +x). The
/// dashpot dissipates D = (σ − σ̄):S:(σ − σ̄)/(E_k τc) per unit volume and time. The stresses
/// are Flamant's (any homogeneous half-plane's under given tractions, out of plane
/// σ_yy = ν(σxx + σzz)), filtered exactly for stresses linear between the points of a graded
/// grid along each path, and ∫∫ D dx dz is taken over depths to `reach`. Agreement within
/// 0.5 %; the quadrature and the truncation of the domain are measured in
/// docs/viscoelastic.md (this grid against one with half the spacings and twice the reach).
#[test]
fn rolling_resistance_power_equals_the_dissipation_inside_the_bodies() {
    let (s, power) = energy_balance_run();
    let dissipated = dissipation_inside(&s, 0.009, 1.0, 20.0);
    assert!(
        (dissipated / power - 1.0).abs() < 5e-3,
        "dissipated inside {dissipated:.6e}, F_r·V = {power:.6e}"
    );
}

/// The frictionless visc_cylindr run of the energy balance (τc = 0.009 s, 120 elements) and its
/// power F_r·V.
fn energy_balance_run() -> (Solved, f64) {
    let s = solve(
        "visc_cylindr_tc0009",
        &["load.tangential.ratio=0", "contact.grid.elements=120"],
    );
    let power = rollbem::output::summary::summary(&s)
        .rolling_resistance
        .unwrap()
        .dissipated_power
        .unwrap();
    (s, power)
}

/// The power the two identical bodies of a visc_cylindr run dissipate (the energy-balance
/// test's docs), with the path and depth spacings divided by `refine` and depths and paths out
/// to `reach`·max(a, L).
fn dissipation_inside(s: &Solved, tc: f64, refine: f64, reach: f64) -> f64 {
    let (e_g, e_r, nu) = (2.0 * 1143.0 * 1.4, 2.0 * 571.5 * 1.4, 0.4);
    let e_k = 1.0 / (1.0 / e_r - 1.0 / e_g);
    let length = 1000.0 * tc;
    let [x0, x1] = s.solution.contact_extent().unwrap();
    let a = 0.5 * (x1 - x0);
    let grid = &s.problem.grid;
    let zero = vec![0.0; s.solution.pressure.len()];
    let stress = |x: f64, z: f64| {
        let st = rollbem::body::flamant::halfplane_stress(grid, &s.solution.pressure, &zero, nu, x, z);
        [st.sxx, st.szz, st.syy, st.txz]
    };
    let reach = reach * a.max(length);
    // Depths: geometric from a/100, 6·refine per factor of 2.
    let ratio = 2f64.powf(1.0 / (6.0 * refine));
    let mut depths = vec![1e-2 * a];
    while *depths.last().unwrap() < reach {
        depths.push(depths.last().unwrap() * ratio);
    }
    let growth = 1.0 + 0.08 / refine;
    let dissipation_at_depth = |z: f64| -> f64 {
        // Path points: spacing min(z/2, a/40) within 2a of the centre, growing geometrically
        // beyond, out to `reach` downstream and reach + 20 L upstream (e^(−20) of the memory).
        let fine = (z / 2.0).min(a / 40.0) / refine;
        let mut xs = Vec::new();
        let (mut down, mut step) = (-2.0 * a, fine);
        while down > -reach {
            step *= growth;
            down -= step;
            xs.push(down);
        }
        xs.reverse();
        let mut x = -2.0 * a;
        while x < 2.0 * a {
            xs.push(x);
            x += fine;
        }
        let (mut up, mut step) = (2.0 * a, fine);
        while up < reach + 20.0 * length {
            xs.push(up);
            step *= growth;
            up += step;
        }
        let sig: Vec<[f64; 4]> = xs.iter().map(|&x| stress(x, z)).collect();
        // σ̄ from upstream (+x) down, exact for σ linear between points: over a step Δ,
        // σ̄_i = e^(−r) σ̄_(i+1) + σ_i (1 − e^(−r)) + (σ_(i+1) − σ_i)(1 − e^(−r)(1 + r))/r, r = Δ/L.
        let n = xs.len();
        let mut filtered = vec![[0.0; 4]; n];
        filtered[n - 1] = sig[n - 1];
        for i in (0..n - 1).rev() {
            let r = (xs[i + 1] - xs[i]) / length;
            let decay = (-r).exp();
            let (w0, w1) = (-(-r).exp_m1(), (1.0 - decay * (1.0 + r)) / r);
            for c in 0..4 {
                filtered[i][c] = decay * filtered[i + 1][c] + sig[i][c] * w0 + (sig[i + 1][c] - sig[i][c]) * w1;
            }
        }
        let density: Vec<f64> = (0..n)
            .map(|i| {
                let d: [f64; 4] = std::array::from_fn(|c| sig[i][c] - filtered[i][c]);
                let trace = d[0] + d[1] + d[2];
                let sq = d[0] * d[0] + d[1] * d[1] + d[2] * d[2] + 2.0 * d[3] * d[3];
                ((1.0 + nu) * sq - nu * trace * trace) / (e_k * tc)
            })
            .collect();
        (0..n - 1)
            .map(|i| 0.5 * (density[i] + density[i + 1]) * (xs[i + 1] - xs[i]))
            .sum()
    };
    use rayon::prelude::*;
    let per_depth: Vec<f64> = depths.par_iter().map(|&z| dissipation_at_depth(z)).collect();
    // D is bounded at the surface: the layer above the first depth as a rectangle.
    let mut body = per_depth[0] * depths[0];
    for k in 0..depths.len() - 1 {
        body += 0.5 * (per_depth[k] + per_depth[k + 1]) * (depths[k + 1] - depths[k]);
    }
    2.0 * body
}

/// The energy balance's quadrature and truncation, for docs/viscoelastic.md:
/// `cargo test --release --test validation energy_balance_convergence -- --ignored --nocapture`.
#[test]
#[ignore = "measurement for the docs (about a minute)"]
fn energy_balance_convergence() {
    let (s, power) = energy_balance_run();
    for (refine, reach) in [(1.0, 20.0), (2.0, 20.0), (1.0, 40.0), (2.0, 40.0)] {
        let d = dissipation_inside(&s, 0.009, refine, reach);
        println!(
            "refine {refine}, reach {reach}·max(a, L): dissipated {d:.6e}, F_r·V {power:.6e}, ratio − 1 = {:+.2e}",
            d / power - 1.0
        );
    }
}

/// Hunter (1961): a rigid cylinder rolling frictionlessly over an SLS half-plane, f = 1 and 9,
/// Vτc/a_r from 0.01 to 100, against the exact solution (its own error below 1e-13 mm). At
/// tolerance 1e-3 the error-controlled grid has to find the leading edge's boundary layer
/// (width Vτc/(1+f), down to 1e-3·a_r) by itself. Measured over the 24 rows (docs/viscoelastic.md):
/// contact edges within 2e-3·a_r, p_max within 3e-4, the pressure centre within 6e-6·a_r.
/// Allowed: edges 5e-3·a_r (an edge is placed to within the grid spacing there), p_max 1e-3
/// (the tolerance on p/p0), the pressure centre 1e-4·a_r and so F_r/P = x_p/R within 2e-6 (an
/// integral of p: its errors average out; a tenth of the tolerance times a_r). The resistance
/// peaks near Vτc ≈ a_r and vanishes at both ends: checked on the computed values.
#[test]
fn hunter_rigid_cylinder_on_a_standard_linear_solid() {
    let rows = exact_rows();
    assert_eq!(rows.len(), 24, "12 speeds for f = 1 and 9");
    let a_r = 2.0;
    for f in [1.0, 9.0] {
        let mut coefficients = Vec::new();
        for row in rows.iter().filter(|r| r.f == f) {
            // Hunter's parabola against rollbem's circle: R and P scaled the other way (a kept)
            // make the profiles agree to 1e-12 instead of (a/2R)² ≈ 1e-4 (RADIUS_SCALE).
            let s = solve_exact_row(row, &["contact.grid.tolerance=1e-3"]);
            let r = rollbem::output::summary::summary(&s).rolling_resistance.unwrap();
            let label = format!("f = {f}, Vτc/a_r = {}", row.v_tau_over_a_r);
            assert!(
                (r.leading_edge - row.edges[0]).abs() < 5e-3 * a_r,
                "{label}: leading edge {} vs {}",
                r.leading_edge,
                row.edges[0]
            );
            assert!(
                (r.trailing_edge - row.edges[1]).abs() < 5e-3 * a_r,
                "{label}: trailing edge {} vs {}",
                r.trailing_edge,
                row.edges[1]
            );
            let p_max = peak(&s) * RADIUS_SCALE;
            assert!(
                (p_max / row.p_max - 1.0).abs() < 1e-3,
                "{label}: p_max {p_max} vs {}",
                row.p_max
            );
            assert!(
                (r.pressure_centre - row.x_p).abs() < 1e-4 * a_r,
                "{label}: x_p {} vs {}",
                r.pressure_centre,
                row.x_p
            );
            let coefficient = r.coefficient * RADIUS_SCALE;
            assert!(
                (coefficient - row.fr_over_p).abs() < 2e-6,
                "{label}: F_r/P {coefficient} vs {}",
                row.fr_over_p
            );
            coefficients.push((row.v_tau_over_a_r, coefficient));
        }
        let (peak_at, _) = coefficients
            .iter()
            .copied()
            .fold((0.0, 0.0), |m, c| if c.1 > m.1 { c } else { m });
        assert!((0.5..=2.0).contains(&peak_at), "f = {f}: peak at Vτc/a_r = {peak_at}");
        let top = coefficients.iter().map(|c| c.1).fold(0.0, f64::max);
        assert!(coefficients[0].1 < 0.05 * top && coefficients.last().unwrap().1 < 0.1 * top);
    }
}

/// Inside the body: the aged interior displacement tends to the surface displacement the
/// flexibility gives (the same ageing, the same datum) as the depth goes to zero, linearly in
/// the depth (the strain is bounded): the differences at depths h/2, h/4, h/8 (h the element
/// length) halve with the depth, and at h/8 they are below 1 % of the displacement.
#[test]
fn interior_displacements_meet_the_surface_ones() {
    use rollbem::body::{BuildContext, ContactLoad, InteriorQuery, Side};
    use rollbem::interior::{InteriorOptions, InteriorSample};
    let s = solve("visc_cylindr_tc0009", &["load.tangential.ratio=0"]);
    let grid = &s.problem.grid;
    let ctx = BuildContext {
        grid,
        side: Side::B,
        rolling: s.scene.rolling(),
        pair: None,
        responses_only: false,
        run: None,
    };
    let body = s.scene.bodies[1].build(&ctx).unwrap();
    let (p, q) = (&s.solution.pressure, &s.solution.shear);
    let surface = body.model().flexibility(grid, Side::B).normal(p, q);
    let load = ContactLoad {
        grid,
        pressure: p,
        shear: q,
    };
    let h = grid.element_length();
    // Nodes in the contact's middle and near its leading edge.
    let nodes: Vec<usize> = [0.0, 0.6 * 5.8]
        .iter()
        .map(|&x: &f64| {
            (0..grid.n_nodes())
                .min_by(|&a, &b| (grid.nodes[a] - x).abs().total_cmp(&(grid.nodes[b] - x).abs()))
                .unwrap()
        })
        .collect();
    for &i in &nodes {
        let differences: Vec<f64> = [0.5, 0.25, 0.125]
            .iter()
            .map(|f| {
                let points = [[grid.nodes[i], -f * h]];
                let query = InteriorQuery {
                    side: Side::B,
                    load,
                    points: &points,
                    options: InteriorOptions {
                        boundary_layer: 0.01,
                        ..Default::default()
                    },
                };
                let InteriorSample::Inside(v) = body.fields().interior(&query).unwrap()[0] else {
                    panic!("inside B")
                };
                // B's normal displacement into the body is −u_y.
                (-v.displacement[1] - surface[i]).abs()
            })
            .collect();
        assert!(differences[2] < 0.01 * surface[i].abs(), "node {i}: {differences:?}");
        assert!(
            differences[0] > 1.6 * differences[1] && differences[1] > 1.6 * differences[2],
            "node {i}: {differences:?} should halve with the depth"
        );
    }
}

/// The leading edge's relaxation layer (src/adapt.rs, `APriori`): two standard linear solids
/// whose layer V·τe is far narrower than the a-priori length of the edge element, at five creep
/// times and tolerances where an independent audit found the tolerance broken (true errors 1.1–2.1
/// times the tolerance, estimates 0.21–0.67 of the truth), each against its own run at 1e-6
/// (about 500 elements; on the first material at τc 1e-5 s, 3000 uniform elements agree with it
/// to 4e-5 p0, their own edge error). Before the edge was graded to the layer the first two of
/// them missed the tolerance with their estimate below it (1.2e-3 p0 at 1e-3, estimate 2.8e-4;
/// 1.8e-4 at 1e-4, estimate 7.8e-5; docs/theory.md, "Viscoelastic edges"). Now the true RMS
/// error of p must meet the tolerance and the estimate lie within [1/3, 3] of it.
#[test]
fn viscoelastic_edges_meet_the_tolerance_with_a_faithful_estimate() {
    // The audit's five failing runs: (material, creep time τc [s], tolerance).
    let first = |tc: f64| {
        vec![
            format!("materials.rubber={{G: 1143.0, nu: 0.4, viscoelastic: {{G_rubbery: 571.5, creep_time: {tc:e}}}}}"),
            "bodies.A.radius=50".to_string(),
            "load.normal.force=600".to_string(),
            "load.speed=1000".to_string(),
        ]
    };
    let second = |tc: f64| {
        vec![
            format!("materials.rubber={{G: 40.0, nu: 0.5, viscoelastic: {{G_rubbery: 10.0, creep_time: {tc:e}}}}}"),
            "bodies.A.radius=80".to_string(),
            "load.normal.force=6".to_string(),
            "load.speed=200".to_string(),
        ]
    };
    let runs = [
        (first(1e-5), 1e-3),
        (first(1e-2), 1e-4),
        (second(1e-5), 1e-4),
        (second(5e-3), 1e-4),
        (second(0.023), 1e-4),
    ];
    for (set, tolerance) in &runs {
        let tolerance = *tolerance;
        let at = |tol: f64| {
            let mut o = set.clone();
            o.push(format!("contact.grid.tolerance={tol:e}"));
            o.push("contact.grid.max_elements=3000".into());
            let o: Vec<&str> = o.iter().map(String::as_str).collect();
            solve("hunter_rigid_on_sls", &o)
        };
        let (reference, run) = (at(1e-6), at(tolerance));
        let truth = crate::fixed_grid_report::errors_against(&reference, &run)[0];
        let estimate = run
            .adaptation
            .as_ref()
            .and_then(|a| a.estimate)
            .expect("an estimate")
            .pressure_rms;
        println!(
            "{}: tolerance {tolerance:e}, {} elements, true {truth:.2e}, estimate {estimate:.2e}",
            set[0],
            run.problem.grid.n_elements()
        );
        assert!(truth <= tolerance, "true error {truth:e} above {tolerance:e}");
        assert!(
            (truth / 3.0..=3.0 * truth).contains(&estimate),
            "estimate {estimate:e}, true {truth:e}"
        );
        // The peak pressure (summary.json `max_pressure`, the largest value of the pressure's
        // interpolant) within the tolerance of the reference's, relative to the reference's
        // peak: the steep rise at the leading edge puts the peak between nodes.
        let peak_of = |s: &Solved| s.problem.grid.interpolant_max(&s.solution.pressure);
        let p_ref = peak_of(&reference);
        let peak_error = (peak_of(&run) - p_ref).abs() / p_ref;
        let nodal_error = (peak(&run) - p_ref).abs() / p_ref;
        println!("  peak pressure: interpolant {peak_error:.2e}, nodal maximum {nodal_error:.2e}");
        assert!(peak_error <= tolerance, "peak pressure off by {peak_error:e}");
    }
}
