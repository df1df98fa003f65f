//! `testrig`: the virtual test rig's command line.

mod cli;
mod commands;

use clap::Parser;

fn main() -> std::process::ExitCode {
    end_quietly_on_a_closed_pipe();
    fail_writes_beyond_the_file_size_limit();
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

/// Beyond a file-size limit (`ulimit -f`) the kernel kills the process by SIGXFSZ unless
/// it is ignored; ignored, the write fails (EFBIG) like a full disk, and the run ends as
/// it does then: the error names the file, the manifest records the failure, and every
/// file already complete keeps its final name.
fn fail_writes_beyond_the_file_size_limit() {
    // SAFETY: sets the disposition of one signal before any thread starts.
    unsafe {
        libc::signal(libc::SIGXFSZ, libc::SIG_IGN);
    }
}
