//! Small dense products shared by the body models and the contact solver.

use faer::Mat;

/// y = A x for a dense matrix and a slice (columns of zero x_j skipped).
pub fn mat_vec(a: &Mat<f64>, x: &[f64]) -> Vec<f64> {
    let mut y = vec![0.0; a.nrows()];
    // Column-major storage: accumulate column by column.
    for (j, &xj) in x.iter().enumerate().take(a.ncols()) {
        if xj != 0.0 {
            for (yi, &aij) in y.iter_mut().zip(a.col_as_slice(j)) {
                *yi += aij * xj;
            }
        }
    }
    y
}

/// y = A x + B z for square dense matrices and slices.
pub fn mat_vec2(a: &Mat<f64>, x: &[f64], b: &Mat<f64>, z: &[f64]) -> Vec<f64> {
    let m = a.nrows();
    let mut y = vec![0.0; m];
    // Column-major storage: accumulate column by column.
    for j in 0..a.ncols() {
        let (xj, zj) = (x[j], z[j]);
        // Slices of the columns (contiguous, unit stride), so the loops vectorise.
        if xj != 0.0 {
            for (yi, &aij) in y.iter_mut().zip(a.col_as_slice(j)) {
                *yi += aij * xj;
            }
        }
        if zj != 0.0 {
            for (yi, &bij) in y.iter_mut().zip(b.col_as_slice(j)) {
                *yi += bij * zj;
            }
        }
    }
    y
}

/// Order from which [`lu_solve_in_place`] factors with faer's threads: below it one thread is
/// faster on the two-core machine, in wall time as well as in CPU time (an error-controlled
/// carter2d run at tolerance 1e-4, largest Newton system 573: 0.07 s against 0.09 s; carter_051
/// at 1e-5, largest system 1267, and on 321 elements, systems of 1259–1928: 6–12 % less wall
/// time and 10–30 % less CPU with one thread), while on 481 elements (systems of 1884–2888) the
/// threads save 8–13 % of the wall time (docs/performance.md).
pub const PARALLEL_LU_MIN: usize = 1536;

/// The memory of [`LuWorkspace::solve_in_place`] besides the matrix: the row permutation and
/// its inverse, and faer's scratch space. Kept across solves, it grows to the largest order met
/// and is then reused, so that a Newton iteration allocates nothing for its LU.
pub struct LuWorkspace {
    perm: Vec<usize>,
    perm_inv: Vec<usize>,
    scratch: faer::dyn_stack::MemBuffer,
    /// What `scratch` was allocated for.
    scratch_req: faer::dyn_stack::StackReq,
}

impl std::fmt::Debug for LuWorkspace {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("LuWorkspace")
            .field("order", &self.perm.len())
            .field("scratch_bytes", &self.scratch_req.size_bytes())
            .finish()
    }
}

impl Default for LuWorkspace {
    fn default() -> Self {
        Self::new()
    }
}

impl LuWorkspace {
    /// An empty workspace: the first solve allocates.
    pub fn new() -> Self {
        let req = faer::dyn_stack::StackReq::EMPTY;
        Self {
            perm: Vec::new(),
            perm_inv: Vec::new(),
            scratch: faer::dyn_stack::MemBuffer::new(req),
            scratch_req: req,
        }
    }

    /// Solves A X = B in place by LU with partial pivoting: `a` (square) is overwritten by its
    /// factors and `rhs` by the solution. faer's `PartialPivLu` copies the matrix and then splits
    /// it into L and U (three more n × n matrices, each paid in page faults at the sizes of the
    /// Newton systems); this factors the caller's matrix where it lies, with faer's same
    /// routines, and keeps the pivots and scratch space for the next solve.
    pub fn solve_in_place(&mut self, mut a: faer::MatMut<'_, f64>, rhs: faer::MatMut<'_, f64>) {
        use faer::dyn_stack::MemStack;
        use faer::linalg::lu::partial_pivoting::{factor, solve};
        let n = a.nrows();
        assert_eq!(n, a.ncols(), "a square matrix");
        assert_eq!(n, rhs.nrows(), "a right side of the matrix's order");
        // Below PARALLEL_LU_MIN unknowns the threads' hand-offs cost more than they share on two
        // cores (docs/performance.md).
        let par = parallelism(n);
        self.perm.resize(n, 0);
        self.perm_inv.resize(n, 0);
        let req = factor::lu_in_place_scratch::<usize, f64>(n, n, par, Default::default())
            .or(solve::solve_in_place_scratch::<usize, f64>(n, rhs.ncols(), par));
        let grown = self.scratch_req.or(req);
        if grown != self.scratch_req {
            self.scratch = faer::dyn_stack::MemBuffer::new(grown);
            self.scratch_req = grown;
        }
        let stack = MemStack::new(&mut self.scratch);
        let (perm, perm_inv) = (&mut self.perm[..n], &mut self.perm_inv[..n]);
        let (_, row_perm) = factor::lu_in_place(a.as_mut(), perm, perm_inv, par, stack, Default::default());
        // L (unit lower) and U share the factored matrix: each solve reads only its own triangle.
        solve::solve_in_place(a.as_ref(), a.as_ref(), row_perm, rhs, par, stack);
    }

    /// Solves A X = B in place for `rhs` with the factors `lu` that this workspace's last
    /// [`LuWorkspace::solve_in_place`] left in its matrix (its pivots are the workspace's): the
    /// same numbers as that call would give for `rhs`, without factoring again.
    pub fn solve_again(&mut self, lu: faer::MatRef<'_, f64>, rhs: faer::MatMut<'_, f64>) {
        use faer::dyn_stack::MemStack;
        use faer::linalg::lu::partial_pivoting::solve;
        let n = lu.nrows();
        assert_eq!(n, self.perm.len(), "the factors of this workspace's last solve");
        assert_eq!(n, rhs.nrows(), "a right side of the matrix's order");
        let par = parallelism(n);
        let req = solve::solve_in_place_scratch::<usize, f64>(n, rhs.ncols(), par);
        let grown = self.scratch_req.or(req);
        if grown != self.scratch_req {
            self.scratch = faer::dyn_stack::MemBuffer::new(grown);
            self.scratch_req = grown;
        }
        let perm = faer::perm::PermRef::new_checked(&self.perm, &self.perm_inv, n);
        solve::solve_in_place(lu, lu, perm, rhs, par, MemStack::new(&mut self.scratch));
    }
}

/// An LU factorisation with partial pivoting kept for later solves: the factors in the
/// factored matrix's place (L unit lower, U upper) and the row permutation. A BEM body that is
/// asked only for its response to a few loads (the fits of an error-controlled grid's
/// stand-ins, the checks of its mesh) is factored once and solved per load, instead of solved
/// at once for every unit load of its contact nodes.
#[derive(Clone)]
pub struct LuFactors {
    lu: Mat<f64>,
    perm: Vec<usize>,
    perm_inv: Vec<usize>,
}

impl std::fmt::Debug for LuFactors {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("LuFactors").field("order", &self.perm.len()).finish()
    }
}

impl LuFactors {
    /// Factors `a` (square) where it lies, with faer's routines as [`LuWorkspace`] does (one
    /// thread below [`PARALLEL_LU_MIN`] unknowns).
    pub fn new(mut a: Mat<f64>) -> Self {
        use faer::dyn_stack::{MemBuffer, MemStack};
        use faer::linalg::lu::partial_pivoting::factor;
        let n = a.nrows();
        assert_eq!(n, a.ncols(), "a square matrix");
        let par = parallelism(n);
        let (mut perm, mut perm_inv) = (vec![0; n], vec![0; n]);
        let mut scratch = MemBuffer::new(factor::lu_in_place_scratch::<usize, f64>(n, n, par, Default::default()));
        factor::lu_in_place(
            a.as_mut(),
            &mut perm,
            &mut perm_inv,
            par,
            MemStack::new(&mut scratch),
            Default::default(),
        );
        Self { lu: a, perm, perm_inv }
    }

    /// The order n of the factored matrix.
    pub fn order(&self) -> usize {
        self.perm.len()
    }

    /// Solves A X = B in place for the columns of `rhs` (n rows).
    pub fn solve_in_place(&self, rhs: faer::MatMut<'_, f64>) {
        use faer::dyn_stack::{MemBuffer, MemStack};
        use faer::linalg::lu::partial_pivoting::solve;
        let n = self.order();
        assert_eq!(n, rhs.nrows(), "a right side of the matrix's order");
        let par = parallelism(n);
        let mut scratch = MemBuffer::new(solve::solve_in_place_scratch::<usize, f64>(n, rhs.ncols(), par));
        let perm = faer::perm::PermRef::new_checked(&self.perm, &self.perm_inv, n);
        let lu = self.lu.as_ref();
        solve::solve_in_place(lu, lu, perm, rhs, par, MemStack::new(&mut scratch));
    }

    /// The ratio of the smallest to the largest |pivot| (U's diagonal): 0 or NaN for a
    /// singular or non-finite matrix.
    pub fn pivot_ratio(&self) -> f64 {
        pivot_ratio(self.lu.as_ref())
    }
}

/// The ratio of the smallest to the largest |diagonal entry| of a factored matrix (its U's
/// pivots): 0 for a zero pivot, NaN where an entry is not finite.
pub fn pivot_ratio(lu: faer::MatRef<'_, f64>) -> f64 {
    let (mut lo, mut hi) = (f64::INFINITY, 0.0f64);
    for k in 0..lu.nrows() {
        let p = lu[(k, k)].abs();
        if p.is_nan() {
            return f64::NAN;
        }
        lo = lo.min(p);
        hi = hi.max(p);
    }
    if hi > 0.0 {
        lo / hi
    } else {
        0.0
    }
}

/// faer's threads from [`PARALLEL_LU_MIN`] unknowns, one thread below.
fn parallelism(n: usize) -> faer::Par {
    if n < PARALLEL_LU_MIN {
        faer::Par::Seq
    } else {
        faer::get_global_parallelism()
    }
}

/// [`LuWorkspace::solve_in_place`] with a workspace of its own, for a single solve.
pub fn lu_solve_in_place(mut a: Mat<f64>, rhs: faer::MatMut<'_, f64>) {
    LuWorkspace::new().solve_in_place(a.as_mut(), rhs);
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn products_match_the_definition() {
        let a = Mat::from_fn(3, 3, |i, j| (1 + i + 3 * j) as f64);
        let b = Mat::from_fn(3, 3, |i, j| (i as f64) - (j as f64));
        let (x, z) = ([1.0, 0.0, -2.0], [0.5, 2.0, 0.0]);
        let want: Vec<f64> = (0..3)
            .map(|i| (0..3).map(|j| a[(i, j)] * x[j] + b[(i, j)] * z[j]).sum())
            .collect();
        assert_eq!(mat_vec2(&a, &x, &b, &z), want);
        let ax: Vec<f64> = (0..3).map(|i| (0..3).map(|j| a[(i, j)] * x[j]).sum()).collect();
        assert_eq!(mat_vec(&a, &x), ax);
    }

    /// A workspace that served larger and smaller orders (on both sides of
    /// [`PARALLEL_LU_MIN`]) solves to the same bits as a new one: it keeps nothing of the last
    /// solve but memory.
    #[test]
    fn a_reused_lu_workspace_solves_like_a_new_one() {
        let system = |n: usize| {
            let a = Mat::from_fn(n, n, |i, j| {
                let v = ((i * 5 + j * 11) % 13) as f64 / 13.0 - 0.5;
                if i == j {
                    v + 3.0
                } else {
                    v / n as f64
                }
            });
            let b = Mat::from_fn(n, 1, |i, _| (i as f64 + 0.5).cos());
            (a, b)
        };
        let mut ws = LuWorkspace::new();
        for n in [40, PARALLEL_LU_MIN + 3, 9, 40, PARALLEL_LU_MIN + 3] {
            let (a, b) = system(n);
            let (mut a_used, mut x_used) = (a.clone(), b.clone());
            ws.solve_in_place(a_used.as_mut(), x_used.as_mut());
            let mut x_new = b.clone();
            lu_solve_in_place(a, x_new.as_mut());
            assert!(
                (0..n).all(|i| x_used[(i, 0)].to_bits() == x_new[(i, 0)].to_bits()),
                "n {n}: a used workspace solves differently"
            );
        }
    }

    /// The in-place LU solves what faer's `PartialPivLu` solves, on both sides of
    /// [`PARALLEL_LU_MIN`], for a nonsymmetric matrix that needs pivoting (zero diagonal in
    /// its first row): the residual A x − b is at round-off of ‖A‖‖x‖.
    #[test]
    fn in_place_lu_solves_like_faer() {
        use faer::linalg::solvers::Solve;
        for n in [7, PARALLEL_LU_MIN + 5] {
            let a = Mat::from_fn(n, n, |i, j| {
                let v = ((i * 7 + j * 13) % 17) as f64 / 17.0 - 0.5;
                if i == j && i > 0 {
                    v + 4.0
                } else if i == 0 && j == 0 {
                    0.0
                } else {
                    v / n as f64
                }
            });
            let b = Mat::from_fn(n, 1, |i, _| (i as f64).sin());
            let mut x = b.clone();
            lu_solve_in_place(a.clone(), x.as_mut());
            let mut reference = b.clone();
            a.partial_piv_lu().solve_in_place(reference.as_mut());
            let r = &a * &x - &b;
            let scale = a.norm_max() * x.norm_max() * n as f64;
            assert!(r.norm_max() <= 1e-14 * scale, "n {n}: residual {:e}", r.norm_max());
            let diff = (&x - &reference).norm_max();
            assert!(
                diff <= 1e-12 * reference.norm_max(),
                "n {n}: differs from faer by {diff:e}"
            );
        }
    }
}
