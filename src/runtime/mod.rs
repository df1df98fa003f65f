//! The runtime of `testrig run`: the paced plant, the instrument stages and the sinks as
//! threads joined by crossbeam channels, and the run's manifest.

pub mod console;
pub mod manifest;
pub mod pacing;
pub mod plant_source;
pub mod previous_run;
pub mod process_usage;
pub mod rolling_regime;
pub mod run;
pub mod sinks;
pub mod status;
pub mod stop_signals;
pub mod wiring;

pub use manifest::write_manifest;
pub use pacing::Pace;
pub use run::{RunOptions, RunResult, run};
pub use stop_signals::StopSignals;
