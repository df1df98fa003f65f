//! `testrig calibrate`: a search (CMA-ES with restarts) over free parameters for the rig
//! that best reproduces target findings, each point judged from more than one approach.

pub(crate) mod calibration_plan;
pub(crate) mod calibration_toml;
pub(crate) mod cma_es;
pub(crate) mod evaluate;
pub(crate) mod free_param;
pub(crate) mod log;
pub(crate) mod objective;
pub(crate) mod report;
pub(crate) mod search;

pub use calibration_plan::{CalibrationPlan, Expect, TargetPoint, build_calibration};
pub use calibration_toml::CalibrationFile;
pub use cma_es::{Candidate, CmaEs, CmaSettings};
pub use evaluate::{Evaluation, evaluate_all};
pub use log::read_all_logs;
pub use objective::PointOutcome;
pub use report::{CalibrationResult, best_record, write_outputs};
pub use search::{SearchOptions, SearchOutcome, TrainingPoints, run_search};
