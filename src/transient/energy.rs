//! The tangential energy balance of one step of a history (Johnson, *Contact Mechanics*, 1985,
//! §7.2 and §8.3: the work of the tangential force, the elastic strain energy and the frictional
//! dissipation; Kalker, *Three-dimensional elastic bodies in rolling contact*, 1990, §1.3, for
//! the slip over a step).
//!
//! With S the slip of a step as the solver forms it (src/transient.rs: the rigid shift, the
//! rigid slip of the surface speeds and the change of w = u_xA − u_xB at the material point),
//!
//! ```text
//! S_i = c + σΔk_i + w_i(t) − w(x_i − σΔ, t − 1)
//! D   = −∫ q·S dx                         (dissipation over the step, ≥ 0)
//! W   = −(Q·c + σΔ ∫ q·k dx)              (work of the rigid shift on the bodies)
//! U   = ½ ∫ q·w dx                        (the tangential part of ½∫(p·u_n + q·u_t) dx)
//! ```
//!
//! c the step's rigid shift of A relative to B [length]; q, the shear on A, opposes A's slip
//! relative to B (Coulomb), and the shift's agent pushes A with −Q. The step's slip is formed
//! with the shear at its end (an implicit step): for bodies whose flexibility is a convolution
//! (half-spaces) the old state shifted to the new material points keeps its energy, and
//! W − ΔU − D = ½⟨q − q̃, W_q(q − q̃)⟩ ≥ 0 (q̃ the old shear at the new material points), the
//! implicit step's own dissipation: quadratic in the change over the step, so O(Δ²) a step and
//! O(Δ) over a fixed rolled distance or a fixed shift divided into steps. The normal part ½∫p·u_n does no work on
//! the shear when the bodies are of one material (Dundurs' β = 0, Johnson §5.7), the case
//! these terms balance; else the coupling's work enters too.
//!
//! All terms are energies per unit length of the cylinders [force·length/length = force],
//! integrated with the grid's nodal weights (as Q = Σ w_j q_j); q is the shear on body A along
//! +x, S along +x of A relative to B.

/// The energy terms of one step [force] (energy per unit length of the cylinders).
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub struct StepEnergy {
    /// D = −∫ q·S dx: minus the shear's work over the slip of the step, the frictional dissipation
    /// (≥ 0: the shear opposes the slip in the slip zones; the solver's sign) [force].
    pub dissipation: f64,
    /// W = −(Q·c + σΔ∫q·k dx): the work done on the bodies by the step's rigid shift c of A
    /// relative to B against the tangential force (and the rigid slip k of curved bodies'
    /// surface speeds) [force].
    pub work: f64,
    /// ΔU = ½∫q·w dx (now) − ½∫q·w dx (the previous step): the change of the tangential
    /// elastic energy [force].
    pub stored_change: f64,
}

impl StepEnergy {
    /// W − ΔU − D [force]: zero for an exact balance; the implicit step's own dissipation
    /// (≥ 0, O(Δ²) a step) on a convolution flexibility.
    pub fn imbalance(&self) -> f64 {
        self.work - self.stored_change - self.dissipation
    }
}

/// The nodal fields of one step that its energy needs, all on the contact grid's nodes.
pub struct StepFields<'a> {
    /// The grid's nodal integration weights [length].
    pub weights: &'a [f64],
    /// The shear q at the end of the step [stress].
    pub shear: &'a [f64],
    /// The slip S over the step [length].
    pub slip: &'a [f64],
    /// w = u_xA − u_xB at the end of the step [length].
    pub displacement: &'a [f64],
    /// The shear at the end of the previous step [stress].
    pub previous_shear: &'a [f64],
    /// w at the end of the previous step [length].
    pub previous_displacement: &'a [f64],
    /// The rigid slip term σΔk_i of each node [length].
    pub rigid_slip: &'a [f64],
    /// The step's rigid shift c of A relative to B along +x [length].
    pub shift: f64,
}

/// D, W and ΔU of a step (module docs).
pub fn step_energy(f: &StepFields) -> StepEnergy {
    let integral = |a: &[f64], b: &[f64]| -> f64 { f.weights.iter().zip(a).zip(b).map(|((w, a), b)| w * a * b).sum() };
    let force: f64 = f.weights.iter().zip(f.shear).map(|(w, q)| w * q).sum();
    StepEnergy {
        dissipation: -integral(f.shear, f.slip),
        work: -(force * f.shift + integral(f.shear, f.rigid_slip)),
        stored_change: 0.5 * (integral(f.shear, f.displacement) - integral(f.previous_shear, f.previous_displacement)),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A rigid slide under a traction that does not change (q opposing the slip): all the work
    /// is dissipated.
    #[test]
    fn a_rigid_slide_dissipates_all_the_work() {
        let (weights, shear, w) = ([0.5, 1.0, 0.5], [-1.0, -2.0, -1.0], [0.1, 0.2, 0.1]);
        let e = step_energy(&StepFields {
            weights: &weights,
            shear: &shear,
            slip: &[0.3; 3],
            displacement: &w,
            previous_shear: &shear,
            previous_displacement: &w,
            rigid_slip: &[0.0; 3],
            shift: 0.3,
        });
        assert!((e.work - 0.9).abs() < 1e-15 && (e.dissipation - 0.9).abs() < 1e-15);
        assert_eq!(e.stored_change, 0.0);
        assert!(e.imbalance().abs() < 1e-15);
    }
}
