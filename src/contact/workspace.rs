//! The reusable memory of the Newton solves: the reduced Newton matrix of
//! [`super::direction`], its right side, the LU's pivots and scratch space, and the work vectors
//! that map nodes to the matrix's rows and columns.
//!
//! **Why.** The reduced matrix has up to (2m + 2)² entries (m contact nodes): 27 MB at m = 924,
//! the largest grid of an error-controlled run at tolerance 1e-5. Allocated anew at every Newton
//! step, each such block is a fresh mapping whose pages the kernel faults in and zeroes at first
//! touch (glibc serves large blocks by `mmap`): a quarter of an error-controlled run's time once
//! went to those faults (docs/performance.md). A [`Workspace`] holds that memory across the
//! Newton steps of a solve and its restarts, and across the solves it is passed to
//! ([`super::methods::solve_in`], [`super::methods::solve_from_in`]: e.g. the grids of an
//! error-controlled run): its capacity grows to the largest system met and is reused for the
//! smaller ones.
//!
//! A workspace holds no state of the solution: a solve with a used workspace gives the same
//! numbers as one with a new one (`solves_alike_with_a_used_workspace` below).

use crate::linalg::LuWorkspace;
use faer::Mat;

/// Tangential state of a node for the pseudo-Jacobian of [`super::direction`] (free: no
/// friction bound; stick; slip with the sign of the slip).
#[derive(Debug, Clone, Copy, PartialEq)]
pub(super) enum Tangential {
    Free,
    Stick,
    Slip(f64),
}

/// Memory reused by the Newton solves of [`super::methods`] (module docs). Create one with
/// [`Workspace::new`] and pass it to every solve of a sequence (e.g. the grids of an
/// error-controlled run); one workspace serves one solve at a time.
#[derive(Debug)]
pub struct Workspace {
    /// The reduced Newton matrix, resized (within its capacity) to each system.
    pub(super) matrix: Mat<f64>,
    /// The order up to which `matrix` and `rhs` resize without allocating.
    capacity: usize,
    /// The right side of the reduced system, then its solution.
    pub(super) rhs: Mat<f64>,
    /// Pivots and scratch space of the LU.
    pub(super) lu: LuWorkspace,
    /// Column of Δp_j in the reduced system, if Δp_j is unknown.
    pub(super) p_col: Vec<Option<usize>>,
    /// Known part of Δp_j.
    pub(super) p_const: Vec<f64>,
    /// Column of Δq_j in the reduced system, if Δq_j is unknown.
    pub(super) q_col: Vec<Option<usize>>,
    /// Known part of Δq_j.
    pub(super) q_const: Vec<f64>,
    /// Coefficient of Δp_j in Δq_j (slipping nodes: μ sgn).
    pub(super) q_pcoef: Vec<f64>,
    /// Nodes whose contact row is in the reduced system.
    pub(super) contact_rows: Vec<usize>,
    /// Nodes whose stick row is in the reduced system.
    pub(super) stick_rows: Vec<usize>,
    /// Normal branch of every node (contact or open).
    pub(super) normal_contact: Vec<bool>,
    /// Tangential branch of every node.
    pub(super) tangential: Vec<Tangential>,
}

impl Default for Workspace {
    fn default() -> Self {
        Self::new()
    }
}

impl Workspace {
    /// An empty workspace: the first Newton step allocates, the next ones reuse.
    pub fn new() -> Self {
        Self {
            matrix: Mat::new(),
            capacity: 0,
            rhs: Mat::new(),
            lu: LuWorkspace::new(),
            p_col: Vec::new(),
            p_const: Vec::new(),
            q_col: Vec::new(),
            q_const: Vec::new(),
            q_pcoef: Vec::new(),
            contact_rows: Vec::new(),
            stick_rows: Vec::new(),
            normal_contact: Vec::new(),
            tangential: Vec::new(),
        }
    }

    /// The largest order of a reduced Newton system the workspace holds without allocating
    /// (0 before the first solve).
    pub fn capacity(&self) -> usize {
        self.capacity
    }

    /// The n × n matrix and zero right side of a reduced system, in the workspace's memory
    /// (grown when n exceeds its capacity), with the LU's workspace. The matrix is **not
    /// cleared**: the entries it shares with the last system (the leading min(n, n_last)
    /// square) hold that system's values, the others are zero. Its caller writes every entry
    /// ([`super::direction`]: the elastic rows by assignment, the rest cleared first); zeroing
    /// the whole matrix at every Newton step was 5 % of a warm-started sweep's time.
    pub(super) fn system(&mut self, n: usize) -> (&mut Mat<f64>, &mut Mat<f64>, &mut LuWorkspace) {
        if n > self.capacity {
            // Freed before the larger one is allocated (a reserve would hold both at once).
            self.matrix = Mat::new();
            self.matrix.reserve(n, n);
            self.rhs.reserve(n, 1);
            self.capacity = n;
        }
        // Truncating to the shared square first makes the resize write only the new entries.
        let kept = n.min(self.matrix.nrows()).min(self.matrix.ncols());
        self.matrix.truncate(kept, kept);
        self.matrix.resize_with(n, n, |_, _| 0.0);
        self.rhs.truncate(0, 0);
        self.rhs.resize_with(n, 1, |_, _| 0.0);
        (&mut self.matrix, &mut self.rhs, &mut self.lu)
    }
}

/// `Workspace` moves between the threads of a parallel sweep with its solve.
const _: fn() = || {
    fn send<T: Send>() {}
    send::<Workspace>();
};

#[cfg(test)]
mod tests {
    use super::*;
    use crate::contact::methods::{solve, solve_in};
    use crate::contact::ContactProblem;

    /// The assembled problem of Carter's case on `elements` elements, and its solver settings.
    fn carter(elements: usize) -> (ContactProblem, crate::contact::SolverSettings) {
        let solved = crate::app::solve_case(
            &crate::case::shipped("carter_051.yaml"),
            &[format!("contact.grid.elements={elements}")],
        )
        .expect("shipped case solves");
        (solved.problem, solved.scene.solver)
    }

    #[test]
    fn solves_alike_with_a_used_workspace() {
        // A workspace that served a larger problem (the first Newton system bonds every node:
        // 2m + 2 unknowns) keeps its capacity and solves a smaller one to the same bits as a
        // new workspace; then the larger one again, without growing.
        let (large, settings) = carter(61);
        let (small, _) = carter(21);
        let mut ws = Workspace::new();
        let (z_large, r_large) = solve_in(&large, &settings, &mut ws);
        let capacity = ws.capacity();
        assert!(r_large.converged);
        assert_eq!(
            capacity,
            2 * large.n_nodes() + 2,
            "the largest system is the first, fully bonded one"
        );
        let (z_fresh, r_fresh) = solve(&small, &settings);
        let (z_used, r_used) = solve_in(&small, &settings, &mut ws);
        assert!(r_fresh.converged);
        assert_eq!(z_used, z_fresh);
        assert_eq!(r_used.iterations, r_fresh.iterations);
        assert_eq!(r_used.residual.to_bits(), r_fresh.residual.to_bits());
        let (z_again, _) = solve_in(&large, &settings, &mut ws);
        assert_eq!(z_again, z_large);
        assert_eq!(ws.capacity(), capacity, "the workspace did not grow again");
    }

    #[test]
    fn every_entry_of_the_reused_matrix_is_written() {
        // The reduced matrix is not cleared between Newton steps (`Workspace::system`): a
        // workspace whose matrix holds NaN everywhere must still solve to the bits of a new
        // one, on a problem with a free overlap and creepage (load rows and columns) and on
        // one whose systems shrink and grow from step to step.
        for elements in [21, 41] {
            let (pb, settings) = carter(elements);
            let (z_fresh, r_fresh) = solve(&pb, &settings);
            let mut ws = Workspace::new();
            solve_in(&pb, &settings, &mut ws);
            let n = ws.capacity();
            ws.matrix.truncate(0, 0);
            ws.matrix.resize_with(n, n, |_, _| f64::NAN);
            let (z_used, r_used) = solve_in(&pb, &settings, &mut ws);
            assert!(r_fresh.converged);
            assert_eq!(z_used, z_fresh);
            assert_eq!(r_used.iterations, r_fresh.iterations);
            assert_eq!(r_used.residual.to_bits(), r_fresh.residual.to_bits());
        }
    }
}
