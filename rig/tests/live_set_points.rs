//! Set points turned while the one plant (the preset's rig) runs act exactly as a knot of
//! the schedule at that instant, and what the plant was not built for is refused with
//! nothing changed.

use rig::{
    LiveCeiling, NetworkPlant, NetworkStart, RigTopology, Schedule, SetPoints, preset, preset_rig,
};

const RATE_HZ: f64 = 51_200.0;

/// The thesis preset's rig.
fn rig() -> RigTopology {
    let params = preset("basmaji-1983").expect("preset");
    preset_rig("test", "a preset's parameters in a test", &params)
}

fn set(speed_rpm: f64, load_nm: f64) -> SetPoints {
    SetPoints {
        speed_rpm,
        load_nm,
        oscillating_load_nm: 0.0,
        oscillating_load_hz: 0.0,
    }
}

#[test]
fn a_knob_turned_at_a_block_boundary_equals_a_step_in_the_schedule() {
    let rig = rig();
    let stepped = Schedule {
        speed_rpm: rig::Track::hold(600.0).step_to(1.0, 1300.0),
        load_nm: rig::Track::hold(2.712).step_to(1.0, 5.424),
        ..Schedule::constant(600.0, 2.712)
    };
    let mut scheduled =
        NetworkPlant::new(&rig, stepped, RATE_HZ, NetworkStart::Steady).expect("plant");
    let ceiling = LiveCeiling {
        speed_rpm: 1300.0,
        oscillating_load_hz: 0.0,
    };
    let mut live = NetworkPlant::live(
        &rig,
        Schedule::constant(600.0, 2.712),
        RATE_HZ,
        NetworkStart::Steady,
        ceiling,
    )
    .expect("plant");
    let (mut a, mut b) = (scheduled.block(), live.block());
    let second = RATE_HZ as usize;
    scheduled.run(2 * second, &mut a).expect("runs");
    live.run(second, &mut b).expect("runs");
    live.hold_set_points(set(1300.0, 5.424))
        .expect("within the ceiling");
    live.run(second, &mut b).expect("runs");
    assert_eq!(a.time_s, b.time_s);
    assert_eq!(a.speed_rad_s, b.speed_rad_s, "speeds differ");
    assert_eq!(a.shaft_torque_nm, b.shaft_torque_nm, "torques differ");
    assert_eq!(a.contact, b.contact);
    assert_eq!(live.set_points(), set(1300.0, 5.424));
    // The motor speeds up towards the new set point (at its torque limit, slowly).
    let mean_rpm = |from: usize| {
        let s = &b.speed_rad_s[0][from..from + second / 5];
        s.iter().sum::<f64>() / s.len() as f64 * 30.0 / std::f64::consts::PI
    };
    let (before, after) = (
        mean_rpm(second - second / 5),
        mean_rpm(2 * second - second / 5),
    );
    assert!(after > before + 10.0, "{before} → {after} rev/min");
}

#[test]
fn set_points_beyond_what_the_plant_was_built_for_are_refused_unchanged() {
    let ceiling = LiveCeiling {
        speed_rpm: 2000.0,
        oscillating_load_hz: 0.0,
    };
    let mut plant = NetworkPlant::live(
        &rig(),
        Schedule::constant(600.0, 2.712),
        RATE_HZ,
        NetworkStart::Steady,
        ceiling,
    )
    .expect("plant");
    let mut block = plant.block();
    plant.run(512, &mut block).expect("runs");
    assert!(plant.hold_set_points(set(2500.0, 2.712)).is_err());
    // The one plant takes an oscillating load at any frequency up to its ceiling's
    // (0 Hz here): one above it is refused.
    let oscillating = SetPoints {
        oscillating_load_nm: 0.5,
        oscillating_load_hz: 10.0,
        ..set(600.0, 2.712)
    };
    assert!(plant.hold_set_points(oscillating).is_err());
    assert!(plant.hold_set_points(set(-1.0, 2.712)).is_err());
    assert_eq!(plant.set_points(), set(600.0, 2.712));
}
