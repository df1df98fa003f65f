//! The physics judge's cost on one settled window: 10 s of output-shaft torque at 51.2 kHz
//! (the live panel's window) and 30 s at 10.24 kHz (a campaign case), with their
//! once-per-revolution samples, judged from the one plant's run of the preset
//! `basmaji-1983-rig`.

use divan::Bencher;
use rig::{JudgeInput, NetworkPlant, NetworkStart, Schedule, judge, preset, preset_rig};

fn main() {
    divan::main();
}

/// The intermediate shaft's torque and its samples at the motor's whole revolutions over
/// `seconds` at `rate_hz`, settled 20 s first.
fn window(seconds: f64, rate_hz: f64) -> (Vec<f64>, Vec<f64>) {
    let params = preset("basmaji-1983-rig").expect("preset");
    let rig = preset_rig("basmaji-1983-rig", "the lab's rig", &params);
    let schedule = Schedule::constant(1300.0, 2.712);
    let mut plant =
        NetworkPlant::new(&rig, schedule, rate_hz, NetworkStart::Steady).expect("valid plant");
    plant.skip((20.0 * rate_hz) as usize).expect("settles");
    plant.take_revolutions();
    let start_s = plant.time_s();
    let mut block = plant.block();
    plant
        .run((seconds * rate_hz) as usize, &mut block)
        .expect("runs");
    let intermediate = rig.shafts.iter().position(|s| s.name == "intermediate");
    let torque = block.shaft_torque_nm[intermediate.expect("the gauged shaft")].clone();
    let revolutions = plant
        .take_revolutions()
        .iter()
        .filter_map(|t| {
            torque
                .get(((t - start_s) * rate_hz).round() as usize)
                .copied()
        })
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
