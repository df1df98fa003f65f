//! A live plant (`NetworkPlant::live`, the panel's and a scenario's commands): the set
//! points it takes and those beyond its ceiling it refuses.

mod rig_support;

use rig::{NetworkPlant, NetworkStart, Schedule};
use rig_support::shipped;

/// A live plant refuses set points above its ceiling and takes its own schedule's: with a
/// ceiling of 1300 rev/min and no oscillating load, a schedule whose brake oscillates at
/// 50 Hz keeps its 50 Hz through a speed change, while 60 Hz and 1400 rev/min are
/// refused, the motion untouched (the set points stay as they were).
#[test]
fn a_live_plant_takes_its_schedules_set_points_and_refuses_beyond_its_ceiling() {
    let rig = shipped("basmaji-1983");
    let schedule = Schedule {
        oscillating_load_nm: rig::Track::hold(0.5),
        oscillating_load_hz: rig::Track::hold(50.0),
        ..Schedule::constant(600.0, 2.712)
    };
    let ceiling = rig::LiveCeiling {
        speed_rpm: 1300.0,
        oscillating_load_hz: 0.0,
    };
    let mut p =
        NetworkPlant::live(&rig, schedule, 51_200.0, NetworkStart::Steady, ceiling).expect("plant");
    let before = p.set_points();
    let faster = rig::SetPoints {
        speed_rpm: 800.0,
        ..before
    };
    p.hold_set_points(faster)
        .expect("the schedule's own 50 Hz is taken");
    for refused in [
        rig::SetPoints {
            oscillating_load_hz: 60.0,
            ..faster
        },
        rig::SetPoints {
            speed_rpm: 1400.0,
            ..faster
        },
    ] {
        assert!(p.hold_set_points(refused).is_err(), "{refused:?}");
    }
    let mut block = p.block();
    p.run(512, &mut block).expect("runs");
    assert_eq!(p.set_points(), faster);
}
