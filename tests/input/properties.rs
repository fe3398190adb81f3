//! Structured property tests (proptest, fixed seeds): what must hold for every case text and
//! every mesh, not only for the examples of the other tests. They run in a few seconds; the
//! open-ended search is `cargo fuzz` (fuzz/README.md).
//!
//! - Any `--set` overrides of a valid case: parsing never panics, and a case that validates holds
//!   only finite numbers.
//! - Any numeric values of a half-space case: solving never panics; it either fails with exit
//!   code 1 (refused) or 2 (broke down), or returns a solution and summary with only finite numbers.
//! - Any byte mutation of a valid mesh (ASCII or binary): reading and checking never panic, and a
//!   mesh that passes has finite coordinates and closed loops.
//! - Any renumbering of a mesh's node tags reads as the same mesh.
//! - A star-shaped polygon is accepted; swapping two neighbouring corners of a convex one makes
//!   it cross itself, which is refused.

use proptest::prelude::*;
use proptest::test_runner::{Config, RngSeed};
use rollbem::mesh::{self, BoundaryElement, BoundaryMesh, MeshError, PhysicalGroup};
use rollbem::post::finite::first_non_finite;
use std::path::{Path, PathBuf};

const BASE: &str = r#"
title: "property"
materials:
  steel: {E: 210000.0, nu: 0.3}
bodies:
  A: {model: half_space, material: steel, radius: 100.0}
  B: {model: half_space, material: steel, radius: 100.0}
contact:
  friction: 0.1
  grid: {elements: 21, extent: 1.3}
load:
  normal: {force: 1812.4573}
  tangential: {ratio: 0.51}
"#;

fn config(cases: u32, seed: u64) -> Config {
    Config {
        cases,
        rng_seed: RngSeed::Fixed(seed),
        failure_persistence: None,
        ..Config::default()
    }
}

const KEYS: &[&str] = &[
    "materials.steel.E",
    "materials.steel.G",
    "materials.steel.nu",
    "bodies.A.radius",
    "bodies.B.radius",
    "bodies.A.model",
    "bodies.B",
    "contact.friction",
    "contact.grid.elements",
    "contact.grid.extent",
    "contact.grid.half_length",
    "contact.grid.element",
    "contact.grid.align_edges",
    "contact.rolling_direction",
    "contact.slip_derivative",
    "load.normal.force",
    "load.normal.overlap",
    "load.normal",
    "load.tangential.ratio",
    "load.tangential.force",
    "load.tangential.creep",
    "load.tangential",
    "solver.method",
    "solver.formulation",
    "solver.penalty",
    "solver.tolerance",
    "solver.max_iterations",
    "output.interior",
    "output.vtk",
    "title",
    "units",
    "materials",
];

const VALUES: &[&str] = &[
    ".nan",
    ".inf",
    "-.inf",
    "0",
    "-0.0",
    "1e308",
    "1.7976931348623157e308",
    "5e-324",
    "-1",
    "1e-30",
    "1e30",
    "1e31",
    "1e400",
    "18446744073709551616",
    "null",
    "[]",
    "{}",
    "!weird 0.1",
    "!!float 1",
    "abc",
    "true",
    "2",
    "0.5",
    "0.99",
    "phi",
    "psi",
    "auto",
    "newton",
    "gauss_seidel",
    "norm_tang",
    "+x",
    "-x",
    "constant",
    "continuous_quadratic",
    "{body: A, x: [-2, 2, 5], y: [0.1, 1, 3]}",
    "{body: B, x: [0, 1, 1e9], y: [-1, -0.1, 3]}",
    "{body: A, x: [-.inf, .inf, 5], y: [0.1, 1, 3]}",
    "{model: rigid, radius: 100}",
    "{model: rigid}",
    "{model: bem, mesh: nowhere.msh, material: steel, boundaries: {}}",
    "{overlap: 0.01}",
    "{force: .nan}",
    "{creep: 1e-3}",
    "[[[[[[[[1]]]]]]]]",
    "\"\\0\"",
];

/// A YAML value: an interesting literal or a number of any magnitude.
fn value() -> impl Strategy<Value = String> {
    prop_oneof![
        proptest::sample::select(VALUES).prop_map(str::to_string),
        any::<f64>().prop_map(|v| format!("{v:e}")),
        any::<u64>().prop_map(|v| v.to_string()),
        (-40i32..40, 1u32..100).prop_map(|(e, m)| format!("{m}e{e}")),
    ]
}

fn overrides() -> impl Strategy<Value = Vec<String>> {
    proptest::collection::vec(
        (proptest::sample::select(KEYS), value()).prop_map(|(k, v)| format!("{k}={v}")),
        0..4,
    )
}

proptest! {
    #![proptest_config(config(600, 0x5EED_0001))]

    /// Parsing any overrides never panics; a case that validates holds finite numbers only.
    #[test]
    fn validated_cases_hold_finite_numbers(set in overrides()) {
        if let Ok(loaded) = rollbem::case::parse(BASE, Path::new("case.yaml"), &set) {
            prop_assert_eq!(first_non_finite(&loaded.case), None, "{:?}", set);
        }
    }
}

/// Numeric overrides drawn mostly from the valid region (log-uniform magnitudes around the
/// base case), so that many cases get solved.
fn numeric_overrides() -> impl Strategy<Value = Vec<String>> {
    let magnitude = |key: &'static str, lo: f64, hi: f64| {
        (lo.log10()..hi.log10()).prop_map(move |e| format!("{key}={:e}", 10f64.powf(e)))
    };
    let one = prop_oneof![
        magnitude("materials.steel.E", 1e-35, 1e35),
        (-1.2f64..0.7).prop_map(|v| format!("materials.steel.nu={v}")),
        magnitude("bodies.A.radius", 1e-35, 1e35),
        magnitude("bodies.B.radius", 1e-35, 1e35),
        magnitude("load.normal.force", 1e-35, 1e35),
        magnitude("contact.friction", 1e-8, 1e7),
        (3usize..40).prop_map(|n| format!("contact.grid.elements={n}")),
        (0.5f64..150.0).prop_map(|v| format!("contact.grid.extent={v}")),
        magnitude("contact.grid.half_length", 1e-35, 1e35),
        (-1.1f64..1.1).prop_map(|v| format!("load.tangential.ratio={v}")),
        (-2.5f64..2.5).prop_map(|v| format!("load.tangential={{creep: {v:e}}}")),
        magnitude("solver.penalty", 1e-14, 1e14),
        proptest::sample::select(&["newton", "newton_plain", "norm_tang", "gauss_seidel"][..])
            .prop_map(|m| format!("solver.method={m}")),
        proptest::sample::select(&["phi", "psi"][..]).prop_map(|m| format!("solver.formulation={m}")),
        proptest::sample::select(&["constant", "discontinuous_quadratic", "continuous_quadratic"][..])
            .prop_map(|m| format!("contact.grid.element={m}")),
        Just("bodies.A={model: rigid, radius: 100.0}".to_string()),
        Just("load.normal={overlap: 0.02}".to_string()),
        magnitude("load.normal.overlap", 1e-35, 1e35)
            .prop_map(|s| format!("load.normal={{overlap: {}}}", s.split('=').nth(1).unwrap())),
        Just("output.interior={body: A, x: [-2, 2, 7], y: [0.05, 2, 5]}".to_string()),
    ];
    proptest::collection::vec(one, 1..5)
}

proptest! {
    #![proptest_config(config(200, 0x5EED_0002))]

    /// Solving any validated numeric variation never panics; a solution is finite throughout.
    #[test]
    fn solutions_are_finite_or_the_run_fails_cleanly(set in numeric_overrides()) {
        let Ok(loaded) = rollbem::case::parse(BASE, Path::new("case.yaml"), &set) else {
            return Ok(());
        };
        match rollbem::app::solve(&loaded) {
            Ok(s) => {
                prop_assert_eq!(first_non_finite(&s.solution), None, "{:?}", set);
                let summary = rollbem::output::summary(&s);
                prop_assert_eq!(first_non_finite(&summary), None, "{:?}", set);
                if let Some(f) = &s.interior {
                    prop_assert!(f.stress.iter().flatten().all(|v| v.is_finite()), "{:?}", set);
                }
            }
            Err(e) => prop_assert!([1, 2].contains(&e.exit_code()), "{:?}: {}", set, e),
        }
    }
}

fn data(name: &str) -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/data/msh").join(name)
}

/// One edit of a file's bytes.
#[derive(Debug, Clone)]
enum Edit {
    /// Replace the byte at (position fraction) with a value.
    Set(f64, u8),
    /// Delete `len` bytes from a position.
    Delete(f64, usize),
    /// Insert a snippet at a position.
    Insert(f64, &'static str),
    /// Keep only the first fraction of the file.
    Truncate(f64),
    /// Replace the n-th whitespace-separated token with a snippet.
    Token(usize, &'static str),
}

const SNIPPETS: &[&str] = &[
    "nan",
    "-1",
    "0",
    "1e308",
    "inf",
    "99999999999999999999",
    "4294967296",
    "-2147483649",
    "$Nodes\n",
    "$EndNodes\n",
    "$Elements\n",
    "\n",
    " ",
    "1",
    "2",
    "3",
    "8",
    "26",
    "1.5",
    "\"",
];

fn edit() -> impl Strategy<Value = Edit> {
    let snippet = || proptest::sample::select(SNIPPETS);
    prop_oneof![
        (0.0f64..1.0, any::<u8>()).prop_map(|(p, b)| Edit::Set(p, b)),
        (0.0f64..1.0, 1usize..40).prop_map(|(p, n)| Edit::Delete(p, n)),
        (0.0f64..1.0, snippet()).prop_map(|(p, s)| Edit::Insert(p, s)),
        (0.0f64..1.0).prop_map(Edit::Truncate),
        (0usize..2000, snippet()).prop_map(|(n, s)| Edit::Token(n, s)),
    ]
}

fn apply(bytes: &mut Vec<u8>, e: &Edit) {
    let at = |p: f64, len: usize| ((p * len as f64) as usize).min(len);
    match *e {
        Edit::Set(p, b) => {
            let i = at(p, bytes.len());
            if i < bytes.len() {
                bytes[i] = b;
            }
        }
        Edit::Delete(p, n) => {
            let i = at(p, bytes.len());
            let j = (i + n).min(bytes.len());
            bytes.drain(i..j);
        }
        Edit::Insert(p, s) => {
            let i = at(p, bytes.len());
            bytes.splice(i..i, s.bytes());
        }
        Edit::Truncate(p) => {
            let i = at(p, bytes.len());
            bytes.truncate(i);
        }
        Edit::Token(n, s) => {
            let mut starts = Vec::new();
            for i in 0..bytes.len() {
                if !bytes[i].is_ascii_whitespace() && (i == 0 || bytes[i - 1].is_ascii_whitespace()) {
                    starts.push(i);
                }
            }
            if let Some(&i) = starts.get(n % starts.len().max(1)) {
                let j = bytes[i..]
                    .iter()
                    .position(|b| b.is_ascii_whitespace())
                    .map_or(bytes.len(), |k| i + k);
                bytes.splice(i..j, s.bytes());
            }
        }
    }
}

proptest! {
    #![proptest_config(config(2000, 0x5EED_0003))]

    /// Reading and checking any mutation of a valid mesh never panics; what passes is sound.
    #[test]
    fn mutated_meshes_are_read_or_refused_without_panic(
        file in proptest::sample::select(&["annulus.msh", "annulus_bin.msh", "square_linear.msh", "plate_bin.msh", "plate.msh"][..]),
        edits in proptest::collection::vec(edit(), 1..4),
    ) {
        let mut bytes = std::fs::read(data(file)).unwrap();
        for e in &edits {
            apply(&mut bytes, e);
        }
        if let Ok(mut m) = mesh::parse_msh_bytes(&bytes, file) {
            if mesh::validate_and_orient(&mut m).is_ok() {
                prop_assert!(m.nodes.iter().flatten().all(|v| v.is_finite()), "{:?}", edits);
                prop_assert!(mesh::boundary_loops(&m).is_ok(), "{:?}", edits);
            }
        }
    }
}

/// The ASCII mesh `text` with its node tags renumbered by `new_tag` (old tag → new tag) in
/// $Nodes and $Elements.
fn renumber(text: &str, new_tag: &dyn Fn(u64) -> u64) -> String {
    let lines: Vec<&str> = text.lines().collect();
    let mut out: Vec<String> = lines.iter().map(|l| l.to_string()).collect();
    let nodes = lines.iter().position(|l| *l == "$Nodes").unwrap() + 1;
    let mut i = nodes + 1;
    while lines[i] != "$EndNodes" {
        let n: usize = lines[i].split_whitespace().nth(3).unwrap().parse().unwrap();
        for k in i + 1..i + 1 + n {
            out[k] = new_tag(lines[k].trim().parse().unwrap()).to_string();
        }
        i += 1 + 2 * n;
    }
    let elements = lines.iter().position(|l| *l == "$Elements").unwrap() + 1;
    let mut i = elements + 1;
    while lines[i] != "$EndElements" {
        let n: usize = lines[i].split_whitespace().nth(3).unwrap().parse().unwrap();
        for k in i + 1..i + 1 + n {
            let words: Vec<u64> = lines[k].split_whitespace().map(|w| w.parse().unwrap()).collect();
            let renamed: Vec<String> = std::iter::once(words[0].to_string())
                .chain(words[1..].iter().map(|&t| new_tag(t).to_string()))
                .collect();
            out[k] = renamed.join(" ");
        }
        i += 1 + n;
    }
    // The header's min and max tags are left as they were: readers must not rely on them.
    out.join("\n") + "\n"
}

/// The mesh as a sorted list of elements, each the bits of its points: independent of numbering.
fn geometry(m: &BoundaryMesh) -> Vec<(String, Vec<[u64; 2]>)> {
    let mut g: Vec<_> = m
        .elements
        .iter()
        .map(|e| {
            (
                m.groups[e.group].name.clone(),
                e.nodes.iter().map(|&n| m.nodes[n].map(f64::to_bits)).collect(),
            )
        })
        .collect();
    g.sort();
    g
}

proptest! {
    #![proptest_config(config(64, 0x5EED_0004))]

    /// Any permutation (and shift) of the node tags reads as the same mesh.
    #[test]
    fn renumbered_node_tags_read_as_the_same_mesh(
        file in proptest::sample::select(&["annulus.msh", "square_linear.msh", "plate.msh"][..]),
        seed in any::<u64>(),
        shift in 0u64..1000,
    ) {
        let text = std::fs::read_to_string(data(file)).unwrap();
        let original = mesh::parse_msh_bytes(text.as_bytes(), file).unwrap();
        let n = original.nodes.len() as u64 * 4;
        // A permutation of 1..=n_tags from the seed (Fisher–Yates with a linear congruential stream).
        let n_tags = text.lines().skip_while(|l| *l != "$Nodes").nth(1).unwrap()
            .split_whitespace().nth(1).unwrap().parse::<u64>().unwrap();
        let mut perm: Vec<u64> = (1..=n_tags).collect();
        let mut state = seed | 1;
        for i in (1..perm.len()).rev() {
            state = state.wrapping_mul(6364136223846793005).wrapping_add(1442695040888963407);
            perm.swap(i, (state >> 33) as usize % (i + 1));
        }
        let renamed = renumber(&text, &|t| perm[(t - 1) as usize] + shift);
        let read = mesh::parse_msh_bytes(renamed.as_bytes(), file);
        prop_assert!(read.is_ok(), "{:?}", read.err());
        prop_assert_eq!(geometry(&read.unwrap()), geometry(&original));
        prop_assert!(n > 0);
    }
}

/// A closed polygon of line2 elements through `points`, in one group.
fn polygon(points: &[[f64; 2]]) -> BoundaryMesh {
    let n = points.len();
    BoundaryMesh::new(
        points.to_vec(),
        (0..n)
            .map(|i| BoundaryElement {
                nodes: vec![i, (i + 1) % n],
                group: 0,
            })
            .collect(),
        vec![PhysicalGroup {
            tag: 1,
            name: "outline".into(),
        }],
        "polygon",
    )
}

proptest! {
    #![proptest_config(config(256, 0x5EED_0005))]

    /// A star-shaped outline is one simple loop; swapping two neighbouring corners of a convex
    /// one makes it cross itself, which is refused with the group named.
    #[test]
    fn simple_outlines_pass_and_swapped_corners_cross(
        angles in proptest::collection::btree_set(0u32..3600, 4..40),
        radii in proptest::collection::vec(0.5f64..1.5, 40),
        swap in any::<proptest::sample::Index>(),
    ) {
        let angle = |a: u32| f64::from(a) * std::f64::consts::PI / 1800.0;
        let star: Vec<[f64; 2]> = angles.iter().zip(&radii)
            .map(|(&a, r)| [r * angle(a).cos(), r * angle(a).sin()]).collect();
        let mut m = polygon(&star);
        prop_assert!(mesh::validate_and_orient(&mut m).is_ok());

        let mut convex: Vec<[f64; 2]> = angles.iter().map(|&a| [angle(a).cos(), angle(a).sin()]).collect();
        let i = swap.index(convex.len());
        let j = (i + 1) % convex.len();
        convex.swap(i, j);
        let err = mesh::validate_and_orient(&mut polygon(&convex)).unwrap_err();
        prop_assert!(
            matches!(&err, MeshError::CrossingBoundary { first, .. } if first == "outline"),
            "{}", err
        );
    }
}

/// `materials.NAME.yield` and `output.strength`: every bad value refused by its key, with what
/// to do (docs/strength.md).
#[test]
fn strength_inputs_are_refused_by_key() {
    use crate::common::rollbem;
    let dir = tempfile::tempdir().unwrap();
    let case = crate::common::case_path("hertz");
    let case = case.to_str().unwrap();
    let out = dir.path().join("o");
    let out = out.to_str().unwrap();
    let refused = |set: &[&str], key: &str, says: &str| {
        let mut args = vec!["run", case, "--out", out];
        for s in set {
            args.extend(["--set", s]);
        }
        let (code, _, stderr) = rollbem(&args);
        assert_eq!(code, 1, "{set:?}: {stderr}");
        assert!(stderr.contains(key) && stderr.contains(says), "{set:?}: {stderr}");
        assert!(!std::path::Path::new(out).exists(), "{set:?} wrote its folder");
    };
    let ask = "output.strength.criterion=von_mises";
    refused(
        &["materials.steel.yield.shear=0", ask],
        "materials.steel.yield.shear",
        "positive",
    );
    refused(
        &["materials.steel.yield.tensile=-5", ask],
        "materials.steel.yield.tensile",
        "positive",
    );
    refused(
        &["materials.steel.yield={shear: 300, tensile: 500}", ask],
        "materials.steel.yield",
        "exactly one",
    );
    refused(&[ask], "output.strength.bodies", "no body to assess");
    refused(
        &["materials.steel.yield.shear=300", "output.strength.criterion=rankine"],
        "output.strength.criterion",
        "von_mises",
    );
    refused(
        &[
            "materials.steel.yield.shear=300",
            ask,
            "bodies.B={model: rigid, radius: 100.0}",
            "output.strength.bodies=[A, B]",
        ],
        "output.strength.bodies",
        "body B is rigid",
    );
    refused(
        &["materials.steel.yield.shear=300", ask, "output.strength.grid=[1, 100]"],
        "output.strength.grid",
        "2..2000",
    );
    refused(
        &[
            "materials.other={E: 1000.0, nu: 0.3}",
            "bodies.B.material=other",
            "materials.steel.yield.shear=300",
            ask,
            "output.strength.bodies=[A, B]",
        ],
        "materials.other.yield",
        "missing",
    );
}
