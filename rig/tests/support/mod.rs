//! Helpers shared by the plant's integration tests.
#![allow(dead_code)]

pub mod reference;

use rig::{Plant, PlantConfig, RigParams, Schedule, SignalBlock, preset};

/// The thesis preset.
pub fn thesis() -> RigParams {
    preset("basmaji-1983").expect("the preset exists")
}

/// A plant on `schedule` at `rate_hz`.
pub fn plant(params: RigParams, schedule: Schedule, rate_hz: f64) -> Plant {
    let config = PlantConfig {
        output_rate_hz: rate_hz,
        ..PlantConfig::default()
    };
    Plant::new(params, schedule, config).expect("valid plant")
}

/// Runs `plant` for `seconds` and returns the samples.
pub fn record(plant: &mut Plant, seconds: f64) -> SignalBlock {
    let samples = (seconds / plant.output_step_s()).round() as usize;
    let mut block = SignalBlock::default();
    plant.run(samples, &mut block).expect("run completes");
    block
}

/// Amplitude and phase (complex) of the component at `freq_hz` in `signal` sampled at
/// `times_s`, by projection (exact for whole periods).
pub fn phasor(times_s: &[f64], signal: &[f64], freq_hz: f64) -> (f64, f64) {
    let w = 2.0 * std::f64::consts::PI * freq_hz;
    let n = signal.len() as f64;
    let (mut re, mut im) = (0.0, 0.0);
    for (&t, &v) in times_s.iter().zip(signal) {
        re += v * (w * t).cos();
        im -= v * (w * t).sin();
    }
    (2.0 * re / n, 2.0 * im / n)
}

/// Mean of a slice.
pub fn mean(values: &[f64]) -> f64 {
    values.iter().sum::<f64>() / values.len() as f64
}

/// Population standard deviation of a slice.
pub fn std_dev(values: &[f64]) -> f64 {
    let m = mean(values);
    (values.iter().map(|v| (v - m).powi(2)).sum::<f64>() / values.len() as f64).sqrt()
}

/// The thesis's rig with every time-varying effect off (no backlash variation, no tooth
/// shifting): loaded, it turns without vibrating.
pub fn quiet() -> RigParams {
    let mut p = thesis();
    p.backlash_variation_c1 = 0.0;
    p.tooth_shifting = false;
    p
}

/// The gears' relative angle X3 − X2 (rad) of each sample.
pub fn mesh_angle(block: &SignalBlock) -> Vec<f64> {
    block.angle_rad[2]
        .iter()
        .zip(&block.angle_rad[1])
        .map(|(x3, x2)| x3 - x2)
        .collect()
}
