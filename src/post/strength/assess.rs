//! The strength of the bodies of a solved run (`output.strength`): each assessed body's
//! elastic stresses on a grid below the contact, from its own interior model (Flamant
//! superposition for a half-space, Somigliana's identity for a BEM body, the solved state of a
//! viscoelastic body), turned into first yield and the shakedown limit
//! ([`super::first_yield`], [`super::shakedown`]).
//!
//! The grid spans x = c ± 2a along the surface and depths (0, 2a] below it ([`row_depths`]:
//! rows fine near the surface), a the half-length and c the centre of the loaded zone: it holds Johnson's critical points (0.78a for first
//! yield, 0.50a for shakedown, the surface at high friction). First yield is then located
//! between the grid points by two local refinements of the best point (9 × 9 points over ±1 and
//! ±1/4 spacing), so the cusp of a partial-slip surface maximum is found, not sampled.

use super::{field_rows, first_yield, shakedown, Criterion, FirstYield, Shakedown};
use crate::body::{ContactLoad, InteriorQuery, Side};
use crate::case::StrengthSpec;
use crate::contact::ContactFrame;
use crate::error::Error;
use crate::grid::ContactGrid;
use crate::interior::{grid_points, InteriorField, InteriorOptions, InteriorSample};
use crate::material::YieldStress;
use crate::post::ContactSolution;
use crate::scene::{BodyModels, Scene};

/// Where first yield lies.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum YieldSite {
    /// In the grid's shallowest rows (within one depth spacing of the surface).
    Surface,
    /// Below them.
    Subsurface,
}

impl YieldSite {
    /// The name in outputs (`surface`, `subsurface`).
    pub fn name(self) -> &'static str {
        match self {
            YieldSite::Surface => "surface",
            YieldSite::Subsurface => "subsurface",
        }
    }
}

/// The strength of one body under the solved tractions. Factors multiply the solved stresses
/// (the tractions scale with the load only where the contact keeps its shape: see
/// docs/strength.md).
#[derive(Debug, Clone)]
pub struct BodyStrength {
    /// `A` or `B`.
    pub body: String,
    /// The body's model.
    pub model: String,
    /// The criterion.
    pub criterion: Criterion,
    /// The shear yield stress k [stress].
    pub shear_yield: f64,
    /// First yield: factor, x along the contact and depth z below the surface [length].
    pub first_yield: FirstYield,
    /// Where first yield lies.
    pub first_yield_site: YieldSite,
    /// Shakedown: factor, governing depth, mode, and the residual per depth.
    pub shakedown: Shakedown,
    /// Grid spacing along x and in depth at the governing shakedown depth [length].
    pub spacing: [f64; 2],
    /// The half-length a of the loaded zone the grid is built on [length].
    pub half_length: f64,
    /// The depth of the shallowest row [length]: 0 where the model gives its surface stresses
    /// in closed form (the half-space), else its shallowest interior row.
    pub shallowest: f64,
    /// Whether the body's material is viscoelastic: its factors are those of the stresses of
    /// the solved steady state.
    pub viscoelastic: bool,
}

/// The depths of the grid's rows below a loaded zone of half-length `a`: z_j = 2a (j/nz)²,
/// j = 1 … nz, fine near the surface (where a high-friction surface governs and the rows
/// within the model's boundary layer are left out) and 0.02a apart at Johnson's critical
/// depths for nz = 100.
fn row_depths(a: f64, nz: usize) -> Vec<f64> {
    (1..=nz).map(|j| 2.0 * a * (j as f64 / nz as f64).powi(2)).collect()
}

/// The spacing of [`row_depths`] at depth z: dz/dj = 4a j/nz² with j = nz √(z/2a).
fn depth_spacing(a: f64, nz: usize, z: f64) -> f64 {
    let j = nz as f64 * (z / (2.0 * a)).max(0.0).sqrt();
    (4.0 * a * j.max(1.0) / (nz * nz) as f64).max(f64::MIN_POSITIVE)
}

/// The boundary layer of the strength grid's interior queries, in element lengths: twice the
/// default. A BEM body's Somigliana stresses amplify the boundary data's error like h/d near
/// its boundary; on fig14_true_geometry at Q/μP = 0.9 its row at 0.058 element lengths gave a
/// shakedown factor 5 % off the half-space's, its rows from 0.1 on agree with it to 1 %
/// (docs/strength.md).
const STRENGTH_BOUNDARY_LAYER: f64 = 0.1;

/// How close to an element's end the surface row may come, as a fraction of the element: the
/// Cauchy integral of a load that jumps between discontinuous elements grows like the
/// logarithm of the distance to the jump, and a sixth keeps the points as far from the ends as
/// the nodes of a discontinuous quadratic element (ξ = ±2/3), where the run's spikes stay below
/// the discretisation error (docs/strength.md).
const END_CLEARANCE: f64 = 1.0 / 6.0 - 1e-9;

/// Where the surface row is evaluated: ten points per spacing of the interior rows `xs` and
/// the contact grid's nodes, except points closer to an element end than [`END_CLEARANCE`]. The surface stresses have square-root cusps at the contact
/// edges (McEwen's σx = 2μp0 at the trailing edge, falling off like √|x + a| on both sides)
/// and kinks at the stick–slip points: a sampling of spacing h under-reads a cusp by about
/// √(h/a) p0, so the surface, which costs little, is sampled ten times finer than the rows.
fn surface_abscissae(grid: &ContactGrid, xs: &[f64]) -> Vec<f64> {
    let (lo, hi) = (xs[0], xs[xs.len() - 1]);
    let n = 10 * (xs.len() - 1);
    let clear_of_ends = |x: f64| {
        let e = grid.edges.partition_point(|&edge| edge <= x);
        if e == 0 || e == grid.edges.len() {
            return true;
        }
        let (a, b) = (grid.edges[e - 1], grid.edges[e]);
        (x - a).min(b - x) >= END_CLEARANCE * (b - a)
    };
    let mut out: Vec<f64> = (0..=n)
        .map(|i| lo + (hi - lo) * i as f64 / n as f64)
        .filter(|&x| clear_of_ends(x))
        .collect();
    out.extend(grid.nodes.iter().copied().filter(|&x| (lo..=hi).contains(&x)));
    out.sort_by(f64::total_cmp);
    out.dedup();
    out
}

/// Whether body `k` (0 = A) is made of a viscoelastic material.
fn viscoelastic_body(scene: &Scene, k: usize) -> bool {
    let case = &scene.case;
    let body = if k == 0 {
        &case.case.bodies.a
    } else {
        &case.case.bodies.b
    };
    body.material_name()
        .is_some_and(|m| case.viscoelastic_material(m).is_some())
}

/// The loaded zone of the solution: (centre, half-length) [length].
fn loaded_zone(solution: &ContactSolution) -> Option<(f64, f64)> {
    let loaded: Vec<f64> = solution
        .x
        .iter()
        .zip(&solution.pressure)
        .filter(|(_, &p)| p > 0.0)
        .map(|(&x, _)| x)
        .collect();
    let (lo, hi) = (loaded.first()?, loaded.last()?);
    (hi > lo).then(|| (0.5 * (lo + hi), 0.5 * (hi - lo)))
}

/// The assessed bodies: `output.strength.bodies`, else every body that has a yield stress
/// (validation has made sure the listed ones do).
fn assessed(scene: &Scene, spec: &StrengthSpec) -> Vec<(usize, String, YieldStress)> {
    let case = &scene.case.case;
    [("A", &case.bodies.a), ("B", &case.bodies.b)]
        .into_iter()
        .enumerate()
        .filter(|(_, (name, _))| spec.bodies.as_ref().is_none_or(|b| b.iter().any(|n| n == name)))
        .filter_map(|(k, (name, body))| {
            let y = case.materials.get(body.material_name()?)?.yield_stress?;
            let stress = match (y.shear, y.tensile) {
                (Some(k), _) => YieldStress::Shear(k),
                (None, Some(t)) => YieldStress::Tensile(t),
                (None, None) => return None,
            };
            Some((k, name.to_string(), stress))
        })
        .collect()
}

/// The strength of every body `spec` assesses, under the solved tractions.
pub fn assess(
    scene: &Scene,
    spec: &StrengthSpec,
    models: &BodyModels,
    grid: &ContactGrid,
    frame: &ContactFrame,
    solution: &ContactSolution,
) -> Result<Vec<BodyStrength>, Error> {
    let Some((centre, a)) = loaded_zone(solution) else {
        return Ok(Vec::new());
    };
    let mut out = Vec::new();
    for (k, body, stress) in assessed(scene, spec) {
        let side = if k == 0 { Side::A } else { Side::B };
        let sign = if k == 0 { 1.0 } else { -1.0 };
        let (pressure, shear) = frame.global_loads(side, &solution.pressure, &solution.shear);
        let load = ContactLoad {
            grid,
            pressure: &pressure,
            shear: &shear,
        };
        let model = models[k].as_ref();
        let fail = |source| Error::Strength {
            case: scene.case.path.clone(),
            body: body.clone(),
            source: Box::new(source),
        };
        let sample = |points: &[[f64; 2]]| {
            // Depth z below the surface is +y in A and −y in B (contact frame), measured from
            // the surface the model's field has (a BEM body's curves away from the contact).
            let points: Vec<[f64; 2]> = points
                .iter()
                .map(|p| [p[0], sign * (model.field_surface(p[0]) + p[1])])
                .collect();
            let query = InteriorQuery {
                side,
                load: ContactLoad { ..load },
                points: &points,
                options: InteriorOptions {
                    boundary_layer: STRENGTH_BOUNDARY_LAYER,
                    displacements: false,
                },
            };
            model.interior(&query).map_err(fail)
        };
        let [nx, nz] = spec.grid;
        let depths = row_depths(a, nz);
        let xs: Vec<f64> = (0..nx)
            .map(|i| centre - 2.0 * a + 4.0 * a * i as f64 / (nx - 1) as f64)
            .collect();
        let points: Vec<[f64; 2]> = depths.iter().flat_map(|&z| xs.iter().map(move |&x| [x, z])).collect();
        let samples = sample(&points)?;
        let field = InteriorField::from_samples(&body, model.model_name(), [nx, nz], points, &samples);
        let k_shear = stress.shear_yield(spec.criterion);
        let mut rows = field_rows(&field);
        let inside: Vec<usize> = (0..field.points.len())
            .filter(|&i| field.status[i] == crate::interior::PointStatus::Inside)
            .collect();
        let mut pts: Vec<[f64; 2]> = inside.iter().map(|&i| field.points[i]).collect();
        let mut sts: Vec<_> = inside.iter().map(|&i| super::plane_stress(&field.stress[i])).collect();
        let shallowest = rows.first().map_or(depths[0], |r| r.0);
        // The surface itself, where the model has it in closed form: at high friction it
        // governs, and the interior rows stop at the boundary layer above it.
        let surface_xs = surface_abscissae(grid, &xs);
        if let Some(surface) = model.surface_stress(&load, side, &surface_xs) {
            let row: Vec<_> = surface_xs.iter().zip(surface).map(|(&x, s)| ([x, 0.0], s)).collect();
            pts.extend(row.iter().map(|r| r.0));
            sts.extend(row.iter().map(|r| r.1));
            rows.insert(0, (0.0, row.into_iter().map(|r| r.1).collect()));
        }
        let (Some(coarse), Some(sd)) = (
            first_yield(&pts, &sts, k_shear, spec.criterion),
            shakedown(&rows, k_shear, spec.criterion),
        ) else {
            continue;
        };
        let dx = 4.0 * a / (nx - 1) as f64;
        let local_dz = |z: f64| depth_spacing(a, nz, z);
        let first = refine_first_yield(coarse, [dx, local_dz(coarse.z)], k_shear, spec.criterion, &sample)?;
        let spacing = [dx, local_dz(sd.z)];
        out.push(BodyStrength {
            body,
            model: model.model_name().to_string(),
            criterion: spec.criterion,
            shear_yield: k_shear,
            first_yield_site: if first.z < shallowest + local_dz(shallowest) {
                YieldSite::Surface
            } else {
                YieldSite::Subsurface
            },
            first_yield: first,
            shakedown: sd,
            spacing,
            half_length: a,
            shallowest: rows.first().map_or(0.0, |r| r.0),
            viscoelastic: viscoelastic_body(scene, k),
        });
    }
    Ok(out)
}

/// The body's interior samples at points (x, depth) [length].
type Sampler<'a> = dyn Fn(&[[f64; 2]]) -> Result<Vec<InteriorSample>, Error> + 'a;

/// First yield between the grid points: two passes of 9 × 9 points around the best point so
/// far, over ±1 and then ±1/4 of the grid spacing (points above the surface or in the
/// boundary layer are left out).
fn refine_first_yield(
    mut best: FirstYield,
    spacing: [f64; 2],
    k: f64,
    criterion: Criterion,
    sample: &Sampler,
) -> Result<FirstYield, Error> {
    for reach in [1.0, 0.25] {
        let (hx, hz) = (reach * spacing[0], reach * spacing[1]);
        let points: Vec<[f64; 2]> = grid_points([best.x - hx, best.x + hx, 9.0], [best.z - hz, best.z + hz, 9.0])
            .into_iter()
            .filter(|p| p[1] > 0.0)
            .collect();
        let samples = sample(&points)?;
        let (pts, sts): (Vec<[f64; 2]>, Vec<_>) = points
            .iter()
            .zip(&samples)
            .filter_map(|(p, s)| match s {
                InteriorSample::Inside(v) => Some((*p, super::plane_stress(&v.stress))),
                _ => None,
            })
            .unzip();
        if let Some(f) = first_yield(&pts, &sts, k, criterion) {
            if f.factor < best.factor {
                best = f;
            }
        }
    }
    Ok(best)
}

/// summary.json's `strength` entry of one body.
#[derive(Debug, Clone, PartialEq, serde::Serialize)]
pub struct StrengthSummary {
    /// `A` or `B`.
    pub body: String,
    /// The body's model.
    pub model: String,
    /// `von_mises` or `tresca`.
    pub criterion: &'static str,
    /// The shear yield stress k [stress].
    pub shear_yield: f64,
    /// First yield.
    pub first_yield: FirstYieldSummary,
    /// Shakedown of steady rolling.
    pub shakedown: ShakedownSummary,
    /// The interior grid: spacings along x and in depth [length], and the half-length a of
    /// the loaded zone it spans (x = c ± 2a, depth to 2a).
    pub grid: StrengthGrid,
}

/// First yield in summary.json.
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize)]
pub struct FirstYieldSummary {
    /// λ_y: the factor on the solved stresses at which yield starts [-].
    pub factor: f64,
    /// x of the point, contact frame [length].
    pub x: f64,
    /// Depth of the point below the surface [length].
    pub z: f64,
    /// `surface` or `subsurface`.
    pub site: &'static str,
}

/// Shakedown in summary.json.
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize)]
pub struct ShakedownSummary {
    /// λ_sd: the largest factor on the solved stresses that shakes down [-].
    pub factor: f64,
    /// The governing depth [length].
    pub z: f64,
    /// `surface` or `subsurface`.
    pub mode: &'static str,
}

/// The grid of a strength assessment in summary.json.
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize)]
pub struct StrengthGrid {
    /// Spacing along x [length].
    pub spacing_x: f64,
    /// Spacing in depth [length].
    pub spacing_z: f64,
    /// Half-length a of the loaded zone [length].
    pub half_length: f64,
}

impl BodyStrength {
    /// The body's entry of summary.json.
    pub fn summary(&self) -> StrengthSummary {
        StrengthSummary {
            body: self.body.clone(),
            model: self.model.clone(),
            criterion: self.criterion.name(),
            shear_yield: self.shear_yield,
            first_yield: FirstYieldSummary {
                factor: self.first_yield.factor,
                x: self.first_yield.x,
                z: self.first_yield.z,
                site: self.first_yield_site.name(),
            },
            shakedown: ShakedownSummary {
                factor: self.shakedown.factor,
                z: self.shakedown.z,
                mode: self.shakedown.mode.name(),
            },
            grid: StrengthGrid {
                spacing_x: self.spacing[0],
                spacing_z: self.spacing[1],
                half_length: self.half_length,
            },
        }
    }
}

/// The notices of a strength assessment, where first yield lies at the surface: for a model
/// without closed-form surface stresses (bem, viscoelastic), that the surface itself was not
/// evaluated; for a contact in partial slip on a grid without error control, that the surface
/// maximum sits on the square-root cusp of σx at a stick–slip point, which the contact grid
/// resolves only to O(√(h/a)) (3 % on 21 elements of Carter's contact at Q/μP = 0.9,
/// under-read: the factor is high; docs/strength.md).
pub fn notices(strength: &[BodyStrength], solution: &ContactSolution, error_controlled: bool) -> Vec<String> {
    use crate::post::NodeState;
    let has = |s: NodeState| solution.state.contains(&s);
    let partial_slip = has(NodeState::Stick) && has(NodeState::Slip);
    let mut out: Vec<String> = strength
        .iter()
        .filter(|b| b.viscoelastic)
        .map(|b| {
            format!(
                "output.strength: body {} is viscoelastic: its factors are those of the stresses of the solved \
                 steady state (Melan's theorem is that of an elastic body; docs/strength.md, \"Limits\")",
                b.body
            )
        })
        .collect();
    for b in strength.iter().filter(|b| b.first_yield_site == YieldSite::Surface) {
        if b.shallowest > 0.0 {
            out.push(format!(
                "output.strength: first yield of body {} lies in its shallowest row (depth {:.4e}), {} element \
                 lengths below the surface, which the {} model does not evaluate closer: at the surface itself the \
                 factor may be a few per cent lower (docs/strength.md, \"Limits\")",
                b.body, b.shallowest, STRENGTH_BOUNDARY_LAYER, b.model
            ));
        } else if partial_slip && !error_controlled {
            out.push(format!(
                "output.strength: first yield of body {} lies at the surface (x = {:.4}) of a contact in partial \
                 slip, whose surface stresses have cusps at the stick–slip point that a fixed contact grid \
                 resolves only to a few per cent (the factor reads high); set contact.grid.tolerance (1e-4: \
                 within 0.5 %) for the surface value",
                b.body, b.first_yield.x
            ));
        }
    }
    out
}
