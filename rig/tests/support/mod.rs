//! Helpers shared by the plant's integration tests.
#![allow(dead_code)]

pub mod reference;

use rig::{NetworkBlock, NetworkPlant, NetworkStart, RigParams, Schedule, preset, preset_rig};

/// The thesis preset.
pub fn thesis() -> RigParams {
    preset("basmaji-1983").expect("the preset exists")
}

/// The one plant of the rig `params` describe (`rig::preset_rig`), on `schedule` at
/// `rate_hz`, starting in its steady state at the schedule's first set points.
pub fn preset_plant(params: &RigParams, schedule: Schedule, rate_hz: f64) -> NetworkPlant {
    let rig = preset_rig("test", "a preset's parameters in a test", params);
    NetworkPlant::new(&rig, schedule, rate_hz, NetworkStart::Steady).expect("valid plant")
}

/// Runs the one plant `plant` for `seconds` and returns the samples.
pub fn run_for(plant: &mut NetworkPlant, seconds: f64) -> NetworkBlock {
    let samples = (seconds / plant.output_step_s()).round() as usize;
    let mut block = plant.block();
    plant.run(samples, &mut block).expect("run completes");
    block
}

/// The driven gear's lag behind the driving gear, θ3 − θ2 (rad, each in its sense of
/// rotation) of each sample of the one plant's `block` (bodies 1 and 2).
pub fn mesh_lag_rad(block: &NetworkBlock) -> Vec<f64> {
    block.angle_rad[2]
        .iter()
        .zip(&block.angle_rad[1])
        .map(|(x3, x2)| x3 - x2)
        .collect()
}

/// The gears' base radius r_b = m z cos α / 2 (m) of `params`.
pub fn base_radius_m(params: &RigParams) -> f64 {
    params.module_m * f64::from(params.teeth) * params.pressure_angle_deg.to_radians().cos() / 2.0
}

/// The thesis's mesh torque (N m) of each sample of the one plant's `block`: the mesh's
/// force along the line of action times the base radius of `params`' gears.
pub fn mesh_torque_nm(params: &RigParams, block: &NetworkBlock) -> Vec<f64> {
    let r_b = base_radius_m(params);
    block.mesh_force_n[0].iter().map(|f| f * r_b).collect()
}

/// Amplitude and phase (complex) of the component at `freq_hz` in `signal` sampled at
/// `times_s`, by projection (exact for whole periods).
pub fn phasor(times_s: &[f64], signal: &[f64], freq_hz: f64) -> (f64, f64) {
    let w = 2.0 * std::f64::consts::PI * freq_hz;
    let n = signal.len() as f64;
    let (mut re, mut im) = (0.0, 0.0);
    for (&t, &v) in times_s.iter().zip(signal) {
        re += v * (w * t).cos();
        im -= v * (w * t).sin();
    }
    (2.0 * re / n, 2.0 * im / n)
}

/// Mean of a slice.
pub fn mean(values: &[f64]) -> f64 {
    values.iter().sum::<f64>() / values.len() as f64
}

/// Population standard deviation of a slice.
pub fn std_dev(values: &[f64]) -> f64 {
    let m = mean(values);
    (values.iter().map(|v| (v - m).powi(2)).sum::<f64>() / values.len() as f64).sqrt()
}

/// The thesis's rig with every time-varying effect off (no backlash variation, no tooth
/// shifting): loaded, it turns without vibrating.
pub fn quiet() -> RigParams {
    let mut p = thesis();
    p.backlash_variation_c1 = 0.0;
    p.tooth_shifting = false;
    p
}

/// The linear rig's dynamic stiffness at `w_rad_s` with the teeth in contact:
/// −ω²M + iωC + K over the five bodies (shafts and mesh as springs with dampers) plus the
/// speed loop on M1, G(iω) = (Kp + Ki/iω)·(ω_f/(iω + ω_f))·iω. Z·X = F gives the steady
/// phasors X (rad) for torque phasors F (N m).
pub fn dynamic_stiffness(p: &RigParams, w_rad_s: f64) -> nalgebra::DMatrix<nalgebra::Complex<f64>> {
    use nalgebra::Complex;
    let w = w_rad_s;
    let iw = Complex::new(0.0, w);
    let springs = [
        (
            0,
            1,
            p.k12_input_shaft_nm_per_rad,
            p.c12_input_shaft_nms_per_rad,
        ),
        (1, 2, p.k23_mesh_nm_per_rad, p.c23_mesh_nms_per_rad),
        (
            2,
            3,
            p.k34_intermediate_shaft_nm_per_rad,
            p.c34_intermediate_shaft_nms_per_rad,
        ),
        (
            3,
            4,
            p.k45_final_shaft_nm_per_rad,
            p.c45_final_shaft_nms_per_rad,
        ),
    ];
    let mut z = nalgebra::DMatrix::<Complex<f64>>::zeros(5, 5);
    for (k, &jk) in p.inertias_kgm2().iter().enumerate() {
        z[(k, k)] += Complex::new(-w * w * jk, 0.0);
    }
    for (a, b, k, c) in springs {
        let s = Complex::new(k, 0.0) + iw * c;
        z[(a, a)] += s;
        z[(b, b)] += s;
        z[(a, b)] -= s;
        z[(b, a)] -= s;
    }
    z[(0, 0)] += speed_loop_parts(p, w).0 * iw;
    z
}

/// The speed loop's transfer from M1's speed to its torque, (Kp + Ki/iω)·ω_f/(iω + ω_f),
/// and the feedback filter ω_f/(iω + ω_f) on its own: (loop, filter).
pub fn speed_loop_parts(
    p: &RigParams,
    w_rad_s: f64,
) -> (nalgebra::Complex<f64>, nalgebra::Complex<f64>) {
    use nalgebra::Complex;
    let iw = Complex::new(0.0, w_rad_s);
    let (kp, ki) = p.speed_loop_gains();
    let wf = 2.0 * std::f64::consts::PI * p.speed_feedback_filter_hz;
    let filter = Complex::new(wf, 0.0) / (iw + wf);
    (
        (Complex::new(kp, 0.0) + Complex::new(ki, 0.0) / iw) * filter,
        filter,
    )
}
