//! The elements of an error-controlled contact grid as dyadic pieces of the start grid.
//!
//! Element `index` at `level` of start element `root` spans the `index`-th of its 2^level equal
//! pieces. Splitting, grading towards a point and merging two sibling pieces back are then
//! exact (every edge is the start element's ends combined with a dyadic fraction, so neighbours
//! agree on their common edge bit for bit), and the grid remembers which pieces may be merged.

use crate::grid::ContactGrid;

/// Deepest bisection of a start element: pieces of 2⁻⁴⁰ of a start element are far below any
/// useful accuracy, and the node spacings stay well above round-off of x.
pub const MAX_LEVEL: u32 = 40;

/// Largest length ratio of neighbouring elements after [`DyadicGrid::balanced`]: the slip
/// operator's three-point stencils and the nodal interpolation keep their accuracy on a grid
/// whose elements change size gradually.
pub const MAX_NEIGHBOUR_RATIO: f64 = 2.0;

/// One element: piece `index` of the 2^`level` equal pieces of start element `root`.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Cell {
    /// Start element it lies in.
    pub root: usize,
    /// Number of bisections from the start element.
    pub level: u32,
    /// Position among the 2^level pieces, from the left.
    pub index: u64,
}

impl Cell {
    /// The two halves, left first.
    pub fn children(self) -> [Cell; 2] {
        let child = |k| Cell {
            root: self.root,
            level: self.level + 1,
            index: 2 * self.index + k,
        };
        [child(0), child(1)]
    }

    /// The element this one is a half of (itself at level 0).
    pub fn parent(self) -> Cell {
        if self.level == 0 {
            return self;
        }
        Cell {
            root: self.root,
            level: self.level - 1,
            index: self.index / 2,
        }
    }

    /// Whether `self` and `next` (its right neighbour) are the two halves of one element.
    pub fn is_sibling_pair(self, next: Cell) -> bool {
        self.level > 0
            && self.root == next.root
            && self.level == next.level
            && self.index.is_multiple_of(2)
            && next.index == self.index + 1
    }
}

/// A contact grid of dyadic pieces of a start grid (module docs).
#[derive(Debug, Clone)]
pub struct DyadicGrid {
    /// The start grid: its elements, straight or mapped on a mesh's curved elements.
    root: ContactGrid,
    /// The elements in increasing x.
    cells: Vec<Cell>,
}

impl DyadicGrid {
    /// The start grid itself: every element a level-0 piece.
    pub fn new(start: &ContactGrid) -> Self {
        Self {
            root: start.clone(),
            cells: (0..start.n_elements())
                .map(|root| Cell {
                    root,
                    level: 0,
                    index: 0,
                })
                .collect(),
        }
    }

    /// The elements in increasing x.
    pub fn cells(&self) -> &[Cell] {
        &self.cells
    }

    /// Number of elements.
    pub fn len(&self) -> usize {
        self.cells.len()
    }

    /// Whether the grid has no element (never, for a grid built from a start grid).
    pub fn is_empty(&self) -> bool {
        self.cells.is_empty()
    }

    /// The intrinsic coordinates [ξ₀, ξ₁] ⊂ [−1, 1] a cell spans in its start element.
    pub fn xi_range(&self, c: Cell) -> (f64, f64) {
        let n = (1u64 << c.level) as f64;
        (-1.0 + 2.0 * c.index as f64 / n, -1.0 + 2.0 * (c.index + 1) as f64 / n)
    }

    /// Whether start element `e` is straight (its mid point the centre of its ends).
    fn root_straight(&self, e: usize) -> bool {
        let (a, b) = (self.root.edges[e], self.root.edges[e + 1]);
        self.root.mids[e] == 0.5 * (a + b)
    }

    /// x of the left (`right == false`) or right end of a cell [length].
    pub fn end(&self, c: Cell, right: bool) -> f64 {
        let (a, b) = (self.root.edges[c.root], self.root.edges[c.root + 1]);
        let n = 1u64 << c.level;
        let k = c.index + u64::from(right);
        if k == n {
            return b;
        }
        if k == 0 {
            return a;
        }
        if self.root_straight(c.root) {
            // Scaling by the power of two n is exact, so every piece's ends are a + (b − a)·k/n
            // rounded once, and two neighbours compute their common end identically.
            a + (b - a) * (k as f64) / (n as f64)
        } else {
            // A mapped element: the x of the mesh's quadratic element at ξ = −1 + 2k/n.
            self.root.element_x(c.root, -1.0 + 2.0 * (k as f64) / (n as f64))
        }
    }

    /// x of a cell's mid point [length]: its centre in a straight start element, the x at
    /// its mid ξ in a mapped one.
    pub fn mid(&self, c: Cell) -> f64 {
        if self.root_straight(c.root) {
            0.5 * (self.end(c, false) + self.end(c, true))
        } else {
            let (x0, x1) = self.xi_range(c);
            self.root.element_x(c.root, 0.5 * (x0 + x1))
        }
    }

    /// Length of a cell [length].
    pub fn length(&self, c: Cell) -> f64 {
        self.end(c, true) - self.end(c, false)
    }

    /// The contact grid of these elements.
    pub fn grid(&self) -> ContactGrid {
        let mut edges = Vec::with_capacity(self.cells.len() + 1);
        edges.push(self.end(self.cells[0], false));
        edges.extend(self.cells.iter().map(|&c| self.end(c, true)));
        let mids = self.cells.iter().map(|&c| self.mid(c)).collect();
        ContactGrid::from_mapped_edges(self.root.kind, edges, mids)
    }

    /// The start grid.
    pub fn root(&self) -> &ContactGrid {
        &self.root
    }

    /// Every element halved: the grid whose solution, set against this grid's, estimates the
    /// discretisation error (super docs).
    pub fn bisected(&self) -> DyadicGrid {
        DyadicGrid {
            cells: self.cells.iter().flat_map(|c| c.children()).collect(),
            ..self.clone()
        }
    }

    /// The grid with each element `e` replaced as `action[e]` says.
    pub fn refined(&self, action: &[Action]) -> DyadicGrid {
        assert_eq!(action.len(), self.cells.len(), "one action per element");
        let mut cells = Vec::with_capacity(self.cells.len());
        let mut e = 0;
        while e < self.cells.len() {
            let c = self.cells[e];
            match action[e] {
                Action::Merge if e + 1 < self.cells.len() && action[e + 1] == Action::Merge => {
                    if c.is_sibling_pair(self.cells[e + 1]) {
                        cells.push(c.parent());
                        e += 2;
                        continue;
                    }
                    cells.push(c);
                }
                Action::Keep | Action::Merge => cells.push(c),
                Action::Split(depth) => self.split_uniformly(c, depth, &mut cells),
                Action::GradeTowards(x, depth) => self.split_towards(c, x, depth, &mut cells),
            }
            e += 1;
        }
        DyadicGrid { cells, ..self.clone() }.balanced()
    }

    /// `c` cut into 2^depth equal pieces (fewer when [`MAX_LEVEL`] is reached).
    fn split_uniformly(&self, c: Cell, depth: u32, out: &mut Vec<Cell>) {
        if depth == 0 || c.level >= MAX_LEVEL {
            out.push(c);
            return;
        }
        for child in c.children() {
            self.split_uniformly(child, depth - 1, out);
        }
    }

    /// `c` halved `depth` times, each time the half that holds `x`: a geometric grading by 2
    /// towards x, `depth + 1` pieces.
    fn split_towards(&self, c: Cell, x: f64, depth: u32, out: &mut Vec<Cell>) {
        if depth == 0 || c.level >= MAX_LEVEL {
            out.push(c);
            return;
        }
        let [left, right] = c.children();
        if x < self.end(left, true) {
            self.split_towards(left, x, depth - 1, out);
            out.push(right);
        } else {
            out.push(left);
            self.split_towards(right, x, depth - 1, out);
        }
    }

    /// The grid with every element at most [`MAX_NEIGHBOUR_RATIO`] times as long as each
    /// neighbour: longer ones are halved until none is.
    pub fn balanced(mut self) -> DyadicGrid {
        loop {
            let n = self.cells.len();
            let too_long = |e: usize, cells: &[Cell]| {
                let l = self.length(cells[e]);
                // 10 % slack: pieces of a mapped (curved) start element are equal in ξ, not quite
                // in x, and a ratio of 2.0001 must not set off a cascade of halvings.
                let over = |j: usize| l > MAX_NEIGHBOUR_RATIO * self.length(cells[j]) * 1.1;
                (e > 0 && over(e - 1)) || (e + 1 < n && over(e + 1))
            };
            let split: Vec<bool> = (0..n)
                .map(|e| too_long(e, &self.cells) && self.cells[e].level < MAX_LEVEL)
                .collect();
            if !split.contains(&true) {
                return self;
            }
            self.cells = self
                .cells
                .iter()
                .zip(&split)
                .flat_map(|(&c, &s)| if s { c.children().to_vec() } else { vec![c] })
                .collect();
        }
    }
}

/// What happens to one element when the grid is refined.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Action {
    /// Stays.
    Keep,
    /// Cut into 2^depth equal pieces.
    Split(u32),
    /// Halved `depth` times towards x [length] (a contact edge or a stick/slip point inside).
    GradeTowards(f64, u32),
    /// Merged with its sibling, when the sibling is merged too.
    Merge,
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::grid::ElementKind;

    fn start() -> DyadicGrid {
        DyadicGrid::new(&ContactGrid::uniform(ElementKind::DiscontinuousQuadratic, 4, -2.0, 2.0))
    }

    #[test]
    fn bisection_halves_every_element_and_keeps_the_ends() {
        let g = start().bisected();
        let grid = g.grid();
        assert_eq!(grid.n_elements(), 8);
        assert_eq!(grid.edges, (0..=8).map(|k| -2.0 + 0.5 * k as f64).collect::<Vec<_>>());
    }

    #[test]
    fn grading_towards_a_point_halves_the_pieces_that_hold_it() {
        let g = start();
        let mut action = vec![Action::Keep; 4];
        // Start element 2 is [0, 1]; three halvings towards 0.3 leave [0, .25], [.25, .375],
        // [.375, .5] and [.5, 1] (then balanced against its short neighbour).
        action[2] = Action::GradeTowards(0.3, 3);
        let r = g.refined(&action);
        let edges = r.grid().edges;
        for x in [0.25, 0.375, 0.5] {
            assert!(edges.contains(&x), "{edges:?} lacks {x}");
        }
        // Balanced: no element more than twice its neighbour.
        for w in edges.windows(3) {
            let (l0, l1) = (w[1] - w[0], w[2] - w[1]);
            assert!(l0 <= 2.0 * l1 + 1e-12 && l1 <= 2.0 * l0 + 1e-12, "{edges:?}");
        }
    }

    #[test]
    fn merged_siblings_give_back_their_parent() {
        let g = start().bisected();
        let mut action = vec![Action::Keep; 8];
        action[0] = Action::Merge;
        action[1] = Action::Merge;
        // 1 and 2 are not siblings: merging only 2 does nothing.
        action[2] = Action::Merge;
        let r = g.refined(&action);
        assert_eq!(r.grid().edges[..3], [-2.0, -1.0, -0.5]);
        assert_eq!(r.len(), 7);
    }

    #[test]
    fn neighbours_agree_on_their_common_edge_at_every_level() {
        let g = start();
        let mut action = vec![Action::Keep; 4];
        action[1] = Action::GradeTowards(-0.999_999, 30);
        let r = g.refined(&action);
        let edges = r.grid().edges;
        assert!(edges.windows(2).all(|w| w[1] > w[0]));
        assert!(r.len() > 30);
    }
}
