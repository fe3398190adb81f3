//! The solver's state in user-facing terms (signs of docs/theory.md): nodal tractions, gap
//! and slip recomputed from the tractions, node states, forces, contact extent and zones.

use super::zones::{zones, NodeState, SlipDirection, Zone};
use crate::contact::residual::State;
use crate::contact::{ContactForces, ContactProblem};
use serde::Serialize;

/// Converged solution at the contact nodes, user-facing signs (docs/theory.md).
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
    /// Slip velocity of A relative to B divided by |V| [-], finite-difference operator (upwind;
    /// downstream at the upstream end node).
    pub slip: Vec<f64>,
    /// Slip from the boundary-integral derivative of the displacements [-], if available.
    pub slip_strain: Option<Vec<f64>>,
    /// Node states.
    pub state: Vec<NodeState>,
    /// Normal force P = ∫p dx [force/length]: the load the solver holds (with tractions along
    /// the contact, the y force of the pressure alone).
    pub normal_force: f64,
    /// Tangential force Q = ∫q dx [force/length] (with tractions along the contact, the x
    /// force of the shear alone).
    pub tangential_force: f64,
    /// The forces on A globally and along the contact (equal to P and Q in global axes).
    pub forces: ContactForces,
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
        // Recompute g and s from the tractions so outputs are exactly consistent with them; the
        // slip velocity everywhere, also at the upstream end node (whose row of the problem is
        // the datum of w, not a slip).
        let gap = pb.gap(&z.pressure, &z.shear, z.overlap);
        let slip = pb.slip_velocity(&z.pressure, &z.shear, z.creep);
        let pressure: Vec<f64> = z.pressure.iter().map(|p| p.max(0.0)).collect();
        let pmax = pressure.iter().fold(0.0_f64, |a, &b| a.max(b));
        let state: Vec<NodeState> = (0..m)
            .map(|i| {
                let p = pressure[i];
                if p <= 1e-12 * pmax {
                    NodeState::Open
                } else if z.shear[i].abs() >= pb.friction_of_slip(i, z.slip[i]) * p * (1.0 - 1e-9) && pb.friction > 0.0
                {
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
            forces: pb.frame.forces(&pb.grid, &pressure, &z.shear),
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
