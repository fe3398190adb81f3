//! The contact grid: traction elements along x on which the contact unknowns live.
//!
//! The grid is a row of elements on `[x_min, x_max]`, usually equal ([`ContactGrid::uniform`];
//! a BEM mesh may give unequal ones, [`ContactGrid::from_edges`]). Each element carries either one node
//! at its centre (constant element), three nodes at the intrinsic coordinates ξ = −2/3, 0, +2/3
//! (discontinuous quadratic element, the paper's choice, §5), or three nodes at ξ = −1, 0, +1
//! whose end nodes are shared with the neighbouring elements (continuous quadratic element: the
//! traction is continuous along the grid, the choice Man & Aliabadi reported ripples with).
//! With ξ = ±2/3 the nodes of a discontinuous quadratic grid are equally spaced (spacing L/3),
//! and those of a continuous one too (spacing L/2), which the slip operator uses.
//! Nodes are numbered in increasing x.
//!
//! **Mapped elements.** A grid built on a BEM mesh's curved contact elements follows their
//! geometry ([`ContactGrid::from_mapped_edges`]): element e maps ξ ∈ [−1, 1] to
//! x(ξ) = ½ξ(ξ−1)x₀ + ½ξ(ξ+1)x₁ + (1−ξ²)x_m, the x of the mesh's quadratic element through its
//! end nodes x₀, x₁ and its mid node x_m, so the grid's nodes are the x of the mesh's field
//! nodes exactly (a mid node at the mid-angle of an arc is not at the mid-x of its ends).
//! Shape functions are the same polynomials in ξ; weights become ∫ N_a(ξ) x'(ξ) dξ. A straight
//! element (x_m the centre) is the linear map of the equal-element formulas, bit for bit.

use serde::Serialize;

/// Traction interpolation on the contact elements.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, serde::Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum ElementKind {
    /// One node at the element centre; traction constant over the element.
    Constant,
    /// Three interior nodes at ξ = −2/3, 0, +2/3; traction quadratic over the element and
    /// discontinuous between elements (González & Abascal §5).
    DiscontinuousQuadratic,
    /// Nodes at ξ = −1, 0, +1, the end nodes shared with the neighbours; traction quadratic over
    /// the element and continuous along the grid. Half-space and rigid bodies only.
    ContinuousQuadratic,
}

/// Intrinsic coordinate of the outer nodes of a discontinuous quadratic element.
pub const DQE_NODE: f64 = 2.0 / 3.0;

impl ElementKind {
    /// Name as written in case files.
    pub fn name(self) -> &'static str {
        match self {
            ElementKind::Constant => "constant",
            ElementKind::DiscontinuousQuadratic => "discontinuous_quadratic",
            ElementKind::ContinuousQuadratic => "continuous_quadratic",
        }
    }

    /// Number of nodes (shape functions) per element.
    pub fn nodes_per_element(self) -> usize {
        match self {
            ElementKind::Constant => 1,
            ElementKind::DiscontinuousQuadratic | ElementKind::ContinuousQuadratic => 3,
        }
    }

    /// Step in global node number from one element to the next: nodes per element, less the
    /// shared end node of continuous elements (also the node intervals per element).
    pub fn node_stride(self) -> usize {
        match self {
            ElementKind::ContinuousQuadratic => 2,
            other => other.nodes_per_element(),
        }
    }

    /// Whether neighbouring elements share their end nodes.
    pub fn shares_nodes(self) -> bool {
        self == ElementKind::ContinuousQuadratic
    }

    /// Intrinsic coordinates ξ ∈ [−1, 1] of the element's nodes.
    pub fn node_coordinates(self) -> &'static [f64] {
        match self {
            ElementKind::Constant => &[0.0],
            ElementKind::DiscontinuousQuadratic => &[-DQE_NODE, 0.0, DQE_NODE],
            ElementKind::ContinuousQuadratic => &[-1.0, 0.0, 1.0],
        }
    }

    /// Coefficients `[c0, c1, c2]` of the shape function of local node `a`, N_a(ξ) = c0 + c1 ξ + c2 ξ².
    pub fn shape_polynomial(self, a: usize) -> [f64; 3] {
        match self {
            ElementKind::Constant => [1.0, 0.0, 0.0],
            ElementKind::DiscontinuousQuadratic => {
                // Lagrange polynomials through ξ = −c, 0, +c.
                let c = DQE_NODE;
                match a {
                    0 => [0.0, -0.5 / c, 0.5 / (c * c)],
                    1 => [1.0, 0.0, -1.0 / (c * c)],
                    _ => [0.0, 0.5 / c, 0.5 / (c * c)],
                }
            }
            // Lagrange polynomials through ξ = −1, 0, +1.
            ElementKind::ContinuousQuadratic => match a {
                0 => [0.0, -0.5, 0.5],
                1 => [1.0, 0.0, -1.0],
                _ => [0.0, 0.5, 0.5],
            },
        }
    }
}

/// A contact grid of `n_elements` equal traction elements.
#[derive(Debug, Clone, Serialize)]
pub struct ContactGrid {
    /// Interpolation used on every element.
    pub kind: ElementKind,
    /// Element end points in increasing x, `n_elements + 1` values [length].
    pub edges: Vec<f64>,
    /// Node x-coordinates in increasing order, `n_elements · nodes_per_element` values [length].
    pub nodes: Vec<f64>,
    /// Integration weights w_j = ∫ N_j dx [length]: P = Σ w_j p_j (paper Eq. 38–39).
    pub weights: Vec<f64>,
    /// x at ξ = 0 of each element [length]: its centre for a straight element, the x of the
    /// mesh's mid node for a mapped one (module docs).
    pub mids: Vec<f64>,
}

impl ContactGrid {
    /// Builds a uniform grid of `n_elements` elements on `[x_min, x_max]`.
    ///
    /// Panics if `n_elements == 0` or the interval is empty: callers validate user input first.
    pub fn uniform(kind: ElementKind, n_elements: usize, x_min: f64, x_max: f64) -> Self {
        assert!(n_elements > 0, "a contact grid needs at least one element");
        assert!(x_max > x_min, "empty grid interval [{x_min}, {x_max}]");
        let length = (x_max - x_min) / n_elements as f64;
        Self::from_edges(kind, (0..=n_elements).map(|e| x_min + length * e as f64).collect())
    }

    /// Builds a grid from its element end points, strictly increasing.
    ///
    /// Panics on fewer than two edges or non-increasing ones: callers validate first.
    pub fn from_edges(kind: ElementKind, edges: Vec<f64>) -> Self {
        let mids = edges.windows(2).map(|w| 0.5 * (w[0] + w[1])).collect();
        Self::from_mapped_edges(kind, edges, mids)
    }

    /// Builds a grid of mapped elements (module docs) from their end points, strictly
    /// increasing, and the x of each element's mid point, `mids[e]` within the middle half of
    /// its element (x(ξ) then increases on [−1, 1]); a mid point outside it is replaced by the
    /// centre.
    ///
    /// Panics on fewer than two edges, non-increasing ones or a wrong number of mids: callers
    /// validate first.
    pub fn from_mapped_edges(kind: ElementKind, edges: Vec<f64>, mids: Vec<f64>) -> Self {
        assert!(edges.len() >= 2, "a contact grid needs at least one element");
        assert_eq!(mids.len() + 1, edges.len(), "one mid point per element");
        assert!(
            edges.windows(2).all(|w| w[1] > w[0]),
            "grid edges must increase: {edges:?}"
        );
        let n_elements = edges.len() - 1;
        let stride = kind.node_stride();
        let n_nodes = n_elements * stride + usize::from(kind.shares_nodes());
        let mids: Vec<f64> = (0..n_elements)
            .map(|e| {
                let (length, centre) = (edges[e + 1] - edges[e], 0.5 * (edges[e] + edges[e + 1]));
                // A bow within the round-off of a mesh file (Gmsh's mid nodes of straight lines
                // are off by up to ~1e-11 of the element) is a straight element, bit for bit.
                let bow = (mids[e] - centre).abs();
                if bow > 1e-9 * length && bow < 0.25 * length {
                    mids[e]
                } else {
                    centre
                }
            })
            .collect();
        let mut nodes = vec![0.0; n_nodes];
        let mut weights = vec![0.0; n_nodes];
        for e in 0..n_elements {
            let length = edges[e + 1] - edges[e];
            let centre = 0.5 * (edges[e] + edges[e + 1]);
            // The map's bow: x(ξ) = centre + ½Lξ + bow·(1 − ξ²), zero for a straight element.
            let bow = mids[e] - centre;
            for (a, xi) in kind.node_coordinates().iter().enumerate() {
                let j = e * stride + a;
                // A shared end node gets the same x from both elements (exactly, at the edge).
                nodes[j] = match (kind.shares_nodes(), a) {
                    (true, 0) => edges[e],
                    (true, 2) => edges[e + 1],
                    _ if bow == 0.0 => centre + 0.5 * length * xi,
                    _ => centre + 0.5 * length * xi + bow * (1.0 - xi * xi),
                };
                let [c0, c1, c2] = kind.shape_polynomial(a);
                // ∫_{-1}^{1} (c0 + c1 ξ + c2 ξ²)(L/2 − 2 bow ξ) dξ, summed over the elements of
                // the node (the odd moments vanish: ∫ξ² = 2/3, ∫ξ⁴ = 2/5).
                weights[j] += (2.0 * c0 + 2.0 * c2 / 3.0) * 0.5 * length;
                if bow != 0.0 {
                    weights[j] -= 2.0 * bow * c1 * 2.0 / 3.0;
                }
            }
        }
        Self {
            kind,
            edges,
            nodes,
            weights,
            mids,
        }
    }

    /// Whether every element is straight (the linear map of its end points).
    pub fn is_straight(&self) -> bool {
        self.edges
            .windows(2)
            .zip(&self.mids)
            .all(|(w, m)| *m == 0.5 * (w[0] + w[1]))
    }

    /// The grid of straight elements between the same edges.
    pub fn straightened(&self) -> ContactGrid {
        ContactGrid::from_edges(self.kind, self.edges.clone())
    }

    /// x(ξ) of element `e` [length] (module docs).
    pub fn element_x(&self, e: usize, xi: f64) -> f64 {
        let (x0, x1) = (self.edges[e], self.edges[e + 1]);
        let centre = 0.5 * (x0 + x1);
        centre + 0.5 * (x1 - x0) * xi + (self.mids[e] - centre) * (1.0 - xi * xi)
    }

    /// ξ ∈ [−1, 1] of x in element `e`: the root of the element's map (linear when straight).
    fn element_xi(&self, e: usize, x: f64) -> f64 {
        let (x0, x1) = (self.edges[e], self.edges[e + 1]);
        let (half, centre) = (0.5 * (x1 - x0), 0.5 * (x0 + x1));
        let bow = self.mids[e] - centre;
        // bow ξ² − half ξ + (x − centre − bow) = 0; the root in [−1, 1] in the cancellation-free
        // form 2c/(−b ± √(b² − 4ac)) (|bow| < half/2 keeps it unique and real).
        let c = x - centre - bow;
        let xi = if bow == 0.0 {
            c / half
        } else {
            let disc = (half * half - 4.0 * bow * c).max(0.0);
            2.0 * c / (half + disc.sqrt())
        };
        xi.clamp(-1.0, 1.0)
    }

    /// Number of contact nodes m.
    pub fn n_nodes(&self) -> usize {
        self.nodes.len()
    }

    /// Number of traction elements.
    pub fn n_elements(&self) -> usize {
        self.edges.len() - 1
    }

    /// Largest element length [length] (the element length of a uniform grid).
    pub fn element_length(&self) -> f64 {
        self.edges.windows(2).map(|w| w[1] - w[0]).fold(0.0, f64::max)
    }

    /// Smallest element length [length].
    pub fn shortest_element(&self) -> f64 {
        self.edges.windows(2).map(|w| w[1] - w[0]).fold(f64::INFINITY, f64::min)
    }

    /// Smallest distance between neighbouring nodes [length] (the spacing of a uniform grid:
    /// L/3 for discontinuous quadratic elements, L for constant ones).
    pub fn node_spacing(&self) -> f64 {
        self.nodes
            .windows(2)
            .map(|w| w[1] - w[0])
            .fold(f64::INFINITY, f64::min)
            .min(self.length())
    }

    /// Whether all elements are straight and have the same length (to 1e-12 relative).
    pub fn is_uniform(&self) -> bool {
        let l = self.length() / self.n_elements() as f64;
        self.is_straight() && self.edges.windows(2).all(|w| ((w[1] - w[0]) - l).abs() <= 1e-12 * l)
    }

    /// Whether two grids have the same kind, edges and nodes (to 1e-12 of the node spacing).
    pub fn coincides_with(&self, other: &ContactGrid) -> bool {
        let tol = 1e-12 * self.node_spacing();
        let close = |a: &[f64], b: &[f64]| a.len() == b.len() && a.iter().zip(b).all(|(a, b)| (a - b).abs() <= tol);
        self.kind == other.kind && close(&self.edges, &other.edges) && close(&self.nodes, &other.nodes)
    }

    /// Shape-function values at x: (node, N_node(x)) for the nodes of the element holding x;
    /// empty outside the grid.
    pub fn interpolation_row(&self, x: f64) -> Vec<(usize, f64)> {
        let n = self.n_elements();
        let (x0, x1) = (self.edges[0], self.edges[n]);
        if x < x0 || x > x1 {
            return Vec::new();
        }
        let e = self
            .edges
            .partition_point(|&edge| edge <= x)
            .saturating_sub(1)
            .min(n - 1);
        let xi = if self.mids[e] == 0.5 * (self.edges[e] + self.edges[e + 1]) {
            let length = self.edges[e + 1] - self.edges[e];
            let centre = 0.5 * (self.edges[e] + self.edges[e + 1]);
            2.0 * (x - centre) / length
        } else {
            self.element_xi(e, x)
        };
        let npe = self.kind.nodes_per_element();
        (0..npe)
            .map(|a| {
                let [c0, c1, c2] = self.kind.shape_polynomial(a);
                (self.global_node(e, a), c0 + c1 * xi + c2 * xi * xi)
            })
            .collect()
    }

    /// Total length of the grid [length].
    pub fn length(&self) -> f64 {
        self.edges[self.edges.len() - 1] - self.edges[0]
    }

    /// Element index and local node index of node `j` (for a shared end node of continuous
    /// elements: the element on its right, except at the right end of the grid).
    pub fn element_of(&self, j: usize) -> (usize, usize) {
        let stride = self.kind.node_stride();
        let e = (j / stride).min(self.n_elements() - 1);
        (e, j - e * stride)
    }

    /// Global node number of local node `a` of element `e`.
    pub fn global_node(&self, e: usize, a: usize) -> usize {
        e * self.kind.node_stride() + a
    }

    /// Integral Σ w_j v_j of a nodal field over the grid (force from a traction) [length·field].
    pub fn integrate(&self, values: &[f64]) -> f64 {
        self.weights.iter().zip(values).map(|(w, v)| w * v).sum()
    }

    /// The points x [length] and weights [length] of an `n`-point Gauss–Legendre rule on every
    /// element (straight between its edges), element by element: Σ w f(x) integrates f over
    /// the grid, exactly for polynomials of degree 2n − 1 on each element.
    pub fn gauss_points(&self, n: usize) -> Vec<(f64, f64)> {
        let (gx, gw) = crate::quadrature::gauss_legendre(n);
        self.edges
            .windows(2)
            .flat_map(|e| {
                let (mid, half) = (0.5 * (e[0] + e[1]), 0.5 * (e[1] - e[0]));
                gx.iter()
                    .zip(&gw)
                    .map(move |(t, w)| (mid + half * t, half * w))
                    .collect::<Vec<_>>()
            })
            .collect()
    }

    /// Largest value of the piecewise interpolant of the nodal values `values` over the grid
    /// [the field's unit]: on each element the largest of its polynomial in ξ ∈ [−1, 1] (at
    /// the ends or at the vertex of a quadratic), so that a peak between nodes is not missed
    /// by up to the field's curvature times the squared node spacing, as the nodal maximum is
    /// (on a graded Hertz grid with spacing 2e-2 a at the centre: 4.2e-5 p0). An element with
    /// a node at or below zero (a contact edge inside) counts between its outer nodes only.
    /// Constant elements give their nodal values.
    pub fn interpolant_max(&self, values: &[f64]) -> f64 {
        let npe = self.kind.nodes_per_element();
        (0..self.n_elements())
            .map(|e| {
                let mut c = [0.0; 3];
                for a in 0..npe {
                    let v = values[self.global_node(e, a)];
                    for (ck, nk) in c.iter_mut().zip(self.kind.shape_polynomial(a)) {
                        *ck += v * nk;
                    }
                }
                // An element with an unloaded node holds a contact edge, where the polynomial
                // through a zero and a steep rise overshoots beyond its nodes: there only the
                // span of its nodes counts.
                let loaded = (0..npe).all(|a| values[self.global_node(e, a)] > 0.0);
                let end = if loaded {
                    1.0
                } else {
                    self.kind.node_coordinates()[npe - 1]
                };
                let at = |xi: f64| c[0] + c[1] * xi + c[2] * xi * xi;
                let vertex = (c[2] < 0.0).then(|| -c[1] / (2.0 * c[2])).filter(|xi| xi.abs() < end);
                [at(-end), at(end), vertex.map_or(f64::NEG_INFINITY, at)]
                    .into_iter()
                    .fold(f64::NEG_INFINITY, f64::max)
            })
            .fold(f64::NEG_INFINITY, f64::max)
    }

    /// Value at `x` of the piecewise interpolant of nodal values (zero outside the grid).
    pub fn interpolate(&self, values: &[f64], x: f64) -> f64 {
        self.interpolation_row(x).into_iter().map(|(j, n)| n * values[j]).sum()
    }

    /// The nodal values on `onto` of the L² projection (weight dx) of the field that `values`
    /// interpolate on this grid, element by element of `onto`: on each of its elements the
    /// polynomial of the element's degree with the same integrals against its shape functions,
    /// so the field's integral over every element of `onto` (a traction's force) is kept
    /// exactly. (Interpolation would miss it where the field has a square-root point inside a
    /// coarse element.) Needs elements of `onto` that do not share nodes; a grid whose elements
    /// do gets the interpolated values. The integrals are exact: each element of `onto` is
    /// split at this grid's edges, and a 5-point Gauss rule integrates the degree-7 products of
    /// a quadratic field, a shape function and the map's derivative on each piece.
    pub fn projected_onto(&self, values: &[f64], onto: &ContactGrid) -> Vec<f64> {
        if onto.kind.shares_nodes() {
            return onto.nodes.iter().map(|&x| self.interpolate(values, x)).collect();
        }
        let (gauss_x, gauss_w) = crate::quadrature::gauss_legendre(5);
        let npe = onto.kind.nodes_per_element();
        let mut out = vec![0.0; onto.n_nodes()];
        for e in 0..onto.n_elements() {
            let (x0, x1) = (onto.edges[e], onto.edges[e + 1]);
            // The pieces' ends in ξ of `onto`'s element: its ends and this grid's edges inside.
            let mut cuts = vec![-1.0];
            cuts.extend(
                self.edges
                    .iter()
                    .filter(|&&x| x > x0 && x < x1)
                    .map(|&x| onto.element_xi(e, x)),
            );
            cuts.push(1.0);
            let mut mass = nalgebra::DMatrix::<f64>::zeros(npe, npe);
            let mut rhs = nalgebra::DVector::<f64>::zeros(npe);
            for piece in cuts.windows(2) {
                let (half, centre) = (0.5 * (piece[1] - piece[0]), 0.5 * (piece[0] + piece[1]));
                for (&g, &w) in gauss_x.iter().zip(&gauss_w) {
                    let xi = centre + half * g;
                    let x = onto.element_x(e, xi);
                    let dx = onto.element_dx_dxi(e, xi) * half * w;
                    let field = self.interpolate(values, x);
                    let shapes: Vec<f64> = (0..npe)
                        .map(|a| {
                            let [c0, c1, c2] = onto.kind.shape_polynomial(a);
                            c0 + c1 * xi + c2 * xi * xi
                        })
                        .collect();
                    for a in 0..npe {
                        rhs[a] += shapes[a] * field * dx;
                        for b in 0..npe {
                            mass[(a, b)] += shapes[a] * shapes[b] * dx;
                        }
                    }
                }
            }
            let local = mass.lu().solve(&rhs).unwrap_or(rhs);
            for a in 0..npe {
                out[onto.global_node(e, a)] = local[a];
            }
        }
        out
    }

    /// dx/dξ of element `e` at ξ (the derivative of [`Self::element_x`]) [length].
    fn element_dx_dxi(&self, e: usize, xi: f64) -> f64 {
        let (x0, x1) = (self.edges[e], self.edges[e + 1]);
        let centre = 0.5 * (x0 + x1);
        0.5 * (x1 - x0) - 2.0 * (self.mids[e] - centre) * xi
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A field of the coarse grid's own space comes back exactly, and the projection of a fine
    /// grid's field keeps its integral over every coarse element (a traction's force), on
    /// straight and on mapped elements; the field here has a square-root point inside a
    /// coarse element, where interpolation misses the integral.
    #[test]
    fn projection_keeps_each_element_integral_and_reproduces_the_coarse_space() {
        let dqe = ElementKind::DiscontinuousQuadratic;
        let coarse_edges = vec![-1.5, -0.9, -0.2, 0.45, 1.1, 1.5];
        let mids: Vec<f64> = coarse_edges
            .windows(2)
            .map(|w| 0.5 * (w[0] + w[1]) + 0.03 * (w[1] - w[0]))
            .collect();
        for coarse in [
            ContactGrid::from_edges(dqe, coarse_edges.clone()),
            ContactGrid::from_mapped_edges(dqe, coarse_edges.clone(), mids),
        ] {
            // A field of the coarse space comes back exactly.
            let own: Vec<f64> = coarse.nodes.iter().map(|&x| 1.0 + x - 0.7 * x * x).collect();
            let same = coarse.projected_onto(&own, &coarse);
            for (a, b) in same.iter().zip(&own) {
                assert!((a - b).abs() <= 1e-12, "own field {a} vs {b}");
            }
            let fine = ContactGrid::uniform(dqe, 257, -1.5, 1.5);
            // A Hertz-like pressure √(1 − x²) with its edge at x = 1 inside an element.
            let hertz: Vec<f64> = fine.nodes.iter().map(|&x| (1.0 - x * x).max(0.0).sqrt()).collect();
            let p = fine.projected_onto(&hertz, &coarse);
            let interpolated: Vec<f64> = coarse.nodes.iter().map(|&x| fine.interpolate(&hertz, x)).collect();
            for e in 0..coarse.n_elements() {
                let (x0, x1) = (coarse.edges[e], coarse.edges[e + 1]);
                let exact = integral_between(&fine, &hertz, x0, x1);
                let projected = integral_between(&coarse, &p, x0, x1);
                assert!(
                    (projected - exact).abs() <= 1e-12,
                    "element {e}: {projected} vs {exact}"
                );
            }
            let total_interp = coarse.integrate(&interpolated);
            let total_exact = fine.integrate(&hertz);
            assert!(
                (total_interp - total_exact).abs() > 1e-4,
                "interpolation should miss the force here"
            );
        }
    }

    /// ∫ from x0 to x1 of the grid's interpolant, by a fine composite rule split at its edges.
    fn integral_between(g: &ContactGrid, v: &[f64], x0: f64, x1: f64) -> f64 {
        let mut cuts = vec![x0];
        cuts.extend(g.edges.iter().copied().filter(|&x| x > x0 && x < x1));
        cuts.push(x1);
        let (gx, gw) = crate::quadrature::gauss_legendre(12);
        cuts.windows(2)
            .map(|w| {
                let (h, c) = (0.5 * (w[1] - w[0]), 0.5 * (w[0] + w[1]));
                gx.iter()
                    .zip(&gw)
                    .map(|(&t, &wt)| wt * h * g.interpolate(v, c + h * t))
                    .sum::<f64>()
            })
            .sum()
    }

    #[test]
    fn dqe_nodes_are_equally_spaced_and_weights_sum_to_length() {
        let g = ContactGrid::uniform(ElementKind::DiscontinuousQuadratic, 7, -1.3, 1.3);
        let h = g.node_spacing();
        for w in g.nodes.windows(2) {
            assert!((w[1] - w[0] - h).abs() < 1e-14);
        }
        let total: f64 = g.weights.iter().sum();
        assert!((total - 2.6).abs() < 1e-14);
    }

    #[test]
    fn continuous_quadratic_grid_shares_end_nodes_and_integrates_quadratics() {
        let kind = ElementKind::ContinuousQuadratic;
        let g = ContactGrid::uniform(kind, 4, 0.0, 2.0);
        assert_eq!(g.n_nodes(), 9);
        for (j, x) in g.nodes.iter().enumerate() {
            assert!((x - 0.25 * j as f64).abs() < 1e-15, "node {j} at {x}");
        }
        // Simpson weights: L/6 at the grid ends, L/3 at shared nodes, 2L/3 at midpoints.
        assert!((g.weights[0] - 0.5 / 6.0).abs() < 1e-15 && (g.weights[2] - 0.5 / 3.0).abs() < 1e-15);
        let f = |x: f64| 3.0 - 2.0 * x + x * x;
        let vals: Vec<f64> = g.nodes.iter().map(|&x| f(x)).collect();
        for x in [0.1, 0.5, 0.77, 1.999] {
            assert!((g.interpolate(&vals, x) - f(x)).abs() < 1e-13);
        }
        assert!((g.integrate(&vals) - (6.0 - 4.0 + 8.0 / 3.0)).abs() < 1e-13);
        assert_eq!(g.element_of(2), (1, 0));
        assert_eq!(g.element_of(8), (3, 2));
        assert_eq!(g.global_node(1, 2), 4);
    }

    /// A grid on the arc elements of a circle: nodes at the x of the arc's points at ξ = −2/3,
    /// 0, 2/3 of each element's quadratic map, weights integrating ∫ f dx of the traction
    /// interpolated in ξ exactly (checked against a fine quadrature of the same interpolant), and
    /// interpolation cardinal at the nodes.
    #[test]
    fn mapped_elements_follow_the_mesh_geometry() {
        let r = 40.0_f64;
        let angles: Vec<f64> = (0..=6).map(|k| (-21.0 + 7.0 * k as f64).to_radians()).collect();
        let edges: Vec<f64> = angles.iter().map(|t| r * t.sin()).collect();
        let mids: Vec<f64> = angles.windows(2).map(|w| r * (0.5 * (w[0] + w[1])).sin()).collect();
        let kind = ElementKind::DiscontinuousQuadratic;
        let g = ContactGrid::from_mapped_edges(kind, edges.clone(), mids.clone());
        assert!(!g.is_straight() && !g.is_uniform() && g.straightened().is_straight());
        for e in 0..g.n_elements() {
            assert!(
                (g.element_x(e, 0.0) - mids[e]).abs() < 1e-14 && (g.element_x(e, 1.0) - edges[e + 1]).abs() < 1e-13
            );
            for a in 0..3 {
                let xi = kind.node_coordinates()[a];
                assert!((g.nodes[e * 3 + a] - g.element_x(e, xi)).abs() < 1e-13);
            }
        }
        // The straight node positions differ from the mapped ones by more than round-off.
        let straight = g.straightened();
        let shift = g
            .nodes
            .iter()
            .zip(&straight.nodes)
            .fold(0.0_f64, |m, (a, b)| m.max((a - b).abs()));
        assert!(shift > 1e-4, "shift {shift}");
        let f = |x: f64| 1.0 + 0.3 * x - 0.02 * x * x;
        let vals: Vec<f64> = g.nodes.iter().map(|&x| f(x)).collect();
        for (j, &x) in g.nodes.iter().enumerate() {
            assert!((g.interpolate(&vals, x) - vals[j]).abs() < 1e-12, "node {j}");
        }
        // Gauss in x over each element (the interpolant is smooth there, not a polynomial in x).
        let (t, w) = crate::quadrature::gauss_legendre(24);
        let fine: f64 = g
            .edges
            .windows(2)
            .map(|e| {
                let (c, h) = (0.5 * (e[0] + e[1]), 0.5 * (e[1] - e[0]));
                t.iter()
                    .zip(&w)
                    .map(|(t, w)| w * h * g.interpolate(&vals, c + h * t))
                    .sum::<f64>()
            })
            .sum();
        assert!(
            (g.integrate(&vals) - fine).abs() < 1e-12 * fine.abs(),
            "{} vs {fine}",
            g.integrate(&vals)
        );
    }

    #[test]
    fn shape_functions_are_cardinal_and_reproduce_quadratics() {
        let kind = ElementKind::DiscontinuousQuadratic;
        for (a, xa) in kind.node_coordinates().iter().enumerate() {
            for b in 0..3 {
                let [c0, c1, c2] = kind.shape_polynomial(b);
                let v = c0 + c1 * xa + c2 * xa * xa;
                assert!((v - if a == b { 1.0 } else { 0.0 }).abs() < 1e-14);
            }
        }
        // Interpolating f(x) = 3 − 2x + x² exactly, and integrating it with the weights.
        let g = ContactGrid::uniform(kind, 4, 0.0, 2.0);
        let f = |x: f64| 3.0 - 2.0 * x + x * x;
        let vals: Vec<f64> = g.nodes.iter().map(|&x| f(x)).collect();
        for x in [0.1, 0.77, 1.5, 1.999] {
            assert!((g.interpolate(&vals, x) - f(x)).abs() < 1e-13);
        }
        let exact = 3.0 * 2.0 - 4.0 + 8.0 / 3.0;
        assert!((g.integrate(&vals) - exact).abs() < 1e-13);
    }
}
