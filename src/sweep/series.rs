//! The campaign as the lab ran it: at each load the speed stepped up through the grid and
//! back down, each point starting from the state the previous one left (no restart from
//! rest), settled, then measured. Where the rig has more than one motion at a speed, the
//! run-up and the run-down show which it keeps (hysteresis).

use std::path::Path;

use anyhow::Context;
use rig::{NetworkPlant, NetworkStart, RigTopology, Schedule, Track};

use super::case_result::{CaseResult, chain_lead_s, measured_samples};
use super::case_run::measure_case;
use super::grid::{Case, SweepPlan};
use crate::steady_point::skip_rig_samples;

/// Time over which the speed knob is turned from one point to the next (s): the
/// operator's few seconds; the speed loop (0.5 Hz) follows within about as long.
pub const STEP_RAMP_S: f64 = 5.0;

/// The speed set point of a series: held at each case's speed for its settling and
/// measuring, ramped over [`STEP_RAMP_S`] between cases. Case i's hold starts at
/// `i · (ramp + settle + measure)`.
fn series_schedule(plan: &SweepPlan, series: &[&Case]) -> Schedule {
    let hold_s = plan.settle_s + plan.measure_s;
    let mut speed = Track::hold(series[0].rpm);
    for (i, case) in series.iter().enumerate().skip(1) {
        let ramp_end_s = i as f64 * (STEP_RAMP_S + hold_s);
        speed = speed.ramp_to(ramp_end_s - STEP_RAMP_S, ramp_end_s, case.rpm);
    }
    Schedule {
        speed_rpm: speed,
        ..Schedule::constant(series[0].rpm, series[0].load_nm)
    }
}

/// Runs the cases of one series in order on one plant; a failure ends the series (the
/// cases after it are reported failed with it).
pub fn run_series(
    plan: &SweepPlan,
    series: &[&Case],
    sweep_dir: Option<&Path>,
) -> Vec<(usize, anyhow::Result<CaseResult>)> {
    let schedule = series_schedule(plan, series);
    let hold_s = plan.settle_s + plan.measure_s;
    // Samples before case i's chain lead, and how far the plant has run.
    let lead_from = |i: usize| {
        let window_from_s = i as f64 * (STEP_RAMP_S + hold_s) + plan.settle_s;
        ((window_from_s - chain_lead_s(plan)) * plan.rate_hz).round() as usize
    };
    let mut position = 0usize;
    let mut advance = |i: usize| {
        let skip = lead_from(i).saturating_sub(position);
        position = lead_from(i).max(position) + measured_samples(plan);
        skip
    };
    let rig = series[0].rig.topology();
    let plant = series_plant(plan, series, &rig, schedule);
    on_one_plant(series, plant, |i, case, plant| {
        skip_rig_samples(plant, advance(i))?;
        measure_case(plan, case, &rig, plant, sweep_dir)
    })
}

/// The plant of a series, steady at its first point under `schedule`, its load checked
/// as every rig's.
fn series_plant(
    plan: &SweepPlan,
    series: &[&Case],
    rig: &RigTopology,
    schedule: Schedule,
) -> anyhow::Result<NetworkPlant> {
    series[0]
        .rig
        .check_load(series[0].load_nm)
        .map_err(|e| anyhow::anyhow!("grid.load_nm {}: {e}", series[0].load_nm))?;
    NetworkPlant::new(rig, schedule, plan.rate_hz, NetworkStart::Steady)
        .with_context(|| format!("rig `{}`: the lab's run up and down", rig.name))
}

/// Runs `measure(i, case, plant)` for each case of `series` in order on `plant`; a plant
/// that could not be made fails every case, and a failed case ends the series (the cases
/// after it are reported failed with it).
pub fn on_one_plant<P>(
    series: &[&Case],
    plant: anyhow::Result<P>,
    mut measure: impl FnMut(usize, &Case, &mut P) -> anyhow::Result<CaseResult>,
) -> Vec<(usize, anyhow::Result<CaseResult>)> {
    let mut plant = match plant {
        Ok(plant) => plant,
        Err(e) => {
            let message = format!("{e:#}");
            return series
                .iter()
                .map(|c| (c.index, Err(anyhow::anyhow!("{message}"))))
                .collect();
        }
    };
    let mut out = Vec::with_capacity(series.len());
    let mut failed: Option<String> = None;
    for (i, case) in series.iter().enumerate() {
        let result = match &failed {
            Some(why) => Err(anyhow::anyhow!("the series stopped: {why}")),
            None => measure(i, case, &mut plant),
        };
        if let (None, Err(e)) = (&failed, &result) {
            failed = Some(format!("case {}: {e:#}", case.index));
        }
        out.push((case.index, result));
    }
    out
}
