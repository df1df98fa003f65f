//! Simulated seconds per wall second of rig files' plants, one thread (issue 33's target:
//! a two-stage rig, 8 bodies and two meshes, at 51.2 kHz output at least 200× real time,
//! i.e. at most 5 ms per simulated second; issue 47's: a one-stage planetary bench at
//! least 100× real time).
//!
//! Each iteration advances one simulated second at 51.2 kHz output in blocks of 2048
//! samples into one reused block, after 2 s of settling: the median time per iteration
//! is the inverse real-time factor.

use divan::Bencher;
use rig::{NetworkBlock, NetworkPlant, NetworkStart, Schedule, Track};
use testrig::scenario::read_rig_file;

fn main() {
    divan::main();
}

const RATE_HZ: usize = 51_200;
const BLOCK: usize = 2048;

fn one_second(bencher: Bencher, rig_name: &str, schedule: Schedule) {
    let path = format!(
        "{}/scenarios/rigs/{rig_name}.toml",
        env!("CARGO_MANIFEST_DIR")
    );
    let rig = read_rig_file(std::path::Path::new(&path)).expect("shipped rig");
    let mut plant =
        NetworkPlant::new(&rig, schedule, RATE_HZ as f64, NetworkStart::Steady).expect("plant");
    let mut block = NetworkBlock::new(&rig);
    plant.run(2 * RATE_HZ, &mut block).expect("settles");
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

/// The two-stage reduction at 1500 rev/min under 60 N m: steady, the teeth together.
#[divan::bench(sample_count = 20)]
fn two_stage_steady_one_second(bencher: Bencher) {
    one_second(bencher, "two-stage", Schedule::constant(1500.0, 60.0));
}

/// The two-stage reduction at 1500 rev/min, 20 N m with 40 N m oscillating at 30 Hz on
/// the brake: both meshes rattle.
#[divan::bench(sample_count = 20)]
fn two_stage_rattling_one_second(bencher: Bencher) {
    let schedule = Schedule {
        oscillating_load_nm: Track::hold(40.0),
        oscillating_load_hz: Track::hold(30.0),
        ..Schedule::constant(1500.0, 20.0)
    };
    one_second(bencher, "two-stage", schedule);
}

/// The 1983 rig as a file at the thesis plant's benchmark point, 1300 rev/min, 2.712 N m.
#[divan::bench(sample_count = 20)]
fn basmaji_1983_file_one_second(bencher: Bencher) {
    one_second(bencher, "basmaji-1983", Schedule::constant(1300.0, 2.712));
}

/// The shipped planetary bench (three planets, six meshes, one and two pairs alternating)
/// at 1500 rev/min under 50 N m: issue 47's target, 100× real time (10 ms per simulated
/// second).
#[divan::bench(sample_count = 20)]
fn planetary_bench_one_second(bencher: Bencher) {
    one_second(bencher, "planetary-bench", Schedule::constant(1500.0, 50.0));
}

/// The two-stage planetary gearbox (17 meshes) at 1500 rev/min under 100 N m.
#[divan::bench(sample_count = 20)]
fn planetary_two_stage_one_second(bencher: Bencher) {
    one_second(
        bencher,
        "planetary-two-stage",
        Schedule::constant(1500.0, 100.0),
    );
}
