//! Scenario files (TOML): what a rehearsal runs, checked with errors at file, line and field.

pub mod build;
pub mod chain_file;
pub mod chain_part;

pub mod coverage;
pub mod file;
pub mod instrument_part;
pub mod overrides;
pub mod plan;
pub mod preset_file;
pub mod rig_part;
pub mod source;
pub mod stage_part;
pub mod values;

pub use build::{CommandLine, build};
pub use coverage::measurement_warnings;
pub use file::Overflow;
pub use overrides::apply_override;
pub use plan::{AnalyserPlan, ChainPlan, Measure, Plan, RecordPlan, ScopePlan};
pub use source::ScenarioSource;
