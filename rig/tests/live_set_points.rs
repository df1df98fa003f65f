//! Set points turned while the plant runs act exactly as a knot of the schedule at that
//! instant, and what the plant was not built for is refused with nothing changed.

use rig::{LiveCeiling, Plant, PlantConfig, Schedule, SetPoints, SignalBlock, preset};

const RATE_HZ: f64 = 51_200.0;

fn config(ceiling: Option<LiveCeiling>) -> PlantConfig {
    PlantConfig {
        output_rate_hz: RATE_HZ,
        live_ceiling: ceiling,
        ..PlantConfig::default()
    }
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
    let params = preset("basmaji-1983").expect("preset");
    let stepped = Schedule {
        speed_rpm: rig::Track::hold(600.0).step_to(1.0, 1300.0),
        load_nm: rig::Track::hold(2.712).step_to(1.0, 5.424),
        ..Schedule::constant(600.0, 2.712)
    };
    let mut scheduled = Plant::new(params.clone(), stepped, config(None)).expect("plant");
    let ceiling = LiveCeiling {
        speed_rpm: 1300.0,
        oscillating_load_hz: 0.0,
    };
    let mut live = Plant::new(
        params,
        Schedule::constant(600.0, 2.712),
        config(Some(ceiling)),
    )
    .expect("plant");
    let (mut a, mut b) = (SignalBlock::default(), SignalBlock::default());
    let second = RATE_HZ as usize;
    scheduled.run(2 * second, &mut a).expect("runs");
    live.run(second, &mut b).expect("runs");
    live.set_points_from_now(set(1300.0, 5.424))
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
    let params = preset("basmaji-1983").expect("preset");
    let ceiling = LiveCeiling {
        speed_rpm: 2000.0,
        oscillating_load_hz: 0.0,
    };
    let mut plant = Plant::new(
        params,
        Schedule::constant(600.0, 2.712),
        config(Some(ceiling)),
    )
    .expect("plant");
    let mut block = SignalBlock::default();
    plant.run(512, &mut block).expect("runs");
    assert!(plant.set_points_from_now(set(2500.0, 2.712)).is_err());
    let oscillating = SetPoints {
        oscillating_load_nm: 0.5,
        oscillating_load_hz: 0.0,
        ..set(600.0, 2.712)
    };
    assert!(plant.set_points_from_now(oscillating).is_err());
    assert!(plant.set_points_from_now(set(-1.0, 2.712)).is_err());
    assert_eq!(plant.set_points(), set(600.0, 2.712));
}
