//! Scenario files (TOML): what a rehearsal runs, checked with errors at file, line and field.

pub(crate) mod build;
pub(crate) mod chain_file;
pub(crate) mod chain_part;

pub(crate) mod coverage;
pub(crate) mod file;
pub(crate) mod instrument_part;
pub(crate) mod overrides;
pub(crate) mod plan;
pub(crate) mod preset_file;
pub(crate) mod rig_part;
pub(crate) mod source;
pub(crate) mod stage_part;
pub(crate) mod values;

pub use build::{CommandLine, build};
pub use coverage::measurement_warnings;
pub use file::Overflow;
pub use overrides::apply_override;
pub use plan::{AnalyserPlan, ChainPlan, Measure, Plan, RecordPlan, ScopePlan};
pub use preset_file::preset_with_overrides;
pub use source::ScenarioSource;
