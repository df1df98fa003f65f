//! Simulated seconds per wall second of the plant, one thread.
//!
//! Each iteration advances one simulated second at 51.2 kHz output, streamed as 25 blocks
//! of 2048 samples into one reused block (as a recorder consumes them), after 2 s of
//! settling: the median time per iteration is the inverse real-time factor.

use divan::Bencher;
use rig::{Plant, PlantConfig, Schedule, SignalBlock, preset};

fn main() {
    divan::main();
}

const RATE_HZ: usize = 51_200;

fn settled_plant(params: rig::RigParams, rpm: f64, load_nm: f64) -> Plant {
    let mut plant = Plant::new(
        params,
        Schedule::constant(rpm, load_nm),
        PlantConfig::default(),
    )
    .expect("valid plant");
    plant.skip(2 * RATE_HZ).expect("settles");
    plant
}

const BLOCK: usize = 2048;

fn one_second(bencher: Bencher, mut plant: Plant) {
    let mut block = SignalBlock::default();
    bencher.bench_local(|| {
        for _ in 0..RATE_HZ / BLOCK {
            block.clear();
            plant.run(BLOCK, &mut block).expect("runs");
        }
        plant.drain_impacts();
        plant.drain_revolutions();
        block.len()
    });
}

/// The benchmark point: preset, 1300 rev/min, 2.712 N m (rattling, period-2).
#[divan::bench(sample_count = 30)]
fn preset_1300rpm_2712mnm_one_second(bencher: Bencher) {
    one_second(
        bencher,
        settled_plant(preset("basmaji-1983").expect("preset"), 1300.0, 2.712),
    );
}

/// No switches at all (backlash variation and tooth shifting off, loaded at 200 rev/min):
/// the cost of the exact step and the output alone.
#[divan::bench(sample_count = 30)]
fn quiet_200rpm_one_second(bencher: Bencher) {
    let mut params = preset("basmaji-1983").expect("preset");
    params.backlash_variation_c1 = 0.0;
    params.tooth_shifting = false;
    one_second(bencher, settled_plant(params, 200.0, 2.712));
}
