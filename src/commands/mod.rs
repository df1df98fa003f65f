//! One file per command.

pub(crate) mod analyse;
pub(crate) mod calibrate;
pub(crate) mod merge;
pub(crate) mod modes;
pub(crate) mod panel;
pub(crate) mod params;
pub(crate) mod run;
pub(crate) mod simulate;
pub(crate) mod sweep;

use std::process::ExitCode;

use crate::cli::Command;

/// Runs one command; the exit status on success (128 + the signal's number for a run
/// stopped by SIGINT, SIGTERM or SIGHUP; 3 for a `--strict` run that ended with warnings).
pub fn run(command: Command) -> anyhow::Result<ExitCode> {
    let done = match command {
        Command::Modes(args) => modes::run(&args),
        Command::Simulate(args) => simulate::run(&args),
        Command::Params(args) => params::run(&args),
        Command::Analyse(args) => analyse::run(&args),
        Command::Run(args) => return run::run(&args),
        Command::Sweep(args) => sweep::run(&args),
        Command::Merge(args) => merge::run(&args),
        Command::Calibrate(args) => calibrate::run(&args),
        Command::Panel(args) => return panel::run(&args),
    };
    done.map(|()| ExitCode::SUCCESS)
}
