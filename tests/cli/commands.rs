//! The `rollbem` binary: exit codes, messages, files written.

use std::path::{Path, PathBuf};

use crate::common::rollbem;

/// The fast Carter case with its results in `out/` next to it.
static BASE: std::sync::LazyLock<String> =
    std::sync::LazyLock::new(|| format!("{}output: {{dir: out}}\n", crate::common::CARTER_CASE));

fn write_case(dir: &Path, text: &str) -> PathBuf {
    let path = dir.join("case.yaml");
    std::fs::write(&path, text).unwrap();
    path
}

#[test]
fn run_writes_the_documented_outputs() {
    let dir = tempfile::tempdir().unwrap();
    let case = write_case(dir.path(), &BASE);
    let (code, stdout, stderr) = rollbem(&["run", case.to_str().unwrap()]);
    assert_eq!(code, 0, "{stderr}");
    assert!(
        stdout.contains("converged") && stdout.contains("stick zones"),
        "{stdout}"
    );
    let out = dir.path().join("out");
    let summary: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(out.join("summary.json")).unwrap()).unwrap();
    for key in [
        "converged",
        "iterations",
        "residual",
        "normal_force",
        "tangential_force",
        "overlap",
        "creep",
        "contact",
        "stick_zones",
        "slip_zones",
        "timings",
        "models",
        "case",
    ] {
        assert!(summary.get(key).is_some(), "summary.json lacks `{key}`");
    }
    for key in ["x_min", "x_max", "half_width"] {
        assert!(
            summary["contact"].get(key).is_some(),
            "summary.json contact lacks `{key}`"
        );
    }
    for key in ["assembly_s", "condense_s", "solve_s", "total_s"] {
        assert!(summary["timings"][key].as_f64().is_some(), "timings lacks `{key}`");
    }
    assert_eq!(summary["converged"], true);
    assert!(!summary["solver"]["history"].as_array().unwrap().is_empty());
    let csv = std::fs::read_to_string(out.join("contact.csv")).unwrap();
    let mut lines = csv.lines();
    assert_eq!(
        lines.next().unwrap(),
        "x,pressure,shear,gap,slip,slip_hbem,state,u_n_A,u_t_A,u_n_B,u_t_B"
    );
    let rows: Vec<&str> = lines.collect();
    assert_eq!(rows.len(), 63);
    assert!(!csv.contains("NaN") && !csv.contains("inf"));
    assert!(
        rows.iter().any(|r| r.contains(",stick,"))
            && rows.iter().any(|r| r.contains(",slip,"))
            && rows.iter().any(|r| r.contains(",open,"))
    );
    let svg = std::fs::read_to_string(out.join("contact.svg")).unwrap();
    assert!(svg.starts_with("<svg") && svg.len() > 2000);
    // No temporary folder left behind.
    let leftovers: Vec<_> = std::fs::read_dir(dir.path())
        .unwrap()
        .filter_map(|e| e.ok())
        .filter(|e| e.file_name().to_string_lossy().contains("partial"))
        .collect();
    assert!(leftovers.is_empty());
}

/// Each defect: exit code 1, a message naming the key, and no output folder.
#[test]
fn bad_input_is_rejected_with_the_key_named_and_nothing_written() {
    let cases: [(&str, &str, &str); 11] = [
        ("unknown key", "  friction: 0.1\n", "  friction: 0.1\n  frictoin: 0.2\n"),
        ("wrong type", "friction: 0.1", "friction: lots"),
        (
            "missing material",
            "A: {model: half_space, material: steel",
            "A: {model: half_space, material: stainless",
        ),
        ("nu outside", "nu: 0.3", "nu: 0.6"),
        ("E <= 0", "E: 210000.0", "E: -5.0"),
        ("mu < 0", "friction: 0.1", "friction: -0.1"),
        ("P <= 0", "force: 1812.4573", "force: 0.0"),
        ("full sliding", "ratio: 0.51", "ratio: 1.0"),
        ("zero elements", "elements: 21", "elements: 0"),
        (
            "two normal keys",
            "normal: {force: 1812.4573}",
            "normal: {force: 1812.4573, overlap: 0.01}",
        ),
        (
            "missing section",
            "load:\n  normal: {force: 1812.4573}\n  tangential: {ratio: 0.51}\n",
            "",
        ),
    ];
    let expected_key = [
        "frictoin",
        "contact.friction",
        "bodies.A.material",
        "materials.steel.nu",
        "materials.steel.E",
        "contact.friction",
        "load.normal.force",
        "load.tangential.ratio",
        "contact.grid.elements",
        "load.normal",
        "load",
    ];
    for ((label, from, to), key) in cases.iter().zip(expected_key) {
        let dir = tempfile::tempdir().unwrap();
        assert!(BASE.contains(from), "{label}: base lacks {from}");
        let case = write_case(dir.path(), &BASE.replacen(from, to, 1));
        let (code, _, stderr) = rollbem(&["run", case.to_str().unwrap()]);
        assert_eq!(code, 1, "{label}: {stderr}");
        assert!(stderr.contains(key), "{label}: message does not name `{key}`: {stderr}");
        assert!(
            stderr.contains("case.yaml"),
            "{label}: message does not name the file: {stderr}"
        );
        assert!(!dir.path().join("out").exists(), "{label}: output written");
    }
}

#[test]
fn bad_override_and_missing_file_are_input_errors() {
    let dir = tempfile::tempdir().unwrap();
    let case = write_case(dir.path(), &BASE);
    let (code, _, stderr) = rollbem(&["run", case.to_str().unwrap(), "--set", "contact.friction"]);
    assert_eq!(code, 1);
    assert!(
        stderr.contains("--set contact.friction") && stderr.contains("key.path=value"),
        "{stderr}"
    );
    let (code, _, stderr) = rollbem(&["run", case.to_str().unwrap(), "--set", "contact.friction.value=2"]);
    assert_eq!(code, 1, "{stderr}");
    let (code, _, stderr) = rollbem(&["run", dir.path().join("nope.yaml").to_str().unwrap()]);
    assert_eq!(code, 1);
    assert!(stderr.contains("nope.yaml"), "{stderr}");
    assert!(!dir.path().join("out").exists());
}

#[test]
fn non_convergence_exits_2_with_history_and_no_result() {
    let dir = tempfile::tempdir().unwrap();
    let case = write_case(dir.path(), &BASE);
    let (code, _, stderr) = rollbem(&["run", case.to_str().unwrap(), "--set", "solver.max_iterations=1"]);
    assert_eq!(code, 2, "{stderr}");
    assert!(stderr.contains("did not converge"), "{stderr}");
    let out = dir.path().join("out");
    let summary: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(out.join("summary.json")).unwrap()).unwrap();
    assert_eq!(summary["converged"], false);
    assert_eq!(summary["solver"]["history"].as_array().unwrap().len(), 1);
    assert!(summary["solver"]["history"][0]["residual"].as_f64().unwrap() > 0.0);
    assert!(
        !out.join("contact.csv").exists(),
        "a non-converged run must not look like a result"
    );
}

#[test]
fn check_prints_hertz_estimates_and_set_overrides_apply() {
    let dir = tempfile::tempdir().unwrap();
    let case = write_case(dir.path(), &BASE);
    let (code, stdout, stderr) = rollbem(&["check", case.to_str().unwrap()]);
    assert_eq!(code, 0, "{stderr}");
    assert!(
        stdout.contains("Hertz half-width a") && stdout.contains("1.000000"),
        "{stdout}"
    );
    assert!(
        stdout.contains("stick zone (Carter)") && stdout.contains("1.4000 a"),
        "{stdout}"
    );
    let (_, stdout, _) = rollbem(&["check", case.to_str().unwrap(), "--set", "contact.grid.elements=41"]);
    assert!(stdout.contains("41 discontinuous_quadratic"), "{stdout}");
}

/// `check --estimate` solves the grid and its halving: the estimate it prints is the
/// `error_estimate` that `run` writes for the same fixed grid, and it warns exactly when the
/// largest part exceeds `--tolerance`; without `--estimate` it says how to get one, and an
/// error-controlled grid is not solved.
#[test]
fn check_estimates_the_fixed_grid_s_error_and_warns_above_the_tolerance() {
    let case = crate::common::case_path("carter_051");
    let case = case.to_str().unwrap();
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("run");
    let (code, _, stderr) = rollbem(&["run", case, "--out", out.to_str().unwrap(), "-q"]);
    assert_eq!(code, 0, "{stderr}");
    let summary: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(out.join("summary.json")).unwrap()).unwrap();
    let e = &summary["error_estimate"];
    let part = |key: &str| e[key].as_f64().unwrap_or_else(|| panic!("error_estimate.{key}"));
    let (p, q, xi) = (part("pressure_rms"), part("shear_rms"), part("creep_rel"));
    let expected = format!("pressure {p:.2e} p0, shear {q:.2e} mu p0, creepage {xi:.2e} (relative)");
    let largest = p.max(q).max(xi);
    // Between the largest part and the others, and above it: no warning, then a warning.
    for (tolerance, warns) in [(2.0 * largest, false), (0.5 * largest, true)] {
        let t = format!("{tolerance}");
        let (code, stdout, stderr) = rollbem(&["check", case, "--estimate", "--tolerance", &t]);
        assert_eq!(code, 0, "{stderr}");
        let line = stdout
            .lines()
            .find(|l| l.contains("grid error (estimated)"))
            .expect("the line");
        assert!(line.contains(&expected), "{line}\nexpected {expected}");
        assert_eq!(
            stdout.contains("warning: the grid's estimated error"),
            warns,
            "{stdout}"
        );
    }
    let (_, stdout, _) = rollbem(&["check", case]);
    assert!(stdout.contains("not estimated: `rollbem check --estimate`"), "{stdout}");
    let (_, stdout, _) = rollbem(&["check", case, "--estimate", "--set", "contact.grid.tolerance=1e-3"]);
    assert!(stdout.contains("contact.grid.tolerance controls it"), "{stdout}");
}

/// Dissimilar bodies without friction: β/μ has no value, and `check` says so in a few words
/// (it printed an infinity of about 300 digits).
#[test]
fn check_says_beta_over_mu_is_undefined_without_friction() {
    let case = crate::common::case_path("dissimilar_al_steel_004");
    let set = ["--set", "contact.friction=0", "--set", "load.tangential={creep: 0}"];
    let (code, stdout, stderr) = rollbem(&[&["check", case.to_str().unwrap()][..], &set].concat());
    assert_eq!(code, 0, "{stderr}");
    let line = stdout
        .lines()
        .find(|l| l.contains("Dundurs beta (kappa"))
        .expect("the Dundurs line");
    assert!(
        line.contains("beta/mu undefined (frictionless)") && line.len() < 120,
        "{line}"
    );
    let (_, stdout, _) = rollbem(&["check", case.to_str().unwrap()]);
    assert!(stdout.contains("beta/mu = "), "{stdout}");
}

/// A `bem` case: `check` reads both meshes and reports groups, loops (none turned round) and the
/// overlap of the contact segments; mesh mistakes are input errors naming file and group.
#[test]
fn check_reads_bem_meshes_and_reports_mesh_errors() {
    let meshes = Path::new(env!("CARGO_MANIFEST_DIR")).join("meshes");
    let case = |a_bounds: &str, mesh_a: &str| {
        format!(
            r#"
materials:
  aluminium: {{G: 23000.0, nu: 0.31}}
  steel: {{G: 82000.0, nu: 0.28}}
bodies:
  A: {{model: bem, mesh: {}, material: aluminium, boundaries: {a_bounds}}}
  B: {{model: bem, mesh: {}, material: steel, boundaries: {{shaft: fixed, free: free}}}}
contact:
  friction: 0.2
load:
  normal: {{force: 405.05}}
  tangential: {{ratio: 0.375}}
"#,
            meshes.join(mesh_a).display(),
            meshes.join("roller_r300_shaft30_B.msh").display()
        )
    };
    let dir = tempfile::tempdir().unwrap();
    let good = write_case(
        dir.path(),
        &case("{shaft: fixed, free: free}", "roller_r150_shaft15_A.msh"),
    );
    let (code, stdout, stderr) = rollbem(&["check", good.to_str().unwrap()]);
    assert_eq!(code, 0, "{stderr}");
    for text in [
        "group `contact`",
        "21 elements",
        "group `shaft`",
        "1 outer, 1 holes",
        "profile radius 150.000000",
        "A and B overlap on [-1.235294, 1.235294]",
    ] {
        assert!(stdout.contains(text), "check output lacks `{text}`:\n{stdout}");
    }
    // The shipped meshes are drawn with rollbem's orientation: no loop is turned round (the
    // notice itself is checked on tests/data/msh/annulus.msh in tests/bem/msh_reader.rs).
    assert!(!stdout.contains("turned"), "a shipped mesh was turned round:\n{stdout}");
    let missing_group = write_case(dir.path(), &case("{shaft: fixed}", "roller_r150_shaft15_A.msh"));
    let (code, _, stderr) = rollbem(&["check", missing_group.to_str().unwrap()]);
    assert_eq!(code, 1);
    assert!(
        stderr.contains("`free`") && stderr.contains("roller_r150_shaft15_A.msh"),
        "{stderr}"
    );
    let unknown_group = write_case(
        dir.path(),
        &case("{shaft: fixed, free: free, hub: fixed}", "roller_r150_shaft15_A.msh"),
    );
    let (code, _, stderr) = rollbem(&["check", unknown_group.to_str().unwrap()]);
    assert_eq!(code, 1);
    assert!(stderr.contains("hub"), "{stderr}");
    let no_file = write_case(dir.path(), &case("{shaft: fixed, free: free}", "nope.msh"));
    let (code, _, stderr) = rollbem(&["check", no_file.to_str().unwrap()]);
    assert_eq!(code, 1);
    assert!(stderr.contains("nope.msh"), "{stderr}");
}

/// A run with bem bodies writes each body's boundary as quadratic edges and lists everything
/// in result.pvd.
#[test]
fn bem_runs_write_boundary_vtk_files_and_the_collection() {
    let dir = tempfile::tempdir().unwrap();
    let case = Path::new(env!("CARGO_MANIFEST_DIR")).join("cases/carter_051_true.yaml");
    let out = dir.path().join("out");
    let (code, _, stderr) = rollbem(&["run", case.to_str().unwrap(), "--out", out.to_str().unwrap()]);
    assert_eq!(code, 0, "{stderr}");
    for f in ["boundary_A.vtu", "boundary_B.vtu", "contact.vtu", "result.pvd"] {
        assert!(out.join(f).exists(), "{f} missing");
    }
    let vtu = std::fs::read_to_string(out.join("boundary_A.vtu")).unwrap();
    assert!(
        vtu.contains("Name=\"displacement\"") && vtu.contains("Name=\"traction\"") && vtu.contains("Name=\"group\"")
    );
    let pvd = std::fs::read_to_string(out.join("result.pvd")).unwrap();
    assert_eq!(pvd.matches("<DataSet").count(), 3, "{pvd}");
}

/// `rollbem validate` solves the built-in reference problems and reports each against its limit.
#[test]
fn validate_runs_the_reference_problems() {
    let (code, stdout, stderr) = rollbem(&["validate"]);
    assert_eq!(code, 0, "{stdout}{stderr}");
    assert!(stdout.contains("9 passed, 0 failed"), "{stdout}");
    assert!(
        stdout.contains("Carter creepage") && stdout.contains("Bufler"),
        "{stdout}"
    );
}

/// A bem body takes its contact grid from its mesh (discontinuous quadratic field nodes): asking
/// for another element type is refused, naming the key, instead of being ignored.
#[test]
fn bem_bodies_refuse_other_contact_element_types() {
    let dir = tempfile::tempdir().unwrap();
    let case = Path::new(env!("CARGO_MANIFEST_DIR")).join("cases/carter_051_block.yaml");
    let out = dir.path().join("out");
    for kind in ["constant", "continuous_quadratic"] {
        let (code, _, stderr) = rollbem(&[
            "run",
            case.to_str().unwrap(),
            "--out",
            out.to_str().unwrap(),
            "--set",
            &format!("contact.grid.element={kind}"),
        ]);
        assert_eq!(code, 1, "{stderr}");
        assert!(
            stderr.contains("contact.grid.element") && stderr.contains(kind),
            "{stderr}"
        );
        assert!(!out.exists());
    }
}

/// `output.interior` of a bem body: Somigliana fields written as CSV and VTU with the
/// displacement and the point status, listed in result.pvd and summarised in summary.json and
/// the run table; points outside the body or on its boundary are flagged and announced; a rigid
/// body is refused before anything is solved, naming the key.
#[test]
fn interior_of_bem_bodies_is_written_and_rigid_bodies_are_refused() {
    let dir = tempfile::tempdir().unwrap();
    let cases = Path::new(env!("CARGO_MANIFEST_DIR")).join("cases");
    let out = dir.path().join("block");
    let block = cases.join("carter_051_block.yaml");
    let (code, stdout, stderr) = rollbem(&["run", block.to_str().unwrap(), "--out", out.to_str().unwrap()]);
    assert_eq!(code, 0, "{stderr}");
    assert!(stdout.contains("interior A (bem)"), "{stdout}");
    let csv = std::fs::read_to_string(out.join("interior_A.csv")).unwrap();
    let mut lines = csv.lines();
    assert_eq!(
        lines.next(),
        Some("x,y,sxx,syy,szz,txy,von_mises,max_shear,ux,uy,status")
    );
    assert_eq!(lines.clone().count(), 31 * 40);
    assert!(lines.all(|l| l.ends_with(",inside")));
    let vtu = std::fs::read_to_string(out.join("interior_A.vtu")).unwrap();
    for name in ["stress", "von_mises", "max_shear", "displacement", "status"] {
        assert!(vtu.contains(&format!("Name=\"{name}\"")), "{name} missing");
    }
    let pvd = std::fs::read_to_string(out.join("result.pvd")).unwrap();
    assert_eq!(pvd.matches("<DataSet").count(), 4, "{pvd}");
    let summary: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(out.join("summary.json")).unwrap()).unwrap();
    let interior = &summary["interior"];
    assert_eq!(interior["model"], "bem");
    assert_eq!(interior["inside"], 31 * 40);
    assert!(interior["max_shear"]["value"].as_f64().unwrap() > 0.0);

    let tyre = cases.join("tyre_b01_incompressible.yaml");
    let rigid = dir.path().join("rigid");
    let (code, _, stderr) = rollbem(&[
        "run",
        tyre.to_str().unwrap(),
        "--out",
        rigid.to_str().unwrap(),
        "--set",
        "output.interior={body: A, x: [-1, 1, 5], y: [0.1, 0.5, 3]}",
    ]);
    assert_eq!(code, 1, "{stderr}");
    assert!(
        stderr.contains("output.interior.body") && stderr.contains("rigid"),
        "{stderr}"
    );
    assert!(!rigid.exists());

    // The 0.1 mm incompressible layer (y from −0.1 to 0): rows at y = −0.12 and −0.109 lie
    // below it, the row at y = −0.001 within its boundary layer.
    let layer = dir.path().join("layer");
    let (code, _, stderr) = rollbem(&[
        "run",
        tyre.to_str().unwrap(),
        "--out",
        layer.to_str().unwrap(),
        "--set",
        "output.interior={body: B, x: [-1.2, 1.2, 25], y: [-0.12, -0.001, 12]}",
    ]);
    assert_eq!(code, 0, "{stderr}");
    assert!(stderr.contains("lie outside the body"), "{stderr}");
    let csv = std::fs::read_to_string(layer.join("interior_B.csv")).unwrap();
    let count = |s: &str| csv.lines().filter(|l| l.ends_with(s)).count();
    assert!(count(",outside") >= 50 && count(",boundary") >= 25 && count(",inside") > 0);
    assert!(!csv.contains("NaN") && !csv.contains("inf"));
}

/// `rollbem study stability --quick` (the CI step): exit code 0 (the default method converged
/// everywhere a solution exists), the table on stdout, stability.csv and the heat maps written.
#[test]
fn study_stability_quick_writes_the_map() {
    let dir = tempfile::tempdir().unwrap();
    let case = Path::new(env!("CARGO_MANIFEST_DIR")).join("cases/carter_051.yaml");
    let out = dir.path().join("stab");
    let (code, stdout, stderr) = rollbem(&[
        "study",
        "stability",
        case.to_str().unwrap(),
        "--quick",
        "--out",
        out.to_str().unwrap(),
    ]);
    assert_eq!(code, 0, "{stdout}{stderr}");
    assert!(
        stdout.contains("gauss_seidel") && stdout.contains("wall time"),
        "{stdout}"
    );
    assert!(out.join("stability.csv").exists() && out.join("img/penalty_load.svg").exists());
    let (code, _, stderr) = rollbem(&[
        "study",
        "stability",
        dir.path().join("nope.yaml").to_str().unwrap(),
        "--quick",
    ]);
    assert_eq!(code, 1);
    assert!(stderr.contains("nope.yaml"), "{stderr}");
}

/// A body mesh too coarse for the tolerance: the thin tyre layer's strip as it was shipped before
/// its bonded face was refined (tests/data/msh/tyre_layer_b01_coarse_bond.msh: elements of
/// 0.5 mm, five layer thicknesses, on the bonded face under the contact; P 2 % off) at 1e-3.
/// Exit code 2, the message naming the body, its mesh and its groups; summary.json written with
/// `converged: false` and the body meshes' estimate after the error control's two bisections;
/// no contact.csv.
#[test]
fn a_body_mesh_too_coarse_exits_2_naming_it_with_the_estimate_written() {
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("out");
    let case = crate::common::case_path("tyre_b01_incompressible");
    let mesh = Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/data/msh/tyre_layer_b01_coarse_bond.msh");
    let (code, _, stderr) = rollbem(&[
        "run",
        case.to_str().unwrap(),
        "--set",
        &format!("bodies.B.mesh={}", mesh.display()),
        "--set",
        "contact.grid.tolerance=1e-3",
        "--out",
        out.to_str().unwrap(),
    ]);
    assert_eq!(code, 2, "{stderr}");
    assert!(
        stderr.contains("the mesh of body B")
            && stderr.contains("tyre_layer_b01_coarse_bond.msh")
            && stderr.contains("groups free, ends, bonded")
            && stderr.contains("too coarse"),
        "{stderr}"
    );
    let summary: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(out.join("summary.json")).unwrap()).unwrap();
    assert_eq!(summary["converged"], false);
    let body_mesh = &summary["error_estimate"]["body_mesh"];
    assert_eq!(body_mesh["bisections"], 2, "{body_mesh}");
    assert!(body_mesh["shear"].as_f64().unwrap() > 1e-3, "{body_mesh}");
    assert!(!out.join("contact.csv").exists());
}

/// The same tyre as shipped (its bonded face as fine as the contact under it) meets 1e-3.
#[test]
fn the_shipped_tyre_mesh_meets_1e_3() {
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("out");
    let case = crate::common::case_path("tyre_b01_incompressible");
    let (code, _, stderr) = rollbem(&[
        "run",
        case.to_str().unwrap(),
        "--set",
        "contact.grid.tolerance=1e-3",
        "--out",
        out.to_str().unwrap(),
    ]);
    assert_eq!(code, 0, "{stderr}");
    let summary: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(out.join("summary.json")).unwrap()).unwrap();
    assert_eq!(summary["error_estimate"]["body_mesh"]["bisections"], 0);
}
