//! Where the teeth of a rig file's rig part under an oscillating brake load: in contact the
//! rig is linear, and the teeth must part where the linear forced response overlaps a mesh
//! by more than its static load does (as `rig/tests/separation.rs` for the 1983 rig).

mod rig_support;

use std::f64::consts::PI;

use rig::{NetworkStart, RigTopology, Schedule, Track};
use rig_support::{plant, run, shipped};

type C = nalgebra::Complex<f64>;

/// Amplitude of each mesh's overlap (m) per N m of oscillating brake torque at `hz`, of
/// the linear rig with every mesh on its drive flank, written here in each body's sense
/// of rotation (φ positive the way it turns): (−ω²M + iωC + K + G) Φ = F, a mesh's
/// overlap δ = r_a φ_a − r_b φ_b pushing −r_a F on its driver and +r_b F on its driven
/// gear, G the speed loop kp + ki/(iω) on the first-order filtered motor speed.
fn overlap_per_nm(rig: &RigTopology, speed_ratio: &[f64], hz: f64) -> Vec<f64> {
    let n = rig.bodies.len();
    let w = 2.0 * PI * hz;
    let iw = C::new(0.0, w);
    let mut z = nalgebra::DMatrix::<C>::zeros(n, n);
    for (i, b) in rig.bodies.iter().enumerate() {
        z[(i, i)] += C::from(-w * w * b.inertia_kgm2) + iw * b.drag_nms_per_rad;
    }
    for s in &rig.shafts {
        let [a, b] = s.between;
        let spring = C::from(s.stiffness_nm_per_rad) + iw * s.damping_nms_per_rad;
        z[(a, a)] += spring;
        z[(b, b)] += spring;
        z[(a, b)] -= spring;
        z[(b, a)] -= spring;
    }
    let radii: Vec<[f64; 2]> = rig.meshes.iter().map(|m| m.base_radii_m()).collect();
    for (m, r) in rig.meshes.iter().zip(&radii) {
        let spring = C::from(m.stiffness_n_per_m) + iw * m.damping_ns_per_m;
        let coupling = [(m.gears[0], r[0]), (m.gears[1], -r[1])];
        for &(x, rx) in &coupling {
            for &(y, ry) in &coupling {
                z[(x, y)] += spring * rx * ry;
            }
        }
    }
    let motor = rig.motor.expect("a motor");
    let d = &rig.drive;
    let seen: f64 = rig
        .bodies
        .iter()
        .zip(speed_ratio)
        .map(|(b, s)| b.inertia_kgm2 * s * s)
        .sum();
    let wn = 2.0 * PI * d.speed_loop_hz;
    let (kp, ki) = (2.0 * d.speed_loop_damping_ratio * wn * seen, seen * wn * wn);
    let wf = 2.0 * PI * d.feedback_filter_hz;
    z[(motor, motor)] += (C::from(kp) + C::from(ki) / iw) * iw * wf / (iw + wf);
    let mut f = nalgebra::DVector::<C>::zeros(n);
    f[rig.brake.expect("a brake")] = C::from(-1.0);
    let phi = z.lu().solve(&f).expect("regular");
    rig.meshes
        .iter()
        .zip(&radii)
        .map(|(m, r)| (phi[m.gears[0]] * r[0] - phi[m.gears[1]] * r[1]).norm())
        .collect()
}

#[test]
fn teeth_part_under_an_oscillating_load_where_the_linear_forced_response_says() {
    // The two-stage rig at 1200 rev/min under 20 N m: each mesh's static overlap is its
    // force over its stiffness; an oscillating brake torque of amplitude A overlaps it
    // by A times the linear response. Below the smallest ratio the teeth stay together,
    // above it they part and strike (counted over 10–12 s, the transients gone).
    let rig = shipped("two-stage");
    let ratios = plant(&rig, Schedule::constant(1200.0, 20.0), NetworkStart::Steady)
        .speed_ratios()
        .to_vec();
    let load = 20.0;
    for hz in [35.0, 90.0] {
        let per_nm = overlap_per_nm(&rig, &ratios, hz);
        let threshold = rig
            .meshes
            .iter()
            .zip(&per_nm)
            .map(|(m, per)| {
                // The driver carries the load in the inverse ratio of the speeds.
                let brake = rig.brake.expect("a brake");
                let driver_torque = load * ratios[brake].abs() / ratios[m.gears[0]].abs();
                let force = driver_torque / m.base_radii_m()[0];
                force / m.stiffness_n_per_m / per
            })
            .fold(f64::INFINITY, f64::min);
        for (factor, parts) in [(0.98, false), (1.02, true)] {
            // The amplitude rises over 5 s: no kick that could start a rattling motion
            // which, once started, may outlast the amplitude that keeps the teeth
            // together.
            let schedule = Schedule {
                oscillating_load_nm: Track::hold(0.0).ramp_to(0.0, 5.0, factor * threshold),
                oscillating_load_hz: Track::hold(hz),
                ..Schedule::constant(1200.0, load)
            };
            let mut p = plant(&rig, schedule, NetworkStart::Steady);
            run(&mut p, &rig, 10.0);
            p.take_impacts();
            run(&mut p, &rig, 2.0);
            let impacts = p.take_impacts().len();
            assert_eq!(
                impacts > 0,
                parts,
                "{hz} Hz, {:.3} N m ({factor} of the linear threshold {threshold:.3} N m): {impacts} impacts",
                factor * threshold
            );
        }
    }
}
