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
//!
//! **Kept factors.** The reduced matrix depends only on the problem, on the nodes' states
//! (contact or open; stick, slip and its sign) and on a few coefficients (μ at slipping nodes,
//! a falling law's slopes, the row weights, the load row's Q/(μP)), not on the residual: when an
//! iterate has the states of the last one factored, the matrix is the same and so are its
//! factors. The steps of a transient history meet this all the time (each step starts from the
//! last step's solution, whose states its last Newton system already had). A workspace made by
//! [`Workspace::keeping_factors`] keeps the last factored system's LU with the system's *key*
//! (`System::system_key` in src/contact/direction.rs: every input of the matrix by its bits,
//! the problem's flexibilities by address and diagonal), and a system with the same key is
//! solved with the kept factors without its matrix being filled: the same numbers as a new LU
//! (the same factors of the same matrix; `kept_factors_give_the_bits_of_new_ones` below), for
//! an O(n²) solve instead of an O(n³) factorisation and the O(n²) fill. The flexibilities are
//! keyed by address, so a problem must not be changed in place while a workspace keeps
//! factors of it (a history that changes its slip blocks makes new ones).

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
    /// The last factored system and its factors (a workspace that keeps factors, module docs).
    kept: Option<KeptFactor>,
}

/// A factored reduced system kept for reuse: its key (empty while none is kept, so that no
/// system's key equals it), its LU factors (in the matrix's place, as
/// [`LuWorkspace::solve_in_place`] leaves them) and the LU workspace that holds their pivots.
#[derive(Debug)]
struct KeptFactor {
    key: Vec<u64>,
    factors: Mat<f64>,
    lu: LuWorkspace,
    /// Systems solved with new factors, and with the kept ones.
    factored: usize,
    reused: usize,
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
            kept: None,
        }
    }

    /// An empty workspace that keeps the last factored Newton matrix and reuses its factors
    /// for a system with the same matrix (module docs): for sequences of solves whose active
    /// sets repeat, such as the steps of a transient history. Results are those of
    /// [`Workspace::new`], bit for bit.
    pub fn keeping_factors() -> Self {
        Self {
            kept: Some(KeptFactor {
                key: Vec::new(),
                factors: Mat::new(),
                lu: LuWorkspace::new(),
                factored: 0,
                reused: 0,
            }),
            ..Self::new()
        }
    }

    /// The reduced systems solved with new LU factors and with kept ones, so far (both 0 for a
    /// workspace that does not keep factors).
    pub fn factorisations(&self) -> (usize, usize) {
        self.kept.as_ref().map_or((0, 0), |k| (k.factored, k.reused))
    }

    /// The largest order of a reduced Newton system the workspace holds without allocating
    /// (0 before the first solve).
    pub fn capacity(&self) -> usize {
        self.capacity
    }

    /// Whether the workspace keeps factors ([`Workspace::keeping_factors`]).
    pub(super) fn keeps_factors(&self) -> bool {
        self.kept.is_some()
    }

    /// Whether the kept factors are those of the system with this key (module docs).
    pub(super) fn kept_for(&self, key: &[u64]) -> bool {
        self.kept.as_ref().is_some_and(|k| !k.key.is_empty() && k.key == key)
    }

    /// The n × n matrix (zero when `zero_matrix`; else as the last system left it, for a system
    /// the kept factors solve) and the zero right side of a reduced system, in the workspace's
    /// memory (grown when n exceeds its capacity), to fill and then solve by
    /// [`Workspace::solve_system`].
    pub(super) fn system(&mut self, n: usize, zero_matrix: bool) -> (&mut Mat<f64>, &mut Mat<f64>) {
        if n > self.capacity {
            // Freed before the larger one is allocated (a reserve would hold both at once).
            self.matrix = Mat::new();
            self.matrix.reserve(n, n);
            self.rhs.reserve(n, 1);
            self.capacity = n;
            // The kept factors trade places with `matrix` (`solve_system`): same capacity.
            if let Some(kept) = self.kept.as_mut() {
                kept.factors = Mat::new();
                kept.factors.reserve(n, n);
                // No system is kept with them: no key equals an empty one.
                kept.key.clear();
            }
        }
        // Truncating first makes the resize write every entry once: zeros, whatever the last
        // system left there.
        if zero_matrix {
            self.matrix.truncate(0, 0);
            self.matrix.resize_with(n, n, |_, _| 0.0);
        }
        self.rhs.truncate(0, 0);
        self.rhs.resize_with(n, 1, |_, _| 0.0);
        (&mut self.matrix, &mut self.rhs)
    }
}

impl Workspace {
    /// Solves the system that [`Workspace::system`] handed out and the caller filled (its right
    /// side; its matrix too unless the kept factors are the system's): the right side becomes
    /// the solution. With kept factors of the same `key` (module docs), by them; else by a new
    /// LU, which a workspace that keeps factors then keeps with `key`.
    pub(super) fn solve_system(&mut self, key: Option<Vec<u64>>) {
        let Self {
            matrix, rhs, lu, kept, ..
        } = self;
        if rhs.nrows() == 0 {
            return;
        }
        let Some(kept) = kept.as_mut() else {
            lu.solve_in_place(matrix.as_mut(), rhs.as_mut());
            return;
        };
        let key = key.unwrap_or_default();
        if !key.is_empty() && kept.key == key {
            kept.lu.solve_again(kept.factors.as_ref(), rhs.as_mut());
            kept.reused += 1;
            return;
        }
        lu.solve_in_place(matrix.as_mut(), rhs.as_mut());
        // The factors stay; the old kept buffer (same capacity) is the next system's matrix.
        std::mem::swap(matrix, &mut kept.factors);
        std::mem::swap(lu, &mut kept.lu);
        kept.key = key;
        kept.factored += 1;
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
    fn kept_factors_give_the_bits_of_new_ones() {
        // Two warm solves from the same perturbed start meet the same sequence of Newton
        // matrices: the second solves each with the first's kept factors when the matrix
        // repeats (at least its first system, whose matrix is the last one the first solve
        // factored only if the states repeat; the second solve's are equal to the first's one
        // by one). Every result equals a solve with a new workspace bit for bit.
        use crate::contact::methods::solve_from_in;
        let (pb, settings) = carter(41);
        let (z, report) = solve(&pb, &settings);
        assert!(report.converged);
        // A start near the solution: the pressures and shears a little off, so the Newton
        // method takes a few steps with the solution's active sets.
        let mut warm = z.clone();
        warm.pressure.iter_mut().for_each(|p| *p *= 1.01);
        warm.shear.iter_mut().for_each(|q| *q *= 0.99);
        let (z_fresh, r_fresh) = solve_from_in(&pb, &settings, Some(warm.clone()), &mut Workspace::new());
        let mut ws = Workspace::keeping_factors();
        let (z_first, r_first) = solve_from_in(&pb, &settings, Some(warm.clone()), &mut ws);
        let after_first = ws.factorisations();
        let (z_second, r_second) = solve_from_in(&pb, &settings, Some(warm), &mut ws);
        let (factored, reused) = ws.factorisations();
        assert!(r_fresh.converged && r_first.converged && r_second.converged);
        assert_eq!(z_first, z_fresh);
        assert_eq!(z_second, z_fresh);
        assert_eq!(r_second.residual.to_bits(), r_fresh.residual.to_bits());
        assert!(
            after_first.0 >= 1,
            "the first solve factored its systems: {after_first:?}"
        );
        assert!(
            reused > after_first.1,
            "the second solve reused kept factors: {after_first:?} then {:?}",
            (factored, reused)
        );
        assert_eq!(Workspace::new().factorisations(), (0, 0));
    }

    #[test]
    fn kept_factors_follow_a_problem_changed_in_place() {
        // The same problem, its friction and its tangential load changed in place between
        // solves (same flexibilities at the same addresses): the key sees μ and Q/(μP), so no
        // stale factor solves the changed system; every result equals a new workspace's. Each
        // pair is solved twice from a start a little off its solution, the second time with
        // the factors the first kept (as in `kept_factors_give_the_bits_of_new_ones`).
        use crate::contact::methods::solve_from_in;
        use crate::contact::TangentialControl;
        let (mut pb, settings) = carter(41);
        let mut ws = Workspace::keeping_factors();
        for (mu, ratio) in [(0.3, 0.51), (0.25, 0.51), (0.25, 0.6), (0.3, 0.51)] {
            pb.friction = mu;
            if let TangentialControl::Ratio(r) = &mut pb.tangential {
                *r = ratio;
            }
            let (z, _) = solve(&pb, &settings);
            let mut warm = z.clone();
            warm.pressure.iter_mut().for_each(|p| *p *= 1.01);
            warm.shear.iter_mut().for_each(|q| *q *= 0.99);
            let (fresh, r_fresh) = solve_from_in(&pb, &settings, Some(warm.clone()), &mut Workspace::new());
            assert!(r_fresh.converged);
            for _ in 0..2 {
                let (kept, r_kept) = solve_from_in(&pb, &settings, Some(warm.clone()), &mut ws);
                assert!(r_kept.converged);
                assert_eq!(kept, fresh, "μ {mu}, Q/μP {ratio}");
            }
        }
        assert!(
            ws.factorisations().1 > 0,
            "some systems reused: {:?}",
            ws.factorisations()
        );
    }
}
