//! Sweeps: a grid of cases (speed, load, backlash, any parameter), each run at fixed set
//! points through the chain and the analyser, in parallel, shardable and resumable.

pub mod approach;
pub mod case;
pub mod facts;
pub mod file;
pub mod lines;
pub mod plan;
pub mod report;
pub mod run;
pub mod sequence;
pub mod shard;
pub mod table;

pub use approach::Approach;
pub use case::{CaseResult, run_case};
pub use plan::{Case, SweepPlan, build_sweep};
pub use run::{Assembled, SweepMeta, SweepOptions, SweepOutcome, assemble, read_meta, run_sweep};
pub use sequence::{Direction, Sequence};
pub use shard::Shard;
