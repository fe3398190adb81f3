//! The `rollbem` command-line program.

use anyhow::Result;
use clap::Parser;
use rollbem::cli::{Cli, Command, StudyCommand};
use rollbem::error::{EXIT_BAD_INPUT, EXIT_INTERNAL_ERROR, EXIT_NOT_CONVERGED};
use std::path::PathBuf;
use std::process::ExitCode;

fn main() -> ExitCode {
    survive_file_size_limit();
    let cli = match Cli::try_parse() {
        Ok(cli) => cli,
        Err(e) => return usage_error(&e),
    };
    let case = cli.case_path().map(|p| p.display().to_string());
    rollbem::logging::init(cli.verbosity());
    install_panic_hook();
    // A panic is a bug: it must not pass for a result. Writers clean up as the panic unwinds
    // (temporary folders, locks), so nothing is written.
    let outcome = std::panic::catch_unwind(std::panic::AssertUnwindSafe(|| dispatch(cli)));
    rollbem::logging::finish();
    match outcome {
        Ok(Ok(code)) => ExitCode::from(code as u8),
        Ok(Err(e)) => {
            let code = e.downcast_ref::<rollbem::error::Error>().map_or(1, |e| e.exit_code());
            eprintln!("error: {e}");
            ExitCode::from(code as u8)
        }
        Err(_) => {
            let what = PANIC.lock().ok().and_then(|mut p| p.take()).unwrap_or_default();
            eprintln!(
                "error: internal error — please report it (with the case file {} and this message): {what}",
                case.as_deref().unwrap_or("(none)")
            );
            ExitCode::from(EXIT_INTERNAL_ERROR as u8)
        }
    }
}

/// Makes a file-size limit (`ulimit -f`) an error, not death: a write past the limit raises
/// SIGXFSZ, whose default action kills the process at once (exit 153, no message, a temporary
/// folder and the lock left). With a handler installed (signal-hook's safe registration of a
/// flag, which nothing reads) the write fails with EFBIG instead, "File too large": the writer
/// reports it, removes its temporary folder and exits 1.
#[cfg(unix)]
fn survive_file_size_limit() {
    let flag = std::sync::Arc::new(std::sync::atomic::AtomicBool::new(false));
    if let Err(e) = signal_hook::flag::register(signal_hook::consts::SIGXFSZ, flag) {
        eprintln!("warning: cannot catch SIGXFSZ ({e}): a file-size limit (ulimit -f) will kill rollbem");
    }
}

/// Other platforms have no SIGXFSZ.
#[cfg(not(unix))]
fn survive_file_size_limit() {}

/// The default folder of a sweep or study: the case's output folder with `_<what>` appended.
fn default_output_dir(case: &rollbem::case::LoadedCase, what: &str) -> PathBuf {
    let dir = case.output_dir();
    let name = dir
        .file_name()
        .map_or(what.into(), |n| format!("{}_{what}", n.to_string_lossy()));
    dir.with_file_name(name)
}

/// Help and version go to stdout with exit code 0; any other command-line error is a usage
/// error: clap's message on stderr, exit code 1 (clap's own 2 means "not converged" here).
fn usage_error(e: &clap::Error) -> ExitCode {
    use clap::error::ErrorKind;
    let _ = e.print();
    match e.kind() {
        ErrorKind::DisplayHelp | ErrorKind::DisplayVersion => ExitCode::SUCCESS,
        _ => ExitCode::from(EXIT_BAD_INPUT as u8),
    }
}

/// The message and place of the last panic, for the internal-error report.
static PANIC: std::sync::Mutex<Option<String>> = std::sync::Mutex::new(None);

/// Records a panic's message and location instead of printing Rust's default report; the
/// backtrace follows when RUST_BACKTRACE asks for it.
fn install_panic_hook() {
    std::panic::set_hook(Box::new(|info| {
        let message = info
            .payload()
            .downcast_ref::<&str>()
            .map(|s| s.to_string())
            .or_else(|| info.payload().downcast_ref::<String>().cloned())
            .unwrap_or_else(|| "panic".into());
        let place = info
            .location()
            .map_or(String::new(), |l| format!(" at {}:{}", l.file(), l.line()));
        let backtrace = std::backtrace::Backtrace::capture();
        let trace = match backtrace.status() {
            std::backtrace::BacktraceStatus::Captured => format!("\n{backtrace}"),
            _ => String::new(),
        };
        if let Ok(mut p) = PANIC.lock() {
            *p = Some(format!("{message}{place}{trace}"));
        }
    }));
}

/// The restarts the default method needed, as one warning: a converged run that needed them
/// took longer than it should, and a different `solver.*` setting may avoid them.
fn warn_restarts(s: &rollbem::output::Summary) {
    // A falling law's fixed point that did not settle is no restart: the error says it.
    let fallbacks: Vec<&str> = s
        .solver
        .fallbacks
        .iter()
        .map(String::as_str)
        .filter(|f| rollbem::contact::falling::is_restart(f))
        .collect();
    if fallbacks.is_empty() {
        return;
    }
    let outcome = if s.converged {
        "converged"
    } else {
        "still did not converge"
    };
    log::warn!(
        "the Newton method stalled and restarted {} time{} ({}); it {outcome} after {} iterations in all",
        fallbacks.len(),
        if fallbacks.len() == 1 { "" } else { "s" },
        fallbacks.join(", "),
        s.iterations
    );
}

/// What to tell the user when a run ends without converging: whether the iteration budget ran
/// out (then more `solver.max_iterations` may help) or the residual stopped improving (then it
/// will not), and where the history is.
fn not_converged_message(report: &rollbem::app::RunReport) -> String {
    use rollbem::contact::stall::{at_roundoff, roundoff_advice};
    let (summary, output_dir) = (&report.summary, &report.output_dir);
    if let Some(unsettled) = summary
        .solver
        .fallbacks
        .iter()
        .find(|f| f.starts_with(rollbem::contact::falling::UNSETTLED))
    {
        return format!(
            "{unsettled}: each solve with the nodal mu frozen converged (scaled residual {:.3e}), \
             but the law falls too steeply over this contact's slip velocities for the fixed \
             point on the nodal mu (docs/friction.md, \"When it does not settle\"): a smaller \
             creepage or load, a smaller difference contact.friction - \
             contact.falling_friction.kinetic or a larger contact.falling_friction.slip_velocity \
             settles. The history is in {}.",
            summary.residual,
            output_dir.join("summary.json").display()
        );
    }
    if at_roundoff(summary.residual, summary.grid.nodes) {
        let history = summary.solver.history.iter().map(|h| h.residual);
        let smallest = history.fold(summary.residual, f64::min);
        return format!(
            "the solver did not converge in {} iterations (scaled residual {:.3e}); {}. The residual \
             history is in {}.",
            summary.iterations,
            summary.residual,
            roundoff_advice(smallest, Some(report.tolerance)),
            output_dir.join("summary.json").display()
        );
    }
    let cause = if summary.iterations >= report.max_iterations {
        "the iteration budget ran out: give more solver.max_iterations (gauss_seidel counts sweeps and \
         needs thousands), or try"
    } else {
        "the residual stopped improving (more iterations will not help): try"
    };
    format!(
        "the solver did not converge in {} iterations (scaled residual {:.3e}); {cause} \
         solver.method: newton (the default), solver.formulation: psi, a different solver.penalty \
         scale, or a finer contact grid. The residual history is in {}.",
        summary.iterations,
        summary.residual,
        output_dir.join("summary.json").display()
    )
}

fn dispatch(cli: Cli) -> Result<i32> {
    let quiet = cli.quiet;
    match cli.command {
        Command::Run { case, out, set, force } => run_case(&case, out.as_deref(), &set, force, quiet),
        Command::Sweep {
            case,
            vary,
            set,
            out,
            shard,
            merge,
            resume,
            per_run_files,
            jobs,
        } => sweep(
            case,
            &vary,
            &set,
            out,
            shard.as_deref(),
            &merge,
            SweepFlags {
                resume,
                per_run_files,
                jobs,
            },
        ),
        Command::Validate => {
            let checks = rollbem::reference::run()?;
            print!("{}", rollbem::reference::render(&checks));
            Ok(if checks.iter().all(|c| c.passed()) {
                0
            } else {
                EXIT_NOT_CONVERGED
            })
        }
        Command::Study { study } => run_study(study),
        Command::Mesh { case, out, set, force } => {
            let out = match out {
                Some(o) => o,
                None => default_output_dir(&rollbem::case::load(&case, &set)?, "mesh"),
            };
            for file in rollbem::app::write_meshes(&case, &set, &out, force)? {
                println!("wrote {}", file.display());
            }
            Ok(0)
        }
        Command::Check {
            case,
            set,
            tolerance,
            estimate,
        } => {
            if !(tolerance > 0.0 && tolerance.is_finite()) {
                anyhow::bail!("--tolerance must be a positive fraction, e.g. 0.01 for 1 % (value = {tolerance})");
            }
            let report = match estimate {
                true => rollbem::check::check_report_estimated(&case, &set, tolerance)?,
                false => rollbem::check::check_report(&case, &set, tolerance)?,
            };
            print!("{report}");
            Ok(0)
        }
    }
}

/// `rollbem run`: solves a case, writes its folder and prints its table.
fn run_case(
    case: &std::path::Path,
    out: Option<&std::path::Path>,
    set: &[String],
    force: bool,
    quiet: bool,
) -> Result<i32> {
    let report = rollbem::app::run_with(case, set, out, force)?;
    rollbem::logging::finish();
    // --quiet says nothing on stderr but errors, as its help promises: the notices and the
    // warnings that qualify the result stay in summary.json (`notices`, `warnings`).
    if !quiet {
        for notice in &report.summary.notices {
            eprintln!("notice: {notice}");
        }
        for warning in &report.summary.warnings {
            eprintln!("warning: {warning}");
        }
        warn_restarts(&report.summary);
    }
    println!("rollbem run {}", case.display());
    print!("{}", rollbem::output::render_table(&report.summary, &report.output_dir));
    if let Some(t) = &report.summary.transient {
        print_transient(t, &report.summary);
        if let Some(why) = &t.stopped {
            eprintln!("error: the history stopped at {why}; the steps before it are written");
            return Ok(EXIT_NOT_CONVERGED);
        }
    }
    if report.summary.converged {
        Ok(0)
    } else {
        eprintln!("error: {}", not_converged_message(&report));
        Ok(EXIT_NOT_CONVERGED)
    }
}

/// The console lines of a transient run: its steps, iterations and last step (the table above
/// shows the last step's contact).
fn print_transient(t: &rollbem::output::transient::TransientSummary, s: &rollbem::output::Summary) {
    let unit = |key: &str| s.units.get(key).map_or("", String::as_str);
    println!(
        "transient: {} rolling steps of {:.6} {} (rolled {:.6} {}), {} Newton iterations ({:.2} a rolling step)",
        t.steps,
        t.step,
        unit("transient.step"),
        t.rolled,
        unit("transient.rolled"),
        t.iterations,
        t.mean_iterations
    );
    let settled = match t.settled_distance {
        Some(d) => format!("within 1e-3 of the last step from {d:.6} {}", unit("transient.rolled")),
        None => "not settled".into(),
    };
    println!(
        "last step: P {:.6} Q {:.6} {}, creepage {:.6e}; change over the step {:.1e} mu*p_max ({}); {settled}",
        s.normal_force,
        s.tangential_force,
        unit("normal_force"),
        s.creep,
        t.change,
        if t.steady { "steady" } else { "not yet steady" }
    );
}

/// `rollbem sweep`'s switches: `--resume` and `--per-run-files`.
struct SweepFlags {
    resume: bool,
    per_run_files: bool,
    /// `--jobs` (0: the global pool, one thread per core or `RAYON_NUM_THREADS`).
    jobs: usize,
}

/// `rollbem sweep`: the runs of a sweep (or a shard of it), or the merge of shards.
fn sweep(
    case: Option<PathBuf>,
    vary: &[String],
    set: &[String],
    out: Option<PathBuf>,
    shard: Option<&str>,
    merge: &[PathBuf],
    flags: SweepFlags,
) -> Result<i32> {
    let SweepFlags {
        resume,
        per_run_files,
        jobs,
    } = flags;
    let cores = std::thread::available_parallelism().map_or(1, |n| n.get());
    let (threads, capped) = rollbem::sweep::threads_for(jobs, cores)?;
    if let Some(warning) = capped {
        eprintln!("warning: {warning}");
    }
    if !merge.is_empty() {
        let out = out.unwrap_or_else(|| merge[0].clone());
        let path = rollbem::sweep::merge(merge, &out)?;
        println!("merged {} folder(s) into {}", merge.len(), path.display());
        return Ok(0);
    }
    let case = case.expect("clap requires CASE without --merge");
    let varies = vary
        .iter()
        .map(|v| rollbem::sweep::Vary::parse(v))
        .collect::<Result<Vec<_>, _>>()?;
    let shard = shard.map(rollbem::sweep::Shard::parse).transpose()?;
    let out = match out {
        Some(o) => o,
        None => default_output_dir(&rollbem::case::load(&case, set)?, "sweep"),
    };
    // The runs' chains split over the pool's threads (rayon::current_num_threads).
    let solve = || rollbem::sweep::run(&case, set, &varies, shard, &out, resume, per_run_files);
    let report = if jobs == 0 {
        solve()?
    } else {
        rayon::ThreadPoolBuilder::new()
            .num_threads(threads)
            .build()
            .map_err(|e| rollbem::error::Error::Sweep {
                message: format!("cannot start {threads} threads: {e}"),
            })?
            .install(solve)?
    };
    let failed: Vec<&rollbem::sweep::RunRow> = report.rows.iter().filter(|r| r.status != "ok").collect();
    let kept = if report.resumed > 0 {
        format!(" ({} kept from the interrupted sweep)", report.resumed)
    } else {
        String::new()
    };
    println!(
        "sweep: {} of {} runs here{kept}, {} ok, {} failed or not converged; table {}",
        report.rows.len(),
        report.total_runs,
        report.rows.len() - failed.len(),
        failed.len(),
        report.csv.display()
    );
    for r in &failed {
        eprintln!("  {} {}: {} {}", r.folder, r.values.join(" "), r.status, r.message);
    }
    Ok(if report.rows.iter().any(|r| r.internal_error) {
        EXIT_INTERNAL_ERROR
    } else if failed.is_empty() {
        0
    } else {
        EXIT_NOT_CONVERGED
    })
}

/// `rollbem study`: the speed-accuracy study or the stability map.
fn run_study(study: StudyCommand) -> Result<i32> {
    match study {
        StudyCommand::Accuracy {
            case,
            out,
            set,
            quick,
            ladder,
            models,
            tolerances,
            reference_curve,
            shaft_ratio,
            jobs,
        } => {
            use rollbem::study::accuracy::{self, AccuracyOptions, SceneModel};
            let loaded = rollbem::case::load(&case, &set)?;
            let mut options = AccuracyOptions {
                shaft_ratio,
                jobs,
                ..AccuracyOptions::default()
            };
            if quick {
                options.ladder = AccuracyOptions::quick_ladder();
                options.tolerances = AccuracyOptions::quick_tolerances();
            } else if !ladder.is_empty() {
                options.ladder = ladder;
            }
            if !tolerances.is_empty() {
                options.tolerances = tolerances;
            }
            if let Some(path) = &reference_curve {
                options.reference_curve = Some(accuracy::read_reference_curve(path)?);
            }
            if !models.is_empty() {
                options.models = models
                    .iter()
                    .map(|m| {
                        SceneModel::parse(m).ok_or_else(|| {
                            anyhow::anyhow!(
                                "--models: unknown model `{m}`; choose from half_space, half_space_block, true_geometry, half_space_adaptive"
                            )
                        })
                    })
                    .collect::<Result<_>>()?;
            }
            let out = out.unwrap_or_else(|| default_output_dir(&loaded, "accuracy"));
            // Lock and check the output folder before the study runs.
            let _claim = rollbem::output::folder::Claim::acquire(
                &out,
                rollbem::output::folder::Kind::StudyAccuracy,
                rollbem::output::folder::Access::Exclusive,
            )?;
            let report = accuracy::run(&loaded, &options, true)?;
            accuracy::write(&out, &report, &loaded.case.title)?;
            print!("{}", accuracy::render(&report));
            println!("  results                {}", out.display());
            Ok(if report.rows.iter().all(|r| r.converged) {
                0
            } else {
                EXIT_NOT_CONVERGED
            })
        }
        StudyCommand::Shakedown { case, out, set, vary } => {
            let out = match out {
                Some(o) => o,
                None => default_output_dir(&rollbem::case::load(&case, &set)?, "shakedown"),
            };
            let study = rollbem::study::shakedown::run(&case, &set, vary.as_deref(), &out)?;
            print!("{}", rollbem::study::shakedown::render_summary(&study));
            println!("results in {}", study.dir.display());
            Ok(0)
        }
        StudyCommand::Stability { case, quick, out, set } => {
            let out = match out {
                Some(o) => o,
                None => default_output_dir(&rollbem::case::load(&case, &set)?, "stability"),
            };
            let preset = if quick {
                rollbem::study::stability::Preset::Quick
            } else {
                rollbem::study::stability::Preset::Default
            };
            let report = rollbem::study::stability::run(&case, &set, preset, &out)?;
            print!("{}", rollbem::study::stability::render_summary(&report));
            println!("results in {}", report.dir.display());
            let failures = report.default_failures();
            for c in &failures {
                let (x, y) = report.coordinates(c);
                eprintln!(
                    "  default method failed: {} at ({x}, {y}): {} {}",
                    report.slices[c.slice].name,
                    c.status.name(),
                    c.message
                );
            }
            Ok(if failures.is_empty() { 0 } else { EXIT_NOT_CONVERGED })
        }
    }
}
