//! The BEM model's setup: a body given by its boundary mesh, material and boundary conditions,
//! condensed to the contact grid; on a refined grid its mesh is cut along the grid
//! ([`crate::mesh::cuts`]).

use super::kept::Kept;
use super::BemBody;
use crate::bem::reuse::FarFieldCache;
use crate::bem::{BemModel, BemOptions, BoundaryCondition};
use crate::body::setup::{
    BodySetup, BuildContext, BuildError, ChangedFor, ContactMesh, PassStandIn, Rolling, SurfaceAt,
    CHECK_QUADRATURE_TOLERANCE,
};
use crate::body::transfer::Transferred;
use crate::body::{Body, BodyLineage, RunCaches, Side, WithCircularProfile};
use crate::grid::ContactGrid;
use crate::material::Elastic;
use crate::mesh::bisect::bisect_outside_group;
use crate::mesh::coarsen::coarsen_outside_group;
use crate::mesh::cuts::{cut_along_grid_on, Circle};
use crate::mesh::LoadedMesh;
use std::sync::Arc;

/// Largest length ratio of neighbouring elements where a cut contact segment meets the rest of
/// the mesh: the ratio an error-controlled grid keeps between its own elements.
pub const MAX_TRANSITION_RATIO: f64 = 2.0;

/// Most halvings of one transition element for the memory estimate: the grid grades an element
/// at most 2⁻¹² per pass, and a transition follows its neighbour's length within
/// [`MAX_TRANSITION_RATIO`], so some tens cover the deepest grids.
pub const MAX_TRANSITION_HALVINGS: usize = 40;

/// A condensed BEM body and its own contact grid (the grid's elements as the body's mesh maps
/// them), which [`BemSetup::build_keeping`] gives back when asked to keep it.
pub(super) type CondensedOnOwnGrid = (ContactGrid, Arc<BemBody>);

/// A `bem` body of a scene: its mesh, material and boundary conditions.
#[derive(Debug, Clone)]
pub struct BemSetup {
    /// The checked and oriented mesh (cut along the grid on a refined grid).
    pub mesh: LoadedMesh,
    /// Elastic constants.
    pub material: Elastic,
    /// Name of the contact group.
    pub contact: String,
    /// Boundary condition of every group: the other groups in name order, the contact group
    /// last (the order numbers the unknowns).
    pub conditions: Vec<(String, BoundaryCondition)>,
    /// Profile radius [length]: `profile_radius` if given, else the circle fitted to the
    /// contact group (used for the Hertz estimates).
    pub radius: f64,
    /// A radius that replaces the mesh's own contact profile in the gap (a BEM block standing
    /// in for a cylinder, paper Fig. 2), if the case gives one.
    pub profile_radius: Option<f64>,
    /// The start mesh a refined grid's cuts are made in (None: `mesh` is the start mesh).
    pub start_mesh: Option<Arc<LoadedMesh>>,
    /// The start mesh's far-field block of H and G ([`crate::bem::reuse`]), integrated by the
    /// first setup that follows a grid (or by the start mesh's own condensation, when the
    /// stand-ins' first level is its own grid) and shared by every setup that follows one from
    /// this one (`Default::default()` when constructing a setup).
    pub far_field: FarFieldCache,
    /// The circle of the contact segment: exact when the body was generated from its geometry
    /// (`geometry:`), fitted to the contact nodes of a mesh file that lie on one circle
    /// ([`crate::mesh::smooth::contact_curve`]). The cuts of [`BodySetup::follow_grid`] then place
    /// their new nodes on it rather than on each element's quadratic. None for a mesh file whose
    /// contact group is no circle.
    pub contact_circle: Option<Circle>,
    /// The identity of the body's mesh, which its condensation is kept under in the run's
    /// caches ([`crate::body::RunCaches`], [`super::kept`]): shared by every setup that follows a
    /// grid from this one (the grid names the cut mesh), fresh for a mesh changed outside the
    /// contact (the same grid, another flexibility).
    pub lineage: BodyLineage,
    /// Whether [`BodySetup::build`] keeps its condensation in the run's caches: set on the body
    /// bisected outside the contact for the run ([`ChangedFor::Run`]: the error control adopted
    /// it, src/adapt/body_mesh.rs), whose first build on the finest grid its stand-in is fitted
    /// on serves the next check of its mesh as its given body.
    pub keep_builds: bool,
    /// Relative accuracy of the element integrals (1e-12; a body changed for the check of the
    /// body mesh's error, [`ChangedFor::Check`], looser).
    pub quadrature_tolerance: f64,
    /// What [`BodySetup::surface_at`] reads of `mesh`'s contact group, computed with the mesh
    /// (every constructor here sets it from the mesh it sets).
    pub shape: ContactShape,
}

/// The contact group's x-range, touching height and fitted radius: read at every node of
/// every grid ([`BodySetup::surface_at`]: the contact frame, the stand-ins' slopes and
/// profiles), so computed once per mesh rather than per call.
#[derive(Debug, Clone, Copy)]
pub struct ContactShape {
    /// x-range of the contact group [length].
    pub range: [f64; 2],
    /// Height y of the contact surface at x = 0 [length], if the group reaches it.
    pub touch: Option<f64>,
    /// Signed radius of the circle fitted to the group ([`LoadedMesh::contact_radius`]) [length].
    pub radius: f64,
}

impl ContactShape {
    /// The shape of `mesh`'s contact group.
    pub fn of(mesh: &LoadedMesh) -> Self {
        Self {
            range: mesh.contact_range(),
            touch: mesh.surface_at(0.0).map(|(y, _)| y),
            radius: mesh.contact_radius(),
        }
    }
}

impl BemSetup {
    /// A body on its start mesh: the profile radius `profile_radius` when the case gives one,
    /// else the mesh's own; nothing cut or cached yet.
    pub fn on_start_mesh(
        mesh: LoadedMesh,
        material: Elastic,
        contact: String,
        conditions: Vec<(String, BoundaryCondition)>,
        profile_radius: Option<f64>,
        contact_circle: Option<Circle>,
    ) -> Self {
        let shape = ContactShape::of(&mesh);
        Self {
            radius: profile_radius.unwrap_or(shape.radius),
            shape,
            mesh,
            material,
            contact,
            conditions,
            profile_radius,
            start_mesh: None,
            far_field: Default::default(),
            contact_circle,
            lineage: BodyLineage::fresh(),
            keep_builds: false,
            quadrature_tolerance: BemOptions::default().quadrature_tolerance,
        }
    }

    /// The body with its far-field cache reusing or not (`contact.grid.reuse_far_field`,
    /// [`FarFieldCache::new`]).
    pub fn reusing_far_field(self, reuse: bool) -> Self {
        Self {
            far_field: FarFieldCache::new(reuse),
            ..self
        }
    }

    /// The BEM model of the body's mesh (its discretisation; nothing assembled).
    fn bem_model(&self) -> Result<BemModel, BuildError> {
        Ok(BemModel::new(
            self.mesh.mesh.clone(),
            self.material,
            self.conditions.clone(),
            self.options(),
        )?)
    }

    /// The model of the body's mesh, condensed to its own contact nodes. A setup that follows
    /// a refined grid (`start_mesh` set) takes the unchanged part of H and G from the run's
    /// [`FarFieldCache`], integrating it on first use: the same body, assembled once per run
    /// where the cuts leave the mesh as it was. With `seed_far_field`, a start mesh condensed
    /// on its own grid before the grids cut from it (the first of the stand-ins' levels) is
    /// assembled the same way, so that its far field, integrated here as part of its own
    /// assembly, is not integrated again by the next level. With `factored_only` the body is
    /// factored, not solved for every unit load ([`BemBody::new_reusing`]).
    fn own_body(&self, side: Side, seed_far_field: bool, factored_only: bool) -> Result<BemBody, BuildError> {
        let t0 = std::time::Instant::now();
        let model_of = |mesh: &LoadedMesh| {
            BemModel::new(
                mesh.mesh.clone(),
                self.material,
                self.conditions.clone(),
                self.options(),
            )
            .ok()
        };
        let far = match &self.start_mesh {
            Some(start) => self.far_field.get_or_build(|| model_of(start)),
            None if seed_far_field => self.far_field.get_or_build(|| model_of(&self.mesh)),
            None => None,
        };
        let far_s = t0.elapsed().as_secs_f64();
        let mut body = BemBody::new_reusing(
            self.bem_model()?,
            &self.contact,
            &self.mesh.contact_grid(),
            side,
            far.as_deref(),
            factored_only,
        )?;
        // The far field's integration (first pass only) is part of the assembly.
        body.condensed.assembly_s += far_s;
        Ok(body)
    }

    /// The body on `ctx.grid`: condensed anew (factored only, when the context asks for
    /// responses only: [`BuildContext::responses_only`]), or taken from the run's caches
    /// ([`BuildContext::run`]) when this mesh was condensed for the same side before in the
    /// run; with `keep`, a new condensation is kept there. With `seed_far_field` a start mesh's
    /// condensation leaves its far field for the setups that follow grids from it
    /// (`own_body`). With `keep` the condensed BEM body comes back too, on its own contact
    /// grid (the grid's elements as the body's mesh maps them), kept or not.
    pub(super) fn build_keeping(
        &self,
        ctx: &BuildContext,
        keep: bool,
        seed_far_field: bool,
    ) -> Result<(Box<dyn Body>, Option<CondensedOnOwnGrid>), BuildError> {
        let own = self.mesh.contact_grid();
        let taken = ctx
            .run
            .and_then(|run| run.condensed::<BemBody>(&self.lineage, ctx.side, &own));
        let mut condensed = None;
        let body: Box<dyn Body> = match taken {
            Some(kept) => {
                log::info!(
                    target: crate::logging::PROGRESS,
                    "body {:?}: BEM of {} boundary elements, condensed on this grid before",
                    ctx.side,
                    self.mesh.mesh.elements.len()
                );
                // A body kept factored only solves for every unit load now, in the build (which
                // runs beside the other body's), rather than when the problem asks for it.
                if !ctx.responses_only {
                    kept.condensed.matrix();
                }
                if keep {
                    condensed = Some(kept.clone());
                }
                Box::new(Kept(kept, false))
            }
            None => {
                log::info!(
                    target: crate::logging::PROGRESS,
                    "body {:?}: BEM of {} boundary elements ({} nodes), condensing to the contact nodes",
                    ctx.side,
                    self.mesh.mesh.elements.len(),
                    self.mesh.mesh.nodes.len()
                );
                let body = self.own_body(ctx.side, seed_far_field, ctx.responses_only)?;
                if keep {
                    let body = Arc::new(body);
                    if let Some(run) = ctx.run {
                        run.keep(&self.lineage, ctx.side, &own, body.clone());
                    }
                    condensed = Some(body.clone());
                    Box::new(Kept(body, true))
                } else {
                    Box::new(body)
                }
            }
        };
        let condensed = condensed.map(|b| (own.clone(), b));
        let on_grid: Box<dyn Body> = if own.coincides_with(ctx.grid) {
            body
        } else {
            let t = Transferred {
                inner: body,
                own_grid: own,
                side: ctx.side,
            };
            t.check(ctx.grid)?;
            Box::new(t)
        };
        let body: Box<dyn Body> = match self.profile_radius {
            Some(r) => Box::new(WithCircularProfile {
                inner: on_grid,
                radius: r,
            }),
            None => on_grid,
        };
        Ok((body, condensed))
    }

    /// The mesh with its elements outside the contact group bisected on their own curves
    /// ([`crate::mesh::bisect`]). Its far field differs from the start mesh's, so the bisected
    /// body is assembled afresh: no start mesh, a cache of its own, built only if the body is
    /// condensed again (adopted by the error control, [`FarFieldCache::for_another_mesh`]).
    pub(super) fn free_boundary_bisected(&self, changed_for: ChangedFor) -> BemSetup {
        let mesh = LoadedMesh {
            mesh: bisect_outside_group(&self.mesh.mesh, self.mesh.contact_group),
            ..self.mesh.clone()
        };
        BemSetup {
            shape: ContactShape::of(&mesh),
            mesh,
            start_mesh: None,
            far_field: self.far_field.for_another_mesh(),
            lineage: BodyLineage::fresh(),
            keep_builds: changed_for == ChangedFor::Run,
            quadrature_tolerance: self.quadrature_tolerance_for(changed_for),
            ..self.clone()
        }
    }

    /// The mesh with its elements outside the contact group merged in pairs
    /// ([`crate::mesh::coarsen`]), None when there are none to merge. Assembled afresh, as
    /// [`Self::free_boundary_bisected`], and nothing of it kept: it is solved once.
    pub(super) fn free_boundary_coarsened(&self, changed_for: ChangedFor) -> Option<BemSetup> {
        let mesh = LoadedMesh {
            mesh: coarsen_outside_group(&self.mesh.mesh, self.mesh.contact_group)?,
            ..self.mesh.clone()
        };
        Some(BemSetup {
            shape: ContactShape::of(&mesh),
            mesh,
            start_mesh: None,
            far_field: self.far_field.for_another_mesh(),
            lineage: BodyLineage::fresh(),
            keep_builds: false,
            quadrature_tolerance: self.quadrature_tolerance_for(changed_for),
            ..self.clone()
        })
    }

    /// The element integrals' accuracy of this body changed for `changed_for`.
    fn quadrature_tolerance_for(&self, changed_for: ChangedFor) -> f64 {
        match changed_for {
            ChangedFor::Check => CHECK_QUADRATURE_TOLERANCE,
            ChangedFor::Run => self.quadrature_tolerance,
        }
    }

    /// The BEM options of the body: the defaults with its integrals' accuracy.
    fn options(&self) -> BemOptions {
        BemOptions {
            quadrature_tolerance: self.quadrature_tolerance,
            ..BemOptions::default()
        }
    }

    /// The setup whose mesh is the start mesh cut along `grid` ([`BodySetup::follow_grid`]).
    pub(super) fn followed(&self, grid: &ContactGrid) -> BemSetup {
        let start = self.start_mesh.clone().unwrap_or_else(|| Arc::new(self.mesh.clone()));
        let mesh = LoadedMesh {
            mesh: cut_along_grid_on(&start, grid, MAX_TRANSITION_RATIO, self.contact_circle.as_ref()),
            ..(*start).clone()
        };
        BemSetup {
            shape: ContactShape::of(&mesh),
            mesh,
            start_mesh: Some(start),
            ..self.clone()
        }
    }
}

impl BodySetup for BemSetup {
    fn model_name(&self) -> &'static str {
        "bem"
    }

    fn radius(&self) -> f64 {
        self.radius
    }

    fn hertz_material(&self) -> Option<Elastic> {
        Some(self.material)
    }

    /// A flat body's twin has a radius 1e6 times the mesh's extent: the half-space model takes
    /// its displacement datum at its radius, which must be finite, and the contact does not
    /// feel that curvature.
    fn half_plane_twin(&self) -> Option<std::sync::Arc<dyn BodySetup>> {
        let radius = if self.radius.is_finite() {
            self.radius
        } else {
            1e6 * self.mesh.mesh.size()
        };
        Some(std::sync::Arc::new(crate::body::half_space::setup::HalfSpaceSetup {
            material: self.material,
            radius,
        }))
    }

    fn contact_mesh(&self) -> Option<ContactMesh<'_>> {
        Some(ContactMesh {
            mesh: &self.mesh,
            group: &self.contact,
        })
    }

    /// The mesh's contact surface (clamped to the contact group's x-range), its profile from
    /// its touching point at x = 0, turning about the contact group's fitted circle. The slope
    /// is the element's, or the contact circle's where the two agree to within the round-off
    /// of the element's nodes (src/body/bem/surface.rs).
    fn surface_at(&self, x: f64, side: Side) -> Option<SurfaceAt> {
        let [x0, x1] = self.shape.range;
        let xc = x.clamp(x0, x1);
        // What `LoadedMesh::surface_at` gives, with the element kept for its round-off.
        let (element, xi) = self.mesh.contact_element_at(xc)?;
        let (y, slope) = element.height_and_slope(xi);
        let touch = self.shape.touch.unwrap_or(y);
        Some(SurfaceAt {
            slope_angle: self.slope_angle_at(&element, xi, [xc, y], slope.atan()),
            profile: (y - touch) * side.sign(),
            radius: self.shape.radius,
        })
    }

    /// The profile radius, or the extent of the mesh (its bounding box's diagonal) where that
    /// is smaller: a flat body (a layer, a block: radius ∞) has its datum at its own fixed
    /// boundary, not infinitely far.
    fn datum_distance(&self) -> f64 {
        self.radius.abs().min(self.mesh.mesh.size())
    }

    /// The distance from the contact node nearest x = 0 to the nearest node of a `fixed` group
    /// [length], when that lies closer than half the body's radius (a cover layer on a rigid
    /// core).
    fn layer_thickness(&self) -> Option<f64> {
        let fixed: Vec<usize> = self
            .conditions
            .iter()
            .filter(|(_, c)| matches!(c, BoundaryCondition::Fixed))
            .filter_map(|(g, _)| self.mesh.mesh.group_index(g).ok())
            .collect();
        let depth = self.mesh.depth_below_contact(&fixed)?;
        (depth < 0.5 * self.radius.abs()).then_some(depth)
    }

    /// The mesh's geometric nodes plus one field node per discontinuous contact element.
    fn discretisation_nodes(&self) -> Option<usize> {
        let lm = &self.mesh;
        let contact_elements = lm.mesh.elements.iter().filter(|e| e.group == lm.contact_group).count();
        Some(lm.mesh.nodes.len() + contact_elements)
    }

    /// Each contact element cut off adds an end node, a mid node and a field node; the graded
    /// transitions at the contact's two ends add at most two nodes per halving of each of
    /// their elements, [`MAX_TRANSITION_HALVINGS`] at most. The error control's check of the
    /// body mesh then solves the final grid once with every element outside the contact
    /// bisected, which adds at most two nodes per such element (a quadratic's two new mid
    /// nodes). Not covered: the further bisections it adopts when the mesh outside the contact
    /// is too coarse for the tolerance.
    fn discretisation_nodes_on(&self, contact_elements: usize) -> Option<usize> {
        let lm = &self.mesh;
        let own = lm.mesh.elements.iter().filter(|e| e.group == lm.contact_group).count();
        let transitions = 2 * MAX_TRANSITION_HALVINGS;
        let outside = lm.mesh.elements.len() - own + transitions;
        let added = 3 * contact_elements.saturating_sub(own) + 2 * transitions + 2 * outside;
        self.discretisation_nodes().map(|n| n + added)
    }

    /// The contact group cut into its elements bisected `bisections` times adds three nodes per
    /// new element; each bisection halves the contact's end elements, and one more halving of
    /// each neighbour outside keeps the lengths' ratio within [`MAX_TRANSITION_RATIO`] (one
    /// element and two nodes a side per bisection: the levels start on the mesh's own grid,
    /// whose neighbours already meet that ratio). The check of the mesh bisects every element
    /// outside the contact: two nodes each. A cover thinner than half its contact group's span
    /// offers no stand-in (src/body/bem.rs `pass_stand_in`): None.
    fn stand_in_nodes(&self, bisections: usize) -> Option<usize> {
        let lm = &self.mesh;
        let grid = lm.contact_grid();
        let span = grid.edges[grid.n_elements()] - grid.edges[0];
        if self.layer_thickness().is_some_and(|b| b < 0.5 * span) {
            return None;
        }
        let own = lm.mesh.elements.iter().filter(|e| e.group == lm.contact_group).count();
        let cut = own.saturating_mul(1usize << bisections.min(30));
        let transitions = 2 * bisections;
        let outside = lm.mesh.elements.len() - own + transitions;
        let added = 3 * cut.saturating_sub(own) + 2 * transitions + 2 * outside;
        self.discretisation_nodes().map(|n| n + added)
    }

    fn notices(&self) -> &[String] {
        &self.mesh.notices
    }

    /// The model's boundary data (held against rigid motion, no pressure mode of an
    /// incompressible body) and its contact nodes against its own contact grid, facing the
    /// other body: what [`Self::build`] checks before it assembles.
    fn preflight(&self, ctx: &BuildContext) -> Result<(), BuildError> {
        let model = self.bem_model()?;
        model.boundary_data(&[])?;
        BemBody::check_contact(&model, &self.contact, &self.mesh.contact_grid(), ctx.side)?;
        Ok(())
    }

    /// Condensed to its own contact nodes; if those differ from the grid's, its flexibility is
    /// carried over by [`Transferred`]. With `profile_radius`, the gap sees that circle.
    fn build(&self, ctx: &BuildContext) -> Result<Box<dyn Body>, BuildError> {
        Ok(self.build_keeping(ctx, self.keep_builds, false)?.0)
    }
    /// The half-plane plus its smooth remainder, fitted on `levels` ([`super::stand_in`]),
    /// the levels' builds sharing `run`'s caches.
    fn pass_stand_in(
        &self,
        levels: &[&ContactGrid],
        side: Side,
        rolling: Rolling,
        run: Option<&RunCaches>,
    ) -> Result<Option<PassStandIn>, BuildError> {
        // Made by the folder's module, which wires a setup to its stand-in: the stand-in is
        // built from the setup, so the setup does not name it.
        super::pass_stand_in(self, levels, side, rolling, run)
    }

    fn follow_grid(&self, grid: &ContactGrid) -> Option<Arc<dyn BodySetup>> {
        Some(Arc::new(self.followed(grid)))
    }

    /// The mesh with its elements outside the contact group bisected on their own curves
    /// ([`crate::mesh::bisect`]). Its far field differs from the start mesh's, so the bisected
    /// body is assembled afresh: no start mesh, a cache of its own, built only if the body is
    /// condensed again (adopted by the error control, [`FarFieldCache::for_another_mesh`]).
    fn with_free_boundary_bisected(&self, changed_for: ChangedFor) -> Option<Arc<dyn BodySetup>> {
        Some(Arc::new(self.free_boundary_bisected(changed_for)))
    }

    /// The mesh with its elements outside the contact group merged in pairs
    /// ([`crate::mesh::coarsen`]).
    fn with_free_boundary_coarsened(&self, changed_for: ChangedFor) -> Option<Arc<dyn BodySetup>> {
        self.free_boundary_coarsened(changed_for)
            .map(|s| Arc::new(s) as Arc<dyn BodySetup>)
    }

    /// The mesh's path (or label) and its groups other than the contact group.
    fn free_boundary_label(&self) -> Option<String> {
        let m = &self.mesh;
        let groups: Vec<&str> = m
            .mesh
            .groups
            .iter()
            .enumerate()
            .filter(|(i, _)| *i != m.contact_group)
            .map(|(_, g)| g.name.as_str())
            .collect();
        Some(format!("{}, groups {}", m.path.display(), groups.join(", ")))
    }
}

/// The roller R 150 on a shaft of 15 of cases/fig14_true_geometry.yaml (body A) in `material`,
/// on its start mesh, whose Gmsh file puts the mid node of the contact element at the centre
/// 4.2e-11 mm off x = 0 (for the tests of this module and of the stand-ins).
#[cfg(test)]
pub(crate) fn fig14_roller_in(material: Elastic) -> BemSetup {
    let path = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("meshes/roller_r150_shaft15_A.msh");
    let (mesh, notices) = crate::mesh::load(&path).unwrap();
    let mesh = LoadedMesh::new(path, mesh, notices, "contact").unwrap();
    let conditions = crate::bem::fixed_shaft_roller_conditions();
    BemSetup::on_start_mesh(mesh, material, "contact".into(), conditions, None, None)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::adapt::cells::{Action, DyadicGrid};
    use crate::material::Elastic;

    /// The roller of [`fig14_roller_in`] in steel.
    fn fig14_roller() -> BemSetup {
        fig14_roller_in(Elastic::new(210_000.0, 0.3))
    }

    /// The build context of body A on `grid`, rolling in +x.
    fn side_a_on(grid: &ContactGrid) -> BuildContext<'_> {
        BuildContext {
            grid,
            side: Side::A,
            rolling: crate::body::Rolling {
                direction: 1.0,
                speed: None,
            },
            pair: None,
            responses_only: false,
            run: None,
        }
    }

    /// A grid graded 12 times towards both ends of the contact (elements of 1/4096 of the
    /// start's there) is followed by the mesh, and the body builds on it: its contact nodes are
    /// the grid's to within 1e-6 of each element. Compared with the grid's smallest spacing
    /// instead, the Gmsh round-off of the uncut centre element's mid node (4.2e-11 mm, 1e-9 of
    /// that element) refused the mesh rollbem had cut itself.
    #[test]
    fn a_deeply_graded_grid_is_followed_and_built() {
        let setup = fig14_roller();
        let start = DyadicGrid::new(&setup.mesh.contact_grid());
        let n = start.len();
        let (lo, hi) = (start.root().edges[0], start.root().edges[n]);
        let mut action = vec![Action::Keep; n];
        action[0] = Action::GradeTowards(lo, 12);
        action[n - 1] = Action::GradeTowards(hi, 12);
        let grid = start.refined(&action).grid();
        assert!(
            grid.node_spacing() * 1e-6 < 4.2e-11,
            "the grid is fine enough to show the old refusal"
        );
        let followed = setup.follow_grid(&grid).expect("a BEM body follows the grid");
        let own = followed.contact_mesh().unwrap().mesh.contact_grid();
        assert_eq!(own.edges.len(), grid.edges.len(), "one mesh element per grid element");
        for (e, (a, b)) in own.edges.iter().zip(&grid.edges).enumerate() {
            // The x of a point placed on the curve at the grid's x: round-off of the root.
            let h = grid.edges[e.max(1)] - grid.edges[e.max(1) - 1];
            assert!((a - b).abs() <= 1e-9 * h, "edge {e}: mesh {a}, grid {b}");
        }
        let ctx = side_a_on(&grid);
        followed.build(&ctx).expect("the body builds on the grid it followed");
    }

    /// The first of the stand-ins' levels, condensed on the start mesh's own grid, assembles
    /// it through the far-field cache the next levels cut from it share: the same flexibility
    /// to the bit as the plain assembly (which a fixed grid keeps, leaving the cache empty), and
    /// the cache filled, so that a level cut from the start mesh integrates its far field no
    /// more.
    #[test]
    fn the_start_meshs_own_level_seeds_the_far_field() {
        let plain = fig14_roller();
        let seeded = fig14_roller();
        let grid = plain.mesh.contact_grid();
        let ctx = side_a_on(&grid);
        let a = plain.build_keeping(&ctx, false, false).unwrap().0;
        assert!(!plain.far_field.is_built(), "a plain build leaves the cache empty");
        let b = seeded.build_keeping(&ctx, false, true).unwrap().0;
        assert!(seeded.far_field.is_built(), "the seeded build fills the cache");
        let (fa, fb) = (
            a.model().flexibility(&grid, Side::A),
            b.model().flexibility(&grid, Side::A),
        );
        for (x, y) in [(&fa.hp, &fb.hp), (&fa.hq, &fb.hq), (&fa.wp, &fb.wp), (&fa.wq, &fb.wq)] {
            for j in 0..x.ncols() {
                for i in 0..x.nrows() {
                    assert_eq!(x[(i, j)].to_bits(), y[(i, j)].to_bits(), "entry ({i}, {j})");
                }
            }
        }
        let finer = DyadicGrid::new(&grid).bisected().grid();
        let follower = seeded.followed(&finer);
        assert!(follower.far_field.is_built(), "the next level shares the seeded cache");

        // `contact.grid.reuse_far_field: false`: the seeded build and its followers, and the
        // bodies changed outside the contact, assemble afresh.
        let off = fig14_roller().reusing_far_field(false);
        off.build_keeping(&ctx, false, true).unwrap();
        assert!(!off.far_field.is_built(), "a cache that does not reuse stays empty");
        let follower = off.followed(&finer);
        assert!(!follower.far_field.reuses(), "the followers share the setting");
        let bisected = off.free_boundary_bisected(ChangedFor::Run);
        assert!(
            !bisected.far_field.reuses(),
            "so does a body changed outside the contact"
        );
    }

    /// The surface the contact frame reads is each mesh's own: the cached shape of a setup that
    /// followed a grid, or whose mesh was bisected or coarsened outside the contact, is that of
    /// its new mesh (the cut adds nodes to the contact group, which moves its fitted circle in
    /// the last bits), not a copy of the start mesh's; and `surface_at` gives what the mesh
    /// itself gives at x, to the bit.
    #[test]
    fn each_setup_reads_its_own_meshs_contact_surface() {
        let setup = fig14_roller();
        let grid = DyadicGrid::new(&setup.mesh.contact_grid()).bisected().grid();
        let changed = [
            setup.followed(&grid),
            setup.free_boundary_bisected(ChangedFor::Run),
            setup
                .free_boundary_coarsened(ChangedFor::Check)
                .expect("the roller coarsens"),
        ];
        for s in std::iter::once(&setup).chain(&changed) {
            let mesh = &s.mesh;
            assert_eq!(s.shape.radius.to_bits(), mesh.contact_radius().to_bits());
            assert_eq!(s.shape.range, mesh.contact_range());
            let touch = mesh.surface_at(0.0).unwrap().0;
            for x in [-1.0, -0.3, 0.0, 0.7] {
                let (y, slope) = mesh.surface_at(x).unwrap();
                let at = s.surface_at(x, Side::A).unwrap();
                assert_eq!(at.profile.to_bits(), ((y - touch) * Side::A.sign()).to_bits());
                assert_eq!(at.slope_angle.to_bits(), slope.atan().to_bits());
            }
        }
        assert_ne!(
            changed[0].shape.radius.to_bits(),
            setup.shape.radius.to_bits(),
            "the cut mesh's circle differs in its last bits, so the test can tell a stale copy"
        );
    }
}
