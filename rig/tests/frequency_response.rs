//! With no backlash the rig is linear: its steady response to a harmonic load torque must
//! equal the analytic frequency response of the equations of motion.

mod support;

use nalgebra::{Complex, DVector};
use rig::{MeshMode, RigParams, Schedule, Track};

type C = Complex<f64>;

/// Phasors X1..X5 (rad) and the controller's Vf (rad/s) and z (rad) for a load torque
/// −A sin ωt on the brake, solved from (−ω²M + iωC + K + G) X = F with the speed loop
/// G(iω) = (Kp + Ki/iω)·(ω_f/(iω + ω_f))·iω on M1.
fn analytic(p: &RigParams, w: f64, amplitude: f64) -> (Vec<C>, C, C) {
    let iw = C::new(0.0, w);
    let z = support::dynamic_stiffness(p, w);
    let (_, filter) = support::speed_loop_parts(p, w);
    let mut f = DVector::<C>::zeros(5);
    f[4] = C::new(0.0, amplitude);
    let x = z.lu().solve(&f).expect("regular");
    let vf = filter * iw * x[0];
    let zi = -vf / iw;
    (x.iter().copied().collect(), vf, zi)
}

fn check(freq_hz: f64) {
    let mut p = support::thesis();
    p.centre_distance_shift_m = 0.0;
    p.tooth_shifting = false;
    let amplitude = 1.0;
    let w = 2.0 * std::f64::consts::PI * freq_hz;
    let (x, vf, z) = analytic(&p, w, amplitude);
    let schedule = Schedule {
        oscillating_load_nm: Track::hold(amplitude),
        oscillating_load_hz: Track::hold(freq_hz),
        ..Schedule::constant(600.0, 0.0)
    };
    let mut plant = support::plant(p, schedule, 51_200.0);
    let mut start = [0.0; 12];
    for k in 0..5 {
        start[k] = x[k].re;
        start[5 + k] = (C::new(0.0, w) * x[k]).re;
    }
    start[10] = vf.re;
    start[11] = z.re;
    let mesh = if start[2] < start[1] {
        MeshMode::Drive
    } else {
        MeshMode::Back
    };
    plant.set_relative_state(start, mesh);
    let scale = x.iter().map(|v| v.norm()).fold(0.0, f64::max);
    let mut worst = 0.0_f64;
    for n in 0..(2.0 * 51_200.0) as usize {
        let t = n as f64 / 51_200.0;
        let rotation = C::new((w * t).cos(), (w * t).sin());
        let state = plant.relative_state();
        for k in 0..5 {
            worst = worst.max((state[k] - (x[k] * rotation).re).abs() / scale);
        }
        plant.skip(1).expect("run completes");
    }
    eprintln!(
        "MEASURED {freq_hz} Hz: worst {worst:e}, amplitude {scale:e} rad, switches {}",
        plant.switch_count()
    );
    assert!(
        plant.switch_count() > 100,
        "the mesh must switch flanks: {}",
        plant.switch_count()
    );
    assert!(
        worst < 1e-6,
        "{freq_hz} Hz: response departs from the analytic one by {worst:e} of its amplitude"
    );
}

#[test]
fn steady_response_equals_analytic_response_at_30_hz() {
    check(30.0);
}

#[test]
fn steady_response_equals_analytic_response_near_the_fundamental() {
    check(17.0);
}

#[test]
fn steady_response_equals_analytic_response_between_the_upper_modes() {
    check(89.0);
}
