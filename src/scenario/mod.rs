//! Scenario files (TOML): what a rehearsal runs, checked with errors at file, line and field.
//!
//! Files: scenario files (TOML) to a checked `Plan`, errors at file:line:column:
//! `scenario_toml.rs` and `chain_toml.rs` the schema (serde, unknown keys rejected, spans
//! kept; `chain_toml.rs` the `[chain.*]` and `[analyser]` tables sweeps share); `values.rs`
//! checked numbers (`NumberError`); `source.rs` the text and its errors (a line written by
//! `--set` names the `--set`); `text_overrides.rs` `--set KEY=VALUE` as an edit of the text;
//! `read_rig.rs` (preset, backlash, overrides, schedule, survey, measurements),
//! `read_chain.rs` (the standard chain, scope, analyser, recordings), `read_stages.rs` (the
//! standard table plus the file's `[[chain.stage]]`s, each fault at its line),
//! `read_instrument.rs` (a filter's or meter's settings from its table); `preset_file.rs`
//! presets from files and `preset_with_overrides` (every command's `--preset` and `--set`);
//! `builtin_rigs.rs` presets that are rig files, built in; `read_rig_file.rs` a rig file
//! to a checked `rig::RigTopology`, `rig_overrides.rs` its values set by path, `read_rig_mesh.rs` its meshes, `read_faults.rs` the faults of meshes, stages and sweeps, `read_rig_planetary.rs` its planetary stages, bearings in the plane and shafts to the frame, `rig_fault_place.rs` where a check's fault lies in it; `run_plan.rs` the result; `build.rs` it all together; `coverage.rs` whether each
//! measurement fits the run

pub(crate) mod build;
pub(crate) mod builtin_rigs;
pub(crate) mod chain_toml;
pub(crate) mod read_chain;

pub(crate) mod coverage;
pub(crate) mod plan_rig;
pub(crate) mod preset_file;
pub(crate) mod preset_rig;
pub(crate) mod read_faults;
pub(crate) mod read_instrument;
pub(crate) mod read_rig;
pub(crate) mod read_rig_file;
pub(crate) mod read_rig_mesh;
pub(crate) mod read_rig_planetary;
pub(crate) mod read_stages;
pub(crate) mod rig_chain;
pub(crate) mod rig_fault_place;
pub(crate) mod rig_file_toml;
pub(crate) mod rig_overrides;
pub(crate) mod run_plan;
pub(crate) mod scenario_toml;
pub(crate) mod source;
pub(crate) mod text_overrides;
pub(crate) mod values;

pub use build::{CommandLine, build};
pub use builtin_rigs::preset_rig_source;
pub use coverage::measurement_warnings;
pub use preset_file::preset_with_overrides;
pub use preset_rig::{command_rig, is_thesis_name, preset_rig_with_overrides};
pub use read_rig_file::{read_rig_file, rig_topology};
pub use rig_overrides::{rig_with_overrides, source_rig_with_overrides};
pub use run_plan::{AnalyserPlan, ChainPlan, Measure, Plan, PlanRig, RecordPlan, ScopePlan};
pub use scenario_toml::Overflow;
pub use source::ScenarioSource;
pub use text_overrides::apply_override;
