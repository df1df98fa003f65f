//! One file per command.

pub(crate) mod analyse;
pub(crate) mod calibrate;
pub(crate) mod fmu;
pub(crate) mod merge;
pub(crate) mod modes;
pub(crate) mod panel;
pub(crate) mod params;
pub(crate) mod run;
pub(crate) mod signal_writer;
pub(crate) mod simulate;
pub(crate) mod sweep;

use std::process::ExitCode;

use crate::cli::CliCommand;

/// Runs one command; the exit status on success (128 + the signal's number for a run
/// stopped by SIGINT, SIGTERM or SIGHUP; 3 for a `--strict` run that ended with warnings).
pub fn run(command: CliCommand) -> anyhow::Result<ExitCode> {
    let done = match command {
        CliCommand::Modes(args) => modes::run(&args),
        CliCommand::Simulate(args) => simulate::run(&args),
        CliCommand::Params(args) => params::run(&args),
        CliCommand::Analyse(args) => analyse::run(&args),
        CliCommand::Run(args) => return run::run(&args),
        CliCommand::Sweep(args) => sweep::run(&args),
        CliCommand::Merge(args) => merge::run(&args),
        CliCommand::Calibrate(args) => calibrate::run(&args),
        CliCommand::Panel(args) => return panel::run(&args),
        CliCommand::Fmu(args) => fmu::run(&args),
    };
    done.map(|()| ExitCode::SUCCESS)
}
