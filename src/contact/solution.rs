//! The converged solution in user-facing terms: forces, contact extent, stick/slip zones.

use super::newton::State;
use super::ContactProblem;
use serde::Serialize;

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

/// A run of neighbouring nodes in the same state.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct Zone {
    /// Node state in the zone.
    pub state: NodeState,
    /// Start x [length] (midway to the previous node of another state).
    pub x0: f64,
    /// End x [length].
    pub x1: f64,
    /// Sign of the slip in a slip zone (+1/−1), 0 otherwise.
    pub direction: i8,
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
        Self {
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
        }
    }

    /// Contact extent [x_min, x_max] (midway between the outermost loaded node and the next
    /// open one), or None if nothing is in contact.
    pub fn contact_extent(&self) -> Option<[f64; 2]> {
        let first = self.zones.iter().find(|z| z.state != NodeState::Open)?;
        let last = self.zones.iter().rev().find(|z| z.state != NodeState::Open)?;
        Some([first.x0, last.x1])
    }

    /// Zones of the given state as [x0, x1] pairs.
    pub fn zones_of(&self, state: NodeState) -> Vec<[f64; 2]> {
        self.zones
            .iter()
            .filter(|z| z.state == state)
            .map(|z| [z.x0, z.x1])
            .collect()
    }

    /// Slip-zone directions (+1/−1) in increasing x.
    pub fn slip_directions(&self) -> Vec<i8> {
        self.zones
            .iter()
            .filter(|z| z.state == NodeState::Slip)
            .map(|z| z.direction)
            .collect()
    }
}

/// Splits the nodes into runs of equal state (and, for slip, equal slip sign).
fn zones(x: &[f64], state: &[NodeState], slip: &[f64]) -> Vec<Zone> {
    let m = x.len();
    let dir = |i: usize| -> i8 {
        if state[i] == NodeState::Slip {
            if slip[i] >= 0.0 {
                1
            } else {
                -1
            }
        } else {
            0
        }
    };
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

/// Slip regime of the classification in paper §5.2 (and reference sheet §4.2), from the slip
/// zones ordered from the leading edge: 1 one slip zone; 2 two zones slipping in the same
/// direction; 3 two zones in opposite directions; 4 three zones, outer two alike and the middle
/// one opposite. Zones of fewer than `min_nodes` nodes are ignored. Returns 0 for full stick or
/// any other pattern.
pub fn slip_regime(solution: &ContactSolution, leading_edge_sign: f64, min_nodes: usize) -> u8 {
    let mut dirs: Vec<i8> = solution
        .zones
        .iter()
        .filter(|z| z.state == NodeState::Slip && z.nodes >= min_nodes)
        .map(|z| z.direction)
        .collect();
    if leading_edge_sign > 0.0 {
        dirs.reverse();
    }
    match dirs.as_slice() {
        [_] => 1,
        [a, b] if a == b => 2,
        [_, _] => 3,
        [a, b, c] if a == c && a != b => 4,
        _ => 0,
    }
}
