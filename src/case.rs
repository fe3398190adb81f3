//! Reading a case: YAML file → value tree → `--set` overrides → typed [`Case`] → validation.
//!
//! This is the only module that names the YAML crate (`serde_norway`, the maintained fork of the
//! archived `serde_yaml`): swapping it is a change to [`parse_yaml`] alone.

mod kinds;
pub mod schema;
pub mod strength;
pub mod transient;
pub mod validate;
pub mod words;

use crate::material::{Elastic, StandardLinearSolid};
pub use schema::*;
use std::path::{Path, PathBuf};
pub use strength::{StrengthSpec, YieldSpec};
pub use transient::{Schedule, TransientSpec};
pub use validate::Violation;
pub use words::plain_message;

/// Everything that can be wrong with a case before solving.
#[derive(Debug, thiserror::Error)]
pub enum CaseError {
    /// The file could not be read.
    #[error("cannot read case file {path}: {source}")]
    Read {
        /// Case file.
        path: PathBuf,
        /// Cause.
        source: std::io::Error,
    },
    /// The file is not valid YAML.
    #[error("{path}: not valid YAML: {message}")]
    Yaml {
        /// Case file.
        path: PathBuf,
        /// Parser message with line and column.
        message: String,
    },
    /// A `--set` argument could not be applied.
    #[error("--set {argument}: {message}")]
    Override {
        /// The argument as given.
        argument: String,
        /// What is wrong and what to do.
        message: String,
    },
    /// A key is unknown, missing or of the wrong type.
    #[error("{path}: key `{key}`: {message}")]
    Schema {
        /// Case file.
        path: PathBuf,
        /// Dotted key path where the problem is.
        key: String,
        /// Serde's message (expected type, unknown field and the valid ones).
        message: String,
    },
    /// Values are out of range or inconsistent; every violation is listed.
    #[error("{path}: invalid case:\n{}", violations.iter().map(|v| format!("  - {v}")).collect::<Vec<_>>().join("\n"))]
    Invalid {
        /// Case file.
        path: PathBuf,
        /// All violations found.
        violations: Vec<Violation>,
    },
}

/// A case that parsed and validated, with where it came from.
#[derive(Debug, Clone)]
pub struct LoadedCase {
    /// The typed case.
    pub case: Case,
    /// The case file.
    pub path: PathBuf,
    /// The case as resolved after overrides, for the summary.
    pub resolved: serde_json::Value,
}

impl LoadedCase {
    /// Refuses a case that gives a `transient:` history for a `command` that solves steady
    /// problems (`rollbem sweep`, the studies): it would solve the steady problem and drop the
    /// history without a word.
    pub fn steady_only(&self, command: &str) -> Result<(), CaseError> {
        match self.case.transient {
            None => Ok(()),
            Some(_) => Err(CaseError::Schema {
                path: self.path.clone(),
                key: "transient".into(),
                message: format!(
                    "the case gives a transient history, and {command} solves steady problems only: \
                     run the history with `rollbem run`, or remove it with `--set transient=null` \
                     (an override `transient=null`) to solve the case's steady problem"
                ),
            }),
        }
    }

    /// Folder of the case file (paths in a case are relative to it).
    pub fn base_dir(&self) -> PathBuf {
        self.path.parent().map(Path::to_path_buf).unwrap_or_default()
    }

    /// The output folder: `output.dir` relative to the case file, else `out/<stem>` next to it.
    pub fn output_dir(&self) -> PathBuf {
        let dir = match &self.case.output.dir {
            Some(dir) => self.base_dir().join(dir),
            None => {
                let stem = self
                    .path
                    .file_stem()
                    .map_or("case".into(), |s| s.to_string_lossy().into_owned());
                self.base_dir().join("out").join(stem)
            }
        };
        normalize(&dir)
    }

    /// The files the case reads: the case file and the Gmsh meshes of its bodies (`mesh:` of
    /// a `bem` or `rigid` body), as paths relative to the working folder. A command never
    /// removes or replaces them ([`crate::files::WriteOptions::inputs`]).
    pub fn input_files(&self) -> Vec<PathBuf> {
        let meshes = [&self.case.bodies.a, &self.case.bodies.b]
            .into_iter()
            .filter_map(|body| body.mesh_file())
            .map(|m| self.base_dir().join(m));
        std::iter::once(self.path.clone()).chain(meshes).collect()
    }

    /// Material by name (validated to exist).
    pub fn material(&self, name: &str) -> Elastic {
        material_of(&self.case.materials[name])
    }

    /// The standard linear solid of a viscoelastic material (validated), None for an elastic
    /// one.
    pub fn viscoelastic_material(&self, name: &str) -> Option<StandardLinearSolid> {
        viscoelastic_of(&self.case.materials[name])
    }
}

/// The standard linear solid of a material spec with `viscoelastic` keys: the spec's E or G is
/// the glassy modulus, `E_rubbery` or `G_rubbery` the rubbery one (validated: the same kind).
pub fn viscoelastic_of(spec: &MaterialSpec) -> Option<StandardLinearSolid> {
    let v = spec.viscoelastic.as_ref()?;
    let glassy = material_of(spec);
    let rubbery_young = match (v.young_rubbery, v.shear_rubbery) {
        (Some(e), _) => e,
        (None, Some(g)) => 2.0 * g * (1.0 + spec.nu),
        (None, None) => f64::NAN,
    };
    Some(StandardLinearSolid {
        glassy,
        rubbery_young,
        creep_time: v.creep_time,
    })
}

/// The normal plan: `transient.normal`, else `load.normal` as a constant (validated cases;
/// an invalid one falls back to the load's).
pub fn normal_plan(spec: &TransientSpec, load: &LoadSpec) -> transient::NormalPlan {
    match spec.normal.as_ref().and_then(|n| n.plan().ok()) {
        Some(plan) => plan,
        None => match load.normal() {
            NormalSpec::Force(p) => transient::NormalPlan::Force(transient::Schedule::Constant(p)),
            NormalSpec::Overlap(d) => transient::NormalPlan::Overlap(transient::Schedule::Constant(d)),
        },
    }
}

/// The tangential plan: `transient.tangential`, else `load.tangential` as a constant.
pub fn tangential_plan(spec: &TransientSpec, load: &LoadSpec) -> transient::TangentialPlan {
    match spec.tangential.as_ref().and_then(|t| t.plan().ok()) {
        Some(plan) => plan,
        None => match load.tangential() {
            TangentialSpec::Ratio(r) => transient::TangentialPlan::Ratio(transient::Schedule::Constant(r)),
            TangentialSpec::Force(q) => transient::TangentialPlan::Force(transient::Schedule::Constant(q)),
            TangentialSpec::Creep(x) => transient::TangentialPlan::Creep(transient::Schedule::Constant(x)),
        },
    }
}

/// The elastic constants of a material spec (validated: exactly one of E and G).
pub fn material_of(spec: &MaterialSpec) -> Elastic {
    match (spec.young, spec.shear) {
        (Some(e), _) => Elastic::new(e, spec.nu),
        (None, Some(g)) => Elastic::from_shear(g, spec.nu),
        (None, None) => Elastic::new(f64::NAN, spec.nu),
    }
}

/// Removes `.` and `name/..` pairs lexically (`cases/../out/x` → `out/x`), `.` when nothing
/// is left.
fn normalize(path: &Path) -> PathBuf {
    let out = crate::files::normalize(path);
    if out.as_os_str().is_empty() {
        PathBuf::from(".")
    } else {
        out
    }
}

/// Parses YAML text into a value tree.
fn parse_yaml(text: &str) -> Result<serde_norway::Value, String> {
    serde_norway::from_str(text).map_err(|e| plain_message(&e.to_string()))
}

/// The path of a shipped case, `cases/<name>` of the repository (for the library's tests).
#[cfg(test)]
pub(crate) fn shipped(name: &str) -> std::path::PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("cases").join(name)
}

/// Loads, overrides and validates a case file.
pub fn load(path: &Path, overrides: &[String]) -> Result<LoadedCase, CaseError> {
    // Checked before opening: reading a FIFO would block for ever.
    let problem = crate::limits::input_file_problem(path, crate::limits::MAX_CASE_BYTES);
    let problem = problem.map_err(|source| CaseError::Read {
        path: path.to_path_buf(),
        source,
    })?;
    if let Some(why) = problem {
        return Err(CaseError::Read {
            path: path.to_path_buf(),
            source: std::io::Error::new(std::io::ErrorKind::InvalidInput, why),
        });
    }
    let text = std::fs::read_to_string(path).map_err(|source| CaseError::Read {
        path: path.to_path_buf(),
        source,
    })?;
    parse(&text, path, overrides)
}

/// Parses, overrides and validates case text as if it had been read from `path` (which names
/// the case in messages, and whose folder resolves the case's relative paths): for cases that
/// live in memory (built-in references, tests, fuzzing) as well as files.
pub fn parse(text: &str, path: &Path, overrides: &[String]) -> Result<LoadedCase, CaseError> {
    ParsedCase::new(text, path).with_overrides(overrides)
}

/// A case file's text parsed once into its YAML tree, for the many runs of a sweep that apply
/// their own overrides to it ([`Self::with_overrides`] gives what [`parse`] gives for the text
/// and the overrides, without reading the YAML again).
#[derive(Debug, Clone)]
pub struct ParsedCase {
    path: PathBuf,
    tree: Result<serde_norway::Value, String>,
}

impl ParsedCase {
    /// The tree of `text`, the case file at `path` (a YAML error is kept and reported by
    /// [`Self::with_overrides`]).
    pub fn new(text: &str, path: &Path) -> Self {
        Self {
            path: path.to_path_buf(),
            tree: parse_yaml(text),
        }
    }

    /// The case with `overrides` (`KEY.PATH=VALUE`) applied, then validated: [`parse`]'s result.
    pub fn with_overrides(&self, overrides: &[String]) -> Result<LoadedCase, CaseError> {
        let value = self.tree.clone().map_err(|message| CaseError::Yaml {
            path: self.path.clone(),
            message,
        })?;
        from_tree(value, &self.path, overrides)
    }
}

/// The case of the YAML tree `value` of the file at `path`, with `overrides` applied, checked
/// and validated.
fn from_tree(mut value: serde_norway::Value, path: &Path, overrides: &[String]) -> Result<LoadedCase, CaseError> {
    for argument in overrides {
        apply_override(&mut value, argument)?;
    }
    let mut violations = Vec::new();
    check_tree(&value, "", &mut violations);
    if !violations.is_empty() {
        return Err(CaseError::Invalid {
            path: path.to_path_buf(),
            violations,
        });
    }
    let mut case: Case = serde_path_to_error::deserialize(value.clone()).map_err(|e| {
        let key = match e.path().to_string() {
            p if p == "." => "(top level)".to_string(),
            p => p,
        };
        let message = plain_message(&e.inner().to_string());
        // The key at fault: an unknown field's own key, else the key where the value failed.
        let culprit = message
            .strip_prefix("unknown field `")
            .and_then(|rest| rest.split_once('`'))
            .map_or_else(
                || key.clone(),
                |(field, _)| match e.path().to_string() {
                    p if p == "." => field.to_string(),
                    p => format!("{p}.{field}"),
                },
            );
        match blamed_override(overrides, &culprit) {
            Some(argument) => CaseError::Override {
                argument: argument.clone(),
                message: format!("key `{key}`: {message}"),
            },
            None => CaseError::Schema {
                path: path.to_path_buf(),
                key,
                message,
            },
        }
    })?;
    let mut violations = validate::validate(&case);
    if !violations.is_empty() {
        // Say which values came from the command line rather than from the file.
        for v in &mut violations {
            if let Some(argument) = blamed_override(overrides, &v.key) {
                v.message = format!("{} (the value given by --set {argument})", v.message);
            }
        }
        return Err(CaseError::Invalid {
            path: path.to_path_buf(),
            violations,
        });
    }
    // The title names the file's case; a run changed on the command line says so (unless the
    // command line sets the title itself).
    if !overrides.is_empty() && !overrides.iter().any(|o| o.trim_start().starts_with("title=")) {
        case.title.push_str(" (modified by --set)");
    }
    let resolved = serde_json::to_value(&value).unwrap_or(serde_json::Value::Null);
    Ok(LoadedCase {
        case,
        path: path.to_path_buf(),
        resolved,
    })
}

/// The last `--set` argument whose key is `key`, lies inside it or holds it (so that its value
/// put there what failed), if any.
fn blamed_override<'a>(overrides: &'a [String], key: &str) -> Option<&'a String> {
    let related = |set: &str| {
        set == key
            || key.strip_prefix(set).is_some_and(|rest| rest.starts_with(['.', '[']))
            || set.strip_prefix(key).is_some_and(|rest| rest.starts_with('.'))
    };
    overrides
        .iter()
        .rev()
        .find(|a| a.split_once('=').is_some_and(|(k, _)| related(k)))
}

/// What the typed schema cannot see in the raw YAML tree: local tags (`friction: !weird 0.1`,
/// which deserialisation would strip silently, so the user's intent is lost) and numbers that are
/// not finite (`.nan`, `.inf`, which no key of a case accepts). Each is reported by its dotted key.
fn check_tree(value: &serde_norway::Value, key: &str, out: &mut Vec<Violation>) {
    use serde_norway::Value;
    let named = |key: &str| {
        if key.is_empty() {
            "(top level)".to_string()
        } else {
            key.to_string()
        }
    };
    match value {
        Value::Tagged(tagged) => out.push(Violation {
            key: named(key),
            message: format!(
                "YAML tag `{}` is not allowed: case values are plain numbers, strings, lists and \
                 mappings; remove the tag",
                tagged.tag
            ),
        }),
        Value::Number(n) => {
            if let Some(v) = n.as_f64().filter(|v| !v.is_finite()) {
                out.push(Violation {
                    key: named(key),
                    message: format!("must be a finite number (value = {v})"),
                });
            }
        }
        Value::Sequence(items) => {
            for (i, item) in items.iter().enumerate() {
                check_tree(item, &format!("{key}[{i}]"), out);
            }
        }
        Value::Mapping(map) => {
            for (k, v) in map {
                let name = match k {
                    Value::String(s) => s.clone(),
                    other => serde_norway::to_string(other).map_or_else(|_| "?".into(), |s| s.trim().to_string()),
                };
                if let Value::Tagged(_) = k {
                    check_tree(k, &name, out);
                }
                let child = if key.is_empty() { name } else { format!("{key}.{name}") };
                check_tree(v, &child, out);
            }
        }
        Value::Null | Value::Bool(_) | Value::String(_) => {}
    }
}

/// Applies `key.path=value` to the value tree, creating missing mappings on the way. The value
/// is read as YAML, so `0.5`, `true`, `phi` and `{force: 10}` all work; `null` (or `~`, or
/// nothing after `=`) removes the key.
pub fn apply_override(root: &mut serde_norway::Value, argument: &str) -> Result<(), CaseError> {
    let err = |message: String| CaseError::Override {
        argument: argument.to_string(),
        message,
    };
    let (key, raw) = argument
        .split_once('=')
        .ok_or_else(|| err("expected key.path=value, e.g. --set contact.friction=0.2".into()))?;
    let value = parse_yaml(raw).map_err(|m| err(format!("value is not valid YAML: {m}")))?;
    let parts: Vec<&str> = key.split('.').collect();
    if parts.iter().any(|p| p.is_empty()) {
        return Err(err("empty key segment; write e.g. load.normal.force=1000".into()));
    }
    let mut node = root;
    for (depth, part) in parts.iter().enumerate() {
        let map = match node {
            serde_norway::Value::Mapping(map) => map,
            serde_norway::Value::Null => {
                *node = serde_norway::Value::Mapping(Default::default());
                match node {
                    serde_norway::Value::Mapping(map) => map,
                    _ => unreachable!(),
                }
            }
            _ => {
                return Err(err(format!(
                    "`{}` is not a mapping, so it has no key `{part}`",
                    parts[..depth].join(".")
                )))
            }
        };
        let k = serde_norway::Value::String(part.to_string());
        if depth + 1 == parts.len() {
            if value.is_null() {
                // `key=null` removes the key: its default applies, and a key that the new
                // value of another key does not take (a rigid body's material) can go.
                map.remove(&k);
            } else {
                map.insert(k, value);
            }
            return Ok(());
        }
        if value.is_null() && !map.contains_key(&k) {
            // Nothing to remove.
            return Ok(());
        }
        node = map.entry(k).or_insert(serde_norway::Value::Null);
    }
    Ok(())
}
