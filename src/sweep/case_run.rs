//! One case of a sweep: its rig (a rig file's, or a preset's as its rig) on the plant of
//! any rig (`rig::NetworkPlant`), settled at the case's point, then measured — the chain
//! stage after stage into the analyser (reading the rig as `crate::rig_roles` says), the
//! physics judge on the gauged shaft's torque, the watched gear's condition indicators —
//! and recorded where the sweep asks. Impacts are counted on the first mesh's driving
//! gear, per revolution of the motor's body.

use std::path::Path;

use rig::{Approach, NetworkPlant, RigTopology};

use super::case_recording::CaseRecording;
use super::case_result::{
    CaseInstruments, CaseResult, KEPT_REVOLUTIONS, case_instruments, case_result, chain_lead_s,
    fault_labels, run_up_wait_s,
};
use super::grid::{Case, SweepPlan};
use super::measured_condition::MeasuredCondition;
use crate::rig_roles::{RoleColumns, gauge_of, gauged_stages, rig_columns_read, signals_with};
use crate::steady_point::{RigPointSpec, RigWindow, settled_rig_plant, skip_rig_samples};
use crate::vocabulary::GearIndicators;
use crate::vocabulary::InputNames;

/// Samples per block.
const BLOCK: usize = 4096;

/// How a sweep's inputs are named in a rig case's errors.
const NAMES: InputNames = InputNames {
    rpm: "grid.rpm",
    load: "grid.load_nm",
    settle: "case.settle_s",
    duration: "case.measure_s",
    rate: "rate_hz",
};

/// Runs `case` of `plan` on a plant of its own, recording into `sweep_dir` where the
/// sweep records.
pub fn run_case(
    plan: &SweepPlan,
    case: &Case,
    sweep_dir: Option<&Path>,
) -> anyhow::Result<CaseResult> {
    let rig = case.rig.topology();
    let mut plant = case_plant(plan, case, &rig)?;
    measure_case(plan, case, &rig, &mut plant, sweep_dir)
}

/// A plant of its own for `case` on `rig`, brought to its point by its approach and
/// settled, standing [`chain_lead_s`] before the case's window. From rest it settles for
/// `settle_s` once the drive has run it up (the run-up at the torque limit,
/// [`run_up_wait_s`]).
pub fn case_plant(
    plan: &SweepPlan,
    case: &Case,
    rig: &RigTopology,
) -> anyhow::Result<NetworkPlant> {
    let spec = RigPointSpec {
        rig,
        rpm: case.rpm,
        load_nm: case.load_nm,
        settle_s: plan.settle_s - chain_lead_s(plan),
        duration_s: plan.measure_s,
        rate_hz: plan.rate_hz,
        approach: case.approach,
    };
    let mut plant = settled_rig_plant(&spec, NAMES, &mut || Ok(()))?;
    if case.approach == Approach::Rest {
        let run_up_s = run_up_wait_s(plant.run_up_from_rest_s(case.rpm, case.load_nm));
        skip_rig_samples(&mut plant, (run_up_s * plan.rate_hz).round() as usize)?;
    }
    Ok(plant)
}

/// Measures `case` of `plan` on `plant` (its rig `rig`), standing [`chain_lead_s`]
/// before the case's window: the chain's lead run, then the window measured, judged and
/// recorded into `sweep_dir` where the sweep records.
pub fn measure_case(
    plan: &SweepPlan,
    case: &Case,
    rig: &RigTopology,
    plant: &mut NetworkPlant,
    sweep_dir: Option<&Path>,
) -> anyhow::Result<CaseResult> {
    let lead_s = chain_lead_s(plan);
    let columns = rig_columns_read(rig, |name| plan.reads(name));
    let mut names = signals_with(rig, &columns);
    let stages = gauged_stages(&plan.chain.stages, rig)?;
    let CaseInstruments {
        mut chain,
        input,
        mut measurement,
    } = case_instruments(plan, case, stages, &mut names)?;
    let mut recording = CaseRecording::start(plan, case, sweep_dir, &names)?;
    let mut window = RigWindow::new(rig, plan.rate_hz);
    let roles = RoleColumns::of(rig);
    let mut measured = MeasuredCondition::new(plan, gauge_of(rig)?.microstrain_per_nm());
    let lead = (lead_s * plan.rate_hz).round() as usize;
    let measured_samples = (plan.measure_s * plan.rate_hz).round() as usize;
    let total = lead + measured_samples;
    window.reserve(measured_samples);
    if let Some(m) = &mut measured {
        m.reserve(measured_samples);
    }
    let mut block = plant.block();
    let mut done = 0;
    while done < total {
        let n = BLOCK.min(if done < lead { lead } else { total } - done);
        block.clear();
        plant.run(n, &mut block)?;
        let frame = chain.process(roles.frame(rig, &block, done as u64, &columns));
        if done >= lead {
            window.add(&block);
            if let Some(m) = &mut measured {
                let angle = &block.angle_rad[roles.watched_gear];
                m.add(&block.time_s, angle, &frame.channels[input]);
            }
            measurement.push(&frame.channels[input]);
            if let Some(r) = &mut recording {
                r.write(&frame)?;
            }
        } else {
            plant.take_impacts();
            plant.take_revolutions();
        }
        done += n;
    }
    let impacts = plant.take_impacts();
    let revolutions_s = plant.take_revolutions();
    let summary = window.summary(rig, case.rpm, &impacts, &revolutions_s);
    let steady = summary.steady;
    let display = measurement.setup.analyser.display();
    let mut result = case_result(plan, case, &steady, &display, measurement.average_count());
    let all_revolutions = window.revolution_torque_nm(&revolutions_s);
    let kept_from = all_revolutions.len().saturating_sub(KEPT_REVOLUTIONS);
    result.revolution_torque_nm = all_revolutions[kept_from..].to_vec();
    result.condition = window.condition_report().as_ref().map(GearIndicators::from);
    result.measured_condition = roles
        .watched_teeth
        .and_then(|teeth| measured.and_then(|m| m.report(teeth)));
    result.faults = fault_labels(rig);
    if let Some(r) = recording {
        result.recordings = r.finish()?;
    }
    Ok(result)
}
