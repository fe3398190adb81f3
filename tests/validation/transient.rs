//! Transient rolling (src/transient.rs) against closed forms: the Cattaneo–Mindlin shift of
//! two similar cylinders pressed together, and the rolling that carries it to Carter's steady
//! state, on the steel rollers of cases/carter_051.yaml (R 100 mm each, a = 1 mm) at μ = 0.3,
//! Q/μP = 0.6.

use rollbem::analytic::Carter;
use rollbem::contact::{NormalControl, TangentialControl};
use rollbem::scene::Scene;
use rollbem::transient::{History, Step, StepSolution};

const FRICTION: f64 = 0.3;
const RATIO: f64 = 0.6;

/// The Carter scene at μ 0.3, Q/μP 0.6 on a uniform grid of `elements`.
fn scene(elements: usize) -> Scene {
    scene_with(elements, "second_order")
}

/// [`scene`] with the steady problem's slip derivative `derivative`.
fn scene_with(elements: usize, derivative: &str) -> Scene {
    let overrides = [
        format!("contact.slip_derivative={derivative}"),
        format!("contact.friction={FRICTION}"),
        format!("load.tangential.ratio={RATIO}"),
        format!("contact.grid.elements={elements}"),
    ];
    let case = rollbem::case::load(&crate::common::case_path("carter_051"), &overrides).expect("loads");
    Scene::from_case(&case).expect("scene")
}

/// Pressed with P, then shifted to Q = 0.6 μP without rolling.
fn cattaneo(history: &mut History, force: f64) -> StepSolution {
    let press = Step {
        distance: 0.0,
        normal: NormalControl::Force(force),
        tangential: TangentialControl::Ratio(0.0),
    };
    history.advance(press).expect("pressed");
    history
        .advance(Step {
            tangential: TangentialControl::Ratio(RATIO),
            ..press
        })
        .expect("shifted")
}

/// RMS over the Hertz contact of q − `exact`, over μp0.
fn rms_error(x: &[f64], q: &[f64], exact: impl Fn(f64) -> f64, carter: &Carter) -> f64 {
    let w = rollbem::post::norms::node_lengths(x);
    let (mut sum, mut length) = (0.0, 0.0);
    for i in (0..x.len()).filter(|&i| x[i].abs() < carter.half_width) {
        sum += w[i] * (q[i] - exact(x[i])).powi(2);
        length += w[i];
    }
    (sum / length).sqrt() / (carter.friction * carter.peak_pressure)
}

/// Cattaneo–Mindlin: q(x) = μp0[√(1 − x²/a²) − (c/a)√(1 − x²/c²)], the inner term on |x| < c,
/// c = a√(1 − Q/μP) (Johnson, Contact Mechanics, 1985, §7.1, Eq. 7.18 in 2D).
fn cattaneo_shear(carter: &Carter, x: f64) -> f64 {
    let (a, mu_p0) = (carter.half_width, carter.friction * carter.peak_pressure);
    let c = a * (1.0 - RATIO).sqrt();
    let outer = (1.0 - (x / a).powi(2)).max(0.0).sqrt();
    let inner = if x.abs() < c {
        (c / a) * (1.0 - (x / c).powi(2)).sqrt()
    } else {
        0.0
    };
    mu_p0 * (outer - inner)
}

/// Step 0 of a history: pressed, then shifted to Q = 0.6μP without rolling. The shear is
/// Cattaneo–Mindlin's to the grid's error: RMS 1.7e-3, 2.4e-3, 5.6e-4 and 3.3e-4 μp0 on 21,
/// 41, 81 and 161 elements.
#[test]
fn a_shift_without_rolling_gives_cattaneo_mindlin() {
    let mut errors = Vec::new();
    for elements in [21, 41, 81, 161] {
        let scene = scene(elements);
        let carter = scene.carter_reference().expect("a ratio");
        let force = match scene.normal {
            NormalControl::Force(p) => p,
            _ => unreachable!("carter_051 gives P"),
        };
        let mut history = History::new(&scene).expect("a history");
        let shifted = cattaneo(&mut history, force);
        let e = rms_error(
            &history.grid().nodes,
            &shifted.state.shear,
            |x| cattaneo_shear(&carter, x),
            &carter,
        );
        eprintln!(
            "{elements} elements: RMS error {e:.3e} μp0, shift {:.4e} mm, {} iterations",
            shifted.state.creep, shifted.iterations
        );
        errors.push(e);
    }
    // The stick/slip point c = 0.632a lies inside an element on every grid, where q has a
    // square-root kink: the RMS error falls unevenly, as h^0.8 from 21 to 161 elements.
    let order = (errors[0] / errors[3]).ln() / 8f64.ln();
    eprintln!("order from 21 to 161 elements: {order:.2}");
    assert!(errors.iter().all(|&e| e < 3e-3), "{errors:?}");
    assert!(errors[3] < 4e-4 && order > 0.5, "{errors:?}, order {order}");
}

/// Rolls the Cattaneo state of `elements` for `distance` in steps of `per_element` element
/// lengths: the steps and the steady solution of the same grid.
fn rolled(elements: usize, distance: f64, per_element: f64) -> (Scene, Vec<StepSolution>, Vec<f64>) {
    let scene = scene(elements);
    let force = match scene.normal {
        NormalControl::Force(p) => p,
        _ => unreachable!("carter_051 gives P"),
    };
    let mut history = History::new(&scene).expect("a history");
    let mut steps = vec![cattaneo(&mut history, force)];
    let delta = per_element * history.grid().element_length();
    let n = (distance / delta).round() as usize;
    for _ in 0..n {
        let step = Step {
            distance: delta,
            normal: NormalControl::Force(force),
            tangential: TangentialControl::Ratio(RATIO),
        };
        steps.push(history.advance(step).expect("rolls"));
    }
    let (_, problem) = scene.assemble().expect("assembles");
    let (steady, report) = rollbem::contact::methods::solve(&problem, &scene.solver);
    assert!(report.converged);
    (scene, steps, steady.shear)
}

/// The largest difference of two nodal fields, over `scale`.
fn max_difference(a: &[f64], b: &[f64], scale: f64) -> f64 {
    a.iter().zip(b).map(|(a, b)| (a - b).abs()).fold(0.0, f64::max) / scale
}

/// Rolling at Q/μP 0.6 from the Cattaneo state on 81 elements, one node spacing a step: the
/// stick zone moves from the centre to the leading edge and the history settles on the steady
/// state of the same grid whose slip is the first-order upwind difference (the paper's Eq. 8:
/// a step of one node spacing is exactly that difference, see src/transient.rs) — within
/// 1e-6 μp0 in q, 1e-9 p0 in p and 1e-6 in ξ after 8a; within 1e-3 μp0 from about 4.5a on.
/// The settled traction lies within 2e-3 μp0 (RMS) of Carter's closed form, the
/// discretisation error of the first-order slip (the second-order steady solver: 6.7e-4).
/// Warm-started, a step takes 1.1 Newton iterations on average (at most 3 expected).
#[test]
fn rolling_carries_cattaneo_to_carter() {
    let (scene, steps, _) = rolled(81, 8.0, 1.0 / 3.0);
    let first_order = scene_with(81, "first_order");
    let (_, problem) = first_order.assemble().expect("assembles");
    let (steady, report) = rollbem::contact::methods::solve(&problem, &first_order.solver);
    assert!(report.converged);
    let carter = scene.carter_reference().expect("a ratio");
    let (p0, mu_p0) = (carter.peak_pressure, carter.friction * carter.peak_pressure);
    let last = &steps.last().expect("steps").state;
    let dq = max_difference(&last.shear, &steady.shear, mu_p0);
    let dp = max_difference(&last.pressure, &steady.pressure, p0);
    let dxi = (last.creep / steady.creep - 1.0).abs();
    let within = |tol: f64| {
        steps
            .iter()
            .find(|s| max_difference(&s.state.shear, &steady.shear, mu_p0) < tol)
            .map(|s| s.rolled / carter.half_width)
    };
    let carter_rms = rms_error(&scene.grid.nodes, &last.shear, |x| carter.shear(x), &carter);
    let iterations = steps[1..].iter().map(|s| s.iterations).sum::<usize>() as f64 / (steps.len() - 1) as f64;
    eprintln!(
        "{} steps: q {dq:.1e} μp0, p {dp:.1e} p0, ξ {dxi:.1e} from the steady state; within 1e-3 μp0 from {:?} a, \
         1e-6 from {:?} a; RMS from Carter {carter_rms:.2e} μp0; {iterations:.2} iterations a step",
        steps.len() - 1,
        within(1e-3),
        within(1e-6)
    );
    assert!(dq < 1e-6 && dp < 1e-9 && dxi < 1e-6, "q {dq:e}, p {dp:e}, ξ {dxi:e}");
    assert!(
        within(1e-3).is_some_and(|d| d > 2.0 && d < 6.0),
        "settles after the contact's width"
    );
    assert!(carter_rms < 2e-3, "RMS from Carter {carter_rms:e}");
    assert!(iterations < 3.0, "{iterations} iterations a step");
    // The stick zone starts at the centre (Cattaneo) and ends at the leading edge (Carter, +x
    // here: the material enters at x = +a).
    let stick_centre = |q: &[f64], p: &[f64]| {
        let x = &scene.grid.nodes;
        let stuck: Vec<f64> = (0..x.len())
            .filter(|&i| p[i] > 0.0 && q[i].abs() < carter.friction * p[i] * (1.0 - 1e-9))
            .map(|i| x[i])
            .collect();
        0.5 * (stuck[0] + stuck[stuck.len() - 1])
    };
    let start = stick_centre(&steps[0].state.shear, &steps[0].state.pressure);
    let end = stick_centre(&last.shear, &last.pressure);
    let carter_centre = carter.stick_centre();
    eprintln!("stick centre {start:+.3} -> {end:+.3} (Carter {carter_centre:+.3})");
    assert!(
        start.abs() < 0.02 * carter.half_width,
        "Cattaneo's stick zone is centred"
    );
    assert!(
        (end - carter_centre).abs() < 0.03 * carter.half_width,
        "Carter's at the leading edge"
    );
}

/// The history's error against Carter as the step grows, on 81 elements: Δ = 1, 2, 3, 6 and 12
/// node spacings after 6a. A step longer than a node spacing carries material across the
/// leading edge as if it had stuck for the whole step, where it slipped freely while outside:
/// an error of the slip of order (Δ/a)^(1/2) that the measured order (about 0.6) shows.
/// Each grows with Δ, and the largest stays below 5e-2 μp0.
#[test]
fn the_history_converges_as_the_step_shrinks() {
    let mut errors = Vec::new();
    for spacings in [1.0, 2.0, 3.0, 6.0, 12.0] {
        let (scene, steps, _) = rolled(81, 6.0, spacings / 3.0);
        let carter = scene.carter_reference().expect("a ratio");
        let last = &steps.last().expect("steps").state;
        let e = rms_error(&scene.grid.nodes, &last.shear, |x| carter.shear(x), &carter);
        let delta = spacings * scene.grid.node_spacing() / carter.half_width;
        eprintln!("Δ = {delta:.4} a: RMS from Carter {e:.3e} μp0");
        errors.push((delta, e));
    }
    for w in errors.windows(2) {
        assert!(w[1].1 > w[0].1, "the error grows with the step: {errors:?}");
    }
    let (first, last) = (errors[1], errors[errors.len() - 1]);
    let order = (last.1 / first.1).ln() / (last.0 / first.0).ln();
    eprintln!("order from Δ = 2 to 12 node spacings: {order:.2}");
    assert!((0.3..1.2).contains(&order), "order {order}");
    assert!(last.1 < 5e-2);
}

/// The same history on the true geometry (cases/fig14_true_geometry.yaml: BEM rollers on their
/// shafts, dissimilar aluminium on steel, so the pressure and the shear couple) and on a
/// bonded cover (cases/tyre_b05_layer.yaml): pressed, shifted, then rolled 400 steps of one
/// node spacing (about 15a and 11a); each settles on its own first-order steady state of the
/// same grid, the difference decaying geometrically (measured at the end: q 7.5e-9 and 2.2e-7
/// of μp_max, p 1.9e-10 and 5.9e-9 of p_max; within 1e-3 μp_max after about 6a and 4.5a).
#[test]
fn true_geometry_and_a_cover_settle_on_their_own_steady_state() {
    for (name, steps) in [("fig14_true_geometry", 400), ("tyre_b05_layer", 400)] {
        let load = |derivative: &str| {
            let overrides = [format!("contact.slip_derivative={derivative}")];
            let case = rollbem::case::load(&crate::common::case_path(name), &overrides).expect("loads");
            Scene::from_case(&case).expect("scene")
        };
        let scene = load("first_order");
        let (_, problem) = scene.assemble().expect("assembles");
        let (steady, report) = rollbem::contact::methods::solve(&problem, &scene.solver);
        assert!(report.converged);
        let mut history = History::new(&scene).expect("a history");
        let (normal, tangential) = (scene.normal, scene.tangential);
        let mut step = Step {
            distance: 0.0,
            normal,
            tangential: TangentialControl::Ratio(0.0),
        };
        history.advance(step).expect("pressed");
        step.tangential = tangential;
        history.advance(step).expect("shifted");
        step.distance = scene.grid.node_spacing();
        let mut last = None;
        let p0 = steady.pressure.iter().copied().fold(0.0, f64::max);
        for _ in 0..steps {
            let s = history.advance(step).expect("rolls");
            last = Some(s);
        }
        let last = last.expect("steps").state;
        let dq = max_difference(&last.shear, &steady.shear, scene.friction * p0);
        let dp = max_difference(&last.pressure, &steady.pressure, p0);
        eprintln!(
            "{name}: {} nodes, uniform {}: q {dq:.1e} μp_max, p {dp:.1e} p_max from the steady state",
            scene.grid.n_nodes(),
            scene.grid.is_uniform()
        );
        assert!(dq < 1e-6 && dp < 1e-7, "{name}: q {dq:e}, p {dp:e}");
    }
}

/// What a history refuses, by name: a viscoelastic body (its kernels are the steady ones), an
/// error-controlled grid (a history keeps one grid), a negative step.
#[test]
fn a_history_refuses_what_it_cannot_follow() {
    let load = |name: &str, overrides: &[&str]| {
        let overrides: Vec<String> = overrides.iter().map(|s| s.to_string()).collect();
        Scene::from_case(&rollbem::case::load(&crate::common::case_path(name), &overrides).expect("loads"))
            .expect("scene")
    };
    let err = History::new(&load("covered_roller_v_peak", &[]))
        .err()
        .expect("refused")
        .to_string();
    assert!(err.contains("body B") && err.contains("viscoelastic"), "{err}");
    let err = History::new(&load("carter_051", &["contact.grid.tolerance=1e-3"]))
        .err()
        .expect("refused")
        .to_string();
    assert!(err.contains("contact.grid.tolerance"), "{err}");
    let scene = load("carter_051", &[]);
    let mut history = History::new(&scene).expect("a history");
    let step = Step {
        distance: -1.0,
        normal: scene.normal,
        tangential: scene.tangential,
    };
    let err = history.advance(step).expect_err("refused").to_string();
    assert!(err.contains("rolling distance"), "{err}");
}
