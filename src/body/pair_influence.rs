//! Influence matrices shared by the two bodies of a pair on one grid.
//!
//! **Why.** Two half-plane bodies (half-spaces, viscoelastic half-spaces, the passes' stand-ins
//! of BEM bodies) need the same influence matrices of the half-plane's kernels on the contact
//! grid, K_ij = Σ_e ∫_e N_j(s) K(x_i − s) ds (src/body/half_space.rs), and two viscoelastic
//! bodies rolling at one speed with one creep time the same aged ones: only their coefficients
//! differ. On a graded grid of m nodes each matrix costs O(m²) element integrals (the aged
//! ones exponential integrals each), and an error-controlled run builds them on every grid.
//! A [`PairInfluence`] lets the first body that needs a matrix keep a copy for the second,
//! which takes it: each matrix is computed once per grid and pair.
//!
//! The bodies of a scene join the pair's store when they are built (`BuildContext::pair`),
//! naming the [`Family`] of matrices they will ask for; a matrix is kept only when two bodies
//! joined its family, and the second to ask takes it out, so nothing outlives the assembly of
//! the pair. A matrix is a function of its [`InfluenceKey`] and the grid alone, so a body gets
//! the same bits whether it computes the matrix or takes it.

use crate::grid::{ContactGrid, ElementKind};
use faer::Mat;
use std::sync::{Arc, Mutex};

/// A family of influence matrices: a kernel integral and the parameters it depends on.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Family {
    /// The elastic half-plane's kernels ln|x − s|, sgn(x − s), 1/(x − s).
    HalfPlane,
    /// The same kernels as the BEM bodies' pass stand-ins make them (src/body/bem/stand_in.rs):
    /// on a grid of curved elements carried from the straight grid between the same edges,
    /// where a half-space body asks for the straight grid's. A family of its own, so that a
    /// stand-in shares with a stand-in only and keeps no copy a half-space partner would not
    /// take.
    StandInHalfPlane,
    /// The kernels aged over the length L = V τc with the material coming from `direction`
    /// (src/body/viscoelastic/aged_kernels.rs), by the bits of (L, direction).
    Aged {
        /// L [length], as bits.
        length: u64,
        /// ±1, as bits.
        direction: u64,
    },
}

/// One influence matrix of a family: the family and the kernel.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct InfluenceKey {
    /// The kernel integral's family.
    pub family: Family,
    /// The kernel within the family: the index of a half-plane kernel
    /// (`crate::body::half_space::Kernel as u8`).
    pub kernel: u8,
}

/// A matrix kept for the second body, with the grid it was computed on.
#[derive(Debug)]
struct Kept {
    key: InfluenceKey,
    kind: ElementKind,
    edges: Vec<f64>,
    nodes: Vec<f64>,
    matrix: Mat<f64>,
}

/// The store of one pair's influence matrices (module docs).
#[derive(Debug, Default)]
pub struct PairInfluence {
    /// The families the bodies joined, once per body.
    joined: Mutex<Vec<Family>>,
    kept: Mutex<Vec<Kept>>,
    /// The matrices a copy was kept of once already (their keys and grids, matrices dropped):
    /// a body that asks again after the other took its copy (body B's own flexibility made
    /// again for a run's outputs) computes it without keeping another, which no body would take.
    served: Mutex<Vec<Kept>>,
}

impl PairInfluence {
    /// An empty store.
    pub fn new() -> Self {
        Self::default()
    }

    /// A body will ask for matrices of `family` (once per body and family).
    pub fn join(&self, family: Family) {
        self.joined.lock().expect("pair store").push(family);
    }

    /// The matrix `key` on `grid`: the one another body kept, else `compute()`'s, of which a copy
    /// is kept when two bodies joined the family.
    pub fn matrix(&self, key: InfluenceKey, grid: &ContactGrid, compute: impl FnOnce() -> Mat<f64>) -> Mat<f64> {
        let same = |k: &Kept| k.key == key && k.kind == grid.kind && k.edges == grid.edges && k.nodes == grid.nodes;
        {
            let mut kept = self.kept.lock().expect("pair store");
            if let Some(i) = kept.iter().position(same) {
                return kept.swap_remove(i).matrix;
            }
        }
        let matrix = compute();
        let users = self
            .joined
            .lock()
            .expect("pair store")
            .iter()
            .filter(|&&f| f == key.family)
            .count();
        let mut served = self.served.lock().expect("pair store");
        if users >= 2 && !served.iter().any(same) {
            let entry = |matrix| Kept {
                key,
                kind: grid.kind,
                edges: grid.edges.clone(),
                nodes: grid.nodes.clone(),
                matrix,
            };
            served.push(entry(Mat::zeros(0, 0)));
            self.kept.lock().expect("pair store").push(entry(matrix.clone()));
        }
        matrix
    }

    /// Number of matrices kept for a body that has not taken them yet.
    pub fn kept(&self) -> usize {
        self.kept.lock().expect("pair store").len()
    }
}

/// The store a body built with `pair` keeps, having joined it for `families` (None: the body
/// is on its own).
pub fn joined(pair: Option<&Arc<PairInfluence>>, families: &[Family]) -> Option<Arc<PairInfluence>> {
    let pair = pair?;
    for &f in families {
        pair.join(f);
    }
    Some(pair.clone())
}

/// A matrix of a pair's store when the body has one, else `compute()`'s.
pub fn shared_or_computed(
    pair: Option<&PairInfluence>,
    key: InfluenceKey,
    grid: &ContactGrid,
    compute: impl FnOnce() -> Mat<f64>,
) -> Mat<f64> {
    match pair {
        Some(p) => p.matrix(key, grid, compute),
        None => compute(),
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::grid::ElementKind;

    fn counting(calls: &mut usize, value: f64) -> Mat<f64> {
        *calls += 1;
        Mat::from_fn(3, 3, |i, j| value + (i + 3 * j) as f64)
    }

    #[test]
    fn the_second_body_takes_what_the_first_computed_and_nothing_stays() {
        let grid = ContactGrid::uniform(ElementKind::DiscontinuousQuadratic, 2, -1.0, 1.0);
        let key = InfluenceKey {
            family: Family::HalfPlane,
            kernel: 0,
        };
        let pair = PairInfluence::new();
        pair.join(Family::HalfPlane);
        pair.join(Family::HalfPlane);
        let mut calls = 0;
        let a = pair.matrix(key, &grid, || counting(&mut calls, 1.0));
        assert_eq!(pair.kept(), 1);
        let b = pair.matrix(key, &grid, || counting(&mut calls, 2.0));
        assert_eq!((calls, pair.kept()), (1, 0));
        assert_eq!(a, b);
        // Another kernel, another grid or a family one body joined: computed, not taken.
        let other = ContactGrid::uniform(ElementKind::DiscontinuousQuadratic, 3, -1.0, 1.0);
        let _ = pair.matrix(key, &other, || counting(&mut calls, 3.0));
        let sign = InfluenceKey { kernel: 1, ..key };
        let s = pair.matrix(sign, &grid, || counting(&mut calls, 4.0));
        assert_eq!(s[(0, 0)], 4.0);
        let aged = Family::Aged {
            length: 2.0f64.to_bits(),
            direction: 1.0f64.to_bits(),
        };
        pair.join(aged);
        let aged_key = InfluenceKey { family: aged, ..key };
        let _ = pair.matrix(aged_key, &grid, || counting(&mut calls, 5.0));
        assert_eq!(calls, 4);
        // The half-plane matrices of `other` and `sign` wait for the second body; the aged one,
        // which only one body joined, was not kept.
        assert_eq!(pair.kept(), 2);
        // A body asking again for a matrix the other took computes it and keeps no copy.
        let again = pair.matrix(key, &grid, || counting(&mut calls, 6.0));
        assert_eq!((again[(0, 0)], calls, pair.kept()), (6.0, 5, 2));
    }
}
