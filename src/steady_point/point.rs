//! One steady point run: its spec checked, the plant settled by its approach, the
//! measuring window run block by block and handed on, then summed up and judged.

use std::time::Instant;

use anyhow::Context;
use rig::{Approach, NetworkBlock, NetworkImpact, NetworkPlant, RigTopology};

use super::summary::RigPointSummary;
use super::window::{RigWindow, condition_json};
use crate::vocabulary::{InputNames, check_times};
use crate::vocabulary::{check_load_nm, check_load_within, check_speed_rpm};

/// What to run.
#[derive(Clone, Debug)]
pub struct RigPointSpec<'a> {
    /// The rig, checked.
    pub rig: &'a RigTopology,
    /// The motor body's set speed (rev/min).
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

/// A point run: the plant as it ended, the window's impacts and summary, and the times.
pub struct RigPointRun {
    /// The plant after the window.
    pub plant: NetworkPlant,
    /// The window's impacts.
    pub impacts: Vec<NetworkImpact>,
    /// The window's summary.
    pub summary: RigPointSummary,
    /// Simulated time, settling included (s).
    pub simulated_s: f64,
    /// Wall time (s).
    pub wall_s: f64,
    /// The watched gear's averaged revolution of the judged shaft's torque (N m), if taken.
    pub average_nm: Option<Vec<f64>>,
}

/// Samples per block handed to the caller.
const BLOCK: usize = 4096;

/// The body the motor drives: every run of a rig file (simulate, sweeps, scenarios, the
/// panel) sets its speed, so a rig without a `[motor]` is refused here, by name.
pub fn motor_of(rig: &RigTopology) -> anyhow::Result<usize> {
    rig.motor.ok_or_else(|| {
        anyhow::anyhow!(
            "rig `{}` has no [motor]: a run sets the motor's speed, so the rig needs one ([motor] body = \"...\", docs/rig-files.md)",
            rig.name
        )
    })
}

/// Checks `spec` (each input refused under its name in `names`), runs it and hands `sink`
/// every block of the measuring window. `keep_going` is asked every
/// [`rig::plant::SKIP_STRETCH`] samples of settling (and `sink` after every block): an
/// error from either stops the run (a Python caller's Ctrl-C).
pub fn run_rig_point(
    spec: &RigPointSpec,
    names: InputNames,
    mut keep_going: impl FnMut() -> anyhow::Result<()>,
    mut sink: impl FnMut(&NetworkBlock) -> anyhow::Result<()>,
) -> anyhow::Result<RigPointRun> {
    check_speed_rpm(spec.rpm).map_err(|e| anyhow::anyhow!("{} {:?}: {e}", names.rpm, spec.rpm))?;
    check_load_nm(spec.load_nm)
        .map_err(|e| anyhow::anyhow!("{} {:?}: {e}", names.load, spec.load_nm))?;
    check_times(spec.settle_s, spec.duration_s, spec.rate_hz, names)?;
    let rig = spec.rig;
    motor_of(rig)?;
    let started = Instant::now();
    let mut plant = settled_rig_plant(spec, names, &mut keep_going)?;
    let mut block = NetworkBlock::new(rig);
    let mut window = RigWindow::new(rig, spec.rate_hz);
    let mut left = (spec.duration_s * spec.rate_hz).round() as usize;
    window.reserve(left);
    while left > 0 {
        let n = left.min(BLOCK);
        block.clear();
        plant.run(n, &mut block)?;
        window.add(&block);
        sink(&block)?;
        left -= n;
    }
    let impacts = plant.take_impacts();
    let revolutions = plant.take_revolutions();
    let report = window.condition_report();
    let mut summary = window.summary(rig, spec.rpm, &impacts, &revolutions);
    summary.condition = report
        .as_ref()
        .map(|r| condition_json(rig, r, &window, spec.rpm));
    Ok(RigPointRun {
        plant,
        impacts,
        summary,
        simulated_s: spec.approach.lead_in_s() + spec.settle_s + spec.duration_s,
        wall_s: started.elapsed().as_secs_f64(),
        average_nm: report.map(|r| r.average_nm),
    })
}

/// The plant of `spec` brought to its point by its approach and run through its lead-in
/// and `settle_s`, its impacts and revolutions so far dropped: the measuring window starts
/// at its next sample. A load the rig cannot hold (the one load check of every rig), or
/// any load on a rig without a brake, is refused (named by `names`). An error from
/// `keep_going`, asked as the settling goes, stops it.
pub fn settled_rig_plant(
    spec: &RigPointSpec,
    names: InputNames,
    keep_going: &mut dyn FnMut() -> anyhow::Result<()>,
) -> anyhow::Result<NetworkPlant> {
    let rig = spec.rig;
    check_load_within(spec.load_nm, rig)
        .map_err(|e| anyhow::anyhow!("{} {}: {e}", names.load, spec.load_nm))?;
    let schedule = spec.approach.schedule(spec.rpm, spec.load_nm);
    let start = spec.approach.network_start();
    let mut plant = NetworkPlant::new(rig, schedule, spec.rate_hz, start)
        .with_context(|| format!("rig `{}` at {} {}", rig.name, names.rpm, spec.rpm))?;
    let settle = ((spec.approach.lead_in_s() + spec.settle_s) * spec.rate_hz).round() as usize;
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
    drop_records(&mut plant);
    Ok(plant)
}

/// Runs `plant` on by `samples` samples, its signals, impacts and revolutions dropped.
pub fn skip_rig_samples(plant: &mut NetworkPlant, samples: usize) -> Result<(), rig::RigError> {
    plant.skip(samples)?;
    drop_records(plant);
    Ok(())
}

/// Drops the impacts and revolutions `plant` has recorded so far.
fn drop_records(plant: &mut NetworkPlant) {
    plant.take_impacts();
    plant.take_revolutions();
}
