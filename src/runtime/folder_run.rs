//! A scenario run into its output folder, whole: the earlier run's files removed, the
//! run, how it ended, its manifest. The one path of `testrig run` and of the Python
//! package's `testrig.run`.

use std::path::Path;

use super::manifest::{Ending, write_manifest};
use super::previous_run::clear_previous_run;
use super::status::SharedStatus;
use super::threaded_run::{RunOptions, RunResult, run_with_status};
use crate::scenario::Plan;

/// What a run into a folder did.
#[derive(Debug)]
pub struct FolderRun {
    /// The run's report.
    pub result: RunResult,
    /// How it ended (as its manifest says).
    pub ending: Ending,
    /// Files of an earlier run removed from the folder first.
    pub removed: usize,
}

/// Runs `plan` (read from `scenario_path`) into `options.out`: the earlier run's files
/// removed, then the run, then `manifest.json`.
pub fn run_into_folder(
    scenario_path: &Path,
    plan: &Plan,
    options: &RunOptions,
) -> anyhow::Result<FolderRun> {
    run_into_folder_with_status(scenario_path, plan, options, SharedStatus::default())
}

/// As [`run_into_folder`], the rack's readings and displays kept in `status` (a live rig
/// reads it).
pub fn run_into_folder_with_status(
    scenario_path: &Path,
    plan: &Plan,
    options: &RunOptions,
    status: SharedStatus,
) -> anyhow::Result<FolderRun> {
    let removed = clear_previous_run(&options.out, &plan.name, options.replace)?;
    let result = run_with_status(plan, options, status)?;
    let ending = match (!result.failures().is_empty(), result.stopped_early) {
        (true, _) => Ending::Failed,
        (false, true) => Ending::Interrupted,
        (false, false) => Ending::Completed,
    };
    write_manifest(
        &options.out,
        scenario_path,
        plan,
        options.pace,
        &result,
        ending,
    )?;
    Ok(FolderRun {
        result,
        ending,
        removed,
    })
}
