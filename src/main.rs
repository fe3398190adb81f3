//! The `rollbem` command-line program.

use anyhow::Result;
use clap::Parser;
use rollbem::cli::{Cli, Command};
use rollbem::error::EXIT_NOT_CONVERGED;
use std::process::ExitCode;

fn main() -> ExitCode {
    let cli = Cli::parse();
    match dispatch(cli) {
        Ok(code) => ExitCode::from(code as u8),
        Err(e) => {
            let code = e.downcast_ref::<rollbem::error::Error>().map_or(1, |e| e.exit_code());
            eprintln!("error: {e}");
            ExitCode::from(code as u8)
        }
    }
}

fn dispatch(cli: Cli) -> Result<i32> {
    match cli.command {
        Command::Run { case, out, set } => {
            let report = rollbem::app::run(&case, &set, out.as_deref())?;
            for notice in &report.summary.notices {
                eprintln!("notice: {notice}");
            }
            println!("rollbem run {}", case.display());
            print!("{}", rollbem::output::render_table(&report.summary, &report.output_dir));
            if report.summary.converged {
                Ok(0)
            } else {
                eprintln!(
                    "error: the solver did not converge in {} iterations (scaled residual {:.3e}); \
                     the residual history is in {}. Try solver.formulation: psi, a different \
                     solver.penalty scale, or more solver.max_iterations.",
                    report.summary.iterations,
                    report.summary.residual,
                    report.output_dir.join("summary.json").display()
                );
                Ok(EXIT_NOT_CONVERGED)
            }
        }
        Command::Check { case, set } => {
            print!("{}", rollbem::app::check_report(&case, &set)?);
            Ok(0)
        }
    }
}
