//! The measuring chain on the rig (a rig file's, or a preset's as its rig): the strain
//! stage and the static calibration on the gauged shaft (the stages were wired on what
//! the plant offers, `crate::rig_roles`).

use super::run_plan::ChainPlan;
use super::source::ScenarioSource;
use crate::rig_roles::gauged_shaft_strain;
use crate::steady_point::motor_of;

/// `chain` on `rig`: its strain stage and static calibration on the gauged shaft. A rig
/// without a motor or gauges is refused, named at the scenario's `rig.file` (a preset's
/// rig has both).
pub fn rig_chain(
    src: &ScenarioSource,
    rig: &rig::RigTopology,
    chain: &ChainPlan,
) -> anyhow::Result<ChainPlan> {
    motor_of(rig).map_err(|e| src.error(0..0, "rig.file", e))?;
    let shaft = gauged_shaft_strain(rig).map_err(|e| src.error(0..0, "rig.file", e))?;
    Ok(chain.on_gauged_shaft(shaft))
}
