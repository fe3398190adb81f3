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
//! per cent of it near stick/slip transitions and by much less elsewhere (docs/hbem.md). When
//! nothing slips (s = 0 at every contact node) there is no scale and no node is flagged.

use super::solution::ContactSolution;
use super::zones::NodeState;
use serde::Serialize;

/// Default threshold as a fraction of max |s| over the nodes in contact: 5 %.
pub const DEFAULT_THRESHOLD_FRACTION: f64 = 0.05;

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
    /// Threshold on |s_h| [-] = `threshold_fraction` · `slip_scale`; null when nothing slips.
    pub threshold: Option<f64>,
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
/// threshold `fraction` · max |s|. None when the solution has no HBEM slip (a body model
/// without a strain operator) or μ = 0 (frictionless: the law constrains nothing).
pub fn check_friction_law(solution: &ContactSolution, friction: f64, fraction: f64) -> Option<FrictionCheck> {
    let hbem = solution.slip_strain.as_ref()?;
    if friction <= 0.0 {
        return None;
    }
    let in_contact = |i: &usize| solution.state[*i] != NodeState::Open && hbem[*i].is_finite();
    let nodes: Vec<usize> = (0..solution.x.len()).filter(in_contact).collect();
    let slip_scale = nodes.iter().map(|&i| solution.slip[i].abs()).fold(0.0, f64::max);
    let threshold = (slip_scale > 0.0).then_some(fraction * slip_scale);
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
        Some(format!(
            "{} contact node(s) where the HBEM slip contradicts the friction law ({} sticking \
             with |s_hbem| > {limit:.3e} = {:.0} % of max |slip|, {} slipping along the shear); \
             see hbem_check in summary.json",
            self.violations.len(),
            count(ViolationKind::StickNodeSlips),
            100.0 * self.threshold_fraction,
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

    #[test]
    fn a_consistent_solution_has_no_violations() {
        let c = check_friction_law(&solution(), 0.1, DEFAULT_THRESHOLD_FRACTION).unwrap();
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
        let c = check_friction_law(&sol, 0.1, DEFAULT_THRESHOLD_FRACTION).unwrap();
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
        let c = check_friction_law(&sol, 0.1, 0.01).unwrap();
        assert_eq!(c.violations.len(), 4, "{:?}", c.violations);
    }

    #[test]
    fn nothing_to_check_without_hbem_slip_friction_or_slip() {
        let mut sol = solution();
        assert!(check_friction_law(&sol, 0.0, 0.05).is_none());
        sol.slip = vec![0.0; 9];
        let c = check_friction_law(&sol, 0.1, 0.05).unwrap();
        assert!(c.threshold.is_none() && c.violations.is_empty());
        sol.slip_strain = None;
        assert!(check_friction_law(&sol, 0.1, 0.05).is_none());
    }
}
