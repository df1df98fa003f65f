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

/// The two-stage rig rattling (20 N m with 40 N m oscillating at 30 Hz), run for 0.3 s in
/// blocks of `block_samples`: its samples and impacts.
fn rattling_in_blocks(block_samples: usize) -> (rig::NetworkBlock, Vec<NetworkImpact>) {
    let rig = shipped("two-stage");
    let schedule = Schedule {
        oscillating_load_nm: rig::Track::hold(40.0),
        oscillating_load_hz: rig::Track::hold(30.0),
        ..Schedule::constant(1500.0, 20.0)
    };
    let mut p = plant(&rig, schedule, NetworkStart::Steady);
    let mut block = p.block();
    let total = (0.3 * rig_support::RATE_HZ) as usize;
    let mut taken = 0;
    while taken < total {
        let n = block_samples.min(total - taken);
        p.run(n, &mut block).expect("runs");
        taken += n;
    }
    (block, p.take_impacts())
}

#[test]
fn a_rattling_rig_runs_to_the_same_bytes_a_sample_at_a_time_as_in_long_blocks() {
    let (one, one_impacts) = rattling_in_blocks(1);
    let (long, long_impacts) = rattling_in_blocks(10_000);
    assert!(
        long_impacts.len() > 100,
        "the rig rattles: {} impacts in 0.3 s",
        long_impacts.len()
    );
    assert_eq!(
        one_impacts, long_impacts,
        "the same impacts at the same instants"
    );
    assert!(one == long, "the same samples, bit for bit");
}

/// The 1983 rig as a file at 1300 rev/min and 2.712 N m (its teeth part and strike every
/// revolution, the half-order motion), settled 3 s by `skip` (no samples written: strides
/// of steps where the teeth are apart) and by `run`, then recorded 0.5 s: the same
/// motion, the same impacts within 0.1 µs, the torques within 1e-4 N m (the intermediate
/// shaft's AC is 7.6 N m RMS). The two round differently, and the motion amplifies
/// rounding: a kick of 1e-13 rad/s at the start parts two recorded runs by 0.14 ns and
/// 3e-8 N m after 3 s; skip and run part by 3.3 ns and 7e-7 N m (measured). A stride
/// that stepped over a switch would miss an impact or shift it by microseconds. At
/// 51.2 kHz (a step a sample, strides of up to 8) and at a sweep's 10.24 kHz (3 steps a
/// sample, strides of 3 or 6: whole output periods).
#[test]
fn a_settling_run_taken_in_strides_keeps_the_motion_of_a_recorded_one() {
    for (rate_hz, substeps) in [(rig_support::RATE_HZ, 1), (10_240.0, 3)] {
        strides_keep_the_motion(rate_hz, substeps);
    }
}

/// [`a_settling_run_taken_in_strides_keeps_the_motion_of_a_recorded_one`] at `rate_hz`,
/// whose plant takes `substeps` steps a sample.
fn strides_keep_the_motion(rate_hz: f64, substeps: u32) {
    let rig = shipped("basmaji-1983");
    let settle = (3.0 * rate_hz) as usize;
    let settled = |by_skip: bool| {
        let schedule = Schedule::constant(1300.0, 2.712);
        let mut p =
            NetworkPlant::new(&rig, schedule, rate_hz, NetworkStart::Steady).expect("plant");
        assert_eq!(p.substeps(), substeps, "{rate_hz} Hz");
        if by_skip {
            p.skip(settle).expect("settles");
        } else {
            p.run(settle, &mut p.block()).expect("settles");
        }
        let settling_impacts = p.take_impacts().len();
        let mut block = p.block();
        p.run((0.5 * rate_hz) as usize, &mut block).expect("runs");
        (settling_impacts, block, p.take_impacts())
    };
    let (skipped_impacts, skipped, skipped_after) = settled(true);
    let (run_impacts, recorded, recorded_after) = settled(false);
    assert_eq!(
        skipped_impacts, run_impacts,
        "{rate_hz} Hz: the same impacts while settling"
    );
    assert!(
        recorded_after.len() > 50,
        "{} impacts",
        recorded_after.len()
    );
    assert_eq!(skipped_after.len(), recorded_after.len(), "{rate_hz} Hz");
    for (a, b) in skipped_after.iter().zip(&recorded_after) {
        assert!(
            (a.time_s - b.time_s).abs() < 1e-7 && a.mesh == b.mesh && a.flank == b.flank,
            "{rate_hz} Hz: impact at {} s against {} s",
            a.time_s,
            b.time_s
        );
    }
    for (a, b) in skipped
        .shaft_torque_nm
        .iter()
        .zip(&recorded.shaft_torque_nm)
    {
        let worst = a
            .iter()
            .zip(b)
            .map(|(x, y)| (x - y).abs())
            .fold(0.0, f64::max);
        assert!(
            worst < 1e-4,
            "{rate_hz} Hz: shaft torques part by {worst} N m"
        );
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

/// A settling run asked between stretches whether to go on (`skip_while`, a Python
/// caller's Ctrl-C) takes the steps of one `skip`, bit for bit: the 1983 rig rattling at
/// 1300 rev/min, 2.712 N m, 3 s; told to stop at its second question, it stops after
/// two stretches.
#[test]
fn a_settling_run_that_may_be_stopped_takes_the_steps_of_one_skip() {
    let rig = shipped("basmaji-1983");
    let settle = (3.0 * rig_support::RATE_HZ) as usize;
    let fresh = || {
        plant(
            &rig,
            Schedule::constant(1300.0, 2.712),
            NetworkStart::Steady,
        )
    };
    let mut whole = fresh();
    whole.skip(settle).expect("settles");
    let mut asked = fresh();
    let mut questions = 0;
    let done = asked
        .skip_while(settle, || {
            questions += 1;
            true
        })
        .expect("settles");
    assert_eq!(done, settle);
    assert_eq!(questions, settle / rig::plant::SKIP_STRETCH as usize);
    let bits =
        |p: &rig::NetworkPlant| -> Vec<u64> { p.state_rad().iter().map(|x| x.to_bits()).collect() };
    assert_eq!(bits(&asked), bits(&whole), "the same state, bit for bit");
    assert_eq!(asked.take_impacts(), whole.take_impacts());
    let mut stopped = fresh();
    let mut questions = 0;
    let done = stopped
        .skip_while(settle, || {
            questions += 1;
            questions < 2
        })
        .expect("stops");
    assert_eq!(done, 2 * rig::plant::SKIP_STRETCH as usize);
}
