//! Condensation of a BEM body to its contact nodes (global axes).
//!
//! With the boundary conditions applied, the BEM system is A x = b0 + Σ_k G_k τ_k, where τ_k
//! are the contact traction components (one per contact node and direction) and G_k the
//! columns of G that multiply them. One LU factorisation of A and one solve with 1 + 2m
//! right-hand sides [b0, G_1 … G_2m] give every unknown as an affine function of the contact
//! tractions; the rows of the contact displacements form the 2m × 2m flexibility
//! (González & Abascal §3, Eq. 11–13: the body's part of S).
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
//! the pair convention of the body models the sign flips of the loads and of w cancel:
//! ∂(∂w/∂x)/∂p = S_xy, ∂(∂w/∂x)/∂q = S_xx on either side, with S the global strain matrix
//! [`ContactFlexibility::surface_strain`].

use super::assemble::{BemModel, BemSolution};
use super::hypersingular::{check_boundary_point, GradientEvaluator, GradientPoint};
use super::reuse::{assemble_reusing, FarField};
use super::{BemError, BoundaryCondition, Component};
use crate::linalg::LuFactors;
use faer::Mat;
use rayon::prelude::*;
use std::sync::{Mutex, OnceLock};

/// Flexibility of a BEM body at the field nodes of its contact group (global axes).
///
/// Made in one of two ways: solved at once for every unit contact load ([`condense()`], what a
/// contact problem on the body's own grid needs), or factored only ([`factor_reusing`]), for a
/// body asked for its response to a few loads ([`ContactFlexibility::displacements`]: the fits
/// of an error-controlled grid's stand-ins and the checks of its mesh). A factored body solves
/// for every unit load when first asked for its whole flexibility or response, so every
/// accessor works in both; only the cost differs.
#[derive(Debug)]
pub struct ContactFlexibility {
    /// Field nodes of the contact group, in increasing x.
    pub nodes: Vec<usize>,
    /// Their abscissae x [length].
    pub x: Vec<f64>,
    /// The known data of every component that the system was set up with (the contact
    /// components traction-type, zero), so that post-processing does not re-evaluate the
    /// boundary conditions.
    pub data: Vec<Component>,
    /// Wall time of the BEM assembly (H, G) [s].
    pub assembly_s: f64,
    /// Wall time of the factorization (and, when solved at once, of the multi-column solve)
    /// [s].
    pub condense_s: f64,
    /// The response to every unit contact load, solved at once or on first use.
    solved: OnceLock<Solved>,
    /// The factored system of a body made by [`factor_reusing`], until it has solved for every
    /// unit load (its LU and right sides are then dropped: the response answers every load).
    factored: Mutex<Option<Factored>>,
    /// The HBEM surface strain with its wall time [s], computed on first use
    /// ([`ContactFlexibility::surface_strain`]): the passes, the stand-ins' levels and the
    /// body-mesh check of an error-controlled grid never ask for it.
    strain: OnceLock<(Mat<f64>, f64)>,
}

/// The response of a condensed body to every unit contact load.
#[derive(Debug)]
struct Solved {
    /// F[(2i + a, 2j + b)] = displacement component a at contact node i per unit nodal value
    /// of the traction component b at contact node j (a, b = 0 for x, 1 for y)
    /// [length/stress].
    matrix: Mat<f64>,
    /// Displacement at the contact nodes with zero contact traction, due to the other
    /// prescribed data [length].
    offset: Vec<[f64; 2]>,
    /// Every unknown of the BEM system as an affine function of the contact tractions
    /// (column 0 with zero contact traction, column 1 + 2j + b per unit traction component b
    /// at contact node j), 2N × (1 + 2m): [`ContactFlexibility::response`].
    response: Mat<f64>,
    /// Wall time of the solve when made on first use (zero when made with the factorization,
    /// whose time `condense_s` holds) [s].
    seconds: f64,
}

/// A body's collocation system A x = b0 + G_c τ factored, with what its right sides are made of.
#[derive(Debug)]
struct Factored {
    /// A's LU factors.
    lu: LuFactors,
    /// The right side of the body's other prescribed data, 2N × 1.
    b0: Mat<f64>,
    /// G's columns of the contact traction components, 2N × 2m (column 2j + b: component b at
    /// contact node j).
    loads: Mat<f64>,
}

impl ContactFlexibility {
    /// The response to every unit load: the one solved at once, or solved now from the factors.
    fn solved(&self) -> &Solved {
        self.solved.get_or_init(|| {
            let t = std::time::Instant::now();
            let f = self
                .factored
                .lock()
                .expect("the factors' lock")
                .take()
                .expect("a condensation is either solved at once or factored");
            let mut rhs = right_sides(&f.b0, f.loads.ncols(), |r, c| f.loads[(r, c)]);
            f.lu.solve_in_place(rhs.as_mut());
            let mut solved = solved_from(rhs, &self.nodes);
            solved.seconds = t.elapsed().as_secs_f64();
            solved
        })
    }

    /// The factored system, while the body has not solved for every unit load.
    fn factors(&self) -> std::sync::MutexGuard<'_, Option<Factored>> {
        self.factored.lock().expect("the factors' lock")
    }

    /// The flexibility F, 2m × 2m: F[(2i + a, 2j + b)] = displacement component a at contact
    /// node i per unit nodal value of the traction component b at contact node j (a, b = 0 for
    /// x, 1 for y) [length/stress].
    pub fn matrix(&self) -> &Mat<f64> {
        &self.solved().matrix
    }

    /// Displacement at the contact nodes with zero contact traction, due to the other
    /// prescribed data [length].
    pub fn offset(&self) -> &[[f64; 2]] {
        &self.solved().offset
    }

    /// Every unknown of the BEM system as an affine function of the contact tractions:
    /// column 0 holds the unknowns x of the collocation system A x = b (a displacement where a
    /// traction is known, a traction scaled by G/L where a displacement is known) with zero
    /// contact traction, column 1 + 2j + b their change per unit traction component b
    /// (0 = x, 1 = y, global axes) at contact node j (the order of `nodes`). Post-processing
    /// rebuilds the whole boundary solution from it without a second solve
    /// ([`ContactFlexibility::boundary_solution`]). Size 2N × (1 + 2m).
    pub fn response(&self) -> &Mat<f64> {
        &self.solved().response
    }

    /// Whether the body was factored only and has not solved for every unit load yet (its
    /// [`Self::displacements`] then cost one solve per load).
    pub fn is_factored_only(&self) -> bool {
        self.factors().is_some()
    }

    /// The contact displacements F·τ (2m × k, global axes) under the k contact loads `loads`
    /// (2m × k: row 2j + b the traction component b at contact node j) [length]: the
    /// flexibility's product where it is made, else one solve of the factored system for the k
    /// loads together.
    pub fn displacements(&self, loads: faer::MatRef<'_, f64>) -> Mat<f64> {
        let m = self.nodes.len();
        assert_eq!(loads.nrows(), 2 * m, "one row per contact traction component");
        if let Some(f) = self.factors().as_ref() {
            let mut rhs = &f.loads * loads;
            f.lu.solve_in_place(rhs.as_mut());
            return Mat::from_fn(2 * m, loads.ncols(), |r, c| rhs[(2 * self.nodes[r / 2] + r % 2, c)]);
        }
        self.matrix() * loads
    }

    /// HBEM surface strain, m × 2m: S[(i, 2j + b)] = du_x/dx along the surface at contact
    /// node i per unit nodal value of the traction component b at contact node j (global axes;
    /// see the module docs) [1/stress]. `model` must be the one this was condensed from.
    /// Computed on the first call, kept for the next.
    pub fn surface_strain(&self, model: &BemModel) -> Result<&Mat<f64>, BemError> {
        if let Some((s, _)) = self.strain.get() {
            return Ok(s);
        }
        let t = std::time::Instant::now();
        let s = response_surface_strain(model, &self.nodes, &self.data, self.response())?;
        Ok(&self.strain.get_or_init(|| (s, t.elapsed().as_secs_f64())).0)
    }

    /// Wall time of the HBEM surface strain [s]; zero until it is computed.
    pub fn strain_s(&self) -> f64 {
        self.strain.get().map_or(0.0, |(_, t)| *t)
    }

    /// Wall time of the solves made after the condensation [s]: a factored body's solve for
    /// every unit load, when asked for ([`Self::matrix`]), and the HBEM strain.
    pub fn later_s(&self) -> f64 {
        self.solved.get().map_or(0.0, |s| s.seconds) + self.strain_s()
    }
}

/// Condenses `model` to the field nodes of its contact group `contact_group` (which must have
/// the [`BoundaryCondition::Contact`] condition): one LU, one multi-column solve.
pub fn condense(model: &BemModel, contact_group: &str) -> Result<ContactFlexibility, BemError> {
    condense_reusing(model, contact_group, None)
}

/// [`condense()`] with H and G assembled by [`assemble_reusing`] when `far` (the unchanged part
/// of the start mesh `model` was cut from) is given: the same matrices, the unchanged block
/// taken from `far` instead of integrated again.
pub fn condense_reusing(
    model: &BemModel,
    contact_group: &str,
    far: Option<&FarField>,
) -> Result<ContactFlexibility, BemError> {
    build(model, contact_group, far, false)
}

/// [`condense_reusing`] factored only: the system's LU and right sides are kept, and the body
/// solves per load ([`ContactFlexibility::displacements`]) or, when asked for its flexibility
/// or response, for every unit load then.
pub fn factor_reusing(
    model: &BemModel,
    contact_group: &str,
    far: Option<&FarField>,
) -> Result<ContactFlexibility, BemError> {
    build(model, contact_group, far, true)
}

/// [`condense_reusing`] (`factored_only` false) or [`factor_reusing`].
fn build(
    model: &BemModel,
    contact_group: &str,
    far: Option<&FarField>,
    factored_only: bool,
) -> Result<ContactFlexibility, BemError> {
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
    let asm = match far {
        Some(far) => assemble_reusing(model, far),
        None => model.assemble(),
    };
    let assembly_s = t_assembly.elapsed().as_secs_f64();
    let t_condense = std::time::Instant::now();
    // A is made in H's place (at the condensation's peak, H, G and the right-hand sides are all
    // it holds).
    let (a, b0, g) = model.linear_system_in_place_of_h(asm, &data);
    let n_dof = data.len();
    // Contact DOFs are traction-type, so each unit contact traction adds its G column to b.
    let contact_column = |r: usize, c: usize| g[(r, 2 * nodes[c / 2] + c % 2)];
    let (solved, factored) = if factored_only {
        let loads = Mat::from_fn(n_dof, 2 * m, contact_column);
        // G is not needed past the right-hand sides: its memory goes before the LU's.
        drop(g);
        let lu = LuFactors::new(a);
        model.check_pivots(lu.pivot_ratio())?;
        (OnceLock::new(), Mutex::new(Some(Factored { lu, b0, loads })))
    } else {
        let mut rhs = right_sides(&b0, 2 * m, contact_column);
        drop(g);
        model.solve_system(a, &mut rhs)?;
        (OnceLock::from(solved_from(rhs, &nodes)), Mutex::new(None))
    };
    let condense_s = t_condense.elapsed().as_secs_f64();
    // The strain is computed when first asked for; its points are checked now, so that a
    // contact node where the HBEM cannot be evaluated is an error of the condensation.
    check_strain_points(model, &nodes)?;
    Ok(ContactFlexibility {
        x: nodes.iter().map(|&k| field[k].position[0]).collect(),
        nodes,
        assembly_s,
        condense_s,
        data,
        solved,
        factored,
        strain: OnceLock::new(),
    })
}

/// The right sides [b0, loads]: the other data's column b0, then `count` load columns,
/// `load(r, c)` the entry of row r in load c.
fn right_sides(b0: &Mat<f64>, count: usize, load: impl Fn(usize, usize) -> f64) -> Mat<f64> {
    Mat::from_fn(
        b0.nrows(),
        1 + count,
        |r, c| if c == 0 { b0[(r, 0)] } else { load(r, c - 1) },
    )
}

/// The flexibility and offset read from the solved right sides `rhs` (column 0 the other
/// data's, 1 + c the unit load c's), which become the response.
fn solved_from(rhs: Mat<f64>, nodes: &[usize]) -> Solved {
    let m = nodes.len();
    // The unknowns at contact DOFs are the displacements themselves (unscaled).
    let matrix = Mat::from_fn(2 * m, 2 * m, |r, c| rhs[(2 * nodes[r / 2] + r % 2, 1 + c)]);
    let offset = nodes.iter().map(|&k| [rhs[(2 * k, 0)], rhs[(2 * k + 1, 0)]]).collect();
    Solved {
        matrix,
        offset,
        response: rhs,
        seconds: 0.0,
    }
}

impl ContactFlexibility {
    /// The whole boundary solution of `model` (u and t at every field node, global axes) under
    /// the traction `traction[j]` = (t_x, t_y) [stress] at contact node j (the order of
    /// [`ContactFlexibility::nodes`]), from the condensed response (no second assembly or
    /// solve, and exactly the state the flexibility describes), or for a factored body one
    /// solve. `model` must be the one condensed.
    pub fn boundary_solution(&self, model: &BemModel, traction: &[[f64; 2]]) -> BemSolution {
        let mut data = self.data.clone();
        for (&k, t) in self.nodes.iter().zip(traction) {
            for (b, &tb) in t.iter().enumerate() {
                data[2 * k + b] = Component::Traction(tb);
            }
        }
        if let Some(f) = self.factors().as_ref() {
            let tau = Mat::from_fn(2 * self.nodes.len(), 1, |c, _| traction[c / 2][c % 2]);
            let mut x = &f.b0 + &f.loads * &tau;
            f.lu.solve_in_place(x.as_mut());
            return model.boundary_values(&data, |k| x[(k, 0)]);
        }
        let response = self.response();
        let n_dof = data.len();
        let mut unknowns: Vec<f64> = (0..n_dof).map(|r| response[(r, 0)]).collect();
        for (j, t) in traction.iter().enumerate() {
            for (b, &tb) in t.iter().enumerate() {
                if tb != 0.0 {
                    let col = 1 + 2 * j + b;
                    for (r, x) in unknowns.iter_mut().enumerate() {
                        *x += response[(r, col)] * tb;
                    }
                }
            }
        }
        model.boundary_values(&data, |k| unknowns[k])
    }
}

/// The data of the response to a unit value of the traction component `loaded`: every
/// prescribed value zero (the other data enter the offset column only), the loaded component 1.
#[cfg(test)]
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
    let n_dof = 2 * model.discretisation.n_nodes();
    let rows = strain_rows(model, nodes)?;
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

/// One node's HBEM row: the coefficients of the nodal u, then of the nodal t (2N each).
type StrainRow = (Vec<f64>, Vec<f64>);

/// The HBEM rows of du_x/dx along the surface at the field nodes `nodes` ([`surface_strain`]):
/// per node, the coefficients of the nodal u and of the nodal t (2N each).
fn strain_rows(model: &BemModel, nodes: &[usize]) -> Result<Vec<StrainRow>, BemError> {
    let d = &model.discretisation;
    let evaluator = GradientEvaluator::new(model);
    nodes
        .par_iter()
        .map(|&k| {
            let (element, local) = d.nodes[k].element;
            let xi = d.interpolation[element].node_coordinates()[local];
            let tangent = d.geometry[element].tangent(xi);
            let rows = evaluator.rows(GradientPoint::Boundary { element, xi })?;
            Ok(rows.directional(0, [1.0, tangent[1] / tangent[0]]))
        })
        .collect()
}

/// Fails as [`strain_rows`] would ([`check_boundary_point`]): a contact node at an element's
/// end (ξ = ±1), where the HBEM boundary strain is not defined.
fn check_strain_points(model: &BemModel, nodes: &[usize]) -> Result<(), BemError> {
    let d = &model.discretisation;
    nodes.iter().try_for_each(|&k| {
        let (element, local) = d.nodes[k].element;
        check_boundary_point(model, element, d.interpolation[element].node_coordinates()[local])
    })
}

/// [`surface_strain`] of the unit contact loads straight from the condensed `response`
/// (columns 1 + c, [`ContactFlexibility::response`]) solved with `data`: the same numbers to
/// round-off in half the product. Of each component's u and t one is the unknown of the
/// response (a displacement where a traction is known, a traction scaled by G/L where a
/// displacement is known) and the other the unit load's datum, zero but for the loaded contact
/// traction component (1). So the m × 4N strain rows times the 4N × 2m boundary fields are the
/// m × 2N rows of the unknowns (the scale folded in) times the response, 2 m · 2N · 2m flops
/// instead of 2 m · 4N · 2m, plus each loaded component's traction coefficient.
fn response_surface_strain(
    model: &BemModel,
    nodes: &[usize],
    data: &[Component],
    response: &Mat<f64>,
) -> Result<Mat<f64>, BemError> {
    let rows = strain_rows(model, nodes)?;
    let s = model.traction_scale();
    let n_dof = data.len();
    let weights = Mat::from_fn(nodes.len(), n_dof, |i, k| match data[k] {
        Component::Traction(_) => rows[i].0[k],
        Component::Displacement(_) => rows[i].1[k] * s,
    });
    let unknowns = response.subcols(1, 2 * nodes.len());
    let mut strain = &weights * unknowns;
    for c in 0..2 * nodes.len() {
        let loaded = 2 * nodes[c / 2] + c % 2;
        for (i, row) in rows.iter().enumerate() {
            strain[(i, c)] += row.1[loaded];
        }
    }
    Ok(strain)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::bem::BemOptions;
    use crate::material::Elastic;

    /// The strain condensed from the response is the strain of the unit loads' boundary
    /// solutions ([`surface_strain`], the product over u and t both), to round-off, on the
    /// aluminium roller of cases/fig14_true_geometry.yaml (a fixed shaft: both kinds of
    /// unknown).
    fn fig14_roller() -> BemModel {
        let path = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("meshes/roller_r150_shaft15_A.msh");
        let (mesh, _) = crate::mesh::load(&path).unwrap();
        BemModel::new(
            mesh,
            Elastic::new(60_260.0, 0.31),
            crate::bem::fixed_shaft_roller_conditions(),
            BemOptions::default(),
        )
        .unwrap()
    }

    #[test]
    fn strain_from_the_response_is_the_strain_of_the_boundary_solutions() {
        let model = fig14_roller();
        let c = condense(&model, "contact").unwrap();
        assert_eq!(c.strain_s(), 0.0, "not computed before it is asked for");
        let responses: Vec<BemSolution> = (0..2 * c.nodes.len())
            .map(|col| {
                let loaded = 2 * c.nodes[col / 2] + col % 2;
                model.boundary_values(&unit_load_data(&c.data, loaded), |k| c.response()[(k, 1 + col)])
            })
            .collect();
        let want = surface_strain(&model, &c.nodes, &responses).unwrap();
        let scale = want.norm_max();
        let diff = (c.surface_strain(&model).unwrap() - &want).norm_max();
        assert!(
            scale > 0.0 && diff <= 1e-12 * scale,
            "differs by {diff:.3e} of {scale:.3e}"
        );
        // Kept: the second call returns the same matrix.
        let first: *const Mat<f64> = c.surface_strain(&model).unwrap();
        assert!(std::ptr::eq(first, c.surface_strain(&model).unwrap()));
    }

    /// A body factored only answers as the body solved at once: its displacements under a few
    /// loads are the flexibility's product, its boundary solution the response's, and the
    /// flexibility it solves for when asked is the one solved at once (the same LU, the same
    /// right sides). The two orders of the products (G's columns times the loads, then the
    /// solve; or the solve, then F times the loads) agree to the system's condition times the
    /// rounding, 1e-11 of the largest value (measured 1.4e-12).
    #[test]
    fn a_factored_body_answers_as_the_body_solved_at_once() {
        let model = fig14_roller();
        let solved = condense(&model, "contact").unwrap();
        let factored = factor_reusing(&model, "contact", None).unwrap();
        assert!(factored.is_factored_only() && !solved.is_factored_only());
        let m = solved.nodes.len();
        let loads = Mat::from_fn(2 * m, 3, |r, c| ((r * (c + 2)) % 7) as f64 - 3.0 + 0.1 * c as f64);
        let want = solved.matrix() * &loads;
        let got = factored.displacements(loads.as_ref());
        let scale = want.norm_max();
        assert!(
            (&got - &want).norm_max() <= 1e-11 * scale,
            "displacements: {:e} of {scale:e}",
            (&got - &want).norm_max()
        );
        assert!(
            factored.is_factored_only(),
            "answered without solving for every unit load"
        );
        let traction: Vec<[f64; 2]> = (0..m).map(|j| [0.3 * j as f64, 100.0 - j as f64]).collect();
        let (a, b) = (
            solved.boundary_solution(&model, &traction),
            factored.boundary_solution(&model, &traction),
        );
        let umax = a.displacement.iter().flatten().fold(0.0f64, |s, v| s.max(v.abs()));
        for (x, y) in a.displacement.iter().flatten().zip(b.displacement.iter().flatten()) {
            assert!((x - y).abs() <= 1e-11 * umax, "boundary displacement {x} vs {y}");
        }
        let tmax = a.traction.iter().flatten().fold(0.0f64, |s, v| s.max(v.abs()));
        for (x, y) in a.traction.iter().flatten().zip(b.traction.iter().flatten()) {
            assert!((x - y).abs() <= 1e-11 * tmax, "boundary traction {x} vs {y}");
        }
        let diff = (factored.matrix() - solved.matrix()).norm_max();
        assert!(
            diff <= 1e-14 * solved.matrix().norm_max(),
            "flexibility differs by {diff:e}"
        );
        assert!(!factored.is_factored_only(), "solved for every unit load once asked");
        assert!((&factored.displacements(loads.as_ref()) - &want).norm_max() <= 1e-11 * scale);
    }

    /// The strain's points are checked at the condensation: a contact node must lie strictly
    /// inside its element (a continuous element's end node would not), and the element exist.
    #[test]
    fn the_strains_points_must_lie_inside_existing_elements() {
        let model = fig14_roller();
        let count = model.discretisation.geometry.len();
        assert!(check_boundary_point(&model, 0, 0.5).is_ok());
        for (element, xi) in [(0, 1.0), (0, -1.0), (count, 0.0), (0, f64::NAN)] {
            assert!(
                matches!(
                    check_boundary_point(&model, element, xi),
                    Err(BemError::BadGradientPoint { .. })
                ),
                "element {element}, xi {xi}"
            );
        }
    }
}
