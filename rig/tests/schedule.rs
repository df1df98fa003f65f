//! Set points that change during a run: the speed loop follows steps and ramps, the brake
//! follows load steps, and the motor torque respects its limit; on the one plant of the
//! thesis's rig (`rig::preset_rig`).

mod support;

use rig::{Schedule, Track};

fn mean_speed_rpm(block: &rig::NetworkBlock, from: usize, to: usize) -> f64 {
    support::mean(&block.speed_rad_s[0][from..to]) * 30.0 / std::f64::consts::PI
}

#[test]
fn the_speed_loop_follows_a_speed_step() {
    let schedule = Schedule {
        speed_rpm: Track::hold(600.0).step_to(1.0, 700.0),
        ..Schedule::constant(600.0, 2.712)
    };
    let mut plant = support::preset_plant(&support::thesis(), schedule, 5_120.0);
    let block = support::run_for(&mut plant, 12.0);
    let rate = 5_120;
    assert!((mean_speed_rpm(&block, 0, rate) - 600.0).abs() < 0.5);
    // A 0.5 Hz loop with ζ 0.7 has settled 10 s later.
    assert!(
        (mean_speed_rpm(&block, 10 * rate, 12 * rate) - 700.0).abs() < 0.5,
        "{}",
        mean_speed_rpm(&block, 10 * rate, 12 * rate)
    );
    // The set points and the absolute angle stay continuous through the step.
    let jump = (1..block.len())
        .map(|i| block.angle_rad[0][i] - block.angle_rad[0][i - 1])
        .fold(0.0, f64::max);
    assert!(
        jump < 700.0 / 60.0 * std::f64::consts::TAU / 5_120.0 * 1.5,
        "{jump}"
    );
}

#[test]
fn the_speed_loop_tracks_a_ramp() {
    let schedule = Schedule {
        speed_rpm: Track::hold(400.0).ramp_to(1.0, 11.0, 700.0),
        ..Schedule::constant(400.0, 2.712)
    };
    let mut plant = support::preset_plant(&support::thesis(), schedule, 5_120.0);
    let block = support::run_for(&mut plant, 11.0);
    let rate = 5_120;
    // PI on the filtered speed follows a ramp with no steady error in the filtered speed,
    // so the shaft runs ahead of the set point by the filter's lag τ·α (τ = 1/(2π·2 Hz),
    // α = 30 rev/min per s): at t = 9..10 s the mean set point is 655 rev/min. The ramp
    // needs J·α + load = 0.845 × 3.14 + 2.712 = 5.4 N m, within the drive's 7.12 N m.
    let tau = 1.0 / (2.0 * std::f64::consts::PI * 2.0);
    let got = mean_speed_rpm(&block, 9 * rate, 10 * rate);
    assert!((got - (655.0 + tau * 30.0)).abs() < 0.2, "{got}");
    // The set point ends on the ramp's last value.
    assert!(
        (plant.set_points().speed_rpm - 700.0).abs() < 0.2,
        "{}",
        plant.set_points().speed_rpm
    );
}

#[test]
fn a_load_step_reaches_the_output_shaft_and_the_motor() {
    let schedule = Schedule {
        load_nm: Track::hold(1.356).step_to(0.5, 4.068),
        ..Schedule::constant(300.0, 1.356)
    };
    let mut p = support::thesis();
    p.backlash_variation_c1 = 0.0;
    p.tooth_shifting = false;
    let mut plant = support::preset_plant(&p, schedule, 5_120.0);
    let block = support::run_for(&mut plant, 10.0);
    let rate = 5_120;
    let before = support::mean(&block.shaft_torque_nm[1][..rate / 2]);
    let after = support::mean(&block.shaft_torque_nm[1][8 * rate..]);
    let motor = support::mean(&block.motor_torque_nm[8 * rate..]);
    assert!((before - 1.356).abs() < 1e-6, "{before}");
    assert!((after - 4.068).abs() < 0.01, "{after}");
    assert!((motor - 4.068).abs() < 0.01, "{motor}");
}

#[test]
fn the_motor_torque_stays_within_its_limit() {
    let p = support::thesis();
    let limit = p.motor_torque_limit_nm();
    let schedule = Schedule {
        speed_rpm: Track::hold(300.0).step_to(0.2, 1500.0),
        ..Schedule::constant(300.0, 2.712)
    };
    let mut plant = support::preset_plant(&p, schedule, 5_120.0);
    let block = support::run_for(&mut plant, 3.0);
    let peak = block
        .motor_torque_nm
        .iter()
        .copied()
        .fold(f64::NEG_INFINITY, f64::max);
    assert!(
        (peak - limit).abs() < 1e-12,
        "a 1200 rev/min step saturates the drive: peak {peak} vs {limit}"
    );
    assert!(
        block
            .motor_torque_nm
            .iter()
            .all(|t| t.abs() <= limit + 1e-12)
    );
}

#[test]
fn speed_steps_at_no_load_ride_the_limit_without_chatter_or_windup() {
    // The subharmonic survey at no load: steps of the speed set point every 18 s. With the
    // integrator frozen at the limit the command slid along it after the 1900 rev/min step
    // and the drive switched in and out of the limit for ever (chatter at t = 110.34 s).
    let mut p = support::thesis();
    p.centre_distance_shift_m = 0.73e-3 / (2.0 * 20f64.to_radians().tan());
    let limit = p.motor_torque_limit_nm();
    let speeds = [800.0, 1000.0, 1100.0, 1300.0, 1500.0, 1700.0, 1900.0];
    let mut speed = Track::hold(speeds[0]);
    for (i, rpm) in speeds.iter().enumerate() {
        speed = speed.step_to(18.0 * i as f64, *rpm);
    }
    let schedule = Schedule {
        speed_rpm: speed,
        ..Schedule::constant(800.0, 0.0)
    };
    let mut plant = support::preset_plant(&p, schedule, 51_200.0);
    plant
        .skip(108 * 51_200)
        .expect("no chatter through five steps");
    let block = support::run_for(&mut plant, 18.0);
    let rate = 51_200;
    let at_limit = block
        .motor_torque_nm
        .iter()
        .filter(|t| (**t - limit).abs() < 1e-9)
        .count();
    assert!(
        at_limit > rate / 10,
        "a 200 rev/min step saturates the drive"
    );
    assert!(
        block
            .motor_torque_nm
            .iter()
            .all(|t| t.abs() <= limit + 1e-9)
    );
    let settled = mean_speed_rpm(&block, 16 * rate, 18 * rate);
    assert!((settled - 1900.0).abs() < 0.5, "{settled}");
    let peak = (0..16 * rate)
        .map(|i| block.speed_rad_s[0][i] * 30.0 / std::f64::consts::PI)
        .fold(f64::NEG_INFINITY, f64::max);
    assert!(
        peak < 1900.0 + 0.1 * 200.0,
        "overshoot {peak} rev/min: integrator wound up"
    );
}

#[test]
fn the_drive_holds_a_load_within_its_current_limit_and_sags_beyond_it() {
    // The 1983 drive's nameplate (2.0 hp, F.L.C. 10.0 A, max 2000 rev/min): the torque at
    // full-load current is 1491.4 W / 209.44 rad/s = 7.121 N m, the torque constant
    // 0.7121 N m/A; a 150 % current limit bounds the torque at 10.68 N m.
    let mut p = support::thesis();
    p.tooth_shifting = false;
    p.drive_current_limit_pct = 150.0;
    let full_load = 2.0 * 745.699_872 / (2000.0 * std::f64::consts::PI / 30.0);
    assert!((p.torque_constant_nm_per_a() - full_load / 10.0).abs() < 1e-12);
    let limit = p.motor_torque_limit_nm();
    assert!((limit - 1.5 * full_load).abs() < 1e-12);
    let inertia: f64 = p.inertias_kgm2().iter().sum();
    let rpm = 600.0;
    let set = rpm * std::f64::consts::PI / 30.0;
    let run = |load_nm: f64| {
        let schedule = Schedule {
            load_nm: Track::hold(1.0).step_to(1.0, load_nm),
            ..Schedule::constant(rpm, 1.0)
        };
        let mut plant = support::preset_plant(&p, schedule, 5_120.0);
        support::run_for(&mut plant, 30.0)
    };
    // 9 N m: beyond the old 7.12 N m limit, within 10.68: the speed holds.
    let held = run(9.0);
    let tail = &held.speed_rad_s[0][25 * 5_120..];
    let speed = support::mean(tail);
    assert!(
        (speed - set).abs() < 0.005 * set,
        "{speed} rad/s against {set}"
    );
    let torque = support::mean(&held.motor_torque_nm[25 * 5_120..]);
    assert!(
        (torque - 9.0).abs() < 0.05,
        "the drive carries the load: {torque} N m"
    );
    // 12 N m: beyond it the motor sits at its limit and the rig's angular momentum
    // Σ J ω falls at load − limit, the speed sagging as the 1983 report says.
    let sagging = run(12.0);
    let inertias = p.inertias_kgm2();
    let momentum = |t: f64| {
        let k = (t * 5_120.0) as usize;
        (0..5)
            .map(|i| inertias[i] * sagging.speed_rad_s[i][k])
            .sum::<f64>()
            / inertia
    };
    let slope = (momentum(4.0) - momentum(2.0)) / 2.0;
    let expected = (limit - 12.0) / inertia;
    assert!(
        (slope - expected).abs() < 0.03 * expected.abs(),
        "falls at {slope} rad/s², (limit − load)/ΣJ = {expected}"
    );
    let at_limit = sagging.motor_torque_nm[2 * 5_120..4 * 5_120]
        .iter()
        .all(|t| (t - limit).abs() < 1e-9);
    assert!(
        at_limit,
        "the motor stays at its current limit while the speed sags"
    );
}
