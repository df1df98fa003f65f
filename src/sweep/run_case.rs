//! One case on a plant of its own, whichever plant its rig runs on: a preset's on the
//! thesis's plant (`case.rs`), a rig file's on the plant of any rig (`rig_case.rs`).

use std::path::Path;

use super::case::{CaseResult, measure_case, settled_plant};
use super::case_rig::CaseRig;
use super::grid::{Case, SweepPlan};
use super::rig_case::run_rig_case;

/// Runs `case` of `plan` on a plant of its own, recording into `sweep_dir` where the
/// sweep records.
pub fn run_case(
    plan: &SweepPlan,
    case: &Case,
    sweep_dir: Option<&Path>,
) -> anyhow::Result<CaseResult> {
    if let CaseRig::File(rig) = &case.rig {
        return run_rig_case(plan, case, rig, sweep_dir);
    }
    let mut plant = settled_plant(plan, case)?;
    measure_case(plan, case, &mut plant, sweep_dir)
}
