//! One steady operating point of the plant alone, unpaced: the set points and times
//! checked, the plant built from a preset and its overrides and brought to the point by
//! its approach (`rig::Approach`), settled, then measured with every block handed to the
//! caller. The one path of `testrig simulate` and of the Python package's
//! `testrig.simulate`.

use crate::chain::{GearCondition, GearConditionReport};
use std::time::Instant;

use anyhow::{Context, bail};
use rig::{Approach, Plant, PlantConfig, RegimeCriteria, SignalBlock, SteadySummary, run_steady};

use crate::scenario::preset_with_overrides;
use crate::vocabulary::{
    InputNames, check_load_nm, check_load_within, check_simulated_s, check_speed_rpm, check_times,
    max_load_nm,
};

/// What to run.
#[derive(Clone, Debug)]
pub struct PointSpec<'a> {
    /// Parameter preset (`testrig params`).
    pub preset: &'a str,
    /// `NAME=VALUE` parameter overrides.
    pub overrides: &'a [String],
    /// Motor speed set point (rev/min).
    pub rpm: f64,
    /// Brake load (N m).
    pub load_nm: f64,
    /// Simulated time before measuring (s).
    pub settle_s: f64,
    /// Measuring window (s).
    pub duration_s: f64,
    /// Output rate of the true signals (Hz).
    pub rate_hz: f64,
    /// How the point is reached (settling counts from the end of a ramp).
    pub approach: Approach,
}

/// A point run: the plant as it ended (its impacts and revolutions), the window's
/// summary, and the times.
pub struct PointRun {
    /// The plant after the window.
    pub plant: Plant,
    /// The measuring window's summary.
    pub summary: SteadySummary,
    /// Simulated time, settling included (s).
    pub simulated_s: f64,
    /// Wall time (s).
    pub wall_s: f64,
    /// The condition indicators of the window's synchronous average of the output-shaft
    /// torque over the driven gear's revolutions (`None` under two revolutions).
    pub condition: Option<GearConditionReport>,
}

/// Checks `spec` (each input refused under its name in `names`), runs it, and hands
/// `sink` every block of the measuring window. `keep_going` is asked every
/// [`rig::CHECK_EVERY`] samples of settling (and `sink` after every block): an error from either stops the run (a
/// Python caller's Ctrl-C).
pub fn run_point(
    spec: &PointSpec,
    names: InputNames,
    mut keep_going: impl FnMut() -> anyhow::Result<()>,
    sink: impl FnMut(&SignalBlock) -> anyhow::Result<()>,
) -> anyhow::Result<PointRun> {
    check_point(spec, names)?;
    let params = preset_with_overrides(spec.preset, spec.overrides)?;
    let rig = format!("preset `{}`", spec.preset);
    check_load_within(spec.load_nm, max_load_nm(&params), &rig, true)
        .map_err(|e| anyhow::anyhow!("{} {:?}: {e}", names.load, spec.load_nm))?;
    let config = PlantConfig {
        output_rate_hz: spec.rate_hz,
        ..PlantConfig::default()
    };
    let mut plant = spec
        .approach
        .plant(params, spec.rpm, spec.load_nm, config)
        .with_context(|| format!("{}/{}/{}", names.rpm, names.load, names.rate))?;
    let started = Instant::now();
    let lead_in_s = spec.approach.lead_in_s();
    let settle = ((lead_in_s + spec.settle_s) * spec.rate_hz).round() as usize;
    let mut stopped = None;
    let settled = plant.skip_while(settle, || match keep_going() {
        Ok(()) => true,
        Err(e) => {
            stopped = Some(e);
            false
        }
    })?;
    if let Some(e) = stopped.filter(|_| settled < settle) {
        return Err(e);
    }
    let mut condition = GearCondition::new(spec.rate_hz);
    let mut sink = sink;
    let summary = run_steady(
        &mut plant,
        0.0,
        spec.duration_s,
        &RegimeCriteria::default(),
        |block| {
            condition.add(block);
            sink(block)
        },
    )?;
    let condition = condition.report(plant.params().teeth as usize);
    Ok(PointRun {
        simulated_s: lead_in_s + spec.settle_s + summary.measured_s,
        wall_s: started.elapsed().as_secs_f64(),
        plant,
        summary,
        condition,
    })
}

/// The set points, times and rate, each refused under its name.
fn check_point(spec: &PointSpec, names: InputNames) -> anyhow::Result<()> {
    check_speed_rpm(spec.rpm).map_err(|e| anyhow::anyhow!("{} {:?}: {e}", names.rpm, spec.rpm))?;
    check_load_nm(spec.load_nm)
        .map_err(|e| anyhow::anyhow!("{} {:?}: {e}", names.load, spec.load_nm))?;
    check_times(spec.settle_s, spec.duration_s, spec.rate_hz, names)
}

/// The approaches by name, as `simulate --approach` and Python's `approach=` take them.
pub const APPROACH_NAMES: [&str; 4] = ["static", "rest", "up", "down"];

/// The approach named `name` (one of [`APPROACH_NAMES`], or `steady` for `static`) to
/// `rpm`, its ramp at `ramp_rpm_per_s`; refused where the rate is not a positive number
/// or the ramp longer than a run may be.
pub fn approach_named(name: &str, rpm: f64, ramp_rpm_per_s: f64) -> anyhow::Result<Approach> {
    let ramp_ok = ramp_rpm_per_s.is_finite() && ramp_rpm_per_s > 0.0;
    let approach = match name {
        "static" | "steady" => Approach::Static,
        "rest" => Approach::Rest,
        "up" | "down" if !ramp_ok => bail!(
            "ramp rate {ramp_rpm_per_s}: a ramp's rate must be a positive number of rev/min per second"
        ),
        "up" => Approach::run_up(rpm, ramp_rpm_per_s),
        "down" => Approach::run_down(rpm, ramp_rpm_per_s),
        other => bail!("approach `{other}`: one of {}", APPROACH_NAMES.join(", ")),
    };
    check_simulated_s(approach.lead_in_s(), true).map_err(|e| {
        anyhow::anyhow!("ramp rate {ramp_rpm_per_s} rev/min per s to {rpm} rev/min: the ramp's {e}")
    })?;
    Ok(approach)
}
