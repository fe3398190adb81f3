//! Stick and slip zones of a solution, the slip regime of their pattern (González & Abascal
//! §5.2) and the ripple of the shear inside them.

use super::solution::ContactSolution;
use serde::{Serialize, Serializer};

/// State of a contact node (the `state` column of contact.csv).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum NodeState {
    /// p = 0: the surfaces are apart (or just touching).
    Open,
    /// In contact, no slip, |q| < μp.
    Stick,
    /// In contact and slipping, |q| = μp.
    Slip,
}

impl NodeState {
    /// Lower-case name used in CSV files.
    pub fn name(self) -> &'static str {
        match self {
            NodeState::Open => "open",
            NodeState::Stick => "stick",
            NodeState::Slip => "slip",
        }
    }
}

/// Direction of the slip in a slip zone: the sign of the slip s, the velocity of A's surface
/// relative to B's divided by |V|. Written as +1 / −1 in summary.json.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum SlipDirection {
    /// s ≥ 0: A's surface slips in +x relative to B's.
    PlusX,
    /// s < 0: A's surface slips in −x relative to B's.
    MinusX,
}

impl SlipDirection {
    /// The direction of a slip s [-] (s = 0 counts as +x).
    pub fn of(slip: f64) -> Self {
        if slip >= 0.0 {
            SlipDirection::PlusX
        } else {
            SlipDirection::MinusX
        }
    }

    /// +1 or −1.
    pub fn sign(self) -> i8 {
        match self {
            SlipDirection::PlusX => 1,
            SlipDirection::MinusX => -1,
        }
    }
}

impl Serialize for SlipDirection {
    fn serialize<S: Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        s.serialize_i8(self.sign())
    }
}

/// Writes a zone's direction as +1 / −1, and 0 for a zone that does not slip.
fn serialize_zone_direction<S: Serializer>(direction: &Option<SlipDirection>, s: S) -> Result<S::Ok, S::Error> {
    s.serialize_i8(direction.map_or(0, SlipDirection::sign))
}

/// Slip regime of the classification of González & Abascal §5.2, from the slip zones ordered
/// from the leading edge. Written as its number 0–4 in summary.json.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum SlipRegime {
    /// 0: full stick, or any pattern not below (e.g. four slip zones).
    Unclassified,
    /// 1: one slip zone.
    OneZone,
    /// 2: two zones slipping in the same direction.
    TwoZonesSameDirection,
    /// 3: two zones slipping in opposite directions.
    TwoZonesOpposite,
    /// 4: three zones, the outer two alike and the middle one opposite.
    ThreeZones,
}

impl SlipRegime {
    /// The number of the paper's classification, 1–4, or 0 for [`SlipRegime::Unclassified`].
    pub fn number(self) -> u8 {
        match self {
            SlipRegime::Unclassified => 0,
            SlipRegime::OneZone => 1,
            SlipRegime::TwoZonesSameDirection => 2,
            SlipRegime::TwoZonesOpposite => 3,
            SlipRegime::ThreeZones => 4,
        }
    }
}

impl std::fmt::Display for SlipRegime {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(f, "{}", self.number())
    }
}

impl Serialize for SlipRegime {
    fn serialize<S: Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        s.serialize_u8(self.number())
    }
}

/// A run of neighbouring nodes in the same state.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct Zone {
    /// Node state in the zone.
    pub state: NodeState,
    /// Start x [length] (midway to the previous node of another state).
    pub x0: f64,
    /// End x [length].
    pub x1: f64,
    /// Direction of the slip in a slip zone, None otherwise (written +1 / −1 / 0).
    #[serde(serialize_with = "serialize_zone_direction")]
    pub direction: Option<SlipDirection>,
    /// Number of nodes in the zone.
    pub nodes: usize,
}

/// Splits the nodes into runs of equal state (and, for slip, equal slip sign).
pub fn zones(x: &[f64], state: &[NodeState], slip: &[f64]) -> Vec<Zone> {
    let m = x.len();
    let dir = |i: usize| (state[i] == NodeState::Slip).then(|| SlipDirection::of(slip[i]));
    let mut out: Vec<Zone> = Vec::new();
    let half = if m > 1 { 0.5 * (x[1] - x[0]) } else { 0.0 };
    for i in 0..m {
        let key = (state[i], dir(i));
        match out.last_mut() {
            Some(z) if (z.state, z.direction) == key => {
                z.x1 = x[i] + half;
                z.nodes += 1;
            }
            _ => out.push(Zone {
                state: state[i],
                x0: x[i] - half,
                x1: x[i] + half,
                direction: key.1,
                nodes: 1,
            }),
        }
    }
    out
}

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
