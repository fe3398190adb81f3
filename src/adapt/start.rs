//! Where an error-controlled run starts its passes: the case's uniform start grid, or the final
//! grid of a neighbouring run (a sweep's chain, src/sequence.rs).
//!
//! Runs of a sweep over loads, friction or speed on one start grid have their square-root
//! points (contact edges, stick/slip points, slip reversals) close together, and the grids
//! that meet the tolerance for them are graded alike. A run started from its neighbour's final
//! grid G (and from the neighbour's solution on G's bisection, carried) skips the passes that
//! grow the grid from the start grid; its own passes then refine where its own points need it
//! (the a-priori length and the estimate are checked as for any run, so it meets the same
//! tolerance). What it may not do is keep the neighbour's grading where its own points are
//! not: [`GridStart::coarsened`] merges sibling pieces back first (src/adapt/cells.rs), so
//! that along a chain the grading of points that moved away does not pile up, and
//! [`GridStart::on_start_grid`] merges them all: the run's own start grid, warm from the
//! neighbour's solution (what a sweep uses; src/sequence.rs, "Error-controlled chains", says
//! why).

use super::cells::{Action, DyadicGrid};
use crate::contact::residual::State;
use crate::grid::ContactGrid;
use crate::scene::Scene;

/// The final grid of an error-controlled run and its solution, as the start of a neighbouring
/// run's passes ([`super::solve_from`]).
#[derive(Debug, Clone)]
pub struct GridStart {
    /// The final pass's grid G (the result was solved on its bisection).
    pub(super) coarse: DyadicGrid,
    /// The result's grid (G bisected) and solution: the warm start of the first solve.
    pub(super) grid: ContactGrid,
    /// The result's solution on `grid` (tractions [stress], gap [length], slip [-], overlap
    /// [length], creepage [-]).
    pub(super) state: State,
}

impl GridStart {
    /// The start with every pair of sibling pieces merged back, `levels` times over (one level
    /// undoes one halving of the refinement everywhere, the grading at the neighbour's
    /// square-root points included), then balanced; the solution is kept.
    pub fn coarsened(&self, levels: u32) -> GridStart {
        let mut coarse = self.coarse.clone();
        for _ in 0..levels {
            coarse = coarse.refined(&vec![Action::Merge; coarse.len()]);
        }
        GridStart { coarse, ..self.clone() }
    }

    /// The start on the start grid its pieces are cut from, warm from the same solution (carried):
    /// every level merged back.
    pub fn on_start_grid(&self) -> GridStart {
        GridStart {
            coarse: DyadicGrid::new(self.coarse.root()),
            ..self.clone()
        }
    }

    /// Whether `scene`'s passes can start here: its start grid is the one this grid's pieces
    /// are cut from (kind, edges and nodes bit for bit). A normal load that resizes the
    /// uniform start grid, another grid setting or other bodies' meshes give another.
    pub fn fits(&self, scene: &Scene) -> bool {
        let root = self.coarse.root();
        root.kind == scene.grid.kind && root.edges == scene.grid.edges && root.nodes == scene.grid.nodes
    }
}
