//! The repository stands alone: what a user reads (docs/, cases/, README.md, tools/, the report
//! programs of examples/, the Gmsh scripts of meshes/ and every `--help` text) cites the literature and the repository's own
//! files, never a document the repository does not hold (a "reference sheet", a "DESIGN" brief,
//! `../shared`) nor a tracker number ("issue 6"). Fails naming the file (or help text) and line
//! of each occurrence.

use std::path::{Path, PathBuf};

use crate::common::rollbem;

/// What must not appear, as (label, matcher over one line).
fn forbidden(line: &str) -> Option<&'static str> {
    let lower = line.to_lowercase();
    if lower.contains("reference sheet") {
        return Some("reference sheet");
    }
    if line.contains("DESIGN") {
        return Some("DESIGN");
    }
    if line.contains("../shared") || line.contains("/work/shared") {
        return Some("../shared");
    }
    if mentions_issue_number(&lower) {
        return Some("issue N");
    }
    None
}

/// "issue 6", "issue #6", "issues 4 and 6": a tracker number.
fn mentions_issue_number(lower: &str) -> bool {
    lower.match_indices("issue").any(|(at, word)| {
        let rest = lower[at + word.len()..].trim_start_matches('s');
        let rest = rest.trim_start_matches([' ', '#']);
        rest.starts_with(|c: char| c.is_ascii_digit())
    })
}

fn violations(label: &str, text: &str) -> Vec<String> {
    text.lines()
        .enumerate()
        .filter_map(|(i, line)| forbidden(line).map(|what| format!("{label}:{}: `{what}`: {}", i + 1, line.trim())))
        .collect()
}

/// Every text file under `dir` (binary files such as PNG are skipped: not UTF-8).
fn text_files(dir: &Path, found: &mut Vec<PathBuf>) {
    let mut entries: Vec<_> = std::fs::read_dir(dir).unwrap().map(|e| e.unwrap().path()).collect();
    entries.sort();
    for path in entries {
        let name = path.file_name().unwrap().to_string_lossy().to_string();
        if name.starts_with('.') || name == "__pycache__" || name == "out" {
            continue;
        }
        if path.is_dir() {
            text_files(&path, found);
        } else {
            found.push(path);
        }
    }
}

#[test]
fn the_grep_recognises_what_it_must_refuse() {
    for bad in [
        "see the reference sheet §2",
        "Reference sheet §3.1",
        "(DESIGN §5)",
        "../shared/paper",
        "study (issue 6): table",
        "Issue #14 asks for",
        "issues 4 and 6",
    ] {
        assert!(forbidden(bad).is_some(), "{bad}");
    }
    for good in [
        "docs/references.md §2 (Carter 1926)",
        "the design of the solver",
        "an issue with 0.5",
        "the issue",
    ] {
        assert_eq!(forbidden(good), None, "{good}");
    }
}

#[test]
fn docs_cases_readme_tools_examples_and_mesh_scripts_cite_nothing_outside_the_repository() {
    let root = PathBuf::from(env!("CARGO_MANIFEST_DIR"));
    let mut files = vec![root.join("README.md")];
    for dir in ["docs", "cases", "tools", "examples"] {
        text_files(&root.join(dir), &mut files);
    }
    // The Gmsh scripts (the .msh files they make hold no prose).
    let mut meshes = Vec::new();
    text_files(&root.join("meshes"), &mut meshes);
    let scripts: Vec<PathBuf> = meshes
        .into_iter()
        .filter(|p| p.extension().is_some_and(|e| e == "geo" || e == "inc"))
        .collect();
    assert!(scripts.len() > 10, "found only {scripts:?}");
    files.extend(scripts);
    assert!(files.len() > 20, "found only {files:?}");
    let mut found = Vec::new();
    for file in &files {
        let Ok(text) = std::fs::read_to_string(file) else {
            continue;
        };
        let label = file.strip_prefix(&root).unwrap().display().to_string();
        found.extend(violations(&label, &text));
    }
    assert!(
        found.is_empty(),
        "references outside the repository:\n{}",
        found.join("\n")
    );
}

/// The subcommands listed under "Commands:" in a help text (without `help`).
fn subcommands(help: &str) -> Vec<String> {
    help.lines()
        .skip_while(|l| !l.starts_with("Commands:"))
        .skip(1)
        .take_while(|l| !l.trim().is_empty())
        .filter(|l| l.starts_with("  ") && !l.starts_with("   "))
        .filter_map(|l| l.split_whitespace().next().map(str::to_string))
        .filter(|c| c != "help")
        .collect()
}

#[test]
fn help_texts_cite_nothing_outside_the_repository() {
    let mut pending = vec![Vec::<String>::new()];
    let mut seen = 0;
    let mut found = Vec::new();
    while let Some(path) = pending.pop() {
        let mut args: Vec<&str> = path.iter().map(String::as_str).collect();
        args.push("--help");
        let (code, stdout, stderr) = rollbem(&args);
        assert_eq!(code, 0, "rollbem {}: {stderr}", args.join(" "));
        seen += 1;
        found.extend(violations(&format!("rollbem {}", args.join(" ")), &stdout));
        for sub in subcommands(&stdout) {
            let mut next = path.clone();
            next.push(sub);
            pending.push(next);
        }
    }
    // rollbem, run, sweep, validate, study, study accuracy, study stability, check
    assert!(seen >= 8, "only {seen} help texts found");
    assert!(
        found.is_empty(),
        "references outside the repository:\n{}",
        found.join("\n")
    );
}
