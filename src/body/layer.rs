//! The layer body model: a cover of thickness b bonded to a rigid core, elastic or a standard
//! linear solid, in plane strain (Bentall & Johnson 1968; Nowell & Hills 1988b; Johnson,
//! *Contact Mechanics* §5.9, §7.2).
//!
//! The cover is taken flat (b ≪ R, the core's curvature neglected in its compliance) with the
//! profile of a circle of its outer radius R, and its surface kernels are exact for that flat
//! layer: the Fourier integrals of its compliances ([`compliance`]). Each kernel is split into
//! the half-plane's, whose element integrals are closed forms ([`super::half_space`], or for a
//! viscoelastic cover the aged ones of [`super::viscoelastic::aged_kernels`]), and a smooth
//! remainder ([`remainder`]) tabulated and integrated by Gauss. The rigid core is the datum of
//! the approach: unlike the half-space's, the overlap is absolute (the datum length ℓ of the
//! half-plane part cancels between its two parts).
//!
//! With a constant Poisson's ratio every compliance is ∝ 1/G, so a viscoelastic cover's surface
//! displacement is, as the viscoelastic half-space's,
//! u = K/G_g + (1/G_r − 1/G_g)·K^L with K the unit-modulus kernel and K^L its twin aged along the
//! material path (L = Vτc).
//!
//! The model gives no interior field and no boundary-integral strain operator (the slip is
//! re-checked from the displacements only).

pub mod compliance;
pub mod remainder;
pub mod setup;

use super::viscoelastic::aged_kernels::Ageing;
use super::viscoelastic::ViscoelasticHalfSpace;
use super::{circle_profile, BodyFields, BodyModel, FieldError, Flexibility, InteriorQuery, InteriorResult, Side, StrainOperator};
use crate::grid::ContactGrid;
use crate::material::StandardLinearSolid;
use faer::Mat;
use remainder::{Component, Remainder};

/// A layer bonded to a rigid core (module docs).
#[derive(Debug, Clone)]
pub struct Layer {
    /// The cover's material: an elastic one is a standard linear solid whose rubbery modulus is
    /// its glassy one and whose creep time is 0.
    pub material: StandardLinearSolid,
    /// Cover thickness b [length].
    pub thickness: f64,
    /// Signed outer radius of the cover [length]: the profile.
    pub radius: f64,
    /// The ageing of the material through the contact; None for an elastic cover or τc = 0.
    pub ageing: Option<Ageing>,
}

impl Layer {
    /// The half-plane part: the (viscoelastic) half-space of the same material, its datum
    /// length ℓ = 2R'/e set to the thickness b by R' = e·b/2 (ℓ cancels between the two parts;
    /// ℓ = b keeps their constants small whatever the profile radius, a flat cover's 1e12 too).
    fn half_plane(&self) -> ViscoelasticHalfSpace {
        ViscoelasticHalfSpace {
            material: self.material,
            radius: 0.5 * std::f64::consts::E * self.thickness,
            ageing: self.ageing,
        }
    }

    /// The remainder blocks [nn, nt, tt] on the grid [length/stress]: the unit-modulus tables
    /// over 1/G_r (no ageing), or over 1/G_g plus the aged tables times (1/G_r − 1/G_g).
    fn remainder_blocks(&self, grid: &ContactGrid) -> [Mat<f64>; 3] {
        let reach = grid.edges[grid.edges.len() - 1] - grid.edges[0];
        let nu = self.material.glassy.poisson;
        let datum = self.half_plane().datum_length();
        let (g, r) = (self.material.glassy.shear(), self.material.rubbery().shear());
        let components = [
            Component::NormalNormal,
            Component::NormalTangential,
            Component::TangentialTangential,
        ];
        let elastic = Remainder::tabulate(self.thickness, nu, datum, reach, None);
        let (elastic_scale, aged) = match &self.ageing {
            None => (1.0 / r, None),
            Some(a) => (
                1.0 / g,
                Some(Remainder::tabulate(self.thickness, nu, datum, reach, Some(a))),
            ),
        };
        components.map(|c| {
            let mut m = elastic.matrix(grid, c) * faer::Scale(elastic_scale);
            if let Some(aged) = &aged {
                m += aged.matrix(grid, c) * faer::Scale(1.0 / r - 1.0 / g);
            }
            m
        })
    }
}

impl BodyModel for Layer {
    fn model_name(&self) -> &'static str {
        "layer"
    }

    /// The half-plane part's blocks plus the remainder's: h from p by S_nn, w from q by S_tt,
    /// h from q by side·S_nt and w from p by −side·S_nt (K_tn = −K_nt, as the half-plane's
    /// sign kernels).
    fn flexibility(&self, grid: &ContactGrid, side: Side) -> Flexibility {
        let mut f = self.half_plane().flexibility(grid, side);
        let [nn, nt, tt] = self.remainder_blocks(grid);
        f.hp += &nn;
        f.wq += &tt;
        let coupling = nt * faer::Scale(side.sign());
        f.hq += &coupling;
        f.wp -= &coupling;
        f
    }

    fn profile(&self, x: f64) -> f64 {
        circle_profile(self.radius, x)
    }

    /// None: the remainder's strain kernel is not assembled (module docs).
    fn strain_operator(&self, _grid: &ContactGrid, _side: Side) -> Option<StrainOperator> {
        None
    }
}

impl BodyFields for Layer {
    /// The layer's interior is not modelled: [`FieldError::NoInteriorModel`].
    fn interior(&self, _query: &InteriorQuery) -> InteriorResult {
        Err(FieldError::NoInteriorModel {
            model: self.model_name(),
            why: "its kernels are known on the surface only",
        })
    }
}
