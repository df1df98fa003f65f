//! Scenario files (TOML): what a rehearsal runs, checked with errors at file, line and field.

pub(crate) mod build;
pub(crate) mod chain_toml;
pub(crate) mod read_chain;

pub(crate) mod coverage;
pub(crate) mod overrides;
pub(crate) mod preset_file;
pub(crate) mod read_instrument;
pub(crate) mod read_rig;
pub(crate) mod read_stages;
pub(crate) mod run_plan;
pub(crate) mod scenario_toml;
pub(crate) mod source;
pub(crate) mod values;

pub use build::{CommandLine, build};
pub use coverage::measurement_warnings;
pub use overrides::apply_override;
pub use preset_file::preset_with_overrides;
pub use run_plan::{AnalyserPlan, ChainPlan, Measure, Plan, RecordPlan, ScopePlan};
pub use scenario_toml::Overflow;
pub use source::ScenarioSource;
