//! The layer model's setup: a cover of given material, outer radius and thickness on a rigid
//! core, built on any grid from the half-plane integrals and the layer's tabulated remainder.

use super::{remainder, Layer};
use crate::body::setup::{BodySetup, BuildContext, BuildError, ContactScales, NormalLoad, Rolling, SurfaceAt};
use crate::body::transfer::Transferred;
use crate::body::viscoelastic::aged_kernels::Ageing;
use crate::body::{Body, Side};
use crate::material::{Elastic, StandardLinearSolid};

/// Most kernel evaluations the layer's tables may take [-]: about a second on two cores
/// (1e8 a second and core), and 40 bytes per wavenumber node held (under 100 MB).
pub const MAX_TABLE_WORK: f64 = 2e8;

/// A `layer` body of a scene (module docs of [`super`]).
#[derive(Debug, Clone)]
pub struct LayerSetup {
    /// The cover's material (an elastic one: rubbery = glassy, creep time 0).
    pub material: StandardLinearSolid,
    /// Signed outer radius of the cover [length].
    pub radius: f64,
    /// Cover thickness b [length].
    pub thickness: f64,
}

impl LayerSetup {
    /// An elastic cover.
    pub fn elastic(material: Elastic, radius: f64, thickness: f64) -> Self {
        Self {
            material: StandardLinearSolid {
                glassy: material,
                rubbery_young: material.young,
                creep_time: 0.0,
            },
            radius,
            thickness,
        }
    }

    /// The thinnest cover whose tables on a grid `reach` long stay within [`MAX_TABLE_WORK`]
    /// [length] (bisection in log b: the work falls as b grows), for the refusal's advice.
    fn thinnest_affordable(&self, ctx: &BuildContext, reach: f64) -> f64 {
        let work = |b: f64| {
            let model = LayerSetup {
                thickness: b,
                ..self.clone()
            }
            .model(ctx);
            remainder::tabulation_work(b, reach, None)
                + model
                    .ageing
                    .map_or(0.0, |a| remainder::tabulation_work(b, reach, Some(&a)))
        };
        let (mut lo, mut hi) = (self.thickness, reach.max(self.thickness));
        for _ in 0..60 {
            let mid = (lo * hi).sqrt();
            if work(mid) > MAX_TABLE_WORK {
                lo = mid;
            } else {
                hi = mid;
            }
        }
        hi
    }

    /// The model on the kinematics of `ctx`: aged with L = V τc when the material creeps
    /// (the case's validation guarantees a speed whenever τc > 0).
    pub fn model(&self, ctx: &BuildContext) -> Layer {
        self.rolling_as(ctx.rolling)
    }

    /// The model rolling as `rolling` says (see [`Self::model`]).
    pub fn rolling_as(&self, rolling: Rolling) -> Layer {
        let length = self.material.creep_time * rolling.speed.unwrap_or(0.0);
        let creeps = length > 0.0 && self.material.rubbery_young < self.material.glassy.young;
        Layer {
            material: self.material,
            thickness: self.thickness,
            radius: self.radius,
            ageing: creeps.then_some(Ageing {
                length,
                direction: rolling.direction,
            }),
        }
    }
}

impl BodySetup for LayerSetup {
    fn model_name(&self) -> &'static str {
        "layer"
    }

    fn radius(&self) -> f64 {
        self.radius
    }

    /// The rubbery constants (the elastic ones of an elastic cover): the softest, widest
    /// contact, which the grid must cover.
    fn hertz_material(&self) -> Option<Elastic> {
        Some(self.material.rubbery())
    }

    /// The cover is stiffer than the half-plane of its material (its rigid core), the more so
    /// the thinner it is: the scales of its own flexibility, on the model of the run's rolling
    /// (a viscoelastic cover as fast as it rolls), against a rigid cylinder
    /// ([`crate::body::scales`]); an overlap measured from the core.
    fn own_contact_scales(
        &self,
        load: NormalLoad,
        effective_radius: f64,
        hertz_half_width: f64,
        rolling: Rolling,
    ) -> Option<ContactScales> {
        let model = self.rolling_as(rolling);
        // The estimate solves on grids about 2.6 Hertz half-widths long (the second one
        // shorter for a cover stiffer than its half-plane): tables too costly there are
        // refused by `preflight` on the run's grid, and the estimate falls back to Hertz's.
        let estimating = 4.0 * 1.3 * hertz_half_width;
        let work = 2.0 * remainder::tabulation_work(self.thickness, estimating, model.ageing.as_ref());
        if work.is_nan() || work > MAX_TABLE_WORK {
            return None;
        }
        let block = crate::body::scales::pressure_block(&model);
        crate::body::scales::normal_contact_scales(&block, load, effective_radius, hertz_half_width)
    }

    /// The half-space's error against the true geometry is not this model's (its own is the
    /// flat cover's, b ≪ R).
    fn shares_half_space_error(&self) -> bool {
        false
    }

    /// The layer's own kernels are exact for a flat cover; the half-plane idealisation's
    /// a/R error estimate does not apply.
    fn idealises_as_half_plane(&self) -> bool {
        false
    }

    /// A BEM model of an elastic cover exists (`geometry: covered_roller`), of a viscoelastic
    /// one not.
    fn has_true_geometry_model(&self) -> bool {
        self.material.creep_time == 0.0
    }

    fn surface_at(&self, _x: f64, _side: Side) -> Option<SurfaceAt> {
        None
    }

    fn relaxation_layer(&self, speed: Option<f64>) -> Option<f64> {
        let layer = speed? * self.material.relaxation_time();
        (layer > 0.0).then_some(layer)
    }

    /// The profile radius, or 20 b where that is smaller: a load's effect on a bonded layer
    /// decays like e^(−c|x|/b), c ≈ 1.3–2 (for the half-plane estimate that sizes the grid).
    fn datum_distance(&self) -> f64 {
        self.radius.abs().min(20.0 * self.thickness)
    }

    // `layer_thickness` keeps its default None: the model advice it feeds estimates the error
    // a half-space model makes on a layer, which this model does not make.

    /// The tables' evaluations on the grid ([`Layer::table_work`]).
    fn kernel_table_evaluations(&self, ctx: &BuildContext) -> f64 {
        self.model(ctx).table_work(ctx.grid)
    }

    /// The kernel tables' cost on the grid ([`Layer::table_work`]) within [`MAX_TABLE_WORK`].
    fn preflight(&self, ctx: &BuildContext) -> Result<(), BuildError> {
        let work = self.model(ctx).table_work(ctx.grid);
        if work <= MAX_TABLE_WORK {
            return Ok(());
        }
        let reach = ctx.grid.edges[ctx.grid.edges.len() - 1] - ctx.grid.edges[0];
        let side = match ctx.side {
            Side::A => "A",
            Side::B => "B",
        };
        Err(BuildError::Cost(format!(
            "bodies.{side}.thickness: a cover of b = {:e} under a contact grid {reach:.4e} long (grid/b = {:.0}) \
             needs {work:.1e} kernel evaluations for its kernel tables, more than {MAX_TABLE_WORK:.0e} (a few \
             seconds): the aged tables of a \
             viscoelastic cover span the grid and grow with (grid/b)²; give a cover of b = {:.2e} or \
             thicker, or a shorter grid (contact.grid.half_length)",
            self.thickness,
            reach / self.thickness,
            self.thinnest_affordable(ctx, reach),
        )))
    }

    /// As the half-space: on a grid of curved elements built on the straightened grid and
    /// carried over.
    fn build(&self, ctx: &BuildContext) -> Result<Box<dyn Body>, BuildError> {
        self.preflight(ctx)?;
        Ok(Transferred::flat_model_on(
            Box::new(self.model(ctx)),
            ctx.grid,
            ctx.side,
        )?)
    }
}
