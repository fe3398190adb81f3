//! What integration and assembly need of a fundamental solution of 2D elastostatics: the
//! displacement kernel U*, the traction kernel T* and the coefficient of U*'s logarithm (which
//! the weakly singular integration subtracts and integrates with a log-weighted rule).
//!
//! [`crate::bem::integrate`] and [`crate::bem::assemble`] are generic over
//! [`FundamentalSolution`], as kernel and assembler are separate pieces in bempp-rs and
//! green-kernels: an anisotropic or viscoelastic (complex-modulus) kernel adds an
//! implementation here, not an assembler. The Kelvin solution of an isotropic elastic plane
//! ([`Kelvin`], Brebbia–Dominguez, *Boundary Elements: An Introductory Course*, §5.2) is the one
//! implementation today; the hypersingular and interior kernels (its gradients and stresses)
//! stay Kelvin's own.

use super::kernel::{Kelvin, KernelFrame};

/// A 2D elastostatic fundamental solution: a unit line force in direction i at the source
/// gives displacement U*_ij and traction T*_ij (on a surface of unit normal n) at the field
/// point. U* must be c·ln(1/r)·δij plus a function bounded at r → 0, T* of order 1/r.
pub trait FundamentalSolution: Sync {
    /// Coefficient c of the logarithmic part c·ln(1/r)·δij of U* [1/stress].
    fn log_coefficient(&self) -> f64;

    /// U*_ij [1/stress] in the frame of one source–field pair.
    fn displacement_in(&self, frame: &KernelFrame) -> [[f64; 2]; 2];

    /// T*_ij [1/length] in the frame of one source–field pair, for the field point's unit
    /// outward normal `normal`.
    fn traction_in(&self, frame: &KernelFrame, normal: [f64; 2]) -> [[f64; 2]; 2];
}

impl FundamentalSolution for Kelvin {
    #[inline]
    fn log_coefficient(&self) -> f64 {
        Kelvin::log_coefficient(self)
    }

    #[inline]
    fn displacement_in(&self, frame: &KernelFrame) -> [[f64; 2]; 2] {
        Kelvin::displacement_in(self, frame)
    }

    #[inline]
    fn traction_in(&self, frame: &KernelFrame, normal: [f64; 2]) -> [[f64; 2]; 2] {
        Kelvin::traction_in(self, frame, normal)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::bem::{BemModel, BemOptions, BoundaryCondition};
    use crate::material::Elastic;
    use crate::mesh::build::half_space_block;

    /// A fundamental solution whose U* is twice Kelvin's (a material of half the shear
    /// modulus and the same ν has exactly that U* and the same T*).
    struct DoubledDisplacement(Kelvin);

    impl FundamentalSolution for DoubledDisplacement {
        fn log_coefficient(&self) -> f64 {
            2.0 * self.0.log_coefficient()
        }
        fn displacement_in(&self, frame: &KernelFrame) -> [[f64; 2]; 2] {
            self.0.displacement_in(frame).map(|row| row.map(|v| 2.0 * v))
        }
        fn traction_in(&self, frame: &KernelFrame, normal: [f64; 2]) -> [[f64; 2]; 2] {
            self.0.traction_in(frame, normal)
        }
    }

    /// The assembler takes any fundamental solution: one given by the trait alone (U* doubled)
    /// assembles G twice Kelvin's and the same H, which is what the Kelvin model of a material
    /// with half the shear modulus assembles.
    #[test]
    fn assembly_is_generic_over_the_fundamental_solution() {
        let mesh = half_space_block(4.0, 2.0, 0.5, 4, 0.5, false);
        let conditions = |mesh: &crate::mesh::BoundaryMesh| -> Vec<(String, BoundaryCondition)> {
            mesh.groups
                .iter()
                .map(|g| {
                    let c = if g.name == "contact" {
                        BoundaryCondition::Contact
                    } else if g.name == "far" {
                        BoundaryCondition::Fixed
                    } else {
                        BoundaryCondition::Free
                    };
                    (g.name.clone(), c)
                })
                .collect()
        };
        let steel = Elastic::new(210_000.0, 0.3);
        let soft = Elastic::from_shear(0.5 * steel.shear(), 0.3);
        let model = BemModel::new(mesh.clone(), steel, conditions(&mesh), BemOptions::default()).unwrap();
        let half = BemModel::new(mesh.clone(), soft, conditions(&mesh), BemOptions::default()).unwrap();
        let doubled = model.assemble_with(&DoubledDisplacement(*model.kernel()));
        let reference = half.assemble();
        let scale = reference.g.norm_max();
        assert!((&doubled.g - &reference.g).norm_max() <= 1e-12 * scale);
        assert!((&doubled.h - &reference.h).norm_max() <= 1e-12 * reference.h.norm_max());
        let kelvin = model.assemble();
        assert!((&doubled.g - &(&kelvin.g * faer::Scale(2.0))).norm_max() <= 1e-12 * scale);
    }
}
