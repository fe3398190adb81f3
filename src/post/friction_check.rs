//! The friction-law check of the boundary-integral (HBEM) slip: where does the slip recomputed
//! from the boundary-integral derivative of the displacements contradict the solved state?
//!
//! The solver enforces Coulomb's law (docs/theory.md) on the finite-difference slip s:
//! stick nodes have s = 0 and |q| ≤ μp, slip nodes q = −μp·sgn(s). The HBEM slip s_h
//! ([`super::solution::ContactSolution::slip_strain`]) differentiates the same displacements without
//! the difference operator (González & Abascal §5.2, "Hyp. Deriv."), so it reveals what the
//! difference operator hid. A contact node contradicts the friction law when
//!
//! * it sticks but |s_h| > threshold (the surfaces do slide there), or
//! * it slips but s_h has the sign of q, with |s_h| > threshold (the friction would push the
//!   slip along instead of opposing it).
//!
//! **Threshold.** A fraction ([`DEFAULT_THRESHOLD_FRACTION`] by default) of the largest |s|
//! (finite-difference slip) over the nodes in contact, the natural size of the slip of the
//! solution: the HBEM and difference slips of a converged, well-resolved case differ by a few
//! per cent of it near stick/slip transitions and by much less elsewhere (docs/hbem.md).
//!
//! **Floor.** The threshold is never below [`SLIP_FLOOR_FRACTION`] = 1 % of the creepage scale
//! μa/R* (a the Hertz half-width, 1/R* = 1/R_A + 1/R_B). The slip of rolling contact is measured
//! by that scale: Carter's creepage ξ = (μa/R*)(1 − √(1 − Q/μP)) reaches μa/R* at full sliding,
//! and the shipped cases have max |s| between 0.35 and 3.5 μa/R* (a tyre layer 240), so their
//! 5 % threshold is at least 1.75 % of μa/R* and the floor leaves their checks as they were.
//! Where little or nothing slips, 5 % of max |s| falls to the HBEM derivative's own
//! discretization error, or to round-off in full stick, and every stick node would be flagged:
//! `fig14_true_geometry` at Q = 0 and μ = 5 (full stick, Bufler's dissimilar solution) has
//! max |s| = 1.2e-18 (round-off) against |s_hbem| up to 7.2e-5 = 0.14 % of μa/R* at its stick
//! nodes (at the contact edges; 1e-8 inside). A slip below 1 % of μa/R* moves the creepage by
//! less than that fraction of its full-sliding value, too little for the friction law to be
//! judged by the HBEM slip. With the floor, a solution where nothing slips is checked too:
//! a stick node whose HBEM slip exceeds the floor is flagged.

use super::solution::ContactSolution;
use super::zones::NodeState;
use serde::Serialize;

/// Default threshold as a fraction of max |s| over the nodes in contact: 5 %.
pub const DEFAULT_THRESHOLD_FRACTION: f64 = 0.05;

/// Floor of the threshold as a fraction of the creepage scale μa/R* (module docs): 1 %.
pub const SLIP_FLOOR_FRACTION: f64 = 0.01;

/// How a node contradicts the friction law.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum ViolationKind {
    /// A stick node whose HBEM slip exceeds the threshold.
    StickNodeSlips,
    /// A slip node whose HBEM slip has the sign of the shear (Coulomb wants the opposite).
    SlipAlongShear,
}

/// One contact node where the HBEM slip contradicts the solved state.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct FrictionViolation {
    /// Node x [length].
    pub x: f64,
    /// Solved state of the node.
    pub state: NodeState,
    /// What is contradicted.
    pub kind: ViolationKind,
    /// Finite-difference slip s [-].
    pub slip: f64,
    /// HBEM slip s_h [-].
    pub slip_hbem: f64,
    /// q/(μp), signed: ±1 at a slip node, inside (−1, 1) at a stick node [-].
    pub shear_ratio: f64,
}

/// The check's result (summary.json `hbem_check`).
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct FrictionCheck {
    /// Threshold on |s_h| [-] = max(`threshold_fraction` · `slip_scale`, `threshold_floor`);
    /// null when both are 0 (nothing slips and no creepage scale).
    pub threshold: Option<f64>,
    /// Floor of the threshold [-]: [`SLIP_FLOOR_FRACTION`] · μa/R* (module docs).
    pub threshold_floor: f64,
    /// The fraction of `slip_scale` used [-].
    pub threshold_fraction: f64,
    /// Scale of the threshold: max |s| (finite-difference slip) over the nodes in contact [-].
    pub slip_scale: f64,
    /// max |s_h − s| over the slip nodes [-] (null without slip nodes).
    pub max_difference_slip_nodes: Option<f64>,
    /// max |s_h| over the stick nodes, where s = 0 [-] (null without stick nodes).
    pub max_hbem_slip_stick_nodes: Option<f64>,
    /// The contradicting nodes, in increasing x.
    pub violations: Vec<FrictionViolation>,
}

/// Checks the HBEM slip of `solution` against its solved states (module docs) with the
/// threshold max(`fraction` · max |s|, [`SLIP_FLOOR_FRACTION`] · μ · `a_over_r`), `a_over_r`
/// being the Hertz half-width over the effective radius, a/|R*| [-] (no floor when it is not a
/// positive finite number). None when the solution has no HBEM slip (a body model without a
/// strain operator) or μ = 0 (frictionless: the law constrains nothing).
pub fn check_friction_law(
    solution: &ContactSolution,
    friction: f64,
    fraction: f64,
    a_over_r: f64,
) -> Option<FrictionCheck> {
    let hbem = solution.slip_strain.as_ref()?;
    if friction <= 0.0 {
        return None;
    }
    let in_contact = |i: &usize| solution.state[*i] != NodeState::Open && hbem[*i].is_finite();
    let nodes: Vec<usize> = (0..solution.x.len()).filter(in_contact).collect();
    let slip_scale = nodes.iter().map(|&i| solution.slip[i].abs()).fold(0.0, f64::max);
    let floor = if a_over_r.is_finite() && a_over_r > 0.0 {
        SLIP_FLOOR_FRACTION * friction * a_over_r
    } else {
        0.0
    };
    let limit = (fraction * slip_scale).max(floor);
    let threshold = (limit > 0.0).then_some(limit);
    let max_over = |state: NodeState, value: &dyn Fn(usize) -> f64| {
        nodes
            .iter()
            .filter(|&&i| solution.state[i] == state)
            .map(|&i| value(i))
            .reduce(f64::max)
    };
    let violations = match threshold {
        Some(limit) => nodes
            .iter()
            .filter_map(|&i| {
                let (s, sh, q) = (solution.slip[i], hbem[i], solution.shear[i]);
                let kind = match solution.state[i] {
                    NodeState::Stick if sh.abs() > limit => ViolationKind::StickNodeSlips,
                    // Coulomb: q = −μp·sgn(s); sh·q > 0 is slip along the shear.
                    NodeState::Slip if sh.abs() > limit && sh * q > 0.0 => ViolationKind::SlipAlongShear,
                    _ => return None,
                };
                Some(FrictionViolation {
                    x: solution.x[i],
                    state: solution.state[i],
                    kind,
                    slip: s,
                    slip_hbem: sh,
                    shear_ratio: q / (friction * solution.pressure[i]),
                })
            })
            .collect(),
        None => Vec::new(),
    };
    Some(FrictionCheck {
        threshold,
        threshold_floor: floor,
        threshold_fraction: fraction,
        slip_scale,
        max_difference_slip_nodes: max_over(NodeState::Slip, &|i| (hbem[i] - solution.slip[i]).abs()),
        max_hbem_slip_stick_nodes: max_over(NodeState::Stick, &|i| hbem[i].abs()),
        violations,
    })
}

impl FrictionCheck {
    /// One line for the run summary, when there are violations.
    pub fn summary_line(&self) -> Option<String> {
        let limit = self.threshold?;
        if self.violations.is_empty() {
            return None;
        }
        let count = |k: ViolationKind| self.violations.iter().filter(|v| v.kind == k).count();
        let what = if limit > self.threshold_fraction * self.slip_scale {
            format!("the floor {:.0} % of mu a/R*", 100.0 * SLIP_FLOOR_FRACTION)
        } else {
            format!("{:.0} % of max |slip|", 100.0 * self.threshold_fraction)
        };
        Some(format!(
            "{} contact node(s) where the HBEM slip contradicts the friction law ({} sticking \
             with |s_hbem| > {limit:.3e} = {what}, {} slipping along the shear); see hbem_check \
             in summary.json",
            self.violations.len(),
            count(ViolationKind::StickNodeSlips),
            count(ViolationKind::SlipAlongShear),
        ))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A Carter-like solution: slip zone on the left (s < 0, q = +μp), stick zone on the right
    /// (s = 0), open ends, with an HBEM slip close to s.
    fn solution() -> ContactSolution {
        let x: Vec<f64> = (0..9).map(|i| -1.2 + 0.3 * i as f64).collect();
        let state = [
            NodeState::Open,
            NodeState::Slip,
            NodeState::Slip,
            NodeState::Slip,
            NodeState::Stick,
            NodeState::Stick,
            NodeState::Stick,
            NodeState::Stick,
            NodeState::Open,
        ];
        let pressure: Vec<f64> = x.iter().map(|x| (1.0 - x * x).max(0.0).sqrt()).collect();
        let shear: Vec<f64> = pressure
            .iter()
            .enumerate()
            .map(|(i, p)| if i < 4 { 0.1 * p } else { 0.05 * p })
            .collect();
        let slip = vec![-3e-3, -2e-3, -1.5e-3, -1e-3, 0.0, 0.0, 0.0, 0.0, 0.0];
        // HBEM: within 2 % of max |s| = 2e-3 of s at every contact node.
        let hbem = vec![-2.9e-3, -2.02e-3, -1.49e-3, -1.03e-3, 3e-5, -1e-5, 0.0, 2e-5, 1.0];
        ContactSolution {
            x,
            normal_force: 1.0,
            tangential_force: 0.1,
            forces: crate::contact::ContactForces {
                global_x: 0.1,
                global_y: 1.0,
                normal: 1.0,
                tangential: 0.1,
            },
            overlap: 0.0,
            creep: -1e-3,
            zones: Vec::new(),
            gap: vec![0.0; 9],
            pressure,
            shear,
            slip,
            slip_strain: Some(hbem),
            state: state.to_vec(),
        }
    }

    /// a/R* of the synthetic solution: μa/R* = 1e-3, half of its max |s|, so the floor
    /// (1e-5) is below its 5 % threshold (1e-4).
    const A_OVER_R: f64 = 0.01;

    #[test]
    fn a_consistent_solution_has_no_violations() {
        let c = check_friction_law(&solution(), 0.1, DEFAULT_THRESHOLD_FRACTION, A_OVER_R).unwrap();
        // The scale ignores open nodes (|s| = 3e-3 there).
        assert_eq!(c.slip_scale, 2e-3);
        assert_eq!(c.threshold, Some(1e-4));
        assert!(c.violations.is_empty(), "{:?}", c.violations);
        assert!((c.max_difference_slip_nodes.unwrap() - 3e-5).abs() < 1e-12);
        assert!((c.max_hbem_slip_stick_nodes.unwrap() - 3e-5).abs() < 1e-12);
        assert!(c.summary_line().is_none());
    }

    #[test]
    fn planted_inconsistencies_are_reported() {
        let mut sol = solution();
        let hbem = sol.slip_strain.as_mut().unwrap();
        hbem[5] = 5e-4; // a stick node slipping at 25 % of max |s|
        hbem[2] = 4e-4; // a slip node (q > 0) slipping in +x: along the shear
        hbem[3] = 5e-5; // wrong sign too, but below the threshold: noise, not reported
        let c = check_friction_law(&sol, 0.1, DEFAULT_THRESHOLD_FRACTION, A_OVER_R).unwrap();
        assert_eq!(c.violations.len(), 2, "{:?}", c.violations);
        let (v0, v1) = (&c.violations[0], &c.violations[1]);
        assert_eq!((v0.kind, v0.state), (ViolationKind::SlipAlongShear, NodeState::Slip));
        assert_eq!((v1.kind, v1.state), (ViolationKind::StickNodeSlips, NodeState::Stick));
        assert!((v0.x - sol.x[2]).abs() < 1e-15 && (v1.x - sol.x[5]).abs() < 1e-15);
        assert!((v0.shear_ratio - 1.0).abs() < 1e-12 && (v1.shear_ratio - 0.5).abs() < 1e-12);
        assert_eq!(v1.slip_hbem, 5e-4);
        let line = c.summary_line().unwrap();
        assert!(
            line.starts_with("2 contact node(s)") && line.contains("1 sticking"),
            "{line}"
        );
        // A tighter threshold (1 %) also catches the small ones.
        let c = check_friction_law(&sol, 0.1, 0.01, A_OVER_R).unwrap();
        assert_eq!(c.violations.len(), 4, "{:?}", c.violations);
    }

    /// Full stick: the difference slip is round-off and the HBEM slip at stick nodes is its
    /// discretization error (as on `fig14_true_geometry` at Q = 0, μ = 5: up to 0.14 % of
    /// μa/R*). Without the floor the threshold was 5 % of the round-off, 5e-22 here, and every
    /// stick node was flagged; with it none is, while a stick node that does slip (5 % of μa/R*)
    /// still is, and the summary line names the floor.
    #[test]
    fn full_stick_noise_is_below_the_floor_and_a_slipping_stick_node_is_not() {
        let mut sol = solution();
        let creep_scale = 0.1 * A_OVER_R;
        for (i, state) in sol.state.iter_mut().enumerate() {
            if *state == NodeState::Slip {
                *state = NodeState::Stick;
            }
            sol.slip[i] = if *state == NodeState::Open {
                0.0
            } else {
                1e-20 * (i as f64 - 4.0)
            };
        }
        let hbem = sol.slip_strain.as_mut().unwrap();
        for (i, h) in hbem.iter_mut().enumerate().take(8).skip(1) {
            *h = 1.4e-3 * creep_scale * if i % 2 == 0 { 1.0 } else { -1.0 };
        }
        let c = check_friction_law(&sol, 0.1, DEFAULT_THRESHOLD_FRACTION, A_OVER_R).unwrap();
        assert!(c.slip_scale < 1e-19);
        assert_eq!(c.threshold_floor, SLIP_FLOOR_FRACTION * creep_scale);
        assert_eq!(c.threshold, Some(c.threshold_floor));
        assert!(c.violations.is_empty(), "{:?}", c.violations);
        sol.slip_strain.as_mut().unwrap()[3] = 0.05 * creep_scale;
        let c = check_friction_law(&sol, 0.1, DEFAULT_THRESHOLD_FRACTION, A_OVER_R).unwrap();
        assert_eq!(c.violations.len(), 1, "{:?}", c.violations);
        assert_eq!(c.violations[0].kind, ViolationKind::StickNodeSlips);
        let line = c.summary_line().unwrap();
        assert!(line.contains("the floor 1 % of mu a/R*"), "{line}");
    }

    #[test]
    fn nothing_to_check_without_hbem_slip_friction_or_any_scale() {
        let mut sol = solution();
        assert!(check_friction_law(&sol, 0.0, 0.05, A_OVER_R).is_none());
        sol.slip = vec![0.0; 9];
        // No slip and no creepage scale (a/R* not positive or not finite): no threshold.
        for a_over_r in [0.0, f64::NAN, f64::INFINITY] {
            let c = check_friction_law(&sol, 0.1, 0.05, a_over_r).unwrap();
            assert!(c.threshold.is_none() && c.violations.is_empty());
        }
        // No slip but a creepage scale: the floor is the threshold.
        let c = check_friction_law(&sol, 0.1, 0.05, A_OVER_R).unwrap();
        assert_eq!(c.threshold, Some(SLIP_FLOOR_FRACTION * 0.1 * A_OVER_R));
        sol.slip_strain = None;
        assert!(check_friction_law(&sol, 0.1, 0.05, A_OVER_R).is_none());
    }
}
