//! Simulated seconds per wall second of the one plant on the 1983 rig, one thread.
//!
//! The rig is the preset's (`rig::preset_rig`, as `--preset` runs it). Each iteration
//! advances one simulated second at 51.2 kHz output, streamed as 25 blocks of 2048
//! samples into one reused block (as a recorder consumes them), after 2 s of settling:
//! the median time per iteration is the inverse real-time factor. The yardstick,
//! a plain RK4 at a 10 µs step (`rig/tests/support/reference.rs`, the same equations),
//! runs in the same process, so that the ratio of the two is free of this machine's
//! drift in speed.

#[path = "../tests/support/reference.rs"]
mod reference;

use divan::Bencher;
use rig::{NetworkPlant, NetworkStart, RigParams, Schedule, preset, preset_rig};

fn main() {
    divan::main();
}

const RATE_HZ: usize = 51_200;
const BLOCK: usize = 2048;

/// The one plant of `params`' rig at `rpm` and `load_nm`, settled 2 s.
fn settled_plant(params: &RigParams, rpm: f64, load_nm: f64) -> NetworkPlant {
    let rig = preset_rig("bench", "the 1983 rig", params);
    let schedule = Schedule::constant(rpm, load_nm);
    let mut plant = NetworkPlant::new(&rig, schedule, RATE_HZ as f64, NetworkStart::Steady)
        .expect("valid plant");
    plant.skip(2 * RATE_HZ).expect("settles");
    plant
}

fn one_second(bencher: Bencher, mut plant: NetworkPlant) {
    let mut block = plant.block();
    bencher.bench_local(|| {
        for _ in 0..RATE_HZ / BLOCK {
            block.clear();
            plant.run(BLOCK, &mut block).expect("runs");
        }
        plant.take_impacts();
        plant.take_revolutions();
        block.len()
    });
}

/// The benchmark point: preset, 1300 rev/min, 2.712 N m (rattling, period-2).
#[divan::bench(sample_count = 30)]
fn preset_1300rpm_2712mnm_one_second(bencher: Bencher) {
    let params = preset("basmaji-1983").expect("preset");
    one_second(bencher, settled_plant(&params, 1300.0, 2.712));
}

/// The benchmark point with a 15 µm profile error at mesh frequency: the cost of the
/// harmonic pair at zΩ (650 Hz here) in the state.
#[divan::bench(sample_count = 30)]
fn profile_error_1300rpm_2712mnm_one_second(bencher: Bencher) {
    let mut params = preset("basmaji-1983").expect("preset");
    params.te_mesh_frequency_um = 15.0;
    one_second(bencher, settled_plant(&params, 1300.0, 2.712));
}

/// The benchmark point with 10 µm tooth-pair spacing errors: the cost of a tooth pass
/// as an event in every mode and of the jumps it makes.
#[divan::bench(sample_count = 30)]
fn spacing_error_1300rpm_2712mnm_one_second(bencher: Bencher) {
    let mut params = preset("basmaji-1983").expect("preset");
    params.tooth_spacing_error_um = 10.0;
    one_second(bencher, settled_plant(&params, 1300.0, 2.712));
}

/// No switches at all (backlash variation and tooth shifting off, loaded at 200 rev/min):
/// the cost of the exact step and the output alone.
#[divan::bench(sample_count = 30)]
fn quiet_200rpm_one_second(bencher: Bencher) {
    let mut params = preset("basmaji-1983").expect("preset");
    params.backlash_variation_c1 = 0.0;
    params.tooth_shifting = false;
    one_second(bencher, settled_plant(&params, 200.0, 2.712));
}

/// The yardstick: classical RK4 at a 10 µs step on the same equations, from the same
/// settled state at the benchmark point (no output samples taken).
#[divan::bench(sample_count = 30)]
fn rk4_10us_1300rpm_2712mnm_one_second(bencher: Bencher) {
    let params = preset("basmaji-1983").expect("preset");
    let plant = settled_plant(&params, 1300.0, 2.712);
    let start = reference::relative_state(&plant);
    bencher.bench_local(|| {
        let mut rk4 = reference::Reference::new(&params, 1300.0, 2.712, start);
        rk4.run(1.0, 1e-5);
        rk4.impacts.len()
    });
}
