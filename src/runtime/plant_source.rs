//! The plant's thread: advances the rig block by block, releases each block at its
//! wall-clock deadline (or at once, unpaced) and summarises the run's last stretch.

use std::sync::Arc;
use std::sync::atomic::{AtomicBool, Ordering};

use crossbeam_channel::{Sender, TrySendError};
use rig::SetPoints;

use super::pacing::{LatenessHistogram, Pace, Pacer};
use super::point_judge::PointJudge;
use super::rolling_regime::RollingRegime;
use super::run_plant::RunPlant;
use super::status::SharedStatus;
use crate::scenario::Overflow;
use crate::vocabulary::Refusal;
use crate::vocabulary::frame::Frame;
use crate::vocabulary::limits::{check_load_nm, check_speed_rpm};
use crate::vocabulary::{CommandInbox, Pending, PointVerdict, RigCommand};

/// Overrun times kept (the count goes on beyond).
const OVERRUN_TIMES_KEPT: usize = 1000;

/// What the plant's thread was asked to do.
pub struct PlantJob {
    /// The plant, at t = 0.
    pub plant: RunPlant,
    /// Samples to produce.
    pub total_samples: u64,
    /// Samples per block.
    pub block_samples: usize,
    /// Pace.
    pub pace: Pace,
    /// Lossless or dropping.
    pub overflow: Overflow,
    /// Set to end the run early (Ctrl-C or an error downstream).
    pub stop: Arc<AtomicBool>,
    /// What the console shows.
    pub status: SharedStatus,
    /// Commands: the scenario's timed ones and, live, those of scripts and pages.
    pub inbox: CommandInbox,
    /// Times of the scenario's own measurements (s); each is a point judged on its own.
    pub measures_s: Vec<f64>,
}

/// What the plant's thread reports.
#[derive(Debug)]
pub struct PlantReport {
    /// Samples released.
    pub samples: u64,
    /// Time between samples (s).
    pub step_s: f64,
    /// Lateness of each release (paced runs).
    pub lateness: LatenessHistogram,
    /// Blocks dropped at a full queue.
    pub overruns: u64,
    /// Simulated times (s) of the first dropped blocks.
    pub overrun_times_s: Vec<f64>,
    /// Contact starts over the whole run.
    pub impacts: u64,
    /// The judged motion of each measured point whose window ended (a run without
    /// measurements is one point: its last stretch).
    pub points: Vec<Arc<PointVerdict>>,
    /// The plant's error, if it stopped the run.
    pub error: Option<String>,
}

/// Runs the job, sending frames to `out`; returns when done, stopped or disconnected.
pub fn run_plant(mut job: PlantJob, out: Sender<Frame>) -> PlantReport {
    let step_s = job.plant.output_step_s();
    let mut judge = PointJudge::new(&job.measures_s, job.total_samples, step_s);
    let pacer = match job.pace {
        Pace::Factor(f) => Some(Pacer::new(1.0 / step_s, f)),
        Pace::Max => None,
    };
    let mut report = PlantReport {
        samples: 0,
        step_s,
        lateness: LatenessHistogram::default(),
        overruns: 0,
        overrun_times_s: Vec::new(),
        impacts: 0,
        points: Vec::new(),
        error: None,
    };
    let mut block = job.plant.block();
    let mut seq = 0;
    // The regime of the last 10 s is for the live panel only.
    let mut rolling = job
        .inbox
        .is_live()
        .then(|| RollingRegime::new(&job.plant, job.status.clone()));
    while report.samples < job.total_samples && !job.stop.load(Ordering::Relaxed) {
        let n = (job.total_samples - report.samples).min(job.block_samples as u64) as usize;
        let commands = take_commands(&mut job, report.samples, report.samples as f64 * step_s);
        if job.stop.load(Ordering::Relaxed) {
            break;
        }
        if let Err(e) = job.plant.advance(n, &mut block) {
            report.error = Some(format!(
                "the plant stopped at t = {:.6} s: {e}",
                job.plant.time_s()
            ));
            break;
        }
        report.impacts += RunPlant::impacts_in(&block) as u64;
        let start_s = report.samples as f64 * step_s;
        let last = report.samples + n as u64 >= job.total_samples;
        let set = job.plant.set_points();
        let verdicts = judge.add(&job.plant, report.samples, &block, &set, last);
        report.points.extend(verdicts.iter().cloned());
        if let Some(rolling) = rolling.as_mut() {
            rolling.add(&job.plant, &block, n, &set);
        }
        let frame = job
            .plant
            .frame(seq, report.samples, &mut block)
            .with_commands(commands, set)
            .with_points(verdicts);
        report.samples += n as u64;
        seq += 1;
        if let Some(pacer) = &pacer {
            let lateness_s = pacer.wait_for(report.samples, &job.stop);
            report.lateness.add(lateness_s);
            job.status.update(|s| s.lateness_s = lateness_s);
        }
        if !release(&job, &out, frame, start_s, &mut report) {
            break;
        }
        let impacts = report.impacts;
        job.status.update(|s| {
            s.simulated_samples = report.samples;
            s.impacts = impacts;
        });
    }
    report
}

/// The commands due at the block starting at `start_sample` (`at_s`): the plant's own
/// (set points, quit) carried out and answered here, the others returned for the frame.
fn take_commands(job: &mut PlantJob, start_sample: u64, at_s: f64) -> Vec<Pending> {
    let mut onward = Vec::new();
    // The set points as the commands of this block leave them (the plant takes them up
    // at its next step, so it cannot be asked between two commands of one block).
    let mut current = job.plant.set_points();
    for pending in job.inbox.due(start_sample, at_s) {
        let mut set = current;
        match pending.command {
            RigCommand::SetSpeed { rpm } => set.speed_rpm = rpm,
            RigCommand::SetLoad { nm } => set.load_nm = nm,
            RigCommand::SetOscillatingLoad { nm, hz } => {
                set.oscillating_load_nm = nm;
                set.oscillating_load_hz = hz;
            }
            RigCommand::Quit => {
                job.stop.store(true, Ordering::Relaxed);
                pending.answer(Ok(()));
                continue;
            }
            _ => {
                onward.push(pending);
                continue;
            }
        }
        let outcome = check_set_points(&set, &job.plant)
            .and_then(|()| job.plant.hold(set).map_err(Refusal::from));
        if outcome.is_ok() {
            current = set;
        }
        // The state shows the set points before the answer goes: a client that reads
        // the state after its reply sees what it set.
        job.status.update(|s| s.set_points = Some(current));
        pending.answer(outcome);
    }
    job.status.update(|s| s.set_points = Some(current));
    onward
}

/// The bounds every command shares (speed, brake load), as for a scenario's set points.
fn check_set_points(set: &SetPoints, plant: &RunPlant) -> Result<(), Refusal> {
    let limit = |what| move |source| Refusal::Limit { what, source };
    check_speed_rpm(set.speed_rpm).map_err(limit("speed"))?;
    check_load_nm(set.load_nm).map_err(limit("load"))?;
    plant
        .check_load(set.load_nm + set.oscillating_load_nm)
        .map_err(limit("load with its oscillating part"))?;
    for (value, what) in [
        (set.oscillating_load_nm, "oscillating load amplitude (N m)"),
        (set.oscillating_load_hz, "oscillating load frequency (Hz)"),
    ] {
        if !(value.is_finite() && value >= 0.0) {
            return Err(Refusal::Setting(format!(
                "{what} {value}: must be finite and ≥ 0"
            )));
        }
    }
    Ok(())
}

/// Sends one frame by the overflow policy; false when nobody listens any more.
fn release(
    job: &PlantJob,
    out: &Sender<Frame>,
    frame: Frame,
    start_s: f64,
    report: &mut PlantReport,
) -> bool {
    // A block carrying commands is never dropped: they would be neither carried out nor
    // answered. The plant waits for room instead (counted as lateness, not an overrun).
    match job.overflow {
        Overflow::Lossless => out.send(frame).is_ok(),
        Overflow::Drop if !frame.commands.is_empty() => out.send(frame).is_ok(),
        Overflow::Drop => match out.try_send(frame) {
            Ok(()) => true,
            Err(TrySendError::Full(_)) => {
                report.overruns += 1;
                if report.overrun_times_s.len() < OVERRUN_TIMES_KEPT {
                    report.overrun_times_s.push(start_s);
                }
                job.status.update(|s| s.overruns = report.overruns);
                true
            }
            Err(TrySendError::Disconnected(_)) => false,
        },
    }
}
