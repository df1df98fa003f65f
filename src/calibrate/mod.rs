//! `testrig calibrate`: a search (CMA-ES with restarts) over free parameters for the rig
//! that best reproduces target findings, each point judged from more than one approach.

pub mod cma_es;
pub mod evaluate;
pub mod file;
pub mod free_param;
pub mod log;
pub mod objective;
pub mod plan;
pub mod report;
pub mod search;

pub use cma_es::{Candidate, CmaEs, CmaSettings};
pub use evaluate::{Evaluation, evaluate_all};
pub use file::CalibrationFile;
pub use plan::{CalibrationPlan, Expect, TargetPoint, build_calibration};
pub use report::{CalibrationResult, best_record, write_outputs};
pub use search::{SearchOptions, SearchOutcome, TrainingPoints, run_search};
