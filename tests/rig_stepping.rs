//! How the plant of any rig steps, held against itself: a run gives the same bytes
//! whatever blocks it is asked for in, a settling run's strides keep a recorded run's
//! motion, and a settling run that may be stopped takes the steps of one `skip`.

mod rig_support;

use rig::{NetworkImpact, NetworkPlant, NetworkStart, Schedule};
use rig_support::{plant, shipped};

/// The shipped rig `name` run for 0.3 s under `schedule` in blocks of `block_samples`:
/// its samples and impacts.
fn run_in_blocks(
    name: &str,
    schedule: &Schedule,
    block_samples: usize,
) -> (rig::NetworkBlock, Vec<NetworkImpact>) {
    let rig = shipped(name);
    let schedule = schedule.clone();
    let mut p = plant(&rig, schedule, NetworkStart::Steady);
    let mut block = p.block();
    let total = (0.3 * rig_support::RATE_HZ) as usize;
    let mut taken = 0;
    while taken < total {
        let n = block_samples.min(total - taken);
        p.run(n, &mut block).expect("runs");
        taken += n;
    }
    (block, p.take_impacts())
}

/// A recorded run's strides (`record_stride.rs`: 4 or 8 samples, begun at whole multiples
/// of their length) are taken on where a block ends inside one, so that blocks of one
/// sample, of 7 (ending at every place inside a stride) and of 10 000 give the same bytes.
#[test]
fn a_rattling_rig_runs_to_the_same_bytes_a_sample_at_a_time_as_in_long_blocks() {
    // The two-stage rig at 20 N m with 40 N m oscillating at 30 Hz; the 1983 rig at
    // 1300 rev/min and 2.712 N m (its teeth part and strike every revolution).
    let two_stage = Schedule {
        oscillating_load_nm: rig::Track::hold(40.0),
        oscillating_load_hz: rig::Track::hold(30.0),
        ..Schedule::constant(1500.0, 20.0)
    };
    let rattling = [
        ("two-stage", two_stage, 100),
        ("basmaji-1983", Schedule::constant(1300.0, 2.712), 50),
    ];
    for (name, schedule, least_impacts) in &rattling {
        let (name, least_impacts) = (*name, *least_impacts);
        let (long, long_impacts) = run_in_blocks(name, schedule, 10_000);
        assert!(
            long_impacts.len() > least_impacts,
            "{name} rattles: {} impacts in 0.3 s",
            long_impacts.len()
        );
        for block_samples in [1, 7] {
            let (short, short_impacts) = run_in_blocks(name, schedule, block_samples);
            assert_eq!(
                short_impacts, long_impacts,
                "{name}, blocks of {block_samples}: the same impacts at the same instants"
            );
            assert!(
                short == long,
                "{name}, blocks of {block_samples}: the same samples, bit for bit"
            );
        }
    }
}

/// The 1983 rig as a file at 1300 rev/min and 2.712 N m (its teeth part and strike every
/// revolution, the half-order motion), settled 3 s by `skip` (no samples written: strides
/// of steps begun wherever the last ended) and by `run` (strides of whole samples begun at
/// multiples of their length, `record_stride.rs`), then recorded 0.5 s: the same
/// motion, the same impacts within 0.1 µs, the torques within 1e-4 N m (the intermediate
/// shaft's AC is 7.6 N m RMS). The two round differently, and the motion amplifies
/// rounding: a kick of 1e-13 rad/s at the start parts two recorded runs by 0.14 ns and
/// 3e-8 N m after 3 s; skip and run part by 3.3 ns and 7e-7 N m (measured). A stride
/// that stepped over a switch would miss an impact or shift it by microseconds. At
/// 51.2 kHz (a step a sample, strides of up to 8) and at a sweep's 10.24 kHz (3 steps a
/// sample, strides of 3 or 6: whole output periods).
#[test]
fn a_settling_run_taken_in_strides_keeps_the_motion_of_a_recorded_one() {
    for (rate_hz, substeps) in [(rig_support::RATE_HZ, 1), (10_240.0, 3)] {
        strides_keep_the_motion(rate_hz, substeps);
    }
}

/// [`a_settling_run_taken_in_strides_keeps_the_motion_of_a_recorded_one`] at `rate_hz`,
/// whose plant takes `substeps` steps a sample.
fn strides_keep_the_motion(rate_hz: f64, substeps: u32) {
    let rig = shipped("basmaji-1983");
    let settle = (3.0 * rate_hz) as usize;
    let settled = |by_skip: bool| {
        let schedule = Schedule::constant(1300.0, 2.712);
        let mut p =
            NetworkPlant::new(&rig, schedule, rate_hz, NetworkStart::Steady).expect("plant");
        assert_eq!(p.substeps(), substeps, "{rate_hz} Hz");
        if by_skip {
            p.skip(settle).expect("settles");
        } else {
            p.run(settle, &mut p.block()).expect("settles");
        }
        let settling_impacts = p.take_impacts().len();
        let mut block = p.block();
        p.run((0.5 * rate_hz) as usize, &mut block).expect("runs");
        (settling_impacts, block, p.take_impacts())
    };
    let (skipped_impacts, skipped, skipped_after) = settled(true);
    let (run_impacts, recorded, recorded_after) = settled(false);
    assert_eq!(
        skipped_impacts, run_impacts,
        "{rate_hz} Hz: the same impacts while settling"
    );
    assert!(
        recorded_after.len() > 50,
        "{} impacts",
        recorded_after.len()
    );
    assert_eq!(skipped_after.len(), recorded_after.len(), "{rate_hz} Hz");
    for (a, b) in skipped_after.iter().zip(&recorded_after) {
        assert!(
            (a.time_s - b.time_s).abs() < 1e-7 && a.mesh == b.mesh && a.flank == b.flank,
            "{rate_hz} Hz: impact at {} s against {} s",
            a.time_s,
            b.time_s
        );
    }
    for (a, b) in skipped
        .shaft_torque_nm
        .iter()
        .zip(&recorded.shaft_torque_nm)
    {
        let worst = a
            .iter()
            .zip(b)
            .map(|(x, y)| (x - y).abs())
            .fold(0.0, f64::max);
        assert!(
            worst < 1e-4,
            "{rate_hz} Hz: shaft torques part by {worst} N m"
        );
    }
}

/// A settling run asked between stretches whether to go on (`skip_while`, a Python
/// caller's Ctrl-C) takes the steps of one `skip`, bit for bit: the 1983 rig rattling at
/// 1300 rev/min, 2.712 N m, 3 s; told to stop at its second question, it stops after
/// two stretches.
#[test]
fn a_settling_run_that_may_be_stopped_takes_the_steps_of_one_skip() {
    let rig = shipped("basmaji-1983");
    let settle = (3.0 * rig_support::RATE_HZ) as usize;
    let fresh = || {
        plant(
            &rig,
            Schedule::constant(1300.0, 2.712),
            NetworkStart::Steady,
        )
    };
    let mut whole = fresh();
    whole.skip(settle).expect("settles");
    let mut asked = fresh();
    let mut questions = 0;
    let done = asked
        .skip_while(settle, || {
            questions += 1;
            true
        })
        .expect("settles");
    assert_eq!(done, settle);
    assert_eq!(questions, settle / rig::plant::SKIP_STRETCH as usize);
    let bits =
        |p: &rig::NetworkPlant| -> Vec<u64> { p.state_rad().iter().map(|x| x.to_bits()).collect() };
    assert_eq!(bits(&asked), bits(&whole), "the same state, bit for bit");
    assert_eq!(asked.take_impacts(), whole.take_impacts());
    let mut stopped = fresh();
    let mut questions = 0;
    let done = stopped
        .skip_while(settle, || {
            questions += 1;
            questions < 2
        })
        .expect("stops");
    assert_eq!(done, 2 * rig::plant::SKIP_STRETCH as usize);
}
