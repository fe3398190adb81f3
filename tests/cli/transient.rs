//! `rollbem run` of a transient case: cases/cattaneo_to_carter.yaml (Carter's steel pair, a =
//! 1 mm, μ 0.3, pressed, shifted to Q/μP = 0.6, then rolled 400 steps of one node spacing on 41
//! elements) against the two closed forms, and the files the run writes.

use crate::common::{case_path, rollbem};

/// Q/(μP) of the case.
const RATIO: f64 = 0.6;

/// transient.csv as rows of named cells.
fn read_rows(text: &str) -> (Vec<String>, Vec<Vec<String>>) {
    let mut lines = text.lines();
    let header: Vec<String> = lines.next().unwrap().split(',').map(str::to_string).collect();
    let rows = lines.map(|l| l.split(',').map(str::to_string).collect()).collect();
    (header, rows)
}

/// `rollbem run` of `case` with `--set` overrides `sets` into `out` (exit 0 asserted): its
/// transient.csv as rows of named cells.
fn run_history(case: &std::path::Path, out: &std::path::Path, sets: &[&str]) -> (Vec<String>, Vec<Vec<String>>) {
    let mut args = vec!["run", case.to_str().unwrap(), "--out", out.to_str().unwrap(), "-q"];
    for set in sets {
        args.extend(["--set", set]);
    }
    let (code, _, stderr) = rollbem(&args);
    assert_eq!(code, 0, "{sets:?}: {stderr}");
    read_rows(&std::fs::read_to_string(out.join("transient.csv")).unwrap())
}

/// Step 0 has Cattaneo–Mindlin's stick zone |x| < c = a√(1 − Q/μP) (Johnson, Contact
/// Mechanics, 1985, §7.1); the last step Carter's, of width 2a√(1 − Q/μP) at the leading edge
/// x = +a. The zone ends are the nodes' midpoints (as in summary.json), so they resolve a stick
/// zone to half a node spacing h/2 = 0.0108a on this grid; measured: step 0 ±0.6344a against
/// ±0.6325a (1.9e-3a), the last step [−0.2688a, 0.9990a] against [−0.2649a, a] (3.9e-3a). The
/// tolerance is h/2. The history settles (tractions within 1e-3 μp_max of the last step's) after
/// 4.1a, and rolls at 1.07 Newton iterations a step.
#[test]
fn cattaneo_to_carter_runs_from_the_case_file() {
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("c2c");
    let case = case_path("cattaneo_to_carter");
    let (code, stdout, stderr) = rollbem(&["run", case.to_str().unwrap(), "--out", out.to_str().unwrap()]);
    assert_eq!(code, 0, "{stderr}");
    assert!(stdout.contains("transient: 400 rolling steps"), "{stdout}");
    let summary: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(out.join("summary.json")).unwrap()).unwrap();
    let t = &summary["transient"];
    let a = summary["estimates"]["hertz_half_width"].as_f64().unwrap();
    let h = summary["grid"]["spacing"].as_f64().unwrap();
    assert_eq!(t["steps"], 400);
    assert!(
        (t["step"].as_f64().unwrap() - h).abs() < 1e-12,
        "the default step: a node spacing"
    );
    assert_eq!(t["steady"], true, "{t}");
    let settled = t["settled_distance"].as_f64().unwrap() / a;
    assert!((2.0..6.0).contains(&settled), "settled after {settled} a");
    assert!(t["mean_iterations"].as_f64().unwrap() < 3.0, "{t}");

    let text = std::fs::read_to_string(out.join("transient.csv")).unwrap();
    assert!(!text.contains("NaN") && !text.contains("inf"));
    let (header, rows) = read_rows(&text);
    assert_eq!(rows.len(), 401);
    let col = |name: &str| {
        header
            .iter()
            .position(|c| c == name)
            .unwrap_or_else(|| panic!("{name}"))
    };
    let value = |row: &[String], name: &str| row[col(name)].parse::<f64>().unwrap();
    for row in &rows {
        assert!((value(row, "load_ratio") - RATIO).abs() < 1e-9, "{row:?}");
    }
    let (first, last) = (&rows[0], &rows[400]);
    assert!(
        first[col("creep")].is_empty() && value(first, "shift") > 0.0,
        "step 0 is a shift"
    );
    assert!(last[col("shift")].is_empty() && value(last, "creep") > 0.0);
    assert!((value(last, "rolled") - 400.0 * h).abs() < 1e-9);

    // The energy columns: every step's balance W + W_n − ΔU − D − C, and its tangential part
    // W − ΔU_t − D, is the implicit step's own dissipation, ≥ 0 (to round-off of its work) and,
    // rolled at one node spacing a step on 41 elements, the tangential part is a few per cent of
    // D (3.0 % over 8.4a in docs/transient.md; below 5 % here).
    let (mut dissipated, mut imbalance) = (0.0, 0.0);
    for row in &rows {
        let (d, w, du, dut) = (
            value(row, "dissipation"),
            value(row, "shift_work"),
            value(row, "stored_change"),
            value(row, "tangential_stored_change"),
        );
        let (wn, c) = (value(row, "normal_work"), value(row, "closing"));
        let round_off = 1e-9 * w.abs().max(wn.abs()).max(1e-12);
        assert!(d >= 0.0 && c >= -round_off, "{row:?}");
        assert!(
            w + wn - du - d - c >= -round_off && w - dut - d >= -round_off,
            "{row:?}"
        );
        if value(row, "step") > 0.0 {
            dissipated += d;
            imbalance += w - dut - d;
        }
    }
    assert!(
        imbalance > 0.0 && imbalance < 0.05 * dissipated,
        "{imbalance} of {dissipated}"
    );

    let c = a * (1.0 - RATIO).sqrt();
    let stick = |row: &[String]| [value(row, "stick_x_min"), value(row, "stick_x_max")];
    let [x0, x1] = stick(first);
    eprintln!(
        "step 0: stick [{x0:.4}, {x1:.4}] against ±{c:.4} (h/2 = {:.4})",
        h / 2.0
    );
    assert!((x0 + c).abs() < h / 2.0 && (x1 - c).abs() < h / 2.0);
    let [x0, x1] = stick(last);
    let carter = [a - 2.0 * c, a];
    eprintln!(
        "last step: stick [{x0:.4}, {x1:.4}] against [{:.4}, {:.4}]",
        carter[0], carter[1]
    );
    assert!((x0 - carter[0]).abs() < h / 2.0 && (x1 - carter[1]).abs() < h / 2.0);

    // Every step's contact.csv and VTU, the series over them, and the last step's usual files.
    for k in [0, 400] {
        assert!(out.join(format!("steps/step_{k:04}.csv")).is_file());
        assert!(out.join(format!("steps/step_{k:04}.vtu")).is_file());
    }
    let pvd = std::fs::read_to_string(out.join("transient.pvd")).unwrap();
    assert_eq!(pvd.matches("<DataSet").count(), 401);
    for file in [
        "contact.csv",
        "contact.svg",
        "contact.vtu",
        "result.pvd",
        ".rollbem-manifest",
    ] {
        assert!(out.join(file).is_file(), "{file}");
    }
    // transient.svg: a whole SVG whose legend names the profiled steps (0, 100, 200, 300, 400)
    // with transient.csv's rolled distance, character for character, and both history charts.
    let svg = std::fs::read_to_string(out.join("transient.svg")).unwrap();
    assert!(svg.trim_start().starts_with("<svg") && svg.trim_end().ends_with("</svg>"));
    assert!(!svg.contains("NaN"));
    for k in [0, 100, 200, 300, 400] {
        let label = format!("step {k}, rolled = {} ", rows[k][col("rolled")]);
        assert!(svg.contains(&label), "{label}");
    }
    assert!(!svg.contains("step 1, rolled") && !svg.contains("step 399, rolled"));
    for text in ["Q/μP", "creepage ξ", "pressure p", "shear q"] {
        assert!(svg.contains(text), "{text}");
    }
    let manifest = std::fs::read_to_string(out.join(".rollbem-manifest")).unwrap();
    assert!(manifest.contains("steps/step_0400.csv") && manifest.contains("transient.csv"));
    let contact = std::fs::read_to_string(out.join("contact.csv")).unwrap();
    let step = std::fs::read_to_string(out.join("steps/step_0400.csv")).unwrap();
    assert!(contact == step, "contact.csv is the last step's");
}

/// A step that does not converge stops the history with exit code 2 naming it; when it is step
/// 0 nothing stands, and nothing is written.
#[test]
fn a_step_that_does_not_converge_stops_the_history() {
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("c2c");
    let case = case_path("cattaneo_to_carter");
    let (code, _, stderr) = rollbem(&[
        "run",
        case.to_str().unwrap(),
        "--out",
        out.to_str().unwrap(),
        "--set",
        "solver.max_iterations=3",
    ]);
    assert_eq!(code, 2, "{stderr}");
    assert!(
        stderr.contains("step 0") && stderr.contains("did not converge"),
        "{stderr}"
    );
    assert!(!out.exists());
}

/// `transient.write_every: 7` on 20 steps: steps/ holds steps 0, 7, 14 and the last (20), the
/// ParaView series those four, and transient.csv every step (21 rows).
#[test]
fn write_every_thins_the_steps_files_not_the_table() {
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("thin");
    let case = case_path("cattaneo_to_carter");
    let (code, _, stderr) = rollbem(&[
        "run",
        case.to_str().unwrap(),
        "--out",
        out.to_str().unwrap(),
        "--set",
        "transient.steps=20",
        "--set",
        "transient.write_every=7",
    ]);
    assert_eq!(code, 0, "{stderr}");
    let mut written: Vec<String> = std::fs::read_dir(out.join("steps"))
        .unwrap()
        .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
        .filter(|n| n.ends_with(".csv"))
        .collect();
    written.sort();
    assert_eq!(
        written,
        ["step_0000.csv", "step_0007.csv", "step_0014.csv", "step_0020.csv"]
    );
    let pvd = std::fs::read_to_string(out.join("transient.pvd")).unwrap();
    assert_eq!(pvd.matches("<DataSet").count(), 4);
    let (_, rows) = read_rows(&std::fs::read_to_string(out.join("transient.csv")).unwrap());
    assert_eq!(rows.len(), 21);
}

/// `rollbem check` of a transient case reports the history as planned: the steps, the step
/// against the node spacing and a, the distance rolled, the steps' files; and a note when the
/// history ends before the 4a a change of load takes to settle (the shipped case rolls 8.6a).
#[test]
fn check_reports_the_history_as_planned() {
    let case = case_path("cattaneo_to_carter");
    let (code, stdout, stderr) = rollbem(&["check", case.to_str().unwrap()]);
    assert_eq!(code, 0, "{stderr}");
    assert!(
        stdout.contains("400 rolling steps of 0.021505 mm (1.000 node spacings")
            && stdout.contains("steps/ will hold 401 steps' files")
            && !stdout.contains("note: the history ends"),
        "{stdout}"
    );
    let (code, stdout, stderr) = rollbem(&[
        "check",
        case.to_str().unwrap(),
        "--set",
        "transient.steps=50",
        "--set",
        "transient.write_every=10",
    ]);
    assert_eq!(code, 0, "{stderr}");
    assert!(
        stdout.contains("steps/ will hold 6 steps' files") && stdout.contains("note: the history ends after 1.08a"),
        "{stdout}"
    );
}

/// `rollbem sweep` and the studies solve steady problems: a transient case is refused by its
/// key `transient` (exit 1, nothing written) rather than swept as its steady problem without a
/// word; `--set transient=null` sweeps the steady problem.
#[test]
fn a_sweep_refuses_a_history_and_takes_its_steady_problem_when_asked() {
    let case = case_path("cattaneo_to_carter");
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("sweep");
    let sweep = |extra: &[&str]| {
        let mut args = vec![
            "sweep",
            case.to_str().unwrap(),
            "--vary",
            "load.tangential.ratio=0.3,0.6",
            "--out",
            out.to_str().unwrap(),
        ];
        args.extend_from_slice(extra);
        rollbem(&args)
    };
    let (code, _, stderr) = sweep(&[]);
    assert_eq!(code, 1, "{stderr}");
    assert!(
        stderr.contains("key `transient`")
            && stderr.contains("`rollbem sweep` solves steady problems only")
            && stderr.contains("--set transient=null"),
        "{stderr}"
    );
    assert!(!out.exists(), "a refused sweep writes nothing");
    for study in [["study", "stability"], ["study", "shakedown"]] {
        let (code, _, stderr) = rollbem(&[
            study[0],
            study[1],
            case.to_str().unwrap(),
            "--out",
            out.to_str().unwrap(),
        ]);
        assert_eq!(code, 1, "{stderr}");
        assert!(stderr.contains("key `transient`"), "{stderr}");
    }
    let (code, _, stderr) = sweep(&["--set", "transient=null"]);
    assert_eq!(code, 0, "{stderr}");
    assert!(out.join("sweep.csv").exists());
}

/// `transient.datum_length` (docs/transient.md, "The datum of a step"): the upstream end's
/// displacement measured as a half-plane pair's from a datum length moves with Q, which acts
/// as a creepage of its own in the steps where Q changes. Over a table that lowers Q/μP from
/// 0.6 to 0.3 and holds it there, the creepage of the steps that change Q differs from the
/// upstream-end datum's by far more than the Newton tolerance, and the shift (step 0, no
/// rolling) does not. Bad values and a body that is not a half-plane are refused by the key.
#[test]
fn a_datum_length_moves_the_upstream_end_with_q() {
    let case = case_path("cattaneo_to_carter");
    let dir = tempfile::tempdir().unwrap();
    let run = |name: &str, extra: &[&str]| {
        let sets = [
            &[
                "transient.steps=30",
                "transient.tangential={ratio: [[0, 0.6], [0.2, 0.3]]}",
            ][..],
            extra,
        ]
        .concat();
        let (header, rows) = run_history(&case, &dir.path().join(name), &sets);
        // Step 0's rigid shift, then each rolling step's creepage.
        let column = |name: &str| header.iter().position(|h| h == name).unwrap();
        let (shift, creep) = (column("shift"), column("creep"));
        rows.iter()
            .enumerate()
            .map(|(k, r)| r[if k == 0 { shift } else { creep }].parse::<f64>().unwrap())
            .collect::<Vec<f64>>()
    };
    let own = run("own", &[]);
    let strip = run("strip", &["transient.datum_length=295.068"]);
    assert_eq!(own.len(), 31);
    assert!(
        (own[0] - strip[0]).abs() <= 1e-9 * own[0].abs().max(1e-12),
        "the shift: {} {}",
        own[0],
        strip[0]
    );
    let changed = (1..own.len())
        .filter(|&k| (own[k] - strip[k]).abs() > 1e-3 * own[k].abs())
        .count();
    assert!(changed >= 3, "the steps that change Q: {own:?} against {strip:?}");

    let (code, _, stderr) = rollbem(&["check", case.to_str().unwrap(), "--set", "transient.datum_length=-1"]);
    assert_eq!(code, 1);
    assert!(stderr.contains("transient.datum_length"), "{stderr}");
    let bem = case_path("braking_step_bem");
    let out = dir.path().join("bem");
    let (code, _, stderr) = rollbem(&[
        "run",
        bem.to_str().unwrap(),
        "--out",
        out.to_str().unwrap(),
        "--set",
        "transient.datum_length=100",
    ]);
    assert_eq!(code, 1, "{stderr}");
    assert!(
        stderr.contains("transient.datum_length") && stderr.contains("bem"),
        "{stderr}"
    );
    // `check` refuses it alike, and reports the datum where it is taken.
    let (code, _, stderr) = rollbem(&["check", bem.to_str().unwrap(), "--set", "transient.datum_length=100"]);
    assert_eq!(code, 1, "{stderr}");
    assert!(stderr.contains("transient.datum_length"), "{stderr}");
    let (code, stdout, stderr) = rollbem(&[
        "check",
        case.to_str().unwrap(),
        "--set",
        "transient.datum_length=295.068",
    ]);
    assert_eq!(code, 0, "{stderr}");
    assert!(stdout.contains("datum length L = 295.068"), "{stdout}");
}

/// `transient.initial_slip` starts each rolling step's solve under a falling law from the last
/// step (`warm`), from below or from above (CONTACT's INISLP). Where a step has one solution,
/// as in the first steps of a history from Q = 0 on CONTACT's veldep_fric scene (a few nodes
/// slip), the three starts find it alike (the tractions' forces agree to 1e-9 relative), in
/// different numbers of Newton iterations; without a falling law the key is refused.
#[test]
fn the_start_of_a_step_under_a_falling_law_is_a_key() {
    let case = case_path("veldep_fric");
    let dir = tempfile::tempdir().unwrap();
    let forces: Vec<Vec<f64>> = ["warm", "below", "above"]
        .iter()
        .map(|side| {
            let history = format!("transient={{steps: 8, step: 0.1, initial_slip: {side}}}");
            let (header, rows) = run_history(&case, &dir.path().join(side), &[&history]);
            let q = header.iter().position(|h| h == "tangential_force").unwrap();
            rows.iter().map(|r| r[q].parse::<f64>().unwrap()).collect()
        })
        .collect();
    for other in &forces[1..] {
        for (a, b) in forces[0].iter().zip(other) {
            assert!((a - b).abs() <= 1e-9 * a.abs().max(1.0), "{:?}", forces);
        }
    }
    let (code, _, stderr) = rollbem(&[
        "check",
        case_path("cattaneo_to_carter").to_str().unwrap(),
        "--set",
        "transient.initial_slip=above",
    ]);
    assert_eq!(code, 1);
    assert!(
        stderr.contains("transient.initial_slip") && stderr.contains("contact.falling_friction"),
        "{stderr}"
    );
}
