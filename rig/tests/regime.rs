//! Regime classification on once-per-revolution samples, of synthetic sequences and of
//! the one plant (the preset's rig) at its motor's whole revolutions.

mod support;

use rig::{Regime, RegimeCriteria, RevolutionSample, Schedule, classify, classify_scaled};

fn samples(states: impl Iterator<Item = f64>) -> Vec<RevolutionSample> {
    states
        .enumerate()
        .map(|(n, v)| RevolutionSample {
            time_s: n as f64,
            state: [v; 10],
            shaft_torque_nm: v,
        })
        .collect()
}

#[test]
fn classifies_synthetic_sequences() {
    let criteria = RegimeCriteria::default();
    assert_eq!(
        classify(&samples((0..20).map(|_| 1.0)), &criteria),
        Regime::Periodic(1)
    );
    assert_eq!(
        classify(&samples((0..20).map(|n| (n % 2) as f64)), &criteria),
        Regime::Periodic(2)
    );
    assert_eq!(
        classify(&samples((0..40).map(|n| (n % 3) as f64)), &criteria),
        Regime::Periodic(3)
    );
    // An irrational rotation never repeats.
    let quasi = (0..60).map(|n| (n as f64 * std::f64::consts::SQRT_2 * 3.0).sin());
    assert_eq!(classify(&samples(quasi), &criteria), Regime::Aperiodic);
    // Too few samples to confirm period 2.
    assert_eq!(
        classify(&samples((0..4).map(|n| (n % 2) as f64)), &criteria),
        Regime::Aperiodic
    );
}

#[test]
fn revolution_instants_are_one_turn_of_the_motor_apart() {
    let mut plant = support::preset_plant(
        &support::thesis(),
        Schedule::constant(600.0, 2.712),
        51_200.0,
    );
    support::run_for(&mut plant, 2.0);
    let revs = plant.take_revolutions();
    assert_eq!(revs.len(), 19, "600 rev/min for 2 s from angle 0");
    for pair in revs.windows(2) {
        let period = pair[1] - pair[0];
        // The motor vibrates about the set rotation, so a turn takes 0.1 s within its
        // vibration.
        assert!((period - 0.1).abs() < 1e-4, "{period}");
    }
}

/// The value of `column` (sampled at `rate_hz` from `start_s`) at `t_s`, linear between
/// the samples either side; `None` past the last sample.
fn at_instant(column: &[f64], start_s: f64, rate_hz: f64, t_s: f64) -> Option<f64> {
    let x = (t_s - start_s) * rate_hz;
    let i = x.floor() as usize;
    let f = x - i as f64;
    Some(column.get(i)? * (1.0 - f) + column.get(i + 1)? * f)
}

/// The regime of the thesis's rig on the one plant at `rpm` and 2.712 N m, settled 20 s:
/// the bodies' speeds about the set speed (rad/s) at the motor's whole revolutions over
/// 5 s, each compared on the RMS of its vibration over the window (angles left out).
fn steady_regime(rpm: f64) -> Regime {
    let rate_hz = 51_200.0;
    let mut plant =
        support::preset_plant(&support::thesis(), Schedule::constant(rpm, 2.712), rate_hz);
    plant.skip((20.0 * rate_hz) as usize).expect("settles");
    plant.take_impacts();
    plant.take_revolutions();
    let block = support::run_for(&mut plant, 5.0);
    let revolutions = plant.take_revolutions();
    assert!(revolutions.len() >= 50);
    let set_rad_s = rpm * std::f64::consts::PI / 30.0;
    let start_s = block.time_s[0];
    let samples: Vec<RevolutionSample> = revolutions
        .iter()
        .filter_map(|&t| {
            let mut state = [0.0; 10];
            for k in 0..5 {
                state[k] = at_instant(&block.angle_rad[k], start_s, rate_hz, t)? - set_rad_s * t;
                state[5 + k] = at_instant(&block.speed_rad_s[k], start_s, rate_hz, t)? - set_rad_s;
            }
            Some(RevolutionSample {
                time_s: t,
                state,
                shaft_torque_nm: at_instant(&block.shaft_torque_nm[1], start_s, rate_hz, t)?,
            })
        })
        .collect();
    let scale: [f64; 10] = std::array::from_fn(|i| match i.checked_sub(5) {
        None => f64::INFINITY,
        Some(k) => support::std_dev(&block.speed_rad_s[k]),
    });
    classify_scaled(&samples, &scale, &RegimeCriteria::default())
}

#[test]
fn the_thesis_rig_shows_the_half_order_at_1300_rpm() {
    assert_eq!(steady_regime(1300.0), Regime::Periodic(2));
}

#[test]
fn the_thesis_rig_is_period_one_at_600_rpm() {
    assert_eq!(steady_regime(600.0), Regime::Periodic(1));
}

#[test]
fn a_regime_is_written_and_read_back_as_its_label() {
    for regime in [Regime::Periodic(1), Regime::Periodic(12), Regime::Aperiodic] {
        let text = regime.to_string();
        assert_eq!(text.parse::<Regime>(), Ok(regime));
    }
    assert_eq!(Regime::Periodic(2).to_string(), "period-2");
    assert_eq!(Regime::Periodic(2).period(), Some(2));
    assert_eq!(Regime::Aperiodic.period(), None);
    for bad in ["period-0", "period-", "period-x", "chaos", ""] {
        assert!(bad.parse::<Regime>().is_err(), "{bad:?} accepted");
    }
}
