//! The motion's repetition as runs report it (`period-k`, `aperiodic`), and the
//! revolution instants it is judged at: the one plant's (the preset's rig) motor's whole
//! revolutions.

mod support;

use rig::{Regime, Schedule};

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
