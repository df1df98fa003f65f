//! `testrig`: the virtual test rig's command line.

mod cli;
mod commands;

use clap::Parser;

fn main() -> std::process::ExitCode {
    end_quietly_on_a_closed_pipe();
    let cli = cli::Cli::parse();
    match commands::run(cli.command) {
        Ok(code) => code,
        Err(error) => {
            eprintln!("testrig: {error:#}");
            std::process::ExitCode::FAILURE
        }
    }
}

/// `testrig modes | head` closes stdout early: end as other Unix tools do, by SIGPIPE,
/// instead of Rust's default of ignoring it and panicking in `println!`. Every command
/// prints to stdout only after its files are complete, so nothing recorded is lost.
fn end_quietly_on_a_closed_pipe() {
    // SAFETY: restores the default disposition of one signal before any thread starts.
    unsafe {
        libc::signal(libc::SIGPIPE, libc::SIG_DFL);
    }
}
