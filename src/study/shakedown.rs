//! `rollbem study shakedown`: Johnson's shakedown map of a Hertz line contact under a sliding
//! traction (Johnson, *Contact Mechanics*, 1985, §9.4, Fig. 9.12; Johnson & Jefferis 1963) for
//! the case's criterion, with the case's own points on it.
//!
//! The map: for traction coefficients μ = Q/P from 0 to 0.5, the load p0/k at first yield and
//! at the shakedown limit of McEwen's field ([`crate::analytic::mcewen`]) by the same searches a
//! run uses ([`crate::post::strength`]): below the first curve the contact stays elastic,
//! between the curves it shakes down to an elastic state, above the second it flows
//! plastically on every pass — below the surface (plastic shakedown of a hardening material
//! or ratchetting) where the limit is governed below it, at the surface (surface ratchetting)
//! where the surface governs. The case's points: each assessed body at its |Q|/P and its
//! p_max/k, with its own first-yield and shakedown loads λ_y p_max/k and λ_sd p_max/k from the
//! run's tractions — partial slip, dissimilar bodies and the true geometry, which the map does
//! not know, move them off the map's curves.

use crate::error::Error;
use crate::files::{Access, Claim, Kind};
use crate::interior::PlaneStress;
use crate::material::YieldCriterion;
use crate::post::strength::{first_yield, shakedown, ShakedownMode};
use rayon::prelude::*;
use std::path::{Path, PathBuf};

/// One traction coefficient of the map: the loads p0/k of its limits.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct MapPoint {
    /// Traction coefficient μ = Q/P of full sliding [-].
    pub mu: f64,
    /// p0/k at first yield [-].
    pub first_yield: f64,
    /// p0/k at the shakedown limit [-].
    pub shakedown: f64,
    /// Where the shakedown limit is governed.
    pub mode: ShakedownMode,
}

/// The map's traction coefficients: 0 to 0.5 every 0.02.
pub fn map_frictions() -> Vec<f64> {
    (0..=25).map(|i| 0.02 * i as f64).collect()
}

/// The limits of McEwen's field at traction coefficient `mu` for `criterion` and Poisson's
/// ratio `nu`: first yield sampled every 0.005a over x ∈ [−1.5a, 1.5a], z ∈ [0, 1.2a];
/// shakedown over rows 0.02a apart from the surface to 1.2a, x ∈ [−3a, 3a] every 0.01a (the map
/// is drawn, not tabulated: docs/strength.md gives the finer closed-form values).
pub fn sliding_limits(mu: f64, criterion: YieldCriterion, nu: f64) -> MapPoint {
    let stress = |x: f64, z: f64| crate::analytic::mcewen::sliding_hertz_stress(x, z, mu, nu);
    let mut points = Vec::new();
    let mut stresses: Vec<PlaneStress> = Vec::new();
    for i in 0..=600 {
        for j in 0..=240 {
            let (x, z) = (-1.5 + 0.005 * i as f64, 0.005 * j as f64);
            points.push([x, z]);
            stresses.push(stress(x, z));
        }
    }
    let fy = first_yield(&points, &stresses, 1.0, criterion).map_or(f64::INFINITY, |f| f.factor);
    let rows: Vec<(f64, Vec<PlaneStress>)> = (0..=60)
        .map(|j| {
            let z = 0.02 * j as f64;
            (z, (0..=600).map(|i| stress(-3.0 + 0.01 * i as f64, z)).collect())
        })
        .collect();
    let sd = shakedown(&rows, 1.0, criterion);
    MapPoint {
        mu,
        first_yield: fy,
        shakedown: sd.as_ref().map_or(f64::INFINITY, |s| s.factor),
        mode: sd.map_or(ShakedownMode::Subsurface, |s| s.mode),
    }
}

/// One assessed body of one run, placed on the map.
#[derive(Debug, Clone, PartialEq)]
pub struct CasePoint {
    /// The run: the case's stem, with the varied value when a key is varied.
    pub label: String,
    /// `A` or `B`.
    pub body: String,
    /// |Q|/P of the run [-].
    pub traction: f64,
    /// p_max/k: the run's peak pressure over the body's shear yield stress [-].
    pub load: f64,
    /// λ_y p_max/k: the load at which this body's own stresses first yield [-].
    pub first_yield: f64,
    /// λ_sd p_max/k: the load of this body's own shakedown limit [-].
    pub shakedown: f64,
    /// Where its shakedown limit is governed.
    pub mode: ShakedownMode,
}

/// What `rollbem study shakedown` computed.
#[derive(Debug, Clone)]
pub struct ShakedownStudy {
    /// The criterion of the case (`output.strength.criterion`).
    pub criterion: YieldCriterion,
    /// Poisson's ratio of the map (the first assessed body's).
    pub poisson: f64,
    /// The map.
    pub map: Vec<MapPoint>,
    /// The case's points.
    pub points: Vec<CasePoint>,
    /// The output folder.
    pub dir: PathBuf,
}

/// Solves the case (each value of `vary`, `KEY=V1,V2,…`, once) with its strength assessment
/// (von Mises when the case has no `output.strength`), draws the map for its criterion and
/// writes shakedown_map.csv, shakedown_points.csv and shakedown.svg into `out`.
pub fn run(case: &Path, overrides: &[String], vary: Option<&str>, out: &Path) -> Result<ShakedownStudy, Error> {
    let mut base = overrides.to_vec();
    let loaded = crate::case::load(case, &base)?;
    loaded.steady_only("`rollbem study shakedown`")?;
    let _claim = Claim::acquire(out, Kind::StudyShakedown, Access::Exclusive)?;
    if loaded.case.output.strength.is_none() {
        base.push("output.strength.criterion=von_mises".into());
    }
    let runs: Vec<(String, Vec<String>)> = match vary {
        None => vec![(stem(case), base.clone())],
        Some(v) => {
            let (key, values) = v.split_once('=').ok_or_else(|| bad_vary(v))?;
            values
                .split(',')
                .map(|value| {
                    let mut o = base.clone();
                    o.push(format!("{key}={value}"));
                    (format!("{} {key}={value}", stem(case)), o)
                })
                .collect()
        }
    };
    let mut points = Vec::new();
    let mut criterion = YieldCriterion::VonMises;
    let mut poisson = None;
    for (label, o) in &runs {
        let loaded = crate::case::load(case, o)?;
        let solved = crate::app::solve(&loaded)?;
        criterion = loaded.case.output.strength.as_ref().map_or(criterion, |s| s.criterion);
        let p_max = solved.solution.pressure.iter().copied().fold(0.0, f64::max);
        let traction = solved.solution.tangential_force.abs() / solved.solution.normal_force;
        for b in &solved.strength {
            let body = if b.body == "A" {
                &loaded.case.bodies.a
            } else {
                &loaded.case.bodies.b
            };
            if poisson.is_none() {
                poisson = body.material_name().map(|m| loaded.material(m).poisson);
            }
            let load = p_max / b.shear_yield;
            points.push(CasePoint {
                label: label.clone(),
                body: b.body.clone(),
                traction,
                load,
                first_yield: b.first_yield.factor * load,
                shakedown: b.shakedown.factor * load,
                mode: b.shakedown.mode,
            });
        }
    }
    let poisson = poisson.unwrap_or(0.3);
    let map: Vec<MapPoint> = map_frictions()
        .par_iter()
        .map(|&mu| sliding_limits(mu, criterion, poisson))
        .collect();
    let study = ShakedownStudy {
        criterion,
        poisson,
        map,
        points,
        dir: out.to_path_buf(),
    };
    crate::output::write_atomically(out, Kind::StudyShakedown, |tmp| write_outputs(tmp, &study))?;
    Ok(study)
}

fn stem(case: &Path) -> String {
    case.file_stem()
        .map_or("case".into(), |s| s.to_string_lossy().into_owned())
}

fn bad_vary(v: &str) -> Error {
    Error::Study {
        message: format!(
            "--vary {v}: give one key and its values as KEY=V1,V2,…, e.g. --vary load.tangential.ratio=0.3,0.6,0.9"
        ),
    }
}

/// The CSV files and the chart.
fn write_outputs(dir: &Path, s: &ShakedownStudy) -> Result<(), Error> {
    use crate::output::number;
    let io = |path: &Path, e: &dyn std::fmt::Display| Error::Output {
        path: path.to_path_buf(),
        message: e.to_string(),
    };
    let map_path = dir.join("shakedown_map.csv");
    let mut text = String::from("mu,first_yield_p0_over_k,shakedown_p0_over_k,shakedown_mode\n");
    for m in &s.map {
        text += &format!(
            "{},{},{},{}\n",
            number(m.mu),
            number(m.first_yield),
            number(m.shakedown),
            m.mode.name()
        );
    }
    std::fs::write(&map_path, text).map_err(|e| io(&map_path, &e))?;
    let points_path = dir.join("shakedown_points.csv");
    let mut text =
        String::from("run,body,q_over_p,pmax_over_k,first_yield_pmax_over_k,shakedown_pmax_over_k,shakedown_mode\n");
    for p in &s.points {
        text += &format!(
            "\"{}\",{},{},{},{},{},{}\n",
            p.label,
            p.body,
            number(p.traction),
            number(p.load),
            number(p.first_yield),
            number(p.shakedown),
            p.mode.name()
        );
    }
    std::fs::write(&points_path, text).map_err(|e| io(&points_path, &e))?;
    crate::output::charts::shakedown::write(&dir.join("shakedown.svg"), &chart_of(s))
}

/// The chart's plain data.
fn chart_of(s: &ShakedownStudy) -> crate::output::charts::shakedown::ShakedownChart {
    use crate::output::charts::shakedown as chart;
    chart::ShakedownChart {
        criterion: s.criterion.name(),
        poisson: s.poisson,
        map: s
            .map
            .iter()
            .map(|m| chart::MapPoint {
                mu: m.mu,
                first_yield: m.first_yield,
                shakedown: m.shakedown,
                surface: m.mode == ShakedownMode::Surface,
            })
            .collect(),
        points: s
            .points
            .iter()
            .map(|p| chart::CasePoint {
                body: p.body.clone(),
                traction: p.traction,
                load: p.load,
                first_yield: p.first_yield,
                shakedown: p.shakedown,
            })
            .collect(),
    }
}

/// The console summary: the case's points against the map at their traction coefficient.
pub fn render_summary(s: &ShakedownStudy) -> String {
    let mut out = format!(
        "shakedown map of a sliding Hertz line contact, {} (nu = {}), mu = 0 … 0.5\n",
        s.criterion.name(),
        s.poisson
    );
    out += &format!(
        "  {:<34} {:>4} {:>8} {:>9} {:>12} {:>12}  {}\n",
        "run", "body", "|Q|/P", "p_max/k", "first yield", "shakedown", "region"
    );
    for p in &s.points {
        let region = if p.load < p.first_yield {
            "elastic"
        } else if p.load < p.shakedown {
            "elastic shakedown"
        } else if p.mode == ShakedownMode::Surface {
            "beyond shakedown: surface ratchetting"
        } else {
            "beyond shakedown: plastic shakedown or ratchetting below the surface"
        };
        out += &format!(
            "  {:<34} {:>4} {:>8.4} {:>9.4} {:>12.4} {:>12.4}  {region}\n",
            p.label, p.body, p.traction, p.load, p.first_yield, p.shakedown
        );
    }
    out
}
