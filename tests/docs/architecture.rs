//! The rules of docs/architecture.md, checked on the source: the imports of `src/` have no
//! cycle, neither between its top-level modules nor between the files of one folder at any
//! depth; no source file is over 700 lines, no function over 150 (but those named as being
//! split), and the driver (`src/app.rs`) stays under 400.
//!
//! Imports are read as text: every `crate::a::b` and `super::b` path (and the items of
//! `crate::{…}` / `super::{…}` groups) outside comments and outside the `#[cfg(test)]` module
//! at the end of a file (tests may use any stage).

use std::collections::{BTreeMap, BTreeSet};
use std::path::{Path, PathBuf};

/// Every `.rs` file under `dir`.
fn sources(dir: &Path) -> Vec<PathBuf> {
    let mut out = Vec::new();
    for entry in std::fs::read_dir(dir).unwrap().map(|e| e.unwrap().path()) {
        if entry.is_dir() {
            out.extend(sources(&entry));
        } else if entry.extension().is_some_and(|e| e == "rs") {
            out.push(entry);
        }
    }
    out.sort();
    out
}

/// The module path of a file: src/post/zones.rs → [post, zones]; src/post.rs → [post].
fn module_path(src: &Path, file: &Path) -> Vec<String> {
    let rel = file.strip_prefix(src).unwrap().with_extension("");
    let mut parts: Vec<String> = rel.iter().map(|p| p.to_string_lossy().into_owned()).collect();
    if matches!(parts.last().map(String::as_str), Some("lib" | "main" | "mod")) {
        parts.pop();
    }
    parts
}

/// The code of a file without comments and without its test module.
fn code(text: &str) -> String {
    let text = text.split("#[cfg(test)]").next().unwrap_or_default();
    text.lines()
        .filter(|l| !l.trim_start().starts_with("//"))
        .collect::<Vec<_>>()
        .join("\n")
}

/// The identifier at the start of `s`.
fn ident(s: &str) -> &str {
    let end = s.find(|c: char| !(c.is_alphanumeric() || c == '_')).unwrap_or(s.len());
    &s[..end]
}

/// The first path segments after each `prefix` (`crate::` or `super::`), reading the
/// items of a `{…}` group one by one.
fn paths_after(code: &str, prefix: &str) -> Vec<Vec<String>> {
    let mut out = Vec::new();
    for (at, _) in code.match_indices(prefix) {
        let rest = &code[at + prefix.len()..];
        if let Some(group) = rest.strip_prefix('{') {
            // Top-level items of the group.
            let (mut depth, mut item_start) = (0, 0);
            for (k, c) in group.char_indices() {
                match c {
                    '{' => depth += 1,
                    '}' if depth == 0 => {
                        out.push(segments(&group[item_start..k]));
                        break;
                    }
                    '}' => depth -= 1,
                    ',' if depth == 0 => {
                        out.push(segments(&group[item_start..k]));
                        item_start = k + 1;
                    }
                    _ => {}
                }
            }
        } else {
            out.push(segments(rest));
        }
    }
    out.into_iter().filter(|p| !p.is_empty()).collect()
}

/// Up to six identifier segments of a path (`a::b::{…}` → [a, b]).
fn segments(s: &str) -> Vec<String> {
    let mut out = Vec::new();
    let mut rest = s.trim();
    while out.len() < 6 {
        let id = ident(rest);
        if id.is_empty() || id == "self" {
            break;
        }
        out.push(id.to_string());
        match rest[id.len()..].strip_prefix("::") {
            Some(r) => rest = r,
            None => break,
        }
    }
    out
}

/// Edges `a → b` of the import graphs: the top level, and each folder's files, at every depth
/// (`src/body/bem`'s files among themselves too). An import names a module by the longest
/// prefix of its path that is a file of `src/`; it is an edge of the folder where the importing
/// module and the imported one first differ (an import of an ancestor or a descendant is none).
fn graphs() -> BTreeMap<String, BTreeSet<(String, String)>> {
    let src = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("src");
    let files = sources(&src);
    let modules: BTreeSet<Vec<String>> = files.iter().map(|f| module_path(&src, f)).collect();
    let mut graphs: BTreeMap<String, BTreeSet<(String, String)>> = BTreeMap::new();
    for file in files {
        let m = module_path(&src, &file);
        if m.is_empty() {
            continue;
        }
        let text = code(&std::fs::read_to_string(&file).unwrap());
        let mut targets = paths_after(&text, "crate::");
        for p in paths_after(&text, "super::") {
            let mut full = m[..m.len() - 1].to_vec();
            full.extend(p);
            targets.push(full);
        }
        for t in targets {
            let Some(t) = (1..=t.len())
                .rev()
                .map(|k| t[..k].to_vec())
                .find(|p| modules.contains(p))
            else {
                continue;
            };
            let Some(d) = (0..m.len().min(t.len())).find(|&d| m[d] != t[d]) else {
                continue;
            };
            let folder = if d == 0 {
                "src".to_string()
            } else {
                format!("src/{}", m[..d].join("/"))
            };
            graphs.entry(folder).or_default().insert((m[d].clone(), t[d].clone()));
        }
    }
    graphs
}

/// The edges of `edges` that lie on a cycle.
fn cyclic(edges: &BTreeSet<(String, String)>) -> Vec<(String, String)> {
    let reaches = |from: &str, to: &str| {
        let (mut seen, mut stack) = (BTreeSet::new(), vec![from.to_string()]);
        while let Some(x) = stack.pop() {
            if x == to {
                return true;
            }
            if seen.insert(x.clone()) {
                stack.extend(edges.iter().filter(|(a, _)| *a == x).map(|(_, b)| b.clone()));
            }
        }
        false
    };
    edges.iter().filter(|(a, b)| reaches(b, a)).cloned().collect()
}

#[test]
fn imports_have_no_cycle_between_modules_or_sibling_files() {
    let graphs = graphs();
    assert!(
        graphs["src"].contains(&("output".into(), "post".into())),
        "the reader finds imports"
    );
    let cycles: Vec<String> = graphs
        .iter()
        .flat_map(|(folder, edges)| {
            cyclic(edges)
                .into_iter()
                .map(move |(a, b)| format!("{folder}: {a} → {b}"))
        })
        .collect();
    assert!(cycles.is_empty(), "imports on a cycle:\n  {}", cycles.join("\n  "));
}

/// The stages in the order of their imports: each may use the ones before it, never one
/// after (the numerical core first: the case schema names the solver's option types, the
/// scene builds body models and the contact problem, post-processing reads the scene; the
/// error control of `contact.grid.tolerance` loops over scene, solver and post-processing).
#[test]
fn stages_import_only_the_stages_below_them() {
    let edges = &graphs()["src"];
    let layers = ["body", "contact", "case", "scene", "post", "adapt", "output", "app"];
    for (i, low) in layers.iter().enumerate() {
        for high in &layers[i + 1..] {
            assert!(
                !edges.contains(&(low.to_string(), high.to_string())),
                "{low} imports {high}, a stage above it"
            );
        }
    }
}

#[test]
fn source_files_stay_small() {
    let src = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("src");
    let long: Vec<String> = sources(&src)
        .into_iter()
        .map(|f| (std::fs::read_to_string(&f).unwrap().lines().count(), f))
        .filter(|(n, f)| *n > 700 || (f.ends_with("app.rs") && *n >= 400))
        .map(|(n, f)| format!("{}: {n} lines", f.display()))
        .collect();
    assert!(
        long.is_empty(),
        "over 700 lines (app.rs: 400):\n  {}",
        long.join("\n  ")
    );
}

/// Longest function of `src/` [lines], from its `fn` line to its closing brace.
const MAX_FUNCTION_LINES: usize = 150;

/// Functions over [`MAX_FUNCTION_LINES`] that are still to be split by concept (file, name):
/// none today; a function that must stay longer is named here with its reason.
const LONG_FUNCTIONS_BEING_SPLIT: [(&str, &str); 0] = [];

/// The functions of a file with their lengths [lines]: from a line that declares a function
/// to the closing brace at its indentation (declarations without a body are skipped).
fn function_lengths(text: &str) -> Vec<(String, usize)> {
    let lines: Vec<&str> = text.lines().collect();
    let mut out = Vec::new();
    for (i, line) in lines.iter().enumerate() {
        let trimmed = line.trim_start();
        let indent = line.len() - trimmed.len();
        let after = [
            "pub fn ",
            "pub(crate) fn ",
            "pub(super) fn ",
            "fn ",
            "const fn ",
            "pub const fn ",
        ]
        .iter()
        .find_map(|p| trimmed.strip_prefix(p));
        let Some(rest) = after else { continue };
        if line.trim_end().ends_with(';') {
            continue;
        }
        let close = format!("{}}}", " ".repeat(indent));
        if let Some(end) = lines[i + 1..].iter().position(|l| l.trim_end() == close) {
            out.push((ident(rest).to_string(), end + 2));
        }
    }
    out
}

/// Small rooms: no function of `src/` over [`MAX_FUNCTION_LINES`] lines but those being split,
/// each named.
#[test]
fn functions_stay_short() {
    let src = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("src");
    let mut long = Vec::new();
    for file in sources(&src) {
        let rel = file.strip_prefix(&src).unwrap().to_string_lossy().replace('\\', "/");
        for (name, n) in function_lengths(&std::fs::read_to_string(&file).unwrap()) {
            let known = LONG_FUNCTIONS_BEING_SPLIT.contains(&(rel.as_str(), name.as_str()));
            if n > MAX_FUNCTION_LINES && !known {
                long.push(format!("{rel}: {name}, {n} lines"));
            }
        }
    }
    assert!(
        long.is_empty(),
        "over {MAX_FUNCTION_LINES} lines (split by concept):\n  {}",
        long.join("\n  ")
    );
}

/// One extension point per body model: the kinds of body are matched only in `src/body/`, in
/// the answers of the case about a body's kind (`src/case/kinds.rs`: its capabilities, its
/// keys, its mesh) and in the registry that turns a spec into a model's setup
/// (`src/scene/registry.rs`); the checks of a case ask those answers and name no variant. The
/// error control reaches bodies only through the scene (it imports neither `bem` nor `mesh`).
#[test]
fn body_kinds_are_matched_only_in_their_modules_and_the_registry() {
    let src = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("src");
    let mut offenders = Vec::new();
    for file in sources(&src) {
        let rel = file.strip_prefix(&src).unwrap().to_string_lossy().replace('\\', "/");
        let text = code(&std::fs::read_to_string(&file).unwrap());
        let allowed = rel.starts_with("body") || rel == "case/kinds.rs" || rel == "scene/registry.rs";
        // A variant is capitalised (`BodySpec::Bem`); a method path (`BodySpec::capabilities`)
        // asks the kind and is fine anywhere.
        let names_variant = text
            .match_indices("BodySpec::")
            .any(|(at, p)| text[at + p.len()..].starts_with(|c: char| c.is_ascii_uppercase()));
        if !allowed && names_variant {
            offenders.push(format!("{rel}: matches on BodySpec"));
        }
        // Nor by their names: a capability of `BodySetup` answers what a stage asks.
        for name in ["half_space", "bem", "layer", "rigid"] {
            if !allowed && (text.contains(&format!("== \"{name}\"")) || text.contains(&format!("\"{name}\" =>"))) {
                offenders.push(format!("{rel}: compares a model's name with \"{name}\""));
            }
        }
        if rel.starts_with("adapt") {
            for t in paths_after(&text, "crate::") {
                if t[0] == "bem" || t[0] == "mesh" {
                    offenders.push(format!("{rel}: imports crate::{}", t[0]));
                }
            }
        }
    }
    assert!(offenders.is_empty(), "{}", offenders.join("\n"));
}
