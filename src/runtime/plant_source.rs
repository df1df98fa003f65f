//! The plant's thread: advances the rig block by block, releases each block at its
//! wall-clock deadline (or at once, unpaced) and summarises the run's last stretch.

use std::sync::Arc;
use std::sync::atomic::{AtomicBool, Ordering};

use crossbeam_channel::{Sender, TrySendError};
use rig::{Plant, RegimeCriteria, SignalBlock, SteadySummary, SteadyWindow};

use super::frame::Frame;
use super::pacing::{LatenessHistogram, Pace, Pacer};
use super::status::SharedStatus;
use crate::scenario::Overflow;

/// Longest stretch at the end of a run whose once-per-revolution samples decide the regime (s).
pub const REGIME_WINDOW_S: f64 = 10.0;
/// Overrun times kept (the count goes on beyond).
const OVERRUN_TIMES_KEPT: usize = 1000;

/// What the plant's thread was asked to do.
pub struct PlantJob {
    /// The plant, at t = 0.
    pub plant: Plant,
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
    /// Summary of the last stretch (up to [`REGIME_WINDOW_S`], at most half the run).
    pub steady: SteadySummary,
    /// The plant's error, if it stopped the run.
    pub error: Option<String>,
}

/// Runs the job, sending frames to `out`; returns when done, stopped or disconnected.
pub fn run_plant(mut job: PlantJob, out: Sender<Frame>) -> PlantReport {
    let step_s = job.plant.output_step_s();
    let duration_s = job.total_samples as f64 * step_s;
    let window_from_s = duration_s - REGIME_WINDOW_S.min(duration_s / 2.0);
    let mut window = SteadyWindow::new(job.plant.params().teeth, step_s);
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
        steady: window.summary(&RegimeCriteria::default()),
        error: None,
    };
    let mut block = SignalBlock::default();
    let mut seq = 0;
    while report.samples < job.total_samples && !job.stop.load(Ordering::Relaxed) {
        let n = (job.total_samples - report.samples).min(job.block_samples as u64) as usize;
        block.clear();
        if let Err(e) = job.plant.run(n, &mut block) {
            report.error = Some(format!(
                "the plant stopped at t = {:.6} s: {e}",
                job.plant.time_s()
            ));
            break;
        }
        let impacts = job.plant.drain_impacts();
        let revolutions = job.plant.drain_revolutions();
        report.impacts += impacts.len() as u64;
        let start_s = report.samples as f64 * step_s;
        if start_s >= window_from_s {
            window.add_block(&block, job.plant.set_points().speed_rad_s());
            window.add_impacts(&impacts);
            window.add_revolutions(&revolutions);
        }
        let frame = Frame::of_block(seq, report.samples, &block, impacts);
        report.samples += n as u64;
        seq += 1;
        if let Some(pacer) = &pacer {
            report.lateness.add(pacer.wait_for(report.samples));
        }
        if !release(&job, &out, frame, start_s, &mut report) {
            break;
        }
        job.status.update(|s| s.simulated_samples = report.samples);
    }
    report.steady = window.summary(&RegimeCriteria::default());
    report
}

/// Sends one frame by the overflow policy; false when nobody listens any more.
fn release(
    job: &PlantJob,
    out: &Sender<Frame>,
    frame: Frame,
    start_s: f64,
    report: &mut PlantReport,
) -> bool {
    match job.overflow {
        Overflow::Lossless => out.send(frame).is_ok(),
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
