//! The converged solution in user-facing terms: forces, contact extent, stick/slip zones.

use super::residual::State;
use super::ContactProblem;
use serde::{Serialize, Serializer};

/// State of a contact node (DESIGN §5 `state` column).
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

/// Slip regime of the classification in paper §5.2 (and reference sheet §4.2), from the slip
/// zones ordered from the leading edge. Written as its number 0–4 in summary.json.
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

/// Converged solution at the contact nodes, user-facing signs (DESIGN §2).
#[derive(Debug, Clone, Serialize)]
pub struct ContactSolution {
    /// Node x [length].
    pub x: Vec<f64>,
    /// Pressure p ≥ 0 [stress].
    pub pressure: Vec<f64>,
    /// Shear q on A in +x [stress].
    pub shear: Vec<f64>,
    /// Gap g ≥ 0 [length].
    pub gap: Vec<f64>,
    /// Slip of A relative to B divided by |V| [-], finite-difference operator.
    pub slip: Vec<f64>,
    /// Slip from the boundary-integral derivative of the displacements [-], if available.
    pub slip_strain: Option<Vec<f64>>,
    /// Node states.
    pub state: Vec<NodeState>,
    /// Normal force P = ∫p dx [force/length].
    pub normal_force: f64,
    /// Tangential force Q = ∫q dx [force/length].
    pub tangential_force: f64,
    /// Overlap δ0 [length].
    pub overlap: f64,
    /// Creepage ξ [-].
    pub creep: f64,
    /// Zones in increasing x.
    pub zones: Vec<Zone>,
}

impl ContactSolution {
    /// Builds the user-facing solution from the solver state.
    pub fn from_state(pb: &ContactProblem, z: &State) -> Self {
        let m = pb.n_nodes();
        // Recompute g and s from the tractions so outputs are exactly consistent with them.
        let gap = pb.gap(&z.pressure, &z.shear, z.overlap);
        let slip = pb.slip(&z.pressure, &z.shear, z.creep);
        let pressure: Vec<f64> = z.pressure.iter().map(|p| p.max(0.0)).collect();
        let pmax = pressure.iter().fold(0.0_f64, |a, &b| a.max(b));
        let state: Vec<NodeState> = (0..m)
            .map(|i| {
                let p = pressure[i];
                if p <= 1e-12 * pmax {
                    NodeState::Open
                } else if z.shear[i].abs() >= pb.friction * p * (1.0 - 1e-9) && pb.friction > 0.0 {
                    NodeState::Slip
                } else {
                    NodeState::Stick
                }
            })
            .collect();
        let zones = zones(&pb.grid.nodes, &state, &slip);
        let mut solution = Self {
            x: pb.grid.nodes.clone(),
            normal_force: pb.grid.integrate(&pressure),
            tangential_force: pb.grid.integrate(&z.shear),
            slip_strain: pb.slip_from_strain(&z.pressure, &z.shear, z.creep),
            pressure,
            shear: z.shear.clone(),
            gap: gap.into_iter().map(|g| g.max(0.0)).collect(),
            slip,
            state,
            overlap: z.overlap,
            creep: z.creep,
            zones,
        };
        solution.snap_zones_to_contact_edges();
        solution
    }

    /// Moves the zone boundaries at the two contact edges onto the extrapolated edges of
    /// [`Self::contact_extent`], so zones and contact extent agree.
    fn snap_zones_to_contact_edges(&mut self) {
        let Some([x0, x1]) = self.contact_extent() else { return };
        let n = self.zones.len();
        if let Some(k) = self.zones.iter().position(|z| z.state != NodeState::Open) {
            self.zones[k].x0 = x0;
            if k > 0 {
                self.zones[k - 1].x1 = x0;
            }
        }
        if let Some(k) = self.zones.iter().rposition(|z| z.state != NodeState::Open) {
            self.zones[k].x1 = x1;
            if k + 1 < n {
                self.zones[k + 1].x0 = x1;
            }
        }
    }

    /// Contact extent [x_min, x_max], or None if nothing is in contact.
    ///
    /// Near a smooth contact edge p ≈ C·√(distance), so p² is linear in x: each end is where the
    /// line through p² at the two outermost loaded nodes reaches zero, kept between the
    /// outermost loaded node and the first open node (sub-node resolution instead of ±h/2).
    pub fn contact_extent(&self) -> Option<[f64; 2]> {
        let loaded: Vec<usize> = (0..self.x.len())
            .filter(|&i| self.state[i] != NodeState::Open)
            .collect();
        let (&first, &last) = (loaded.first()?, loaded.last()?);
        let h = if self.x.len() > 1 { self.x[1] - self.x[0] } else { 0.0 };
        let edge = |i: usize, j: usize, outward: f64| -> f64 {
            // Extrapolate p² from node j (inner) through node i (outermost) to zero.
            let (pi, pj) = (self.pressure[i].powi(2), self.pressure[j].powi(2));
            let slope = (pi - pj) / (self.x[i] - self.x[j]);
            let t = if slope * outward < 0.0 {
                -pi / slope
            } else {
                0.5 * h * outward
            };
            self.x[i] + t.clamp(-h, h).abs().min(h) * outward
        };
        let x0 = if last > first && self.state[first + 1] != NodeState::Open {
            edge(first, first + 1, -1.0)
        } else {
            self.x[first] - 0.5 * h
        };
        let x1 = if last > first && self.state[last - 1] != NodeState::Open {
            edge(last, last - 1, 1.0)
        } else {
            self.x[last] + 0.5 * h
        };
        Some([x0, x1])
    }

    /// Zones of the given state as [x0, x1] pairs.
    pub fn zones_of(&self, state: NodeState) -> Vec<[f64; 2]> {
        self.zones
            .iter()
            .filter(|z| z.state == state)
            .map(|z| [z.x0, z.x1])
            .collect()
    }

    /// Slip-zone directions in increasing x.
    pub fn slip_directions(&self) -> Vec<SlipDirection> {
        self.zones
            .iter()
            .filter(|z| z.state == NodeState::Slip)
            .filter_map(|z| z.direction)
            .collect()
    }
}

/// Splits the nodes into runs of equal state (and, for slip, equal slip sign).
fn zones(x: &[f64], state: &[NodeState], slip: &[f64]) -> Vec<Zone> {
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
