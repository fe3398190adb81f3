//! The BEM body model: a body meshed by boundary elements ([`crate::bem`]), condensed to the
//! contact grid whose nodes it shares ([`crate::bem::condense()`]).
//!
//! # Pair convention ([`super`])
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
//! The HBEM surface strain of [`crate::bem::condense`](mod@crate::bem::condense) enters the pair
//! convention the same way: p ↦ S_xy, q ↦ S_xx on either side.

pub mod kept;
pub mod setup;
pub mod stand_in;
mod surface;

use super::kind::Capabilities;
use super::{
    BodyFields, BodyModel, BoundaryField, ContactLoad, FieldError, Flexibility, InteriorQuery, InteriorResult, Side,
    StrainOperator,
};
use crate::bem::reuse::FarField;
use crate::bem::somigliana::interior_fields;
use crate::bem::{condense_reusing, factor_reusing, BemError, BemModel, BemSolution, ContactFlexibility};
use crate::grid::{ContactGrid, ElementKind};
use crate::interior::{InteriorOptions, InteriorSample};
use faer::{Mat, MatRef};

/// What the checks of a case ask of the `bem` model. A boundary element body: elastic only (the BEM has no aged kernels), with interior fields by
/// Somigliana's identity, its contact grid the contact elements of its mesh.
pub const CAPABILITIES: Capabilities = Capabilities {
    name: "bem",
    deforms: true,
    accepts_viscoelastic: false,
    interior_fields: true,
    boundary_elements: true,
};

/// A body modelled by the BEM, condensed to a contact grid whose nodes it shares.
#[derive(Debug)]
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
    /// The checks of [`Self::new`] before it condenses (cheap: no assembly): the grid's
    /// element kind, the contact group's field nodes at the grid's nodes, the contact surface
    /// facing the other body. `rollbem check` runs them as `run` does.
    pub fn check_contact(
        model: &BemModel,
        contact_group: &str,
        grid: &ContactGrid,
        side: Side,
    ) -> Result<(), BemError> {
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
        // Relative to each node's own element: a mesh file's round-off (a mid node 1e-11 of its
        // element off a straight element's centre, which the grid takes as straight) is far
        // below it, and so is any real mismatch above it, however fine the grid is elsewhere.
        let stride = grid.kind.node_stride();
        let tolerance = |i: usize| {
            let e = (i / stride).min(grid.n_elements() - 1);
            1e-6 * (grid.edges[e + 1] - grid.edges[e])
        };
        if let Some((_, (x_mesh, x_grid))) = xs
            .iter()
            .zip(&grid.nodes)
            .enumerate()
            .find(|(i, (a, b))| (*a - *b).abs() > tolerance(*i))
        {
            return Err(mismatch(format!(
                "mesh node at x = {x_mesh} but grid node at x = {x_grid}: the contact elements \
                 must coincide with the grid's elements"
            )));
        }
        let facing = match side {
            Side::A => -1.0,
            Side::B => 1.0,
        };
        let cos_limit = MAX_CONTACT_ANGLE_DEG.to_radians().cos();
        if let Some(k) = model
            .discretisation
            .nodes_of_group(g)
            .into_iter()
            .find(|&k| field[k].normal[1] * facing < cos_limit)
        {
            return Err(mismatch(format!(
                "the contact surface at x = {} does not face the other body (outward normal \
                 {:?}, expected within {MAX_CONTACT_ANGLE_DEG}° of (0, {facing}) for body {side:?}: \
                 the contact grid runs along x, so a contact group must stay within that angle \
                 of the contact's centre)",
                field[k].position[0], field[k].normal
            )));
        }
        Ok(())
    }

    /// Condenses `model` to the nodes of `grid` for a body on `side`.
    ///
    /// Fails unless `grid` uses discontinuous quadratic elements, the contact group's field
    /// nodes lie at the grid's node abscissae (to 1e-6 of their element's length: the grid of a mesh
    /// follows its curved elements, [`crate::grid::ContactGrid::from_mapped_edges`]), and the
    /// contact surface faces the other body (outward normal −y on A, +y on B, within
    /// [`MAX_CONTACT_ANGLE_DEG`]).
    pub fn new(model: BemModel, contact_group: &str, grid: &ContactGrid, side: Side) -> Result<Self, BemError> {
        Self::new_reusing(model, contact_group, grid, side, None, false)
    }

    /// [`Self::new`] for a model cut from a start mesh whose unchanged part `far` holds
    /// ([`crate::bem::reuse`]): the same body, its far-field block of H and G taken from `far`.
    /// With `factored_only` the body is factored and not solved for every unit load
    /// ([`crate::bem::factor_reusing`]): for a caller that asks for its response to a few loads
    /// ([`BodyModel::displacements`]) and its boundary field.
    pub fn new_reusing(
        model: BemModel,
        contact_group: &str,
        grid: &ContactGrid,
        side: Side,
        far: Option<&FarField>,
        factored_only: bool,
    ) -> Result<Self, BemError> {
        Self::check_contact(&model, contact_group, grid, side)?;
        let facing = match side {
            Side::A => -1.0,
            Side::B => 1.0,
        };
        let g = model.mesh.group_index(contact_group)?;
        let condensed = if factored_only {
            factor_reusing(&model, contact_group, far)?
        } else {
            condense_reusing(&model, contact_group, far)?
        };
        let extreme = contact_heights(&model, g)
            .into_iter()
            .map(|(_, y)| y * facing)
            .fold(f64::NEG_INFINITY, f64::max)
            * facing;
        let mut body = Self {
            contact_group: contact_group.to_string(),
            side,
            condensed,
            touch_y: extreme,
            model,
        };
        // The touching point is the surface at x = 0 (the contact frame's origin; for a convex
        // body drawn touching there also its extreme point, for a concave bore the only one);
        // a contact group that does not cross x = 0 keeps its extreme point.
        if let Some(y0) = body.surface_height(0.0) {
            body.touch_y = y0;
        }
        Ok(body)
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
            if let Some(xi) = geom.parameter_at_x(x) {
                return Some(geom.point(xi)[1]);
            }
        }
        None
    }
}

/// Largest angle [°] between a contact node's outward normal and the direction facing the
/// other body (−y on A, +y on B). The contact grid is parametrised by x, which stays one-to-one
/// along an arc well short of 90°; 60° admits conformal contacts whose arc spans up to 120°.
pub const MAX_CONTACT_ANGLE_DEG: f64 = 60.0;

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
    /// the contact group is (q, p) on A and (−q, −p) on B), from the condensed response
    /// ([`ContactFlexibility::boundary_solution`]).
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
        let traction: Vec<[f64; 2]> = p.iter().zip(q).map(|(p, q)| [sign * q, sign * p]).collect();
        Ok(c.boundary_solution(&self.model, &traction))
    }

    /// The boundary field under nodal contact tractions on `grid` (see
    /// [`BodyFields::boundary_field`]): [`Self::contact_solution`] sampled at ξ = −1, 1, 0 of
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
    /// contact tractions (see [`BodyFields::interior`]), by Somigliana's identity
    /// ([`crate::bem::somigliana`]) from [`Self::contact_solution`]. The mesh's axes are the contact
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
        let f = self.condensed.matrix();
        Flexibility {
            hp: Mat::from_fn(m, m, |i, j| f[(2 * i + 1, 2 * j + 1)]),
            hq: Mat::from_fn(m, m, |i, j| f[(2 * i + 1, 2 * j)]),
            wp: Mat::from_fn(m, m, |i, j| f[(2 * i, 2 * j + 1)]),
            wq: Mat::from_fn(m, m, |i, j| f[(2 * i, 2 * j)]),
        }
    }

    /// The displacements under the loads, per load (module docs: on either side h = F_yy p +
    /// F_yx q and w = F_xy p + F_xx q, the global traction (q, p) on A and (−q, −p) on B whose
    /// sign cancels against that of the shares): one solve of a factored body for the k loads
    /// together, the flexibility's product otherwise. Same `grid`/`side` contract as
    /// [`BodyModel::flexibility`].
    fn displacements(&self, grid: &ContactGrid, side: Side, p: MatRef<'_, f64>, q: MatRef<'_, f64>) -> [Mat<f64>; 2] {
        self.assert_same_grid(grid, side);
        let (m, k) = (grid.n_nodes(), p.ncols());
        // Global axes with the sign folded out: rows 2j, 2j + 1 take q and p.
        let loads = Mat::from_fn(2 * m, k, |r, c| if r % 2 == 0 { q[(r / 2, c)] } else { p[(r / 2, c)] });
        let u = self.condensed.displacements(loads.as_ref());
        [
            Mat::from_fn(m, k, |i, c| u[(2 * i + 1, c)]),
            Mat::from_fn(m, k, |i, c| u[(2 * i, c)]),
        ]
    }

    /// Distance of the undeformed contact surface from the common tangent at x [length]
    /// (y − y_touch on A, y_touch − y on B): positive where a convex surface bends away from the
    /// other body, negative where a concave bore bends towards it; beyond the contact group,
    /// the value at its nearer end.
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
        (y - self.touch_y) * facing
    }

    /// (assembly, condensation + HBEM surface strain) [s].
    fn stage_seconds(&self) -> (f64, f64) {
        (
            self.condensed.assembly_s,
            self.condensed.condense_s + self.condensed.later_s(),
        )
    }

    /// The HBEM surface strain ∂w/∂x at the contact nodes (module docs, "Surface strain by
    /// HBEM") in the pair convention: p ↦ S_xy, q ↦ S_xx on either side (the sign of w and of
    /// the loads flip together on B). Linear: the prescribed data of a bem body are zero in
    /// contact runs. Same `grid`/`side` contract as [`BodyModel::flexibility`].
    fn strain_operator(&self, grid: &ContactGrid, side: Side) -> Option<StrainOperator> {
        self.assert_same_grid(grid, side);
        let m = grid.n_nodes();
        // The condensation checked the strain's points, so this cannot fail but for an
        // internal error, which leaves the run without the HBEM slip check (logged).
        let s = match self.condensed.surface_strain(&self.model) {
            Ok(s) => s,
            Err(e) => {
                log::error!("body {side:?}: the HBEM surface strain failed: {e}");
                return None;
            }
        };
        Some(StrainOperator {
            p: Mat::from_fn(m, m, |i, j| s[(i, 2 * j + 1)]),
            q: Mat::from_fn(m, m, |i, j| s[(i, 2 * j)]),
        })
    }
}

impl BodyFields for BemBody {
    /// The boundary solution under the nodal contact tractions (on A (q, p), on B (−q, −p) in
    /// global axes), from the condensed response ([`BemBody::contact_solution`]), sampled at
    /// ξ = −1, 1, 0 of every element.
    fn boundary_field(&self, load: &ContactLoad) -> Option<Result<BoundaryField, FieldError>> {
        Some(
            self.boundary_solution(load.grid, load.pressure, load.shear)
                .map_err(FieldError::from),
        )
    }

    /// Somigliana's identity, see [`BemBody::interior_samples`]; the query's side must be the
    /// body's own.
    fn interior(&self, query: &InteriorQuery) -> InteriorResult {
        let (side, load) = (query.side, &query.load);
        if side != self.side {
            return Err(FieldError::Bem(BemError::ContactGridMismatch {
                path: self.model.mesh.source.clone(),
                group: self.contact_group.clone(),
                problem: format!("body built for side {:?}, asked for side {side:?}", self.side),
            }));
        }
        Ok(self.interior_samples(load.grid, load.pressure, load.shear, query.points, &query.options)?)
    }

    /// The mesh's undeformed contact surface ([`BodyModel::profile`]).
    fn field_surface(&self, x: f64) -> f64 {
        self.profile(x)
    }
}

/// A `bem` body's stand-in for the passes of an error-controlled grid
/// ([`crate::body::BodySetup::pass_stand_in`]): its half-plane plus the smooth remainder fitted
/// on `levels` ([`stand_in`]), or None where the remainder cannot follow the body; its
/// levels' builds share `run`'s caches when given.
pub(crate) fn pass_stand_in(
    setup: &setup::BemSetup,
    levels: &[&ContactGrid],
    side: Side,
    rolling: super::setup::Rolling,
    run: Option<&super::run_caches::RunCaches>,
) -> Result<Option<super::setup::PassStandIn>, super::setup::BuildError> {
    // A cover thinner than half the grid's span has a remainder that varies on the scale of
    // its thickness, which the series cannot follow (the shipped tyre layers differ from
    // their stand-ins by more than p0; a bore's 15 mm rim under a 19 mm grid by 2e-5); a
    // contact group that does not cover the grid keeps nodes of its own inside it, whose
    // flexibility carried over to the grid the remainder does not follow (3e-3 on
    // cases/carter_051_true_nonmatching.yaml before its cuts conformed to the grid). Both
    // keep the full BEM in every pass. A group that covers the grid is cut to the grid's
    // elements there, its own nodes or not ([`crate::mesh::cuts`]).
    let (lo, hi) = (levels[0].edges[0], levels[0].edges[levels[0].n_elements()]);
    let thin = super::setup::BodySetup::layer_thickness(setup).is_some_and(|b| b < 0.5 * (hi - lo));
    let start = setup.start_mesh.as_deref().unwrap_or(&setup.mesh).contact_grid();
    let slack = 1e-9 * (hi - lo);
    let covers = start.edges[0] <= lo + slack && start.edges[start.n_elements()] >= hi - slack;
    if thin || !covers {
        return Ok(None);
    }
    let stand_in = stand_in::BemStandIn::of(setup, levels, side, rolling, run)?;
    let check = stand_in
        .gives_results()
        .then(|| std::sync::Arc::new(stand_in.checking()) as std::sync::Arc<dyn super::setup::BodySetup>);
    let check_change = stand_in.gives_results().then(|| stand_in.check_change());
    Ok(Some(super::setup::PassStandIn {
        check_change,
        condense_s: stand_in.condense_seconds(),
        body: std::sync::Arc::new(stand_in),
        check,
    }))
}
