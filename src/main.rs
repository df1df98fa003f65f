//! `testrig`: the virtual test rig's command line.

mod cli;
mod commands;
mod rig_setup;
mod wav_input;

use clap::Parser;

fn main() -> std::process::ExitCode {
    let cli = cli::Cli::parse();
    match commands::run(cli.command) {
        Ok(code) => code,
        Err(error) => {
            eprintln!("testrig: {error:#}");
            std::process::ExitCode::FAILURE
        }
    }
}
