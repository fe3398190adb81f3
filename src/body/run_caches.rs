//! What one run's body builds share, held by the run rather than by the bodies' setups.
//!
//! An error-controlled run condenses each BEM body on the finer of its stand-in's two grids
//! (src/body/bem/stand_in.rs) and, once the contact grid meets the tolerance, solves the
//! bodies on that same grid again to check their meshes (src/adapt/body_mesh.rs); a body mesh
//! bisected outside the contact and adopted by the run is condensed by that check and again
//! by its own stand-in. The second build takes the first's condensation: the same matrices,
//! not a copy computed again. The driver of the run (`adapt::solve_with`) owns the
//! [`RunCaches`] that hold them, passes it by reference to every build
//! ([`super::BuildContext::run`]) and drops it, and what it holds, when the run ends.
//!
//! A condensation is found by the [`BodyLineage`] of the setup that built it, its side and
//! its own contact grid: a setup that follows a grid keeps its lineage (its mesh is the start
//! mesh cut along that grid, so the grid names it), a setup whose own mesh is replaced (its
//! elements outside the contact bisected or merged) takes a fresh one, since it has the same
//! grid as the body it came from but not the same flexibility.

use super::Side;
use crate::grid::ContactGrid;
use std::any::Any;
use std::collections::HashMap;
use std::hash::{Hash, Hasher};
use std::sync::{Arc, Mutex};

/// The identity of one body mesh and the setups that follow contact grids from it (their
/// meshes are cut from it). Issued fresh ([`Self::fresh`]) wherever a body's own mesh is
/// replaced; cloning a setup shares it. Two lineages are equal only if one was cloned from
/// the other.
#[derive(Clone)]
pub struct BodyLineage(Arc<()>);

impl BodyLineage {
    /// A lineage no other setup has.
    pub fn fresh() -> Self {
        // Each `Arc::new` allocates its own counts, so the allocation's address tells lineages
        // apart; the cache's key keeps it allocated, so no later lineage takes that address
        // while an entry of this one is held.
        Self(Arc::new(()))
    }

    /// Whether only the cache's own key still holds the lineage: every setup of it dropped,
    /// so no later build can ask for its entry.
    fn ended(&self) -> bool {
        Arc::strong_count(&self.0) == 1
    }
}

impl PartialEq for BodyLineage {
    fn eq(&self, other: &Self) -> bool {
        Arc::ptr_eq(&self.0, &other.0)
    }
}

impl Eq for BodyLineage {}

impl Hash for BodyLineage {
    fn hash<H: Hasher>(&self, state: &mut H) {
        (Arc::as_ptr(&self.0) as usize).hash(state);
    }
}

impl std::fmt::Debug for BodyLineage {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(f, "BodyLineage({:p})", Arc::as_ptr(&self.0))
    }
}

/// A condensation kept: the side it was built for, the edges of its own contact grid, and the
/// condensed body (of the model that kept it).
struct Condensed {
    side: Side,
    edges: Vec<f64>,
    body: Arc<dyn Any + Send + Sync>,
}

/// The caches of one run (module docs): at most one condensed body per [`BodyLineage`], the
/// last one kept.
#[derive(Default)]
pub struct RunCaches {
    condensed: Mutex<HashMap<BodyLineage, Condensed>>,
}

impl std::fmt::Debug for RunCaches {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        let held = self.condensed.lock().map(|c| c.len()).unwrap_or(0);
        write!(f, "RunCaches({held} condensed bodies)")
    }
}

impl RunCaches {
    /// An empty cache for a new run.
    pub fn new() -> Self {
        Self::default()
    }

    /// The body of type `T` kept for `lineage` on `side` with its own contact grid `own`, if
    /// any.
    pub fn condensed<T: Any + Send + Sync>(
        &self,
        lineage: &BodyLineage,
        side: Side,
        own: &ContactGrid,
    ) -> Option<Arc<T>> {
        let mut held = self.condensed.lock().ok()?;
        forget_ended(&mut held);
        let kept = held.get(lineage)?;
        if kept.side != side || kept.edges != own.edges {
            return None;
        }
        kept.body.clone().downcast::<T>().ok()
    }

    /// Keeps `body`, built for `lineage` on `side` with its own contact grid `own`, in place of
    /// what was kept for the lineage.
    pub fn keep<T: Any + Send + Sync>(&self, lineage: &BodyLineage, side: Side, own: &ContactGrid, body: Arc<T>) {
        if let Ok(mut held) = self.condensed.lock() {
            forget_ended(&mut held);
            let kept = Condensed {
                side,
                edges: own.edges.clone(),
                body,
            };
            held.insert(lineage.clone(), kept);
        }
    }

    /// How many condensed bodies the cache holds.
    pub fn len(&self) -> usize {
        self.condensed.lock().map(|c| c.len()).unwrap_or(0)
    }

    /// Whether the cache holds no condensed body.
    pub fn is_empty(&self) -> bool {
        self.len() == 0
    }
}

/// Drops the entries of lineages no setup holds any more (a body replaced by its bisection
/// for the run): their memory goes before the next condensation is made, as when the setups
/// held it themselves, rather than when the run ends.
fn forget_ended(held: &mut HashMap<BodyLineage, Condensed>) {
    held.retain(|lineage, _| !lineage.ended());
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A body is found by its own lineage, side and grid only: a fresh lineage (a mesh
    /// replaced) on the same grid finds nothing, a clone of the lineage finds it, and its entry
    /// goes once no setup holds the lineage.
    #[test]
    fn a_body_is_found_by_its_lineage_side_and_grid() {
        let run = RunCaches::new();
        let grid = ContactGrid::uniform(crate::grid::ElementKind::Constant, 4, -1.0, 1.0);
        let other = ContactGrid::uniform(crate::grid::ElementKind::Constant, 8, -1.0, 1.0);
        let given = BodyLineage::fresh();
        run.keep(&given, Side::A, &grid, Arc::new(7_u32));
        let follower = given.clone();
        assert_eq!(run.condensed::<u32>(&follower, Side::A, &grid).as_deref(), Some(&7));
        assert!(run.condensed::<u32>(&given, Side::B, &grid).is_none(), "another side");
        assert!(run.condensed::<u32>(&given, Side::A, &other).is_none(), "another grid");
        assert!(run.condensed::<u64>(&given, Side::A, &grid).is_none(), "another type");
        let replaced = BodyLineage::fresh();
        assert!(
            run.condensed::<u32>(&replaced, Side::A, &grid).is_none(),
            "a body whose mesh was replaced does not share the given one's entry"
        );
        drop((given, follower));
        assert!(run.condensed::<u32>(&replaced, Side::A, &grid).is_none());
        assert!(run.is_empty(), "the ended lineage's entry is dropped");
    }
}
