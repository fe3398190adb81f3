//! A contact's size and peak pressure from a body's own compliance: for the models whose
//! contact the Hertz estimates of an elastic half-plane misjudge (a cover bonded to a rigid
//! core is stiffer than the half-plane of its material, by a factor that grows as the cover
//! thins), the estimates of a scene ask the body ([`super::setup::BodySetup::own_contact_scales`]).
//!
//! The scales come from the frictionless normal contact of a rigid cylinder of radius R* on the
//! body, solved on a coarse grid by an active-set iteration: on the loaded nodes
//! Σ_j H_ij p_j = δ − x_i²/2R* with Σ_i w_i p_i = P (w the grid's integration weights), no
//! pressure elsewhere; nodes with a negative pressure leave the set, nodes the cylinder
//! penetrates join it, until neither happens (the discrete Signorini conditions). Twice: on the
//! Hertz contact and again on the contact found, so that its half-width is read on nodes a few
//! percent of it apart.

use super::setup::{ContactScales, NormalLoad};
use super::Side;
use crate::grid::{ContactGrid, ElementKind};
use crate::linalg::{lu_solve_in_place, mat_vec};
use faer::Mat;

/// Elements of each of the two grids: 30 quadratic elements (90 nodes) over 2.6 half-widths
/// read the half-width to about 1.5 % of itself, in a few milliseconds.
const ELEMENTS: usize = 30;

/// Grid half-length over the half-width it is built around: the Hertz one may be only just
/// above the true one (a thick cover), the second grid's estimate within its spacing.
const EXTENT: f64 = 1.3;

/// The half-width and peak pressure of the frictionless contact of a rigid cylinder of signed
/// effective radius `radius` [length] pressed by `load` on a body whose normal
/// flexibility at a grid's nodes `normal_flexibility` gives (H_p of
/// [`super::Flexibility`], [length/stress]), starting from the half-width `first_guess`
/// [length] (the Hertz one). None when no contact is found (a force or radius out of range).
pub fn normal_contact_scales(
    normal_flexibility: &dyn Fn(&ContactGrid) -> Mat<f64>,
    load: NormalLoad,
    radius: f64,
    first_guess: f64,
) -> Option<ContactScales> {
    let (NormalLoad::Force(v) | NormalLoad::Overlap(v)) = load;
    if !(v > 0.0 && first_guess > 0.0 && v.is_finite() && first_guess.is_finite()) {
        return None;
    }
    let first = scales_on(normal_flexibility, load, radius, first_guess)?;
    scales_on(normal_flexibility, load, radius, first.half_width)
}

/// [`normal_contact_scales`] on the uniform grid [−EXTENT·a, EXTENT·a] around the contact's
/// centre (0).
fn scales_on(
    normal_flexibility: &dyn Fn(&ContactGrid) -> Mat<f64>,
    load: NormalLoad,
    radius: f64,
    half_width: f64,
) -> Option<ContactScales> {
    let l = EXTENT * half_width;
    let grid = ContactGrid::uniform(ElementKind::DiscontinuousQuadratic, ELEMENTS, -l, l);
    let h = normal_flexibility(&grid);
    let p = signorini_pressure(&h, &grid, load, radius)?;
    let loaded: Vec<f64> = grid
        .nodes
        .iter()
        .zip(&p)
        .filter(|(_, p)| **p > 0.0)
        .map(|(x, _)| *x)
        .collect();
    let (lo, hi) = (loaded.first()?, loaded.last()?);
    // The edges lie between the outermost loaded nodes and their unloaded neighbours: half a
    // spacing out.
    let half_width = 0.5 * (hi - lo) + 0.5 * grid.node_spacing();
    let peak_pressure = p.iter().copied().fold(0.0, f64::max);
    Some(ContactScales {
        half_width,
        peak_pressure,
        normal_force: grid.integrate(&p),
    })
}

/// The nodal pressures [stress] of the frictionless contact of a rigid cylinder (module docs),
/// None if the active set does not settle. Under a given overlap δ the approach is known and
/// the force row drops out.
fn signorini_pressure(h: &Mat<f64>, grid: &ContactGrid, load: NormalLoad, radius: f64) -> Option<Vec<f64>> {
    let m = grid.n_nodes();
    let profile: Vec<f64> = grid.nodes.iter().map(|x| x * x / (2.0 * radius)).collect();
    let mut active = vec![true; m];
    for _ in 0..4 * m {
        let ids: Vec<usize> = (0..m).filter(|&i| active[i]).collect();
        if ids.is_empty() {
            return None;
        }
        let n = ids.len();
        // Force:   [H_AA  −1] [p_A]   [−x²/2R]      overlap:  H_AA p_A = δ − x²/2R
        //          [w_Aᵀ   0] [ δ ] = [   P  ]
        let k = n + usize::from(matches!(load, NormalLoad::Force(_)));
        let mut a = Mat::<f64>::zeros(k, k);
        let mut rhs = Mat::<f64>::zeros(k, 1);
        for (r, &i) in ids.iter().enumerate() {
            for (c, &j) in ids.iter().enumerate() {
                a[(r, c)] = h[(i, j)];
            }
            rhs[(r, 0)] = -profile[i];
            match load {
                NormalLoad::Force(_) => {
                    a[(r, n)] = -1.0;
                    a[(n, r)] = grid.weights[i];
                }
                NormalLoad::Overlap(delta) => rhs[(r, 0)] += delta,
            }
        }
        if let NormalLoad::Force(force) = load {
            rhs[(n, 0)] = force;
        }
        lu_solve_in_place(a, rhs.as_mut());
        let mut p = vec![0.0; m];
        for (r, &i) in ids.iter().enumerate() {
            p[i] = rhs[(r, 0)];
        }
        let approach = match load {
            NormalLoad::Force(_) => rhs[(n, 0)],
            NormalLoad::Overlap(delta) => delta,
        };
        if p.iter().any(|v| !v.is_finite()) {
            return None;
        }
        let mut changed = false;
        // Tension: released.
        for &i in &ids {
            if p[i] < 0.0 {
                active[i] = false;
                changed = true;
            }
        }
        if !changed {
            // Penetration by the cylinder where nothing presses: loaded.
            let w = mat_vec(h, &p);
            for i in 0..m {
                if !active[i] && approach - profile[i] - w[i] > 1e-12 * approach.abs() {
                    active[i] = true;
                    changed = true;
                }
            }
        }
        if !changed {
            return Some(p);
        }
    }
    None
}

/// The normal flexibility H_p of a body model on a grid, seen from side B (the pressure block
/// does not depend on the side).
pub fn pressure_block(model: &dyn super::BodyModel) -> impl Fn(&ContactGrid) -> Mat<f64> + '_ {
    move |grid| model.flexibility(grid, Side::B).hp
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::analytic::{hertz_half_width, hertz_peak_pressure};
    use crate::body::half_space::HalfSpace;
    use crate::material::Elastic;

    /// On an elastic half-plane the scales are Hertz's: a and p0 within the grid's reading
    /// (half a node spacing of 2.6a/90 in a, a few 1e-3 in p0 at the nodes).
    #[test]
    fn on_a_half_plane_the_scales_are_hertzs() {
        let steel = Elastic {
            young: 210_000.0,
            poisson: 0.3,
        };
        let body = HalfSpace::new(steel, 50.0);
        let (force, radius) = (1000.0, 50.0);
        let e_star = 1.0 / steel.plane_strain_compliance();
        let a = hertz_half_width(force, radius, e_star);
        let p0 = hertz_peak_pressure(force, a);
        // A first guess 30 % off: the second grid is built on the first's answer.
        let s = normal_contact_scales(&pressure_block(&body), NormalLoad::Force(force), radius, 1.3 * a)
            .expect("a contact");
        assert!((s.half_width / a - 1.0).abs() < 0.02, "a {} against {a}", s.half_width);
        assert!(
            (s.peak_pressure / p0 - 1.0).abs() < 0.01,
            "p0 {} against {p0}",
            s.peak_pressure
        );
    }
}
