//! The native part of the Python package `rollbem`: the module `rollbem._rollbem`.
//!
//! It is thin on purpose. Each function takes a case (a file path, or YAML/JSON text with the
//! name it goes by in messages), runs the library's public stages (`app::load_case`,
//! `app::solve`, `app::run`, `check::report`, `output::summary`) without the GIL, and hands back
//! plain data: summary.json's text exactly as the CLI writes it and the contact line's columns
//! as numpy arrays (the values contact.csv prints with `output::number`), so that Python and the
//! CLI agree bit for bit. The Python layer (`python-src/rollbem/__init__.py`) turns them into
//! `Result` objects and rows and raises `NotConverged` for a run that did not converge.
//!
//! Errors map as `rollbem`'s exit codes do (src/main.rs): exit code 1 (bad input, output folder
//! refused) is `rollbem.InputError`, 2 (a numerical breakdown, an error-controlled grid that
//! missed its tolerance) is `rollbem.NotConverged`, 3 (a panic, caught here with
//! `catch_unwind`, never unwound into Python) is `rollbem.InternalError`. Log messages of the
//! library (the `log` facade) go to Python's `logging`, logger `rollbem` and its children
//! (`rollbem.progress` for the per-iteration progress), through pyo3-log.

use numpy::PyArray1;
use pyo3::prelude::*;
use pyo3::types::PyDict;
use rollbem::app::{self, CaseSource};
use rollbem::cancel::Token;
use rollbem::contact::ContactProblem;
use rollbem::error::{Error, EXIT_NOT_CONVERGED};
use rollbem::output::{self, folder, Summary};
use rollbem::post::ContactSolution;
use std::panic::AssertUnwindSafe;
use std::path::{Path, PathBuf};
use std::sync::atomic::{AtomicUsize, Ordering};
use std::sync::mpsc::{self, RecvTimeoutError};
use std::sync::{Mutex, Once, OnceLock};
use std::time::{Duration, Instant};

/// A case as the Python layer hands it over: a file, or text that stands for one.
struct Source {
    /// The file, or the name the text goes by in messages (its folder resolves the case's
    /// relative paths: for a dict case a bare name, so they resolve from the current directory).
    path: PathBuf,
    /// YAML (or JSON) text of a case given as a dict.
    text: Option<String>,
}

impl Source {
    fn case_source(&self) -> CaseSource<'_> {
        match &self.text {
            Some(text) => CaseSource::Text { text, path: &self.path },
            None => CaseSource::File(&self.path),
        }
    }
}

/// Why a call failed: the library's error, a panic (a bug) with its message, or a cancellation
/// (Ctrl-C, see [`interruptible`]).
enum Failure {
    Library(Error),
    Panic(String),
    Cancelled,
}

impl From<Error> for Failure {
    fn from(e: Error) -> Self {
        Failure::Library(e)
    }
}

/// Calls under way in [`guarded`]: while any is, the panic hook records panics instead of
/// printing Rust's report on stderr.
static GUARDED: AtomicUsize = AtomicUsize::new(0);

/// The message and place of the last panic recorded by the hook.
static LAST_PANIC: Mutex<Option<String>> = Mutex::new(None);

/// Installs (once) a panic hook that records a panic's message and place while a guarded call
/// runs, and leaves any other panic of the process to the hook that was there before.
fn install_panic_hook() {
    static ONCE: Once = Once::new();
    ONCE.call_once(|| {
        let previous = std::panic::take_hook();
        std::panic::set_hook(Box::new(move |info| {
            if GUARDED.load(Ordering::SeqCst) == 0 {
                return previous(info);
            }
            let place = info
                .location()
                .map_or(String::new(), |l| format!(" at {}:{}", l.file(), l.line()));
            if let Ok(mut last) = LAST_PANIC.lock() {
                *last = Some(format!("{}{place}", payload_text(info.payload())));
            }
        }));
    });
}

/// The text of a panic's payload (`panic!` with a literal or a formatted message).
fn payload_text(payload: &(dyn std::any::Any + Send)) -> String {
    payload
        .downcast_ref::<&str>()
        .map(|s| s.to_string())
        .or_else(|| payload.downcast_ref::<String>().cloned())
        .unwrap_or_else(|| "panic".into())
}

/// Runs `f`, turning a panic into [`Failure::Panic`] (with the place the hook recorded).
fn guarded<T>(f: impl FnOnce() -> Result<T, Failure>) -> Result<T, Failure> {
    GUARDED.fetch_add(1, Ordering::SeqCst);
    let outcome = std::panic::catch_unwind(AssertUnwindSafe(f));
    GUARDED.fetch_sub(1, Ordering::SeqCst);
    outcome.unwrap_or_else(|payload| {
        let recorded = LAST_PANIC.lock().ok().and_then(|mut p| p.take());
        Err(Failure::Panic(recorded.unwrap_or_else(|| payload_text(&*payload))))
    })
}

/// Runs `work` under a cancellation token (`rollbem::cancel`) and `guarded`: a cancelled run is
/// [`Failure::Cancelled`].
fn cancellable<T>(token: &Token, work: impl FnOnce() -> Result<T, Failure>) -> Result<T, Failure> {
    guarded(|| token.run(work).unwrap_or(Err(Failure::Cancelled)))
}

/// Stack of the thread a call's work runs on: that of a main thread (Linux's default 8 MiB),
/// not the 2 MiB of a spawned one.
const WORK_STACK: usize = 8 << 20;

/// How often the calling thread looks for signals while the work runs.
const SIGNAL_POLL: Duration = Duration::from_millis(50);

/// Runs `work` without the GIL on a thread of its own while the calling thread looks at
/// Python's signals every [`SIGNAL_POLL`] (`Python::check_signals`: Python runs its handlers
/// in the main thread only, so elsewhere this just waits). When a handler raises (Ctrl-C's
/// `KeyboardInterrupt`), the token is set, the work stops at the solver's next checkpoint
/// (within a Newton step) and that exception is returned; otherwise the work's own outcome.
fn interruptible<T: Send>(py: Python<'_>, work: impl FnOnce(&Token) -> T + Send) -> Result<T, PyErr> {
    let token = Token::new();
    // Taken by the thread that runs it: the worker, or this one when no thread can be started.
    let work = Mutex::new(Some(work));
    let take = || work.lock().ok().and_then(|mut w| w.take());
    let (outcome, interrupt) = py.detach(|| {
        std::thread::scope(|scope| {
            let (done, finished) = mpsc::channel::<()>();
            let spawned = std::thread::Builder::new()
                .name("rollbem".into())
                .stack_size(WORK_STACK)
                .spawn_scoped(scope, {
                    let (take, token) = (&take, &token);
                    move || {
                        let outcome = take().map(|work| work(token));
                        let _ = done.send(());
                        outcome
                    }
                });
            let Ok(worker) = spawned else {
                // No thread to spare: the work runs here, without Ctrl-C.
                return (take().map(|work| work(&token)), None);
            };
            let mut interrupt = None;
            while let Err(RecvTimeoutError::Timeout) = finished.recv_timeout(SIGNAL_POLL) {
                if interrupt.is_none() {
                    if let Err(e) = Python::attach(|py| py.check_signals()) {
                        token.cancel();
                        interrupt = Some(e);
                    }
                }
            }
            match worker.join() {
                Ok(outcome) => (outcome, interrupt),
                Err(payload) => std::panic::resume_unwind(payload),
            }
        })
    });
    match (interrupt, outcome) {
        (Some(e), _) => Err(e),
        (None, Some(outcome)) => Ok(outcome),
        (None, None) => Err(exception(
            py,
            "InternalError",
            "internal error — please report it: the work of the call was lost".into(),
        )),
    }
}

/// Resets pyo3-log's cache of Python loggers and their levels, so that a change of the logging
/// configuration between calls takes effect.
static LOG_RESET: OnceLock<Option<pyo3_log::ResetHandle>> = OnceLock::new();

fn refresh_logging() {
    if let Some(Some(handle)) = LOG_RESET.get() {
        handle.reset();
    }
}

/// An instance of one of the exception classes of `rollbem._errors` (Python-defined, so that
/// they carry docstrings and typed attributes).
fn exception(py: Python<'_>, class: &str, message: String) -> PyErr {
    let made = py
        .import("rollbem._errors")
        .and_then(|m| m.getattr(class))
        .and_then(|c| c.call1((message,)));
    match made {
        Ok(instance) => PyErr::from_value(instance),
        Err(e) => e,
    }
}

/// The Python exception of a failure, chosen by the CLI's exit code (module docs).
fn to_py_err(py: Python<'_>, case: &Path, failure: Failure) -> PyErr {
    match failure {
        // Only a signal handler's exception cancels (it is raised instead of this one).
        Failure::Cancelled => pyo3::exceptions::PyKeyboardInterrupt::new_err("rollbem: the run was cancelled"),
        Failure::Panic(what) => exception(
            py,
            "InternalError",
            format!(
                "internal error — please report it (with the case file {} and this message): {what}",
                case.display()
            ),
        ),
        Failure::Library(e) if e.exit_code() == EXIT_NOT_CONVERGED => {
            let err = exception(py, "NotConverged", e.to_string());
            if let Error::ToleranceNotReached {
                tolerance,
                elements,
                max_elements,
                pressure,
                shear,
                creep,
                ..
            } = e
            {
                let estimate = PyDict::new(py);
                let set = || -> PyResult<()> {
                    estimate.set_item("tolerance", tolerance)?;
                    estimate.set_item("elements", elements)?;
                    estimate.set_item("max_elements", max_elements)?;
                    estimate.set_item("pressure", pressure)?;
                    estimate.set_item("shear", shear)?;
                    estimate.set_item("creep", creep)?;
                    err.value(py).setattr("estimate", &estimate)
                };
                if let Err(e) = set() {
                    return e;
                }
            }
            err
        }
        Failure::Library(e) => exception(py, "InputError", e.to_string()),
    }
}

/// A run's results as plain data (built without the GIL).
struct RunData {
    /// summary.json's content, serialised as the CLI writes it.
    summary: String,
    /// contact.csv's numeric columns in order (`slip_hbem` only when it exists).
    columns: Vec<(&'static str, Vec<f64>)>,
    /// contact.csv's `state` column.
    state: Vec<&'static str>,
    /// The output folder, when one was written.
    output_dir: Option<PathBuf>,
    /// The CLI's message for a run that did not converge (None when it converged).
    not_converged: Option<String>,
}

impl RunData {
    fn new(summary: &Summary, sol: &ContactSolution, pb: &ContactProblem, out: Option<PathBuf>) -> Result<Self, Error> {
        let text = serde_json::to_string_pretty(summary).map_err(|e| Error::Output {
            path: out.clone().unwrap_or_default(),
            message: e.to_string(),
        })?;
        let d = pb.surface_displacements(&sol.pressure, &sol.shear);
        let mut columns = vec![
            ("x", sol.x.clone()),
            ("pressure", sol.pressure.clone()),
            ("shear", sol.shear.clone()),
            ("gap", sol.gap.clone()),
            ("slip", sol.slip.clone()),
        ];
        if let Some(s) = sol.slip_strain.as_ref().filter(|s| s.iter().all(|v| v.is_finite())) {
            columns.push(("slip_hbem", s.clone()));
        }
        columns.extend([
            ("u_n_A", d.normal_a),
            ("u_t_A", d.tangential_a),
            ("u_n_B", d.normal_b),
            ("u_t_B", d.tangential_b),
        ]);
        let not_converged = (!summary.converged).then(|| not_converged_message(summary, out.as_deref()));
        Ok(Self {
            summary: text,
            columns,
            state: sol.state.iter().map(|s| s.name()).collect(),
            output_dir: out,
            not_converged,
        })
    }

    fn into_py<'py>(self, py: Python<'py>) -> PyResult<Bound<'py, PyDict>> {
        let d = PyDict::new(py);
        d.set_item("summary", self.summary)?;
        let columns = PyDict::new(py);
        for (name, values) in self.columns {
            columns.set_item(name, PyArray1::from_vec(py, values))?;
        }
        d.set_item("columns", columns)?;
        d.set_item("state", self.state)?;
        d.set_item("output_dir", self.output_dir)?;
        d.set_item("not_converged", self.not_converged)?;
        Ok(d)
    }
}

/// What the CLI says when a run ends without converging (src/main.rs): whether the iteration
/// budget ran out or the residual stopped improving, and what to try.
fn not_converged_message(summary: &Summary, out: Option<&Path>) -> String {
    let budget = summary
        .case
        .pointer("/solver/max_iterations")
        .and_then(serde_json::Value::as_u64)
        .unwrap_or(u64::MAX);
    let cause = if summary.iterations as u64 >= budget {
        "the iteration budget ran out: give more solver.max_iterations (gauss_seidel counts sweeps and \
         needs thousands), or try"
    } else {
        "the residual stopped improving (more iterations will not help): try"
    };
    let history = match out {
        Some(dir) => format!("in {}", dir.join("summary.json").display()),
        None => "the result's summary['solver']['history']".to_string(),
    };
    format!(
        "the solver did not converge in {} iterations (scaled residual {:.3e}); {cause} \
         solver.method: newton (the default), solver.formulation: psi, a different solver.penalty \
         scale, or a finer contact grid. The residual history is {history}.",
        summary.iterations, summary.residual
    )
}

/// A history (`transient:`) asked of a run without a folder: its steps are files
/// (transient.csv, steps/), which only a run into a folder writes.
fn transient_refused(case: &rollbem::case::LoadedCase) -> Error {
    Error::Case(rollbem::case::CaseError::Invalid {
        path: case.path.clone(),
        violations: vec![rollbem::case::Violation {
            key: "transient".into(),
            message: "a history's results are its files (transient.csv, steps/): run it into a folder, \
                      rollbem.run(CASE_FILE, out=FOLDER), or with `rollbem run CASE`; remove the section \
                      for the steady state"
                .into(),
        }],
    })
}

/// One run: `app::run` for a case file written to a folder (the CLI's own path), else the same
/// stages for a case file or text, writing only when `out` is given.
fn run_case(source: &Source, overrides: &[String], out: Option<&Path>) -> Result<RunData, Error> {
    if let (None, Some(out)) = (&source.text, out) {
        let r = app::run(&source.path, overrides, Some(out))?;
        return RunData::new(&r.summary, &r.solution, &r.problem, Some(r.output_dir));
    }
    let start = Instant::now();
    let case = app::load_case(source.case_source(), overrides)?;
    if case.case.transient.is_some() {
        return Err(transient_refused(&case));
    }
    // Lock and check the output folder before solving, as `app::run` does.
    let _claim = match out {
        Some(dir) => Some(folder::Claim::acquire(
            dir,
            folder::Kind::Run,
            folder::Access::Exclusive,
        )?),
        None => None,
    };
    let s = app::solve_run(&case)?;
    let mut summary = output::summary(&s);
    rollbem::post::finite::check(&case.path, "summary.json", &summary)?;
    if let Some(dir) = out {
        output::write_run(dir, &mut summary, &s, start)?;
    }
    RunData::new(&summary, &s.solution, &s.problem, out.map(Path::to_path_buf))
}

/// Solves a case (`rollbem run`) and returns its results as plain data: `summary` (summary.json's
/// text), `columns` (contact.csv's numeric columns as float64 arrays), `state`, `output_dir`
/// and `not_converged` (the CLI's message when the run did not converge, else None). Without
/// `out` nothing is written. Raises `rollbem.InputError`, `rollbem.NotConverged` (numerical
/// breakdown, missed tolerance) or `rollbem.InternalError`. Releases the GIL while it solves.
#[pyfunction]
#[pyo3(signature = (path, text, overrides, out=None))]
fn run<'py>(
    py: Python<'py>,
    path: PathBuf,
    text: Option<String>,
    overrides: Vec<String>,
    out: Option<PathBuf>,
) -> PyResult<Bound<'py, PyDict>> {
    refresh_logging();
    let source = Source { path, text };
    let outcome = interruptible(py, |token| {
        cancellable(token, || Ok(run_case(&source, &overrides, out.as_deref())?))
    })?;
    outcome.map_err(|f| to_py_err(py, &source.path, f))?.into_py(py)
}

/// `rollbem check`: the case as understood, without solving. Returns `report` (the text the
/// CLI prints), `estimates` (summary.json's `estimates` as JSON text: Hertz half-width and peak
/// pressure, E*, R*, ...) and `case` (the case resolved after the overrides, JSON text).
/// `tolerance` is the accuracy the model advice aims at, a fraction of p0 and μp0; with
/// `estimate` the report ends with the grid's estimated error (`rollbem check --estimate`:
/// the case solved on its grid and on the grid halved).
#[pyfunction]
#[pyo3(signature = (path, text, overrides, tolerance=0.01, estimate=false))]
fn check<'py>(
    py: Python<'py>,
    path: PathBuf,
    text: Option<String>,
    overrides: Vec<String>,
    tolerance: f64,
    estimate: bool,
) -> PyResult<Bound<'py, PyDict>> {
    refresh_logging();
    if !(tolerance > 0.0 && tolerance.is_finite()) {
        return Err(exception(
            py,
            "InputError",
            format!("tolerance must be a positive fraction, e.g. 0.01 for 1 % (value = {tolerance})"),
        ));
    }
    let source = Source { path, text };
    let outcome = py.detach(|| {
        guarded(|| {
            let case = app::load_case(source.case_source(), &overrides)?;
            let mut report = rollbem::check::report(&case, tolerance)?;
            report.push_str(&rollbem::check::grid_error_lines(&case, tolerance, estimate)?);
            let scene = rollbem::scene::Scene::from_case(&case)?;
            let estimates = serde_json::to_string(&scene.estimates).map_err(|e| Error::Output {
                path: case.path.clone(),
                message: e.to_string(),
            })?;
            Ok((report, estimates, case.resolved.to_string()))
        })
    });
    let (report, estimates, case) = outcome.map_err(|f| to_py_err(py, &source.path, f))?;
    let d = PyDict::new(py);
    d.set_item("report", report)?;
    d.set_item("estimates", estimates)?;
    d.set_item("case", case)?;
    Ok(d)
}

/// One sweep run's row: the columns of sweep.csv after `run`, `folder`, `status`, the varied
/// values and `message`, with numbers as numbers (JSON) instead of text.
fn sweep_row(run: usize, outcome: Result<Summary, Failure>) -> serde_json::Value {
    use serde_json::{json, Value};
    let mut row = serde_json::Map::new();
    row.insert("run".into(), json!(run));
    match outcome {
        Ok(s) => {
            let c = s.contact.as_ref();
            row.insert("status".into(), json!(if s.converged { "ok" } else { "not_converged" }));
            row.insert("message".into(), json!(""));
            // In the order of sweep.csv's columns (rollbem::sweep::RESULT_COLUMNS).
            let values: [Value; rollbem::sweep::RESULT_COLUMNS.len()] = [
                json!(s.converged),
                json!(s.iterations),
                json!(s.residual),
                json!(s.normal_force),
                json!(s.tangential_force),
                json!(s.load_ratio),
                json!(s.overlap),
                json!(s.creep),
                json!(c.map(|c| c.x_min)),
                json!(c.map(|c| c.x_max)),
                json!(c.map(|c| c.centre)),
                json!(c.map(|c| c.half_width)),
                json!(s.max_pressure),
                json!(s.slip_regime.number()),
                json!(s.stick_zones.len()),
                json!(s.slip_zones.len()),
                json!(s.rolling_resistance.map(|r| r.pressure_centre)),
                json!(s.rolling_resistance.map(|r| r.coefficient)),
                json!(s.timings.assembly_s),
                json!(s.timings.condense_s),
                json!(s.timings.solve_s),
                json!(s.timings.total_s),
            ];
            for (name, value) in rollbem::sweep::RESULT_COLUMNS.iter().zip(values) {
                row.insert(name.to_string(), value);
            }
        }
        Err(failure) => {
            let message = match failure {
                Failure::Library(e) => e.to_string().replace('\n', " "),
                Failure::Panic(what) => format!("internal error — please report it: {}", what.replace('\n', " ")),
                Failure::Cancelled => "cancelled".into(),
            };
            row.insert("status".into(), json!("failed"));
            row.insert("message".into(), json!(message));
            for name in rollbem::sweep::RESULT_COLUMNS {
                row.insert(name.to_string(), Value::Null);
            }
        }
    }
    Value::Object(row)
}

/// `rollbem sweep` without files: the Cartesian product of `varies` (the first varies slowest)
/// over the case with `overrides`, solved as the CLI's sweep solves it (chains of neighbours on
/// one shared assembly, warm-started; `rollbem::sweep::summaries`) on a rayon pool of `jobs`
/// threads (all cores when None). Returns one JSON row per run, in run order (see [`sweep_row`]). A bad case file
/// fails at once; a run that fails is a row with status `failed` and its message.
#[pyfunction]
#[pyo3(signature = (path, text, overrides, varies, jobs=None))]
fn sweep(
    py: Python<'_>,
    path: PathBuf,
    text: Option<String>,
    overrides: Vec<String>,
    varies: Vec<(String, Vec<String>)>,
    jobs: Option<usize>,
) -> PyResult<Vec<String>> {
    refresh_logging();
    let source = Source { path, text };
    let outcome = interruptible(py, |token| {
        cancellable(token, || {
            if varies.is_empty() || varies.iter().any(|(_, v)| v.is_empty()) {
                return Err(Error::Sweep {
                    message: "nothing to sweep: give vary={'key.path': [v1, v2, ...]} with at least one value".into(),
                }
                .into());
            }
            if jobs == Some(0) {
                return Err(Error::Sweep {
                    message: "jobs must be at least 1 (or None for every core)".into(),
                }
                .into());
            }
            // Fail fast on an unreadable case, as the CLI's sweep does.
            app::load_case(source.case_source(), &overrides)?
                .steady_only("`rollbem.sweep`")
                .map_err(Error::from)?;
            let varies: Vec<rollbem::sweep::Vary> = varies
                .iter()
                .map(|(key, values)| rollbem::sweep::Vary {
                    key: key.clone(),
                    values: values.clone(),
                })
                .collect();
            // Solved as the CLI's sweep solves them: chains of neighbours on one shared assembly,
            // each run warm-started from the one before it.
            let all = || -> Result<Vec<String>, Error> {
                let outcomes = rollbem::sweep::summaries(source.case_source(), &overrides, &varies, |solve| {
                    cancellable(token, || Ok(solve()?))
                })?;
                Ok(outcomes
                    .into_iter()
                    .enumerate()
                    .map(|(n, r)| sweep_row(n, r).to_string())
                    .collect())
            };
            let rows = match jobs {
                None => all(),
                Some(n) => rayon::ThreadPoolBuilder::new()
                    .num_threads(n)
                    .build()
                    .map_err(|e| Error::Sweep {
                        message: format!("cannot start {n} threads: {e}"),
                    })?
                    .install(all),
            }?;
            // A run cancelled is a row like a failed one: the sweep as a whole is cancelled.
            rollbem::cancel::checkpoint();
            Ok(rows)
        })
    })?;
    outcome.map_err(|f| to_py_err(py, &source.path, f))
}

/// Panics inside a guarded call: the test of the mapping of a panic to `rollbem.InternalError`
/// (python/tests), which no input is known to trigger.
#[pyfunction]
fn _panic_for_tests(py: Python<'_>, message: String) -> PyResult<()> {
    let outcome = py.detach(|| guarded::<()>(|| panic!("{message}")));
    outcome.map_err(|f| to_py_err(py, Path::new("(none)"), f))
}

/// The module `rollbem._rollbem`.
#[pymodule]
fn _rollbem(m: &Bound<'_, PyModule>) -> PyResult<()> {
    install_panic_hook();
    LOG_RESET.get_or_init(|| {
        // Another extension may have installed a `log` logger first: then rollbem's messages go
        // to that one.
        pyo3_log::Logger::new(m.py(), pyo3_log::Caching::LoggersAndLevels)
            .ok()
            .and_then(|l| l.install().ok())
    });
    m.add("__version__", env!("CARGO_PKG_VERSION"))?;
    m.add("RESULT_COLUMNS", rollbem::sweep::RESULT_COLUMNS.to_vec())?;
    // The most threads a sweep takes, the bound of `rollbem sweep --jobs`.
    m.add("MAX_JOBS", rollbem::sweep::MAX_JOBS)?;
    // contact.csv's columns, in order, from the writer's own list.
    let contact_columns: Vec<&str> = rollbem::output::units::CONTACT_CSV_UNITS.iter().map(|c| c.0).collect();
    m.add("CONTACT_COLUMNS", contact_columns)?;
    m.add_function(wrap_pyfunction!(run, m)?)?;
    m.add_function(wrap_pyfunction!(check, m)?)?;
    m.add_function(wrap_pyfunction!(sweep, m)?)?;
    m.add_function(wrap_pyfunction!(_panic_for_tests, m)?)?;
    Ok(())
}
