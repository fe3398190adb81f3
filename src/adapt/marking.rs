//! The marking step of the error-control loop (src/adapt.rs, module docs step 4): where H's
//! tractions have square-root points, and what to do with each element of G.

use super::a_priori::APriori;
use super::cells::{Action, DyadicGrid};
use super::estimate::Comparison;
use super::{CREEPAGE_ALONE, MAX_DEPTH_PER_PASS, SAFETY};
use crate::contact::residual::State;
use crate::contact::ContactProblem;
use crate::post::adaptation::ErrorEstimate;
use crate::post::{ContactSolution, NodeState};

/// Where the tractions have square-root points [length]: between neighbouring nodes where the
/// contact opens (an edge), where stick turns to slip, and where the slip reverses.
pub(super) fn singular_points(pb: &ContactProblem, z: &State) -> Vec<f64> {
    let sol = ContactSolution::from_state(pb, z);
    let x = &pb.grid.nodes;
    (1..x.len())
        .filter(|&i| {
            let (a, b) = (sol.state[i - 1], sol.state[i]);
            let reversal = a == NodeState::Slip && b == NodeState::Slip && sol.shear[i - 1] * sol.shear[i] < 0.0;
            a != b || reversal
        })
        .map(|i| 0.5 * (x[i - 1] + x[i]))
        .collect()
}

/// What to do with each element of `coarse` (module docs, step 4) from the contact grid's
/// comparison `cmp` (its indicators) and the pass's estimate `e` (with the overlap where
/// controlled), no element of the bisection of the result shorter than `shortest` [length];
/// None when no element can be halved.
pub(super) fn actions(
    coarse: &DyadicGrid,
    cmp: &Comparison,
    e: &ErrorEstimate,
    singular: &[f64],
    tolerance: f64,
    lengths: &APriori,
    shortest: f64,
) -> Option<Vec<Action>> {
    let indicator = &cmp.detail;
    let active = indicator.iter().filter(|&&z| z > 0.0).count().max(1);
    // The estimate (squared) is taken to fall with the sum of the local indicators: to bring
    // the largest of the three estimates to SAFETY·tolerance, the sum must fall by `factor`,
    // shared equally among the elements that carry it.
    let largest = e.largest();
    let factor = if largest > 0.0 {
        (SAFETY * tolerance / largest).powi(2).min(1.0)
    } else {
        1.0
    };
    let target = indicator.iter().sum::<f64>() * factor / active as f64;
    // The creepage's error alone above the tolerance, the tractions' an order of magnitude
    // below it: the creepage is a functional of the shear over the whole stick zone, and its
    // error is the smooth error there, which the indicators do not see: every element in the
    // contact is halved (module docs).
    let creepage_alone = e.creep_rel > tolerance && e.pressure_rms.max(e.shear_rms) <= CREEPAGE_ALONE * tolerance;
    let mut action: Vec<Action> = coarse
        .cells()
        .iter()
        .zip(indicator)
        .zip(&cmp.open)
        .map(|((&c, &z), &open)| {
            let (x0, x1) = (coarse.end(c, false), coarse.end(c, true));
            let inside = singular.iter().copied().find(|&x| x >= x0 && x <= x1);
            // The nearest square-root point, when it lies within an element length: the
            // discrete transition may sit one node off the true one, in this element.
            let near = singular
                .iter()
                .copied()
                .filter(|&x| (x0 - x).max(x - x1).max(0.0) <= x1 - x0)
                .min_by(|a, b| (a - 0.5 * (x0 + x1)).abs().total_cmp(&(b - 0.5 * (x0 + x1)).abs()));
            // An element of H holding a square-root point is at most A_PRIORI_LENGTH·tolerance·a
            // long: a node beside the point has an error ∝ √(h/a), standing for a length h, so
            // its share of the RMS is ∝ h/a whatever the estimate saw (a node can fall close
            // enough to the point that both grids miss its error). Graded there in one pass, as
            // deep as the rule asks: the point is located to H's node spacing, and where the next
            // pass finds it elsewhere it grades again there, as [`resolved`] asks of every pass.
            // (Three halvings a pass at most, as before, left the rule for one more pass where
            // the estimate already met the tolerance: fig14_true_geometry at 1e-5, four passes
            // to 518 elements against three to 454 now.)
            let a_priori = inside.map_or(0, |x| {
                // G's element is halved once more in H.
                let ratio = (x1 - x0) / (2.0 * lengths.at(x));
                if ratio > 1.0 {
                    (ratio.log2().ceil() as u32).min(MAX_DEPTH_PER_PASS)
                } else {
                    0
                }
            });
            if z > target && target > 0.0 {
                let ratio = (z / target).log2();
                let depth =
                    |per_halving: f64| (ratio / per_halving).ceil().clamp(1.0, f64::from(MAX_DEPTH_PER_PASS)) as u32;
                match inside.or(near) {
                    // Next to a square-root point the share falls by 4 per halving.
                    Some(x) => Action::GradeTowards(x.clamp(x0, x1), depth(2.0).max(a_priori)),
                    // Where the solution is smooth, by 2⁷ (nodal error h³, over a length h): one
                    // halving a pass is plenty, and keeps a pass from multiplying the grid.
                    None => Action::Split(depth(7.0).min(1)),
                }
            } else if let (Some(x), true) = (inside, a_priori > 0) {
                Action::GradeTowards(x, a_priori)
            } else if creepage_alone && !open {
                Action::Split(1)
            } else if open && inside.is_none() && z <= target / 64.0 {
                Action::Merge
            } else {
                Action::Keep
            }
        })
        .collect();
    // The grid's H halves each element of the result once more: 2^(depth + 1) pieces of an
    // element must each be at least `shortest` long.
    let deepest: Vec<u32> = coarse
        .cells()
        .iter()
        .map(|&c| {
            let pieces = (coarse.end(c, true) - coarse.end(c, false)) / shortest;
            (pieces.log2().floor() - 1.0).max(0.0) as u32
        })
        .collect();
    for (a, &d) in action.iter_mut().zip(&deepest) {
        *a = match *a {
            Action::Split(_) | Action::GradeTowards(..) if d == 0 => Action::Keep,
            Action::Split(k) => Action::Split(k.min(d)),
            Action::GradeTowards(x, k) => Action::GradeTowards(x, k.min(d)),
            other => other,
        };
    }
    // Never a pass without a refinement: the element with the largest share is halved.
    if !action
        .iter()
        .any(|a| matches!(a, Action::Split(_) | Action::GradeTowards(..)))
    {
        let worst = (0..indicator.len())
            .filter(|&k| deepest[k] > 0)
            .max_by(|&a, &b| indicator[a].total_cmp(&indicator[b]))?;
        action[worst] = Action::Split(1);
    }
    Some(action)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::adapt::A_PRIORI_LENGTH;
    use crate::grid::{ContactGrid, ElementKind};

    /// A grid of four elements of length 1/2 on [−1, 1] whose third holds a square-root point
    /// at 0.3 and carries all the error, far above the tolerance.
    fn marked(shortest: f64) -> Option<Vec<Action>> {
        let coarse = DyadicGrid::new(&ContactGrid::uniform(ElementKind::DiscontinuousQuadratic, 4, -1.0, 1.0));
        let cmp = Comparison {
            estimate: crate::post::adaptation::ErrorEstimate {
                pressure_rms: 1e-1,
                shear_rms: 1e-1,
                creep_rel: 1e-1,
                overlap_rel: None,
                body_mesh: None,
            },
            detail: vec![0.0, 0.0, 1.0, 0.0],
            open: vec![false; 4],
        };
        let lengths = APriori {
            everywhere: A_PRIORI_LENGTH * 1e-4,
            leading_edge: None,
            stick_ends: Vec::new(),
        };
        actions(&coarse, &cmp, &cmp.estimate, &[0.3], 1e-4, &lengths, shortest)
    }

    /// The grading towards a square-root point stops where the grid's bisection would hold an
    /// element shorter than the bodies' meshes can be cut to; with no element left to halve
    /// there is nothing to do (the run then ends, not reaching the tolerance, instead of cutting
    /// a mesh into elements of zero length).
    #[test]
    fn no_element_is_graded_below_the_shortest_length() {
        let depth = |a: &Action| match *a {
            Action::GradeTowards(_, k) | Action::Split(k) => k,
            _ => 0,
        };
        // Unlimited: graded as deep as a pass grades.
        let free = marked(1e-12).expect("a refinement");
        assert!(depth(&free[2]) > 3, "{:?}", free[2]);
        // Pieces of 1/16 at most (1/2 halved three times, once more in H): depth 2.
        let limited = marked(1.0 / 16.0).expect("a refinement");
        assert_eq!(depth(&limited[2]), 2, "{:?}", limited[2]);
        // Elements of 1/2 whose bisection is 1/4 already: none can be halved.
        assert!(marked(0.2).is_none());
    }
}
