//! One case of a sweep on a rig file's rig: the plant of any rig (`rig::NetworkPlant`)
//! settled at the case's point, then measured as a preset's case is — the chain stage
//! after stage into the analyser, the physics judge on the gauged shaft's torque, the
//! watched gear's condition indicators — and recorded where the sweep asks.
//!
//! The chain's standard stages read the rig under the standard chain's input names: the
//! gauged shaft's torque as `torque_intermediate_shaft_nm` (the strain stage takes the
//! gauge's diameter and shear modulus), the motor body's speed as `speed1_rad_s` (the
//! tacho), and the speed of the gauged shaft's first body as `speed3_rad_s` (the slip
//! rings turn with it); and the watched gear's once-per-revolution pulse as
//! `keyphasor_v`. Impacts are counted on the first mesh's driving gear, per revolution
//! of the motor's body.

use std::path::Path;

use instruments::ShaftStrain;
use rig::{
    Gauge, Motion, NetworkBlock, NetworkImpact, Regime, RigTopology, SteadySummary,
    impacts_per_tooth,
};

use super::case::{
    CaseInstruments, CaseResult, KEPT_REVOLUTIONS, case_instruments, case_result, chain_lead_s,
};
use super::case_recording::CaseRecording;
use super::grid::{Case, SweepPlan};
use super::measured_condition::MeasuredCondition;
use crate::chain::ChainStages;
use crate::rig_point::{
    RigPointSpec, RigPointSummary, RigWindow, judged_shaft, settled_rig_plant, watched_gear,
};
use crate::steady_point::InputNames;
use crate::vocabulary::GearIndicators;
use crate::vocabulary::frame::{Frame, SignalNames};
use crate::vocabulary::signal_names::{
    KEYPHASOR_V, MOTOR_SPEED_RAD_S, SHAFT_TORQUE_NM, SLIP_RING_SPEED_RAD_S,
};

/// Samples per block.
const BLOCK: usize = 4096;

/// The signals a rig file's case hands the chain, in frame order.
pub const RIG_CASE_SIGNALS: [&str; 5] = [
    "time_s",
    SHAFT_TORQUE_NM,
    MOTOR_SPEED_RAD_S,
    SLIP_RING_SPEED_RAD_S,
    KEYPHASOR_V,
];

/// The keyphasor's high level (V): [`KEYPHASOR_V`] is this over the first
/// 1/[`KEYPHASOR_MARK_SHARE`] of each turn of the watched gear (a reflective mark under an
/// optical probe), 0 V otherwise; its rising edges are the revolutions a synchronous
/// average starts from.
const KEYPHASOR_HIGH_V: f64 = 5.0;

/// Revolutions per keyphasor mark width: the mark spans 1/64 of a turn.
const KEYPHASOR_MARK_SHARE: f64 = 64.0;

/// How a sweep's inputs are named in a rig case's errors.
const NAMES: InputNames = InputNames {
    rpm: "grid.rpm",
    load: "grid.load_nm",
    settle: "case.settle_s",
    duration: "case.measure_s",
    rate: "rate_hz",
};

/// Every signal of a rig file's case: [`RIG_CASE_SIGNALS`], then the stages' outputs.
pub fn rig_case_signal_names(stages: &ChainStages) -> SignalNames {
    let mut names = SignalNames::of(&RIG_CASE_SIGNALS);
    for output in stages.outputs() {
        names.push(output);
    }
    names
}

/// The body the motor drives: a sweep sets its speed.
pub fn motor_of(rig: &RigTopology) -> anyhow::Result<usize> {
    rig.motor.ok_or_else(|| {
        anyhow::anyhow!(
            "rig `{}` has no [motor]: a sweep sets the motor's speed",
            rig.name
        )
    })
}

/// The rig's strain gauges: a sweep measures the strain of a gauged shaft.
fn gauge_of(rig: &RigTopology) -> anyhow::Result<&Gauge> {
    rig.gauge.as_ref().ok_or_else(|| {
        anyhow::anyhow!(
            "rig `{}` has no [gauge]: a sweep measures the strain of a gauged shaft",
            rig.name
        )
    })
}

/// The chain's stages for `rig`: the strain stage on its gauged shaft.
pub fn rig_case_stages(stages: &ChainStages, rig: &RigTopology) -> anyhow::Result<ChainStages> {
    let gauge = gauge_of(rig)?;
    let shaft = ShaftStrain::new(gauge.diameter_m, gauge.shear_modulus_pa)?;
    Ok(stages.with_gauged_shaft(shaft))
}

/// Runs `case` of `plan` on `rig`, recording into `sweep_dir` where the sweep records.
pub fn run_rig_case(
    plan: &SweepPlan,
    case: &Case,
    rig: &RigTopology,
    sweep_dir: Option<&Path>,
) -> anyhow::Result<CaseResult> {
    let lead_s = chain_lead_s(plan);
    let spec = RigPointSpec {
        rig,
        rpm: case.rpm,
        load_nm: case.load_nm,
        settle_s: plan.settle_s - lead_s,
        duration_s: plan.measure_s,
        rate_hz: plan.rate_hz,
        approach: case.approach,
    };
    let mut plant = settled_rig_plant(&spec, NAMES)?;
    let mut names = SignalNames::of(&RIG_CASE_SIGNALS);
    let stages = rig_case_stages(&plan.chain.stages, rig)?;
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
    let total = lead + (plan.measure_s * plan.rate_hz).round() as usize;
    let mut block = NetworkBlock::new(rig.bodies.len(), rig.shafts.len(), rig.meshes.len());
    let mut done = 0;
    while done < total {
        let n = BLOCK.min(if done < lead { lead } else { total } - done);
        block.clear();
        plant.run(n, &mut block)?;
        let frame = chain.process(roles.frame(&block, done as u64));
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
    let summary = window.summary(rig, &spec, &impacts, &revolutions_s);
    let steady = steady_summary(plan, case, rig, &summary, &impacts, revolutions_s.len())?;
    let display = measurement.setup.analyser.display();
    let mut result = case_result(plan, case, &steady, &display, measurement.average_count());
    let all_revolutions = window.revolution_torque_nm(&revolutions_s, plan.rate_hz);
    let kept_from = all_revolutions.len().saturating_sub(KEPT_REVOLUTIONS);
    result.revolution_torque_nm = all_revolutions[kept_from..].to_vec();
    result.condition = window.condition_report().as_ref().map(GearIndicators::from);
    result.measured_condition = roles
        .watched_teeth
        .and_then(|teeth| measured.and_then(|m| m.report(teeth)));
    result.faults = case.rig.fault_labels();
    if let Some(r) = recording {
        result.recordings = r.finish()?;
    }
    Ok(result)
}

/// A rig case's window as a preset's case sums its own up: the gauged shaft's torque
/// and motion, impacts on the first mesh's driving gear per revolution of the motor's
/// body, the first mesh's time apart, the motor's speed offset.
fn steady_summary(
    plan: &SweepPlan,
    case: &Case,
    rig: &RigTopology,
    summary: &RigPointSummary,
    impacts: &[NetworkImpact],
    revolutions: usize,
) -> anyhow::Result<SteadySummary> {
    let judged = &summary.shafts[judged_shaft(rig)];
    let teeth = case.rig.counted_teeth();
    let first_mesh = impacts.iter().filter(|i| i.mesh == 0);
    Ok(SteadySummary {
        measured_s: plan.measure_s,
        impacts: impacts.len(),
        torque_rms_nm: judged.torque_ac_rms_nm.hypot(judged.torque_mean_nm),
        regime: regime_of(summary.motion.motion),
        motion: summary.motion.clone(),
        revolutions,
        impacts_per_rev: impacts.len() as f64 / revolutions.max(1) as f64,
        impacts_per_tooth: impacts_per_tooth(teeth, first_mesh.map(|i| i.teeth[0])),
        separates: summary.meshes.iter().any(|m| m.apart_fraction > 0.0),
        apart_fraction: summary.meshes.first().map_or(0.0, |m| m.apart_fraction),
        torque_mean_nm: judged.torque_mean_nm,
        torque_ac_rms_nm: judged.torque_ac_rms_nm,
        speed_offset_rpm: summary.bodies[motor_of(rig)?].speed_mean_rpm - case.rpm,
    })
}

/// The regime a rig case reports: the judge's period (at rest: period 1), aperiodic
/// otherwise (the thesis's plant classifies its own state once per revolution; a rig
/// file's plant is judged on the gauged shaft's torque alone).
fn regime_of(motion: Motion) -> Regime {
    match motion {
        Motion::Periodic(k) => Regime::Periodic(k),
        Motion::AtRest => Regime::Periodic(1),
        _ => Regime::Aperiodic,
    }
}

/// Where the standard chain's inputs sit in a rig's block.
struct RoleColumns {
    gauged_shaft: usize,
    motor: usize,
    slip_ring_body: usize,
    watched_gear: usize,
    /// The watched gear's teeth (none without a mesh: no indicators then).
    watched_teeth: Option<u32>,
}

/// The first body of the gauged shaft (a rig without meshes has no watched gear).
fn gauged_shaft_body(rig: &RigTopology) -> usize {
    rig.shafts[judged_shaft(rig)].between[0]
}

impl RoleColumns {
    fn of(rig: &RigTopology) -> Self {
        let gauged_shaft = judged_shaft(rig);
        let watched = watched_gear(rig);
        Self {
            gauged_shaft,
            motor: rig.motor.unwrap_or(0),
            slip_ring_body: gauged_shaft_body(rig),
            watched_gear: watched.map_or(gauged_shaft_body(rig), |(g, _)| g),
            watched_teeth: watched.map(|(_, teeth)| teeth),
        }
    }

    /// The frame of [`RIG_CASE_SIGNALS`] of `block`, starting at sample `start`.
    fn frame(&self, block: &NetworkBlock, start: u64) -> Frame {
        let mut frame = Frame::of_channels(vec![
            block.time_s.clone(),
            block.shaft_torque_nm[self.gauged_shaft].clone(),
            block.speed_rad_s[self.motor].clone(),
            block.speed_rad_s[self.slip_ring_body].clone(),
            block.angle_rad[self.watched_gear]
                .iter()
                .map(|&angle| {
                    let turn = (angle / std::f64::consts::TAU).rem_euclid(1.0);
                    if turn < 1.0 / KEYPHASOR_MARK_SHARE {
                        KEYPHASOR_HIGH_V
                    } else {
                        0.0
                    }
                })
                .collect(),
        ]);
        frame.start_sample = start;
        frame
    }
}
