//! Sweeps: a grid of cases (speed, load, backlash, any parameter), each run at fixed set
//! points through the chain and the analyser, in parallel, shardable and resumable.

pub mod approach;
pub mod case;
pub mod facts;
pub mod file;
pub mod lines;
pub mod meta;
pub mod plan;
pub mod report;
pub mod run;
pub mod sequence;
pub mod series;
pub mod shard;
pub mod table;
pub mod thesis;

pub use approach::Approach;
pub use case::{CaseResult, run_case};
pub use meta::{SweepMeta, read_meta};
pub use plan::{Case, SweepPlan, build_sweep};
pub use run::{Assembled, SweepOptions, SweepOutcome, assemble, run_sweep};
pub use sequence::{Direction, Sequence};
pub use shard::Shard;
