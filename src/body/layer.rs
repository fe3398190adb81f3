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

use super::kind::Capabilities;
use super::viscoelastic::aged_kernels::Ageing;
use super::viscoelastic::ViscoelasticHalfSpace;
use super::{
    circle_profile, circle_profile_slope, BodyFields, BodyModel, FieldError, Flexibility, InteriorQuery,
    InteriorResult, Side, StrainOperator,
};
use crate::grid::ContactGrid;
use crate::material::StandardLinearSolid;
use faer::Mat;
use remainder::{Component, Remainder};

/// What the checks of a case ask of the `layer` model. A cover on a rigid core: it deforms and takes a viscoelastic material, but its flat-layer
/// kernels give its surface tractions only, not the stresses inside the cover.
pub const CAPABILITIES: Capabilities = Capabilities {
    name: "layer",
    deforms: true,
    accepts_viscoelastic: true,
    interior_fields: false,
    boundary_elements: false,
};

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
            pair: None,
        }
    }

    /// Kernel evaluations that [`Self::remainder_blocks`] spends on its tables on `grid`
    /// ([`remainder::tabulation_work`]): the elastic table, and the aged one of a creeping cover.
    pub fn table_work(&self, grid: &ContactGrid) -> f64 {
        let reach = grid.edges[grid.edges.len() - 1] - grid.edges[0];
        let elastic = remainder::tabulation_work(self.thickness, reach, None);
        elastic
            + self
                .ageing
                .as_ref()
                .map_or(0.0, |a| remainder::tabulation_work(self.thickness, reach, Some(a)))
    }

    /// The remainder blocks [nn, nt, tt] on the grid [length/stress]: the unit-modulus tables
    /// over 1/G_r (no ageing), or over 1/G_g plus the aged tables times (1/G_r − 1/G_g).
    fn remainder_blocks(&self, grid: &ContactGrid) -> [Mat<f64>; 3] {
        let reach = grid.edges[grid.edges.len() - 1] - grid.edges[0];
        let nu = self.material.glassy.poisson;
        let datum = self.half_plane().datum_length();
        let (g, r) = (self.material.glassy.shear(), self.material.rubbery().shear());
        let elastic = Remainder::tabulate(self.thickness, nu, datum, reach, None);
        let (elastic_scale, aged) = match &self.ageing {
            None => (1.0 / r, None),
            Some(a) => (
                1.0 / g,
                Some(Remainder::tabulate(self.thickness, nu, datum, reach, Some(a))),
            ),
        };
        Component::ALL.map(|c| {
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

    fn profile_slope(&self, x: f64) -> f64 {
        circle_profile_slope(self.radius, x)
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

#[cfg(test)]
mod tests {
    use super::*;
    use crate::grid::ElementKind;
    use crate::material::Elastic;
    use crate::quadrature::gauss_legendre;
    use compliance::layer_compliance;

    /// The flexibility blocks applied to a Gaussian load e^(−x²/σ²) (its transform
    /// σ√π e^(−k²σ²/4)) against the surface displacements summed in Fourier space from the
    /// compliances directly: w = (1/π)∫ C_nn p̂ cos kx dk, u_x from shear likewise with C_tt,
    /// u_z from shear −(1/π)∫ C_nt q̂ sin kx dk, u_x from pressure (1/π)∫ C_tn p̂ sin kx dk. This
    /// checks the split, the datum and the tabulated remainder on a thin layer (b = σ/6), to the
    /// grid's interpolation error of the load (measured 2e-6 of the largest displacement, allowed
    /// 1e-5).
    #[test]
    fn flexibility_is_the_fourier_response_to_a_gaussian_load() {
        let (sigma, b, g) = (0.3, 0.05, 1.7);
        let grid = ContactGrid::uniform(ElementKind::DiscontinuousQuadratic, 100, -2.0, 2.0);
        let load: Vec<f64> = grid.nodes.iter().map(|x| (-(x / sigma).powi(2)).exp()).collect();
        let (gx, gw) = gauss_legendre(16);
        for nu in [0.3, 0.5] {
            let layer = Layer {
                material: StandardLinearSolid {
                    glassy: Elastic::from_shear(g, nu),
                    rubbery_young: Elastic::from_shear(g, nu).young,
                    creep_time: 0.0,
                },
                thickness: b,
                radius: 1e12,
                ageing: None,
            };
            let f = layer.flexibility(&grid, Side::A);
            let apply = |m: &Mat<f64>| -> Vec<f64> {
                (0..grid.n_nodes())
                    .map(|i| (0..grid.n_nodes()).map(|j| m[(i, j)] * load[j]).sum())
                    .collect()
            };
            let (hp, hq, wp, wq) = (apply(&f.hp), apply(&f.hq), apply(&f.wp), apply(&f.wq));
            let scale = hp.iter().chain(&wq).fold(0.0_f64, |m, v| m.max(v.abs()));
            for (i, &x) in grid.nodes.iter().enumerate().step_by(7) {
                let mut direct = [0.0; 4];
                for p in 0..800 {
                    let (k0, k1) = (p as f64 * 0.2, (p + 1) as f64 * 0.2);
                    for (t, w) in gx.iter().zip(&gw) {
                        let k = 0.5 * (k0 + k1) + 0.5 * (k1 - k0) * t;
                        let weight = 0.5 * (k1 - k0) * w / std::f64::consts::PI
                            * sigma
                            * std::f64::consts::PI.sqrt()
                            * (-0.25 * (k * sigma).powi(2)).exp();
                        let c = layer_compliance(k, b, g, nu);
                        let (sin, cos) = (k * x).sin_cos();
                        direct[0] += weight * c.nn * cos;
                        direct[1] -= weight * c.nt * sin;
                        direct[2] += weight * c.tn * sin;
                        direct[3] += weight * c.tt * cos;
                    }
                }
                for (name, model, d) in [
                    ("hp", hp[i], direct[0]),
                    ("hq", hq[i], direct[1]),
                    ("wp", wp[i], direct[2]),
                    ("wq", wq[i], direct[3]),
                ] {
                    assert!((model - d).abs() < 1e-5 * scale, "nu {nu} x {x} {name}: {model} vs {d}");
                }
            }
        }
    }
}
