//! The physics judge on signals whose answer is known: synthetic period-2 (a strong and
//! a faint half-order line, at any phase), period-3 and
//! quasi-periodic torques, a chaotic sequence from the logistic map, a torque that does not vibrate, and the
//! one plant (the preset's rig) in its linear regime and in the thesis's period-2 motion.

mod support;

use std::f64::consts::TAU;

use rig::{JudgeInput, Judgement, Motion, Schedule, judge};

const RATE_HZ: f64 = 5120.0;
const RUNNING_HZ: f64 = 1300.0 / 60.0;

/// Judges `torque(t, revolution)` sampled at [`RATE_HZ`] for `revolutions` turns at
/// [`RUNNING_HZ`], with the once-per-revolution samples at the turn marks.
fn judge_signal(revolutions: usize, torque: impl Fn(f64, usize) -> f64) -> Judgement {
    let period_s = 1.0 / RUNNING_HZ;
    let samples = (revolutions as f64 * period_s * RATE_HZ) as usize;
    let torque_nm: Vec<f64> = (0..samples)
        .map(|i| {
            let t = i as f64 / RATE_HZ;
            torque(t, (t / period_s) as usize)
        })
        .collect();
    let revolution_torque_nm: Vec<f64> = (0..revolutions)
        .map(|n| torque(n as f64 * period_s, n))
        .collect();
    judge(&JudgeInput {
        torque_nm: &torque_nm,
        rate_hz: RATE_HZ,
        running_hz: RUNNING_HZ,
        revolution_torque_nm: &revolution_torque_nm,
    })
}

/// `count` iterates of the logistic map at r = 4 (chaotic), from 0.3.
fn logistic_map(count: usize) -> Vec<f64> {
    let mut x = 0.3;
    (0..count)
        .map(|_| {
            x = 4.0 * x * (1.0 - x);
            x
        })
        .collect()
}

#[test]
fn a_synthetic_period_two_torque_is_period_two_with_a_clear_half_order_line() {
    let w = TAU * RUNNING_HZ;
    let j = judge_signal(600, |t, _| {
        2.712 + (w * t).sin() + 0.6 * (0.5 * w * t + 0.4).sin() + 0.05 * (30.0 * w * t).cos()
    });
    assert_eq!(j.motion, Motion::Periodic(2), "{j:?}");
    assert!(
        j.spread[0].unwrap() > 0.1,
        "every revolution differs: {j:?}"
    );
    assert!(
        j.spread[1].unwrap() < 1e-6,
        "every two revolutions repeat: {j:?}"
    );
    assert!(j.line_fraction[0].unwrap() < 0.8, "{j:?}");
    assert!(j.line_fraction[1].unwrap() > 0.999, "{j:?}");
    assert!(j.half_order_clear(), "{j:?}");
    assert!(j.third_order_db.unwrap() < 20.0, "no third order: {j:?}");
    assert!(j.chaos_k.unwrap() < 0.2, "{j:?}");
}

#[test]
fn a_small_half_order_part_makes_period_two_whatever_its_phase_at_the_turn_marks() {
    // 1 %, 2.6 % and 4.5 % of the AC power on the half order: the once-per-revolution
    // samples differ by less than the 5 % a period needs (or not at all, where the
    // half-order part crosses zero at the turn marks) and the period-1 lines hold 95 % of
    // the power, yet the half-order line stands far over the floor: a subharmonic on the
    // analyser's log display, and a motion that repeats every two revolutions.
    let w = TAU * RUNNING_HZ;
    for (share, phase) in [(0.01_f64, 0.3), (0.026, 0.0), (0.026, 0.2), (0.045, 0.0)] {
        let a = (share / (1.0 - share)).sqrt();
        let j = judge_signal(600, |t, _| {
            2.712 + (w * t).sin() + a * (0.5 * w * t + phase).sin()
        });
        assert!(
            j.spread[0].unwrap() <= rig::judge::SPREAD_MAX && j.line_fraction[0].unwrap() >= 0.95,
            "share {share}, phase {phase}: period 1 by samples and power alone: {j:?}"
        );
        assert!(j.half_order_clear(), "share {share}: {j:?}");
        assert_eq!(
            j.motion,
            Motion::Periodic(2),
            "share {share}, phase {phase}: {j:?}"
        );
    }
}

#[test]
fn a_third_order_line_makes_period_three_not_one() {
    let w = TAU * RUNNING_HZ;
    let j = judge_signal(600, |t, _| (w * t).sin() + 0.12 * (w * t / 3.0).sin());
    assert!(j.third_order_db.unwrap() >= 20.0, "{j:?}");
    assert_eq!(j.motion, Motion::Periodic(3), "{j:?}");
}

#[test]
fn a_clean_period_one_torque_stays_period_one() {
    let w = TAU * RUNNING_HZ;
    let j = judge_signal(600, |t, _| {
        2.712 + (w * t).sin() + 0.3 * (2.0 * w * t + 1.0).sin() + 0.05 * (30.0 * w * t).cos()
    });
    assert!(!j.half_order_clear(), "{j:?}");
    assert_eq!(j.motion, Motion::Periodic(1), "{j:?}");
}

#[test]
fn a_period_two_torque_buried_in_broadband_motion_is_not_period_two() {
    // The same lines with a random revolution-to-revolution amplitude on top: the
    // half-order line is there, but the motion does not repeat.
    let w = TAU * RUNNING_HZ;
    let kicks = logistic_map(700);
    let j = judge_signal(600, |t, n| {
        (w * t).sin() + 0.3 * (0.5 * w * t).sin() + (kicks[n] - 0.5) * (3.7 * w * t).sin()
    });
    assert_eq!(j.motion, Motion::Chaotic, "{j:?}");
    assert!(j.spread[1].unwrap() > 0.1, "{j:?}");
}

#[test]
fn a_chaotic_map_sampled_once_per_revolution_is_chaotic() {
    let w = TAU * RUNNING_HZ;
    let amplitudes = logistic_map(700);
    let j = judge_signal(600, |t, n| amplitudes[n] * (1.0 + (w * t).sin()));
    assert_eq!(j.motion, Motion::Chaotic, "{j:?}");
    assert!(j.chaos_k.unwrap() > 0.8, "{j:?}");
    assert!((1..=8).all(|k| j.spread[k - 1].unwrap() > 0.1), "{j:?}");
}

#[test]
fn an_incommensurate_second_frequency_is_quasi_periodic() {
    let w = TAU * RUNNING_HZ;
    let j = judge_signal(600, |t, _| {
        (w * t).sin() + 0.5 * (w * t * 0.5 * 5f64.sqrt()).sin()
    });
    assert_eq!(j.motion, Motion::QuasiPeriodic, "{j:?}");
}

#[test]
fn a_torque_that_does_not_vibrate_is_no_vibration() {
    let j = judge_signal(200, |_, _| 2.712);
    assert_eq!(j.motion, Motion::NoVibration, "{j:?}");
}

/// The value of `column` (sampled at `rate_hz` from `start_s`) at `t_s`, linear between
/// the samples either side; `None` past the last sample.
fn at_instant(column: &[f64], start_s: f64, rate_hz: f64, t_s: f64) -> Option<f64> {
    let x = (t_s - start_s) * rate_hz;
    let i = x.floor() as usize;
    let f = x - i as f64;
    Some(column.get(i)? * (1.0 - f) + column.get(i + 1)? * f)
}

/// The judge's verdict on the one plant of `params`' rig at `rpm` and `load_nm`, settled
/// 40 s then measured 20 s: the intermediate (gauged) shaft's torque, and its value at
/// the motor's whole revolutions.
fn plant_judgement(params: rig::RigParams, rpm: f64, load_nm: f64) -> Judgement {
    let intermediate_shaft = 1;
    let mut plant = support::preset_plant(&params, Schedule::constant(rpm, load_nm), RATE_HZ);
    plant.skip((40.0 * RATE_HZ) as usize).expect("settles");
    plant.take_impacts();
    plant.take_revolutions();
    let block = support::run_for(&mut plant, 20.0);
    let torque_nm = &block.shaft_torque_nm[intermediate_shaft];
    let revolution_torque_nm: Vec<f64> = plant
        .take_revolutions()
        .iter()
        .filter_map(|&t| at_instant(torque_nm, block.time_s[0], RATE_HZ, t))
        .collect();
    judge(&JudgeInput {
        torque_nm,
        rate_hz: RATE_HZ,
        running_hz: rpm / 60.0,
        revolution_torque_nm: &revolution_torque_nm,
    })
}

#[test]
fn the_plant_in_its_linear_regime_is_period_one() {
    // Teeth never part: no backlash variation, no tooth shifting, a small once-per-rev
    // error torque under a heavy load. The linear plant forced once per revolution can
    // only answer at the running speed and its harmonics.
    let params = rig::RigParams {
        backlash_variation_c1: 0.0,
        tooth_shifting: false,
        gear_error_c2_nm: 0.2,
        ..support::thesis()
    };
    let j = plant_judgement(params, 700.0, 5.424);
    assert_eq!(j.motion, Motion::Periodic(1), "{j:?}");
    assert!(j.line_fraction[0].unwrap() > 0.999, "{j:?}");
    assert!(j.spread[0].unwrap() < 1e-3, "{j:?}");
}

#[test]
fn the_thesis_rig_at_1300_rpm_is_cleanly_period_two() {
    let j = plant_judgement(support::thesis(), 1300.0, 2.712);
    assert_eq!(j.motion, Motion::Periodic(2), "{j:?}");
    assert!(j.half_order_clear(), "{j:?}");
    assert!(j.chaos_k.unwrap() < 0.2, "{j:?}");
}
