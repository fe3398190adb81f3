//! Stick and slip zones: the node states, the runs of equal state along the grid, and the
//! names of their patterns (slip direction, slip regime of González & Abascal §5.2).

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
    // A node stands for the half-spacings on either side of it (the end nodes' outer half the
    // same as their inner one), so zones meet half-way between unequally spaced nodes too.
    let half_left = |i: usize| match i {
        0 if m > 1 => 0.5 * (x[1] - x[0]),
        0 => 0.0,
        _ => 0.5 * (x[i] - x[i - 1]),
    };
    let half_right = |i: usize| {
        if i + 1 < m {
            0.5 * (x[i + 1] - x[i])
        } else {
            half_left(i)
        }
    };
    for i in 0..m {
        let key = (state[i], dir(i));
        match out.last_mut() {
            Some(z) if (z.state, z.direction) == key => {
                z.x1 = x[i] + half_right(i);
                z.nodes += 1;
            }
            _ => out.push(Zone {
                state: state[i],
                x0: x[i] - half_left(i),
                x1: x[i] + half_right(i),
                direction: key.1,
                nodes: 1,
            }),
        }
    }
    out
}
