//! Command-line interface (DESIGN §5).

use clap::{Parser, Subcommand};
use std::path::PathBuf;

/// rollbem — 2D steady rolling contact of elastic cylinders (half-space or BEM bodies),
/// coupled normal–tangential, Coulomb friction, generalized Newton (González & Abascal 2000).
///
/// Exit codes: 0 solved; 1 bad input (message names the file and key; nothing written);
/// 2 the solver did not converge (summary.json written with converged: false and the
/// residual history).
#[derive(Debug, Parser)]
#[command(name = "rollbem", version, about, long_about)]
pub struct Cli {
    /// What to do.
    #[command(subcommand)]
    pub command: Command,
}

/// The verbs.
#[derive(Debug, Subcommand)]
pub enum Command {
    /// Solve a case: print a summary table and write summary.json, contact.csv, contact.svg.
    ///
    /// Example: rollbem run cases/carter_051.yaml --set contact.friction=0.2
    Run {
        /// Case file (YAML; see cases/README.md for the keys).
        case: PathBuf,
        /// Output folder (default: output.dir of the case, relative to the case file).
        #[arg(long)]
        out: Option<PathBuf>,
        /// Override a case value by its dotted key path, e.g. --set load.tangential.ratio=0.84
        /// or --set contact.grid.elements=81. Repeatable.
        #[arg(long = "set", value_name = "KEY.PATH=VALUE")]
        set: Vec<String>,
    },
    /// Validate a case without solving: print the bodies, materials, Hertz estimates (a, p0),
    /// the grid spacing, the Carter stick-zone estimate and model advice.
    Check {
        /// Case file.
        case: PathBuf,
        /// Override a case value (as for `run`). Repeatable.
        #[arg(long = "set", value_name = "KEY.PATH=VALUE")]
        set: Vec<String>,
    },
}
