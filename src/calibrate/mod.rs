//! `testrig calibrate`: a search (CMA-ES with restarts) over free parameters for the rig
//! that best reproduces target findings, each point judged from more than one approach.
//!
//! Files: `testrig calibrate`: `calibration_toml.rs` the file (a campaign, `[[target]]`
//! points, `[[natural]]` frequencies, `[[free]]` parameters, `[search]`),
//! `calibration_plan.rs` it checked, `free_param.rs` a parameter's range on [0, 1],
//! `cma_es.rs` CMA-ES with IPOP restarts (ask/tell), `objective.rs` the line-height hinge
//! or the judged motion, `evaluate.rs` every candidate's points as sweep cases in parallel,
//! `log.rs` the JSON-lines log, `search.rs` the loop (budget, resume, shards,
//! cross-validation), `report.rs` `preset.toml` (a rig file's campaign: `rig-set.toml`),
//! `result.json`, the convergence plot, `report.md`. The rig is the campaign's: a preset's,
//! or a rig file's with its free parameters by path.

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
