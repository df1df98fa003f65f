//! The plant of rigs nobody tuned (`scenarios/rigs/two-stage.toml`, `fzg-back-to-back.toml`)
//! judged against physics: the load carried through each stage in the ratio of the teeth,
//! a loop holding its locked-in torque with the motor supplying only the losses, energy
//! kept without damping, impacts at the instants of an independent RK4 of the same
//! equations written here from the file's numbers.

mod rig_support;

use std::f64::consts::PI;

use rig::{NetworkImpact, NetworkPlant, NetworkStart, RigTopology, Schedule};
use rig_support::{body, mean, plant, run, run_up, shaft, shipped, tail};

#[test]
fn a_two_stage_reduction_carries_the_load_through_each_stage_in_the_ratio_of_its_teeth() {
    let rig = shipped("two-stage");
    let mut p = plant(&rig, run_up(1500.0, 60.0), NetworkStart::Rest);
    let block = run(&mut p, &rig, 6.0);
    let torque = |name| mean(tail(&block.shaft_torque_nm[shaft(&rig, name)], 2.0));
    let speed = |name| mean(tail(&block.speed_rad_s[body(&rig, name)], 2.0)) * 30.0 / PI;
    let (input, intermediate, output) = (torque("input"), torque("intermediate"), torque("output"));
    let close = |a: f64, b: f64| (a / b - 1.0).abs() < 1e-3;
    assert!(
        close(output, 60.0),
        "the output shaft carries the load: {output} N m"
    );
    assert!(
        close(intermediate / input, 60.0 / 20.0),
        "stage 1: {intermediate} / {input}"
    );
    assert!(
        close(output / intermediate, 54.0 / 18.0),
        "stage 2: {output} / {intermediate}"
    );
    assert!(close(speed("pinion1"), 1500.0), "{}", speed("pinion1"));
    assert!(close(speed("pinion1") / speed("wheel1"), 3.0));
    assert!(close(speed("pinion2") / speed("brake"), 3.0));
}

#[test]
fn a_back_to_back_loop_holds_its_locked_torque_at_rest_and_running_the_motor_giving_only_the_losses()
 {
    let rig = shipped("fzg-back-to-back");
    let locked = rig
        .locked_torque
        .as_ref()
        .expect("a locked torque")
        .torque_nm;
    let loop_shaft = shaft(&rig, "loop");
    let mut at_rest = plant(&rig, Schedule::constant(0.0, 0.0), NetworkStart::Rest);
    let block = run(&mut at_rest, &rig, 1.0);
    let standing = mean(&block.shaft_torque_nm[loop_shaft]);
    assert!(
        (standing / locked - 1.0).abs() < 0.01,
        "at rest: {standing} N m"
    );

    let mut running = plant(&rig, run_up(1450.0, 0.0), NetworkStart::Rest);
    let block = run(&mut running, &rig, 5.0);
    let turning = mean(tail(&block.shaft_torque_nm[loop_shaft], 2.0));
    assert!(
        (turning / locked - 1.0).abs() < 0.01,
        "running: {turning} N m"
    );
    let wheel = mean(tail(
        &block.shaft_torque_nm[shaft(&rig, "wheel_shaft")],
        2.0,
    ));
    assert!(
        (wheel / (locked * 24.0 / 16.0) - 1.0).abs() < 0.01,
        "wheel shaft: {wheel}"
    );
    // The motor's mean torque is the bearing drag's power over its speed.
    let omega = 1450.0 * PI / 30.0;
    let ratios = running.speed_ratios().to_vec();
    let losses: f64 = rig
        .bodies
        .iter()
        .zip(&ratios)
        .map(|(b, s)| b.drag_nms_per_rad * s * s * omega)
        .sum();
    let motor = mean(tail(&block.motor_torque_nm, 2.0));
    assert!(losses > 0.1, "the example rig has drag: {losses} N m");
    assert!(
        (motor / losses - 1.0).abs() < 0.01,
        "motor {motor} N m, losses {losses} N m"
    );
    assert!(
        motor < 0.05 * locked,
        "the motor gives far less than the loop carries"
    );
}

/// `rig` without damping, drag, motor or brake.
fn conservative(mut rig: RigTopology) -> RigTopology {
    for s in &mut rig.shafts {
        s.damping_nms_per_rad = 0.0;
    }
    for m in &mut rig.meshes {
        m.damping_ns_per_m = 0.0;
    }
    for b in &mut rig.bodies {
        b.drag_nms_per_rad = 0.0;
    }
    rig.motor = None;
    rig.brake = None;
    rig
}

/// Kicks body `a` by `kick` rad/s and body `b` the other way so that the rig's angular
/// momentum stays zero (Σ J s ω: it rattles in place instead of spinning away).
fn kick_in_place(p: &mut NetworkPlant, rig: &RigTopology, (a, b): (usize, usize), kick: f64) {
    let s = p.speed_ratios().to_vec();
    let (ja, jb) = (rig.bodies[a].inertia_kgm2, rig.bodies[b].inertia_kgm2);
    p.kick(a, kick * s[a].signum());
    p.kick(
        b,
        -kick * s[a].signum() * ja * s[a].abs() / (jb * s[b].abs()) * s[b].signum(),
    );
}

#[test]
fn without_damping_a_rattling_rig_keeps_its_energy_to_1e_9_over_10_s() {
    let cases = [
        ("two-stage", ("pinion1", "wheel2"), 40.0),
        ("fzg-back-to-back", ("test_pinion", "test_wheel"), 60.0),
    ];
    for (name, (a, b), kick) in cases {
        let rig = conservative(shipped(name));
        let mut p = plant(&rig, Schedule::constant(0.0, 0.0), NetworkStart::Rest);
        let rest = p.energy_j();
        kick_in_place(&mut p, &rig, (body(&rig, a), body(&rig, b)), kick);
        let before = p.energy_j();
        run(&mut p, &rig, 10.0);
        let impacts = p.take_impacts().len();
        let after = p.energy_j();
        assert!(
            impacts > 1000,
            "{name}: the gears rattle ({impacts} impacts)"
        );
        let kicked = before - rest;
        assert!(
            ((after - before) / kicked).abs() < 1e-9,
            "{name}: {before} J then {after} J, the kick gave {kicked} J"
        );
    }
}

/// An RK4 of the rig's equations in absolute angles, written from the topology alone:
/// state [θ, ω], shafts k·twist + c·twist' + T0 (T0 such that the loop's shaft carries
/// its locked torque in the start state, which is at rest), meshes F = k(δ ∓ b) + c δ'
/// beyond the free play, bearing drag, no motor or brake. Returns each crossing of δ = ±b from inside as
/// (time, mesh), located by linear interpolation between steps; `touching` says which
/// meshes touch at the start.
fn rk4_impacts(
    rig: &RigTopology,
    (kicked, kick): (usize, f64),
    (start, touching): (&[f64], &[bool]),
    seconds: f64,
    step_s: f64,
) -> Vec<(f64, usize)> {
    let n = rig.bodies.len();
    let preload = |s: &rig::Shaft| {
        let locked = rig.locked_torque.as_ref();
        locked
            .filter(|l| rig.shafts[l.shaft].name == s.name)
            .map_or(0.0, |l| {
                l.torque_nm - s.stiffness_nm_per_rad * (start[s.between[0]] - start[s.between[1]])
            })
    };
    let deflection = |x: &[f64], m: &rig::Mesh| {
        let [ra, rb] = m.base_radii_m();
        ra * x[m.gears[0]] + rb * x[m.gears[1]]
    };
    let derivative = |x: &[f64]| -> Vec<f64> {
        let mut dx = vec![0.0; 2 * n];
        let mut torque = vec![0.0; n];
        for s in &rig.shafts {
            let [a, b] = s.between;
            let t = s.stiffness_nm_per_rad * (x[a] - x[b])
                + s.damping_nms_per_rad * (x[n + a] - x[n + b])
                + preload(s);
            torque[a] -= t;
            torque[b] += t;
        }
        for m in &rig.meshes {
            let [ra, rb] = m.base_radii_m();
            let delta = deflection(x, m);
            let rate = ra * x[n + m.gears[0]] + rb * x[n + m.gears[1]];
            let b = m.half_backlash_m();
            let f = if delta > b {
                m.stiffness_n_per_m * (delta - b) + m.damping_ns_per_m * rate
            } else if delta < -b {
                m.stiffness_n_per_m * (delta + b) + m.damping_ns_per_m * rate
            } else {
                0.0
            };
            torque[m.gears[0]] -= ra * f;
            torque[m.gears[1]] -= rb * f;
        }
        for i in 0..n {
            let b = &rig.bodies[i];
            dx[i] = x[n + i];
            dx[n + i] = (torque[i] - b.drag_nms_per_rad * x[n + i]) / b.inertia_kgm2;
        }
        dx
    };
    let mut x = start.to_vec();
    x[n + kicked] += kick;
    let mut impacts = Vec::new();
    let mut apart: Vec<bool> = touching.iter().map(|t| !t).collect();
    let steps = (seconds / step_s).round() as usize;
    let axpy = |x: &[f64], k: &[f64], h: f64| -> Vec<f64> {
        x.iter().zip(k).map(|(a, b)| a + h * b).collect()
    };
    for step in 0..steps {
        let k1 = derivative(&x);
        let k2 = derivative(&axpy(&x, &k1, step_s / 2.0));
        let k3 = derivative(&axpy(&x, &k2, step_s / 2.0));
        let k4 = derivative(&axpy(&x, &k3, step_s));
        let next: Vec<f64> = (0..2 * n)
            .map(|i| x[i] + step_s / 6.0 * (k1[i] + 2.0 * k2[i] + 2.0 * k3[i] + k4[i]))
            .collect();
        for (j, m) in rig.meshes.iter().enumerate() {
            let b = m.half_backlash_m();
            let (d0, d1) = (deflection(&x, m), deflection(&next, m));
            let now_apart = d1.abs() < b;
            if apart[j] && !now_apart {
                let edge = b.copysign(d1);
                let s = (edge - d0) / (d1 - d0);
                impacts.push(((step as f64 + s) * step_s, j));
            }
            apart[j] = now_apart;
        }
        x = next;
    }
    impacts
}

#[test]
fn impacts_fall_within_1_us_of_a_20_ns_rk4_on_both_example_rigs() {
    for (name, kicked, kick) in [
        ("two-stage", "pinion1", 40.0),
        ("fzg-back-to-back", "test_pinion", 60.0),
    ] {
        let mut rig = shipped(name);
        rig.motor = None;
        rig.brake = None;
        let kicked = body(&rig, kicked);
        let mut p = plant(&rig, Schedule::constant(0.0, 0.0), NetworkStart::Rest);
        let n = rig.bodies.len();
        let start = p.state_rad().to_vec();
        let touching: Vec<bool> = p
            .contacts()
            .iter()
            .map(|c| *c != rig::Contact::Apart)
            .collect();
        p.kick(kicked, kick);
        let seconds = 0.02;
        run(&mut p, &rig, seconds);
        let ours: Vec<NetworkImpact> = p.take_impacts();
        let reference = rk4_impacts(
            &rig,
            (kicked, kick),
            (&start[..2 * n], &touching),
            seconds,
            20e-9,
        );
        assert!(
            ours.len() >= 4,
            "{name}: the kick makes the teeth strike ({})",
            ours.len()
        );
        assert_eq!(
            ours.len(),
            reference.len(),
            "{name}: {ours:?} against {reference:?}"
        );
        for (a, (t, mesh)) in ours.iter().zip(&reference) {
            assert_eq!(a.mesh, *mesh, "{name}");
            assert!(
                (a.time_s - t).abs() < 1e-6,
                "{name}: {} s against {t} s",
                a.time_s
            );
        }
    }
}

/// Seconds from rest until the motor's body first turns at `rpm`, or `None` within
/// `within_s`, sampled at 10.24 kHz in blocks of one second.
fn reaches_set_speed_s(
    plant: &mut NetworkPlant,
    rig: &RigTopology,
    rpm: f64,
    within_s: f64,
) -> Option<f64> {
    let rate_hz = 10_240.0;
    let motor = body(rig, "motor");
    let mut block = plant.block();
    let mut done = 0usize;
    while (done as f64) < within_s * rate_hz {
        block.clear();
        plant.run(10_240, &mut block).expect("runs");
        let at = block.speed_rad_s[motor]
            .iter()
            .position(|w| w * 30.0 / PI >= rpm);
        if let Some(k) = at {
            return Some((done + k) as f64 / rate_hz);
        }
        done += 10_240;
    }
    None
}

/// A drive at its torque limit runs a rig up from rest as J dω/dt = spare − c ω says,
/// everything seen at the motor (J = Σ J s², c = Σ c s², the brake's load times its
/// speed share): the time a sweep's case from rest waits before it settles. The two-stage
/// rig (1:9, a drag on every body, an 8 N m limit against 60 N m at the brake) and the
/// 1983 rig as the lab ran it (29 s) reach their set speed within 3 % of that time; the
/// speed loop's own lag (its 2 Hz filter) is the rest.
#[test]
fn a_drive_at_its_limit_runs_a_rig_up_from_rest_in_the_time_its_inertia_and_spare_torque_give() {
    let mut two_stage = shipped("two-stage");
    two_stage.drive.torque_limit_nm = Some(8.0);
    for b in &mut two_stage.bodies {
        b.drag_nms_per_rad = 0.002;
    }
    let cases = [
        (two_stage, 1500.0, 60.0),
        (shipped("basmaji-1983-drive"), 1300.0, 2.712),
    ];
    for (rig, rpm, load_nm) in cases {
        let schedule = Schedule::constant(rpm, load_nm);
        let mut p = NetworkPlant::new(&rig, schedule, 10_240.0, NetworkStart::Rest).expect("plant");
        let expected_s = p.run_up_from_rest_s(rpm, load_nm).expect("torque to spare");
        assert!(expected_s > 5.0, "{}: a run-up of {expected_s} s", rig.name);
        let reached_s =
            reaches_set_speed_s(&mut p, &rig, rpm, 2.0 * expected_s).unwrap_or_else(|| {
                panic!(
                    "{}: not at {rpm} rev/min in {} s",
                    rig.name,
                    2.0 * expected_s
                )
            });
        assert!(
            (reached_s / expected_s - 1.0).abs() < 0.03,
            "{}: at {rpm} rev/min after {reached_s} s, expected {expected_s} s",
            rig.name
        );
    }
}
