//! One steady operating point of a rig alone, unpaced (`testrig simulate`, Python's
//! `testrig.simulate`; a preset's rig or a rig file's): the plant of any topology (`rig::NetworkPlant`) brought to the set speed and
//! load by its approach (`rig::Approach`), settled, then measured with every block handed to the caller;
//! its signals named after the rig's bodies, shafts and meshes.
//!
//! The motion is judged, as for the 1983 rig (`docs/physics.md`), on the gauged shaft's
//! torque (the last shaft where the file has no `[gauge]`) in revolutions of the motor's
//! body.

use std::f64::consts::PI;
use std::time::Instant;

use anyhow::Context;
use rig::{
    Approach, JudgeInput, Judgement, Motion, NetworkBlock, NetworkImpact, NetworkPlant, Regime,
    RigTopology, SteadySummary, impacts_per_tooth, judge,
};
use serde::Serialize;

use crate::chain::{GearCondition, GearConditionReport, sensed_stage, stage_lines, watched_gear};
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

/// One shaft over the window.
#[derive(Clone, Debug, Serialize)]
pub struct ShaftSummary {
    /// Its name.
    pub name: String,
    /// Mean torque (N m).
    pub torque_mean_nm: f64,
    /// RMS of the torque about its mean (N m).
    pub torque_ac_rms_nm: f64,
}

/// One mesh over the window.
#[derive(Clone, Debug, Serialize)]
pub struct MeshSummary {
    /// Its name.
    pub name: String,
    /// Impacts in the window.
    pub impacts: usize,
    /// Share of the window with the teeth apart.
    pub apart_fraction: f64,
}

/// One body over the window.
#[derive(Clone, Debug, Serialize)]
pub struct BodySummary {
    /// Its name.
    pub name: String,
    /// Mean speed in its sense of rotation (rev/min).
    pub speed_mean_rpm: f64,
}

/// The measuring window of a rig's point: the keys of the steady summary
/// (`rig::SteadySummary`), so that `simulate --json` reads alike for a preset and a rig
/// file (the judged shaft's torque; the impacts of every mesh, in all and per revolution
/// of the motor's body; the first mesh's impacts on each tooth of its driving gear, from
/// tooth 1, and its time apart; the regime, the motor's speed offset), then the rig's
/// own: every body, shaft and mesh.
#[derive(Clone, Debug, Serialize)]
pub struct RigPointSummary {
    /// The window in the steady summary's keys.
    #[serde(flatten)]
    pub steady: SteadySummary,
    /// The motor's mean torque (N m).
    pub motor_torque_mean_nm: f64,
    /// Each body.
    pub bodies: Vec<BodySummary>,
    /// Each shaft.
    pub shafts: Vec<ShaftSummary>,
    /// Each mesh.
    pub meshes: Vec<MeshSummary>,
    /// The shaft judged (the gauged one, else the last).
    pub judged_shaft: String,
    /// The watched gear's condition: the judged shaft's torque averaged synchronously
    /// over its revolutions (`null` without a mesh or under two revolutions).
    pub condition: Option<serde_json::Value>,
}

/// A rig's window in the steady summary's keys: its `bodies`, `shafts` and `meshes` as
/// summed, its `motion` over `measured_s` and whole `revolutions` of the motor's body,
/// the shaft judged `judged`, the motor's body set to `rpm` (rev/min), `impacts` the
/// window's.
fn steady_summary(
    rig: &RigTopology,
    (bodies, shafts, meshes): (&[BodySummary], &[ShaftSummary], &[MeshSummary]),
    (motion, measured_s, revolutions): (Judgement, f64, usize),
    judged: usize,
    rpm: f64,
    impacts: &[NetworkImpact],
) -> SteadySummary {
    let shaft = shafts.get(judged);
    let (mean, ac) = shaft.map_or((0.0, 0.0), |s| (s.torque_mean_nm, s.torque_ac_rms_nm));
    let teeth = rig.meshes.first().map_or(0, |m| m.teeth[0]);
    let first_mesh = impacts.iter().filter(|i| i.mesh == 0);
    let motor_rpm = rig.motor.map_or(rpm, |m| bodies[m].speed_mean_rpm);
    SteadySummary {
        measured_s,
        impacts: impacts.len(),
        impacts_per_rev: impacts.len() as f64 / revolutions.max(1) as f64,
        // Teeth are numbered 1..=z, the counts from tooth 1 at index 0.
        impacts_per_tooth: impacts_per_tooth(teeth, first_mesh.map(|i| i.teeth[0] - 1)),
        regime: regime_of(motion.motion),
        separates: meshes.iter().any(|m| m.apart_fraction > 0.0),
        apart_fraction: meshes.first().map_or(0.0, |m| m.apart_fraction),
        torque_mean_nm: mean,
        torque_rms_nm: ac.hypot(mean),
        torque_ac_rms_nm: ac,
        revolutions,
        speed_offset_rpm: motor_rpm - rpm,
        motion,
    }
}

/// The regime a rig's window reports: the judge's period of the judged shaft's torque (at
/// rest: period 1), aperiodic otherwise.
pub fn regime_of(motion: Motion) -> Regime {
    match motion {
        Motion::Periodic(k) => Regime::Periodic(k),
        Motion::NoVibration => Regime::Periodic(1),
        _ => Regime::Aperiodic,
    }
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

/// The shaft the judge and the strain column watch: the gauged one, else the last.
pub fn judged_shaft(rig: &RigTopology) -> usize {
    rig.gauge
        .as_ref()
        .map_or(rig.shafts.len().saturating_sub(1), |g| g.shaft)
}

/// What a measuring window keeps: sums per column, the judged shaft's torque and the
/// watched gear's synchronous average.
#[derive(Clone, Debug)]
pub struct RigWindow {
    rate_hz: f64,
    start_s: Option<f64>,
    samples: usize,
    speed_sum: Vec<f64>,
    torque: Vec<(f64, f64)>,
    apart: Vec<usize>,
    motor_sum: f64,
    judged: usize,
    judged_torque: Vec<f64>,
    watched: Option<(usize, u32)>,
    condition: GearCondition,
    /// The rig and the column of its ring sensor, where the average takes that rather
    /// than the judged shaft's torque.
    sensor: Option<(RigTopology, usize)>,
}

impl RigWindow {
    /// An empty window on `rig`'s signals at `rate_hz`.
    pub fn new(rig: &RigTopology, rate_hz: f64) -> Self {
        let watched = watched_gear(rig);
        Self {
            rate_hz,
            start_s: None,
            samples: 0,
            speed_sum: vec![0.0; rig.bodies.len()],
            torque: vec![(0.0, 0.0); rig.shafts.len()],
            apart: vec![0; rig.meshes.len()],
            motor_sum: 0.0,
            judged: judged_shaft(rig),
            judged_torque: Vec::new(),
            watched,
            condition: GearCondition::new(rate_hz),
            sensor: sensed_stage(rig, watched).and_then(|stage| {
                let name = format!("sensor_{}_n", rig.planetary[stage].name);
                let column = rig::column_names(rig).iter().position(|c| *c == name)?;
                Some((rig.clone(), column))
            }),
        }
    }

    /// This window without the watched gear's average (no condition report then).
    pub fn without_condition(mut self) -> Self {
        self.watched = None;
        self
    }

    /// Room for a window of `samples` samples, so that its torques are stored without
    /// growing ([`GearCondition::reserve`]).
    pub fn reserve(&mut self, samples: usize) {
        self.judged_torque.reserve(samples);
        if self.watched.is_some() {
            self.condition.reserve(samples);
        }
    }

    /// Adds a block of the window.
    pub fn add(&mut self, block: &NetworkBlock) {
        if self.start_s.is_none() {
            self.start_s = block.time_s.first().copied();
        }
        self.samples += block.len();
        for (sum, column) in self.speed_sum.iter_mut().zip(&block.speed_rad_s) {
            *sum += column.iter().sum::<f64>();
        }
        for (sums, column) in self.torque.iter_mut().zip(&block.shaft_torque_nm) {
            sums.0 += column.iter().sum::<f64>();
            sums.1 += column.iter().map(|t| t * t).sum::<f64>();
        }
        for (count, column) in self.apart.iter_mut().zip(&block.contact) {
            *count += column.iter().filter(|&&c| c == 0).count();
        }
        self.motor_sum += block.motor_torque_nm.iter().sum::<f64>();
        if let Some(column) = block.shaft_torque_nm.get(self.judged) {
            self.judged_torque.extend_from_slice(column);
            if let Some((gear, _)) = self.watched {
                let sensed = self
                    .sensor
                    .as_ref()
                    .and_then(|(rig, k)| rig::column(rig, block, *k));
                let averaged = sensed.as_deref().unwrap_or(column);
                self.condition
                    .add_samples(&block.time_s, &block.angle_rad[gear], averaged);
            }
        }
    }

    /// The judged shaft's torque at each of `revolutions_s` (the motor body's whole
    /// revolutions in the window, s) (N m).
    pub fn revolution_torque_nm(&self, revolutions_s: &[f64]) -> Vec<f64> {
        let start_s = self.start_s.unwrap_or(0.0);
        revolutions_s
            .iter()
            .filter_map(|t| {
                let i = ((t - start_s) * self.rate_hz).round() as usize;
                self.judged_torque.get(i).copied()
            })
            .collect()
    }

    /// The window summed up and its motion judged, the motor set to `rpm` (rev/min);
    /// `impacts` and `revolutions_s` those of the window.
    pub fn summary(
        &self,
        rig: &RigTopology,
        rpm: f64,
        impacts: &[NetworkImpact],
        revolutions_s: &[f64],
    ) -> RigPointSummary {
        let n = self.sample_count();
        let revolution_torque_nm = self.revolution_torque_nm(revolutions_s);
        let motion = judge(&JudgeInput {
            torque_nm: &self.judged_torque,
            rate_hz: self.rate_hz,
            running_hz: rpm / 60.0,
            revolution_torque_nm: &revolution_torque_nm,
        });
        let (bodies, shafts, meshes) = (
            self.bodies(rig),
            self.shafts(rig),
            self.meshes(rig, impacts),
        );
        let lists = (&bodies[..], &shafts[..], &meshes[..]);
        let measured_s = self.samples as f64 / self.rate_hz;
        let window = (motion, measured_s, revolutions_s.len());
        let steady = steady_summary(rig, lists, window, self.judged, rpm, impacts);
        RigPointSummary {
            steady,
            motor_torque_mean_nm: self.motor_sum / n,
            judged_shaft: rig
                .shafts
                .get(self.judged)
                .map_or(String::new(), |s| s.name.clone()),
            bodies,
            shafts,
            meshes,
            condition: None,
        }
    }

    /// The window's samples, as the divisor of its means (at least 1).
    fn sample_count(&self) -> f64 {
        self.samples.max(1) as f64
    }

    /// Each body's mean speed over the window.
    fn bodies(&self, rig: &RigTopology) -> Vec<BodySummary> {
        let n = self.sample_count();
        let speeds = rig.bodies.iter().zip(&self.speed_sum);
        speeds
            .map(|(b, sum)| BodySummary {
                name: b.name.clone(),
                speed_mean_rpm: sum / n * 30.0 / PI,
            })
            .collect()
    }

    /// Each shaft's mean torque and its RMS about the mean over the window.
    fn shafts(&self, rig: &RigTopology) -> Vec<ShaftSummary> {
        let n = self.sample_count();
        let torques = rig.shafts.iter().zip(&self.torque);
        torques
            .map(|(s, (sum, squares))| {
                let mean = sum / n;
                ShaftSummary {
                    name: s.name.clone(),
                    torque_mean_nm: mean,
                    torque_ac_rms_nm: (squares / n - mean * mean).max(0.0).sqrt(),
                }
            })
            .collect()
    }

    /// Each mesh's impacts (of `impacts`, the window's) and share of the window apart.
    fn meshes(&self, rig: &RigTopology, impacts: &[NetworkImpact]) -> Vec<MeshSummary> {
        let n = self.sample_count();
        let meshes = rig.meshes.iter().enumerate();
        meshes
            .map(|(i, m)| MeshSummary {
                name: m.name.clone(),
                impacts: impacts.iter().filter(|x| x.mesh == i).count(),
                apart_fraction: self.apart[i] as f64 / n,
            })
            .collect()
    }

    /// The watched gear's synchronous average and its indicators, if taken.
    pub fn condition_report(&self) -> Option<GearConditionReport> {
        let (_, teeth) = self.watched?;
        self.condition.report(teeth as usize)
    }
}

/// A condition report as JSON, its gear and averaged signal named; for a rig with
/// planetary stages, each stage's characteristic lines and the averaged signal's level
/// at each (`chain::stage_lines`), the motor at `rpm`.
fn condition_json(
    rig: &RigTopology,
    report: &GearConditionReport,
    window: &RigWindow,
    rpm: f64,
) -> serde_json::Value {
    let mut json = report.to_json();
    if let (Some(map), Some((gear, teeth))) = (json.as_object_mut(), window.watched) {
        map.insert("gear".into(), rig.bodies[gear].name.clone().into());
        map.insert("teeth".into(), teeth.into());
        let signal = match &window.sensor {
            Some((_, k)) => rig::column_names(rig)[*k].clone(),
            None => rig
                .shafts
                .get(window.judged)
                .map_or(String::new(), |s| format!("torque_{}_nm", s.name)),
        };
        map.insert("signal".into(), signal.into());
        if !rig.planetary.is_empty() {
            let stages: Vec<serde_json::Value> = stage_lines(rig, rpm)
                .iter()
                .map(|s| s.to_json(|hz| window.condition.line_amplitude(hz)))
                .collect();
            map.insert("planetary".into(), stages.into());
        }
    }
    json
}
