//! A run at fixed set points: settle, then measure what the thesis read off the rig.

use serde::Serialize;

use crate::error::RigError;
use crate::plant::Plant;
use crate::regime::{RegimeCriteria, classify_scaled, impacts_per_tooth};
use crate::signals::{INTERMEDIATE_SHAFT, SignalBlock};

/// Samples advanced per call while measuring.
const BLOCK: usize = 8192;

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
    /// `period-k` or `aperiodic`, from once-per-revolution samples.
    pub regime: String,
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
    let (mut sum, mut sum_sq, mut apart, mut done) = (0.0, 0.0, 0_usize, 0_usize);
    let mut speed_moments = [(0.0, 0.0); 5];
    while done < total {
        let n = BLOCK.min(total - done);
        block.clear();
        plant.run(n, &mut block)?;
        for &torque in &block.shaft_torque_nm[INTERMEDIATE_SHAFT] {
            sum += torque;
            sum_sq += torque * torque;
        }
        apart += block.contact.iter().filter(|&&c| c == 0).count();
        for (moments, speeds) in speed_moments.iter_mut().zip(&block.speed_rad_s) {
            for &w in speeds {
                let v = w - plant.set_points().speed_rad_s();
                moments.0 += v;
                moments.1 += v * v;
            }
        }
        sink(&block)?;
        done += n;
    }
    let count = total.max(1) as f64;
    let mean = sum / count;
    let impacts = plant.impacts();
    let revolutions = plant.revolutions();
    let teeth = plant.params().teeth;
    Ok(SteadySummary {
        measured_s: total as f64 / rate,
        impacts: impacts.len(),
        impacts_per_rev: impacts.len() as f64 / revolutions.len().max(1) as f64,
        impacts_per_tooth: impacts_per_tooth(teeth, impacts.iter().map(|i| i.tooth)),
        regime: classify_scaled(
            revolutions,
            &vibration_scale(&speed_moments, count),
            criteria,
        )
        .label(),
        separates: apart > 0 || !impacts.is_empty(),
        apart_fraction: apart as f64 / count,
        torque_mean_nm: mean,
        torque_rms_nm: (sum_sq / count).sqrt(),
        torque_ac_rms_nm: (sum_sq / count - mean * mean).max(0.0).sqrt(),
        revolutions: revolutions.len(),
    })
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
