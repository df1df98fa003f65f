//! How a run of the one plant (the preset's rig) reaches its point (`rig::Approach`): from
//! rest the drive's current limit runs the rig up at (limit − load) / ΣJ and the speed loop
//! then holds the set speed; a slow ramp arrives at the set speed; a knock on the driven
//! gear changes its speed alone.

mod support;

use rig::{Approach, NetworkPlant, RigParams, preset_rig};

const RATE_HZ: f64 = 5_120.0;

/// The one plant of `params`' rig at the start of a run to `rpm` and `load_nm` by
/// `approach`, sampled at [`RATE_HZ`].
fn plant(approach: Approach, params: &RigParams, rpm: f64, load_nm: f64) -> NetworkPlant {
    let rig = preset_rig("test", "a preset's parameters in a test", params);
    NetworkPlant::new(
        &rig,
        approach.schedule(rpm, load_nm),
        RATE_HZ,
        approach.network_start(),
    )
    .expect("plant")
}

/// Mean of speeds (rad/s) in rev/min.
fn mean_rpm(values: &[f64]) -> f64 {
    support::mean(values) * 30.0 / std::f64::consts::PI
}

#[test]
fn from_rest_the_current_limit_runs_the_rig_up_then_the_loop_holds_the_speed() {
    let mut params = support::thesis();
    params.drive_current_limit_pct = 150.0;
    let limit_nm = params.motor_torque_limit_nm();
    let inertias = params.inertias_kgm2();
    let inertia_kgm2 = params.total_inertia_kgm2();
    let (rpm, load_nm) = (1300.0, 5.424);
    let mut plant = plant(Approach::Rest, &params, rpm, load_nm);
    let block = support::run_for(&mut plant, 40.0);
    // At t = 0 every body stands and the motor is at its limit.
    for body in 0..5 {
        assert!(block.speed_rad_s[body][0].abs() < 0.05, "body {body}");
    }
    // The one plant takes its limit from the rig's drive ratings, which round it apart
    // from `motor_torque_limit_nm` by an ulp (measured 10.681363862261428 against
    // 10.68136386226143 N m).
    let torque_nm = block.motor_torque_nm[1];
    assert!(
        (torque_nm / limit_nm - 1.0).abs() < 1e-12,
        "{torque_nm} N m at the start, limit {limit_nm} N m"
    );
    // Over 1..5 s the rig's mean speed rises at (limit − load − drag) / ΣJ.
    let rate = RATE_HZ as usize;
    let speed_at = |s: usize| {
        (0..5)
            .map(|b| {
                inertias[b] * support::mean(&block.speed_rad_s[b][s - rate / 10..s + rate / 10])
            })
            .sum::<f64>()
            / inertia_kgm2
    };
    let (w1, w5) = (speed_at(rate), speed_at(5 * rate));
    let mid_speed = 0.5 * (w1 + w5);
    let drag_nm = params.brake_drag_nm + 5.0 * params.bearing_drag_nms_per_rad * mid_speed;
    let expected = (limit_nm - load_nm - drag_nm) / inertia_kgm2;
    let got = (w5 - w1) / 4.0;
    assert!(
        (got / expected - 1.0).abs() < 0.03,
        "acceleration {got} rad/s², expected {expected}"
    );
    // The motor's speed first reaches the set speed where the run-up at the limit says.
    let arrival_s = block.speed_rad_s[0]
        .iter()
        .position(|&w| w * 30.0 / std::f64::consts::PI >= rpm)
        .expect("arrives") as f64
        / RATE_HZ;
    let estimate_s = params.run_up_from_rest_s(rpm, load_nm).expect("turns");
    assert!(
        (arrival_s / estimate_s - 1.0).abs() < 0.05,
        "arrived after {arrival_s} s, estimated {estimate_s} s"
    );
    // Over the last 5 s the loop holds the set speed.
    let late = mean_rpm(&block.speed_rad_s[0][35 * rate..]);
    assert!((late / rpm - 1.0).abs() < 0.01, "{late} rev/min");
}

#[test]
fn a_slow_run_up_and_run_down_arrive_at_the_set_speed() {
    for (approach, from_rpm) in [
        (Approach::run_up(900.0, 20.0), 250.0),
        (Approach::run_down(900.0, 20.0), 2000.0),
    ] {
        let mut plant = plant(approach, &support::thesis(), 900.0, 2.712);
        let lead_s = approach.lead_in_s();
        assert!((lead_s - (900.0_f64 - from_rpm).abs() / 20.0).abs() < 1e-9);
        let block = support::run_for(&mut plant, lead_s + 15.0);
        let rate = RATE_HZ as usize;
        let first = mean_rpm(&block.speed_rad_s[0][..rate / 10]);
        let last = mean_rpm(&block.speed_rad_s[0][block.len() - 5 * rate..]);
        assert!((first - from_rpm).abs() < 2.0, "{first}");
        assert!((last - 900.0).abs() < 9.0, "{last}");
        assert_eq!(plant.set_points().speed_rpm, 900.0);
    }
}

#[test]
fn a_knock_changes_the_driven_gears_speed_alone() {
    let driven_gear = 2;
    let mut knocked = plant(Approach::Static, &support::thesis(), 1300.0, 2.712);
    knocked.skip(RATE_HZ as usize).expect("run");
    let before = knocked.state_rad().to_vec();
    let contacts = knocked.contacts();
    knocked.kick(driven_gear, 3.0);
    let after = knocked.state_rad().to_vec();
    // The state: five angles, then five speeds, then the speed loop's two states.
    for (i, (a, b)) in after.iter().zip(&before).enumerate() {
        let expected = if i == 5 + driven_gear { b + 3.0 } else { *b };
        assert_eq!(*a, expected, "state {i}");
    }
    assert_eq!(knocked.contacts(), contacts);
    // The knock reaches the output shaft: its torque departs from the unknocked run's.
    let mut twin = plant(Approach::Static, &support::thesis(), 1300.0, 2.712);
    twin.skip(RATE_HZ as usize).expect("run");
    let (a, b) = (
        support::run_for(&mut knocked, 0.05),
        support::run_for(&mut twin, 0.05),
    );
    let most = (0..a.len())
        .map(|i| (a.shaft_torque_nm[1][i] - b.shaft_torque_nm[1][i]).abs())
        .fold(0.0, f64::max);
    assert!(most > 1.0, "{most} N m");
}
