//! The runtime of `testrig run`: the paced plant, the instrument stages and the sinks as
//! threads joined by crossbeam channels, and the run's manifest.
//!
//! Files: `testrig run`'s threads: `plant_source.rs` (the paced plant, overruns; a paced
//! wait looks at the stop flag every 50 ms) on `run_plant.rs` (any rig's plant as a run
//! drives it, its block and judged window), `rolling_regime.rs` (the regime and the
//! judge's motion of each full 10 s window once settled, live: "settling" for 15 s after a change of set points), `pacing.rs` (deadlines, lateness
//! histogram), `wiring.rs` (stage and sink threads; a panic in one fails the run by name),
//! `sinks/` (`monitor`, `recorder`, `analyser` with `analyser_live` (commands, the display
//! published), `scope` with `scope_live` (the panel's scope, owned by the storage scope),
//! `measure_clock`), `status.rs` + `console.rs`, `process_usage.rs` (CPU, peak RSS),
//! `manifest.rs`, `threaded_run.rs` (spawns and joins everything), `folder_run.rs` (a run
//! into its folder whole: the earlier run's files removed, the run, the manifest; `run` and
//! Python's `testrig.run`), `sinks/tap.rs` (live runs: the latest block of every signal
//! kept in the status, for Python's `Rig.read`), `stop_signals.rs`, `previous_run.rs` (a
//! rerun removes the earlier run's files: its manifest's, or its journal's when it was
//! killed); `point_judge.rs` the judged motion of each measured point over its settled
//! window (until the set points change, the next measurement or the end), sent to the sinks
//! on a frame and kept for the manifest; `sinks/recorder.rs` low-passes each decimated
//! signal before keeping every M-th sample.

pub(crate) mod console;
pub(crate) mod folder_run;
pub(crate) mod manifest;
pub(crate) mod pacing;
pub(crate) mod plant_source;
pub(crate) mod point_judge;
pub(crate) mod previous_run;
pub(crate) mod process_usage;
pub(crate) mod rolling_regime;
pub(crate) mod run_plant;
pub(crate) mod sinks;
pub(crate) mod status;
pub(crate) mod stop_signals;
pub(crate) mod threaded_run;
pub(crate) mod wiring;

pub use folder_run::{FolderRun, run_into_folder, run_into_folder_with_status};
pub use manifest::{Ending, write_command_manifest, write_manifest};
pub use pacing::{LatenessHistogram, Pace};
pub use previous_run::clear_previous_run;
pub use status::{LatestBlock, SharedStatus, Status};
pub use stop_signals::StopSignals;
pub use threaded_run::{RunOptions, RunResult, run, run_with_status};
