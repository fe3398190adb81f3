//! The energy balance of one step of a history (Johnson, *Contact Mechanics*, 1985, §7.2 and
//! §8.3: the work of the forces, the elastic strain energy and the frictional dissipation;
//! Kalker, *Three-dimensional elastic bodies in rolling contact*, 1990, §1.3, for the slip
//! over a step).
//!
//! With S the slip of a step as the solver forms it (src/transient.rs: the rigid shift, the
//! rigid slip of the surface speeds and the change of w = u_xA − u_xB at the material point),
//! h the compression (the displacements into both bodies, H_p p + H_q q), h₀ the profile and δ
//! the approach (the gap g = h₀ − δ + h, zero where p > 0):
//!
//! ```text
//! S_i = c + σΔk_i + w_i(t) − w(x_i − σΔ, t − 1)
//! D   = −∫ q·S dx                              (frictional dissipation over the step, ≥ 0)
//! W   = −(Q·c + σΔ ∫ q·k dx)                   (work of the rigid shift on the bodies)
//! W_n = P·(δ(t) − δ(t − 1)) − ∫ p·(h₀(x) − h₀(x − σΔ)) dx
//!                                              (work of the approach and of the profile)
//! C   = ∫ p·g(x − σΔ, t − 1) dx                (the gap the step closes, ≥ 0)
//! U   = ½ ∫ (p·h + q·w) dx                     (the stored elastic energy)
//! ```
//!
//! c the step's rigid shift of A relative to B [length]; q, the shear on A, opposes A's slip
//! relative to B (Coulomb), and the shift's agent pushes A with −Q. The tractions' work on the
//! bodies over the step, formed with the tractions at its end (an implicit step), is
//! ⟨p, h − h̃⟩ + ⟨q, w − w̃⟩ (h̃, w̃ the previous step's at the new material points), and by
//! the slip's definition and g = 0 under pressure that is W + W_n − C − D. For bodies whose
//! flexibility is a convolution (half-spaces) the previous state shifted to the new material
//! points keeps its energy, and with the flexibility symmetric (Betti: W_p = H_qᵀ)
//!
//! ```text
//! W + W_n − ΔU − D − C = ½⟨x − x̃, F(x − x̃)⟩ ≥ 0,      x = (p, q), F the flexibility,
//! ```
//!
//! the implicit step's own dissipation: quadratic in the change over the step, so O(Δ²) a step
//! and O(Δ) over a fixed rolled distance or a fixed shift divided into steps. For bodies of one
//! material (Dundurs' β = 0, Johnson §5.7) the pressure does no tangential work, the pressure
//! of a step under a constant P does not change, and W_n, C and the normal part of ΔU vanish to
//! the discretization's round-off: the tangential terms balance on their own. For dissimilar
//! bodies the coupling's work enters through them. U's normal part is measured from the body
//! model's datum of h and δ (a half-space's logarithmic displacement has no absolute one), which
//! cancels in ΔU and W_n while P stays constant.
//!
//! All terms are energies per unit length of the cylinders [force·length/length = force],
//! integrated with the grid's nodal weights (as Q = Σ w_j q_j, P = Σ w_j p_j); q is the shear on
//! body A along +x, S along +x of A relative to B, p ≥ 0 compressive.

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
    /// W_n = P·Δδ − ∫p·(h₀(x) − h₀(x − σΔ)) dx: the work of the step's change of approach and
    /// of the profile's passage through the material [force].
    pub normal_work: f64,
    /// C = ∫p·g̃ dx ≥ 0, g̃ the previous step's gap at the new material points: the gap the
    /// step closes under its pressure, an implicit step's loss like the slip's [force].
    pub closing: f64,
    /// ΔU = ½∫(p·h + q·w) dx (now) − the same at the previous step: the change of the stored
    /// elastic energy [force].
    pub stored_change: f64,
    /// ΔU_t, the change of ½∫q·w dx alone: the tangential part of ΔU [force].
    pub tangential_stored_change: f64,
}

impl StepEnergy {
    /// W + W_n − ΔU − D − C [force]: zero for an exact balance; the implicit step's own
    /// dissipation (≥ 0, O(Δ²) a step) on a convolution flexibility (module docs).
    pub fn imbalance(&self) -> f64 {
        self.work + self.normal_work - self.stored_change - self.dissipation - self.closing
    }

    /// W − ΔU_t − D [force]: the tangential balance without the pressure's terms, which equals
    /// [`Self::imbalance`] for bodies of one material and misses the coupling's work for
    /// dissimilar ones.
    pub fn tangential_imbalance(&self) -> f64 {
        self.work - self.tangential_stored_change - self.dissipation
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
    /// The pressure at the end of the step [stress].
    pub pressure: &'a [f64],
    /// The compression h at the end of the step [length].
    pub compression: &'a [f64],
    /// The pressure at the end of the previous step [stress].
    pub previous_pressure: &'a [f64],
    /// h at the end of the previous step [length].
    pub previous_compression: &'a [f64],
    /// The previous step's gap at each node's material point one step earlier, g(x_i − σΔ)
    /// [length].
    pub previous_gap_upstream: &'a [f64],
    /// h₀(x_i) − h₀(x_i − σΔ): the profile's change at each node's material point [length].
    pub profile_change: &'a [f64],
    /// The step's change of approach δ(t) − δ(t − 1) [length].
    pub approach_change: f64,
    /// The rigid slip term σΔk_i of each node [length].
    pub rigid_slip: &'a [f64],
    /// The step's rigid shift c of A relative to B along +x [length].
    pub shift: f64,
}

/// D, W, W_n, C and ΔU of a step (module docs).
pub fn step_energy(f: &StepFields) -> StepEnergy {
    let integral = |a: &[f64], b: &[f64]| -> f64 { f.weights.iter().zip(a).zip(b).map(|((w, a), b)| w * a * b).sum() };
    let resultant = |t: &[f64]| -> f64 { f.weights.iter().zip(t).map(|(w, t)| w * t).sum() };
    let tangential = 0.5 * (integral(f.shear, f.displacement) - integral(f.previous_shear, f.previous_displacement));
    let normal = 0.5 * (integral(f.pressure, f.compression) - integral(f.previous_pressure, f.previous_compression));
    StepEnergy {
        dissipation: -integral(f.shear, f.slip),
        work: -(resultant(f.shear) * f.shift + integral(f.shear, f.rigid_slip)),
        normal_work: resultant(f.pressure) * f.approach_change - integral(f.pressure, f.profile_change),
        closing: integral(f.pressure, f.previous_gap_upstream),
        stored_change: normal + tangential,
        tangential_stored_change: tangential,
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
        let (p, h) = ([1.0, 2.0, 1.0], [0.05, 0.1, 0.05]);
        let e = step_energy(&StepFields {
            weights: &weights,
            shear: &shear,
            slip: &[0.3; 3],
            displacement: &w,
            previous_shear: &shear,
            previous_displacement: &w,
            pressure: &p,
            compression: &h,
            previous_pressure: &p,
            previous_compression: &h,
            previous_gap_upstream: &[0.0; 3],
            profile_change: &[0.0; 3],
            approach_change: 0.0,
            rigid_slip: &[0.0; 3],
            shift: 0.3,
        });
        assert!((e.work - 0.9).abs() < 1e-15 && (e.dissipation - 0.9).abs() < 1e-15);
        assert_eq!((e.stored_change, e.normal_work, e.closing), (0.0, 0.0, 0.0));
        assert!(e.imbalance().abs() < 1e-15);
    }

    /// The identity of the module docs on a shift (Δ = 0) of a coupled pair with a symmetric,
    /// positive flexibility (W_p = H_qᵀ in the grid's weighted inner product, as Betti's
    /// theorem makes it for dissimilar half-planes): with the slip and the gap formed as the
    /// solver forms them and g = 0 wherever p > 0, W + W_n − ΔU − D − C equals
    /// ½⟨x₁ − x₀, F(x₁ − x₀)⟩ to round-off, and the tangential terms alone miss the coupling's
    /// work.
    #[test]
    fn a_coupled_step_balances_to_its_implicit_dissipation() {
        let m = 4;
        let weights = [0.3, 0.7, 0.7, 0.3];
        // S symmetric positive (2m × 2m); F = diag(weights)⁻¹ S, so that Σ w_i x_i (F y)_i is
        // symmetric in x and y.
        let s = |i: usize, j: usize| -> f64 {
            let r = |k: usize| ((k * 7 + 3) % 11) as f64 / 11.0 - 0.4;
            let diagonal = if i == j { 3.0 } else { 0.0 };
            diagonal + 0.5 * (r(i) * r(j) + r(i + j) * 0.3)
        };
        let wt = |i: usize| weights[i % m];
        let apply = |x: &[f64]| -> Vec<f64> {
            (0..2 * m)
                .map(|i| (0..2 * m).map(|j| s(i, j) * x[j]).sum::<f64>() / wt(i))
                .collect()
        };
        let x0 = [0.0, 0.8, 0.9, 0.0, 0.0, -0.1, 0.2, 0.0];
        let x1 = [0.0, 1.1, 0.7, 0.2, 0.05, -0.2, 0.25, 0.1];
        let (d0, d1) = (apply(&x0), apply(&x1));
        let (p0, q0, h0_, w0) = (&x0[..m], &x0[m..], &d0[..m], &d0[m..]);
        let (p1, q1, h1, w1) = (&x1[..m], &x1[m..], &d1[..m], &d1[m..]);
        let (delta0, delta1, c) = (0.01, 0.03, 0.02);
        // The profile closes the gap under p1 > 0 and leaves it open elsewhere.
        let profile: Vec<f64> = (0..m).map(|i| if p1[i] > 0.0 { delta1 - h1[i] } else { 1.0 }).collect();
        let previous_gap: Vec<f64> = (0..m).map(|i| profile[i] - delta0 + h0_[i]).collect();
        let slip: Vec<f64> = (0..m).map(|i| c + w1[i] - w0[i]).collect();
        let e = step_energy(&StepFields {
            weights: &weights,
            shear: q1,
            slip: &slip,
            displacement: w1,
            previous_shear: q0,
            previous_displacement: w0,
            pressure: p1,
            compression: h1,
            previous_pressure: p0,
            previous_compression: h0_,
            previous_gap_upstream: &previous_gap,
            profile_change: &[0.0; 4],
            approach_change: delta1 - delta0,
            rigid_slip: &[0.0; 4],
            shift: c,
        });
        let change: Vec<f64> = x1.iter().zip(&x0).map(|(a, b)| a - b).collect();
        let f_change = apply(&change);
        let implicit: f64 = 0.5 * (0..2 * m).map(|i| wt(i) * change[i] * f_change[i]).sum::<f64>();
        assert!(implicit > 0.0);
        assert!(
            (e.imbalance() - implicit).abs() < 1e-13,
            "{} against {implicit}",
            e.imbalance()
        );
        assert!((e.tangential_imbalance() - implicit).abs() > 1e-3, "{e:?}");
    }
}
