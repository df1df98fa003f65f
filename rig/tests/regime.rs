//! Regime classification on once-per-revolution samples.

mod support;

use rig::{Regime, RegimeCriteria, RevolutionSample, Schedule, classify};

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
fn revolution_samples_are_one_turn_of_the_driving_gear_apart() {
    let mut plant = support::plant(
        support::thesis(),
        Schedule::constant(600.0, 2.712),
        51_200.0,
    );
    support::record(&mut plant, 2.0);
    let revs = plant.revolutions();
    assert_eq!(revs.len(), 19, "600 rev/min for 2 s from angle 0");
    for pair in revs.windows(2) {
        let period = pair[1].time_s - pair[0].time_s;
        // The gear vibrates about the set rotation, so a turn takes 0.1 s within its vibration.
        assert!((period - 0.1).abs() < 1e-4, "{period}");
    }
}

fn steady_regime(rpm: f64) -> Regime {
    let mut plant = support::plant(support::thesis(), Schedule::constant(rpm, 2.712), 51_200.0);
    let summary = rig::run_steady(&mut plant, 20.0, 5.0, &RegimeCriteria::default(), |_| {
        Ok::<(), rig::RigError>(())
    })
    .expect("runs");
    assert!(summary.revolutions >= 50);
    summary.regime
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
