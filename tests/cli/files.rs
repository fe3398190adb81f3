//! The user's files and the exit codes, at the command line: rollbem never deletes or
//! overwrites a file it did not write, replaces its own results atomically, locks an output
//! folder before solving, exits 1 on usage errors and 3 (writing nothing) on an internal error.
//! docs/reliability.md states these guarantees.

use std::collections::BTreeMap;
use std::path::{Path, PathBuf};
use std::process::Command;
use std::time::{Duration, Instant};

use crate::common::{rollbem_with, CARTER_CASE as CASE};

fn rollbem_in(cwd: &Path, env: &[(&str, &str)], args: &[&str]) -> (i32, String, String) {
    rollbem_with(Some(cwd), env, args)
}

fn rollbem(cwd: &Path, args: &[&str]) -> (i32, String, String) {
    rollbem_in(cwd, &[], args)
}

/// Every file and folder under `dir` (hidden ones included) with its content (folders: empty).
fn snapshot(dir: &Path) -> BTreeMap<PathBuf, Vec<u8>> {
    let mut out = BTreeMap::new();
    let mut stack = vec![dir.to_path_buf()];
    while let Some(d) = stack.pop() {
        for e in std::fs::read_dir(&d).unwrap() {
            let p = e.unwrap().path();
            let rel = p.strip_prefix(dir).unwrap().to_path_buf();
            if p.is_dir() {
                stack.push(p);
                out.insert(rel, Vec::new());
            } else {
                out.insert(rel, std::fs::read(&p).unwrap());
            }
        }
    }
    out
}

fn write(dir: &Path, name: &str, text: &str) -> PathBuf {
    let p = dir.join(name);
    std::fs::create_dir_all(p.parent().unwrap()).unwrap();
    std::fs::write(&p, text).unwrap();
    p
}

#[test]
fn out_dot_in_a_folder_with_the_case_file_keeps_every_file_and_exits_1() {
    let dir = tempfile::tempdir().unwrap();
    write(dir.path(), "case.yaml", CASE);
    write(dir.path(), "notes/thesis.tex", "years of work");
    let before = snapshot(dir.path());
    let (code, stdout, stderr) = rollbem(dir.path(), &["run", "case.yaml", "--out", "."]);
    assert_eq!(code, 1, "{stdout}{stderr}");
    // The folder and the first foreign entry are named; nothing was solved or written.
    assert!(
        stderr.contains(&dir.path().canonicalize().unwrap().display().to_string()),
        "{stderr}"
    );
    assert!(
        stderr.contains("`case.yaml`") && stderr.contains("did not write"),
        "{stderr}"
    );
    assert!(!stdout.contains("converged"), "{stdout}");
    assert_eq!(snapshot(dir.path()), before);
    // Refused before locking: no lock file appeared beside the folder either.
    let name = dir.path().file_name().unwrap().to_string_lossy().into_owned();
    let lock = dir.path().parent().unwrap().join(format!(".{name}.rollbem-lock"));
    assert!(!lock.exists());
}

#[test]
fn a_results_folder_holding_another_file_is_refused_and_the_file_kept() {
    let dir = tempfile::tempdir().unwrap();
    write(dir.path(), "case.yaml", CASE);
    write(dir.path(), "results/thesis.csv", "1,2,3\n");
    let before = snapshot(dir.path());
    let (code, _, stderr) = rollbem(dir.path(), &["run", "case.yaml", "--out", "results"]);
    assert_eq!(code, 1, "{stderr}");
    assert!(
        stderr.contains("results") && stderr.contains("`thesis.csv`"),
        "{stderr}"
    );
    assert_eq!(snapshot(dir.path()), before);
    // output.dir of a case pointing at the meshes: refused, the mesh kept.
    write(
        dir.path(),
        "meshes/roller.msh",
        "$MeshFormat\n4.1 0 8\n$EndMeshFormat\n",
    );
    write(
        dir.path(),
        "cases/wipe.yaml",
        &format!("{CASE}output: {{dir: ../meshes}}\n"),
    );
    let before = snapshot(dir.path());
    let (code, _, stderr) = rollbem(dir.path(), &["run", "cases/wipe.yaml"]);
    assert_eq!(code, 1, "{stderr}");
    assert!(stderr.contains("`roller.msh`"), "{stderr}");
    assert_eq!(snapshot(dir.path()), before);
    // A sweep and a study are refused the same way.
    let (code, _, stderr) = rollbem(
        dir.path(),
        &[
            "sweep",
            "case.yaml",
            "--vary",
            "contact.friction=0.1,0.2",
            "--out",
            "results",
        ],
    );
    assert_eq!(code, 1, "{stderr}");
    assert!(stderr.contains("`thesis.csv`"), "{stderr}");
    let (code, _, stderr) = rollbem(
        dir.path(),
        &["study", "stability", "case.yaml", "--quick", "--out", "."],
    );
    assert_eq!(code, 1, "{stderr}");
    assert!(stderr.contains("`case.yaml`"), "{stderr}");
    assert_eq!(snapshot(dir.path()), before);
}

#[test]
fn an_earlier_result_is_replaced_and_nothing_is_left_beside_it() {
    let dir = tempfile::tempdir().unwrap();
    write(dir.path(), "case.yaml", CASE);
    let (code, _, stderr) = rollbem(dir.path(), &["run", "case.yaml", "--out", "res"]);
    assert_eq!(code, 0, "{stderr}");
    let first = std::fs::read_to_string(dir.path().join("res/summary.json")).unwrap();
    let (code, _, stderr) = rollbem(
        dir.path(),
        &[
            "run",
            "case.yaml",
            "--out",
            "res",
            "--set",
            "contact.friction=0.2",
            "--set",
            "output.vtk=false",
        ],
    );
    assert_eq!(code, 0, "{stderr}");
    let second = std::fs::read_to_string(dir.path().join("res/summary.json")).unwrap();
    assert_ne!(first, second);
    assert!(second.contains("\"friction\": 0.2"), "{second}");
    // The new result replaced the old one whole: no file of the first run (contact.vtu) stays.
    let names: Vec<String> = std::fs::read_dir(dir.path().join("res"))
        .unwrap()
        .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
        .collect();
    assert!(!names.contains(&"contact.vtu".to_string()), "{names:?}");
    let manifest: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(dir.path().join("res/.rollbem-manifest")).unwrap()).unwrap();
    assert_eq!(manifest["kind"], "run");
    let mut listed: Vec<String> = manifest["files"]
        .as_array()
        .unwrap()
        .iter()
        .map(|f| f.as_str().unwrap().to_string())
        .collect();
    listed.push(".rollbem-manifest".into());
    listed.sort();
    let mut names = names;
    names.sort();
    assert_eq!(listed, names);
    // No temporary folder, old result or lock file beside it.
    let beside: Vec<String> = std::fs::read_dir(dir.path())
        .unwrap()
        .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
        .collect();
    assert_eq!(beside.len(), 2, "{beside:?}");
    // A file the user adds to the result makes it theirs: refused, kept.
    write(dir.path(), "res/my_plot.png", "png");
    let (code, _, stderr) = rollbem(dir.path(), &["run", "case.yaml", "--out", "res"]);
    assert_eq!(code, 1, "{stderr}");
    assert!(stderr.contains("`my_plot.png`"), "{stderr}");
    assert_eq!(
        std::fs::read_to_string(dir.path().join("res/summary.json")).unwrap(),
        second
    );
}

#[test]
fn a_killed_writer_leaves_the_earlier_result_and_its_temporary_is_cleaned_next_time() {
    let dir = tempfile::tempdir().unwrap();
    write(dir.path(), "case.yaml", CASE);
    let (code, _, stderr) = rollbem(dir.path(), &["run", "case.yaml", "--out", "res"]);
    assert_eq!(code, 0, "{stderr}");
    let result = snapshot(&dir.path().join("res"));
    // Killed (abort: no unwinding, no cleanup) after writing the new result, before renaming it.
    let (code, _, _) = rollbem_in(
        dir.path(),
        &[("ROLLBEM_TEST_FAULT", "abort")],
        &["run", "case.yaml", "--out", "res", "--set", "contact.friction=0.2"],
    );
    assert_ne!(code, 0);
    assert_eq!(snapshot(&dir.path().join("res")), result, "the earlier result changed");
    let leftovers = |d: &Path| -> Vec<String> {
        std::fs::read_dir(d)
            .unwrap()
            .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
            .filter(|n| n.starts_with(".res."))
            .collect()
    };
    assert!(leftovers(dir.path()).iter().any(|n| n.starts_with(".res.partial-")));
    // A folder of the user's with a temporary-looking name but no rollbem manifest is not ours.
    write(dir.path(), ".res.partial-1/keep.txt", "mine");
    let (code, _, stderr) = rollbem(dir.path(), &["run", "case.yaml", "--out", "res"]);
    assert_eq!(code, 0, "{stderr}");
    assert_eq!(leftovers(dir.path()), [".res.partial-1"]);
    assert_eq!(
        std::fs::read_to_string(dir.path().join(".res.partial-1/keep.txt")).unwrap(),
        "mine"
    );
}

#[test]
fn a_second_writer_of_a_folder_is_refused_at_once_before_solving() {
    let dir = tempfile::tempdir().unwrap();
    write(dir.path(), "case.yaml", CASE);
    let out = dir.path().join("res");
    // This test process holds the folder as a running `rollbem run` would.
    let held = rollbem::output::folder::Claim::acquire(
        &out,
        rollbem::output::folder::Kind::Run,
        rollbem::output::folder::Access::Exclusive,
    )
    .unwrap();
    let before = snapshot(dir.path());
    let start = Instant::now();
    let (code, stdout, stderr) = rollbem(dir.path(), &["run", "case.yaml", "--out", "res"]);
    let elapsed = start.elapsed();
    assert_eq!(code, 1, "{stdout}{stderr}");
    assert!(stderr.contains("being written by another rollbem process"), "{stderr}");
    assert!(!stdout.contains("converged"), "it solved before refusing: {stdout}");
    assert_eq!(snapshot(dir.path()), before);
    // At once: far less than a solve plus a process start on a loaded machine.
    assert!(elapsed < Duration::from_secs(5), "{elapsed:?}");
    drop(held);
    let (code, _, stderr) = rollbem(dir.path(), &["run", "case.yaml", "--out", "res"]);
    assert_eq!(code, 0, "{stderr}");
    // Two processes at once: exactly one writes, or they follow each other; never a half result
    // or "Directory not empty".
    let children: Vec<_> = (0..2)
        .map(|_| {
            Command::new(env!("CARGO_BIN_EXE_rollbem"))
                .current_dir(dir.path())
                .args(["run", "case.yaml", "--out", "res"])
                .env_remove("ROLLBEM_TEST_FAULT")
                .output()
        })
        .collect();
    for c in children {
        let c = c.unwrap();
        let code = c.status.code().unwrap_or(-1);
        let stderr = String::from_utf8_lossy(&c.stderr);
        assert!(
            code == 0 || (code == 1 && stderr.contains("being written by another rollbem process")),
            "{code} {stderr}"
        );
    }
    assert!(dir.path().join("res/summary.json").is_file());
}

#[test]
fn usage_errors_exit_1_and_help_exits_0() {
    let dir = tempfile::tempdir().unwrap();
    write(dir.path(), "case.yaml", CASE);
    for args in [
        vec!["run"],
        vec!["run", "case.yaml", "--no-such-flag"],
        vec!["check", "case.yaml", "--tolerance", "abc"],
        vec!["frobnicate"],
        vec![],
        vec!["sweep", "case.yaml", "--merge", "x", "--shard", "1/2"],
    ] {
        let (code, stdout, stderr) = rollbem(dir.path(), &args);
        assert_eq!(code, 1, "{args:?}: {stdout}{stderr}");
        assert!(
            stderr.contains("error") || stderr.contains("Usage"),
            "{args:?}: {stderr}"
        );
    }
    for args in [vec!["--help"], vec!["run", "--help"], vec!["--version"]] {
        let (code, stdout, _) = rollbem(dir.path(), &args);
        assert_eq!(code, 0, "{args:?}");
        assert!(stdout.contains("rollbem") || stdout.contains("Usage"), "{stdout}");
    }
    assert_eq!(snapshot(dir.path()).len(), 1);
}

#[test]
fn an_internal_error_exits_3_names_the_case_and_writes_nothing() {
    let dir = tempfile::tempdir().unwrap();
    write(dir.path(), "case.yaml", CASE);
    let fault = [("ROLLBEM_TEST_FAULT", "panic")];
    // Into a new folder under new parents: none of them is left.
    let before = snapshot(dir.path());
    let (code, stdout, stderr) = rollbem_in(dir.path(), &fault, &["run", "case.yaml", "--out", "a/b/res"]);
    assert_eq!(code, 3, "{stdout}{stderr}");
    assert!(stderr.contains("internal error — please report"), "{stderr}");
    assert!(stderr.contains("case.yaml"), "{stderr}");
    assert!(!stderr.contains("panicked at"), "Rust's own report leaked: {stderr}");
    assert_eq!(snapshot(dir.path()), before);
    // Over an earlier result: it stays as it was.
    let (code, _, stderr) = rollbem(dir.path(), &["run", "case.yaml", "--out", "res"]);
    assert_eq!(code, 0, "{stderr}");
    let before = snapshot(dir.path());
    let (code, _, _) = rollbem_in(
        dir.path(),
        &fault,
        &["run", "case.yaml", "--out", "res", "--set", "contact.friction=0.3"],
    );
    assert_eq!(code, 3);
    assert_eq!(snapshot(dir.path()), before);
}

#[test]
fn an_overlong_or_nul_output_dir_creates_nothing() {
    let dir = tempfile::tempdir().unwrap();
    let long = "x".repeat(300);
    write(dir.path(), "long.yaml", &format!("{CASE}output: {{dir: out/{long}}}\n"));
    write(
        dir.path(),
        "nul.yaml",
        &format!("{CASE}output: {{dir: \"out/a\\0b\"}}\n"),
    );
    // A name that fits the file system (255) but not the temporary sibling's longer name.
    let near = "y".repeat(250);
    write(dir.path(), "near.yaml", &format!("{CASE}output: {{dir: out/{near}}}\n"));
    let before = snapshot(dir.path());
    for (case, says) in [
        ("long.yaml", "300 bytes"),
        ("nul.yaml", "NUL"),
        ("near.yaml", "250 bytes"),
    ] {
        let (code, stdout, stderr) = rollbem(dir.path(), &["run", case]);
        assert_eq!(code, 1, "{case}: {stdout}{stderr}");
        assert!(
            stderr.contains(says) && stderr.contains("output.dir"),
            "{case}: {stderr}"
        );
        assert!(!stdout.contains("converged"), "{case} was solved first");
        assert_eq!(snapshot(dir.path()), before, "{case} created something");
    }
    let (code, _, stderr) = rollbem(dir.path(), &["run", "long.yaml", "--out", &format!("o/{long}/r")]);
    assert_eq!(code, 1, "{stderr}");
    assert_eq!(snapshot(dir.path()), before);
}

/// Hidden entries of `dir` (locks, temporaries).
fn hidden_in(dir: &Path) -> Vec<String> {
    let mut names: Vec<String> = std::fs::read_dir(dir)
        .unwrap()
        .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
        .filter(|n| n.starts_with('.'))
        .collect();
    names.sort();
    names
}

/// A file or a symbolic link named like rollbem's lock beside `--out res` is the user's: it is
/// neither locked through nor removed (it was taken for a stale lock and deleted), and the run
/// is refused with exit 1; rollbem's own lock is removed when it finishes.
#[test]
fn a_user_file_or_link_named_like_the_lock_is_kept() {
    let dir = tempfile::tempdir().unwrap();
    write(dir.path(), "case.yaml", CASE);
    let lock = dir.path().join(".res.rollbem-lock");
    std::fs::write(&lock, "my notes").unwrap();
    let (code, _, stderr) = rollbem(dir.path(), &["run", "case.yaml", "--out", "res"]);
    assert_eq!(code, 1, "{stderr}");
    assert!(stderr.contains("named like a rollbem lock file"), "{stderr}");
    assert_eq!(std::fs::read_to_string(&lock).unwrap(), "my notes");
    assert!(!dir.path().join("res").exists());
    std::fs::remove_file(&lock).unwrap();
    let target = write(dir.path(), "precious.txt", "keep me");
    std::os::unix::fs::symlink(&target, &lock).unwrap();
    let (code, _, stderr) = rollbem(dir.path(), &["run", "case.yaml", "--out", "res"]);
    assert_eq!(code, 1, "{stderr}");
    assert!(stderr.contains("a symbolic link"), "{stderr}");
    assert!(std::fs::symlink_metadata(&lock).unwrap().file_type().is_symlink());
    assert_eq!(std::fs::read_to_string(&target).unwrap(), "keep me");
    std::fs::remove_file(&lock).unwrap();
    let (code, _, stderr) = rollbem(dir.path(), &["run", "case.yaml", "--out", "res"]);
    assert_eq!(code, 0, "{stderr}");
    assert!(hidden_in(dir.path()).is_empty(), "{:?}", hidden_in(dir.path()));
}

/// Under a file-size limit (`ulimit -f`) a run fails with "File too large" and exit 1, leaving
/// no temporary folder and no lock (SIGXFSZ killed it: exit 153, no message, both left).
#[test]
fn a_file_size_limit_is_an_error_not_a_kill() {
    let dir = tempfile::tempdir().unwrap();
    write(dir.path(), "case.yaml", CASE);
    let out = Command::new("sh")
        .current_dir(dir.path())
        .arg("-c")
        .arg("ulimit -f 2 && exec \"$0\" run case.yaml --out res")
        .arg(env!("CARGO_BIN_EXE_rollbem"))
        .env_remove("ROLLBEM_TEST_FAULT")
        .output()
        .unwrap();
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(1), "{stderr}");
    assert!(stderr.contains("File too large"), "{stderr}");
    assert!(!dir.path().join("res").exists());
    assert!(hidden_in(dir.path()).is_empty(), "{:?}", hidden_in(dir.path()));
}

/// When the earlier result cannot be removed whole after the new one took its place (a file
/// appeared in it since it was checked; a read-only folder alike), the run says what was left
/// where instead of leaving `.res.old-PID` silently.
#[test]
fn what_is_left_of_a_replaced_result_is_reported() {
    let dir = tempfile::tempdir().unwrap();
    write(dir.path(), "case.yaml", CASE);
    let (code, _, stderr) = rollbem(dir.path(), &["run", "case.yaml", "--out", "res"]);
    assert_eq!(code, 0, "{stderr}");
    let (code, _, stderr) = rollbem_in(
        dir.path(),
        &[("ROLLBEM_TEST_FAULT", "intrude@res")],
        &["run", "case.yaml", "--out", "res", "--set", "contact.friction=0.2"],
    );
    assert_eq!(code, 0, "{stderr}");
    let left = hidden_in(dir.path());
    assert_eq!(left.len(), 1, "{left:?}");
    assert!(left[0].starts_with(".res.old-"), "{left:?}");
    assert!(
        stderr.contains("could not be removed completely")
            && stderr.contains(&left[0])
            && stderr.contains("intruder.txt"),
        "{stderr}"
    );
    assert!(dir.path().join(&left[0]).join("intruder.txt").is_file());
}

/// An empty folder of the user's (here reached through a symbolic link) keeps its mode when a
/// result is written into it (it became 0755).
#[test]
fn the_users_folder_keeps_its_mode() {
    use std::os::unix::fs::PermissionsExt;
    let dir = tempfile::tempdir().unwrap();
    write(dir.path(), "case.yaml", CASE);
    let mine = dir.path().join("mine");
    std::fs::create_dir(&mine).unwrap();
    std::fs::set_permissions(&mine, std::fs::Permissions::from_mode(0o700)).unwrap();
    std::os::unix::fs::symlink(&mine, dir.path().join("link")).unwrap();
    for _ in 0..2 {
        let (code, _, stderr) = rollbem(dir.path(), &["run", "case.yaml", "--out", "link"]);
        assert_eq!(code, 0, "{stderr}");
        let mode = std::fs::metadata(&mine).unwrap().permissions().mode() & 0o7777;
        assert_eq!(mode, 0o700, "{mode:o}");
        assert!(mine.join("summary.json").is_file());
    }
}

/// A result file the user edited since rollbem wrote it (the manifest records each file's size
/// and hash) stops the next run before it solves, whether the edit changed its size or not, and
/// is kept; `--force` replaces it.
#[test]
fn an_edited_result_is_kept_unless_forced() {
    let dir = tempfile::tempdir().unwrap();
    write(dir.path(), "case.yaml", CASE);
    let (code, _, stderr) = rollbem(dir.path(), &["run", "case.yaml", "--out", "res"]);
    assert_eq!(code, 0, "{stderr}");
    let csv = dir.path().join("res/contact.csv");
    let written = std::fs::read(&csv).unwrap();
    // The same size, one byte changed; then a line appended.
    let mut same_size = written.clone();
    same_size[0] ^= 1;
    let mut appended = written.clone();
    appended.extend_from_slice(b"# my notes\n");
    for edited in [same_size, appended] {
        std::fs::write(&csv, &edited).unwrap();
        let before = snapshot(dir.path());
        let (code, stdout, stderr) = rollbem(dir.path(), &["run", "case.yaml", "--out", "res"]);
        assert_eq!(code, 1, "{stdout}{stderr}");
        assert!(
            stderr.contains("contact.csv was changed since rollbem wrote it") && stderr.contains("--force"),
            "{stderr}"
        );
        assert!(!stdout.contains("converged"), "it solved before refusing: {stdout}");
        assert_eq!(snapshot(dir.path()), before);
    }
    let (code, _, stderr) = rollbem(dir.path(), &["run", "case.yaml", "--out", "res", "--force"]);
    assert_eq!(code, 0, "{stderr}");
    assert_eq!(std::fs::read(&csv).unwrap(), written);
}

/// A run folder of a sweep belongs to the sweep (its table describes it): `rollbem run --out
/// SWEEP/run_0000` is refused, `--force` or not, and leaves the sweep as it was (it replaced the
/// folder, and `--resume` kept it: the table then described another case); the sweep itself
/// still resumes and replaces it, but not over an edited run file.
#[test]
fn a_sweeps_run_folder_is_written_by_its_sweep_only() {
    let dir = tempfile::tempdir().unwrap();
    write(dir.path(), "case.yaml", CASE);
    let sweep = [
        "sweep",
        "--per-run-files",
        "case.yaml",
        "--vary",
        "contact.friction=0.1,0.2",
        "--out",
        "sw",
    ];
    let (code, _, stderr) = rollbem(dir.path(), &sweep);
    assert_eq!(code, 0, "{stderr}");
    let before = snapshot(dir.path());
    for run in ["sw/run_0000", "sw/run_0007"] {
        for force in [&[][..], &["--force"][..]] {
            let mut args = vec!["run", "case.yaml", "--out", run, "--set", "contact.friction=0.3"];
            args.extend(force);
            let (code, stdout, stderr) = rollbem(dir.path(), &args);
            assert_eq!(code, 1, "{args:?}: {stdout}{stderr}");
            assert!(stderr.contains("is a run folder of the sweep in"), "{stderr}");
            assert_eq!(snapshot(dir.path()), before);
        }
    }
    let (code, _, stderr) = rollbem(dir.path(), &[&sweep[..], &["--resume"]].concat());
    assert_eq!(code, 0, "{stderr}");
    let (code, _, stderr) = rollbem(dir.path(), &sweep);
    assert_eq!(code, 0, "{stderr}");
    let summary = dir.path().join("sw/run_0001/summary.json");
    let mut text = std::fs::read_to_string(&summary).unwrap();
    text.push('\n');
    std::fs::write(&summary, &text).unwrap();
    let (code, _, stderr) = rollbem(dir.path(), &sweep);
    assert_eq!(code, 1, "{stderr}");
    assert!(stderr.contains("run_0001/summary.json was changed"), "{stderr}");
    assert_eq!(std::fs::read_to_string(&summary).unwrap(), text);
}

/// A lock file that is empty (or holds a beginning of rollbem's marker) was left by a rollbem
/// process that could not write it, a full disk: it blocked the folder for good ("a file rollbem
/// did not create") after space was freed. It is taken over with a warning and removed after.
#[test]
fn an_empty_lock_file_is_taken_over() {
    let dir = tempfile::tempdir().unwrap();
    write(dir.path(), "case.yaml", CASE);
    let lock = dir.path().join(".res.rollbem-lock");
    for left in ["", "rollbem lo"] {
        std::fs::write(&lock, left).unwrap();
        let (code, _, stderr) = rollbem(dir.path(), &["run", "case.yaml", "--out", "res"]);
        assert_eq!(code, 0, "{left:?}: {stderr}");
        assert!(
            stderr.contains(".res.rollbem-lock") && stderr.contains("taken over"),
            "{stderr}"
        );
        assert!(hidden_in(dir.path()).is_empty(), "{:?}", hidden_in(dir.path()));
    }
}
