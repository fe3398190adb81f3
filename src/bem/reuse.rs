//! Reuse of a BEM body's far-field assembly across the passes of an error-controlled grid.
//!
//! Each pass of an error-controlled grid cuts the body's start mesh along a refined contact grid
//! ([`crate::mesh::cuts`]): the contact group's elements are replaced, and the two elements
//! next to its ends may be graded into transitions; every other element (the shaft, the free
//! circle, the rim) stays as it was, node for node. Collocated at an unchanged field node, the
//! entries of H and G that belong to an unchanged field node depend only on the source point and
//! on the unchanged elements that carry that node, so they are the same numbers in every pass.
//! [`FarField`] integrates that block once per run, from the start mesh; [`assemble_reusing`]
//! then integrates per pass only
//!
//! * the whole rows of the changed field nodes (the contact nodes, the transitions' nodes and
//!   the nodes those share with an unchanged element), and
//! * in the rows of the unchanged nodes, the columns of the changed nodes: the elements that
//!   carry a changed node, integrated from every unchanged source point.
//!
//! With N_f unchanged and N_c changed field nodes and E_f unchanged, E_c changed elements, a
//! pass integrates (N_c · (E_f + E_c) + N_f · E_c) source–element pairs instead of
//! (N_f + N_c)(E_f + E_c).
//!
//! **Same numbers.** An element is taken as unchanged only when its three geometric nodes, its
//! field interpolation and its group are bitwise those of a start-mesh element away from the
//! contact, and a field node only when every element carrying it is unchanged and its position
//! and normal are bitwise the start's. Each entry is then accumulated from the same element
//! integrals in the same order as [`BemModel::assemble`] accumulates it, and the rigid-body
//! diagonal is summed over the whole row afterwards as there, so H and G are bitwise those of a
//! build from scratch (`reused_assembly_is_the_assembly_from_scratch` below checks it). Anything
//! that fails these checks (a kernel of another length scale, because the cut moved the mesh's
//! bounding box, or another material) is integrated afresh.
//!
//! **Why the factorisation is not reused.** Block elimination with the unchanged block A_ff
//! (n_f unknowns) factorised once solves the pass's A x = [b₀, G_c] (n = n_f + n_c unknowns,
//! k = 1 + 2m right-hand sides) as Y = A_ff⁻¹[A_fc, R_f] (2 n_f² (n_c + k) flops), the Schur
//! complement S = A_cc − A_cf Y (2 n_c n_f (n_c + k)), its LU and solve ((2/3) n_c³ + 2 n_c² k)
//! and the back-substitution X_f (2 n_f n_c k). Against one LU of the whole system and its
//! solve, (2/3) n³ + 2 n² k, that saves (2/3) n_f³ flops and nothing else: with n_f = 700,
//! n_c = 1500 and k = 1500 (fig14_true_geometry's last pass at tolerance 1e-4) 0.23 of 21.6
//! GFlop. And A_ff is not the same matrix from pass to pass: the rigid-body diagonal of an
//! unchanged row, H_ii = −Σ_{j≠i} H_ij, sums over the changed columns too, whose integrals
//! change with the cut geometry (its mid nodes) at the level of the quadrature tolerance, so a
//! cached factor would need a correction step costing another 2 n_f² (n_c + k) flops — more
//! than it saves. The solve therefore stays one partial-pivoting LU of the pass's system.

use super::assemble::{Assembly, BemModel};
use super::discretise::Discretisation;
use super::fundamental::FundamentalSolution;
use super::integrate::{element_integrals, ElementIntegrals, SourcePosition};
use crate::quadrature::Quadrature;
use rayon::prelude::*;
use std::collections::HashMap;
use std::sync::atomic::{AtomicBool, Ordering};
use std::sync::{Arc, OnceLock};

/// An element's identity: the bits of its three geometric nodes, of its field interpolation's
/// end-node parameters, and its group.
type ElementKey = ([u64; 6], [u64; 2], usize);

fn element_key(model: &BemModel, e: usize) -> ElementKey {
    let d = &model.discretisation;
    let n = &d.geometry[e].nodes;
    let f = &d.interpolation[e];
    (
        [
            n[0][0].to_bits(),
            n[0][1].to_bits(),
            n[1][0].to_bits(),
            n[1][1].to_bits(),
            n[2][0].to_bits(),
            n[2][1].to_bits(),
        ],
        [f.start.to_bits(), f.end.to_bits()],
        model.mesh.elements[e].group,
    )
}

/// The number of elements carrying each field node.
fn carriers(d: &Discretisation) -> Vec<usize> {
    let mut count = vec![0; d.n_nodes()];
    for ids in &d.element_nodes {
        let mut seen: Vec<usize> = ids.to_vec();
        seen.sort_unstable();
        seen.dedup();
        for k in seen {
            count[k] += 1;
        }
    }
    count
}

/// The unchanged part of a BEM body's start mesh (module docs): its elements away from the
/// contact group and its field nodes carried only by them, with the rows of H and G collocated
/// at those nodes restricted to their columns.
#[derive(Debug)]
pub struct FarField {
    /// Start-mesh element of each unchanged element's identity.
    elements: HashMap<ElementKey, usize>,
    /// The start mesh's discretisation (positions, normals, element → node map).
    start: Discretisation,
    /// Number of elements carrying each start field node.
    start_carriers: Vec<usize>,
    /// Index in the blocks below of each start field node, if it is unchanged.
    index: Vec<Option<usize>>,
    /// The kernel's length scale ℓ [length] and the material (E, ν) the blocks were integrated
    /// with, as bits.
    kernel_bits: [u64; 3],
    /// Per unchanged node p, its rows 2p, 2p + 1 of H [-] then of G [length/stress] restricted to
    /// the unchanged nodes' columns (4 × 2 N_f values, row after row; the rigid-body diagonal is
    /// left out, it is summed per pass). Row by row, so that a pass copies them in the order
    /// it lays out its own rows.
    rows: Vec<Vec<f64>>,
    /// Wall time of the block's integration [s].
    pub assembly_s: f64,
}

impl FarField {
    /// The unchanged part of `start` (the model of the uncut start mesh): its elements outside
    /// the contact groups that share no end node with a contact element (those are the ones
    /// [`crate::mesh::cuts::cut_along_grid`] may grade), the field nodes carried only by them,
    /// and their block of H and G, integrated in parallel over the source nodes.
    pub fn new(start: &BemModel) -> Self {
        let t0 = std::time::Instant::now();
        let mesh = &start.mesh;
        let d = &start.discretisation;
        let contact = |e: usize| start.conditions[mesh.elements[e].group].is_contact();
        let mut contact_node = vec![false; mesh.nodes.len()];
        for (e, el) in mesh.elements.iter().enumerate() {
            if contact(e) {
                for &v in &el.nodes {
                    contact_node[v] = true;
                }
            }
        }
        let unchanged: Vec<bool> = (0..mesh.elements.len())
            .map(|e| !contact(e) && mesh.elements[e].nodes[..2].iter().all(|&v| !contact_node[v]))
            .collect();
        let mut carried_elsewhere = vec![false; d.n_nodes()];
        for (e, ids) in d.element_nodes.iter().enumerate() {
            if !unchanged[e] {
                for &k in ids {
                    carried_elsewhere[k] = true;
                }
            }
        }
        let mut index = vec![None; d.n_nodes()];
        let mut fixed = Vec::new();
        for k in 0..d.n_nodes() {
            if !carried_elsewhere[k] {
                index[k] = Some(fixed.len());
                fixed.push(k);
            }
        }
        let elements: HashMap<ElementKey, usize> = (0..mesh.elements.len())
            .filter(|&e| unchanged[e])
            .map(|e| (element_key(start, e), e))
            .collect();
        let unchanged_elements: Vec<usize> = (0..mesh.elements.len()).filter(|&e| unchanged[e]).collect();
        let nf = 2 * fixed.len();
        let kernel = start.kernel();
        let quadrature = Quadrature::new(start.options.quadrature());
        // Rows 2p, 2p+1 of H then of G over the unchanged columns, accumulated element by
        // element in the order BemModel::assemble accumulates them.
        let rows: Vec<Vec<f64>> = fixed
            .par_iter()
            .map(|&i| {
                let mut rows = vec![0.0; 4 * nf];
                for &e in &unchanged_elements {
                    let ids = &d.element_nodes[e];
                    let ints = integrals_at(&quadrature, kernel, d, e, i);
                    for (a, &col) in ids.iter().enumerate() {
                        // A node shared with a changed element is a changed column: integrated
                        // per pass.
                        let Some(q) = index[col] else { continue };
                        ints.add_node_to_rows(a, &mut rows, nf, q);
                    }
                }
                rows
            })
            .collect();
        Self {
            elements,
            start_carriers: carriers(d),
            start: d.clone(),
            index,
            kernel_bits: kernel_bits(start),
            rows,
            assembly_s: t0.elapsed().as_secs_f64(),
        }
    }

    /// The number of unchanged field nodes.
    pub fn n_nodes(&self) -> usize {
        self.rows.len()
    }

    /// For each field node of `model` (a cut of the start mesh), its index in the blocks if it
    /// is an unchanged node (module docs: all its carrying elements unchanged, its position and
    /// normal the start's), else None; all None when the model's kernel is not the start's.
    pub fn node_map(&self, model: &BemModel) -> Vec<Option<usize>> {
        let d = &model.discretisation;
        let mut map = vec![None; d.n_nodes()];
        if kernel_bits(model) != self.kernel_bits {
            return map;
        }
        let matched: Vec<Option<usize>> = (0..d.geometry.len())
            .map(|e| self.elements.get(&element_key(model, e)).copied())
            .collect();
        let mut all_matched = vec![true; d.n_nodes()];
        for (e, ids) in d.element_nodes.iter().enumerate() {
            if matched[e].is_none() {
                for &k in ids {
                    all_matched[k] = false;
                }
            }
        }
        let count = carriers(d);
        let mut taken = vec![false; self.n_nodes()];
        for (k, node) in d.nodes.iter().enumerate() {
            let (e, local) = node.element;
            let Some(e0) = matched[e] else { continue };
            let k0 = self.start.element_nodes[e0][local];
            let Some(p) = self.index[k0] else { continue };
            let start = &self.start.nodes[k0];
            let same = all_matched[k]
                && count[k] == self.start_carriers[k0]
                && !taken[p]
                && bits(start.position) == bits(node.position)
                && bits(start.normal) == bits(node.normal)
                && start.group == node.group;
            if same {
                taken[p] = true;
                map[k] = Some(p);
            }
        }
        map
    }
}

fn bits(p: [f64; 2]) -> [u64; 2] {
    [p[0].to_bits(), p[1].to_bits()]
}

fn kernel_bits(model: &BemModel) -> [u64; 3] {
    [
        model.kernel().length_scale.to_bits(),
        model.material.young.to_bits(),
        model.material.poisson.to_bits(),
    ]
}

/// Where source node `i` lies relative to element `e`, as [`BemModel::assemble`] takes it.
/// The integrals over element `e` of `d` with the source at field node `i`.
fn integrals_at<K: FundamentalSolution>(
    quadrature: &Quadrature,
    kernel: &K,
    d: &Discretisation,
    e: usize,
    i: usize,
) -> ElementIntegrals {
    element_integrals(
        quadrature,
        kernel,
        &d.geometry[e],
        &d.interpolation[e],
        d.nodes[i].position,
        source_position(d, e, i),
    )
}

fn source_position(d: &Discretisation, e: usize, i: usize) -> SourcePosition {
    match d.element_nodes[e].iter().position(|&k| k == i) {
        Some(local) => SourcePosition::OnNode {
            xi: d.interpolation[e].node_coordinates()[local],
            local,
        },
        None => SourcePosition::Off,
    }
}

/// H and G of `model`, a cut of the start mesh `far` was built from, with the unchanged block
/// taken from `far` (module docs): bitwise the matrices of [`BemModel::assemble`].
pub fn assemble_reusing(model: &BemModel, far: &FarField) -> Assembly {
    let d = &model.discretisation;
    let n = d.n_nodes();
    let m = 2 * n;
    let map = far.node_map(model);
    let kernel = model.kernel();
    let quadrature = Quadrature::new(model.options.quadrature());
    // The elements that carry a changed node: the only ones an unchanged row integrates.
    let changed_elements: Vec<usize> = (0..d.geometry.len())
        .filter(|&e| d.element_nodes[e].iter().any(|&k| map[k].is_none()))
        .collect();
    log::debug!(
        "BEM assembly: {} of {} field nodes and {} of {} elements unchanged from the start mesh",
        map.iter().filter(|q| q.is_some()).count(),
        n,
        d.geometry.len() - changed_elements.len(),
        d.geometry.len()
    );
    let fixed_columns: Vec<(usize, usize)> = map.iter().enumerate().filter_map(|(l, q)| q.map(|q| (l, q))).collect();
    super::assemble::assemble_by_rows(n, |i| {
        let Some(p) = map[i] else {
            return model.collocation_rows(kernel, i, &quadrature);
        };
        let mut rows = vec![0.0; 4 * m];
        let (cached, nf) = (&far.rows[p], 2 * far.n_nodes());
        for r in 0..4 {
            for &(l, q) in &fixed_columns {
                for jc in 0..2 {
                    rows[r * m + 2 * l + jc] = cached[r * nf + 2 * q + jc];
                }
            }
        }
        for &e in &changed_elements {
            let ints = integrals_at(&quadrature, kernel, d, e, i);
            for (a, &col) in d.element_nodes[e].iter().enumerate() {
                if map[col].is_none() {
                    ints.add_node_to_rows(a, &mut rows, m, col);
                }
            }
        }
        super::assemble::rigid_body_diagonal(&mut rows, i, n);
        rows
    })
}

/// A [`FarField`] built once and shared by the setups of one run (the setup of the start mesh
/// and every setup that follows a refined grid from it, [`crate::body::bem::setup`]): cloning
/// the cache shares it. A cache made with `reuse` false (`contact.grid.reuse_far_field: false`)
/// never hands one out: every grid is assembled afresh, with the same results to the element
/// integrals' accuracy.
#[derive(Clone)]
pub struct FarFieldCache {
    /// The far field, once built.
    field: Arc<OnceLock<Arc<FarField>>>,
    /// Set while the first use is still to be refused ([`Self::for_another_mesh`]).
    skip_first_use: Arc<AtomicBool>,
    /// Whether the cache hands out a far field at all.
    reuse: bool,
}

impl Default for FarFieldCache {
    fn default() -> Self {
        Self::new(true)
    }
}

impl std::fmt::Debug for FarFieldCache {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self.field.get() {
            Some(far) => write!(f, "FarFieldCache({} unchanged nodes)", far.n_nodes()),
            None if !self.reuse => write!(f, "FarFieldCache(off)"),
            None => write!(f, "FarFieldCache(empty)"),
        }
    }
}

impl FarFieldCache {
    /// An empty cache that builds the far field on its first use, or, with `reuse` false,
    /// never gives one.
    pub fn new(reuse: bool) -> Self {
        Self {
            field: Default::default(),
            skip_first_use: Default::default(),
            reuse,
        }
    }

    /// A cache of its own for a mesh whose far field differs from this one's, with this one's
    /// `reuse`, that gives no far field to its first use and builds it on the second: for a
    /// mesh condensed once as a rule (the check of a body's mesh, src/adapt/body_mesh.rs),
    /// whose far field, integrated apart and copied into H and G, would cost two matrices of
    /// the system's size beside them and a second pass over the block, for no reuse.
    pub fn for_another_mesh(&self) -> Self {
        Self {
            field: Default::default(),
            skip_first_use: Arc::new(AtomicBool::new(true)),
            reuse: self.reuse,
        }
    }

    /// Whether the cache hands out far fields (`contact.grid.reuse_far_field`).
    pub fn reuses(&self) -> bool {
        self.reuse
    }

    /// Whether the far field has been built (by the first setup that needed it).
    pub fn is_built(&self) -> bool {
        self.field.get().is_some()
    }

    /// The far field of the start mesh, built by `start` on first use, or on the second for a
    /// cache [`Self::for_another_mesh`] (None when the cache does not reuse, and for that
    /// first use).
    pub fn get_or_build(&self, start: impl FnOnce() -> Option<BemModel>) -> Option<Arc<FarField>> {
        if !self.reuse || self.skip_first_use.swap(false, Ordering::Relaxed) {
            return None;
        }
        if let Some(far) = self.field.get() {
            return Some(far.clone());
        }
        let far = Arc::new(FarField::new(&start()?));
        Some(self.field.get_or_init(|| far).clone())
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::adapt::cells::{Action, DyadicGrid};
    use crate::bem::{condense, condense_reusing, BemOptions};
    use crate::material::Elastic;
    use crate::mesh::cuts::cut_along_grid;
    use crate::mesh::LoadedMesh;

    /// The aluminium roller R 150 on a rigid shaft of 15 of cases/fig14_true_geometry.yaml.
    fn roller() -> LoadedMesh {
        let path = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("meshes/roller_r150_shaft15_A.msh");
        let (mut mesh, notices) = crate::mesh::load(&path).unwrap();
        crate::mesh::validate_and_orient(&mut mesh).unwrap();
        LoadedMesh::new(path, mesh, notices, "contact").unwrap()
    }

    fn model(mesh: crate::mesh::BoundaryMesh) -> BemModel {
        model_of(mesh, Elastic::new(60_260.0, 0.31))
    }

    fn model_of(mesh: crate::mesh::BoundaryMesh, material: Elastic) -> BemModel {
        BemModel::new(
            mesh,
            material,
            crate::bem::fixed_shaft_roller_conditions(),
            BemOptions::default(),
        )
        .unwrap()
    }

    /// The start mesh cut along a grid split in its middle and graded 8 times towards both
    /// contact ends (so the free elements next to the contact are graded into transitions).
    fn cut(start: &LoadedMesh) -> crate::mesh::BoundaryMesh {
        let grid = DyadicGrid::new(&start.contact_grid());
        let n = grid.len();
        let (lo, hi) = (grid.root().edges[0], grid.root().edges[n]);
        let mut action = vec![Action::Keep; n];
        action[0] = Action::GradeTowards(lo, 8);
        action[n - 1] = Action::GradeTowards(hi, 8);
        action[n / 2] = Action::Split(2);
        cut_along_grid(start, &grid.refined(&action).grid(), 2.0)
    }

    /// On a cut mesh, the flexibility condensed with the start mesh's far field reused is the
    /// one condensed from scratch (relative difference below 1e-10; by construction the
    /// matrices are bitwise equal), and the far field covers most of the body, so the reuse
    /// is not vacuous.
    #[test]
    fn reused_flexibility_is_the_flexibility_from_scratch() {
        let start = roller();
        let far = FarField::new(&model(start.mesh.clone()));
        let cut_model = model(cut(&start));
        let map = far.node_map(&cut_model);
        let reused_nodes = map.iter().filter(|q| q.is_some()).count();
        assert!(
            reused_nodes > 300 && reused_nodes < cut_model.discretisation.n_nodes() - 100,
            "{reused_nodes} of {} field nodes reused",
            cut_model.discretisation.n_nodes()
        );
        let scratch = condense(&cut_model, "contact").unwrap();
        let reused = condense_reusing(&cut_model, "contact", Some(&far)).unwrap();
        let scale = scratch.matrix().norm_max();
        let diff = (reused.matrix() - scratch.matrix()).norm_max();
        assert!(
            diff <= 1e-10 * scale,
            "flexibility differs by {diff:.3e} of {scale:.3e}"
        );
        let strain =
            (reused.surface_strain(&cut_model).unwrap() - scratch.surface_strain(&cut_model).unwrap()).norm_max();
        assert!(
            strain <= 1e-10 * scratch.surface_strain(&cut_model).unwrap().norm_max(),
            "surface strain differs by {strain:.3e}"
        );
    }

    /// The assembled H and G themselves are bitwise those of a build from scratch, on the cut
    /// mesh and on the start mesh itself (the first pass of an error-controlled grid).
    #[test]
    fn reused_assembly_is_the_assembly_from_scratch() {
        let start = roller();
        let start_model = model(start.mesh.clone());
        let far = FarField::new(&start_model);
        for m in [start_model, model(cut(&start))] {
            let scratch = m.assemble();
            let reused = assemble_reusing(&m, &far);
            assert!(reused.h == scratch.h, "H differs");
            assert!(reused.g == scratch.g, "G differs");
        }
    }

    /// A model of another material than the far field's integrates everything afresh.
    #[test]
    fn another_kernel_reuses_nothing() {
        let start = roller();
        let far = FarField::new(&model(start.mesh.clone()));
        let other = model_of(cut(&start), Elastic::new(210_000.0, 0.3));
        assert!(far.node_map(&other).iter().all(Option::is_none));
    }
}
