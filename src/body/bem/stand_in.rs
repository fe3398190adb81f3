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
//! **The final grid.** The stand-in can also give the run's results on the final grid, where
//! the full BEM would be assembled on the finest grid of the run: its surface strain is the
//! derivative along x of its own tangential displacement, the half-plane's strain (exact on any
//! grid) plus ∂R/∂x of the remainder's w blocks, as the BEM's HBEM strain is the derivative of
//! the BEM's displacement. (A remainder fitted to the BEM's strain instead missed the part of
//! the strain local to each node, ∝ p(x), that a series in R(x, s)·w_j cannot carry from the
//! fitted grids' weights to the final grid's: 8 % of the creepage in the HBEM slip of
//! fig14_true_geometry's stick zone, against 2e-4 now.) Its boundary field is the full
//! BEM body's on the finest fitted grid (condensed for the fit already) under the final
//! tractions projected onto that grid element by element
//! ([`crate::grid::ContactGrid::projected_onto`], which keeps each element's force). Whether
//! its results are accurate enough is measured by a second stand-in whose remainder is known
//! less well ([`BemStandIn::checking`]): fitted on three grids, the result extrapolates the two
//! finest and the check the two coarsest, and the Richardson remainders' errors fall by about
//! 4 per bisection, as a second-order term does (measured on fig14_true_geometry: 1.1e-4,
//! 2.4e-5 and 5.8e-6 of the creepage at the three pairs of levels), so a third of the
//! difference of their solutions estimates the result's error (Richardson's estimate);
//! fitted on two grids, the check is the finer fit alone, whose error is the first-order one
//! that the extrapolation removes (3.5–6.5 times the result's). src/adapt.rs adds that
//! estimate to the grid's and solves the final grid with the full BEM only when the sum
//! exceeds the tolerance, or when the run asks for interior fields (the stand-in has none).

mod remainder;

use super::setup::{BemSetup, CondensedOnOwnGrid};
use super::BemBody;
use crate::body::half_space::{influence_matrix, HalfSpace, Kernel};
use crate::body::run_caches::RunCaches;
use crate::body::setup::{BodySetup, BuildContext, BuildError, Rolling, SurfaceAt};
use crate::body::transfer::{carried_weights, transfer_blocks, Transferred};
use crate::body::{
    circle_profile, Body, BodyFields, BodyModel, BoundaryField, ContactLoad, FieldError, Flexibility,
    FlexibilityChange, InteriorQuery, InteriorResult, LowRankFlexibility, Side, StrainOperator,
};
use crate::grid::ContactGrid;
use crate::material::Elastic;
use faer::{Mat, MatRef};

use std::sync::Arc;

#[cfg(test)]
use remainder::chebyshev_rows;
use remainder::{FitFactors, SmoothRemainder};

/// Degree of the Chebyshev series of the remainder in each variable: 8 fits a bore's
/// conformal contact (a/R = 0.2) to 2e-5 p0 where 4 leaves 2e-3 (bore_a020_tractive, measured
/// against the full BEM on the final grid); convex rollers need less and lose nothing by it.
pub const REMAINDER_DEGREE: usize = 8;

/// How often the error control bisects the start grid for the coarser of the two grids the
/// pass stand-ins' result is extrapolated from (src/adapt/stand_ins.rs `level`): not for
/// tolerances down to 3e-4, once down to 3e-5, twice below (measured on fig14_true_geometry,
/// whose remainder converges slowest of the shipped cases). The memory estimate of a tolerance
/// run condenses the BEM bodies on the finer grid, this level bisected once more.
pub fn level_bisections(tolerance: f64) -> usize {
    if tolerance >= 3e-4 {
        0
    } else if tolerance >= 3e-5 {
        1
    } else {
        2
    }
}

/// The half-plane of the body's material and profile radius on `grid`, its columns scaled to
/// a load per unit arc (module docs): 1/cos θ_j with θ the body's surface slope at node j. On a
/// grid of curved elements, which the closed-form element integrals do not cover, its two
/// kernels are made on the straight grid between the same edges and carried over (as
/// [`Transferred::flat_model_on`] does); the W blocks are made from them last, so each m × m
/// matrix is made once (on a graded final grid every further one costs its page faults).
fn arc_half_plane(
    half: &HalfSpace,
    grid: &ContactGrid,
    side: Side,
    slope: &dyn Fn(f64) -> f64,
) -> Result<Flexibility, BuildError> {
    let (mut hp, mut hq) = if grid.is_straight() {
        half.kernel_blocks(grid, side)
    } else {
        // Each kernel carried once per grid and pair (the other body's stand-in takes the
        // pair's copy), then made into the body's blocks as on a straight grid, the column
        // term −B w_j ln ℓ with the straight grid's weights carried: the blocks carried, to
        // rounding, as the matrix-free displacements of `StandInBody` carry them.
        let straight = grid.straightened();
        // The carry's check (the grid within the straight one's span) is made here, once.
        let weights = carried_weights(&straight, grid)?;
        let carried = |kernel: Kernel| {
            half.shared_kernel(grid, kernel, || {
                let flat = influence_matrix(&straight, kernel);
                let [k] = transfer_blocks([&flat], &straight, grid).expect("the carry was checked");
                k
            })
        };
        half.blocks_of_kernels(carried(Kernel::Log), carried(Kernel::Sign), &weights, side)
    };
    scale_columns([&mut hp, &mut hq], grid, slope);
    Ok(Flexibility::of_half_plane(hp, hq))
}

/// 1/cos θ_j at the grid's nodes, θ the surface's slope: a load per unit x made per unit arc.
fn arc_scales(grid: &ContactGrid, slope: &dyn Fn(f64) -> f64) -> Vec<f64> {
    grid.nodes.iter().map(|&x| 1.0 / slope(x).cos()).collect()
}

/// The columns of `blocks` times [`arc_scales`] (divided by cos θ_j at the grid's node j).
fn scale_columns<const N: usize>(blocks: [&mut Mat<f64>; N], grid: &ContactGrid, slope: &dyn Fn(f64) -> f64) {
    let scales = arc_scales(grid, slope);
    for block in blocks {
        for (j, &scale) in scales.iter().enumerate() {
            for v in block.col_mut(j).iter_mut() {
                *v *= scale;
            }
        }
    }
}

/// Where a stand-in's body sits: its side, the rolling, the span its series map, and their
/// degree (the same on every level: the levels' fits are combined term by term).
#[derive(Debug, Clone, Copy)]
struct Placement {
    side: Side,
    rolling: Rolling,
    span: [f64; 2],
    degree: usize,
}

/// The degree of the remainder's series on levels whose coarsest grid is `coarsest`: fewer
/// nodes than twice the series' terms would fit the BEM's element pattern, not the remainder
/// (a mesh with four contact elements gives a start grid of 12 nodes, degree 5).
fn series_degree(coarsest: &ContactGrid) -> usize {
    REMAINDER_DEGREE.min((coarsest.n_nodes() / 2).saturating_sub(1)).max(1)
}

/// The remainder of `setup`'s BEM condensed on `grid` (the mesh cut along it unless the grid is
/// the mesh's own; a condensation kept in `run` on that grid before is taken), the body built
/// there, and with `keep` the condensed BEM body with its own contact grid (the grid's elements
/// as the body's mesh maps them), kept in `run` for the later builds on that grid.
fn level_fit(
    setup: &BemSetup,
    half: &HalfSpace,
    grid: &ContactGrid,
    place: &Placement,
    keep: bool,
    run: Option<&RunCaches>,
) -> Result<LevelFit, BuildError> {
    let degree = place.degree;
    let side = place.side;
    let own = setup.mesh.contact_grid().coincides_with(grid);
    let follows = (!own).then(|| setup.followed(grid));
    let level = follows.as_ref().unwrap_or(setup);
    let ctx = BuildContext {
        grid,
        side,
        rolling: place.rolling,
        pair: None,
        // The fit asks for the body's response to a few loads (and the finest level's boundary
        // field and mesh check, for a few more).
        responses_only: true,
        run,
    };
    // The start mesh's own level seeds the far field the levels cut from it reuse.
    let (body, condensed) = level.build_keeping(&ctx, keep, own)?;
    let slope = |x: f64| setup.surface_at(x, side).map_or(0.0, |s| s.slope_angle);
    let flat = arc_half_plane(half, grid, side, &slope)?;
    let fit_factors = FitFactors::on(grid, place.span, degree);
    // The body's response to the fit's loads, pressure then shear ones: [H_p V, H_q V] and
    // [W_p V, W_q V] from one solve of the factored BEM.
    let (m, r) = (grid.n_nodes(), degree + 1);
    let v = &fit_factors.right;
    let p = Mat::from_fn(m, 2 * r, |i, c| if c < r { v[(i, c)] } else { 0.0 });
    let q = Mat::from_fn(m, 2 * r, |i, c| if c < r { 0.0 } else { v[(i, c - r)] });
    let [h, w] = body.model().displacements(grid, side, p.as_ref(), q.as_ref());
    let (first, second) = (
        |x: &Mat<f64>| x.subcols(0, r).to_owned(),
        |x: &Mat<f64>| x.subcols(r, r).to_owned(),
    );
    let fit = SmoothRemainder::fitted(
        &[
            (first(&h), &flat.hp * v),
            (second(&h), &flat.hq * v),
            (first(&w), &flat.wp * v),
            (second(&w), &flat.wq * v),
        ],
        &fit_factors,
        place.span,
        degree,
    );
    // Zero for a body condensed on this grid before (that build counted it).
    let (_, condense_s) = body.model().stage_seconds();
    Ok(LevelFit {
        fit,
        body,
        condensed,
        condense_s,
    })
}

/// What [`level_fit`] gives.
struct LevelFit {
    fit: SmoothRemainder,
    body: Box<dyn Body>,
    /// With `keep`: the condensed BEM body on its own contact grid (returned here, not read
    /// back from the run's caches, which need not be there).
    condensed: Option<CondensedOnOwnGrid>,
    /// Wall time [s] of the condensation.
    condense_s: f64,
}

/// What the fits on the levels give: the remainders and the finest level's body.
#[derive(Debug)]
struct Fitted {
    /// The flexibility's remainder the stand-in solves with (extrapolated from the two finest
    /// levels).
    result: SmoothRemainder,
    /// The flexibility's remainder of the check ([`BemStandIn::checking`]).
    check: SmoothRemainder,
    /// Wall time [s] the levels' condensations took.
    condense_s: f64,
    /// The finest level's full BEM body and its own contact grid (the level's, or the same
    /// elements mapped by its own mesh), for the boundary field.
    finest: Option<(ContactGrid, Arc<BemBody>)>,
}

/// The check's remainder less the result's ([`BemStandIn::check_change`]).
#[derive(Debug)]
struct CheckChange(Arc<Fitted>);

impl FlexibilityChange for CheckChange {
    /// The same on either side: the remainders were fitted for the stand-in's own.
    fn on_grid(&self, grid: &ContactGrid, _side: Side) -> LowRankFlexibility {
        self.0.result.change_to(&self.0.check, grid)
    }
}

/// Which remainder a stand-in solves with.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum Use {
    /// The best one: the result.
    Result,
    /// The one known less well, to estimate the result's error.
    Check,
}

/// A BEM body's stand-in: its setup, its half-plane and its smooth remainders.
#[derive(Debug, Clone)]
pub struct BemStandIn {
    /// The body it stands in for (its surface, constants and profile).
    inner: Arc<BemSetup>,
    /// The half-plane of its material and profile radius.
    half: HalfSpace,
    /// The remainders and the finest level's body, shared by every pass.
    fitted: Arc<Fitted>,
    /// Which flexibility remainder this stand-in solves with.
    used: Use,
    /// The BEM body's profile at x = 0 (its touching point's height over the mesh's surface at
    /// x = 0, which [`BodySetup::surface_at`] measures from) [length].
    profile_shift: f64,
}

impl BemStandIn {
    /// The stand-in of `setup` on `side` from its BEM condensed to each of `levels` (two or
    /// three grids, each the bisection of the one before; the first the start grid or one of
    /// its bisections), the mesh cut along each, their builds sharing `run`'s caches. The
    /// finest level's condensation is held by the stand-in, whose boundary field comes from it,
    /// and kept in `run`: the check of the body's mesh solves on the same grid (src/adapt.rs).
    pub fn of(
        setup: &BemSetup,
        levels: &[&ContactGrid],
        side: Side,
        rolling: Rolling,
        run: Option<&RunCaches>,
    ) -> Result<Self, BuildError> {
        assert!(
            levels.len() == 2 || levels.len() == 3,
            "a stand-in is fitted on two or three levels"
        );
        let half = HalfSpace::new(setup.material, setup.radius);
        let span = [levels[0].edges[0], levels[0].edges[levels[0].n_elements()]];
        let place = Placement {
            side,
            rolling,
            span,
            degree: series_degree(levels[0]),
        };
        let mut fits = Vec::with_capacity(levels.len());
        let mut profile_shift = 0.0;
        let mut finest = None;
        let mut condense_s = 0.0;
        for (k, &grid) in levels.iter().enumerate() {
            let last = k + 1 == levels.len();
            let level = level_fit(setup, &half, grid, &place, last, run)?;
            condense_s += level.condense_s;
            fits.push(level.fit);
            if k == 0 {
                profile_shift = level.body.model().profile(0.0);
            }
            if last {
                // On its own contact grid: the other body's mesh may map the elements between
                // the same ends differently.
                finest = level.condensed;
            }
        }
        let n = fits.len();
        let result = SmoothRemainder::extrapolated(&fits[n - 2], &fits[n - 1]);
        let check = if n == 3 {
            SmoothRemainder::extrapolated(&fits[0], &fits[1])
        } else {
            fits[1].clone()
        };
        Ok(Self {
            inner: Arc::new(setup.clone()),
            half,
            fitted: Arc::new(Fitted {
                result,
                check,
                finest,
                condense_s,
            }),
            used: Use::Result,
            profile_shift,
        })
    }

    /// The same stand-in solving with the remainder known less well (module docs): the
    /// difference of the two solutions on the final grid, scaled as src/adapt.rs does by the
    /// number of levels, estimates the error of this one's.
    pub fn checking(&self) -> Self {
        Self {
            used: Use::Check,
            ..self.clone()
        }
    }

    /// How [`Self::checking`] differs from this stand-in: the check's flexibility remainder
    /// less the result's, a low-rank change on any grid (the half-plane part is the same).
    pub fn check_change(&self) -> Arc<dyn FlexibilityChange> {
        Arc::new(CheckChange(self.fitted.clone()))
    }

    /// Wall time [s] the fitted levels' condensations took.
    pub fn condense_seconds(&self) -> f64 {
        self.fitted.condense_s
    }

    /// Whether the stand-in can give the final grid's results: its boundary field needs the
    /// finest level's BEM body kept (its strain, the half-plane's plus the series', it always has).
    pub fn gives_results(&self) -> bool {
        self.fitted.finest.is_some()
    }

    /// The surface of the body at x as the body itself has it on a pass's grid: on the circle
    /// its contact nodes lie on, where it has one (a generated body's exact circle, a mesh
    /// file's fitted one), else on its start mesh's elements. A body cut along a grid puts its
    /// new contact nodes on that circle (src/mesh/cuts.rs), so on the fine grids of the passes
    /// its surface is the circle to the cut elements' tiny interpolation error; the start mesh's
    /// quadratics instead change slope at their ends (beside the ends of the 1.06 mm elements of
    /// the generated bore of tests/data/bore_c30_tractive.yaml, 1.4e-6 rad off the circle's). The contact frame turns by that kink
    /// ([`crate::scene::contact_frame`]), stepping the normal gap by tan ψ·w (docs/theory.md,
    /// "Tractions along the contact") at every start element's end: a step the passes resolved
    /// as a contact edge, grading towards it to 1e-8 mm and never meeting 1e-5
    /// (tests/validation/stand_in_surface.rs).
    fn surface(&self, x: f64, side: Side) -> Option<SurfaceAt> {
        let on_mesh = self.inner.surface_at(x, side)?;
        let Some(circle) = self.inner.contact_circle else {
            return Some(on_mesh);
        };
        // As `BemSetup::surface_at`: clamped to the contact group's x-range, the branch of the
        // circle the mesh's surface lies on, the profile from the touching point at x = 0.
        let [x0, x1] = self.inner.shape.range;
        let xc = x.clamp(x0, x1);
        let (y, _) = self.inner.mesh.surface_at(xc)?;
        let p = circle.at_abscissa_of([xc, y]);
        let dy = p[1] - circle.centre[1];
        if dy == 0.0 {
            return Some(on_mesh);
        }
        let touch = self
            .inner
            .shape
            .touch
            .map_or(p[1], |t| circle.at_abscissa_of([0.0, t])[1]);
        Some(SurfaceAt {
            slope_angle: (-(xc - circle.centre[0]) / dy).atan(),
            profile: (p[1] - touch) * side.sign(),
            radius: on_mesh.radius,
        })
    }

    /// The profile of the BEM body: its surface ([`Self::surface`]) from its touching point, or
    /// the case's `profile_radius` circle.
    fn profile(&self, x: f64, side: Side) -> f64 {
        match self.inner.profile_radius {
            Some(r) => circle_profile(r, x),
            None => self.surface(x, side).map_or(0.0, |s| s.profile) + self.profile_shift,
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
        self.surface(x, side)
    }

    fn half_plane_twin(&self) -> Option<std::sync::Arc<dyn BodySetup>> {
        self.inner.half_plane_twin()
    }

    fn datum_distance(&self) -> f64 {
        self.inner.datum_distance()
    }

    fn build(&self, ctx: &BuildContext) -> Result<Box<dyn Body>, BuildError> {
        let half = self.half.clone().in_pair_of_stand_ins(ctx.pair);
        Ok(Box::new(StandInBody {
            flat: Transferred::flat_model_on(Box::new(half.clone()), ctx.grid, ctx.side)?,
            half,
            setup: self.clone(),
            side: ctx.side,
        }))
    }
}

impl StandInBody {
    /// The flexibility remainder this stand-in solves with.
    fn remainder(&self) -> &SmoothRemainder {
        let fitted = &self.setup.fitted;
        match self.setup.used {
            Use::Result => &fitted.result,
            Use::Check => &fitted.check,
        }
    }
}

/// The stand-in on one grid.
struct StandInBody {
    /// The half-plane on the grid (carried over from the straightened grid on a curved one).
    flat: Box<dyn Body>,
    /// The half-plane itself (in the pair's store), whose kernels [`arc_half_plane`] carries.
    half: HalfSpace,
    setup: BemStandIn,
    side: Side,
}

impl StandInBody {
    /// The slope angle θ [rad] of the body's surface at x on `side` (0 beyond its contact).
    fn slope(&self, x: f64, side: Side) -> f64 {
        self.setup.surface(x, side).map_or(0.0, |s| s.slope_angle)
    }

    /// The nodal loads `v` per unit x made per unit arc ([`arc_scales`]: the column scaling of
    /// [`arc_half_plane`], applied to the load).
    fn per_arc(&self, grid: &ContactGrid, side: Side, v: MatRef<'_, f64>) -> Mat<f64> {
        let scales = arc_scales(grid, &|x| self.slope(x, side));
        Mat::from_fn(v.nrows(), v.ncols(), |j, c| scales[j] * v[(j, c)])
    }
}

impl BodyModel for StandInBody {
    fn model_name(&self) -> &'static str {
        "bem"
    }

    /// The half-plane per unit arc ([`arc_half_plane`]) plus the remainder, added in place.
    fn flexibility(&self, grid: &ContactGrid, side: Side) -> Flexibility {
        let slope = |x: f64| self.slope(x, side);
        let mut f = arc_half_plane(&self.half, grid, side, &slope).expect("a grid lies within its straightened self");
        self.remainder()
            .add_to(grid, [&mut f.hp, &mut f.hq, &mut f.wp, &mut f.wq].into_iter());
        f
    }

    /// [`Self::flexibility`]'s product without its blocks: the half-plane's applied to the
    /// loads per unit arc (on a curved grid carried as [`arc_half_plane`] carries its blocks),
    /// the remainder's in factors.
    fn displacements(&self, grid: &ContactGrid, side: Side, p: MatRef<'_, f64>, q: MatRef<'_, f64>) -> [Mat<f64>; 2] {
        let (pa, qa) = (self.per_arc(grid, side, p), self.per_arc(grid, side, q));
        let [h, w] = self.flat.model().displacements(grid, side, pa.as_ref(), qa.as_ref());
        let [rh, rw] = self.remainder().times(grid, p, q);
        [h + rh, w + rw]
    }

    fn profile(&self, x: f64) -> f64 {
        self.setup.profile(x, self.side)
    }

    /// The derivative along x of the stand-in's own tangential displacement (module docs): the
    /// half-plane's strain plus ∂R/∂x of the remainder's w blocks.
    fn strain_operator(&self, grid: &ContactGrid, side: Side) -> Option<StrainOperator> {
        let slope = |x: f64| self.slope(x, side);
        let mut s = self.flat.model().strain_operator(grid, side)?;
        scale_columns([&mut s.p, &mut s.q], grid, &slope);
        self.remainder().add_w_derivatives_to(grid, [&mut s.p, &mut s.q]);
        Some(s)
    }

    /// [`Self::strain_operator`]'s product without its blocks (as [`Self::displacements`]).
    fn strain_at(&self, grid: &ContactGrid, side: Side, p: MatRef<'_, f64>, q: MatRef<'_, f64>) -> Option<Mat<f64>> {
        let (pa, qa) = (self.per_arc(grid, side, p), self.per_arc(grid, side, q));
        let flat = self.flat.model().strain_at(grid, side, pa.as_ref(), qa.as_ref())?;
        Some(flat + self.remainder().w_derivatives_times(grid, p, q))
    }
}

impl BodyFields for StandInBody {
    /// The full BEM body's boundary on the finest fitted grid under the load projected onto
    /// that grid (module docs).
    fn boundary_field(&self, load: &ContactLoad) -> Option<Result<BoundaryField, FieldError>> {
        let (grid, body) = self.setup.fitted.finest.as_ref()?;
        let pressure = load.grid.projected_onto(load.pressure, grid);
        let shear = load.grid.projected_onto(load.shear, grid);
        Some(
            body.boundary_solution(grid, &pressure, &shear)
                .map_err(FieldError::from),
        )
    }

    /// None: a run that asks for interior fields solves its final grid with the full BEM body.
    fn interior(&self, _query: &InteriorQuery) -> InteriorResult {
        Err(FieldError::NoInteriorField { model: "bem stand-in" })
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::adapt::cells::DyadicGrid;
    use nalgebra::DMatrix;

    /// The aluminium roller R 150 on a shaft of 15 of cases/fig14_true_geometry.yaml (body A).
    fn fig14_roller() -> BemSetup {
        crate::body::bem::setup::fig14_roller_in(Elastic::new(60_260.0, 0.31))
    }

    /// A level's remainder fitted from the body's response to the fit's loads (a factored BEM,
    /// 2(d + 1) right sides) is the least-squares series of the samples (B − H)_ij / w_j of the
    /// whole flexibility, as the fit was defined: P⁺ S P⁺ᵀ block by block, on the start grid
    /// and on its bisection (a level cut from the mesh), to round-off of the coefficients.
    #[test]
    fn the_fit_from_the_responses_is_the_fit_of_the_samples() {
        let setup = fig14_roller();
        let start = DyadicGrid::new(&setup.mesh.contact_grid());
        let rolling = Rolling {
            direction: 1.0,
            speed: None,
        };
        let half = HalfSpace::new(setup.material, setup.radius);
        for grid in [start.grid(), start.bisected().grid()] {
            let span = [grid.edges[0], grid.edges[grid.n_elements()]];
            let place = Placement {
                side: Side::A,
                rolling,
                span,
                degree: REMAINDER_DEGREE,
            };
            let level = level_fit(&setup, &half, &grid, &place, false, None).unwrap();
            let bem = level.body.model().flexibility(&grid, Side::A);
            let slope = |x: f64| setup.surface_at(x, Side::A).map_or(0.0, |s| s.slope_angle);
            let flat = arc_half_plane(&half, &grid, Side::A, &slope).unwrap();
            let t = chebyshev_rows(&grid.nodes, span[0], span[1], REMAINDER_DEGREE);
            let pinv = (t.transpose() * &t).try_inverse().unwrap() * t.transpose();
            let m = grid.n_nodes();
            for (k, (b, h)) in [
                (&bem.hp, &flat.hp),
                (&bem.hq, &flat.hq),
                (&bem.wp, &flat.wp),
                (&bem.wq, &flat.wq),
            ]
            .into_iter()
            .enumerate()
            {
                let samples = DMatrix::from_fn(m, m, |i, j| (b[(i, j)] - h[(i, j)]) / grid.weights[j]);
                let want = &pinv * samples * pinv.transpose();
                let got = &level.fit.coefficients[k];
                let scale = want.amax();
                assert!(scale > 0.0, "block {k}: a remainder to fit");
                assert!(
                    (got - &want).amax() <= 1e-10 * scale,
                    "block {k} on {} elements: {:.3e} of {scale:.3e}",
                    grid.n_elements(),
                    (got - &want).amax()
                );
            }
        }
    }
}
