//! The physics judge's cost on one settled window: 10 s of output-shaft torque at 51.2 kHz
//! (the live panel's window) and 30 s at 10.24 kHz (a campaign case), with their
//! once-per-revolution samples, judged from the plant's own run.

use divan::Bencher;
use rig::{JudgeInput, Plant, PlantConfig, Schedule, SignalBlock, judge, preset};

fn main() {
    divan::main();
}

/// The torque and its revolution samples over `seconds` at `rate_hz`, settled first.
fn window(seconds: f64, rate_hz: f64) -> (Vec<f64>, Vec<f64>) {
    let config = PlantConfig {
        output_rate_hz: rate_hz,
        ..PlantConfig::default()
    };
    let params = preset("basmaji-1983-rig").expect("preset");
    let mut plant =
        Plant::new(params, Schedule::constant(1300.0, 2.712), config).expect("valid plant");
    plant.skip((20.0 * rate_hz) as usize).expect("settles");
    plant.drain_revolutions();
    let mut block = SignalBlock::default();
    plant
        .run((seconds * rate_hz) as usize, &mut block)
        .expect("runs");
    let torque = block.shaft_torque_nm[rig::INTERMEDIATE_SHAFT].clone();
    let revolutions = plant
        .drain_revolutions()
        .iter()
        .map(|r| r.shaft_torque_nm)
        .collect();
    (torque, revolutions)
}

fn bench_window(bencher: Bencher, seconds: f64, rate_hz: f64) {
    let (torque, revolutions) = window(seconds, rate_hz);
    bencher.bench_local(|| {
        judge(&JudgeInput {
            torque_nm: &torque,
            rate_hz,
            running_hz: 1300.0 / 60.0,
            revolution_torque_nm: &revolutions,
        })
    });
}

/// The live panel's 10 s window at 51.2 kHz.
#[divan::bench(sample_count = 10)]
fn panel_window_10s_51200hz(bencher: Bencher) {
    bench_window(bencher, 10.0, 51_200.0);
}

/// A campaign case's 30 s window at 10.24 kHz.
#[divan::bench(sample_count = 10)]
fn campaign_case_30s_10240hz(bencher: Bencher) {
    bench_window(bencher, 30.0, 10_240.0);
}
