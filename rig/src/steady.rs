//! A run at fixed set points: settle, then measure what the thesis read off the rig.

use serde::Serialize;

use crate::error::RigError;
use crate::judge::{JudgeInput, Judgement, judge};
use crate::plant::Plant;
use crate::records::{Impact, RevolutionSample};
use crate::regime::{Regime, RegimeCriteria, classify_scaled, impacts_per_tooth};
use crate::signals::{INTERMEDIATE_SHAFT, SignalBlock};

/// Samples advanced per call while measuring.
const BLOCK: usize = 8192;
/// Most samples of the output-shaft torque a window keeps for the judge (the latest):
/// 2^22, 410 s at 10240 Hz, 32 MiB.
const JUDGED_SAMPLES_MAX: usize = 1 << 22;

/// What a settled run shows (the measuring window only).
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct SteadySummary {
    /// Length of the measuring window (s).
    pub measured_s: f64,
    /// Contact starts in the window.
    pub impacts: usize,
    /// Contact starts per revolution of the driving gear.
    pub impacts_per_rev: f64,
    /// Contact starts in the window on each tooth of the driving gear.
    pub impacts_per_tooth: Vec<u64>,
    /// Period-k or aperiodic, from once-per-revolution samples.
    pub regime: Regime,
    /// Whether the teeth ever lose contact in the window.
    pub separates: bool,
    /// Share of samples with no mesh torque.
    pub apart_fraction: f64,
    /// Mean intermediate (output) shaft torque (N m).
    pub torque_mean_nm: f64,
    /// RMS of the intermediate shaft torque, mean included (N m).
    pub torque_rms_nm: f64,
    /// RMS of the intermediate shaft torque about its mean (N m).
    pub torque_ac_rms_nm: f64,
    /// Revolutions of the driving gear in the window.
    pub revolutions: usize,
    /// Mean speed of the motor over the window less the set speed (rev/min): near 0
    /// where the motor holds the set speed, negative where its torque limit lets it sag.
    pub speed_offset_rpm: f64,
    /// The physics judge's verdict on the output-shaft torque, with its numbers.
    pub motion: Judgement,
}

/// What a measuring window accumulates, block by block, with memory bounded by the
/// window's revolutions (impacts are counted, not kept).
#[derive(Clone, Debug)]
pub struct SteadyWindow {
    samples: usize,
    sum: f64,
    sum_sq: f64,
    apart: usize,
    speed_moments: [(f64, f64); 5],
    impacts: usize,
    impacts_per_tooth: Vec<u64>,
    revolutions: Vec<RevolutionSample>,
    step_s: f64,
    torque_nm: Vec<f64>,
    running_hz: f64,
}

impl SteadyWindow {
    /// An empty window for a plant of `teeth` teeth sampled every `step_s` (s).
    pub fn new(teeth: u32, step_s: f64) -> Self {
        Self {
            samples: 0,
            sum: 0.0,
            sum_sq: 0.0,
            apart: 0,
            speed_moments: [(0.0, 0.0); 5],
            impacts: 0,
            impacts_per_tooth: vec![0; teeth as usize],
            revolutions: Vec::new(),
            step_s,
            torque_nm: Vec::new(),
            running_hz: 0.0,
        }
    }

    /// Adds a block of true signals; speeds are taken about `set_speed_rad_s`.
    pub fn add_block(&mut self, block: &SignalBlock, set_speed_rad_s: f64) {
        let torques = &block.shaft_torque_nm[INTERMEDIATE_SHAFT];
        for &torque in torques {
            self.sum += torque;
            self.sum_sq += torque * torque;
        }
        self.keep_torque(torques);
        self.running_hz = set_speed_rad_s / std::f64::consts::TAU;
        self.apart += block.contact.iter().filter(|&&c| c == 0).count();
        for (moments, speeds) in self.speed_moments.iter_mut().zip(&block.speed_rad_s) {
            for &w in speeds {
                let v = w - set_speed_rad_s;
                moments.0 += v;
                moments.1 += v * v;
            }
        }
        self.samples += block.len();
    }

    /// Keeps the latest [`JUDGED_SAMPLES_MAX`] torque samples (dropping the oldest half
    /// at a time, so the cost per sample stays constant).
    fn keep_torque(&mut self, torques: &[f64]) {
        self.torque_nm.extend_from_slice(torques);
        if self.torque_nm.len() > 2 * JUDGED_SAMPLES_MAX {
            let excess = self.torque_nm.len() - JUDGED_SAMPLES_MAX;
            self.torque_nm.drain(..excess);
        }
    }

    /// The judge's verdict on the torque kept and the revolutions of the same stretch.
    pub fn judgement(&self) -> Judgement {
        let kept = self.torque_nm.len().min(JUDGED_SAMPLES_MAX);
        let torque_nm = &self.torque_nm[self.torque_nm.len() - kept..];
        // The revolutions of the kept stretch: those within its length of the last one.
        let kept_s = self.step_s * kept as f64;
        let last_s = self.revolutions.last().map_or(0.0, |r| r.time_s);
        let revolution_torque_nm: Vec<f64> = self
            .revolutions
            .iter()
            .filter(|r| last_s - r.time_s < kept_s)
            .map(|r| r.shaft_torque_nm)
            .collect();
        judge(&JudgeInput {
            torque_nm,
            rate_hz: 1.0 / self.step_s,
            running_hz: self.running_hz,
            revolution_torque_nm: &revolution_torque_nm,
        })
    }

    /// The output-shaft torque of the last `count` revolution samples (N m).
    pub fn last_revolution_torques_nm(&self, count: usize) -> Vec<f64> {
        let from = self.revolutions.len().saturating_sub(count);
        self.revolutions[from..]
            .iter()
            .map(|r| r.shaft_torque_nm)
            .collect()
    }

    /// Adds contact starts of the window.
    pub fn add_impacts(&mut self, impacts: &[Impact]) {
        self.impacts += impacts.len();
        let counts = impacts_per_tooth(
            self.impacts_per_tooth.len() as u32,
            impacts.iter().map(|i| i.tooth),
        );
        for (total, n) in self.impacts_per_tooth.iter_mut().zip(counts) {
            *total += n;
        }
    }

    /// Adds once-per-revolution samples of the window.
    pub fn add_revolutions(&mut self, revolutions: &[RevolutionSample]) {
        self.revolutions.extend_from_slice(revolutions);
    }

    /// The regime of the once-per-revolution samples alone: cheap enough for a paced
    /// thread (no spectrum, unlike [`Self::summary`]'s judge).
    pub fn regime(&self, criteria: &RegimeCriteria) -> Regime {
        let count = self.samples.max(1) as f64;
        classify_scaled(
            &self.revolutions,
            &vibration_scale(&self.speed_moments, count),
            criteria,
        )
    }

    /// The summary of everything added, the judge's verdict included.
    pub fn summary(&self, criteria: &RegimeCriteria) -> SteadySummary {
        let count = self.samples.max(1) as f64;
        let mean = self.sum / count;
        let revolutions = self.revolutions.len();
        SteadySummary {
            measured_s: self.samples as f64 * self.step_s,
            impacts: self.impacts,
            impacts_per_rev: self.impacts as f64 / revolutions.max(1) as f64,
            impacts_per_tooth: self.impacts_per_tooth.clone(),
            regime: self.regime(criteria),
            separates: self.apart > 0 || self.impacts > 0,
            apart_fraction: self.apart as f64 / count,
            torque_mean_nm: mean,
            torque_rms_nm: (self.sum_sq / count).sqrt(),
            torque_ac_rms_nm: (self.sum_sq / count - mean * mean).max(0.0).sqrt(),
            revolutions,
            speed_offset_rpm: self.speed_moments[0].0 / count * 30.0 / std::f64::consts::PI,
            motion: self.judgement(),
        }
    }
}

/// Runs `plant` for `settle_s` unrecorded, then `measure_s` while handing every block of
/// true signals to `sink`, and summarises the window.
/// Errors of the plant come back as `E`, beside the sink's own.
pub fn run_steady<E: From<RigError>>(
    plant: &mut Plant,
    settle_s: f64,
    measure_s: f64,
    criteria: &RegimeCriteria,
    mut sink: impl FnMut(&SignalBlock) -> Result<(), E>,
) -> Result<SteadySummary, E> {
    let rate = 1.0 / plant.output_step_s();
    plant.skip((settle_s * rate).round() as usize)?;
    plant.drain_impacts();
    plant.drain_revolutions();
    let total = (measure_s * rate).round() as usize;
    let mut block = SignalBlock::default();
    let mut window = SteadyWindow::new(plant.params().teeth, plant.output_step_s());
    let mut done = 0;
    while done < total {
        let n = BLOCK.min(total - done);
        block.clear();
        plant.run(n, &mut block)?;
        window.add_block(&block, plant.set_points().speed_rad_s());
        sink(&block)?;
        done += n;
    }
    window.add_impacts(plant.impacts());
    window.add_revolutions(plant.revolutions());
    Ok(window.summary(criteria))
}

/// Scale of each Poincaré state for the regime: angles left out (infinity), speeds on the
/// RMS of their vibration about the mean over the window (rad/s).
fn vibration_scale(speed_moments: &[(f64, f64); 5], count: f64) -> [f64; 10] {
    std::array::from_fn(|i| match i.checked_sub(5) {
        None => f64::INFINITY,
        Some(k) => {
            let (sum, sum_sq) = speed_moments[k];
            let mean = sum / count;
            (sum_sq / count - mean * mean).max(0.0).sqrt()
        }
    })
}
