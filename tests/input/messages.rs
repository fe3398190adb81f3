//! Deterministic fuzzing of the messages: every key of every shipped case (cases/*.yaml) deleted
//! or given a value of the wrong kind (strings, lists, mappings, huge, negative and fractional
//! numbers, booleans), then checked as `rollbem check` checks it. Whatever is refused must be
//! refused in the words of a case file: no message may name a Rust type (`untagged enum
//! BoundarySpec`, `expected struct Units`, `u128`, `f64`, `Option<…>`), since the reader of the
//! message writes YAML, not Rust.

use std::collections::BTreeSet;
use std::path::{Path, PathBuf};

/// Values put in place of each key: `null` deletes it (cases/README.md: `--set key=null`).
const MUTATIONS: &[&str] = &[
    "null",
    "abc",
    "[1, 2]",
    "{a: 1}",
    "1e300",
    "-5",
    "-0.5",
    "true",
    "0",
    "2.5",
    "123456789012345678901234567890",
    "-123456789012345678901234567890",
    "18446744073709551616",
];

/// Fragments of Rust and serde vocabulary that a user of the case file cannot act on.
const RUST_WORDS: &[&str] = &[
    "enum ",
    "struct ",
    "u128",
    "i128",
    "usize",
    "isize",
    "u64",
    "i64",
    "u32",
    "i32",
    "u16",
    "u8",
    "f64",
    "f32",
    "Option<",
    "Vec<",
    "variant",
    "Value::",
    "newtype",
    "tuple",
    "unit value",
    "untagged",
    "serde",
    "a sequence",
    "a map",
    "byte array",
];

fn root() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).to_path_buf()
}

/// The type names of the case schema (src/case/schema.rs, src/case/transient.rs).
fn schema_types() -> BTreeSet<String> {
    let mut names = BTreeSet::new();
    for file in ["src/case/schema.rs", "src/case/transient.rs"] {
        let text = std::fs::read_to_string(root().join(file)).unwrap();
        for line in text.lines() {
            let line = line.trim_start();
            for prefix in ["pub struct ", "pub enum ", "struct ", "enum "] {
                if let Some(rest) = line.strip_prefix(prefix) {
                    let name: String = rest.chars().take_while(|c| c.is_alphanumeric() || *c == '_').collect();
                    if !name.is_empty() {
                        names.insert(name);
                    }
                }
            }
        }
    }
    names
}

/// Dotted keys of every mapping entry of `value` (maps only: list items are left whole).
fn keys(value: &serde_norway::Value, prefix: &str, out: &mut Vec<String>) {
    if let serde_norway::Value::Mapping(map) = value {
        for (k, v) in map {
            let Some(k) = k.as_str() else { continue };
            let key = if prefix.is_empty() {
                k.to_string()
            } else {
                format!("{prefix}.{k}")
            };
            out.push(key.clone());
            keys(v, &key, out);
        }
    }
}

/// A message names a Rust type when it holds one of [`RUST_WORDS`] or a schema type as a word.
fn rust_in(message: &str, types: &BTreeSet<String>) -> Option<String> {
    // A word ending in a letter or digit must end there: "a map" is not "a mapping".
    let holds = |w: &str| {
        message.match_indices(w).any(|(at, _)| {
            !w.ends_with(|c: char| c.is_alphanumeric())
                || !message[at + w.len()..].starts_with(|c: char| c.is_alphanumeric())
        })
    };
    if let Some(w) = RUST_WORDS.iter().find(|w| holds(w)) {
        return Some((*w).to_string());
    }
    message
        .split(|c: char| !c.is_alphanumeric() && c != '_')
        .find(|w| types.contains(*w))
        .map(str::to_string)
}

#[test]
fn no_message_about_a_mutated_shipped_case_names_a_rust_type() {
    let types = schema_types();
    assert!(types.contains("BoundarySpec") && types.contains("Units"), "{types:?}");
    let mut cases: Vec<PathBuf> = std::fs::read_dir(root().join("cases"))
        .unwrap()
        .map(|e| e.unwrap().path())
        .filter(|p| p.extension().is_some_and(|x| x == "yaml"))
        .collect();
    cases.sort();
    let (mut tried, mut refused) = (0, 0);
    let mut bad = Vec::new();
    for case in &cases {
        let text = std::fs::read_to_string(case).unwrap();
        let tree: serde_norway::Value = serde_norway::from_str(&text).unwrap();
        let mut all = Vec::new();
        keys(&tree, "", &mut all);
        for key in &all {
            for value in MUTATIONS {
                let set = vec![format!("{key}={value}")];
                tried += 1;
                // Loading and validating is what every command does first; the check of the
                // bodies (meshes, estimates) follows for the cases that load.
                let message = match rollbem::app::load_case(case.as_path(), &set) {
                    Err(e) => e.to_string(),
                    Ok(_) => match rollbem::check::check_report(case, &set, 1e-6) {
                        Err(e) => e.to_string(),
                        Ok(_) => continue,
                    },
                };
                refused += 1;
                // The echoed argument is the user's own text: judge the rest.
                let judged = message.replace(&set[0], "");
                if let Some(word) = rust_in(&judged, &types) {
                    bad.push(format!("{} --set {}: `{word}` in: {message}", case.display(), set[0]));
                }
            }
        }
    }
    eprintln!("{tried} mutations, {refused} refused, {} naming Rust types", bad.len());
    assert!(tried > 5000, "only {tried} mutations");
    assert!(
        bad.is_empty(),
        "{} of {refused} messages name Rust types:\n{}",
        bad.len(),
        bad[..bad.len().min(4000)].join("\n")
    );
}
