//! The runtime of `testrig run`: the paced plant, the instrument stages and the sinks as
//! threads joined by crossbeam channels, and the run's manifest.

pub(crate) mod console;
pub(crate) mod folder_run;
pub(crate) mod manifest;
pub(crate) mod pacing;
pub(crate) mod plant_source;
pub(crate) mod point_judge;
pub(crate) mod previous_run;
pub(crate) mod process_usage;
pub(crate) mod rolling_regime;
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
