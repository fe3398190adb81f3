//! Boundary meshes of plane bodies: what the BEM needs from a Gmsh `.msh` file.
//!
//! A [`BoundaryMesh`] is the boundary of one plane body (possibly multiply connected: an outer
//! contour and any number of holes), cut into 2-node (`line2`) or 3-node (`line3`) elements,
//! each element belonging to one physical curve group (`contact`, `shaft`, `free`, …).
//! Coordinates are in the length unit of the case (mm in the shipped cases), in the plane z = 0.
//!
//! # Orientation convention
//! **The material lies on the left of every element**, walking from its node 0 to its node 1.
//! The outer contour therefore runs counter-clockwise and holes run clockwise, and the unit
//! normal n = (t_y, −t_x), with t the unit tangent in the walking direction, points **out of
//! the material** (Brebbia–Telles–Wrobel's outward normal, used by the kernels of
//! [`crate::bem::kernel`]). [`check::validate_and_orient`] establishes this for any input order
//! and reports every loop it had to turn round.
//!
//! # Node order inside an element
//! Gmsh's order: `line2` = [end0, end1], `line3` = [end0, end1, mid] (intrinsic coordinates
//! ξ = −1, +1, 0).

pub mod bisect;
pub mod build;
pub mod check;
pub mod coarsen;
pub mod cuts;
pub mod geometry;
pub mod loaded;
pub mod msh;
pub mod parametric;
pub mod smooth;

pub use check::{boundary_loops, validate_and_orient, BoundaryLoop};
pub use geometry::ElementGeometry;
pub use loaded::LoadedMesh;
pub use msh::{parse_msh_bytes, read_msh, write_msh41_ascii};

use std::path::Path;

/// A named physical curve group of the mesh (Gmsh `Physical Curve("name", tag)`).
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct PhysicalGroup {
    /// Gmsh's physical tag.
    pub tag: i32,
    /// Gmsh's physical name (the key used by boundary conditions in a case).
    pub name: String,
}

/// One boundary element.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct BoundaryElement {
    /// Indices into [`BoundaryMesh::nodes`]: 2 (`line2`: [end0, end1]) or 3 (`line3`:
    /// [end0, end1, mid]).
    pub nodes: Vec<usize>,
    /// Index into [`BoundaryMesh::groups`].
    pub group: usize,
}

impl BoundaryElement {
    /// The two end nodes (start, end) in the walking direction.
    pub fn ends(&self) -> (usize, usize) {
        (self.nodes[0], self.nodes[1])
    }

    /// Turns the element round: swaps its end nodes (the mid node of a `line3` stays).
    pub fn reverse(&mut self) {
        self.nodes.swap(0, 1);
    }
}

/// The boundary of one plane body.
#[derive(Debug, Clone, PartialEq)]
pub struct BoundaryMesh {
    /// Node coordinates (x, y) [length].
    pub nodes: Vec<[f64; 2]>,
    /// Boundary elements.
    pub elements: Vec<BoundaryElement>,
    /// Physical curve groups referenced by the elements.
    pub groups: Vec<PhysicalGroup>,
    /// Where the mesh came from (file path or a label), for messages.
    pub source: String,
}

impl BoundaryMesh {
    /// Builds a mesh from its parts, labelled `source` in messages.
    pub fn new(
        nodes: Vec<[f64; 2]>,
        elements: Vec<BoundaryElement>,
        groups: Vec<PhysicalGroup>,
        source: impl Into<String>,
    ) -> Self {
        Self {
            nodes,
            elements,
            groups,
            source: source.into(),
        }
    }

    /// Index of the physical group called `name`, or [`MeshError::MissingGroup`] listing the
    /// groups the mesh has.
    pub fn group_index(&self, name: &str) -> Result<usize, MeshError> {
        self.groups
            .iter()
            .position(|g| g.name == name)
            .ok_or_else(|| MeshError::MissingGroup {
                path: self.source.clone(),
                name: name.to_string(),
                available: self.group_names().join(", "),
            })
    }

    /// Names of the physical groups, in the mesh's order.
    pub fn group_names(&self) -> Vec<String> {
        self.groups.iter().map(|g| g.name.clone()).collect()
    }

    /// Number of elements of group `group` (an index into [`Self::groups`]).
    pub fn count_in_group(&self, group: usize) -> usize {
        self.elements.iter().filter(|e| e.group == group).count()
    }

    /// The x coordinates [length] of the end nodes of group `group`'s elements, sorted, each
    /// once (coordinates closer than `tolerance` [length] count as one): a built mesh's
    /// contact edges, which the mesh builders' tests compare with the grid they were given.
    #[cfg(test)]
    pub(crate) fn group_end_abscissae(&self, group: usize, tolerance: f64) -> Vec<f64> {
        let mut xs: Vec<f64> = self
            .elements
            .iter()
            .filter(|e| e.group == group)
            .flat_map(|e| [self.nodes[e.nodes[0]][0], self.nodes[e.nodes[1]][0]])
            .collect();
        xs.sort_by(f64::total_cmp);
        xs.dedup_by(|a, b| (*a - *b).abs() <= tolerance);
        xs
    }

    /// Length of the bounding-box diagonal [length]; the scale for geometric tolerances.
    pub fn size(&self) -> f64 {
        let mut lo = [f64::INFINITY; 2];
        let mut hi = [f64::NEG_INFINITY; 2];
        for p in &self.nodes {
            for k in 0..2 {
                lo[k] = lo[k].min(p[k]);
                hi[k] = hi[k].max(p[k]);
            }
        }
        if self.nodes.is_empty() {
            return 0.0;
        }
        ((hi[0] - lo[0]).powi(2) + (hi[1] - lo[1]).powi(2)).sqrt()
    }
}

/// Reads a Gmsh MSH 4.1 file (ASCII or binary), checks it and orients its loops (see the module
/// docs). Returns the mesh and one notice per loop that had to be turned round.
pub fn load(path: &Path) -> Result<(BoundaryMesh, Vec<String>), MeshError> {
    let mut mesh = read_msh(path)?;
    let notices = validate_and_orient(&mut mesh)?;
    Ok((mesh, notices))
}

/// Everything that can be wrong with a boundary mesh. Each message names the file (or the
/// mesh's label), the group or element concerned, and what to do.
#[derive(Debug, thiserror::Error)]
pub enum MeshError {
    /// The file does not exist.
    #[error("mesh file {path} not found (paths in a case are relative to the case file)")]
    NotFound {
        /// The path as given.
        path: String,
    },
    /// The file exists but cannot be read.
    #[error("cannot read mesh file {path}: {source}")]
    Io {
        /// The path as given.
        path: String,
        /// The operating-system error.
        #[source]
        source: std::io::Error,
    },
    /// The file is not in Gmsh's MSH 4.1 format.
    #[error(
        "{path} is not a Gmsh MSH 4.1 file ({found}); export it with `gmsh -1 -format msh41 file.geo` \
         or `Mesh.MshFileVersion = 4.1;` (ASCII or binary both work)"
    )]
    NotMsh4 {
        /// The file.
        path: String,
        /// What was found instead (the version line, or "no $MeshFormat header").
        found: String,
    },
    /// The MSH parser rejected the file.
    #[error("cannot parse {path}: {message}")]
    Parse {
        /// The file.
        path: String,
        /// The parser's message.
        message: String,
    },
    /// A boundary (curve) element is neither `line2` nor `line3`.
    #[error(
        "{path}: element {element} on curve {curve} is of type {kind}; rollbem reads 2-node (line2) \
         and 3-node (line3) boundary elements only: mesh with `Mesh.ElementOrder = 2;` (or 1)"
    )]
    UnknownElementType {
        /// The file.
        path: String,
        /// Gmsh element tag.
        element: u64,
        /// Gmsh curve (entity) tag.
        curve: i32,
        /// Gmsh's element type name.
        kind: String,
    },
    /// A physical curve group has no entry in `$PhysicalNames`.
    #[error(
        "{path}: physical curve group {tag} has no name; name it in the .geo, e.g. \
         `Physical Curve(\"contact\", {tag}) = {{...}};`, because boundary conditions refer to groups by name"
    )]
    MissingPhysicalName {
        /// The file.
        path: String,
        /// Gmsh physical tag.
        tag: i32,
    },
    /// Boundary elements lie on a curve that belongs to no physical group.
    #[error(
        "{path}: curve {curve} has boundary elements but belongs to no physical group; put every \
         boundary curve in a `Physical Curve(\"name\")` so that it gets a boundary condition"
    )]
    UntaggedCurve {
        /// The file.
        path: String,
        /// Gmsh curve (entity) tag.
        curve: i32,
    },
    /// A curve belongs to several physical curve groups, so its boundary condition is ambiguous.
    #[error(
        "{path}: curve {curve} belongs to several physical groups ({groups}); each boundary curve \
         must be in exactly one `Physical Curve`"
    )]
    AmbiguousGroup {
        /// The file.
        path: String,
        /// Gmsh curve (entity) tag.
        curve: i32,
        /// The group names (or tags).
        groups: String,
    },
    /// The path is not a regular file (a folder, a FIFO, a device: reading it could block or
    /// never end), or the file is beyond [`crate::limits::MAX_MESH_BYTES`].
    #[error("cannot read mesh file {path}: {kind}; give the path of a Gmsh .msh file")]
    NotRegularFile {
        /// The path as given.
        path: String,
        /// What it is instead, or why it is too large.
        kind: String,
    },
    /// Two nodes of the `$Nodes` section carry the same tag.
    #[error(
        "{path}: node tag {node} is defined twice, at ({}, {}, {}) and at ({}, {}, {}); every node \
         needs its own tag: regenerate the mesh or renumber it (`Coherence Mesh;`, `RenumberMeshNodes;`)",
        first[0], first[1], first[2], second[0], second[1], second[2]
    )]
    DuplicateNode {
        /// The file.
        path: String,
        /// Gmsh node tag.
        node: u64,
        /// Its first coordinates.
        first: [f64; 3],
        /// Its second coordinates.
        second: [f64; 3],
    },
    /// A node coordinate is NaN or infinite.
    #[error(
        "{path}: node {node} has a coordinate that is not a finite number ({}, {}, {}); fix or \
         regenerate the mesh",
        xyz[0], xyz[1], xyz[2]
    )]
    NonFiniteNode {
        /// The file.
        path: String,
        /// Gmsh node tag.
        node: u64,
        /// Its coordinates.
        xyz: [f64; 3],
    },
    /// An element refers to a node tag that the `$Nodes` section does not define.
    #[error("{path}: element {element} refers to node {node}, which is not in the $Nodes section")]
    UnknownNode {
        /// The file.
        path: String,
        /// Gmsh element tag.
        element: u64,
        /// Gmsh node tag.
        node: u64,
    },
    /// The file holds no boundary elements at all.
    #[error(
        "{path}: no boundary (curve) elements found; mesh the curves (`gmsh -1`) and tag them with \
         `Physical Curve(\"name\")`"
    )]
    NoBoundaryElements {
        /// The file.
        path: String,
    },
    /// A node is out of the plane z = 0.
    #[error("{path}: node {node} lies at z = {z}; rollbem is plane: draw the bodies in z = 0")]
    NotPlanar {
        /// The file.
        path: String,
        /// Gmsh node tag.
        node: u64,
        /// Its z coordinate.
        z: f64,
    },
    /// An element refers to a node index outside the node list (in-memory meshes).
    #[error("{path}: element {element} refers to node {node}, but the mesh has {count} nodes")]
    NodeOutOfRange {
        /// The mesh.
        path: String,
        /// Element index (0-based, in the mesh's element list).
        element: usize,
        /// The node index.
        node: usize,
        /// Number of nodes.
        count: usize,
    },
    /// An element has neither 2 nor 3 nodes, or an unknown group (in-memory meshes).
    #[error("{path}: element {element} is malformed: {problem}")]
    MalformedElement {
        /// The mesh.
        path: String,
        /// Element index (0-based).
        element: usize,
        /// What is wrong.
        problem: String,
    },
    /// A boundary loop is not closed.
    #[error(
        "{path}: the boundary is not closed: element {element} of group `{group}` ends at node \
         {node} ({x}, {y}) and no other element starts there. Gmsh writes only the curves of \
         physical groups: if a curve of the outline is in none, it is missing from the file \
         (this file has the groups {groups}): add it to one (`Physical Curve(\"contact\") = \
         {{...}};`). Otherwise close the curve loop in the .geo (shared end points, `Coherence;`) \
         and mesh all its curves"
    )]
    OpenLoop {
        /// The mesh.
        path: String,
        /// The physical groups the file has, listed for the message.
        groups: String,
        /// Group of the dangling element.
        group: String,
        /// Element index (0-based).
        element: usize,
        /// Node index (0-based) of the free end.
        node: usize,
        /// x of the free end.
        x: f64,
        /// y of the free end.
        y: f64,
    },
    /// More than two elements meet at one node (a T-junction or a duplicated curve).
    #[error(
        "{path}: {count} element ends meet at node {node} ({x}, {y}) (groups {groups}); a body's \
         boundary must be simple closed loops: remove duplicated or internal curves"
    )]
    BranchingBoundary {
        /// The mesh.
        path: String,
        /// Node index (0-based).
        node: usize,
        /// How many element ends meet there.
        count: usize,
        /// x of the node.
        x: f64,
        /// y of the node.
        y: f64,
        /// Groups of the elements meeting there.
        groups: String,
    },
    /// An element that cannot be integrated: zero length or a folded mapping.
    #[error("{path}: element {element} of group `{group}` at ({x}, {y}) {defect}")]
    BadElement {
        /// The mesh.
        path: String,
        /// Group name.
        group: String,
        /// Element index (0-based).
        element: usize,
        /// x of its first node.
        x: f64,
        /// y of its first node.
        y: f64,
        /// What is wrong with it.
        defect: ElementDefect,
    },
    /// Two pieces of the boundary cross or touch: a bow-tie outline, or a hole that crosses the
    /// outer contour or another hole.
    #[error(
        "{path}: the boundary crosses itself near ({x}, {y}): an element of group `{first}` meets one \
         of group `{second}`; a body's boundary must be closed loops that neither cross nor touch \
         (check the order of the points of the outline, and that every hole lies inside the body)"
    )]
    CrossingBoundary {
        /// The mesh.
        path: String,
        /// Group of one of the two elements.
        first: String,
        /// Group of the other.
        second: String,
        /// x near the crossing.
        x: f64,
        /// y near the crossing.
        y: f64,
    },
    /// A loop lies outside the body's outer contour (a second body), or inside a hole (an island).
    #[error(
        "{path}: the loop of group(s) `{groups}` through ({x}, {y}) lies {}; a mesh describes one body: \
         one outer contour (here group(s) `{outer}`) and holes directly inside it. Move the loop into \
         the body or remove it",
        if *island { "inside a hole of the body (an island)" } else { "outside the body's outer contour" }
    )]
    LoopOutsideBody {
        /// The mesh.
        path: String,
        /// Groups of the offending loop.
        groups: String,
        /// Groups of the outer contour.
        outer: String,
        /// x of a node of the loop.
        x: f64,
        /// y of that node.
        y: f64,
        /// Whether the loop lies inside a hole rather than outside the outer contour.
        island: bool,
    },
    /// A boundary condition (or the contact) names a group that the mesh does not have.
    #[error("{path}: no physical group named `{name}`; the mesh has: {available}")]
    MissingGroup {
        /// The mesh.
        path: String,
        /// The requested name.
        name: String,
        /// The names that exist.
        available: String,
    },
}

/// What makes an element of a mesh unusable ([`MeshError::BadElement`]).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum ElementDefect {
    /// Its ends coincide (numerically).
    ZeroLength,
    /// The mid node of a 3-node element is so far off-centre that the mapping folds over.
    Distorted,
    /// Its node count (2 or 3) differs from that of the mesh's first element: the boundary
    /// mixes line2 and line3 elements.
    MixedOrder {
        /// Nodes of this element.
        nodes: usize,
        /// Nodes of the mesh's first element.
        first: usize,
    },
}

impl std::fmt::Display for ElementDefect {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(match self {
            Self::ZeroLength => "has zero length; remove duplicated points or degenerate curves from the geometry",
            Self::Distorted => {
                "is distorted (its mid node is not in the middle third between its ends); \
                 regenerate the mesh"
            }
            Self::MixedOrder { nodes, first } => {
                return write!(
                    f,
                    "has {nodes} nodes where the mesh's first element has {first}: rollbem takes a \
                     boundary of line2 elements or of line3 elements, not both; mesh every curve at \
                     one order (Gmsh: Mesh.ElementOrder = {order}, or `SetOrder {order};`)",
                    order = first - 1
                )
            }
        })
    }
}
