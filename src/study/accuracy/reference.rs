//! What the accuracy study measures its runs against — Carter's or Hertz's closed form, else
//! the finest true-geometry run — and the nodal error norms of a run.

use super::scenes::{self, SceneBody};
use super::Outcome;
use crate::analytic::{hertz_pressure, Carter};
use crate::case::{LoadedCase, NormalSpec, TangentialSpec};
use crate::post::norms::{nodal_error, ErrorNorms};
use crate::post::ContactSolution;

/// The closed form a scene has, if any.
#[derive(Debug, Clone, Copy)]
pub(super) enum ClosedForm {
    /// Carter's shear (and creepage) for similar bodies under a load ratio; the effective
    /// radius [length].
    Carter(Carter, f64),
    /// Hertz's pressure for similar bodies at Q = 0.
    Hertz { half_width: f64, peak: f64 },
}

/// The reference of a study.
#[derive(Debug, Clone)]
pub(super) enum Reference {
    /// The scene's closed form.
    Closed(ClosedForm),
    /// The finest converged true-geometry run.
    FinestRun {
        /// Its contact elements.
        elements: usize,
        /// Its solution (boxed: far larger than the closed forms).
        solution: Box<ContactSolution>,
        /// Friction coefficient μ of the scene.
        friction: f64,
    },
}

impl Reference {
    /// The finest true-geometry run `o` of `elements` contact elements as the reference.
    pub(super) fn finest_run(elements: usize, o: &Outcome, case: &LoadedCase) -> Self {
        Reference::FinestRun {
            elements,
            solution: Box::new(o.solution.clone()),
            friction: case.case.contact.friction,
        }
    }

    /// What the errors are measured against, for the table, the JSON and the chart.
    pub(super) fn describe(&self) -> String {
        match self {
            Reference::Closed(ClosedForm::Carter(..)) => {
                "Carter's shear: |q - q_Carter| / (mu p0), RMS and max over the nodes with |x| < a".to_string()
            }
            Reference::Closed(ClosedForm::Hertz { .. }) => {
                "Hertz's pressure: |p - p_Hertz| / p0, RMS and max over the nodes with |x| < a".to_string()
            }
            Reference::FinestRun { elements, .. } => format!(
                "no closed form for this scene: the finest true-geometry run ({elements} contact elements); \
                 the larger of |p - p_ref| / p_ref,max and |q - q_ref| / (mu p_ref,max), RMS and max over \
                 the nodes inside its contact"
            ),
        }
    }

    /// The nodal error norms of a run and its relative creepage error (closed forms with a
    /// creepage only).
    pub(super) fn measure(&self, sol: &ContactSolution) -> (ErrorNorms, Option<f64>) {
        match self {
            Reference::Closed(c) => measure_closed(c, sol),
            Reference::FinestRun { solution, friction, .. } => (measure_against(solution, sol, *friction), None),
        }
    }
}

/// Carter or Hertz when both bodies are elastic and similar and P is given.
pub(super) fn closed_form(case: &LoadedCase, scene: &[SceneBody; 2]) -> Option<ClosedForm> {
    let c = &case.case;
    let similar = match (&scene[0].material, &scene[1].material) {
        (Some(ma), Some(mb)) => {
            (ma.young - mb.young).abs() <= 1e-12 * ma.young && (ma.poisson - mb.poisson).abs() <= 1e-12
        }
        _ => false,
    };
    if !similar || !matches!(c.load.normal(), NormalSpec::Force(_)) {
        return None;
    }
    let half_spaces = scenes::half_space_scene(case, scene);
    let est = &half_spaces.estimates;
    match c.load.tangential() {
        TangentialSpec::Ratio(r) if r != 0.0 => half_spaces
            .carter_reference()
            .map(|k| ClosedForm::Carter(k, est.effective_radius)),
        TangentialSpec::Ratio(_) => Some(ClosedForm::Hertz {
            half_width: est.hertz_half_width,
            peak: est.hertz_peak_pressure,
        }),
        _ => None,
    }
}

/// Error norms and creep error against Carter or Hertz, over the nodes with |x| < a.
fn measure_closed(closed: &ClosedForm, sol: &ContactSolution) -> (ErrorNorms, Option<f64>) {
    match *closed {
        ClosedForm::Carter(k, radius) => {
            let scale = k.friction * k.peak_pressure;
            let e = nodal_error(&sol.x, k.half_width, |i| {
                (sol.shear[i] - k.shear(sol.x[i])).abs() / scale
            });
            (e, Some(sol.creep / k.creep(radius) - 1.0))
        }
        ClosedForm::Hertz { half_width, peak } => {
            let e = nodal_error(&sol.x, half_width, |i| {
                (sol.pressure[i] - hertz_pressure(sol.x[i], half_width, peak)).abs() / peak
            });
            (e, None)
        }
    }
}

/// Error norms against a reference solution interpolated to this run's nodes, over the nodes
/// inside the reference's contact.
fn measure_against(reference: &ContactSolution, sol: &ContactSolution, friction: f64) -> ErrorNorms {
    let p_max = reference
        .pressure
        .iter()
        .fold(0.0_f64, |m, &p| m.max(p))
        .max(f64::MIN_POSITIVE);
    let mu = friction.max(f64::MIN_POSITIVE);
    let interp = |v: &[f64], x: f64| linear(&reference.x, v, x);
    let [x0, x1] = reference.contact_extent().unwrap_or([0.0, 0.0]);
    let (centre, half) = (0.5 * (x0 + x1), 0.5 * (x1 - x0));
    let shifted: Vec<f64> = sol.x.iter().map(|x| x - centre).collect();
    nodal_error(&shifted, half, |i| {
        let dp = (sol.pressure[i] - interp(&reference.pressure, sol.x[i])).abs() / p_max;
        let dq = (sol.shear[i] - interp(&reference.shear, sol.x[i])).abs() / (mu * p_max);
        dp.max(dq)
    })
}

/// Piecewise-linear interpolation of (xs, v) at x (xs increasing; constant beyond the ends).
fn linear(xs: &[f64], v: &[f64], x: f64) -> f64 {
    let k = xs.partition_point(|&t| t < x);
    if k == 0 {
        return v[0];
    }
    if k == xs.len() {
        return v[xs.len() - 1];
    }
    let t = (x - xs[k - 1]) / (xs[k] - xs[k - 1]);
    v[k - 1] + t * (v[k] - v[k - 1])
}
