//! Moving a body's flexibility from its own contact nodes to the common contact grid.
//!
//! When the two bodies' meshes do not share contact-node x-coordinates, each body's
//! flexibility, known at its own contact nodes (its own elements and interpolation), is carried
//! to the one contact grid by its own interpolation (docs/theory.md):
//!
//! * tractions grid → body: the traction at body node k is the grid's interpolant at x_k,
//!   T[k, j] = N_j^grid(x_k);
//! * displacements body → grid: the displacement at grid node i is the body's interpolant at
//!   x_i, D[i, k] = N_k^body(x_i);
//!
//! so F_grid = D · F_body · T for every block. When the grids coincide the transfer is the
//! identity, and the flexibility is returned unchanged (bit for bit).

use super::{
    Body, BodyFields, BodyModel, BoundaryField, ContactLoad, FieldError, Flexibility, InteriorQuery, InteriorResult,
    Side, StrainOperator,
};
use crate::grid::ContactGrid;
use faer::{Mat, MatRef};
use rayon::prelude::*;

/// The contact grid reaches beyond the body's contact segment: the body cannot say what its
/// displacement is there.
#[derive(Debug, thiserror::Error)]
#[error(
    "the contact grid [{grid_min:.6}, {grid_max:.6}] reaches beyond the body's contact segment \
     [{body_min:.6}, {body_max:.6}]: make the mesh's contact group longer or the grid shorter"
)]
pub struct TransferError {
    /// Grid range.
    pub grid_min: f64,
    /// Grid range.
    pub grid_max: f64,
    /// Body contact range.
    pub body_min: f64,
    /// Body contact range.
    pub body_max: f64,
}

/// Interpolation matrix M[i, j] = N_j^{from}(x_i^{to}): values at the nodes of `to` of the
/// interpolant of nodal values on `from`.
pub fn interpolation_matrix(from: &ContactGrid, to: &ContactGrid) -> Mat<f64> {
    let mut m = Mat::zeros(to.n_nodes(), from.n_nodes());
    for (i, &x) in to.nodes.iter().enumerate() {
        for (j, n) in from.interpolation_row(x) {
            m[(i, j)] = n;
        }
    }
    m
}

/// An interpolation matrix by rows, each holding its few nonzeros (at most the nodes of one
/// element): carrying a matrix through two of them costs O(m²), where the dense products cost
/// O(m³) and were most of a pass on a curved grid.
struct SparseRows {
    /// (column, value) of each row's nonzeros.
    rows: Vec<Vec<(usize, f64)>>,
}

impl SparseRows {
    /// The rows of [`interpolation_matrix`]`(from, to)`.
    fn interpolation(from: &ContactGrid, to: &ContactGrid) -> Self {
        Self {
            rows: to.nodes.iter().map(|&x| from.interpolation_row(x)).collect(),
        }
    }

    /// The matrix times each column of `x`.
    fn columns_times(&self, x: MatRef<'_, f64>) -> Mat<f64> {
        Mat::from_fn(self.rows.len(), x.ncols(), |i, c| {
            self.rows[i].iter().map(|&(j, v)| v * x[(j, c)]).sum()
        })
    }

    /// The matrix times the vector `x`, row by row over the nonzeros: summed from 0 in the
    /// columns' order and skipping zero x_j, as the dense product of `linalg::mat_vec` does,
    /// so that the two agree to the bit.
    fn times(&self, x: &[f64]) -> Vec<f64> {
        self.rows
            .iter()
            .map(|row| {
                let mut row = row.clone();
                row.sort_by_key(|&(j, _)| j);
                row.iter()
                    .filter(|&&(j, _)| x[j] != 0.0)
                    .fold(0.0, |sum, &(j, v)| sum + v * x[j])
            })
            .collect()
    }
}

/// D·F·T with D (m × n) and T (n × k) given by their sparse rows, F dense (n × n): F·T by the
/// rows of T (row l adds T_lj times F's column l to column j), then D's rows combine its rows.
/// Column by column on both threads: an O(m²) product that every pass of an error-controlled
/// grid on a curved contact makes eight times (four blocks, two bodies).
fn carried(d: &SparseRows, f: &Mat<f64>, t: &SparseRows, k: usize) -> Mat<f64> {
    let n = f.nrows();
    // T's nonzeros by column: column j of F·T is Σ_l T_lj F[:, l].
    let mut by_column: Vec<Vec<(usize, f64)>> = vec![Vec::new(); k];
    for (l, row) in t.rows.iter().enumerate() {
        for &(j, v) in row {
            by_column[j].push((l, v));
        }
    }
    let mut out = Mat::<f64>::zeros(d.rows.len(), k);
    out.par_col_iter_mut().zip(by_column.par_iter()).for_each_init(
        || vec![0.0; n],
        |ft, (column, entries)| {
            ft.fill(0.0);
            for &(l, v) in entries {
                for (a, &b) in ft.iter_mut().zip(f.col_as_slice(l)) {
                    *a += v * b;
                }
            }
            // A column of a freshly allocated matrix is contiguous.
            let column = column
                .try_as_col_major_mut()
                .expect("a contiguous column")
                .as_slice_mut();
            for (o, row) in column.iter_mut().zip(&d.rows) {
                *o = row.iter().map(|&(r, v)| v * ft[r]).sum();
            }
        },
    );
    out
}

/// The body's flexibility on its own nodes (`body`) carried to the contact grid (`grid`).
pub fn transfer_flexibility(
    flex: &Flexibility,
    body: &ContactGrid,
    grid: &ContactGrid,
) -> Result<Flexibility, TransferError> {
    if grid.coincides_with(body) {
        return Ok(flex.clone());
    }
    // A half-plane's W blocks are its H blocks (W_q = H_p, W_p = −H_q:
    // `Flexibility::of_half_plane`): carried once, they are the same numbers to the bit (the
    // carry is linear, and a sign change rounds symmetrically), at half the cost.
    if same_entries(&flex.wq, &flex.hp, 1.0) && same_entries(&flex.wp, &flex.hq, -1.0) {
        let [hp, hq] = transfer_blocks([&flex.hp, &flex.hq], body, grid)?;
        return Ok(Flexibility::of_half_plane(hp, hq));
    }
    let [hp, hq, wp, wq] = transfer_blocks([&flex.hp, &flex.hq, &flex.wp, &flex.wq], body, grid)?;
    Ok(Flexibility { hp, hq, wp, wq })
}

/// Operator blocks on the body's own nodes (`body`) carried to the contact grid (`grid`) by
/// the sparse product D·F·T of each; copied when the nodes coincide.
pub fn transfer_blocks<const N: usize>(
    blocks: [&Mat<f64>; N],
    body: &ContactGrid,
    grid: &ContactGrid,
) -> Result<[Mat<f64>; N], TransferError> {
    if grid.coincides_with(body) {
        return Ok(blocks.map(|f| f.clone()));
    }
    let (d, t) = operators(body, grid)?;
    Ok(blocks.map(|f| carried(&d, f, &t, grid.n_nodes())))
}

/// Whether a = sign·b entry for entry, exactly.
fn same_entries(a: &Mat<f64>, b: &Mat<f64>, sign: f64) -> bool {
    a.nrows() == b.nrows()
        && a.ncols() == b.ncols()
        && (0..a.ncols()).all(|j| {
            a.col_as_slice(j)
                .iter()
                .zip(b.col_as_slice(j))
                .all(|(&x, &y)| x == sign * y)
        })
}

/// The body's surface-strain operator carried to the contact grid, like the flexibility.
pub fn transfer_strain(
    op: &StrainOperator,
    body: &ContactGrid,
    grid: &ContactGrid,
) -> Result<StrainOperator, TransferError> {
    if grid.coincides_with(body) {
        return Ok(op.clone());
    }
    let (d, t) = operators(body, grid)?;
    Ok(StrainOperator {
        p: carried(&d, &op.p, &t, grid.n_nodes()),
        q: carried(&d, &op.q, &t, grid.n_nodes()),
    })
}

/// The body's node weights carried to the grid's columns, Tᵀw (w the body's weights, T the
/// traction carry of [`transfer_blocks`]): the weights a column term w_j·c of a body's block
/// takes when the block is carried, D (1 wᵀ) T = 1 (Tᵀw)ᵀ (D's rows sum to one).
pub fn carried_weights(body: &ContactGrid, grid: &ContactGrid) -> Result<Vec<f64>, TransferError> {
    let (_, t) = operators(body, grid)?;
    let mut carried = vec![0.0; grid.n_nodes()];
    for (l, row) in t.rows.iter().enumerate() {
        for &(j, v) in row {
            carried[j] += body.weights[l] * v;
        }
    }
    Ok(carried)
}

/// (D, T): displacement body → grid and traction grid → body.
fn operators(body: &ContactGrid, grid: &ContactGrid) -> Result<(SparseRows, SparseRows), TransferError> {
    let (b0, b1) = (body.edges[0], body.edges[body.n_elements()]);
    let (g0, g1) = (grid.edges[0], grid.edges[grid.n_elements()]);
    let tol = 1e-9 * body.length();
    if g0 < b0 - tol || g1 > b1 + tol {
        return Err(TransferError {
            grid_min: g0,
            grid_max: g1,
            body_min: b0,
            body_max: b1,
        });
    }
    Ok((
        SparseRows::interpolation(body, grid),
        SparseRows::interpolation(grid, body),
    ))
}

/// A body model known on its own contact nodes, seen on the common contact grid through the
/// transfer of this module (identity when the nodes coincide).
pub struct Transferred {
    /// The model, whose flexibility is asked on `own_grid`.
    pub inner: Box<dyn Body>,
    /// The body's own contact grid.
    pub own_grid: ContactGrid,
    /// Which body of the pair the inner model was built for.
    pub side: Side,
}

impl BodyModel for Transferred {
    fn model_name(&self) -> &'static str {
        self.inner.model_name()
    }

    /// Panics if the grid reaches beyond the body's segment; [`Transferred::check`] first.
    fn flexibility(&self, grid: &ContactGrid, side: Side) -> Flexibility {
        let own = self.inner.flexibility(&self.own_grid, side);
        transfer_flexibility(&own, &self.own_grid, grid).expect("grid checked against the body segment")
    }

    /// The loads carried to the body's own nodes (T), its displacements there carried back (D).
    fn displacements(&self, grid: &ContactGrid, side: Side, p: MatRef<'_, f64>, q: MatRef<'_, f64>) -> [Mat<f64>; 2] {
        if grid.coincides_with(&self.own_grid) {
            return self.inner.displacements(&self.own_grid, side, p, q);
        }
        let (d, t) = operators(&self.own_grid, grid).expect("grid checked against the body segment");
        let (p, q) = (t.columns_times(p), t.columns_times(q));
        self.inner
            .displacements(&self.own_grid, side, p.as_ref(), q.as_ref())
            .map(|v| d.columns_times(v.as_ref()))
    }

    fn profile(&self, x: f64) -> f64 {
        self.inner.profile(x)
    }

    fn profile_slope(&self, x: f64) -> f64 {
        self.inner.profile_slope(x)
    }

    fn strain_operator(&self, grid: &ContactGrid, side: Side) -> Option<StrainOperator> {
        let own = self.inner.strain_operator(&self.own_grid, side)?;
        transfer_strain(&own, &self.own_grid, grid).ok()
    }

    /// The loads carried to the body's own nodes (T), its strain there carried back (D), as
    /// [`transfer_strain`] carries the operator.
    fn strain_at(&self, grid: &ContactGrid, side: Side, p: MatRef<'_, f64>, q: MatRef<'_, f64>) -> Option<Mat<f64>> {
        if grid.coincides_with(&self.own_grid) {
            return self.inner.strain_at(&self.own_grid, side, p, q);
        }
        let (d, t) = operators(&self.own_grid, grid).ok()?;
        let (p, q) = (t.columns_times(p), t.columns_times(q));
        let own = self.inner.strain_at(&self.own_grid, side, p.as_ref(), q.as_ref())?;
        Some(d.columns_times(own.as_ref()))
    }

    fn stage_seconds(&self) -> (f64, f64) {
        self.inner.stage_seconds()
    }
}

impl Transferred {
    /// The load's nodal tractions carried to the body's own nodes by the grid's interpolation:
    /// (pressure, shear) there.
    fn own_tractions(&self, load: &ContactLoad) -> (Vec<f64>, Vec<f64>) {
        let t = SparseRows::interpolation(load.grid, &self.own_grid);
        (t.times(load.pressure), t.times(load.shear))
    }
}

impl BodyFields for Transferred {
    /// Tractions are carried to the body's own nodes by the grid's interpolation first.
    fn boundary_field(&self, load: &ContactLoad) -> Option<Result<BoundaryField, FieldError>> {
        let (p, q) = self.own_tractions(load);
        self.inner.boundary_field(&ContactLoad {
            grid: &self.own_grid,
            pressure: &p,
            shear: &q,
        })
    }

    /// Tractions are carried to the body's own nodes by the grid's interpolation first.
    fn interior(&self, query: &InteriorQuery) -> InteriorResult {
        let (p, q) = self.own_tractions(&query.load);
        let load = ContactLoad {
            grid: &self.own_grid,
            pressure: &p,
            shear: &q,
        };
        self.inner.interior(&InteriorQuery { load, ..*query })
    }

    fn field_surface(&self, x: f64) -> f64 {
        self.inner.field_surface(x)
    }
}

impl Transferred {
    /// Checks that `grid` lies within the body's own contact segment.
    pub fn check(&self, grid: &ContactGrid) -> Result<(), TransferError> {
        operators(&self.own_grid, grid).map(|_| ())
    }

    /// A closed-form flat model on `grid`: itself on a straight grid; on a grid of mapped
    /// (curved) elements, which the closed-form element integrals do not cover, built on the
    /// straight grid between the same edges and carried over.
    pub fn flat_model_on(body: Box<dyn Body>, grid: &ContactGrid, side: Side) -> Result<Box<dyn Body>, TransferError> {
        if grid.is_straight() {
            return Ok(body);
        }
        let t = Transferred {
            inner: body,
            own_grid: grid.straightened(),
            side,
        };
        t.check(grid)?;
        Ok(Box::new(t))
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::body::half_space::HalfSpace;
    use crate::grid::ElementKind;
    use crate::material::Elastic;

    fn body() -> HalfSpace {
        HalfSpace::new(Elastic::new(210_000.0, 0.3), 100.0)
    }

    /// The sparse product D·F·T equals the dense one of the interpolation matrices.
    #[test]
    fn the_sparse_carry_is_the_dense_product() {
        let body = ContactGrid::uniform(ElementKind::DiscontinuousQuadratic, 7, -1.5, 1.5);
        let grid = ContactGrid::uniform(ElementKind::ContinuousQuadratic, 5, -1.2, 1.1);
        let n = body.n_nodes();
        let f = Mat::from_fn(n, n, |i, j| ((i * 13 + j * 7) % 11) as f64 - 4.5 + 0.1 * i as f64);
        let dense = interpolation_matrix(&body, &grid) * &f * interpolation_matrix(&grid, &body);
        let (d, t) = operators(&body, &grid).unwrap();
        let sparse = carried(&d, &f, &t, grid.n_nodes());
        assert_eq!((sparse.nrows(), sparse.ncols()), (dense.nrows(), dense.ncols()));
        for i in 0..dense.nrows() {
            for j in 0..dense.ncols() {
                assert!((sparse[(i, j)] - dense[(i, j)]).abs() < 1e-12, "({i}, {j})");
            }
        }
        // The product with a vector (a load carried to the body's nodes) to the bit, zeros too.
        let x: Vec<f64> = (0..grid.n_nodes())
            .map(|i| if i % 4 == 0 { 0.0 } else { i as f64 - 3.3 })
            .collect();
        let dense_x = crate::linalg::mat_vec(&interpolation_matrix(&grid, &body), &x);
        assert_eq!(SparseRows::interpolation(&grid, &body).times(&x), dense_x);
    }

    /// A half-plane's flexibility carried by its two H blocks is, to the bit, the four
    /// blocks carried one by one; a flexibility of another shape carries all four.
    #[test]
    fn a_half_plane_is_carried_by_its_two_kernels_to_the_bit() {
        let own = ContactGrid::uniform(ElementKind::DiscontinuousQuadratic, 8, -1.4, 1.4);
        let grid = ContactGrid::uniform(ElementKind::DiscontinuousQuadratic, 5, -1.2, 1.1);
        let f = body().flexibility(&own, Side::B);
        let (d, t) = operators(&own, &grid).unwrap();
        let carry = |m: &Mat<f64>| carried(&d, m, &t, grid.n_nodes());
        let shortcut = transfer_flexibility(&f, &own, &grid).unwrap();
        for (a, b) in [
            (&shortcut.hp, carry(&f.hp)),
            (&shortcut.hq, carry(&f.hq)),
            (&shortcut.wp, carry(&f.wp)),
            (&shortcut.wq, carry(&f.wq)),
        ] {
            assert!(*a == b, "the shortcut differs from the block's own carry");
        }
        let mut other = f.clone();
        let mid = own.n_nodes() / 2;
        other.wq[(mid, mid)] *= 1.0 + 1e-9;
        let carried_all = transfer_flexibility(&other, &own, &grid).unwrap();
        assert!(carried_all.wq == carry(&other.wq) && carried_all.wq != shortcut.wq);
    }

    /// A half-plane's two kernels carried as blocks ([`transfer_blocks`], what a stand-in
    /// carries) are its flexibility's carried H blocks to the bit, and are copied unchanged
    /// onto the same grid.
    #[test]
    fn the_kernel_blocks_carry_as_the_flexibility_does() {
        let own = ContactGrid::uniform(ElementKind::DiscontinuousQuadratic, 8, -1.4, 1.4);
        let grid = ContactGrid::uniform(ElementKind::DiscontinuousQuadratic, 5, -1.2, 1.1);
        let (hp, hq) = body().kernel_blocks(&own, Side::B);
        let whole = transfer_flexibility(&body().flexibility(&own, Side::B), &own, &grid).unwrap();
        let [cp, cq] = transfer_blocks([&hp, &hq], &own, &grid).unwrap();
        assert!(cp == whole.hp && cq == whole.hq);
        let [sp, sq] = transfer_blocks([&hp, &hq], &own, &own.clone()).unwrap();
        assert!(sp == hp && sq == hq);
    }

    #[test]
    fn coinciding_grids_are_passed_through_exactly() {
        let g = ContactGrid::uniform(ElementKind::DiscontinuousQuadratic, 9, -1.3, 1.3);
        let f = body().flexibility(&g, Side::A);
        let t = transfer_flexibility(&f, &g, &g.clone()).unwrap();
        assert!(f.hp == t.hp && f.wq == t.wq && f.hq == t.hq && f.wp == t.wp);
    }

    /// A half-plane known on a finer, non-uniform, wider set of body elements and carried to
    /// the grid reproduces the displacements of the half-plane evaluated on the grid directly,
    /// for the Hertz pressure and a Carter-like shear: displacement differences (the log datum
    /// is arbitrary) agree to 1 % of their range, and better as the body mesh is refined.
    #[test]
    fn transfer_from_a_finer_nonuniform_body_mesh_matches_direct_evaluation() {
        let grid = ContactGrid::uniform(ElementKind::DiscontinuousQuadratic, 15, -1.3, 1.3);
        let hs = body();
        let direct = hs.flexibility(&grid, Side::B);
        let p: Vec<f64> = grid.nodes.iter().map(|x| (1.0 - x * x).max(0.0).sqrt()).collect();
        let q: Vec<f64> = grid
            .nodes
            .iter()
            .map(|x| 0.3 * (1.0 - x * x).max(0.0).sqrt() * x)
            .collect();
        let apply = |f: &Flexibility| {
            let (h, w) = (f.normal(&p, &q), f.tangential(&p, &q));
            let c = h.len() / 2;
            (
                h.iter().map(|v| v - h[c]).collect::<Vec<_>>(),
                w.iter().map(|v| v - w[c]).collect::<Vec<_>>(),
            )
        };
        let (h_ref, w_ref) = apply(&direct);
        let range = |v: &[f64]| v.iter().fold(0.0_f64, |a, b| a.max(b.abs()));
        let mut errors = Vec::new();
        for n in [20, 40, 80] {
            // Graded, wider body mesh: edges ξ³-stretched on [−1.6, 1.6].
            let edges: Vec<f64> = (0..=n)
                .map(|k| {
                    let t = -1.0 + 2.0 * k as f64 / n as f64;
                    1.6 * (0.6 * t + 0.4 * t * t * t)
                })
                .collect();
            let own = ContactGrid::from_edges(ElementKind::DiscontinuousQuadratic, edges);
            let carried = transfer_flexibility(&hs.flexibility(&own, Side::B), &own, &grid).unwrap();
            let (h, w) = apply(&carried);
            let eh = h.iter().zip(&h_ref).fold(0.0_f64, |a, (x, y)| a.max((x - y).abs())) / range(&h_ref);
            let ew = w.iter().zip(&w_ref).fold(0.0_f64, |a, (x, y)| a.max((x - y).abs())) / range(&w_ref);
            errors.push(eh.max(ew));
        }
        println!("transfer errors (20, 40, 80 body elements): {errors:?}");
        assert!(errors[2] < 0.01, "transfer errors {errors:?}");
        assert!(errors[2] < errors[0], "transfer errors {errors:?}");
    }

    #[test]
    fn a_grid_longer_than_the_body_segment_is_an_error() {
        let grid = ContactGrid::uniform(ElementKind::DiscontinuousQuadratic, 5, -1.3, 1.3);
        let own = ContactGrid::uniform(ElementKind::DiscontinuousQuadratic, 5, -1.0, 1.0);
        let f = body().flexibility(&own, Side::A);
        let e = transfer_flexibility(&f, &own, &grid).unwrap_err();
        assert!(e.to_string().contains("beyond the body's contact segment"));
    }
}
