//! A body's boundary mesh cut along a contact grid: each contact element cut where the grid's
//! elements end, the new nodes on the contact surface's circle where it has one
//! ([`cut_along_grid_on`]: a generated body's exact circle, or the circle a mesh file's contact
//! nodes lie on, [`super::smooth`]), else on the element's own quadratic geometry. A circle
//! keeps the surface smooth across the original elements' ends, where two quadratics through
//! points of a circle meet with a slope jump that a fine grid would otherwise resolve as a kink.
//!
//! A contact element of the start mesh spans one or more elements of the grid (the grid is the
//! start mesh's contact grid refined). Its pieces are new quadratic elements whose end nodes lie
//! on the original element's curve at the x of the grid's element ends, and whose mid nodes lie
//! on it at the mid parameter between them, so that the contact grid the cut mesh gives is the
//! grid node for node, for the body the grid was built from and for a matching body across the
//! contact alike (the x of a point fixes it on either curve).
//!
//! **Snapping.** A start-mesh node at an element end that is meant to coincide with a grid edge
//! but lies off it by round-off (Gmsh writes x = −4e-11 for a node of the other body's mesh at
//! x = 0) is moved along its curve onto the grid's x. Both elements that share it move with it,
//! so the mesh stays connected, and the cut mesh's contact nodes are the grid's exactly; without
//! this the round-off of the user's mesh file would, on a deeply graded grid, exceed any
//! tolerance relative to the grid's smallest spacing.
//!
//! **Non-matching meshes.** A mesh whose contact elements end elsewhere than the grid's (a body
//! meshed on its own, across the contact from the body whose mesh set the grid) is first cut at
//! every grid edge its elements hold; the pieces that then share one grid element are merged
//! into one element spanning it, on the curve of the piece that holds the grid element's mid
//! abscissa ([`conformed_to_grid`]). Within the grid the cut mesh's contact elements are the
//! grid's, as a matching mesh's are: its own nodes there are replaced by the error-controlled
//! grid's, and its flexibility needs no interpolation between two sets of nodes. Its contact
//! elements beyond the grid stay as they were.
//!
//! The rest of the mesh is unchanged but for the two elements that meet the contact group at
//! its ends: where the grid's end element was cut much shorter than its neighbour outside the
//! group, that neighbour is halved towards the common node ([`graded_transitions`]), so the
//! element lengths also change by at most `max_ratio` from the contact segment into the rest of
//! the mesh (or by no more than the start mesh had them change there).

use super::geometry::ElementGeometry;
use super::{BoundaryElement, BoundaryMesh, LoadedMesh};
use crate::grid::ContactGrid;
use std::collections::HashMap;

/// Relative distance (of an element's length in x) within which a start-mesh node and a grid
/// edge are the same point: far above a mesh file's round-off (1e-11 of an element), far below
/// any element a grid makes of it (2⁻¹² per pass at most).
pub const SNAP_TOLERANCE: f64 = 1e-6;

/// The mesh with its contact elements cut along the elements of `grid` and their neighbours
/// graded into the rest (module docs), neighbouring lengths within `max_ratio` there. `grid`
/// must run along the contact group of `loaded` (its refinement, or the other body's matching
/// contact grid); a contact element that holds fewer than two of the grid's elements is kept
/// as it is, its end nodes snapped onto the grid's edges.
pub fn cut_along_grid(loaded: &LoadedMesh, grid: &ContactGrid, max_ratio: f64) -> BoundaryMesh {
    cut_along_grid_on(loaded, grid, max_ratio, None)
}

/// A circle [length]: the contact surface of a generated body (exact), or of a mesh file whose
/// contact nodes lie on it (fitted, [`super::smooth::contact_curve`]).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Circle {
    /// Centre (x, y).
    pub centre: [f64; 2],
    /// Radius > 0.
    pub radius: f64,
}

impl Circle {
    /// The point of the circle at the abscissa of `p`, on the side of the centre that `p` is on
    /// (`p` itself where the circle has no point at that abscissa).
    pub fn at_abscissa_of(&self, p: [f64; 2]) -> [f64; 2] {
        let dx = p[0] - self.centre[0];
        let h2 = self.radius * self.radius - dx * dx;
        if h2 <= 0.0 {
            return p;
        }
        let side = if p[1] >= self.centre[1] { 1.0 } else { -1.0 };
        [p[0], self.centre[1] + side * h2.sqrt()]
    }

    /// The angle [rad] of the circle's tangent from +x at its point of abscissa `p[0]` on the
    /// side of the centre that `p` is on ([`Self::at_abscissa_of`]); None where the circle has
    /// no point at that abscissa or its tangent there is vertical. Computed from the centre's
    /// offsets, each to a relative round-off, not from differences of nearby points.
    pub fn slope_angle_at(&self, p: [f64; 2]) -> Option<f64> {
        let on = self.at_abscissa_of(p);
        let dy = on[1] - self.centre[1];
        let dx = on[0] - self.centre[0];
        (dy != 0.0 && dx * dx < self.radius * self.radius).then(|| (-dx / dy).atan())
    }

    /// The round-off [length] of a point placed on the circle by [`Self::at_abscissa_of`]: a
    /// few ulps of the centre's coordinates and the radius it is computed from.
    pub fn placement_round_off(&self) -> f64 {
        let scale = self.centre[0].abs().max(self.centre[1].abs()) + self.radius;
        4.0 * f64::EPSILON * scale
    }
}

/// [`cut_along_grid`] with the new and moved contact nodes placed on `exact` (keeping their
/// abscissae, which the grid fixes) instead of on each element's quadratic, when the body's
/// contact surface is that circle (a generated body's, or the one fitted to a mesh file's
/// contact nodes).
pub fn cut_along_grid_on(
    loaded: &LoadedMesh,
    grid: &ContactGrid,
    max_ratio: f64,
    exact: Option<&Circle>,
) -> BoundaryMesh {
    let mesh = &loaded.mesh;
    let on_surface = |p: [f64; 2]| exact.map_or(p, |c| c.at_abscissa_of(p));
    let group = loaded.contact_group;
    let mut nodes = mesh.nodes.clone();
    let mut elements = Vec::with_capacity(mesh.elements.len());
    for (e, el) in mesh.elements.iter().enumerate() {
        if el.group != group {
            elements.push(el.clone());
            continue;
        }
        let geom = ElementGeometry::from_mesh(mesh, e);
        let (xa, xb) = (geom.nodes[0][0], geom.nodes[1][0]);
        let (lo, hi) = (xa.min(xb), xa.max(xb));
        // Never below twice the distance at which the mesh's contact grid takes two edges as
        // one ([`LoadedMesh::contact_grid`]): no piece is shorter than that.
        let tol = (SNAP_TOLERANCE * (hi - lo)).max(2e-9 * mesh.size());
        let increasing = xa <= xb;
        let (at_lo, at_hi) = if increasing {
            (el.nodes[0], el.nodes[1])
        } else {
            (el.nodes[1], el.nodes[0])
        };
        // The element's ends snapped onto the grid's edges they stand for, and the grid's edges
        // strictly inside it (a body whose contact elements end elsewhere than the grid's, a
        // non-matching mesh, is cut at every grid edge it holds; [`conformed_to_grid`] then
        // merges the pieces that share a grid element).
        let snapped = |x: f64| {
            let k = grid.edges.partition_point(|&e| e < x);
            [k.wrapping_sub(1), k]
                .into_iter()
                .filter_map(|k| grid.edges.get(k).copied())
                .find(|e| (e - x).abs() <= tol)
                .unwrap_or(x)
        };
        let (x_lo, x_hi) = (snapped(lo), snapped(hi));
        let first = grid.edges.partition_point(|&x| x <= x_lo + tol);
        let last = grid.edges.partition_point(|&x| x < x_hi - tol);
        let mut inside = vec![x_lo];
        inside.extend_from_slice(&grid.edges[first..last.max(first)]);
        inside.push(x_hi);
        let (xi_lo, xi_hi) = if increasing { (-1.0, 1.0) } else { (1.0, -1.0) };
        snap(&mut nodes, at_lo, &geom, x_lo, lo);
        snap(&mut nodes, at_hi, &geom, x_hi, hi);
        for v in [at_lo, at_hi] {
            nodes[v] = on_surface(nodes[v]);
        }
        if inside.len() == 2 {
            elements.push(el.clone());
            continue;
        }
        // The cut nodes in increasing x, with their parameters and abscissae: the element's own
        // end nodes at the ends.
        let mut cuts = vec![(at_lo, xi_lo, inside[0])];
        for &x in &inside[1..inside.len() - 1] {
            let xi = parameter_at(&geom, x);
            nodes.push(on_surface(geom.point(xi)));
            cuts.push((nodes.len() - 1, xi, x));
        }
        cuts.push((at_hi, xi_hi, inside[inside.len() - 1]));
        // The mid node halfway in the parameter on a curved element; halfway in x on one that is
        // straight to the round-off of a mesh file, as the grid takes it
        // ([`ContactGrid::from_mapped_edges`]).
        let bow = (geom.nodes[2][0] - 0.5 * (xa + xb)).abs();
        let curved = bow > 1e-9 * (hi - lo) && bow < 0.25 * (hi - lo);
        let mut children: Vec<BoundaryElement> = cuts
            .windows(2)
            .map(|w| {
                let mid = if curved {
                    0.5 * (w[0].1 + w[1].1)
                } else {
                    parameter_at(&geom, 0.5 * (w[0].2 + w[1].2))
                };
                nodes.push(on_surface(geom.point(mid)));
                BoundaryElement {
                    nodes: vec![w[0].0, w[1].0, nodes.len() - 1],
                    group,
                }
            })
            .collect();
        // Keep the element's walking direction (the orientation of its loop).
        if !increasing {
            children.reverse();
            for c in &mut children {
                c.nodes.swap(0, 1);
            }
        }
        elements.extend(children);
    }
    let elements = conformed_to_grid(&mut nodes, elements, group, grid, &on_surface);
    let elements = graded_transitions(mesh, &mut nodes, elements, group, max_ratio);
    BoundaryMesh::new(nodes, elements, mesh.groups.clone(), mesh.source.clone())
}

/// `elements` with the contact pieces that share one grid element merged into one element
/// spanning it (module docs, non-matching meshes): its end nodes the pieces' outer ends (on the
/// grid's edges), its mid node new, on the piece's curve that holds the grid element's mid
/// abscissa, at that abscissa. A grid element the contact group does not cover whole (the
/// group ends inside it) keeps its pieces. A matching mesh has one piece per grid element, and
/// comes back unchanged.
fn conformed_to_grid(
    nodes: &mut Vec<[f64; 2]>,
    elements: Vec<BoundaryElement>,
    group: usize,
    grid: &ContactGrid,
    on_surface: &dyn Fn([f64; 2]) -> [f64; 2],
) -> Vec<BoundaryElement> {
    let (edges, n) = (&grid.edges, grid.n_elements());
    // Each element's x-range, with the nodes at its lower and upper ends.
    let ranges: Vec<(f64, f64, usize, usize)> = elements
        .iter()
        .map(|el| {
            let (a, b) = (el.nodes[0], el.nodes[1]);
            if nodes[a][0] <= nodes[b][0] {
                (nodes[a][0], nodes[b][0], a, b)
            } else {
                (nodes[b][0], nodes[a][0], b, a)
            }
        })
        .collect();
    let slack = |k: usize| 1e-9 * (edges[k + 1] - edges[k]);
    let cell_of = |i: usize| -> Option<usize> {
        let (lo, hi, _, _) = ranges[i];
        let mid = 0.5 * (lo + hi);
        if !(edges[0]..=edges[n]).contains(&mid) {
            return None;
        }
        let k = edges.partition_point(|&e| e <= mid).saturating_sub(1).min(n - 1);
        (lo >= edges[k] - slack(k) && hi <= edges[k + 1] + slack(k)).then_some(k)
    };
    let mut by_cell: HashMap<usize, Vec<usize>> = HashMap::new();
    for i in (0..elements.len()).filter(|&i| elements[i].group == group) {
        if let Some(k) = cell_of(i) {
            by_cell.entry(k).or_default().push(i);
        }
    }
    let mut merged: HashMap<usize, BoundaryElement> = HashMap::new();
    let mut dropped = vec![false; elements.len()];
    for (k, mut pieces) in by_cell.into_iter().filter(|(_, p)| p.len() > 1) {
        pieces.sort_by(|&a, &b| ranges[a].0.total_cmp(&ranges[b].0));
        let (first, last) = (ranges[pieces[0]], ranges[pieces[pieces.len() - 1]]);
        let chained = pieces.windows(2).all(|w| ranges[w[0]].3 == ranges[w[1]].2);
        let covered = (first.0 - edges[k]).abs() <= slack(k) && (last.1 - edges[k + 1]).abs() <= slack(k);
        if !(chained && covered) {
            continue;
        }
        let x_mid = grid.mids[k];
        let holder = pieces
            .iter()
            .copied()
            .find(|&i| (ranges[i].0..=ranges[i].1).contains(&x_mid))
            .unwrap_or(pieces[0]);
        let geom = ElementGeometry::of_element(&elements[holder], nodes);
        let y = geom.point(parameter_at(&geom, x_mid))[1];
        nodes.push(on_surface([x_mid, y]));
        // The walking direction of the pieces (the loop's): from the lower end or the upper.
        let increasing = elements[pieces[0]].nodes[0] == first.2;
        let (start, end) = if increasing {
            (first.2, last.3)
        } else {
            (last.3, first.2)
        };
        let anchor = *pieces.iter().min().expect("two pieces or more");
        for &i in &pieces {
            dropped[i] = true;
        }
        merged.insert(
            anchor,
            BoundaryElement {
                nodes: vec![start, end, nodes.len() - 1],
                group,
            },
        );
    }
    elements
        .into_iter()
        .enumerate()
        .filter_map(|(i, el)| merged.remove(&i).or((!dropped[i]).then_some(el)))
        .collect()
}

/// Moves node `v` (an end of `geom`, at abscissa `x_now`) along the curve
/// onto abscissa `x` when the two differ (module docs, snapping).
fn snap(nodes: &mut [[f64; 2]], v: usize, geom: &ElementGeometry, x: f64, x_now: f64) {
    if x != x_now {
        nodes[v] = geom.point(parameter_at(geom, x));
    }
}

/// The parameter ξ of `geom` at abscissa x, x within (or at round-off outside) its x-range; the
/// linear guess only guards round-off at its ends.
fn parameter_at(geom: &ElementGeometry, x: f64) -> f64 {
    let (xa, xb) = (geom.nodes[0][0], geom.nodes[1][0]);
    geom.parameter_at_x(x)
        .unwrap_or_else(|| (2.0 * (x - xa) / (xb - xa) - 1.0).clamp(-1.0, 1.0))
}

/// `elements` (the cut mesh's, on `nodes`) with every element outside contact group `group`
/// that shares an end node with it graded towards that node ([`graded_transition`]). `original`
/// is the mesh before the cuts: the contact element there at the common node sets the length
/// ratio the start mesh already had, which is kept where it exceeds `max_ratio`.
fn graded_transitions(
    original: &BoundaryMesh,
    nodes: &mut Vec<[f64; 2]>,
    elements: Vec<BoundaryElement>,
    group: usize,
    max_ratio: f64,
) -> Vec<BoundaryElement> {
    let cut_ends = contact_end_lengths(&elements, nodes, group);
    let uncut_ends = contact_end_lengths(&original.elements, &original.nodes, group);
    let mut out = Vec::with_capacity(elements.len());
    for el in &elements {
        let touches = |v: usize| el.group != group && cut_ends.contains_key(&v);
        let shared = match (touches(el.nodes[0]), touches(el.nodes[1])) {
            (true, false) => el.nodes[0],
            (false, true) => el.nodes[1],
            // Not next to the contact group, or between two of its ends: kept as it is.
            _ => {
                out.push(el.clone());
                continue;
            }
        };
        let cut = cut_ends[&shared];
        let uncut = uncut_ends.get(&shared).copied().unwrap_or(cut);
        let own = ElementGeometry::of_element(el, nodes).length();
        // 10 % slack, as in the grid's balance: equal pieces in ξ are nearly equal in length.
        let allowed = (max_ratio * 1.1).max(own / uncut);
        let halvings = (own / (cut * allowed)).log2().ceil().max(0.0) as u32;
        out.extend(graded_transition(el, shared == el.nodes[0], halvings, nodes));
    }
    out
}

/// The length of the contact group's element at each of its end nodes [length]; a node between
/// two contact elements gets the shorter (only the group's two ends meet other elements).
fn contact_end_lengths(elements: &[BoundaryElement], nodes: &[[f64; 2]], group: usize) -> HashMap<usize, f64> {
    let mut ends = HashMap::new();
    for el in elements.iter().filter(|e| e.group == group) {
        let l = ElementGeometry::of_element(el, nodes).length();
        for v in [el.nodes[0], el.nodes[1]] {
            let e = ends.entry(v).or_insert(l);
            *e = f64::min(*e, l);
        }
    }
    ends
}

/// `el` halved `halvings` times towards its start (`towards_start`) or its end, each time the
/// half at that end: `halvings + 1` pieces on the element's own curve, in its walking direction,
/// each at most twice as long as its neighbour (in ξ, exactly).
fn graded_transition(
    el: &BoundaryElement,
    towards_start: bool,
    halvings: u32,
    nodes: &mut Vec<[f64; 2]>,
) -> Vec<BoundaryElement> {
    if halvings == 0 {
        return vec![el.clone()];
    }
    let geom = ElementGeometry::of_element(el, nodes);
    // Fractions of the element from the graded end: 0, 2^-halvings, …, 1/2, 1.
    let mut fractions = vec![0.0];
    fractions.extend((0..halvings).rev().map(|k| 0.5f64.powi(k as i32 + 1)));
    fractions.push(1.0);
    let mut xi: Vec<f64> = fractions
        .iter()
        .map(|&t| if towards_start { -1.0 + 2.0 * t } else { 1.0 - 2.0 * t })
        .collect();
    if !towards_start {
        xi.reverse();
    }
    let mut ends = vec![el.nodes[0]];
    for &x in &xi[1..xi.len() - 1] {
        nodes.push(geom.point(x));
        ends.push(nodes.len() - 1);
    }
    ends.push(el.nodes[1]);
    (0..xi.len() - 1)
        .map(|k| {
            let mut piece = vec![ends[k], ends[k + 1]];
            if el.nodes.len() == 3 {
                nodes.push(geom.point(0.5 * (xi[k] + xi[k + 1])));
                piece.push(nodes.len() - 1);
            }
            BoundaryElement {
                nodes: piece,
                group: el.group,
            }
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::adapt::cells::{Action, DyadicGrid, MAX_NEIGHBOUR_RATIO};
    use crate::mesh::{boundary_loops, validate_and_orient};

    /// The shipped roller of radius 100 on a shaft of radius 10 (meshes/roller_r100_shaft10_A.msh):
    /// 17 contact elements on |x| ≤ 1.25, its free arc graded from there at ratio ≤ 1.04.
    fn roller() -> LoadedMesh {
        shipped("roller_r100_shaft10_A.msh")
    }

    /// The mesh `name` of meshes/, oriented, with its group `contact`.
    fn shipped(name: &str) -> LoadedMesh {
        let path = std::path::Path::new(env!("CARGO_MANIFEST_DIR"))
            .join("meshes")
            .join(name);
        let (mut mesh, _) = crate::mesh::load(&path).unwrap();
        validate_and_orient(&mut mesh).unwrap();
        LoadedMesh::new(path, mesh, Vec::new(), "contact").unwrap()
    }

    /// The edges of `g` inside [lo, hi] and beyond it, to 1e-9 of the interval's length.
    fn edges_inside_and_beyond(g: &ContactGrid, [lo, hi]: [f64; 2]) -> (Vec<f64>, Vec<f64>) {
        let slack = 1e-9 * (hi - lo);
        g.edges.iter().partition(|&&x| x >= lo - slack && x <= hi + slack)
    }

    /// Length ratios of consecutive elements along every loop of `mesh`, largest first.
    fn neighbour_ratios(mesh: &BoundaryMesh) -> Vec<(f64, usize, usize)> {
        let length = |e: usize| ElementGeometry::from_mesh(mesh, e).length();
        let mut ratios = Vec::new();
        for lp in boundary_loops(mesh).unwrap() {
            let els = &lp.elements;
            for k in 0..els.len() {
                let (a, b) = (els[k], els[(k + 1) % els.len()]);
                let (la, lb) = (length(a), length(b));
                ratios.push((la.max(lb) / la.min(lb), a, b));
            }
        }
        ratios.sort_by(|x, y| y.0.total_cmp(&x.0));
        ratios
    }

    /// A grid graded 12 times towards each end of the contact segment (singular points at
    /// its ends) cuts the end contact elements to 1/4096 of their length; the free elements
    /// next to them are halved towards the contact until no two neighbours anywhere differ
    /// by more than the grid's 2 (+10 % slack), on the circle they were on, without a change
    /// of the boundary's length or of the mesh away from the contact's ends.
    #[test]
    fn cut_contact_ends_grade_their_neighbours_into_the_mesh() {
        let loaded = roller();
        let start = DyadicGrid::new(&loaded.contact_grid());
        let n = start.len();
        let (lo, hi) = (start.root().edges[0], start.root().edges[n]);
        let mut action = vec![Action::Keep; n];
        action[0] = Action::GradeTowards(lo, 12);
        action[n - 1] = Action::GradeTowards(hi, 12);
        let cells = start.refined(&action);
        let before = &loaded.mesh;
        let start_ratio = neighbour_ratios(before)[0].0;
        let after = cut_along_grid(&loaded, &cells.grid(), MAX_NEIGHBOUR_RATIO);

        let mut checked = after.clone();
        validate_and_orient(&mut checked).expect("the refined mesh is a valid boundary");
        let worst = neighbour_ratios(&after)[0];
        assert!(
            worst.0 <= (MAX_NEIGHBOUR_RATIO * 1.1).max(start_ratio),
            "elements {} and {} differ by {:.2} (start mesh: {start_ratio:.2})",
            worst.1,
            worst.2,
            worst.0
        );
        // Without the transition the worst ratio is the cut: the neighbour over 1/4096 of a
        // contact element (the test would not see a missing transition otherwise).
        let free = after.group_index("free").unwrap();
        let free_before = before.count_in_group(free);
        let free_after = after.count_in_group(free);
        assert!(
            free_after >= free_before + 2 * 10,
            "{free_before} -> {free_after} free elements"
        );
        // Every node of the free arc stays on the roller's circle (centre (0, 100), R 100).
        for el in after.elements.iter().filter(|e| e.group == free) {
            for &v in &el.nodes {
                let [x, y] = after.nodes[v];
                let r = (x * x + (y - 100.0).powi(2)).sqrt();
                assert!((r - 100.0).abs() < 1e-3, "node {v} at radius {r}");
            }
        }
        // The boundary's length is the same (the pieces lie on the elements' own curves; the
        // quadratic arcs through the new mid nodes differ from the original ones at O(h⁴)).
        let total = |m: &BoundaryMesh| -> f64 {
            (0..m.elements.len())
                .map(|e| ElementGeometry::from_mesh(m, e).length())
                .sum()
        };
        let (l0, l1) = (total(before), total(&after));
        assert!((l1 - l0).abs() < 1e-9 * l0, "length {l0} -> {l1}");
    }

    /// The non-matching roller of cases/carter_051_true_nonmatching.yaml (54 contact elements on
    /// |x| ≤ 1.5, the grid's 21 on |x| ≤ 1.24 from the other roller's mesh) cut along the grid,
    /// as given and graded 6 times towards its ends: inside the grid its contact elements are
    /// the grid's, edge for edge and mid node for mid node to 1e-6 of their length (its own
    /// nodes there gone, each new node on its circle), beyond it its own elements' ends stay,
    /// and the boundary is closed.
    #[test]
    fn a_non_matching_mesh_is_cut_to_the_grids_elements() {
        let own = shipped("roller_r100_shaft10_B_nonmatching.msh");
        let start = DyadicGrid::new(&roller().contact_grid());
        let n = start.len();
        let (lo, hi) = (start.root().edges[0], start.root().edges[n]);
        let mut action = vec![Action::Keep; n];
        action[0] = Action::GradeTowards(lo, 6);
        action[n - 1] = Action::GradeTowards(hi, 6);
        let own_grid = own.contact_grid();
        let beyond = |g: &ContactGrid| edges_inside_and_beyond(g, [lo, hi]).1;
        let own_inside = own_grid.nodes.iter().filter(|&&x| (lo..=hi).contains(&x)).count();
        assert!(own_inside > 3 * 21, "{own_inside} of its own nodes inside the grid");
        for grid in [start.grid(), start.refined(&action).grid()] {
            let cut = cut_along_grid(&own, &grid, MAX_NEIGHBOUR_RATIO);
            let mut checked = cut.clone();
            validate_and_orient(&mut checked).expect("the cut mesh is a valid boundary");
            let loaded = LoadedMesh {
                mesh: cut,
                ..own.clone()
            };
            let cut_grid = loaded.contact_grid();
            let inside: Vec<usize> = (0..cut_grid.n_elements())
                .filter(|&e| cut_grid.edges[e] >= lo - 1e-12 && cut_grid.edges[e + 1] <= hi + 1e-12)
                .collect();
            assert_eq!(inside.len(), grid.n_elements(), "one element per grid element");
            let h = grid.node_spacing();
            for (k, &e) in inside.iter().enumerate() {
                assert!((cut_grid.edges[e] - grid.edges[k]).abs() < 1e-12 * h, "edge {k}");
                // The grid's mid abscissa where pieces were merged; a piece that spans a grid
                // element whole keeps its own curve's mid parameter, as a matching mesh's does.
                let length = grid.edges[k + 1] - grid.edges[k];
                let off = (cut_grid.mids[e] - grid.mids[k]).abs();
                assert!(off < 1e-6 * length, "mid {k}: {off:e} off in {length:e}");
            }
            assert_eq!(beyond(&cut_grid), beyond(&own_grid), "its own edges beyond the grid");
            // Every contact node on the roller's circle (centre (0, −100), R 100).
            for el in loaded.contact_elements() {
                for [x, y] in el.nodes {
                    let r = (x * x + (y + 100.0).powi(2)).sqrt();
                    assert!((r - 100.0).abs() < 1e-9, "contact node at radius {r}");
                }
            }
        }
    }

    /// Rollers meshed at random across the contact (R 100 below it, 4 to 40 contact elements
    /// whose ends fall anywhere on |x| ≤ 1.5), cut along the shipped roller's grid refined at
    /// random (elements kept, split or graded towards a point inside): every cut mesh is a valid
    /// boundary, its contact elements inside the grid are the grid's edge for edge, every node
    /// lies on the curve of the original element that holds it, its own edges beyond the grid
    /// stay, and the contact segment keeps its length.
    #[test]
    fn randomly_meshed_rollers_are_cut_to_randomly_refined_grids() {
        use crate::mesh::build::MeshBuilder;
        // A small linear congruential generator: the same cases on every run.
        let mut state = 0x2545_f491_4f6c_dd1du64;
        let mut uniform = move || {
            state = state
                .wrapping_mul(6_364_136_223_846_793_005)
                .wrapping_add(1_442_695_040_888_963_407);
            (state >> 11) as f64 / (1u64 << 53) as f64
        };
        let (r, centre) = (100.0, [0.0, -100.0]);
        let surface = |x: f64| [x, -r + (r * r - x * x).sqrt()];
        let start = DyadicGrid::new(&roller().contact_grid());
        let n = start.len();
        let (lo, hi) = (start.root().edges[0], start.root().edges[n]);
        for case in 0..40 {
            let elements = 4 + (uniform() * 37.0) as usize;
            let mut ends: Vec<f64> = (1..elements).map(|_| -1.5 + 3.0 * uniform()).collect();
            ends.sort_by(f64::total_cmp);
            ends.dedup_by(|a, b| (*a - *b).abs() < 1e-3);
            let mut b = MeshBuilder::new(true, "random roller");
            b.move_to(surface(1.5));
            for &x in ends.iter().rev().chain([-1.5].iter()) {
                b.arc_to(centre, surface(x), 1, true, 1.0, "contact");
            }
            b.arc_to(centre, [0.0, -2.0 * r], 24, true, 1.26, "free");
            b.arc_to(centre, surface(1.5), 24, true, 1.0 / 1.26, "free");
            b.circle(centre, 10.0, 24, "shaft");
            let mut mesh = b.finish();
            validate_and_orient(&mut mesh).unwrap();
            let own = LoadedMesh::new("random roller", mesh, Vec::new(), "contact").unwrap();
            let actions: Vec<Action> = (0..n)
                .map(|e| match (uniform() * 3.0) as usize {
                    0 => Action::Keep,
                    1 => Action::Split(1 + (uniform() * 3.0) as u32),
                    _ => {
                        let (a, b) = (start.root().edges[e], start.root().edges[e + 1]);
                        Action::GradeTowards(a + (b - a) * uniform(), 1 + (uniform() * 8.0) as u32)
                    }
                })
                .collect();
            let grid = start.refined(&actions).grid();
            let cut = cut_along_grid(&own, &grid, MAX_NEIGHBOUR_RATIO);
            let mut checked = cut.clone();
            validate_and_orient(&mut checked).unwrap_or_else(|e| panic!("case {case}: {e}"));
            let loaded = LoadedMesh {
                mesh: cut,
                ..own.clone()
            };
            let (before, after) = (own.contact_grid(), loaded.contact_grid());
            let (cut_inside, cut_beyond) = edges_inside_and_beyond(&after, [lo, hi]);
            let h = grid.node_spacing();
            let grid_edges = &grid.edges;
            assert_eq!(cut_inside.len(), grid_edges.len(), "case {case}: edges inside the grid");
            for (k, (a, b)) in cut_inside.iter().zip(grid_edges).enumerate() {
                assert!(
                    (a - b).abs() < 1e-12 * h.max(1e-3),
                    "case {case}: edge {k}: {a} against {b}"
                );
            }
            assert_eq!(
                cut_beyond,
                edges_inside_and_beyond(&before, [lo, hi]).1,
                "case {case}: its own edges beyond the grid"
            );
            // Every contact node on the curve of the original element that holds its abscissa.
            let originals: Vec<ElementGeometry> = own.contact_elements().collect();
            for el in loaded.contact_elements() {
                for [x, y] in el.nodes {
                    let on_curve = originals.iter().any(|g| {
                        g.parameter_at_x(x)
                            .is_some_and(|xi| (g.point(xi)[1] - y).abs() < 1e-12 * r)
                    });
                    assert!(on_curve, "case {case}: contact node ({x}, {y}) off its element's curve");
                }
            }
            let length = |m: &LoadedMesh| -> f64 { m.contact_elements().map(|g| g.length()).sum() };
            let (l0, l1) = (length(&own), length(&loaded));
            assert!((l1 - l0).abs() < 1e-9 * l0, "case {case}: contact length {l0} -> {l1}");
        }
    }

    /// A grid that refines only inside the contact leaves every element outside the contact
    /// group as it was: the transition adds nothing where the cut is within the grid's ratio.
    #[test]
    fn interior_refinement_leaves_the_rest_of_the_mesh_alone() {
        let loaded = roller();
        let start = DyadicGrid::new(&loaded.contact_grid());
        let n = start.len();
        let mut action = vec![Action::Keep; n];
        action[n / 2] = Action::Split(3);
        let after = cut_along_grid(&loaded, &start.refined(&action).grid(), MAX_NEIGHBOUR_RATIO);
        let outside = |m: &BoundaryMesh| -> Vec<Vec<[f64; 2]>> {
            m.elements
                .iter()
                .filter(|e| e.group != loaded.contact_group)
                .map(|e| e.nodes.iter().map(|&v| m.nodes[v]).collect())
                .collect()
        };
        assert_eq!(outside(&after), outside(&loaded.mesh));
    }
}
