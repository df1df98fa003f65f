//! Sweeps: a grid of cases (speed, load, backlash, any parameter), each run at fixed set
//! points through the chain and the analyser, in parallel, shardable and resumable.

pub(crate) mod approach;
pub(crate) mod case;
pub(crate) mod facts;
pub(crate) mod grid;
pub(crate) mod lines;
pub(crate) mod meta;
pub(crate) mod report;
pub(crate) mod runner;
pub(crate) mod sequence;
pub(crate) mod series;
pub(crate) mod shard;
pub(crate) mod sweep_toml;
pub(crate) mod table;
pub(crate) mod thesis;

pub use approach::Approach;
pub use case::{CaseResult, run_case};
pub use grid::{Case, SweepPlan, build_sweep};
pub use meta::{SweepMeta, fingerprint, read_meta, sweep_meta};
pub use runner::{Assembled, SweepOptions, SweepOutcome, assemble, missing_cases, run_sweep};
pub use sequence::{Direction, Sequence};
pub use shard::Shard;
pub use sweep_toml::SweepFile;
