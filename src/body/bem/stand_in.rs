//! A BEM body's stand-in for the passes of an error-controlled grid: the half-plane's
//! flexibility on the pass's grid, exact and cheap, plus the smooth remainder of the true
//! geometry taken from the BEM on two coarse grids.
//!
//! The flexibility of a body whose contact surface is smooth is the half-plane's logarithmic
//! and step kernels (the local singular behaviour of every elastic body under a surface load)
//! plus a remainder R(x, s) that is smooth along the contact: the curvature of the surface, the
//! shaft, the rim and the datum of the approach (docs/theory.md, "Stand-ins for the passes").
//! On a grid the remainder's entries are R(x_i, s_j)·w_j to the order of the element integrals,
//! so a BEM condensed to one grid gives samples of R that serve every finer grid: each block is
//! fitted by a tensor-product Chebyshev series of degree [`REMAINDER_DEGREE`] in x and in s
//! (least squares over the grid's nodes), evaluated at the new nodes and weighted by the new
//! weights. Two details make the remainder smooth:
//!
//! - the half-plane's columns are scaled by 1/cos θ_j, θ the surface's slope at node j: the BEM
//!   loads its element by the traction per unit arc, the half-plane per unit x, and the
//!   difference, a logarithm times (1/cos θ − 1), is not smooth (a bore's contact at
//!   a/R = 0.2, where the surface turns by 0.2 rad, differed from the full BEM by 2.5e-3 p0
//!   without the scaling and by 2e-5 with it);
//! - the BEM's own discretisation error in the remainder falls as the contact grid's spacing
//!   (first order: fitted on one grid alone, fig14_true_geometry's remainder left 2.1e-4, 9.9e-5
//!   and 4.8e-5 p0 on the start grid and its first and second bisections), so the two grids'
//!   fits are combined by Richardson's extrapolation, 2·R_fine − R_coarse.
//!
//! tests/validation/stand_in.rs compares the stand-in with the full BEM on a grid finer than
//! both fitted grids (a roller on its shaft, a bore's conformal contact) and drops a wrong
//! stand-in through the final check.
//!
//! The stand-in serves only the passes: the run's final grid is solved again with the full BEM
//! body (its mesh cut along the grid, as without the stand-in), which gives the results and
//! every field, and the difference between the two solutions on that grid is added to the
//! estimate (src/adapt.rs).

use super::setup::BemSetup;
use crate::body::half_space::HalfSpace;
use crate::body::setup::{BodySetup, BuildContext, BuildError, Rolling, SurfaceAt};
use crate::body::transfer::Transferred;
use crate::body::{
    circle_profile, Body, BodyFields, BodyModel, FieldError, Flexibility, InteriorQuery, InteriorResult, Side,
    StrainOperator,
};
use crate::grid::ContactGrid;
use crate::material::Elastic;
use faer::Mat;
use nalgebra::DMatrix;
use std::sync::atomic::{AtomicBool, Ordering};
use std::sync::{Arc, OnceLock};

/// Degree of the Chebyshev series of the remainder in each variable: 8 fits a bore's
/// conformal contact (a/R = 0.2) to 2e-5 p0 where 4 leaves 2e-3 (bore_a020_tractive, measured
/// against the full BEM on the final grid); convex rollers need less and lose nothing by it.
pub const REMAINDER_DEGREE: usize = 8;

static ENABLED: AtomicBool = AtomicBool::new(true);

/// Turns the stand-in on or off for the runs that follow (benchmarks compare both).
pub fn set_stand_in_enabled(enabled: bool) {
    ENABLED.store(enabled, Ordering::Relaxed);
}

/// Whether the passes of an error-controlled grid use the stand-in: unless turned off by
/// [`set_stand_in_enabled`] or by the environment variable `ROLLBEM_BEM_STAND_IN=0` (every pass
/// then cuts and condenses the full BEM, as before; docs/performance.md).
pub fn stand_in_enabled() -> bool {
    static ENV: OnceLock<bool> = OnceLock::new();
    let env = *ENV.get_or_init(|| std::env::var("ROLLBEM_BEM_STAND_IN").map_or(true, |v| v.trim() != "0"));
    env && ENABLED.load(Ordering::Relaxed)
}

/// The Chebyshev polynomials T_0..T_d at `x`, mapped from [lo, hi] to [−1, 1] (one row each).
fn chebyshev_rows(x: &[f64], lo: f64, hi: f64, degree: usize) -> DMatrix<f64> {
    DMatrix::from_fn(x.len(), degree + 1, |i, k| {
        let t = ((2.0 * x[i] - lo - hi) / (hi - lo)).clamp(-1.0, 1.0);
        (k as f64 * t.acos()).cos()
    })
}

/// The smooth remainder R(x, s) of a body's four flexibility blocks as Chebyshev series.
#[derive(Debug, Clone)]
pub struct SmoothRemainder {
    /// The interval the series map to [−1, 1] (the start grid's span) [length].
    span: [f64; 2],
    /// Degree in each variable.
    degree: usize,
    /// Coefficients of hp, hq, wp, wq [length/force per length²].
    coefficients: [DMatrix<f64>; 4],
}

impl SmoothRemainder {
    /// The least-squares series of (F_bem − F_half)_ij / w_j over the nodes of `grid`.
    fn fitted(bem: &Flexibility, half: &Flexibility, grid: &ContactGrid, span: [f64; 2], degree: usize) -> Self {
        let t = chebyshev_rows(&grid.nodes, span[0], span[1], degree);
        // (TᵀT)⁻¹Tᵀ: the normal equations of a (degree + 1)-column basis, well conditioned on
        // the nodes of a grid that covers its interval.
        let pinv = (t.transpose() * &t)
            .try_inverse()
            .unwrap_or_else(|| DMatrix::zeros(degree + 1, degree + 1))
            * t.transpose();
        let m = grid.n_nodes();
        let fit = |b: &Mat<f64>, h: &Mat<f64>| {
            let samples = DMatrix::from_fn(m, m, |i, j| (b[(i, j)] - h[(i, j)]) / grid.weights[j]);
            &pinv * samples * pinv.transpose()
        };
        Self {
            span,
            degree,
            coefficients: [
                fit(&bem.hp, &half.hp),
                fit(&bem.hq, &half.hq),
                fit(&bem.wp, &half.wp),
                fit(&bem.wq, &half.wq),
            ],
        }
    }

    /// Richardson's extrapolation of a first-order error: 2·fine − coarse.
    fn extrapolated(coarse: &Self, fine: &Self) -> Self {
        let c = |k: usize| 2.0 * &fine.coefficients[k] - &coarse.coefficients[k];
        Self {
            span: fine.span,
            degree: fine.degree,
            coefficients: [c(0), c(1), c(2), c(3)],
        }
    }

    /// The remainder's blocks on `grid`: R(x_i, s_j)·w_j.
    pub fn on(&self, grid: &ContactGrid) -> Flexibility {
        let t = chebyshev_rows(&grid.nodes, self.span[0], self.span[1], self.degree);
        let m = grid.n_nodes();
        let block = |c: &DMatrix<f64>| {
            let r = &t * c * t.transpose();
            Mat::from_fn(m, m, |i, j| r[(i, j)] * grid.weights[j])
        };
        Flexibility {
            hp: block(&self.coefficients[0]),
            hq: block(&self.coefficients[1]),
            wp: block(&self.coefficients[2]),
            wq: block(&self.coefficients[3]),
        }
    }
}

/// The half-plane of the body's material and profile radius on `grid`, its columns scaled to
/// a load per unit arc (module docs): 1/cos θ_j with θ the body's surface slope at node j.
fn arc_half_plane(
    half: &HalfSpace,
    grid: &ContactGrid,
    side: Side,
    slope: &dyn Fn(f64) -> f64,
) -> Result<Flexibility, BuildError> {
    let body = Transferred::flat_model_on(Box::new(half.clone()), grid, side)?;
    Ok(arc_scaled(body.model().flexibility(grid, side), grid, slope))
}

/// A flexibility's columns divided by cos θ_j (a load per unit arc).
fn arc_scaled(mut f: Flexibility, grid: &ContactGrid, slope: &dyn Fn(f64) -> f64) -> Flexibility {
    for (j, &x) in grid.nodes.iter().enumerate() {
        let scale = 1.0 / slope(x).cos();
        for block in [&mut f.hp, &mut f.hq, &mut f.wp, &mut f.wq] {
            for v in block.col_mut(j).iter_mut() {
                *v *= scale;
            }
        }
    }
    f
}

/// A BEM body's stand-in: its setup, its half-plane and its smooth remainder.
#[derive(Debug, Clone)]
pub struct BemStandIn {
    /// The body it stands in for (its surface, constants and profile).
    inner: Arc<BemSetup>,
    /// The half-plane of its material and profile radius.
    half: HalfSpace,
    /// The remainder, shared by every pass.
    remainder: Arc<SmoothRemainder>,
    /// The BEM body's profile at x = 0 (its touching point's height over the mesh's surface at
    /// x = 0, which [`BodySetup::surface_at`] measures from) [length].
    profile_shift: f64,
}

impl BemStandIn {
    /// The stand-in of `setup` on `side` from its BEM condensed to `levels[0]` (the start grid
    /// or one of its bisections) and to `levels[1]` (the bisection of `levels[0]`), the mesh cut
    /// along each.
    pub fn of(setup: &BemSetup, levels: [&ContactGrid; 2], side: Side, rolling: Rolling) -> Result<Self, BuildError> {
        let half = HalfSpace::new(setup.material, setup.radius);
        let slope = |x: f64| setup.surface_at(x, side).map_or(0.0, |s| s.slope_angle);
        let span = [levels[0].edges[0], levels[0].edges[levels[0].n_elements()]];
        let mut fits = Vec::with_capacity(2);
        let mut profile_shift = 0.0;
        for (k, grid) in levels.into_iter().enumerate() {
            // The start grid is the mesh's own; a finer level cuts the mesh along it.
            let own = setup.mesh.contact_grid().coincides_with(grid);
            let follows = (!own).then(|| setup.followed(grid));
            let level = follows.as_ref().unwrap_or(setup);
            // The finer level's condensation is kept: the check of the body's mesh solves on
            // the same grid (src/adapt.rs).
            let ctx = BuildContext {
                grid,
                side,
                rolling,
                pair: None,
            };
            let body = level.build_keeping(&ctx, k == 1)?;
            if k == 0 {
                profile_shift = body.model().profile(0.0);
            }
            let bem = body.model().flexibility(grid, side);
            let flat = arc_half_plane(&half, grid, side, &slope)?;
            // Fewer nodes than twice the series' terms would fit the BEM's element pattern,
            // not the remainder.
            let degree = REMAINDER_DEGREE.min((grid.n_nodes() / 2).saturating_sub(1)).max(1);
            fits.push(SmoothRemainder::fitted(&bem, &flat, grid, span, degree));
        }
        Ok(Self {
            inner: Arc::new(setup.clone()),
            half,
            remainder: Arc::new(SmoothRemainder::extrapolated(&fits[0], &fits[1])),
            profile_shift,
        })
    }

    /// The profile of the BEM body: the mesh's surface from its touching point, or the case's
    /// `profile_radius` circle.
    fn profile(&self, x: f64, side: Side) -> f64 {
        match self.inner.profile_radius {
            Some(r) => circle_profile(r, x),
            None => self.inner.surface_at(x, side).map_or(0.0, |s| s.profile) + self.profile_shift,
        }
    }
}

impl BodySetup for BemStandIn {
    fn model_name(&self) -> &'static str {
        "bem"
    }

    fn radius(&self) -> f64 {
        self.inner.radius
    }

    fn hertz_material(&self) -> Option<Elastic> {
        Some(self.inner.material)
    }

    fn surface_at(&self, x: f64, side: Side) -> Option<SurfaceAt> {
        self.inner.surface_at(x, side)
    }

    fn datum_distance(&self) -> f64 {
        self.inner.datum_distance()
    }

    fn build(&self, ctx: &BuildContext) -> Result<Box<dyn Body>, BuildError> {
        Ok(Box::new(StandInBody {
            flat: Transferred::flat_model_on(Box::new(self.half.clone().in_pair(ctx.pair)), ctx.grid, ctx.side)?,
            setup: self.clone(),
            side: ctx.side,
        }))
    }
}

/// The stand-in on one grid.
struct StandInBody {
    /// The half-plane on the grid (carried over from the straightened grid on a curved one).
    flat: Box<dyn Body>,
    setup: BemStandIn,
    side: Side,
}

impl BodyModel for StandInBody {
    fn model_name(&self) -> &'static str {
        "bem"
    }

    fn flexibility(&self, grid: &ContactGrid, side: Side) -> Flexibility {
        let inner = &self.setup.inner;
        let slope = |x: f64| inner.surface_at(x, side).map_or(0.0, |s| s.slope_angle);
        let mut f = arc_scaled(self.flat.model().flexibility(grid, side), grid, &slope);
        let r = self.setup.remainder.on(grid);
        f.hp += &r.hp;
        f.hq += &r.hq;
        f.wp += &r.wp;
        f.wq += &r.wq;
        f
    }

    fn profile(&self, x: f64) -> f64 {
        self.setup.profile(x, self.side)
    }

    /// None: the passes need no strain (the final grid's full BEM gives it).
    fn strain_operator(&self, _grid: &ContactGrid, _side: Side) -> Option<StrainOperator> {
        None
    }
}

impl BodyFields for StandInBody {
    /// None: only the final grid's full BEM body is post-processed.
    fn interior(&self, _query: &InteriorQuery) -> InteriorResult {
        Err(FieldError::NoInteriorField { model: "bem stand-in" })
    }
}
