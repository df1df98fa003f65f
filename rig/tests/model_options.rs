//! The model options beyond the thesis (off in its presets), each against what it must do
//! physically: bearing drag, the eddy-current brake's characteristic, the transmission
//! error as a displacement, tooth-pair spacing errors, a smoothed mesh stiffness; on the
//! one plant of the thesis's rig (`rig::preset_rig`).

mod support;

use rig::{GearGeometry, NetworkBlock, RigParams, Schedule};

const LOAD_NM: f64 = 2.712;

#[test]
fn bearing_drag_loads_each_shaft_with_the_drag_behind_it_and_starts_static() {
    let mut p = support::quiet();
    p.bearing_drag_nms_per_rad = 0.002;
    let rpm = 600.0;
    let drag = 0.002 * rpm * std::f64::consts::PI / 30.0;
    let mut plant = support::preset_plant(&p, Schedule::constant(rpm, LOAD_NM), 10_240.0);
    let block = support::run_for(&mut plant, 2.0);
    // Intermediate shaft (K34): the brake's load and the drag of M4 and M5; input shaft
    // (K12): M2 … M5; the motor: all five.
    for (torque, bodies) in [
        (&block.shaft_torque_nm[1], 2.0),
        (&block.shaft_torque_nm[0], 4.0),
        (&block.motor_torque_nm, 5.0),
    ] {
        let expected = LOAD_NM + bodies * drag;
        assert!(
            (support::mean(torque) - expected).abs() < 1e-9,
            "{} vs {expected}",
            support::mean(torque)
        );
        assert!(
            support::std_dev(torque) < 1e-9,
            "the steady state is not steady: {}",
            support::std_dev(torque)
        );
    }
}

#[test]
fn the_brake_characteristic_is_its_slope_at_the_set_point() {
    // T(ω) = T_set g(ω)/g(Ω), g = 2x/(1 + x²): linearised, a slope T_set (1 − x²)/((1 + x²) Ω).
    // At 600 rev/min (x = 2/3, as the thesis's plant was held at 1000 against 1500): the
    // one plant balances its propagator for the rig's fastest rate with the set slope
    // alone (the characteristic's left out), so the two runs part by rounding (1e-14 N m
    // after one sample), and at 1000 rev/min the rattling grows that to 2e-5 N m in 2 s
    // (measured); at 600 it stays within 1.3e-11 N m.
    let (rpm, critical_rpm) = (600.0, 900.0);
    let omega = rpm * std::f64::consts::PI / 30.0;
    let x2: f64 = (rpm / critical_rpm).powi(2);
    let slope = LOAD_NM * (1.0 - x2) / ((1.0 + x2) * omega);
    let mut with_characteristic = support::thesis();
    with_characteristic.brake_critical_speed_rpm = critical_rpm;
    let mut with_slope = support::thesis();
    with_slope.brake_speed_slope_nms_per_rad = slope;
    let run = |p: RigParams| {
        let mut plant = support::preset_plant(&p, Schedule::constant(rpm, LOAD_NM), 10_240.0);
        support::run_for(&mut plant, 2.0).shaft_torque_nm[2].clone()
    };
    let (a, b) = (run(with_characteristic), run(with_slope));
    assert!(
        support::std_dev(&a) > 1e-3,
        "the case does not vibrate: it shows nothing"
    );
    let worst = a
        .iter()
        .zip(&b)
        .map(|(x, y)| (x - y).abs())
        .fold(0.0, f64::max);
    assert!(worst < 1e-9, "differs by {worst} N m");
    // The brake damps below its critical speed and feeds vibration above it: with the
    // same vibration, the brake's shaft rings less at 600 than with the slope reversed,
    // the brake above its critical speed (600²/900 rev/min: x → 1/x reverses the slope;
    // a rig refuses a negative slope as a setting).
    let mut reversed = support::thesis();
    reversed.brake_critical_speed_rpm = rpm * rpm / critical_rpm;
    let x_reversed: f64 = (critical_rpm / rpm).powi(2);
    let reversed_slope = LOAD_NM * (1.0 - x_reversed) / ((1.0 + x_reversed) * omega);
    assert!((reversed_slope + slope).abs() < 1e-12 * slope);
    assert!(slope > 0.0);
    assert!(support::std_dev(&run(reversed)) > support::std_dev(&a));
}

/// Runs `p` at `rpm` under load for `periods` of `freq_hz` (samples at `rate_hz`) and
/// returns the phasor (rad) of the gears' relative angle θ3 − θ2 at `freq_hz`, with the
/// recorded block; the teeth must stay in contact throughout.
fn mesh_phasor(
    p: RigParams,
    rpm: f64,
    freq_hz: f64,
    periods: f64,
    rate_hz: f64,
) -> ((f64, f64), NetworkBlock) {
    let mut plant = support::preset_plant(&p, Schedule::constant(rpm, LOAD_NM), rate_hz);
    let block = support::run_for(&mut plant, periods / freq_hz);
    assert!(
        block.contact[0].iter().all(|&c| c == 1),
        "the teeth separated"
    );
    let d = support::mesh_lag_rad(&block);
    (support::phasor(&block.time_s, &d, freq_hz), block)
}

/// The phasor is `amplitude_rad` cos (in phase with the set rotation's φ = 0 at the
/// start) within 2 % in size and 0.05 rad in phase.
fn assert_follows((re, im): (f64, f64), amplitude_rad: f64) {
    let amplitude = re.hypot(im);
    assert!(
        (amplitude / amplitude_rad - 1.0).abs() < 0.02,
        "{amplitude:e} rad vs {amplitude_rad:e} rad"
    );
    assert!(re > 0.0 && im.abs() < 0.05 * re, "phase: {re:e} + {im:e} i");
}

#[test]
fn a_quasi_static_transmission_error_turns_the_driven_gear_by_the_error() {
    // At 20 rev/min (0.33 Hz, far below the 17.8 Hz fundamental) under load the teeth stay
    // in contact and the driven gear follows the driving one displaced by e = E cos φ.
    let mut p = support::quiet();
    p.te_once_per_rev_um = 20.0;
    let e_rad = 20e-6 / GearGeometry::of(&p).pitch_radius_m;
    let (rpm, hz) = (20.0, 20.0 / 60.0);
    assert_follows(mesh_phasor(p, rpm, hz, 2.0, 1024.0).0, e_rad);
    // The error torques C2 move the gears apart by no more than the shaft deflection they cause.
    let mut torque = support::quiet();
    torque.gear_error_c2_nm = 0.5;
    let ((re, im), _) = mesh_phasor(torque, rpm, hz, 2.0, 1024.0);
    assert!(
        re.hypot(im) < 0.01 * e_rad,
        "C2 moved the mesh by {:e} rad",
        re.hypot(im)
    );
}

#[test]
fn a_quasi_static_profile_error_turns_the_driven_gear_by_the_error_at_mesh_frequency() {
    // At 2 rev/min the mesh frequency is 30 x 1/30 Hz = 1 Hz, far below the 17.8 Hz
    // fundamental: under load the driven gear follows the driving one displaced by
    // e = P cos zφ, tooth by tooth.
    let mut p = support::quiet();
    p.te_mesh_frequency_um = 5.0;
    let p_rad = 5e-6 / GearGeometry::of(&p).pitch_radius_m;
    let mesh_hz = f64::from(p.teeth) * 2.0 / 60.0;
    let (phasor, block) = mesh_phasor(p.clone(), 2.0, mesh_hz, 3.0, 256.0);
    assert_follows(phasor, p_rad);
    // The recorded mesh torque carries the load (the error moves the gears, not the torque,
    // when they follow it quasi-statically): within 1 % of the load.
    let worst = support::mesh_torque_nm(&p, &block)
        .iter()
        .map(|t| (t - LOAD_NM).abs())
        .fold(0.0, f64::max);
    assert!(worst < 0.01 * LOAD_NM, "mesh torque departs by {worst} N m");
}

#[test]
fn a_smoothed_mesh_stiffness_steps_through_its_staircase_for_the_set_share_of_each_pitch() {
    // Quasi-static under load, the mesh torque over the tooth overlap is the stiffness in
    // force: K23 with one pair, 2 K23 with two, and with smoothing w four steps between
    // them at K23 (1 + (l − ½)/4), each held for w/4 of the pitch at both changes.
    let share_at = |smoothing: f64| {
        let mut p = support::quiet();
        p.mesh_pairs = rig::MeshPairs::Alternating;
        p.mesh_stiffness_smoothing = smoothing;
        let k = p.k23_mesh_nm_per_rad;
        let b = GearGeometry::of(&p).half_backlash_rad;
        let mut plant = support::preset_plant(&p, Schedule::constant(20.0, LOAD_NM), 10_240.0);
        let block = support::run_for(&mut plant, 1.0);
        let torque = support::mesh_torque_nm(&p, &block);
        let stiffness: Vec<f64> = (0..block.len())
            .map(|n| {
                let overlap = -(block.angle_rad[2][n] - block.angle_rad[1][n]) - b;
                torque[n] / overlap / k
            })
            .collect();
        let share = |level: f64| {
            stiffness
                .iter()
                .filter(|s| (*s / level - 1.0).abs() < 0.01)
                .count() as f64
                / stiffness.len() as f64
        };
        let steps: Vec<f64> = (1..=4)
            .map(|l| share(1.0 + (f64::from(l) - 0.5) / 4.0))
            .collect();
        (share(1.0), share(2.0), steps)
    };
    let (one, two, steps) = share_at(0.0);
    assert!(
        steps.iter().all(|&s| s == 0.0),
        "steps without smoothing: {steps:?}"
    );
    assert!(one + two > 0.97, "one {one}, two {two}");
    let w = 0.2;
    let (one_s, two_s, steps) = share_at(w);
    for s in &steps {
        assert!(
            (s - w / 2.0).abs() < 0.01,
            "each step held {s} of the time, expected {}",
            w / 2.0
        );
    }
    // The staircase takes its time half from each neighbouring zone.
    assert!(
        (one - one_s - w).abs() < 0.02 && (two - two_s - w).abs() < 0.02,
        "{one} → {one_s}, {two} → {two_s}"
    );
}

/// Tooth-pair spacing errors: quasi-statically (1 rev/min, each pair in mesh for 2 s) under
/// load the driven gear follows the driving one displaced by the spacing error of the
/// pair in mesh, pair after pair, as seeded. The pair in mesh is the one whose tooth
/// period of the driving gear's angle holds it (pair p over θ2 in [p, p + 1) pitches,
/// tooth p mod z of each gear, as the plant numbers them).
#[test]
fn each_tooth_pair_displaces_the_mesh_by_its_own_spacing_error() {
    let mut p = support::quiet();
    p.tooth_spacing_error_um = 10.0;
    // Damping in the shafts, so that the ringing after each pass dies within the pitch.
    p.c12_input_shaft_nms_per_rad = 0.6;
    p.c34_intermediate_shaft_nms_per_rad = 1.0;
    // Each pair's error as the rig's mesh draws it (m along the line of action, per tooth
    // of each gear), as a relative rotation of the gears (rad).
    let mesh = &rig::preset_rig("spacing", "spacing errors", &p).meshes[0];
    let [driver, driven] = rig::spacing::mesh_spacing_m(mesh);
    let r_b = support::base_radius_m(&p);
    let errors: Vec<f64> = driver
        .iter()
        .zip(&driven)
        .map(|(a, b)| (a + b) / r_b)
        .collect();
    assert_eq!(errors.len(), p.teeth as usize);
    let rms = (errors.iter().map(|e| e * e).sum::<f64>() / errors.len() as f64).sqrt();
    let mut plant = support::preset_plant(&p, Schedule::constant(1.0, LOAD_NM), 512.0);
    let block = support::run_for(&mut plant, 64.0);
    let relative = support::mesh_lag_rad(&block);
    let pitch = GearGeometry::of(&p).tooth_pitch_rad;
    let tooth: Vec<usize> = block.angle_rad[1]
        .iter()
        .map(|theta2| ((theta2 / pitch).floor() as i64).rem_euclid(i64::from(p.teeth)) as usize)
        .collect();
    // Each stretch with one pair in mesh: the mean relative angle over its second half.
    let mut stretches: Vec<(usize, f64)> = Vec::new();
    let mut start = 0;
    for i in 1..=block.len() {
        if i == block.len() || tooth[i] != tooth[start] {
            let half = &relative[start + (i - start) / 2..i];
            stretches.push((tooth[start], support::mean(half)));
            start = i;
        }
    }
    // The first and last stretches are cut short by the run.
    let whole = &stretches[1..stretches.len() - 1];
    assert!(whole.len() >= 30, "{} pairs in mesh", whole.len());
    let residual: Vec<f64> = whole
        .iter()
        .map(|&(tooth, mean)| mean - errors[tooth])
        .collect();
    let offset = support::mean(&residual);
    let worst = residual
        .iter()
        .map(|r| (r - offset).abs())
        .fold(0.0, f64::max);
    eprintln!("MEASURED worst {:e} of RMS", worst / rms);
    assert!(
        worst < 0.03 * rms,
        "the displacement misses a pair's error by {worst:e} rad (RMS {rms:e})"
    );
    let means: Vec<f64> = whole.iter().map(|&(_, m)| m).collect();
    assert!(
        support::std_dev(&means) > 0.9 * rms,
        "the pairs do not differ"
    );
}
