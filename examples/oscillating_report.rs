//! An oscillating normal load P(s) = P0(1 + ε sin 2πs/λ) at constant creepage ξ
//! (cases/oscillating_load.yaml: Carter's steel pair, a = 1 mm at P0, μ 0.3, ξ = 2.2e-3, so
//! Q/μP = 0.6 in the steady state at P0): the history's tangential force Q(s) against the
//! quasi-steady one, the steady solution at each step's P and the same ξ (Johnson, *Contact
//! Mechanics*, 1985, §8.3, for the steady rolling; J.J. Kalker, *Three-dimensional elastic
//! bodies in rolling contact*, 1990, §1.3, for the transient slip).
//!
//! Fits the last period's Q(s) to Q̄ + A sin(2πs/λ + φ) by least squares over the steps of
//! one full period after a run-in of 10a, for λ/a ∈ {1, 2, 5, 10, 20, 50}, and prints A over
//! the quasi-steady amplitude (dQ/dP at constant ξ times εP0) and φ. tests/docs compares the
//! table with docs/transient.md; tests/validation/oscillating.rs checks the quasi-steady limit.
//!
//! Run: cargo run --release --example oscillating_report

mod common;

use common::Table;
use rollbem::contact::{methods, ContactProblem, NormalControl, State, TangentialControl};
use rollbem::scene::Scene;
use rollbem::transient::{History, Step};

/// The relative amplitude ε of the shipped case.
pub const EPSILON: f64 = 0.1;
/// The run-in before the fitted period, in contact half-widths a (the history at constant P
/// settles within 1e-6 of its steady Q in about 5a: docs/transient.md).
pub const RUN_IN: f64 = 10.0;
/// The wavelengths of the table, in a.
pub const WAVELENGTHS: [f64; 6] = [1.0, 2.0, 5.0, 10.0, 20.0, 50.0];

/// The shipped case's scene (its `load.normal` is P0, its `load.tangential` ξ).
pub fn scene() -> Scene {
    let case = rollbem::case::load(&common::case_path("oscillating_load"), &[]).expect("the case loads");
    Scene::from_case(&case).expect("a scene")
}

/// P0 [N/mm] and ξ of the scene.
pub fn controls(scene: &Scene) -> (f64, f64) {
    match (scene.normal, scene.tangential) {
        (NormalControl::Force(p), TangentialControl::Creep(x)) => (p, x),
        _ => panic!("oscillating_load prescribes P and ξ"),
    }
}

/// One step of a history: rolled distance s [mm], P and Q [N/mm], p_max [N/mm²].
#[derive(Debug, Clone, Copy)]
pub struct Sample {
    /// Rolled distance s [mm].
    pub s: f64,
    /// Normal force P [N/mm].
    pub p: f64,
    /// Tangential force Q [N/mm] (positive along +x on A).
    pub q: f64,
    /// Peak pressure [N/mm²].
    pub p_max: f64,
}

/// The sample of a contact state on `problem`'s grid.
fn sample(problem: &ContactProblem, s: f64, state: &State) -> Sample {
    Sample {
        s,
        p: problem.grid.integrate(&state.pressure),
        q: problem.grid.integrate(&state.shear),
        p_max: state.pressure.iter().copied().fold(0.0, f64::max),
    }
}

/// The history at P(s) = P0(1 + ε sin 2πs/λ) and the scene's ξ, one node spacing a step, from
/// the pressed state (step 0) over `distance` [mm]: every rolling step.
pub fn history(scene: &Scene, wavelength: f64, distance: f64) -> Vec<Sample> {
    let (p0, xi) = controls(scene);
    let mut history = History::new(scene).expect("a history");
    let force = |s: f64| p0 * (1.0 + EPSILON * (std::f64::consts::TAU * s / wavelength).sin());
    let mut step = Step {
        distance: 0.0,
        normal: NormalControl::Force(force(0.0)),
        tangential: TangentialControl::Ratio(0.0),
    };
    history.advance(step).expect("pressed");
    let delta = scene.grid.node_spacing();
    let n = (distance / delta).ceil() as usize;
    (1..=n)
        .map(|k| {
            let s = k as f64 * delta;
            step = Step {
                distance: delta,
                normal: NormalControl::Force(force(s)),
                tangential: TangentialControl::Creep(xi),
            };
            let solved = history.advance(step).expect("a step converges");
            sample(history.problem(), s, &solved.state)
        })
        .collect()
}

/// The steady solver at ξ on the scene's grid, warm-started along a list of forces.
pub struct Steady {
    problem: ContactProblem,
    scene_solver: rollbem::contact::SolverSettings,
    warm: Option<State>,
}

impl Steady {
    /// The steady problem of `scene` (its slip derivative, first order for the shipped case).
    pub fn new(scene: &Scene) -> Self {
        let (_, problem) = scene.assemble().expect("assembles");
        Self {
            problem,
            scene_solver: scene.solver,
            warm: None,
        }
    }

    /// The steady state at normal force `p` [N/mm] and the scene's ξ.
    pub fn at(&mut self, p: f64) -> Sample {
        self.problem.normal = NormalControl::Force(p);
        let (state, report) = methods::solve_from(&self.problem, &self.scene_solver, self.warm.take());
        assert!(report.converged, "steady at P = {p}");
        let out = sample(&self.problem, 0.0, &state);
        self.warm = Some(state);
        out
    }

    /// The quasi-steady amplitude A_qs [N/mm] about P0: the first harmonic of the steady Q along
    /// one cycle P0(1 + ε sin θ), θ at 720 points. It is dQ/dP·εP0 to O(ε²) relative, taken
    /// over the whole cycle: a difference quotient over a fraction of it would see the fixed
    /// grid's staircase of Q_ss(P) (a node changing state as the contact's ends move), not
    /// the slope.
    pub fn amplitude(&mut self, p0: f64) -> f64 {
        let samples: Vec<Sample> = (0..720)
            .map(|k| {
                let s = k as f64 / 720.0;
                Sample {
                    s,
                    ..self.at(p0 * (1.0 + EPSILON * (std::f64::consts::TAU * s).sin()))
                }
            })
            .collect();
        fit(&samples, 1.0).1
    }
}

/// Carter's quasi-steady amplitude dQ/dP·εP0 [N/mm] at constant ξ: with c/a = 1 − ξR/(μa)
/// and a ∝ √P, Q = μ(2k√(P·P0) − k²P0), k = ξR/(μa0), so dQ/dP = μk at P0 (Johnson, *Contact
/// Mechanics*, 1985, §8.3; R the relative radius, a0 the half-width at P0).
pub fn carter_amplitude(scene: &Scene) -> f64 {
    let (p0, xi) = controls(scene);
    let e = &scene.estimates;
    let k = xi * e.effective_radius / (scene.friction * e.hertz_half_width);
    scene.friction * k * EPSILON * p0
}

/// The least-squares fit of Q̄ + A sin(2πs/λ + φ) to the samples: (Q̄, A ≥ 0, φ [rad] in (−π, π]).
pub fn fit(samples: &[Sample], wavelength: f64) -> (f64, f64, f64) {
    let mut m = [[0.0; 3]; 3];
    let mut r = [0.0; 3];
    for s in samples {
        let t = std::f64::consts::TAU * s.s / wavelength;
        let f = [1.0, t.sin(), t.cos()];
        for i in 0..3 {
            r[i] += f[i] * s.q;
            for j in 0..3 {
                m[i][j] += f[i] * f[j];
            }
        }
    }
    let c = solve3(m, r);
    (c[0], c[1].hypot(c[2]), c[2].atan2(c[1]))
}

/// Solves the 3×3 system m c = r by Cramer's rule (the normal equations of [`fit`], well
/// conditioned over a full period).
fn solve3(m: [[f64; 3]; 3], r: [f64; 3]) -> [f64; 3] {
    let det = |a: [[f64; 3]; 3]| {
        a[0][0] * (a[1][1] * a[2][2] - a[1][2] * a[2][1]) - a[0][1] * (a[1][0] * a[2][2] - a[1][2] * a[2][0])
            + a[0][2] * (a[1][0] * a[2][1] - a[1][1] * a[2][0])
    };
    let d = det(m);
    std::array::from_fn(|k| {
        let mut a = m;
        (0..3).for_each(|i| a[i][k] = r[i]);
        det(a) / d
    })
}

/// The steps of the last full period of a history run over RUN_IN·a + λ.
pub fn last_period(scene: &Scene, wavelength: f64) -> Vec<Sample> {
    let a = scene.estimates.hertz_half_width;
    let all = history(scene, wavelength, RUN_IN * a + wavelength);
    let end = all.last().expect("steps").s;
    all.into_iter().filter(|s| s.s > end - wavelength + 1e-9 * a).collect()
}

/// The table of docs/transient.md: A/A_qs, φ and the lag −φλ/2π against λ/a.
pub fn table() -> Table {
    let scene = scene();
    let (p0, _) = controls(&scene);
    let a = scene.estimates.hertz_half_width;
    let mut steady = Steady::new(&scene);
    let quasi = steady.amplitude(p0);
    let mut t = Table::new(&["λ/a", "steps a period", "A/A_qs", "φ (°)", "lag −φλ/2π (a)"]);
    for ratio in WAVELENGTHS {
        let wavelength = ratio * a;
        let period = last_period(&scene, wavelength);
        let (_, amplitude, phase) = fit(&period, wavelength);
        t.push(vec![
            format!("{ratio}"),
            format!("{}", period.len()),
            format!("{:.3}", amplitude / quasi),
            format!("{:.1}", phase.to_degrees()),
            format!("{:.3}", -phase * wavelength / std::f64::consts::TAU / a),
        ]);
    }
    t
}

fn main() {
    let scene = scene();
    let (p0, xi) = controls(&scene);
    println!(
        "P0 = {p0} N/mm, ε = {EPSILON}, ξ = {xi}, a = {:.4} mm, step {:.4e} mm\n",
        scene.estimates.hertz_half_width,
        scene.grid.node_spacing()
    );
    let quasi = Steady::new(&scene).amplitude(p0);
    println!(
        "A_qs = {quasi:.4} N/mm on the grid (Carter's closed form: {:.4} N/mm)\n",
        carter_amplitude(&scene)
    );
    print!("{}", table().markdown());
}
