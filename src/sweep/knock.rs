//! The lab's doubtful repeat: a point started on its own (from rest, or from the static
//! load), measured, then its driven gear knocked by a seeded kick, settled again and
//! measured again, as many times as the sweep's `case.repeats`. Where the point can hold
//! more than one motion, a knock may move the rig from one to another.

use std::path::Path;

use rand::{RngExt, SeedableRng};
use rand_pcg::Pcg64Mcg;

use super::case::{CaseResult, chain_lead_s, measure_case, settled_plant};
use super::grid::{Case, SweepPlan};
use super::series::on_one_plant;

/// Smallest knock, as a share of the set speed: enough to part the teeth.
pub const KNOCK_MIN_SHARE: f64 = 0.02;
/// Largest knock, as a share of the set speed.
pub const KNOCK_MAX_SHARE: f64 = 0.2;

/// A knock's change of the driven gear's speed (rad/s) at `rpm`, drawn from `seed`: a
/// share of the set speed uniform in [[`KNOCK_MIN_SHARE`], [`KNOCK_MAX_SHARE`]], either
/// way.
pub fn knock_rad_s(seed: u64, rpm: f64) -> f64 {
    let mut rng = Pcg64Mcg::seed_from_u64(seed);
    let share = KNOCK_MIN_SHARE + (KNOCK_MAX_SHARE - KNOCK_MIN_SHARE) * rng.random::<f64>();
    let sign = if rng.random::<bool>() { 1.0 } else { -1.0 };
    sign * share * rpm * std::f64::consts::PI / 30.0
}

/// Runs a point and its knocked repeats, in order, on one plant; a failure ends the
/// series (the repeats after it are reported failed with it).
pub fn run_knocked(
    plan: &SweepPlan,
    series: &[&Case],
    sweep_dir: Option<&Path>,
) -> Vec<(usize, anyhow::Result<CaseResult>)> {
    let settle = ((plan.settle_s - chain_lead_s(plan)) * plan.rate_hz).round() as usize;
    on_one_plant(series, settled_plant(plan, series[0]), |i, case, plant| {
        if i > 0 {
            plant.kick_driven_gear(case.kick_rad_s);
            plant.skip(settle)?;
        }
        measure_case(plan, case, plant, sweep_dir)
    })
}
