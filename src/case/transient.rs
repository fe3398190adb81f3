//! The `transient:` section of a case: a history of rolling steps instead of the steady state
//! (cases/README.md, "Transient rolling"; docs/transient.md).
//!
//! The controls keep the keys of `load.normal` and `load.tangential` (one key each, so a
//! control cannot change kind between steps); each value is a [`Schedule`]: a constant, a
//! table of one value a rolling step, or a piecewise-linear function of the rolled distance.

use serde::{Deserialize, Serialize};

/// `transient:`: how far the contact rolls each step, how many steps, and what is prescribed.
#[derive(Debug, Clone, Deserialize, Serialize)]
#[serde(deny_unknown_fields)]
pub struct TransientSpec {
    /// Number of rolling steps N ≥ 1 (after step 0, which presses and optionally shifts).
    pub steps: usize,
    /// Rolling distance Δ of each step [length]. Default = the contact grid's node spacing
    /// (with which a history settles on the first-order steady state; docs/transient.md).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub step: Option<f64>,
    /// The step as a time [time] instead of `step`: Δ = `load.speed` × `time_step`.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub time_step: Option<f64>,
    /// Step 0's tangential loading without rolling after the bodies are pressed
    /// (Cattaneo–Mindlin). Default = none (step 0 only presses, Q = 0).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub shift: Option<ShiftKeys>,
    /// The normal control of each step: `force` or `overlap`, each a [`Schedule`].
    /// Default = `load.normal` as a constant.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub normal: Option<NormalSchedule>,
    /// The tangential control of each rolling step: `ratio`, `force` or `creep`, each a
    /// [`Schedule`]. Default = `load.tangential` as a constant.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub tangential: Option<TangentialSchedule>,
    /// The datum of a rolling step's tangential displacement [length] (docs/transient.md, "The
    /// datum of a step"): absent (the default), the material at the grid's upstream end; a
    /// length L > 0, the half-plane pair's displacement there measured from L, as a 2D model
    /// of a strip of width b of a 3D half-space measures it from infinity (L = b·e^(ν/(1−ν));
    /// CONTACT's DY = b). Half-space and rigid bodies only.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub datum_length: Option<f64>,
    /// Where each rolling step's solve under a falling friction law starts (CONTACT's INISLP;
    /// docs/friction.md, "Choosing the branch of a step"): `warm` (the default: the last step's
    /// state), `below` (zero slip velocity, μ = μ_s: the continuation from Coulomb's solution)
    /// or `above` (μ = μ_k at every node). A step of a steep law can have several solutions;
    /// this picks the one each side finds.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub initial_slip: Option<InitialSlipKey>,
    /// Write the files of every `write_every`-th step into steps/ (and the ParaView series),
    /// always with step 0 and the last: N ≥ 1. Default = 1 (every step). transient.csv keeps a
    /// row for every step.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub write_every: Option<usize>,
}

impl TransientSpec {
    /// The rolling distance Δ of a step [length]: `step`, else `time_step` × the rolling
    /// `speed` [length/time], else the grid's node `spacing` [length] (the default).
    pub fn step_length(&self, speed: Option<f64>, spacing: f64) -> f64 {
        match (self.step, self.time_step, speed) {
            (Some(d), _, _) => d,
            (None, Some(dt), Some(v)) => v * dt,
            _ => spacing,
        }
    }

    /// Whether step `k` of a history whose last step is `last` has its files in steps/
    /// (`write_every`: step 0, every N-th and the last).
    pub fn writes_step(&self, k: usize, last: usize) -> bool {
        let every = self.write_every.unwrap_or(1).max(1);
        k == 0 || k == last || k.is_multiple_of(every)
    }
}

/// `transient.initial_slip`: where a rolling step's solve under a falling law starts.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Deserialize, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum InitialSlipKey {
    /// From the last step's state.
    Warm,
    /// From zero slip velocity (μ = μ_s everywhere; CONTACT's INISLP = 1).
    Below,
    /// From μ = μ_k everywhere (CONTACT's INISLP = −1).
    Above,
}

impl InitialSlipKey {
    /// The solver's start of that name.
    pub fn start(self) -> crate::contact::falling::InitialSlip {
        use crate::contact::falling::InitialSlip;
        match self {
            Self::Warm => InitialSlip::Warm,
            Self::Below => InitialSlip::Below,
            Self::Above => InitialSlip::Above,
        }
    }
}

/// `transient.shift`: exactly one key, the tangential control of a shift without rolling.
#[derive(Debug, Clone, Default, Deserialize, Serialize)]
#[serde(deny_unknown_fields)]
pub struct ShiftKeys {
    /// Q/(μP) ∈ (−1, 1).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub ratio: Option<f64>,
    /// Tangential force per unit length Q [force/length], |Q| < μP.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub force: Option<f64>,
    /// Rigid tangential shift of A relative to B along +x [length].
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub displacement: Option<f64>,
}

/// `transient.normal`: exactly one key.
#[derive(Debug, Clone, Default, Deserialize, Serialize)]
#[serde(deny_unknown_fields)]
pub struct NormalSchedule {
    /// Normal force per unit length P > 0 [force/length].
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub force: Option<Schedule>,
    /// Rigid overlap δ0 > 0 [length].
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub overlap: Option<Schedule>,
}

/// `transient.tangential`: exactly one key.
#[derive(Debug, Clone, Default, Deserialize, Serialize)]
#[serde(deny_unknown_fields)]
pub struct TangentialSchedule {
    /// Q/(μP) ∈ (−1, 1).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub ratio: Option<Schedule>,
    /// Tangential force per unit length Q [force/length].
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub force: Option<Schedule>,
    /// Creepage ξ = (V_A − V_B)/V [-]: the rigid shift of a step over its rolling distance.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub creep: Option<Schedule>,
}

/// The value of a control along the history.
#[derive(Debug, Clone, PartialEq, Serialize)]
#[serde(untagged)]
pub enum Schedule {
    /// The same value at every step: `0.6`.
    Constant(f64),
    /// One value a rolling step, in order: `[0.2, 0.4, 0.6]` (as many as `steps`).
    Table(Vec<f64>),
    /// Piecewise linear in the rolled distance s [length] at the end of a step, constant
    /// beyond the first and last points: `[[0, 0.2], [5, 0.6]]` (s strictly increasing).
    Points(Vec<[f64; 2]>),
    /// A sine of the rolled distance s [length] at the end of a step:
    /// `{sine: {mean: 1812.5, amplitude: 181.2, wavelength: 50.0}}` gives
    /// mean + amplitude·sin(2πs/wavelength + phase), e.g. an oscillating normal load.
    Sine {
        /// The wave's parameters.
        sine: SineWave,
    },
}

/// `{sine: {...}}`: v(s) = mean + amplitude·sin(2πs/λ + phase), s the rolled distance [length].
#[derive(Debug, Clone, Copy, PartialEq, Deserialize, Serialize)]
#[serde(deny_unknown_fields)]
pub struct SineWave {
    /// The mean value, in the control's unit (P [force/length], δ0 [length], Q/μP, Q, ξ).
    pub mean: f64,
    /// The amplitude, in the control's unit (its sign flips the phase by π).
    pub amplitude: f64,
    /// The wavelength λ > 0 in rolled distance [length].
    pub wavelength: f64,
    /// The phase at s = 0 [rad] (default 0: the value starts at the mean, rising).
    #[serde(default)]
    pub phase: f64,
}

impl SineWave {
    /// The value at rolled distance `s` [length].
    pub fn at(&self, s: f64) -> f64 {
        self.mean + self.amplitude * (std::f64::consts::TAU * s / self.wavelength + self.phase).sin()
    }
}

impl<'de> Deserialize<'de> for Schedule {
    fn deserialize<D: serde::Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        #[derive(Deserialize)]
        #[serde(untagged)]
        enum Raw {
            Constant(f64),
            Table(Vec<f64>),
            Points(Vec<[f64; 2]>),
            Sine { sine: SineWave },
        }
        Raw::deserialize(d)
            .map(|r| match r {
                Raw::Constant(v) => Schedule::Constant(v),
                Raw::Table(v) => Schedule::Table(v),
                Raw::Points(v) => Schedule::Points(v),
                Raw::Sine { sine } => Schedule::Sine { sine },
            })
            .map_err(|_| {
                serde::de::Error::custom(
                    "expected a number (the same at every step), a list of numbers (one a step), a list of \
                     [distance, value] pairs (piecewise linear in the rolled distance) or {sine: {mean, \
                     amplitude, wavelength, phase}} (a sine of the rolled distance)",
                )
            })
    }
}

impl Schedule {
    /// The value at rolling step `step` (1-based; 0 is the value at the start, s = 0) whose end
    /// lies at rolled distance `rolled` [length]. A table gives its first value at step 0.
    pub fn at(&self, step: usize, rolled: f64) -> f64 {
        match self {
            Schedule::Constant(v) => *v,
            Schedule::Table(v) => v[step.saturating_sub(1).min(v.len() - 1)],
            Schedule::Points(p) => piecewise_linear(p, rolled),
            Schedule::Sine { sine } => sine.at(rolled),
        }
    }

    /// Every value the schedule takes (to check their range; a sine's extremes).
    pub fn values(&self) -> Vec<f64> {
        match self {
            Schedule::Constant(v) => vec![*v],
            Schedule::Table(v) => v.clone(),
            Schedule::Points(p) => p.iter().map(|q| q[1]).collect(),
            Schedule::Sine { sine } => vec![sine.mean - sine.amplitude.abs(), sine.mean + sine.amplitude.abs()],
        }
    }
}

/// The piecewise-linear function through `points` ([s, value], s increasing) at `s`, constant
/// beyond the ends.
fn piecewise_linear(points: &[[f64; 2]], s: f64) -> f64 {
    let (first, last) = (points[0], points[points.len() - 1]);
    if s <= first[0] {
        return first[1];
    }
    if s >= last[0] {
        return last[1];
    }
    let k = points.windows(2).position(|w| s <= w[1][0]).unwrap_or(0);
    let ([s0, v0], [s1, v1]) = (points[k], points[k + 1]);
    v0 + (v1 - v0) * (s - s0) / (s1 - s0)
}

/// The normal control as a schedule: which key, and its values.
#[derive(Debug, Clone, PartialEq)]
pub enum NormalPlan {
    /// P [force/length].
    Force(Schedule),
    /// δ0 [length].
    Overlap(Schedule),
}

/// The tangential control as a schedule.
#[derive(Debug, Clone, PartialEq)]
pub enum TangentialPlan {
    /// Q/(μP).
    Ratio(Schedule),
    /// Q [force/length].
    Force(Schedule),
    /// ξ [-].
    Creep(Schedule),
}

impl NormalSchedule {
    /// The plan, or a message if not exactly one key is given.
    pub fn plan(&self) -> Result<NormalPlan, String> {
        match (&self.force, &self.overlap) {
            (Some(p), None) => Ok(NormalPlan::Force(p.clone())),
            (None, Some(d)) => Ok(NormalPlan::Overlap(d.clone())),
            _ => Err("give exactly one of `force` (P) or `overlap` (delta0)".into()),
        }
    }
}

impl TangentialSchedule {
    /// The plan, or a message if not exactly one key is given.
    pub fn plan(&self) -> Result<TangentialPlan, String> {
        match (&self.ratio, &self.force, &self.creep) {
            (Some(r), None, None) => Ok(TangentialPlan::Ratio(r.clone())),
            (None, Some(q), None) => Ok(TangentialPlan::Force(q.clone())),
            (None, None, Some(x)) => Ok(TangentialPlan::Creep(x.clone())),
            _ => Err("give exactly one of `ratio` (Q/muP), `force` (Q) or `creep` (xi)".into()),
        }
    }
}

/// The shift's control: Q/(μP), Q [force/length] or the rigid shift [length].
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum ShiftPlan {
    /// Q/(μP).
    Ratio(f64),
    /// Q [force/length].
    Force(f64),
    /// The rigid shift [length].
    Displacement(f64),
}

impl ShiftKeys {
    /// The shift's control, or a message if not exactly one key is given.
    pub fn plan(&self) -> Result<ShiftPlan, String> {
        match (self.ratio, self.force, self.displacement) {
            (Some(r), None, None) => Ok(ShiftPlan::Ratio(r)),
            (None, Some(q), None) => Ok(ShiftPlan::Force(q)),
            (None, None, Some(s)) => Ok(ShiftPlan::Displacement(s)),
            _ => Err("give exactly one of `ratio` (Q/muP), `force` (Q) or `displacement` (the rigid shift)".into()),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn schedules_give_their_value_at_each_step() {
        assert_eq!(Schedule::Constant(0.6).at(7, 3.0), 0.6);
        let table = Schedule::Table(vec![0.1, 0.2, 0.3]);
        assert_eq!([0, 1, 3, 9].map(|k| table.at(k, 0.0)), [0.1, 0.1, 0.3, 0.3]);
        let points = Schedule::Points(vec![[0.0, 0.0], [2.0, 1.0], [4.0, 1.0]]);
        assert_eq!(
            [-1.0, 0.5, 2.0, 3.0, 9.0].map(|s| points.at(1, s)),
            [0.0, 0.25, 1.0, 1.0, 1.0]
        );
        let sine = Schedule::Sine {
            sine: SineWave {
                mean: 2.0,
                amplitude: 0.5,
                wavelength: 4.0,
                phase: 0.0,
            },
        };
        let at = [0.0, 1.0, 2.0, 3.0].map(|s| sine.at(1, s));
        assert!(
            at.iter().zip([2.0, 2.5, 2.0, 1.5]).all(|(a, b)| (a - b).abs() < 1e-12),
            "{at:?}"
        );
        assert_eq!(sine.values(), vec![1.5, 2.5]);
    }
}
