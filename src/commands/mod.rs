//! One file per command.

mod analyse;
mod modes;
mod params;
mod simulate;

use crate::cli::Command;

/// Runs one command.
pub fn run(command: Command) -> anyhow::Result<()> {
    match command {
        Command::Modes(args) => modes::run(&args),
        Command::Simulate(args) => simulate::run(&args),
        Command::Params(args) => params::run(&args),
        Command::Analyse(args) => analyse::run(&args),
    }
}
