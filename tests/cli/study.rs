//! `rollbem study accuracy`: the three body models of the Carter scene against the
//! closed form, and the command's outputs.

use crate::common::rollbem;
use rollbem::case;
use rollbem::study::accuracy::{self, AccuracyOptions, SceneModel};

/// Carter's similar rollers (Q/μP = 0.51), quick ladder 11, 21, 41: every model converges and
/// its RMS shear error against Carter falls at least like h^(1/2) over the two grid doublings
/// (measured: half-space 8.6e-3 → 1.3e-3, blocks 8.2e-3 → 1.3e-3, true rollers 8.8e-3 → 1.9e-3,
/// i.e. ×4.6 to ×6.6; the limit ×2 is what a first-order traction error near the stick/slip kink
/// can still guarantee), and at 41 elements it is below 0.3 % of μp0 (the max-norm limits of
/// docs/validation.md are 2 % for the half-space and blocks, 3 % for the true rollers). The
/// creepage against Carter's is within 2 % at 11 elements (measured 0.90–1.17 %) and falls by
/// at least half over the two doublings, below 0.6 % at 41 (measured 0.21–0.48 %, ×2.4 to ×4.4
/// over the two doublings).
#[test]
fn accuracy_study_of_the_carter_scene_converges_for_every_model() {
    let loaded = case::load(&crate::common::case_path("carter_051"), &[]).unwrap();
    let options = AccuracyOptions {
        ladder: AccuracyOptions::quick_ladder(),
        tolerances: vec![1e-2, 1e-3, 1e-4],
        ..AccuracyOptions::default()
    };
    let report = accuracy::run(&loaded, &options, false).unwrap();
    assert!(report.reference.starts_with("Carter"), "{}", report.reference);
    assert_eq!(report.rows.len(), 12);
    // The error-controlled runs meet their tolerance in the study's own measure (against
    // Carter), each on a larger grid than the one before.
    let adaptive: Vec<_> = report
        .rows
        .iter()
        .filter(|r| r.model == SceneModel::HalfSpaceAdaptive)
        .collect();
    assert_eq!(adaptive.len(), 3);
    for r in &adaptive {
        let tol = r.tolerance.unwrap();
        assert!(r.converged && r.error <= tol, "{r:?}");
    }
    assert!(adaptive
        .windows(2)
        .all(|w| w[1].contact_elements > w[0].contact_elements));
    for model in SceneModel::ALL {
        let rows: Vec<_> = report.rows.iter().filter(|r| r.model == model).collect();
        assert!(rows.iter().all(|r| r.converged), "{model:?}: {rows:?}");
        let (coarse, fine) = (rows[0].error, rows[2].error);
        assert!(coarse / fine > 2.0, "{model:?}: RMS error {coarse} → {fine}");
        assert!(fine < 3e-3, "{model:?}: RMS error {fine} at 41 elements");
        let creep: Vec<f64> = rows.iter().map(|r| r.creep_error.unwrap().abs()).collect();
        assert!(creep[0] < 0.02, "{model:?}: creepage error {} at 11 elements", creep[0]);
        assert!(
            creep[2] < 0.5 * creep[0] && creep[2] < 6e-3,
            "{model:?}: creepage error {creep:?} does not converge"
        );
        if !matches!(model, SceneModel::HalfSpace | SceneModel::HalfSpaceAdaptive) {
            assert!(rows.iter().all(|r| r.boundary_elements > 0));
        }
    }
    // The Pareto front runs from fast and coarse to slow and accurate.
    let front = accuracy::pareto_front(&report);
    assert!(front.len() >= 2);
    assert!(front.windows(2).all(|w| w[1].0 >= w[0].0 && w[1].1 < w[0].1));
}

/// A scene without a closed form (dissimilar materials) is measured against its finest
/// true-geometry run, and says so.
#[test]
fn accuracy_study_without_a_closed_form_uses_the_finest_true_geometry_run() {
    let loaded = case::load(&crate::common::case_path("dissimilar_beta0288_075"), &[]).unwrap();
    let options = AccuracyOptions {
        ladder: vec![11, 21],
        models: vec![SceneModel::HalfSpace],
        ..AccuracyOptions::default()
    };
    let report = accuracy::run(&loaded, &options, false).unwrap();
    assert!(
        report.reference.contains("finest true-geometry run (21"),
        "{}",
        report.reference
    );
    assert_eq!(report.rows.len(), 2, "only the requested model is reported");
    assert!(report
        .rows
        .iter()
        .all(|r| r.converged && r.error.is_finite() && r.error > 0.0));
}

#[test]
fn study_accuracy_command_writes_the_table_and_the_chart() {
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("acc");
    let case = crate::common::case_path("carter_051");
    let (code, stdout, stderr) = rollbem(&[
        "study",
        "accuracy",
        case.to_str().unwrap(),
        "--quick",
        "--models",
        "half_space,true_geometry",
        "--out",
        out.to_str().unwrap(),
    ]);
    assert_eq!(code, 0, "{stdout}{stderr}");
    assert!(
        stdout.contains("true_geometry") && stdout.contains("RMS error"),
        "{stdout}"
    );
    let csv = std::fs::read_to_string(out.join("accuracy.csv")).unwrap();
    assert_eq!(csv.lines().count(), 1 + 6, "{csv}");
    assert!(csv.starts_with("model,contact_elements,tolerance,boundary_elements,converged"));
    let svg = std::fs::read_to_string(out.join("accuracy.svg")).unwrap();
    assert!(svg.contains("<svg") && svg.contains("Pareto front"));
    assert!(out.join("accuracy.json").exists());

    let (code, _, stderr) = rollbem(&["study", "accuracy", case.to_str().unwrap(), "--models", "fem"]);
    assert_eq!(code, 1);
    assert!(stderr.contains("unknown model `fem`"), "{stderr}");

    // A rung too small to hold the contact is a usage error, not a panic in the grid.
    let refused = dir.path().join("refused");
    let (code, _, stderr) = rollbem(&[
        "study",
        "accuracy",
        case.to_str().unwrap(),
        "--ladder",
        "21,0",
        "--out",
        refused.to_str().unwrap(),
    ]);
    assert_eq!(code, 1, "{stderr}");
    assert!(stderr.contains("--ladder") && stderr.contains("value = 0"), "{stderr}");
    assert!(!refused.exists(), "a refused study writes nothing");
}

/// The error-controlled runs next to the uniform ladder, with CONTACT's measured curve on the
/// chart (docs/data/contact_carter2d.csv).
#[test]
fn study_accuracy_draws_the_error_controlled_runs_and_a_reference_curve() {
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("acc");
    let case = crate::common::case_path("carter2d_contact");
    let data = case
        .parent()
        .unwrap()
        .parent()
        .unwrap()
        .join("docs/data/contact_carter2d.csv");
    let (code, stdout, stderr) = rollbem(&[
        "study",
        "accuracy",
        case.to_str().unwrap(),
        "--models",
        "half_space,half_space_adaptive",
        "--ladder",
        "21,41",
        "--tolerances",
        "1e-3,1e-4",
        "--reference-curve",
        data.to_str().unwrap(),
        "--out",
        out.to_str().unwrap(),
    ]);
    assert_eq!(code, 0, "{stdout}{stderr}");
    assert!(stdout.contains("(tolerance 1e-4)"), "{stdout}");
    let csv = std::fs::read_to_string(out.join("accuracy.csv")).unwrap();
    let adaptive: Vec<Vec<&str>> = csv
        .lines()
        .map(|l| l.split(',').collect::<Vec<_>>())
        .filter(|r| r[0] == "half_space_adaptive")
        .collect();
    assert_eq!(adaptive.len(), 2, "{csv}");
    for r in &adaptive {
        let (tol, error): (f64, f64) = (r[2].parse().unwrap(), r[6].parse().unwrap());
        assert!(error <= tol, "{csv}");
    }
    let svg = std::fs::read_to_string(out.join("accuracy.svg")).unwrap();
    assert!(svg.contains("half_space_adaptive") && svg.contains("CONTACT"), "legend");

    let bad = dir.path().join("bad.csv");
    std::fs::write(
        &bad,
        "elements,error,time_s
50,x,0.1
",
    )
    .unwrap();
    let (code, _, stderr) = rollbem(&[
        "study",
        "accuracy",
        case.to_str().unwrap(),
        "--reference-curve",
        bad.to_str().unwrap(),
    ]);
    assert_eq!(code, 1, "{stderr}");
    assert!(stderr.contains("line 2"), "{stderr}");
}

/// `rollbem check` advises from the measured half-space error tables (src/advice.rs): the
/// paper's rollers (a/R = 0.02, error 0.5 % of μp0) meet 1 % but not 0.1 %; a cover layer of
/// b/a ≈ 0.1 needs the BEM at any usual tolerance.
#[test]
fn check_advises_the_model_for_the_tolerance() {
    let carter = crate::common::case_path("carter_051");
    let (code, out, _) = rollbem(&["check", carter.to_str().unwrap()]);
    assert_eq!(code, 0);
    assert!(out.contains("half_space is enough for a tolerance of 1.00 %"), "{out}");
    let (_, out, _) = rollbem(&["check", carter.to_str().unwrap(), "--tolerance", "0.001"]);
    assert!(out.contains("use bem"), "{out}");
    let tyre = crate::common::case_path("tyre_b01_incompressible");
    let (_, out, _) = rollbem(&["check", tyre.to_str().unwrap(), "--tolerance", "0.1"]);
    assert!(out.contains("layer thickness b") && out.contains("use bem"), "{out}");
    let (code, _, err) = rollbem(&["check", carter.to_str().unwrap(), "--tolerance", "0"]);
    assert_eq!(code, 1, "{err}");
}

/// `rollbem check` on a roller in a ring bore reports the internal-contact family (its ring
/// wall is not a cover layer): the measured half-space error, 28.5 % of p0 at a/R1 = 0.2 and
/// 0.66 % at 0.01 (src/advice.rs INTERNAL_ERROR), so the BEM at the conformal contact and the
/// half-space at 1 % for the small one.
#[test]
fn check_advises_internal_contact_from_its_own_table() {
    let conformal = crate::common::case_path("bore_a020_tractive");
    let (code, out, _) = rollbem(&["check", conformal.to_str().unwrap()]);
    assert_eq!(code, 0);
    assert!(
        out.contains("roller in a ring bore (internal contact), a/R1 = 2.000e-1"),
        "{out}"
    );
    assert!(out.contains("use bem") && out.contains("28.50 % of p0"), "{out}");
    assert!(!out.contains("layer thickness b"), "{out}");
    let small = crate::common::case_path("bore_a001_tractive");
    let (_, out, _) = rollbem(&["check", small.to_str().unwrap()]);
    assert!(out.contains("half_space is enough for a tolerance of 1.00 %"), "{out}");
    assert!(out.contains("0.66 % of p0"), "{out}");
}

/// `rollbem study accuracy` on a roller in a ring bore: every model converges, and the true
/// geometry is the roller on its shaft inside a ring round the bore (rim fixed), whose
/// creepage departs from Carter's by the curvature term of internal contact (docs/conformal.md
/// §6: +43 % at a/R1 = 0.05, μ = 0.2) while the half-space stays within 1 % of it.
#[test]
fn study_accuracy_runs_on_a_roller_in_a_ring_bore() {
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("acc");
    let case = crate::common::case_path("bore_a005_tractive");
    let (code, stdout, stderr) = rollbem(&[
        "study",
        "accuracy",
        case.to_str().unwrap(),
        "--quick",
        "--out",
        out.to_str().unwrap(),
    ]);
    assert_eq!(code, 0, "{stdout}{stderr}");
    let csv = std::fs::read_to_string(out.join("accuracy.csv")).unwrap();
    let rows: Vec<Vec<&str>> = csv.lines().skip(1).map(|l| l.split(',').collect()).collect();
    assert_eq!(rows.len(), 11, "{csv}");
    for r in &rows {
        assert_eq!(r[4], "true", "{csv}");
        let creep_error: f64 = r[8].parse().unwrap();
        match r[0] {
            "true_geometry" => assert!(creep_error > 0.3 && creep_error < 0.6, "{csv}"),
            "half_space" | "half_space_adaptive" => assert!(creep_error.abs() < 0.01, "{csv}"),
            _ => {}
        }
    }
}

/// `rollbem study shakedown`: the map of the case's criterion has Johnson's values at its ends
/// (von Mises: first yield 3.10, shakedown 4.0 at μ = 0, the limit governed at the surface at
/// μ = 0.5), and each run of `--vary` puts both bodies on it at the run's |Q|/P and p_max/k, with
/// their own limits the run's factors times that load.
#[test]
fn shakedown_study_draws_the_map_and_the_case() {
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("sd");
    let (code, stdout, stderr) = rollbem(&[
        "study",
        "shakedown",
        crate::common::case_path("carter_051").to_str().unwrap(),
        "--set",
        "contact.friction=0.3",
        "--vary",
        "load.tangential.ratio=0.3,0.9",
        "--out",
        out.to_str().unwrap(),
    ]);
    assert_eq!(code, 0, "{stderr}");
    assert!(stdout.contains("elastic"), "{stdout}");
    for f in ["shakedown_map.csv", "shakedown_points.csv", "shakedown.svg"] {
        assert!(out.join(f).exists(), "{f}");
    }
    let map = std::fs::read_to_string(out.join("shakedown_map.csv")).unwrap();
    let rows: Vec<Vec<&str>> = map.lines().skip(1).map(|l| l.split(',').collect()).collect();
    let num = |s: &str| s.parse::<f64>().unwrap();
    assert_eq!(rows.len(), 26);
    assert!(
        (num(rows[0][1]) - 3.107).abs() < 3e-3 && (num(rows[0][2]) - 4.0).abs() < 2e-3,
        "{:?}",
        rows[0]
    );
    assert_eq!(rows[25][3], "surface");
    let points = std::fs::read_to_string(out.join("shakedown_points.csv")).unwrap();
    let points: Vec<Vec<&str>> = points.lines().skip(1).map(|l| l.split(',').collect()).collect();
    assert_eq!(points.len(), 4, "two runs, two bodies");
    // Q/μP 0.3 and 0.9 at μ = 0.3: |Q|/P = 0.09 and 0.27; p_max/k = 1153.83/866.03.
    assert!((num(points[0][2]) - 0.09).abs() < 1e-9 && (num(points[2][2]) - 0.27).abs() < 1e-9);
    assert!(
        (num(points[0][3]) - 1153.826441 / 866.025404).abs() < 1e-5,
        "{:?}",
        points[0]
    );
}

/// A run with `output.strength` (cases/carter_051.yaml ships with it) writes summary.json's
/// `strength` for both bodies, each proved by its residual-stress table (whose least row factor
/// is the body's) and drawn in strength_<body>.svg.
#[test]
fn a_strength_run_writes_its_factors_and_their_proof() {
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("run");
    let case = crate::common::case_path("carter_051");
    let (code, stdout, stderr) = rollbem(&["run", case.to_str().unwrap(), "--out", out.to_str().unwrap()]);
    assert_eq!(code, 0, "{stderr}");
    assert!(stdout.contains("strength A (half_space)"), "{stdout}");
    let summary: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(out.join("summary.json")).unwrap()).unwrap();
    let strength = summary["strength"].as_array().unwrap();
    assert_eq!(strength.len(), 2);
    for s in strength {
        let body = s["body"].as_str().unwrap();
        let factor = s["shakedown"]["factor"].as_f64().unwrap();
        assert!(
            s["first_yield"]["factor"].as_f64().unwrap() < factor,
            "first yield comes first: {s}"
        );
        let csv = std::fs::read_to_string(out.join(format!("residual_stress_{body}.csv"))).unwrap();
        let least = csv
            .lines()
            .skip(1)
            .map(|l| l.split(',').nth(1).unwrap().parse::<f64>().unwrap())
            .fold(f64::INFINITY, f64::min);
        assert!((least - factor).abs() < 1e-12 * factor, "{body}: {least} {factor}");
        assert!(out.join(format!("strength_{body}.svg")).exists());
    }
}
