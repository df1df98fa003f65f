//! Energy: conserved without damping or forcing; balanced against work and dissipation with them.

mod support;

use rig::{MeshMode, RigParams, Schedule, SignalBlock};

use rig::energy::{kinetic_energy_j, mesh_energy_j, shaft_energy_j};

/// No damping, no motor control, no load, constant backlash, no tooth shifting.
fn conservative() -> RigParams {
    let mut p = support::thesis();
    p.c12_input_shaft_nms_per_rad = 0.0;
    p.c23_mesh_nms_per_rad = 0.0;
    p.c34_intermediate_shaft_nms_per_rad = 0.0;
    p.c45_final_shaft_nms_per_rad = 0.0;
    p.speed_loop_hz = 0.0;
    p.backlash_variation_c1 = 0.0;
    p.tooth_shifting = false;
    p
}

/// Vibration energy (J) and angular momentum (N m s) from the plant's relative state
/// [X1..X5, V1..V5] (full precision, unlike absolute angles after many turns).
fn relative_energy(p: &RigParams, omega: f64, x: &[f64; 12]) -> (f64, f64) {
    let j = p.inertias_kgm2();
    let angle: [f64; 5] = std::array::from_fn(|k| x[k]);
    let v: [f64; 5] = std::array::from_fn(|k| x[5 + k]);
    let momentum_rel = j.iter().zip(&v).map(|(j, v)| j * v).sum::<f64>();
    let mean = momentum_rel / p.total_inertia_kgm2();
    let relative: [f64; 5] = std::array::from_fn(|k| v[k] - mean);
    let energy = kinetic_energy_j(p, &relative)
        + shaft_energy_j(p, &angle)
        + mesh_energy_j(p, angle[2] - angle[1]);
    (energy, momentum_rel + p.total_inertia_kgm2() * omega)
}

#[test]
fn energy_is_conserved_through_impacts_without_damping_or_forcing() {
    let p = conservative();
    // The gears set moving apart inside the free play (rad/s on M2, M3, M5): the teeth
    // rattle. The plant's angles are relative to the set rotation; without a speed loop
    // they drift with the rig's mean speed, and a drift of 0.12 rad/s takes them to 1.2 rad
    // in 10 s, where every step rounds them by 2e-16 rad: a random walk of ~1e-13 rad in
    // the shaft twists, 1e-9 of this energy by itself. So the set rotation is the rig's
    // own mean speed (the same motion, seen from the frame that turns with the rig).
    let kick = [0.0, 0.3, -0.6, 0.0, 0.1];
    let j = p.inertias_kgm2();
    let mean = j.iter().zip(&kick).map(|(j, v)| j * v).sum::<f64>() / p.total_inertia_kgm2();
    let omega = 1000.0 * std::f64::consts::PI / 30.0 + mean;
    let rpm = omega * 30.0 / std::f64::consts::PI;
    let mut plant = support::plant(p.clone(), Schedule::constant(rpm, 0.0), 51_200.0);
    let mut state = plant.relative_state();
    for (k, v) in kick.iter().enumerate() {
        state[5 + k] += v - mean;
    }
    plant.set_relative_state(state, MeshMode::Apart);
    let (e0, m0) = relative_energy(&p, omega, &plant.relative_state());
    let (mut worst_energy, mut worst_momentum) = (0.0_f64, 0.0_f64);
    for _ in 0..(10.0 * 51_200.0) as usize {
        plant.skip(1).expect("run completes");
        let (e, m) = relative_energy(&p, omega, &plant.relative_state());
        worst_energy = worst_energy.max((e - e0).abs() / e0);
        worst_momentum = worst_momentum.max((m - m0).abs() / m0);
    }
    assert!(
        plant.impacts().len() > 100,
        "only {} impacts",
        plant.impacts().len()
    );
    eprintln!("MEASURED energy drift {worst_energy:e} momentum {worst_momentum:e}");
    assert!(
        worst_energy < 1e-9,
        "vibration energy drifts by {worst_energy:e} of {e0} J"
    );
    assert!(
        worst_momentum < 1e-12,
        "momentum drifts by {worst_momentum:e}"
    );
}

/// Work in minus dissipation and stored energy over `block` (trapezoid rule), and the
/// scale ∫|power in| dt, for constant backlash.
fn balance(p: &RigParams, b: &SignalBlock, rpm: f64, load_nm: f64) -> (f64, f64) {
    let omega = rpm * std::f64::consts::PI / 30.0;
    let geometry = rig::GearGeometry::of(p);
    let power = |i: usize| -> (f64, f64) {
        let w: [f64; 5] = std::array::from_fn(|k| b.speed_rad_s[k][i]);
        let gear_error = -p.gear_error_c2_nm * (omega * b.time_s[i]).cos();
        let input = b.motor_torque_nm[i] * w[0] - load_nm * w[4] + gear_error * (w[1] + w[2]);
        let shafts = p.c12_input_shaft_nms_per_rad * (w[0] - w[1]).powi(2)
            + p.c34_intermediate_shaft_nms_per_rad * (w[2] - w[3]).powi(2)
            + p.c45_final_shaft_nms_per_rad * (w[3] - w[4]).powi(2);
        let d = b.angle_rad[2][i] - b.angle_rad[1][i];
        let mesh = if (d.abs() >= geometry.half_backlash_rad) && b.contact[i] != 0 {
            p.c23_mesh_nms_per_rad * (w[2] - w[1]).powi(2)
        } else {
            0.0
        };
        (input, shafts + mesh)
    };
    let stored = |i: usize| {
        let w: [f64; 5] = std::array::from_fn(|k| b.speed_rad_s[k][i]);
        let a: [f64; 5] = std::array::from_fn(|k| b.angle_rad[k][i]);
        kinetic_energy_j(p, &w) + shaft_energy_j(p, &a) + mesh_energy_j(p, a[2] - a[1])
    };
    let (mut work, mut lost, mut scale) = (0.0, 0.0, 0.0);
    for i in 1..b.len() {
        let h = b.time_s[i] - b.time_s[i - 1];
        let (in0, d0) = power(i - 1);
        let (in1, d1) = power(i);
        work += 0.5 * h * (in0 + in1);
        lost += 0.5 * h * (d0 + d1);
        scale += 0.5 * h * (in0.abs() + in1.abs());
    }
    let change = stored(b.len() - 1) - stored(0);
    (work - lost - change, scale)
}

fn forced(mesh_damping: f64) -> RigParams {
    let mut p = support::thesis();
    p.backlash_variation_c1 = 0.0;
    p.tooth_shifting = false;
    p.gear_error_c2_nm = 3.0;
    p.c23_mesh_nms_per_rad = mesh_damping;
    p
}

/// Runs the forced rig at 1300 rev/min, 2.712 N m and checks the energy balance to 1e-6.
fn assert_balanced(mesh_damping: f64, rate_hz: f64, seconds: f64, min_impacts: usize) {
    let p = forced(mesh_damping);
    let (rpm, load) = (1300.0, 2.712);
    let mut plant = support::plant(p.clone(), Schedule::constant(rpm, load), rate_hz);
    let block = support::record(&mut plant, seconds);
    let impacts = plant.impacts().len();
    assert!(impacts > min_impacts, "only {impacts} impacts");
    let (residual, scale) = balance(&p, &block, rpm, load);
    eprintln!("MEASURED balance {:e}", residual / scale);
    assert!(
        (residual / scale).abs() < 1e-6,
        "energy balance off by {:e} of {scale} J",
        residual / scale
    );
}

#[test]
fn work_balances_energy_and_dissipation_with_elastic_impacts() {
    // Shaft dampers, speed loop, load and a gear error torque; impacts without mesh damping,
    // so every power term is continuous across a contact switch.
    assert_balanced(0.0, 409_600.0, 1.0, 20);
}

#[test]
fn work_balances_energy_and_dissipation_with_mesh_damping() {
    // The damping power jumps at every contact switch: a fine output rate keeps the
    // trapezoid rule's error at the jumps small.
    assert_balanced(support::thesis().c23_mesh_nms_per_rad, 2_048_000.0, 0.5, 10);
}
