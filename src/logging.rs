//! What the program says while it works: messages through the `log` facade, printed on stderr by
//! [`Logger`], and a progress line for long runs.
//!
//! The library only calls `log::warn!`, `log::info!`, `log::debug!`; without a logger installed
//! (a library user, the tests) they cost a comparison. Messages with the target [`PROGRESS`] say
//! where a run is (the stage, each Newton step with its residual): they appear only when the
//! program asked for them ([`init`]) and only once the run has taken longer than a second
//! ([`PROGRESS_AFTER_ENV`] changes that), so a quick run prints nothing but its table. In a
//! terminal they replace each other on one line (an indicatif spinner, cleared at the end);
//! otherwise (a log file, CI) they are plain lines, at most one a second. With `-v` every
//! message of level info and every progress message is printed at once as its own line, with the
//! time since the start.
//!
//! The logger is ours (60 lines) rather than env_logger's or simplelog's: its messages must
//! share stderr with the spinner (each is printed with the spinner suspended, or it would tear
//! the line), and it prints in the program's own style (`warning: …`, like `error: …` and
//! `notice: …`).

use indicatif::{ProgressBar, ProgressDrawTarget, ProgressStyle};
use log::{Level, LevelFilter, Log, Metadata, Record};
use std::io::IsTerminal;
use std::sync::{Mutex, OnceLock};
use std::time::{Duration, Instant};

/// Target of the progress messages: `log::info!(target: PROGRESS, …)`.
pub const PROGRESS: &str = "rollbem::progress";

/// Environment variable: seconds after which progress is shown (default 1).
pub const PROGRESS_AFTER_ENV: &str = "ROLLBEM_PROGRESS_AFTER";

/// How much the program says.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Verbosity {
    /// −1 quiet (errors only), 0 default (warnings), 1 info (-v), 2 debug (-vv), 3 trace.
    pub level: i8,
    /// Whether this command shows the progress of its run (a single run, not a sweep).
    pub progress: bool,
}

impl Verbosity {
    /// The level of the non-progress messages printed.
    pub fn filter(self) -> LevelFilter {
        match self.level {
            i8::MIN..=-1 => LevelFilter::Error,
            0 => LevelFilter::Warn,
            1 => LevelFilter::Info,
            2 => LevelFilter::Debug,
            _ => LevelFilter::Trace,
        }
    }
}

/// The progress line's state.
#[derive(Default)]
struct ProgressLine {
    /// The latest progress message not yet shown.
    pending: Option<String>,
    /// The delay has passed: progress is shown.
    live: bool,
    /// The spinner, in a terminal.
    bar: Option<ProgressBar>,
    /// When the last plain progress line was printed.
    last_line: Option<Instant>,
    /// The run is over: nothing more is shown.
    finished: bool,
}

/// The logger of the `rollbem` program (module docs).
pub struct Logger {
    verbosity: Verbosity,
    start: Instant,
    terminal: bool,
    line: Mutex<ProgressLine>,
}

static LOGGER: OnceLock<Logger> = OnceLock::new();

/// Installs the logger for the process (once; later calls change nothing) and, when progress
/// is asked for, starts the timer that reveals it.
pub fn init(verbosity: Verbosity) {
    let logger = LOGGER.get_or_init(|| Logger {
        verbosity,
        start: Instant::now(),
        terminal: std::io::stderr().is_terminal(),
        line: Mutex::new(ProgressLine::default()),
    });
    if log::set_logger(logger).is_err() {
        return;
    }
    let progress = verbosity.progress && verbosity.level >= 0;
    let max = if progress {
        verbosity.filter().max(LevelFilter::Info)
    } else {
        verbosity.filter()
    };
    log::set_max_level(max);
    if progress && verbosity.level < 1 {
        let delay = std::env::var(PROGRESS_AFTER_ENV)
            .ok()
            .and_then(|s| s.parse::<f64>().ok())
            .filter(|s| s.is_finite() && *s >= 0.0)
            .unwrap_or(1.0);
        if delay == 0.0 {
            // At once, not from a thread that a quick run may finish before it is scheduled.
            logger.go_live();
        } else {
            std::thread::spawn(move || {
                std::thread::sleep(Duration::from_secs_f64(delay));
                logger.go_live();
            });
        }
    }
}

/// Ends the progress line (clears the spinner) before the results are printed.
pub fn finish() {
    if let Some(logger) = LOGGER.get() {
        let mut line = logger.lock();
        line.finished = true;
        if let Some(bar) = line.bar.take() {
            bar.finish_and_clear();
        }
    }
}

impl Logger {
    fn lock(&self) -> std::sync::MutexGuard<'_, ProgressLine> {
        self.line.lock().unwrap_or_else(|e| e.into_inner())
    }

    /// The delay has passed: show the pending progress message, and the later ones.
    fn go_live(&self) {
        let mut line = self.lock();
        if line.finished {
            return;
        }
        line.live = true;
        if self.terminal {
            let bar = ProgressBar::with_draw_target(None, ProgressDrawTarget::stderr());
            bar.set_style(
                ProgressStyle::with_template("{spinner} {elapsed:>4} {wide_msg}")
                    .unwrap_or_else(|_| ProgressStyle::default_spinner()),
            );
            bar.enable_steady_tick(Duration::from_millis(120));
            if let Some(msg) = line.pending.take() {
                bar.set_message(msg);
            }
            line.bar = Some(bar);
        } else if let Some(msg) = line.pending.take() {
            self.plain_progress(&mut line, &msg);
        }
    }

    fn plain_progress(&self, line: &mut ProgressLine, msg: &str) {
        eprintln!("progress: [{:.1} s] {msg}", self.start.elapsed().as_secs_f64());
        line.last_line = Some(Instant::now());
    }

    fn progress(&self, msg: String) {
        let mut line = self.lock();
        if line.finished {
            return;
        }
        if !line.live {
            line.pending = Some(msg);
        } else if let Some(bar) = &line.bar {
            bar.set_message(msg);
        } else if line.last_line.is_none_or(|t| t.elapsed() >= Duration::from_secs(1)) {
            self.plain_progress(&mut line, &msg);
        } else {
            line.pending = Some(msg);
        }
    }

    fn print(&self, record: &Record) {
        let text = match record.level() {
            Level::Error => format!("error: {}", record.args()),
            Level::Warn => format!("warning: {}", record.args()),
            level if record.target() == PROGRESS => format!(
                "{}: [{:.3} s] {}",
                level.as_str().to_lowercase(),
                self.start.elapsed().as_secs_f64(),
                record.args()
            ),
            level => format!("{}: {}", level.as_str().to_lowercase(), record.args()),
        };
        match &self.lock().bar {
            Some(bar) => bar.suspend(|| eprintln!("{text}")),
            None => eprintln!("{text}"),
        }
    }
}

impl Log for Logger {
    fn enabled(&self, metadata: &Metadata) -> bool {
        metadata.level() <= self.verbosity.filter()
            || (metadata.target() == PROGRESS && self.verbosity.progress && self.verbosity.level >= 0)
    }

    fn log(&self, record: &Record) {
        if !self.enabled(record.metadata()) {
            return;
        }
        let verbose = record.level() <= self.verbosity.filter();
        if record.target() == PROGRESS && !verbose {
            self.progress(record.args().to_string());
        } else {
            self.print(record);
        }
    }

    fn flush(&self) {}
}
