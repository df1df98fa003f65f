//! Condition indicators and the synchronous average on signals whose values are known:
//! a Gaussian's moments (3, 15, 105), a pulse train's crest factor, a mesh tone's FM0, a
//! revolution recovered from noise at a drifting speed, and a local tooth fault raising
//! FM4 where a healthy mesh keeps it at 3.

use std::f64::consts::TAU;

use instruments::{
    GaussianSource, central_moment, condition_indicators, gear_signals, normalised_moment,
    synchronous_average,
};

fn gaussian(seed: u64, n: usize) -> Vec<f64> {
    let mut source = GaussianSource::new(seed);
    (0..n).map(|_| source.sample()).collect()
}

#[test]
fn a_gaussians_normalised_moments_are_3_15_and_105() {
    let x = gaussian(7, 2_000_000);
    let (k4, k6, k8) = (
        normalised_moment(&x, 4),
        normalised_moment(&x, 6),
        normalised_moment(&x, 8),
    );
    eprintln!("moments {k4:.4} {k6:.3} {k8:.2}");
    assert!((k4 - 3.0).abs() < 0.03, "kurtosis {k4}");
    assert!((k6 - 15.0).abs() < 0.5, "6th moment {k6}");
    assert!((k8 - 105.0).abs() < 8.0, "8th moment {k8}");
}

#[test]
fn a_pulse_trains_crest_factor_and_a_mesh_tones_fm0_are_as_computed_by_hand() {
    // One sample in every 64 at 1: about its mean, peak 63/64 and RMS √63/64 → √63.
    let pulses: Vec<f64> = (0..4096)
        .map(|i| if i % 64 == 0 { 1.0 } else { 0.0 })
        .collect();
    let ci = condition_indicators(&pulses, 16, &[]);
    assert!(
        (ci.crest_factor - 63f64.sqrt()).abs() < 1e-9,
        "{}",
        ci.crest_factor
    );
    // A pure mesh tone (30 teeth): peak-to-peak 2A over its amplitude A.
    let n = 1024;
    let tone: Vec<f64> = (0..n)
        .map(|j| 0.7 * (TAU * 30.0 * j as f64 / n as f64).sin())
        .collect();
    let ci = condition_indicators(&tone, 30, &[]);
    assert!((ci.fm0 - 2.0).abs() < 1e-9, "FM0 {}", ci.fm0);
    assert!((ci.rms - 0.7 / 2f64.sqrt()).abs() < 1e-9);
    let parts = gear_signals(&tone, 30);
    assert!((parts.mesh_amplitudes[0] - 0.7).abs() < 1e-9);
    assert!(
        parts.difference.iter().all(|d| d.abs() < 1e-9),
        "the tone is all regular"
    );
}

#[test]
fn the_synchronous_average_recovers_a_revolution_from_noise_at_a_drifting_speed() {
    // A revolution's shape (orders 1 and 30) at a speed drifting 10 % over 200
    // revolutions, under noise of 1 (RMS) against a shape of amplitude 0.5.
    let rate = 20_000.0;
    let shape = |phase: f64| 0.3 * (TAU * phase).sin() + 0.2 * (TAU * 30.0 * phase).cos();
    let (mut pulses, mut signal) = (vec![0.0], Vec::new());
    let mut noise = GaussianSource::new(3);
    let mut phase = 0.0;
    let mut t = 0.0;
    while pulses.len() < 201 {
        let speed_hz = 20.0 * (1.0 + 0.1 * t / 10.0);
        signal.push(shape(phase) + noise.sample());
        let next = phase + speed_hz / rate;
        if next.floor() > phase.floor() {
            // The pulse at the moment the phase crossed a whole revolution.
            let frac = (next.floor() - phase) / (next - phase);
            pulses.push(t + frac / rate);
        }
        phase = next;
        t += 1.0 / rate;
    }
    let points = 512;
    let average = synchronous_average(&signal, rate, &pulses, points).expect("averaged");
    let worst = (0..points)
        .map(|j| (average[j] - shape(j as f64 / points as f64)).abs())
        .fold(0.0, f64::max);
    // Noise of 1 over 200 revolutions: 0.07 RMS; the worst of 512 points within 4 σ.
    eprintln!("synchronous average: worst error {worst:.3}");
    assert!(worst < 0.3, "worst error {worst}");
    let rms_error = ((0..points)
        .map(|j| (average[j] - shape(j as f64 / points as f64)).powi(2))
        .sum::<f64>()
        / points as f64)
        .sqrt();
    assert!(rms_error < 0.1, "RMS error {rms_error}");
    assert!(synchronous_average(&signal, rate, &[0.0], points).is_err());
}

#[test]
fn a_local_tooth_fault_raises_fm4_where_a_healthy_mesh_keeps_it_near_3() {
    let (n, teeth) = (1024, 30);
    let noise = gaussian(11, n);
    let healthy: Vec<f64> = (0..n)
        .map(|j| {
            let p = j as f64 / n as f64;
            (TAU * teeth as f64 * p).sin()
                + 0.3 * (TAU * 2.0 * teeth as f64 * p).sin()
                + 0.05 * noise[j]
        })
        .collect();
    let ci = condition_indicators(&healthy, teeth, &[]);
    eprintln!("healthy FM4 {:.3}", ci.fm4);
    assert!((ci.fm4 - 3.0).abs() < 0.5, "healthy FM4 {}", ci.fm4);
    // A short impulse at one tooth (a crack's stiffness loss as the tooth meshes).
    let mut faulty = healthy.clone();
    for (j, x) in faulty.iter_mut().enumerate().skip(500).take(6) {
        *x += 0.6 * (std::f64::consts::PI * (j - 500) as f64 / 5.0).sin();
    }
    let fault = condition_indicators(&faulty, teeth, &[]);
    eprintln!("faulty FM4 {:.3}, NA4 {:.3}", fault.fm4, fault.na4);
    assert!(fault.fm4 > 10.0, "faulty FM4 {}", fault.fm4);
    assert!(fault.m6a > ci.m6a && fault.m8a > ci.m8a);
    // NA4 against the healthy run's residual variance grows more than against its own.
    let healthy_var = central_moment(&gear_signals(&healthy, teeth).residual, 2);
    let trended = condition_indicators(&faulty, teeth, &[healthy_var]);
    assert!(
        trended.na4 > fault.na4,
        "{} against {}",
        trended.na4,
        fault.na4
    );
}
