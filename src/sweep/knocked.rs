//! The lab's doubtful repeat: a point started on its own (from rest, or from the static
//! load), measured, then its driven gear knocked by a seeded kick (`knock.rs`), settled
//! again and measured again, as many times as the sweep's `case.repeats`. Where the point
//! can hold more than one motion, a knock may move the rig from one to another.

use std::path::Path;

use anyhow::Context;

use super::case_result::{CaseResult, chain_lead_s};
use super::case_run::{case_plant, measure_case};
use super::grid::{Case, SweepPlan};
use super::series::on_one_plant;
use crate::steady_point::skip_rig_samples;

/// Runs a point and its knocked repeats, in order, on one plant; a failure ends the
/// series (the repeats after it are reported failed with it).
pub fn run_knocked(
    plan: &SweepPlan,
    series: &[&Case],
    sweep_dir: Option<&Path>,
) -> Vec<(usize, anyhow::Result<CaseResult>)> {
    let settle = ((plan.settle_s - chain_lead_s(plan)) * plan.rate_hz).round() as usize;
    let rig = series[0].rig.topology();
    // The knock in the driven gear's own sense of rotation, as the thesis's plant's.
    let driven = rig.meshes.first().map(|m| m.gears[1]);
    let plant = case_plant(plan, series[0], &rig);
    on_one_plant(series, plant, |i, case, plant| {
        if i > 0 {
            let body = driven.context("a knock strikes the driven gear: the rig has no mesh")?;
            let sense = plant.speed_ratios()[body].signum();
            plant.kick(body, sense * case.kick_rad_s);
            skip_rig_samples(plant, settle)?;
        }
        measure_case(plan, case, &rig, plant, sweep_dir)
    })
}
