//! The viscoelastic half-space: a standard linear solid in steady rolling, as a half-plane whose
//! surface kernels are aged along the material's path through the contact
//! ([`aged_kernels`]; Johnson, *Contact Mechanics* §7.2; Hunter 1961; Kalker's viscoelastic
//! half-space in CONTACT).
//!
//! With a constant Poisson's ratio every half-plane coefficient (A, B of [`super::half_space`])
//! is a compliance ∝ 1/E, so the surface displacement under the steady tractions is
//!
//! ```text
//! u = [A_g, B_g]·K + ([A_r, B_r] − [A_g, B_g])·K^L,   L = V τc,
//! ```
//!
//! with K the elastic kernels (glassy constants g) and K^L their aged twins: the creep that the
//! material has not yet had time to make (its age in the contact is x/V) is what makes the
//! pressure lean towards the leading edge and the rolling cost work. The stresses under given
//! tractions do not depend on the material (a homogeneous half-plane), so the interior stresses
//! are Flamant's; the interior displacements are aged like the surface ones.
//!
//! τc = 0 is the rubbery elastic half-space and V τc → ∞ the glassy one (the tests check both
//! limits to round-off).

pub mod aged_kernels;
pub mod exponential_integrals;
pub mod setup;

use super::flamant::halfplane_interior;
use super::half_space::{influence_matrix_of, shared_influence_matrix, Kernel};
use super::pair_influence::{joined, shared_or_computed, Family, InfluenceKey, PairInfluence};
use super::{
    circle_profile, circle_profile_slope, BodyFields, BodyModel, Flexibility, InteriorQuery, InteriorResult, Side,
    StrainOperator,
};
use crate::grid::ContactGrid;
use crate::interior::{InteriorSample, InteriorValue};
use crate::material::StandardLinearSolid;
use crate::quadrature::gauss_legendre;
use aged_kernels::Ageing;
use faer::Mat;
use std::sync::Arc;

/// A viscoelastic half-plane standing in for a cylinder of radius `radius`, rolling steadily.
#[derive(Debug, Clone)]
pub struct ViscoelasticHalfSpace {
    /// The standard linear solid.
    pub material: StandardLinearSolid,
    /// Signed profile radius [length] (as [`super::half_space::HalfSpace::radius`]).
    pub radius: f64,
    /// The ageing of the material through the contact; None when τc = 0 (the rubbery elastic
    /// half-space).
    pub ageing: Option<Ageing>,
    /// The pair's shared influence matrices, when the body was built as one of a pair
    /// ([`PairInfluence`]: a twin body of the same L and direction takes the aged matrices this
    /// one computed, and any half-plane body the elastic ones); None computes them alone.
    pub pair: Option<Arc<PairInfluence>>,
}

impl ViscoelasticHalfSpace {
    /// Datum length ℓ = 2|R|/e [length] of the logarithmic displacement, as for the elastic
    /// half-space (the aged kernels keep it: ∫ e^(−v) dv = 1).
    pub fn datum_length(&self) -> f64 {
        2.0 * self.radius.abs() / std::f64::consts::E
    }

    /// The half-plane coefficients (A, B) [1/stress] of the glassy material and the part
    /// (A_r − A_g, B_r − B_g) that creeps.
    fn coefficients(&self) -> ([f64; 2], [f64; 2]) {
        let (g, r) = (self.material.glassy, self.material.rubbery());
        let glassy = [g.halfplane_sgn_coefficient(), g.halfplane_log_coefficient()];
        let rubbery = [r.halfplane_sgn_coefficient(), r.halfplane_log_coefficient()];
        match self.ageing {
            Some(_) => (glassy, [rubbery[0] - glassy[0], rubbery[1] - glassy[1]]),
            // τc = 0: all of the creep has happened at once.
            None => (rubbery, [0.0, 0.0]),
        }
    }

    /// The body as one of a pair that shares influence matrices through `pair` (joined here
    /// for the elastic kernels and, when it ages, for its aged ones), or on its own when `pair`
    /// is None.
    pub fn in_pair(mut self, pair: Option<&Arc<PairInfluence>>) -> Self {
        let aged = self.ageing.as_ref().map(aged_family);
        let families: Vec<Family> = std::iter::once(Family::HalfPlane).chain(aged).collect();
        self.pair = joined(pair, &families);
        self
    }

    /// K_ij of the aged kernel on the grid.
    fn aged_matrix(&self, grid: &ContactGrid, kernel: Kernel, ageing: &Ageing) -> Mat<f64> {
        let key = InfluenceKey {
            family: aged_family(ageing),
            kernel: kernel as u8,
        };
        shared_or_computed(self.pair.as_deref(), key, grid, || {
            influence_matrix_of(grid, |s1, s2, x| ageing.element_integrals(grid.kind, kernel, s1, s2, x))
        })
    }

    /// elastic·c_elastic + aged·c_aged, entry by entry (the aged matrix only where there is creep).
    fn combined(&self, grid: &ContactGrid, kernel: Kernel, elastic_coef: f64, creep_coef: f64) -> Mat<f64> {
        let mut k = shared_influence_matrix(self.pair.as_deref(), grid, kernel);
        for j in 0..k.ncols() {
            for v in k.col_mut(j).iter_mut() {
                *v *= elastic_coef;
            }
        }
        if let (Some(ageing), true) = (self.ageing, creep_coef != 0.0) {
            k += self.aged_matrix(grid, kernel, &ageing) * faer::Scale(creep_coef);
        }
        k
    }
}

/// The family of the aged kernels of `ageing` (its length and direction, bit for bit).
fn aged_family(ageing: &Ageing) -> Family {
    Family::Aged {
        length: ageing.length.to_bits(),
        direction: ageing.direction.to_bits(),
    }
}

impl BodyModel for ViscoelasticHalfSpace {
    fn model_name(&self) -> &'static str {
        "viscoelastic_half_space"
    }

    /// The half-space's blocks with the glassy coefficients on the elastic kernels and the
    /// creeping part on the aged ones (module docs).
    fn flexibility(&self, grid: &ContactGrid, side: Side) -> Flexibility {
        let ([a_g, b_g], [a_c, b_c]) = self.coefficients();
        let sign = side.sign();
        let ln_datum = self.datum_length().ln();
        // ∫ N_j ln(|x−s|/ℓ) ds = ∫ N_j ln|x−s| ds − w_j ln ℓ, in both the elastic and the aged part.
        let mut hp = self.combined(grid, Kernel::Log, -b_g, -b_c);
        for (j, &w) in grid.weights.iter().enumerate() {
            for v in hp.col_mut(j).iter_mut() {
                *v += (b_g + b_c) * w * ln_datum;
            }
        }
        let hq = self.combined(grid, Kernel::Sign, sign * a_g, sign * a_c);
        Flexibility::of_half_plane(hp, hq)
    }

    fn profile(&self, x: f64) -> f64 {
        circle_profile(self.radius, x)
    }

    fn profile_slope(&self, x: f64) -> f64 {
        circle_profile_slope(self.radius, x)
    }

    /// ∂w/∂x = −side·[2A_g p(x) + (A_r − A_g) ∫ p ∂K^L_sgn/∂x] − [B_g PV∫ q/(x−s) + (B_r − B_g)
    /// ∫ q K^L_(1/t)]: the elastic operator of the half-space plus its aged part.
    fn strain_operator(&self, grid: &ContactGrid, side: Side) -> Option<StrainOperator> {
        let ([a_g, b_g], [a_c, b_c]) = self.coefficients();
        let m = grid.n_nodes();
        let q = self.combined(grid, Kernel::Cauchy, -b_g, -b_c);
        let mut p = Mat::zeros(m, m);
        for i in 0..m {
            p[(i, i)] = -side.sign() * 2.0 * a_g;
        }
        if let (Some(ageing), true) = (self.ageing, a_c != 0.0) {
            let aged = influence_matrix_of(grid, |s1, s2, x| ageing.sign_derivative_integrals(grid.kind, s1, s2, x));
            p += aged * faer::Scale(-side.sign() * a_c);
        }
        Some(StrainOperator { p, q })
    }
}

impl BodyFields for ViscoelasticHalfSpace {
    /// Stresses: Flamant's (they do not depend on the material of a homogeneous half-plane).
    /// Displacements: the unit-compliance Flamant displacement u₁ aged along the material path,
    /// u = u₁/G_g + (1/G_r − 1/G_g) ∫_0^∞ e^(−v) u₁(x + dLv) dv, by a Gauss rule on panels that
    /// double from a quarter of the point's depth (u₁ varies on the scale of the depth).
    fn interior(&self, query: &InteriorQuery) -> InteriorResult {
        let (g, r) = (self.material.glassy, self.material.rubbery());
        let unit = |points: &[[f64; 2]]| {
            halfplane_interior(
                &query.load,
                1.0,
                g.poisson,
                self.datum_length(),
                query.side,
                points,
                &query.options,
            )
        };
        let here = unit(query.points);
        let Some(ageing) = self.ageing else {
            return Ok(scale_displacements(here, 1.0 / r.shear()));
        };
        let creep = 1.0 / r.shear() - 1.0 / g.shear();
        let (gx, gw) = gauss_legendre(6);
        let mut out = Vec::with_capacity(here.len());
        for (sample, &[x, y]) in here.into_iter().zip(query.points) {
            let InteriorSample::Inside(value) = sample else {
                out.push(sample);
                continue;
            };
            let panels = ageing_panels(y.abs(), ageing.length);
            let mut shifted = Vec::new();
            let mut weights = Vec::new();
            for pair in panels.windows(2) {
                let (a, b) = (pair[0], pair[1]);
                for (xi, w) in gx.iter().zip(&gw) {
                    let v = 0.5 * (a + b) + 0.5 * (b - a) * xi;
                    shifted.push([x + ageing.direction * ageing.length * v, y]);
                    weights.push(0.5 * (b - a) * w * (-v).exp());
                }
            }
            let mut aged = [0.0; 2];
            for (s, w) in unit(&shifted).into_iter().zip(&weights) {
                if let InteriorSample::Inside(v) = s {
                    aged[0] += w * v.displacement[0];
                    aged[1] += w * v.displacement[1];
                }
            }
            let displacement = std::array::from_fn(|k| value.displacement[k] / g.shear() + creep * aged[k]);
            out.push(InteriorSample::Inside(InteriorValue {
                displacement,
                stress: value.stress,
            }));
        }
        Ok(out)
    }
}

/// Panel ends in the ageing variable v for a point at `depth`: 0, then (depth/4)·2^k / L
/// doubling up to v = 40 (e^(−40) ≈ 4e-18).
fn ageing_panels(depth: f64, length: f64) -> Vec<f64> {
    let mut ends = vec![0.0];
    let mut v = 0.25 * depth / length;
    while v < 40.0 {
        ends.push(v);
        v *= 2.0;
    }
    ends.push(40.0);
    ends
}

/// The samples' displacements times `factor` (a unit-compliance field made physical).
fn scale_displacements(samples: Vec<InteriorSample>, factor: f64) -> Vec<InteriorSample> {
    samples
        .into_iter()
        .map(|s| match s {
            InteriorSample::Inside(v) => InteriorSample::Inside(InteriorValue {
                displacement: v.displacement.map(|u| u * factor),
                stress: v.stress,
            }),
            other => other,
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::body::half_space::HalfSpace;
    use crate::grid::ElementKind;
    use crate::material::Elastic;

    fn same(a: &Flexibility, b: &Flexibility) -> bool {
        a.hp == b.hp && a.hq == b.hq && a.wp == b.wp && a.wq == b.wq
    }

    /// Bodies built as a pair take the influence matrices the first computed and get the same
    /// bits as bodies on their own; a matrix only one of them needs (a half-space next to a
    /// viscoelastic body: the aged ones) is not kept.
    #[test]
    fn a_pair_shares_its_influence_matrices_and_gets_the_same_flexibilities() {
        let grid = ContactGrid::uniform(ElementKind::DiscontinuousQuadratic, 12, -1.3, 1.3);
        let material = StandardLinearSolid {
            glassy: Elastic::new(3000.0, 0.4),
            rubbery_young: 1500.0,
            creep_time: 0.01,
        };
        let ageing = Some(Ageing {
            length: 0.7,
            direction: 1.0,
        });
        let alone = |radius: f64| ViscoelasticHalfSpace {
            material,
            radius,
            ageing,
            pair: None,
        };
        // Two viscoelastic bodies (different radii, one ageing): everything is shared.
        let pair = Arc::new(PairInfluence::new());
        let a = alone(50.0).in_pair(Some(&pair));
        let b = alone(80.0).in_pair(Some(&pair));
        let fa = a.flexibility(&grid, Side::A);
        assert!(pair.kept() > 0, "the first body keeps what the second needs");
        let fb = b.flexibility(&grid, Side::B);
        assert_eq!(pair.kept(), 0, "the second body took every kept matrix");
        assert!(same(&fa, &alone(50.0).flexibility(&grid, Side::A)));
        assert!(same(&fb, &alone(80.0).flexibility(&grid, Side::B)));
        let (sa, sb) = (a.strain_operator(&grid, Side::A), b.strain_operator(&grid, Side::B));
        assert_eq!(pair.kept(), 0);
        let own = alone(80.0).strain_operator(&grid, Side::B).unwrap();
        let sb = sb.unwrap();
        assert!(sa.is_some() && sb.p == own.p && sb.q == own.q);

        // A half-space and a viscoelastic body share the elastic kernels only.
        let pair = Arc::new(PairInfluence::new());
        let h = HalfSpace::new(Elastic::new(210_000.0, 0.3), 100.0).in_pair(Some(&pair));
        let v = alone(50.0).in_pair(Some(&pair));
        let fh = h.flexibility(&grid, Side::A);
        assert_eq!(pair.kept(), 2, "ln and sgn wait for the second body");
        let fv = v.flexibility(&grid, Side::B);
        assert_eq!(pair.kept(), 0, "the aged matrices were not kept for anyone");
        assert!(same(
            &fh,
            &HalfSpace::new(Elastic::new(210_000.0, 0.3), 100.0).flexibility(&grid, Side::A)
        ));
        assert!(same(&fv, &alone(50.0).flexibility(&grid, Side::B)));
    }
}
