//! Collocation assembly of H u = G t, boundary conditions, and the dense solve.
//!
//! Row pair (2i, 2i+1) of H and G is the BIE collocated at field node i (Brebbia–Telles–Wrobel
//! Eq. 4.13): H_ij = ∫ T* N_j dΓ (+ the free term on the diagonal), G_ij = ∫ U* N_j dΓ. The
//! 2 × 2 diagonal blocks of H (free term + Cauchy principal value) come from rigid-body
//! translation, H_ii = −Σ_{j≠i} H_ij (their §4.3), valid for bounded bodies. Rows are
//! assembled in parallel (rayon).
//!
//! With the boundary conditions each of the 2N components has one known and one unknown
//! value; moving the known ones to the right gives A x = b, solved by LU with partial pivoting
//! (faer). Unknown tractions are scaled by G/L (shear modulus over body size) so that the
//! columns of A have comparable magnitudes.

use super::discretise::{Discretisation, FieldNode};
use super::fundamental::FundamentalSolution;
use super::integrate::{element_integrals, SourcePosition};
use super::kernel::Kelvin;
use super::{BemError, BoundaryCondition, Component};
use crate::material::Elastic;
use crate::mesh::{boundary_loops, validate_and_orient, BoundaryMesh};
use crate::quadrature::{Quadrature, QuadratureOptions};
use faer::Mat;
use rayon::prelude::*;

/// Options of the BEM discretisation and integration.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct BemOptions {
    /// Largest tangent jump at an element junction that still counts as smooth [degrees]; sharper junctions are corners with discontinuous element ends. Default = 15.
    pub corner_angle_deg: f64,
    /// Length ℓ in the logarithm of U* [length] (see [`super::kernel`]); `None` takes 4 × the mesh's bounding-box diagonal. Default = None.
    pub log_length_scale: Option<f64>,
    /// Target relative accuracy of the regular and nearly singular element integrals. Default = 1e-12.
    pub quadrature_tolerance: f64,
    /// Smallest Bernstein-ellipse parameter of the nearest kernel singularity accepted without halving the integration interval. Default = 3.
    pub min_ellipse: f64,
    /// Fewest Gauss points per (sub)interval. Default = 4.
    pub min_gauss_points: usize,
    /// Most Gauss points per (sub)interval. Default = 24.
    pub max_gauss_points: usize,
    /// Deepest interval halving for nearly singular integrals. Default = 30.
    pub max_subdivision_depth: usize,
    /// Gauss–Legendre points on each side of the source in a singular element. Default = 16.
    pub singular_gauss_points: usize,
    /// Log-weighted Gauss points on each side of the source in a singular element. Default = 12.
    pub log_gauss_points: usize,
    /// Smallest ratio of the smallest to the largest LU pivot before the system is declared singular; a last resort, since rigid-body motions are caught before the solve (an incompressible body's loop pressure mode lowers the ratio like h³, to ~1e-8 at 128 elements per loop). Default = 1e-13.
    pub min_pivot_ratio: f64,
}

impl Default for BemOptions {
    fn default() -> Self {
        let q = QuadratureOptions::default();
        Self {
            corner_angle_deg: 15.0,
            log_length_scale: None,
            quadrature_tolerance: q.tolerance,
            min_ellipse: q.min_ellipse,
            min_gauss_points: q.min_points,
            max_gauss_points: q.max_points,
            max_subdivision_depth: q.max_depth,
            singular_gauss_points: q.singular_points,
            log_gauss_points: q.log_points,
            min_pivot_ratio: 1e-13,
        }
    }
}

impl BemOptions {
    /// The element-integration controls.
    pub fn quadrature(&self) -> QuadratureOptions {
        QuadratureOptions {
            tolerance: self.quadrature_tolerance,
            min_ellipse: self.min_ellipse,
            min_points: self.min_gauss_points,
            max_points: self.max_gauss_points,
            max_depth: self.max_subdivision_depth,
            singular_points: self.singular_gauss_points,
            log_points: self.log_gauss_points,
        }
    }
}

/// Sets the 2 × 2 diagonal block of H in `rows` (rows 2i, 2i+1 of H then of G for collocation
/// at node i of `n`, as [`BemModel::collocation_rows`] lays them out) from rigid-body
/// translation: u = e_j gives zero traction, so Σ_k H_(i,k) = 0 for each j.
pub(crate) fn rigid_body_diagonal(rows: &mut [f64], i: usize, n: usize) {
    let m = 2 * n;
    for ic in 0..2 {
        for jc in 0..2 {
            let row = &rows[ic * m..(ic + 1) * m];
            let off: f64 = (0..n).filter(|&k| k != i).map(|k| row[2 * k + jc]).sum();
            rows[ic * m + 2 * i + jc] = -off;
        }
    }
}

/// A point constraint: the displacement component `component` (0 = x, 1 = y) of field node
/// `node` is prescribed to `value` [length]; its traction becomes an unknown. Used to remove
/// the rigid-body motion of a body loaded by tractions only.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Pin {
    /// Field node index.
    pub node: usize,
    /// 0 for x, 1 for y.
    pub component: usize,
    /// Prescribed displacement [length].
    pub value: f64,
}

/// Boundary values at every field node after a solve (global axes).
#[derive(Debug, Clone, PartialEq)]
pub struct BemSolution {
    /// Displacement u [length] per field node.
    pub displacement: Vec<[f64; 2]>,
    /// Traction t = σ·n [stress] per field node, n out of the material.
    pub traction: Vec<[f64; 2]>,
}

/// Collocation points whose rows [`assemble_by_rows`] makes at a time.
const ROW_CHUNK: usize = 64;

/// H and G (2n × 2n) from the rows of each of the `n` collocation points (`rows(i)`: rows 2i,
/// 2i+1 of H then of G, 4 × 2n values, as [`BemModel::collocation_rows`] gives them), made in
/// parallel a chunk of points at a time and copied in: the rows of all points at once would
/// double the memory of H and G at the assembly's end (a body's largest matrices).
pub(crate) fn assemble_by_rows(n: usize, rows: impl Fn(usize) -> Vec<f64> + Sync) -> Assembly {
    let m = 2 * n;
    let mut h = Mat::zeros(m, m);
    let mut g = Mat::zeros(m, m);
    for first in (0..n).step_by(ROW_CHUNK) {
        let chunk: Vec<Vec<f64>> = (first..n.min(first + ROW_CHUNK)).into_par_iter().map(&rows).collect();
        // Column by column, the chunk's rows are contiguous in each matrix.
        for c in 0..m {
            for (k, point) in chunk.iter().enumerate() {
                for r in 0..2 {
                    h[(2 * (first + k) + r, c)] = point[r * m + c];
                    g[(2 * (first + k) + r, c)] = point[(2 + r) * m + c];
                }
            }
        }
    }
    Assembly { h, g }
}

/// The collocation matrices of a model.
#[derive(Debug, Clone)]
pub struct Assembly {
    /// H (2N × 2N) [-], rigid-body diagonal included.
    pub h: Mat<f64>,
    /// G (2N × 2N) [length/stress].
    pub g: Mat<f64>,
}

/// A BEM model of one body: oriented mesh, material, boundary conditions, field nodes.
#[derive(Debug, Clone)]
pub struct BemModel {
    /// The oriented mesh.
    pub mesh: BoundaryMesh,
    /// The material.
    pub material: Elastic,
    /// Boundary condition of each physical group (same order as `mesh.groups`).
    pub conditions: Vec<BoundaryCondition>,
    /// Options.
    pub options: BemOptions,
    /// Field nodes and interpolation.
    pub discretisation: Discretisation,
    /// Notices from orienting the mesh (one per loop turned round).
    pub notices: Vec<String>,
    /// Boundary loop (index into [`crate::mesh::boundary_loops`]) of each field node.
    pub loop_of_node: Vec<usize>,
    kernel: Kelvin,
}

impl BemModel {
    /// Builds a model: checks the material and the mesh, orients the loops, matches every
    /// physical group with exactly one boundary condition, and places the field nodes.
    pub fn new(
        mut mesh: BoundaryMesh,
        material: Elastic,
        conditions: Vec<(String, BoundaryCondition)>,
        options: BemOptions,
    ) -> Result<Self, BemError> {
        let (e, nu) = (material.young, material.poisson);
        if !(e.is_finite() && e > 0.0 && nu > -1.0 && nu <= 0.5) {
            return Err(BemError::InvalidMaterial {
                path: mesh.source.clone(),
                young: e,
                poisson: nu,
            });
        }
        let notices = validate_and_orient(&mut mesh)?;
        let mut per_group: Vec<Option<BoundaryCondition>> = vec![None; mesh.groups.len()];
        for (name, condition) in conditions {
            let g = mesh.group_index(&name)?;
            if per_group[g].is_some() {
                return Err(BemError::DuplicateCondition {
                    path: mesh.source.clone(),
                    group: name,
                });
            }
            per_group[g] = Some(condition);
        }
        let given: Vec<String> = mesh
            .groups
            .iter()
            .zip(&per_group)
            .filter(|(_, c)| c.is_some())
            .map(|(g, _)| g.name.clone())
            .collect();
        let mut conditions = Vec::with_capacity(per_group.len());
        for (g, c) in per_group.into_iter().enumerate() {
            conditions.push(c.ok_or_else(|| BemError::MissingCondition {
                path: mesh.source.clone(),
                group: mesh.groups[g].name.clone(),
                given: given.join(", "),
            })?);
        }
        let contact: Vec<bool> = conditions.iter().map(BoundaryCondition::is_contact).collect();
        let discretisation = Discretisation::new(&mesh, &contact, options.corner_angle_deg.to_radians());
        let length_scale = options.log_length_scale.unwrap_or(4.0 * mesh.size());
        let kernel = Kelvin::new(&material, length_scale);
        let mut loop_of_element = vec![0; mesh.elements.len()];
        for (k, lp) in boundary_loops(&mesh)?.iter().enumerate() {
            for &e in &lp.elements {
                loop_of_element[e] = k;
            }
        }
        let loop_of_node = discretisation
            .nodes
            .iter()
            .map(|n| loop_of_element[n.element.0])
            .collect();
        Ok(Self {
            mesh,
            material,
            conditions,
            options,
            discretisation,
            notices,
            loop_of_node,
            kernel,
        })
    }

    /// The field nodes (unknown locations), in system order: node k owns rows/columns 2k, 2k+1.
    pub fn field_nodes(&self) -> &[FieldNode] {
        &self.discretisation.nodes
    }

    /// Field nodes of the group called `name`.
    pub fn group_nodes(&self, name: &str) -> Result<Vec<usize>, BemError> {
        let g = self.mesh.group_index(name)?;
        Ok(self.discretisation.nodes_of_group(g))
    }

    /// The Kelvin kernels used (material and logarithm length scale).
    pub fn kernel(&self) -> &Kelvin {
        &self.kernel
    }

    /// Assembles H and G with the model's Kelvin kernels, in parallel over the collocation
    /// points.
    pub fn assemble(&self) -> Assembly {
        self.assemble_with(&self.kernel)
    }

    /// Assembles H and G of the model's discretisation with the fundamental solution
    /// `kernel`, in parallel over the collocation points.
    pub fn assemble_with<K: FundamentalSolution>(&self, kernel: &K) -> Assembly {
        let n = self.discretisation.n_nodes();
        let quadrature = Quadrature::new(self.options.quadrature());
        assemble_by_rows(n, |i| self.collocation_rows(kernel, i, &quadrature))
    }

    /// Rows 2i, 2i+1 of H then of G (4 × 2N values, row after row) for collocation at node i.
    pub(crate) fn collocation_rows<K: FundamentalSolution>(
        &self,
        kernel: &K,
        i: usize,
        quadrature: &Quadrature,
    ) -> Vec<f64> {
        let d = &self.discretisation;
        let m = 2 * d.n_nodes();
        let mut rows = vec![0.0; 4 * m];
        let source = d.nodes[i].position;
        for (e, ids) in d.element_nodes.iter().enumerate() {
            let position = match ids.iter().position(|&k| k == i) {
                Some(local) => SourcePosition::OnNode {
                    xi: d.interpolation[e].node_coordinates()[local],
                    local,
                },
                None => SourcePosition::Off,
            };
            let ints = element_integrals(
                quadrature,
                kernel,
                &d.geometry[e],
                &d.interpolation[e],
                source,
                position,
            );
            for (a, &col) in ids.iter().enumerate() {
                ints.add_node_to_rows(a, &mut rows, m, col);
            }
        }
        rigid_body_diagonal(&mut rows, i, d.n_nodes());
        rows
    }

    /// Known data of every component (2N values) from the group conditions and the pins.
    pub fn boundary_data(&self, pins: &[Pin]) -> Result<Vec<Component>, BemError> {
        let d = &self.discretisation;
        let mut data = Vec::with_capacity(2 * d.n_nodes());
        for node in &d.nodes {
            let c = self.conditions[node.group].components(node.position, node.normal);
            data.extend_from_slice(&c);
        }
        for pin in pins {
            if pin.node >= d.n_nodes() || pin.component > 1 {
                return Err(BemError::BadPin {
                    path: self.mesh.source.clone(),
                    node: pin.node,
                    count: d.n_nodes(),
                });
            }
            data[2 * pin.node + pin.component] = Component::Displacement(pin.value);
        }
        self.check_rigid_body_support(&data)?;
        self.check_incompressible_loops(&data)?;
        Ok(data)
    }

    /// The prescribed displacement components must block both translations and the rotation:
    /// the 3 × 3 Gram matrix of the rigid modes (1, 0), (0, 1), (−y, x)/L restricted to those
    /// components must be regular (smallest/largest eigenvalue above 1e-10; a single fixed
    /// point leaves the rotation about it free and gives exactly 0).
    fn check_rigid_body_support(&self, data: &[Component]) -> Result<(), BemError> {
        let nodes = &self.discretisation.nodes;
        let size = self.mesh.size();
        let centre = nodes.first().map_or([0.0; 2], |n| n.position);
        let mut gram = nalgebra::Matrix3::<f64>::zeros();
        for (k, c) in data.iter().enumerate() {
            if let Component::Displacement(_) = c {
                let p = nodes[k / 2].position;
                let rot = [-(p[1] - centre[1]) / size, (p[0] - centre[0]) / size];
                let row = if k % 2 == 0 {
                    nalgebra::Vector3::new(1.0, 0.0, rot[0])
                } else {
                    nalgebra::Vector3::new(0.0, 1.0, rot[1])
                };
                gram += row * row.transpose();
            }
        }
        let eig = gram.symmetric_eigenvalues();
        let (lo, hi) = (eig.min(), eig.max());
        if hi <= 0.0 || lo < 1e-10 * hi {
            return Err(BemError::RigidBodyMotion {
                path: self.mesh.source.clone(),
            });
        }
        Ok(())
    }

    /// At ν = 0.5 the Kelvin displacement field is divergence-free, so ∮ U*·n dΓ = 0 on every
    /// closed loop: G cannot see a uniform pressure on a loop. With two or more loops loaded
    /// by tractions, pressurising one of them relative to the others deforms the body without
    /// changing G t, and the displacement BIE has no unique solution (see the module docs).
    fn check_incompressible_loops(&self, data: &[Component]) -> Result<(), BemError> {
        if self.material.poisson < 0.5 - 1e-12 {
            return Ok(());
        }
        let mut loops: Vec<usize> = data
            .iter()
            .enumerate()
            .filter(|(_, c)| matches!(c, Component::Traction(_)))
            .map(|(k, _)| self.loop_of_node[k / 2])
            .collect();
        loops.sort_unstable();
        loops.dedup();
        if loops.len() < 2 {
            return Ok(());
        }
        let describe = |l: usize| {
            let mut groups: Vec<&str> = self
                .discretisation
                .nodes
                .iter()
                .zip(&self.loop_of_node)
                .filter(|(_, &lp)| lp == l)
                .map(|(n, _)| self.mesh.groups[n.group].name.as_str())
                .collect();
            groups.sort_unstable();
            groups.dedup();
            format!("[{}]", groups.join(", "))
        };
        Err(BemError::IncompressibleTractionLoops {
            path: self.mesh.source.clone(),
            loops: loops.iter().map(|&l| describe(l)).collect::<Vec<_>>().join(", "),
        })
    }

    /// Scale s of the unknown tractions in the system: x = t / s with s = G/L.
    pub(crate) fn traction_scale(&self) -> f64 {
        self.material.shear() / self.mesh.size()
    }

    /// System matrix A and right-hand side b of A x = b for the given data (see module docs),
    /// made in H's place: A's column of a known traction is H's, of a
    /// known displacement −G's times the traction scale, so H becomes A and G stays (but for
    /// the columns of known displacements) for right-hand sides of more tractions. Returns
    /// (A, b, G): one matrix of the system's size fewer than A beside H and G.
    pub(crate) fn linear_system_in_place_of_h(
        &self,
        asm: Assembly,
        data: &[Component],
    ) -> (Mat<f64>, Mat<f64>, Mat<f64>) {
        let Assembly { h: mut a, g } = asm;
        let m = data.len();
        let s = self.traction_scale();
        let mut b = Mat::zeros(m, 1);
        for (k, c) in data.iter().enumerate() {
            match *c {
                Component::Displacement(v) => {
                    for r in 0..m {
                        b[(r, 0)] -= a[(r, k)] * v;
                        a[(r, k)] = -g[(r, k)] * s;
                    }
                }
                Component::Traction(v) => {
                    for r in 0..m {
                        b[(r, 0)] += g[(r, k)] * v;
                    }
                }
            }
        }
        (a, b, g)
    }

    /// Factorises A and solves A X = B in place (B may have several columns); fails when the
    /// pivots reveal a singular system. A is factored where it lies
    /// ([`crate::linalg::lu_solve_in_place`]): faer's `partial_piv_lu` would copy it and split
    /// the copy into L and U, three more matrices of the system's size, each paid in page faults.
    pub(crate) fn solve_system(&self, mut a: Mat<f64>, b: &mut Mat<f64>) -> Result<(), BemError> {
        let mut ws = crate::linalg::LuWorkspace::new();
        ws.solve_in_place(a.as_mut(), b.as_mut());
        // The factored matrix holds U on and above its diagonal; B is left unused on failure.
        self.check_pivots(crate::linalg::pivot_ratio(a.as_ref()))
    }

    /// Fails when the pivots' ratio of a factored system (smallest over largest |pivot|)
    /// reveals a singular system, or is NaN (non-finite input).
    pub(crate) fn check_pivots(&self, ratio: f64) -> Result<(), BemError> {
        if ratio.is_nan() || ratio < self.options.min_pivot_ratio {
            return Err(BemError::SingularSystem {
                path: self.mesh.source.clone(),
                pivot_ratio: ratio,
            });
        }
        Ok(())
    }

    /// Solves the model with its group conditions (contact groups traction-free).
    pub fn solve(&self) -> Result<BemSolution, BemError> {
        self.solve_pinned(&[])
    }

    /// Solves the model with point constraints `pins` added to the group conditions.
    pub fn solve_pinned(&self, pins: &[Pin]) -> Result<BemSolution, BemError> {
        let data = self.boundary_data(pins)?;
        self.solve_assembled(self.assemble(), &data)
    }

    /// Solves with an assembly (taken: the system matrix is made in H's place) and explicit
    /// per-component data.
    pub fn solve_assembled(&self, asm: Assembly, data: &[Component]) -> Result<BemSolution, BemError> {
        let (a, mut x, _) = self.linear_system_in_place_of_h(asm, data);
        self.solve_system(a, &mut x)?;
        Ok(self.boundary_values(data, |k| x[(k, 0)]))
    }

    /// Boundary values (u, t) at every field node from one solution `x` of A x = b: each
    /// component's known value from `data`, its unknown one from `x(k)` (an unknown traction
    /// rescaled by [`Self::traction_scale`], see the module docs).
    pub(crate) fn boundary_values(&self, data: &[Component], x: impl Fn(usize) -> f64) -> BemSolution {
        let s = self.traction_scale();
        let n = data.len() / 2;
        let mut displacement = vec![[0.0; 2]; n];
        let mut traction = vec![[0.0; 2]; n];
        for (k, c) in data.iter().enumerate() {
            let (node, comp) = (k / 2, k % 2);
            match *c {
                Component::Displacement(v) => {
                    displacement[node][comp] = v;
                    traction[node][comp] = x(k) * s;
                }
                Component::Traction(v) => {
                    displacement[node][comp] = x(k);
                    traction[node][comp] = v;
                }
            }
        }
        BemSolution { displacement, traction }
    }
}
