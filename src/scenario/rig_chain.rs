//! The measuring chain on a rig file's rig: the strain stage on the gauged shaft, every
//! stage checked to read only what a rig file's plant hands the chain
//! (`crate::rig_roles`).

use super::run_plan::ChainPlan;
use super::source::ScenarioSource;
use crate::rig_roles::{RIG_SIGNALS, gauged_shaft_strain, motor_of};
use crate::vocabulary::frame::SignalNames;

/// `chain` on `rig` at `rate_hz`: its strain stage and static calibration on the gauged
/// shaft. A rig without a motor or gauges, or a stage reading a signal a rig file's plant
/// does not offer, is refused (named at the scenario's `rig.file` or the stage).
pub fn rig_chain(
    src: &ScenarioSource,
    rig: &rig::RigTopology,
    chain: &ChainPlan,
    rate_hz: f64,
) -> anyhow::Result<ChainPlan> {
    motor_of(rig).map_err(|e| src.error(0..0, "rig.file", e))?;
    let shaft = gauged_shaft_strain(rig).map_err(|e| src.error(0..0, "rig.file", e))?;
    let gauged = chain.on_gauged_shaft(shaft);
    let mut names = SignalNames::of(&RIG_SIGNALS);
    gauged.stages.build(rate_hz, &mut names).map_err(|e| {
        src.error(
            0..0,
            &format!("chain.stage `{}`", e.output()),
            format!(
                "{e} (a rig file's plant offers {} to the chain)",
                RIG_SIGNALS.join(", ")
            ),
        )
    })?;
    Ok(gauged)
}
