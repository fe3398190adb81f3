//! What the zones and the shear of a solution say: the slip regime of the slip zones'
//! pattern (González & Abascal §5.2) and the ripple of the shear inside the zones.

use super::solution::ContactSolution;
use super::zones::{NodeState, SlipDirection, SlipRegime};

/// The [`SlipRegime`] of a solution whose leading edge lies on the side `leading_edge_sign` of
/// the contact (+1: at +x). Zones of fewer than `min_nodes` nodes are ignored.
pub fn slip_regime(solution: &ContactSolution, leading_edge_sign: f64, min_nodes: usize) -> SlipRegime {
    let mut dirs: Vec<SlipDirection> = solution
        .zones
        .iter()
        .filter(|z| z.state == NodeState::Slip && z.nodes >= min_nodes)
        .filter_map(|z| z.direction)
        .collect();
    if leading_edge_sign > 0.0 {
        dirs.reverse();
    }
    match dirs.as_slice() {
        [_] => SlipRegime::OneZone,
        [a, b] if a == b => SlipRegime::TwoZonesSameDirection,
        [_, _] => SlipRegime::TwoZonesOpposite,
        [a, b, c] if a == c && a != b => SlipRegime::ThreeZones,
        _ => SlipRegime::Unclassified,
    }
}

/// Ripple of the shear [stress]: node-to-node zig-zag, measured as the largest
/// min(|Δ²q_i|, |Δ²q_{i+1}|) over neighbouring second differences of opposite sign whose
/// stencils lie inside one zone. A smooth traction changes the sign of Δ²q only at inflection
/// points, where Δ²q is small (about h³ times the third derivative), and square-root kinks at
/// zone or contact edges keep one sign; an odd–even oscillation of amplitude A (the ripples Man
/// & Aliabadi reported with continuous elements) gives about 4A.
pub fn traction_ripple(solution: &ContactSolution) -> f64 {
    let m = solution.x.len();
    let q = &solution.shear;
    let key = |i: usize| {
        (
            solution.state[i],
            solution.slip[i] >= 0.0 || solution.state[i] != NodeState::Slip,
        )
    };
    let inside = |i: usize| solution.state[i] != NodeState::Open && key(i - 1) == key(i) && key(i + 1) == key(i);
    let d2 = |i: usize| q[i - 1] - 2.0 * q[i] + q[i + 1];
    (1..m.saturating_sub(2))
        .filter(|&i| inside(i) && inside(i + 1) && key(i) == key(i + 1) && d2(i) * d2(i + 1) < 0.0)
        .map(|i| d2(i).abs().min(d2(i + 1).abs()))
        .fold(0.0, f64::max)
}
