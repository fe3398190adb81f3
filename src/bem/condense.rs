//! Condensation of a BEM body to its contact nodes, and the BEM [`BodyModel`].
//!
//! With the boundary conditions applied, the BEM system is A x = b0 + Σ_k G_k τ_k, where τ_k
//! are the contact traction components (one per contact node and direction) and G_k the
//! columns of G that multiply them. One LU factorisation of A and one solve with 1 + 2m
//! right-hand sides [b0, G_1 … G_2m] give every unknown as an affine function of the contact
//! tractions; the rows of the contact displacements form the 2m × 2m flexibility
//! (González & Abascal §3, Eq. 11–13: the body's part of S).
//!
//! # Pair convention ([`crate::body`])
//! Body A lies above the contact (its contact surface faces −y), body B below (+y). The
//! pressure p ≥ 0 pushes each body away from the other and the shear q acts on A in +x, on B
//! in −x, so the global traction on the contact surface is t = (q, p) on A and (−q, −p) on B.
//! The normal share h is the displacement into the body, u_y on A and −u_y on B; the tangential
//! share w is u_x on A and −u_x on B. The two sign flips cancel in every block, so for both
//! sides hp = F_yy, hq = F_yx, wp = F_xy, wq = F_xx, with F the global flexibility; the
//! dissimilar-coupling signs come out of each body's own geometry.
//!
//! The contact group must use the contact grid's nodes: discontinuous quadratic elements whose
//! field nodes lie at the grid's node abscissae (checked in [`BemBody::new`]).
//!
//! # Surface strain by HBEM
//! The same multi-column solve gives the whole boundary response (u, t at every field node) to
//! each unit contact traction component. Applying the hypersingular rows of
//! [`super::hypersingular`] at each contact node (a field node strictly inside its
//! discontinuous element) gives the derivative of u_x along the contact surface per unit x,
//!
//! ```text
//! du_x/dx|surface = u_x,x + u_x,y · dy/dx        (dy/dx: slope of the element at the node)
//! ```
//!
//! which is what the finite-difference slip differentiates (w at the nodes against their x),
//! not u_x,x alone. It is linear in the contact tractions: the response to the body's other
//! prescribed data (its offset) is left out, which is exact while contact runs admit only zero
//! prescribed data on bem bodies (`fixed`, `free`; the case validation rejects the rest). In
//! the pair convention both sign flips cancel again: ∂(∂w/∂x)/∂p = S_xy, ∂(∂w/∂x)/∂q = S_xx
//! on either side, with S the global strain matrix [`ContactFlexibility::surface_strain`].

use super::assemble::{BemModel, BemSolution};
use super::hypersingular::{GradientEvaluator, GradientPoint};
use super::somigliana::interior_fields;
use super::{BemError, BoundaryCondition, Component};
use crate::body::{BodyModel, BoundaryField, Flexibility, Side, StrainOperator};
use crate::grid::{ContactGrid, ElementKind};
use crate::interior::{InteriorError, InteriorOptions, InteriorSample};
use faer::Mat;
use rayon::prelude::*;

/// Flexibility of a BEM body at the field nodes of its contact group (global axes).
#[derive(Debug, Clone)]
pub struct ContactFlexibility {
    /// Field nodes of the contact group, in increasing x.
    pub nodes: Vec<usize>,
    /// Their abscissae x [length].
    pub x: Vec<f64>,
    /// F[(2i + a, 2j + b)] = displacement component a at contact node i per unit nodal value
    /// of the traction component b at contact node j (a, b = 0 for x, 1 for y)
    /// [length/stress].
    pub matrix: Mat<f64>,
    /// Displacement at the contact nodes with zero contact traction, due to the other
    /// prescribed data [length].
    pub offset: Vec<[f64; 2]>,
    /// Every unknown of the BEM system as an affine function of the contact tractions:
    /// column 0 holds the unknowns x of the collocation system A x = b (a displacement where a
    /// traction is known, a traction scaled by G/L where a displacement is known) with zero
    /// contact traction, column 1 + 2j + b their change per unit traction component b
    /// (0 = x, 1 = y, global axes) at contact node j (the order of `nodes`). Post-processing
    /// rebuilds the whole boundary solution from it without a second solve
    /// ([`BemBody::contact_solution`]). Size 2N × (1 + 2m).
    pub response: Mat<f64>,
    /// The known data of every component that `response` was solved with (the contact
    /// components traction-type, zero), so that post-processing does not re-evaluate the
    /// boundary conditions.
    pub data: Vec<Component>,
    /// Wall time of the BEM assembly (H, G) [s].
    pub assembly_s: f64,
    /// Wall time of the factorization and the multi-column solve [s].
    pub condense_s: f64,
    /// HBEM surface strain, m × 2m: S[(i, 2j + b)] = du_x/dx along the surface at contact
    /// node i per unit nodal value of the traction component b at contact node j (global axes;
    /// see the module docs) [1/stress].
    pub surface_strain: Mat<f64>,
    /// Wall time of the HBEM surface strain [s].
    pub strain_s: f64,
}

/// Condenses `model` to the field nodes of its contact group `contact_group` (which must have
/// the [`BoundaryCondition::Contact`] condition): one LU, one multi-column solve.
pub fn condense(model: &BemModel, contact_group: &str) -> Result<ContactFlexibility, BemError> {
    let g = model.mesh.group_index(contact_group)?;
    if !matches!(model.conditions[g], BoundaryCondition::Contact) {
        return Err(BemError::ContactGridMismatch {
            path: model.mesh.source.clone(),
            group: contact_group.to_string(),
            problem: format!("its boundary condition is {:?}, not contact", model.conditions[g]),
        });
    }
    let field = model.field_nodes();
    let mut nodes = model.discretisation.nodes_of_group(g);
    nodes.sort_by(|&a, &b| field[a].position[0].total_cmp(&field[b].position[0]));
    let m = nodes.len();

    let data = model.boundary_data(&[])?;
    let t_assembly = std::time::Instant::now();
    let asm = model.assemble();
    let assembly_s = t_assembly.elapsed().as_secs_f64();
    let t_condense = std::time::Instant::now();
    let (a, b0) = model.linear_system(&asm, &data);
    let n_dof = data.len();
    // Contact DOFs are traction-type, so each unit contact traction adds its G column to b.
    let mut rhs = Mat::from_fn(n_dof, 1 + 2 * m, |r, c| {
        if c == 0 {
            b0[(r, 0)]
        } else {
            let (j, comp) = ((c - 1) / 2, (c - 1) % 2);
            asm.g[(r, 2 * nodes[j] + comp)]
        }
    });
    model.solve_system(&a, &mut rhs)?;
    // The unknowns at contact DOFs are the displacements themselves (unscaled).
    let matrix = Mat::from_fn(2 * m, 2 * m, |r, c| rhs[(2 * nodes[r / 2] + r % 2, 1 + c)]);
    let offset = nodes.iter().map(|&k| [rhs[(2 * k, 0)], rhs[(2 * k + 1, 0)]]).collect();
    let condense_s = t_condense.elapsed().as_secs_f64();
    let t_strain = std::time::Instant::now();
    let responses: Vec<BemSolution> = (0..2 * m)
        .map(|c| {
            let loaded = 2 * nodes[c / 2] + c % 2;
            model.boundary_values(&unit_load_data(&data, loaded), |k| rhs[(k, 1 + c)])
        })
        .collect();
    let surface_strain = surface_strain(model, &nodes, &responses)?;
    let strain_s = t_strain.elapsed().as_secs_f64();
    Ok(ContactFlexibility {
        x: nodes.iter().map(|&k| field[k].position[0]).collect(),
        nodes,
        matrix,
        assembly_s,
        condense_s,
        offset,
        surface_strain,
        strain_s,
        response: rhs,
        data,
    })
}

/// The data of the response to a unit value of the traction component `loaded`: every
/// prescribed value zero (the other data enter the offset column only), the loaded component 1.
fn unit_load_data(data: &[Component], loaded: usize) -> Vec<Component> {
    data.iter()
        .enumerate()
        .map(|(k, c)| match c {
            Component::Displacement(_) => Component::Displacement(0.0),
            Component::Traction(_) => Component::Traction(if k == loaded { 1.0 } else { 0.0 }),
        })
        .collect()
}

/// HBEM du_x/dx along the surface at the field nodes `nodes` (strictly inside their elements)
/// for each boundary response in `responses` (module docs): an m × responses matrix. Each node
/// gives one row on the nodal (u, t), ∇u_x·(1, dy/dx); the responses are stacked as the columns
/// of a 4N-row matrix and the two multiplied (one dense product instead of m × responses dot
/// products).
pub fn surface_strain(model: &BemModel, nodes: &[usize], responses: &[BemSolution]) -> Result<Mat<f64>, BemError> {
    let d = &model.discretisation;
    let n_dof = 2 * d.n_nodes();
    let evaluator = GradientEvaluator::new(model);
    let rows: Vec<(Vec<f64>, Vec<f64>)> = nodes
        .par_iter()
        .map(|&k| {
            let (element, local) = d.nodes[k].element;
            let xi = d.interpolation[element].node_coordinates()[local];
            let tangent = d.geometry[element].tangent(xi);
            let rows = evaluator.rows(GradientPoint::Boundary { element, xi })?;
            Ok(rows.directional(0, [1.0, tangent[1] / tangent[0]]))
        })
        .collect::<Result<_, BemError>>()?;
    let strain_rows = Mat::from_fn(nodes.len(), 2 * n_dof, |i, c| {
        if c < n_dof {
            rows[i].0[c]
        } else {
            rows[i].1[c - n_dof]
        }
    });
    let fields = Mat::from_fn(2 * n_dof, responses.len(), |r, c| {
        let (values, r) = if r < n_dof {
            (&responses[c].displacement, r)
        } else {
            (&responses[c].traction, r - n_dof)
        };
        values[r / 2][r % 2]
    });
    Ok(&strain_rows * &fields)
}

/// A body modelled by the BEM, condensed to a contact grid whose nodes it shares.
#[derive(Debug, Clone)]
pub struct BemBody {
    /// The BEM model of the body.
    pub model: BemModel,
    /// Name of the contact group.
    pub contact_group: String,
    /// Which body of the pair this is.
    pub side: Side,
    /// The condensed flexibility (global axes).
    pub condensed: ContactFlexibility,
    /// Height of the contact surface's touching point: its lowest y on A, highest on B
    /// [length].
    touch_y: f64,
}

impl BemBody {
    /// Condenses `model` to the nodes of `grid` for a body on `side`.
    ///
    /// Fails unless `grid` uses discontinuous quadratic elements, the contact group's field
    /// nodes lie at the grid's node abscissae (to 1e-3 of the node spacing), and the contact
    /// surface faces the other body (outward normal −y on A, +y on B, within 25°).
    ///
    /// The tolerance admits curved contact elements: Gmsh puts the mid node of an arc at its
    /// mid-angle, which moves the interior field nodes off the uniform grid by about
    /// R·θ·δ²/2 (θ the angle from the contact centre, δ the element's half angle), some 1e-5
    /// of the node spacing for a = 1 mm on R = 100 mm. A pairing offset ε·spacing changes the
    /// influence coefficients by a relative O(ε), far below the discretisation error.
    pub fn new(model: BemModel, contact_group: &str, grid: &ContactGrid, side: Side) -> Result<Self, BemError> {
        let mismatch = |problem: String| BemError::ContactGridMismatch {
            path: model.mesh.source.clone(),
            group: contact_group.to_string(),
            problem,
        };
        if grid.kind != ElementKind::DiscontinuousQuadratic {
            return Err(mismatch(
                "the contact grid must use discontinuous quadratic elements for a BEM body".to_string(),
            ));
        }
        let g = model.mesh.group_index(contact_group)?;
        let field = model.field_nodes();
        let mut xs: Vec<f64> = model
            .discretisation
            .nodes_of_group(g)
            .iter()
            .map(|&k| field[k].position[0])
            .collect();
        xs.sort_by(f64::total_cmp);
        if xs.len() != grid.n_nodes() {
            return Err(mismatch(format!(
                "{} contact nodes in the mesh, {} in the grid ({} elements of length {})",
                xs.len(),
                grid.n_nodes(),
                grid.n_elements(),
                grid.element_length()
            )));
        }
        let tolerance = 1e-3 * grid.node_spacing();
        if let Some((x_mesh, x_grid)) = xs.iter().zip(&grid.nodes).find(|(a, b)| (*a - *b).abs() > tolerance) {
            return Err(mismatch(format!(
                "mesh node at x = {x_mesh} but grid node at x = {x_grid}: the contact elements \
                 must coincide with the grid's elements"
            )));
        }
        let facing = match side {
            Side::A => -1.0,
            Side::B => 1.0,
        };
        let cos_limit = 25f64.to_radians().cos();
        if let Some(k) = model
            .discretisation
            .nodes_of_group(g)
            .into_iter()
            .find(|&k| field[k].normal[1] * facing < cos_limit)
        {
            return Err(mismatch(format!(
                "the contact surface at x = {} does not face the other body (outward normal \
                 {:?}, expected close to (0, {facing}) for body {side:?})",
                field[k].position[0], field[k].normal
            )));
        }
        let condensed = condense(&model, contact_group)?;
        let touch_y = contact_heights(&model, g)
            .into_iter()
            .map(|(_, y)| y * facing)
            .fold(f64::NEG_INFINITY, f64::max)
            * facing;
        Ok(Self {
            contact_group: contact_group.to_string(),
            side,
            condensed,
            touch_y,
            model,
        })
    }

    /// Height y(x) of the undeformed contact surface at abscissa x [length], if x lies on
    /// the contact group.
    fn surface_height(&self, x: f64) -> Option<f64> {
        let g = self.model.mesh.group_index(&self.contact_group).ok()?;
        let d = &self.model.discretisation;
        for (e, el) in self.model.mesh.elements.iter().enumerate() {
            if el.group != g {
                continue;
            }
            let geom = &d.geometry[e];
            // x(ξ) = xm + ξ (x1 − x0)/2 + ξ² ((x0 + x1)/2 − xm): solve for ξ ∈ [−1, 1].
            let [p0, p1, pm] = geom.nodes;
            let (c0, c1, c2) = (pm[0] - x, 0.5 * (p1[0] - p0[0]), 0.5 * (p0[0] + p1[0]) - pm[0]);
            let roots: Vec<f64> = if c2.abs() < 1e-14 * c1.abs() {
                vec![-c0 / c1]
            } else {
                let disc = c1 * c1 - 4.0 * c2 * c0;
                if disc < 0.0 {
                    continue;
                }
                let s = disc.sqrt();
                vec![(-c1 + s) / (2.0 * c2), (-c1 - s) / (2.0 * c2)]
            };
            if let Some(&xi) = roots.iter().find(|r| r.abs() <= 1.0 + 1e-12) {
                return Some(geom.point(xi.clamp(-1.0, 1.0))[1]);
            }
        }
        None
    }
}

/// Sample points (x, y) of the contact group's geometry (21 per element).
fn contact_heights(model: &BemModel, group: usize) -> Vec<(f64, f64)> {
    let d = &model.discretisation;
    model
        .mesh
        .elements
        .iter()
        .enumerate()
        .filter(|(_, el)| el.group == group)
        .flat_map(|(e, _)| {
            (0..=20).map(move |s| {
                let p = d.geometry[e].point(-1.0 + 0.1 * s as f64);
                (p[0], p[1])
            })
        })
        .collect()
}

impl BemBody {
    /// Panics unless `grid` and `side` are the ones given to [`BemBody::new`] (a programming
    /// error: the mesh was checked against those).
    fn assert_same_grid(&self, grid: &ContactGrid, side: Side) {
        assert!(
            side == self.side
                && grid.n_nodes() == self.condensed.x.len()
                && grid
                    .nodes
                    .iter()
                    .zip(&self.condensed.x)
                    .all(|(a, b)| (a - b).abs() <= 1e-3 * grid.node_spacing()),
            "BemBody called with another grid or side than BemBody::new"
        );
    }

    /// The whole boundary solution (u and t at every field node, global axes) under the nodal
    /// contact tractions `p`, `q` at this body's contact nodes (pair convention: the traction on
    /// the contact group is (q, p) on A and (−q, −p) on B), from the condensed response: no
    /// second assembly or solve, and exactly the state the flexibility describes.
    pub fn contact_solution(&self, p: &[f64], q: &[f64]) -> Result<BemSolution, BemError> {
        let c = &self.condensed;
        let m = c.nodes.len();
        if p.len() != m || q.len() != m {
            return Err(BemError::ContactGridMismatch {
                path: self.model.mesh.source.clone(),
                group: self.contact_group.clone(),
                problem: format!("{} contact tractions given for {m} contact nodes", p.len().min(q.len())),
            });
        }
        let sign = self.side.sign();
        let mut data = c.data.clone();
        let n_dof = data.len();
        let mut unknowns: Vec<f64> = (0..n_dof).map(|r| c.response[(r, 0)]).collect();
        for (j, &k) in c.nodes.iter().enumerate() {
            let traction = [sign * q[j], sign * p[j]];
            for (b, &tb) in traction.iter().enumerate() {
                data[2 * k + b] = Component::Traction(tb);
                if tb != 0.0 {
                    let col = 1 + 2 * j + b;
                    for (r, x) in unknowns.iter_mut().enumerate() {
                        *x += c.response[(r, col)] * tb;
                    }
                }
            }
        }
        Ok(self.model.boundary_values(&data, |k| unknowns[k]))
    }

    /// The boundary field under nodal contact tractions on `grid` (see
    /// [`BodyModel::boundary_field`]): [`Self::contact_solution`] sampled at ξ = −1, 1, 0 of
    /// every element.
    pub fn boundary_solution(&self, grid: &ContactGrid, p: &[f64], q: &[f64]) -> Result<BoundaryField, BemError> {
        self.check_grid(grid)?;
        let sol = self.contact_solution(p, q)?;
        let model = &self.model;
        let d = &model.discretisation;
        let mut out = BoundaryField {
            points: Vec::new(),
            displacement: Vec::new(),
            traction: Vec::new(),
            group: Vec::new(),
            group_names: model.mesh.group_names(),
        };
        for (e, nodes) in d.element_nodes.iter().enumerate() {
            for xi in [-1.0, 1.0, 0.0] {
                let n = d.interpolation[e].shape(xi);
                let mix = |v: &[[f64; 2]]| {
                    let mut r = [0.0; 2];
                    for (a, &k) in nodes.iter().enumerate() {
                        r[0] += n[a] * v[k][0];
                        r[1] += n[a] * v[k][1];
                    }
                    r
                };
                out.points.push(d.geometry[e].point(xi));
                out.displacement.push(mix(&sol.displacement));
                out.traction.push(mix(&sol.traction));
            }
            out.group.push(model.mesh.elements[e].group as i32);
        }
        Ok(out)
    }

    /// Interior displacement and stress at `points` of the contact frame under the nodal
    /// contact tractions (see [`BodyModel::interior`]), by Somigliana's identity
    /// ([`super::somigliana`]) from [`Self::contact_solution`]. The mesh's axes are the contact
    /// frame up to the height of the touching point (zero for meshes drawn touching the
    /// origin, as the shipped ones): a point (x, y) is evaluated at (x, y + y_touch) of the mesh.
    pub fn interior_samples(
        &self,
        grid: &ContactGrid,
        p: &[f64],
        q: &[f64],
        points: &[[f64; 2]],
        options: &InteriorOptions,
    ) -> Result<Vec<InteriorSample>, BemError> {
        self.check_grid(grid)?;
        let sol = self.contact_solution(p, q)?;
        let mesh_points: Vec<[f64; 2]> = points.iter().map(|&[x, y]| [x, y + self.touch_y]).collect();
        Ok(interior_fields(&self.model, &sol, &mesh_points, options))
    }

    /// The grid must be the one the body was built on (its contact nodes at the grid's nodes).
    fn check_grid(&self, grid: &ContactGrid) -> Result<(), BemError> {
        let same = grid.n_nodes() == self.condensed.x.len()
            && grid
                .nodes
                .iter()
                .zip(&self.condensed.x)
                .all(|(a, b)| (a - b).abs() <= 1e-3 * grid.node_spacing());
        if same {
            Ok(())
        } else {
            Err(BemError::ContactGridMismatch {
                path: self.model.mesh.source.clone(),
                group: self.contact_group.clone(),
                problem: format!(
                    "post-processing asked on a grid of {} nodes that is not the body's own ({} nodes)",
                    grid.n_nodes(),
                    self.condensed.x.len()
                ),
            })
        }
    }
}

impl BodyModel for BemBody {
    fn model_name(&self) -> &'static str {
        "bem"
    }

    /// The condensed flexibility in the pair convention (module docs).
    ///
    /// `grid` and `side` must be the ones given to [`BemBody::new`], which checked the mesh
    /// against them; anything else is a programming error and panics.
    fn flexibility(&self, grid: &ContactGrid, side: Side) -> Flexibility {
        self.assert_same_grid(grid, side);
        let m = grid.n_nodes();
        let f = &self.condensed.matrix;
        Flexibility {
            hp: Mat::from_fn(m, m, |i, j| f[(2 * i + 1, 2 * j + 1)]),
            hq: Mat::from_fn(m, m, |i, j| f[(2 * i + 1, 2 * j)]),
            wp: Mat::from_fn(m, m, |i, j| f[(2 * i, 2 * j + 1)]),
            wq: Mat::from_fn(m, m, |i, j| f[(2 * i, 2 * j)]),
        }
    }

    /// Distance of the undeformed contact surface from the common tangent at x [length]
    /// (y − y_touch on A, y_touch − y on B); beyond the contact group, the value at its
    /// nearer end.
    fn profile(&self, x: f64) -> f64 {
        let (lo, hi) = (
            self.condensed.x.first().copied().unwrap_or(x),
            self.condensed.x.last().copied().unwrap_or(x),
        );
        let facing = match self.side {
            Side::A => 1.0,
            Side::B => -1.0,
        };
        let y = self
            .surface_height(x)
            .or_else(|| self.surface_height(x.clamp(lo, hi)))
            .unwrap_or(self.touch_y);
        ((y - self.touch_y) * facing).max(0.0)
    }

    /// (assembly, condensation + HBEM surface strain) [s].
    fn stage_seconds(&self) -> (f64, f64) {
        (
            self.condensed.assembly_s,
            self.condensed.condense_s + self.condensed.strain_s,
        )
    }

    /// The boundary solution under the nodal contact tractions (on A (q, p), on B (−q, −p) in
    /// global axes), from the condensed response ([`BemBody::contact_solution`]), sampled at
    /// ξ = −1, 1, 0 of every element.
    fn boundary_field(&self, grid: &ContactGrid, p: &[f64], q: &[f64]) -> Option<Result<BoundaryField, String>> {
        Some(self.boundary_solution(grid, p, q).map_err(|e| e.to_string()))
    }

    /// The HBEM surface strain ∂w/∂x at the contact nodes (module docs, "Surface strain by
    /// HBEM") in the pair convention: p ↦ S_xy, q ↦ S_xx on either side (the sign of w and of
    /// the loads flip together on B). Linear: the prescribed data of a bem body are zero in
    /// contact runs. Same `grid`/`side` contract as [`BodyModel::flexibility`].
    fn strain_operator(&self, grid: &ContactGrid, side: Side) -> Option<StrainOperator> {
        self.assert_same_grid(grid, side);
        let m = grid.n_nodes();
        let s = &self.condensed.surface_strain;
        Some(StrainOperator {
            p: Mat::from_fn(m, m, |i, j| s[(i, 2 * j + 1)]),
            q: Mat::from_fn(m, m, |i, j| s[(i, 2 * j)]),
        })
    }

    /// Somigliana's identity, see [`BemBody::interior_samples`]; `side` must be the body's own.
    fn interior(
        &self,
        grid: &ContactGrid,
        side: Side,
        p: &[f64],
        q: &[f64],
        points: &[[f64; 2]],
        options: &InteriorOptions,
    ) -> Result<Vec<InteriorSample>, InteriorError> {
        if side != self.side {
            return Err(InteriorError::Bem(BemError::ContactGridMismatch {
                path: self.model.mesh.source.clone(),
                group: self.contact_group.clone(),
                problem: format!("body built for side {:?}, asked for side {side:?}", self.side),
            }));
        }
        Ok(self.interior_samples(grid, p, q, points, options)?)
    }
}
