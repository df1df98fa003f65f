//! How a run reaches its point (`rig::Approach`): from rest the drive's current limit
//! runs the rig up at (limit − load) / ΣJ and the speed loop then holds the set speed; a
//! slow ramp arrives at the set speed; a knock on the driven gear changes its speed alone.

mod support;

use rig::{Approach, PlantConfig};

const RATE_HZ: f64 = 5_120.0;

fn config() -> PlantConfig {
    PlantConfig {
        output_rate_hz: RATE_HZ,
        ..PlantConfig::default()
    }
}

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
    let mut plant = Approach::Rest
        .plant(params.clone(), rpm, load_nm, config())
        .expect("plant");
    let block = support::record(&mut plant, 40.0);
    // At t = 0 every body stands and the motor is at its limit.
    for body in 0..5 {
        assert!(block.speed_rad_s[body][0].abs() < 0.05, "body {body}");
    }
    assert_eq!(block.motor_torque_nm[1], limit_nm);
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
        let mut plant = approach
            .plant(support::thesis(), 900.0, 2.712, config())
            .expect("plant");
        let lead_s = approach.lead_in_s();
        assert!((lead_s - (900.0_f64 - from_rpm).abs() / 20.0).abs() < 1e-9);
        let block = support::record(&mut plant, lead_s + 15.0);
        let rate = RATE_HZ as usize;
        let first = mean_rpm(&block.speed_rad_s[0][..rate / 10]);
        assert!((first - from_rpm).abs() < 2.0, "{first}");
        let last = mean_rpm(&block.speed_rad_s[0][block.len() - 5 * rate..]);
        assert!((last - 900.0).abs() < 9.0, "{last}");
        assert_eq!(plant.set_points().speed_rpm, 900.0);
    }
}

#[test]
fn a_knock_changes_the_driven_gears_speed_alone() {
    let mut plant = Approach::Static
        .plant(support::thesis(), 1300.0, 2.712, config())
        .expect("plant");
    plant.skip(RATE_HZ as usize).expect("run");
    let before = plant.relative_state();
    let mode = plant.mode();
    plant.kick_driven_gear(3.0);
    let after = plant.relative_state();
    for (i, (a, b)) in after.iter().zip(&before).enumerate() {
        let expected = if i == 7 { b + 3.0 } else { *b };
        assert_eq!(*a, expected, "state {i}");
    }
    assert_eq!(plant.mode().mesh, mode.mesh);
    // The knock reaches the output shaft: its torque departs from the unknocked run's.
    let mut twin = Approach::Static
        .plant(support::thesis(), 1300.0, 2.712, config())
        .expect("plant");
    twin.skip(RATE_HZ as usize).expect("run");
    let (a, b) = (
        support::record(&mut plant, 0.05),
        support::record(&mut twin, 0.05),
    );
    let most = (0..a.len())
        .map(|i| (a.shaft_torque_nm[1][i] - b.shaft_torque_nm[1][i]).abs())
        .fold(0.0, f64::max);
    assert!(most > 1.0, "{most} N m");
}
