//! Sweeps: a grid of cases (speed, load, backlash, any parameter), each run at fixed set
//! points through the chain and the analyser, in parallel, shardable and resumable.
//!
//! Files: `sweep_toml.rs` (grid, case timing, chain, analyser and recordings as in a
//! scenario), `grid.rs` (the grid expanded into cases; each case's start is a
//! `rig::Approach`), `case_rig.rs` (a case's rig: a preset's parameters, or a rig file's with its
//! faults; either run as a rig),
//! `sequence.rs` (`Sequence`: each point on its own, or up and down;
//! `Direction`), `case_result.rs` (a case's result with its fault labels, timing and instruments), `case_run.rs` (one
//! case: its rig's plant settled, the chain inline into ADC and analyser, regime and the
//! judge's motion), `measured_condition.rs` (the indicators of the
//! signal as the chain measures it), `case_recording.rs` (a case's WAV/CSV/UFF58 in
//! `recordings/`), `series.rs` (the lab's run: one plant per load
//! stepping the speeds up and back down; a series is one unit of work), `knock.rs` (the
//! seeded knock), `knocked.rs` (a point and its knocked repeats on one plant), `held_motions.rs` (the motions each point
//! held, by approach), `motion_lines.rs` (them in words for any rig's report), `lines.rs` (order
//! lines over their local floor), `table.rs` (a JSON per case, `cases.csv`), `labels.rs`
//! (`labels.csv`: each case's recordings, fault, point, motion and indicators), `meta.rs`
//! (`sweep.json`), `shard.rs` (`--shard`, SLURM arrays), `runner.rs` (rayon pool, resume,
//! assembly of table and plots, also for `merge`), `thesis.rs` (what the thesis saw at each
//! point and how a case is held against it), `facts.rs` (the thesis's facts against the
//! judged motion), `report.rs` (`report.md`: the 1983 rig's healthy cases held against the
//! thesis, a preset's or a rig file's that `reproduces` it; hysteresis, where the motor
//! cannot hold the set speed), `case_table.rs` (what a rig file's sweep adds: its case by
//! case table, and the summary where no thesis holds it)

pub(crate) mod case_recording;
pub(crate) mod case_result;
pub(crate) mod case_rig;
pub(crate) mod case_run;
pub(crate) mod case_table;
pub(crate) mod facts;
pub(crate) mod grid;
pub(crate) mod held_motions;
pub(crate) mod knock;
pub(crate) mod knocked;
pub(crate) mod labels;
pub(crate) mod lines;
pub(crate) mod measured_condition;
pub(crate) mod meta;
pub(crate) mod motion_lines;
pub(crate) mod report;
pub(crate) mod runner;
pub(crate) mod sequence;
pub(crate) mod series;
pub(crate) mod shard;
pub(crate) mod sweep_toml;
pub(crate) mod table;
pub(crate) mod thesis;

pub use case_result::CaseResult;
pub use case_result::FaultLabel;
pub use case_rig::CaseRig;
pub use case_run::run_case;
pub use grid::{Case, SweepPlan, build_sweep};
pub use meta::{SweepMeta, fingerprint, read_meta, sweep_meta};
pub use runner::{Assembled, SweepOptions, SweepOutcome, assemble, missing_cases, run_sweep};
pub use sequence::{Direction, Sequence};
pub use shard::Shard;
pub use sweep_toml::SweepFile;
