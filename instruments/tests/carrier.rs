//! Slip rings and the carrier amplifier: gain, ripple, and why a carrier rejects lead noise.

use instruments::{
    Block, CarrierDemodulator, CarrierModulator, CarrierSettings, SlipRing, SlipRingSettings,
};
use std::f64::consts::PI;

const RATE: f64 = 51_200.0;

fn settings() -> CarrierSettings {
    CarrierSettings {
        carrier_hz: 5_000.0,
        output_lowpass_hz: 500.0,
        gain: 100.0,
    }
}

fn rms(values: &[f64]) -> f64 {
    (values.iter().map(|v| v * v).sum::<f64>() / values.len() as f64).sqrt()
}

/// Bridge output → modulator → (slip rings) → demodulator.
fn through_chain(input: &[f64], rings: Option<&mut SlipRing>) -> Vec<f64> {
    let mut modulator = CarrierModulator::new(settings(), RATE).expect("valid");
    let mut demodulator = CarrierDemodulator::new(settings(), RATE).expect("valid");
    let mut carried = vec![0.0; input.len()];
    modulator.process(input, &mut carried);
    if let Some(r) = rings {
        let copy = carried.clone();
        r.process(&copy, &mut carried);
    }
    let mut out = vec![0.0; input.len()];
    demodulator.process(&carried, &mut out);
    out
}

#[test]
fn a_steady_bridge_voltage_comes_out_times_the_gain_with_the_carrier_ripple() {
    let n = RATE as usize;
    let out = through_chain(&vec![1e-3; n], None);
    let tail = &out[n / 2..];
    let mean = tail.iter().sum::<f64>() / tail.len() as f64;
    assert!((mean - 0.1).abs() < 1e-6, "{mean}");
    // Ripple: the 2ω_c product through the output low-pass, |H(10 kHz)| of the gain.
    let demodulator = CarrierDemodulator::new(settings(), RATE).expect("valid");
    let h = demodulator.response(10_000.0).expect("linear").norm() * 1e-3;
    let ripple = rms(&tail.iter().map(|v| v - mean).collect::<Vec<_>>()) * 2f64.sqrt();
    assert!((ripple / h - 1.0).abs() < 0.05, "ripple {ripple} vs {h}");
}

#[test]
fn a_strain_signal_passes_as_the_output_lowpass_says() {
    let n = 2 * RATE as usize;
    let input: Vec<f64> = (0..n)
        .map(|k| 1e-3 * (2.0 * PI * 100.0 * k as f64 / RATE).sin())
        .collect();
    let out = through_chain(&input, None);
    let demodulator = CarrierDemodulator::new(settings(), RATE).expect("valid");
    let want = demodulator.response(100.0).expect("linear").norm() * 1e-3;
    let got = rms(&out[n / 2..]) * 2f64.sqrt();
    assert!((got / want - 1.0).abs() < 0.01, "{got} vs {want}");
}

#[test]
fn slip_rings_modulate_once_per_revolution_and_their_noise_is_seeded() {
    let quiet = SlipRingSettings {
        broadband_rms: 0.0,
        per_rev_amplitude: 0.05,
        contact_noise_v_rms: 0.0,
        seed: 1,
    };
    let mut rings = SlipRing::new(quiet, RATE, 10.0).expect("valid");
    let input = vec![2.0; 5120];
    let mut out = vec![0.0; 5120];
    rings.process(&input, &mut out);
    for (k, v) in out.iter().enumerate() {
        let want = 2.0 * (1.0 + 0.05 * (2.0 * PI * 10.0 * k as f64 / RATE).sin());
        assert!((v - want).abs() < 1e-9);
    }
    let noisy = SlipRingSettings {
        broadband_rms: 0.01,
        per_rev_amplitude: 0.0,
        contact_noise_v_rms: 1e-4,
        seed: 9,
    };
    let mut rings = SlipRing::new(noisy, RATE, 10.0).expect("valid");
    let zeros = vec![0.0; 200_000];
    let mut first = vec![0.0; zeros.len()];
    rings.process(&zeros, &mut first);
    assert!((rms(&first) / 1e-4 - 1.0).abs() < 0.01, "{}", rms(&first));
    rings.reset();
    let mut second = vec![0.0; zeros.len()];
    rings.process(&zeros, &mut second);
    assert_eq!(first, second);
}

#[test]
fn the_carrier_rejects_low_frequency_lead_noise() {
    // The same additive contact noise hurts a DC bridge directly but mostly falls outside
    // the demodulator's ±500 Hz window around the carrier: white noise of density N0 leaves
    // √(2·N0·B) where B is the low-pass's noise bandwidth, against √(N0·f_s/2) unfiltered.
    let noise = SlipRingSettings {
        broadband_rms: 0.0,
        per_rev_amplitude: 0.0,
        contact_noise_v_rms: 1e-4,
        seed: 3,
    };
    let mut rings = SlipRing::new(noise, RATE, 10.0).expect("valid");
    let n = 4 * RATE as usize;
    let out = through_chain(&vec![0.0; n], Some(&mut rings));
    let noise_out = rms(&out[n / 4..]) / settings().gain;
    // A second-order Butterworth's noise bandwidth is π/(2√2)·f_c = 1.11 f_c.
    let expected = 1e-4 * (2.0 * 1.1107 * 500.0 / (RATE / 2.0)).sqrt();
    assert!(
        (noise_out / expected - 1.0).abs() < 0.1,
        "{noise_out} vs {expected}"
    );
    assert!(noise_out < 0.3e-4);
    assert!(
        SlipRing::new(
            SlipRingSettings {
                broadband_rms: -1.0,
                ..noise
            },
            RATE,
            10.0
        )
        .is_err()
    );
    assert!(
        CarrierModulator::new(
            CarrierSettings {
                carrier_hz: 20_000.0,
                ..settings()
            },
            RATE
        )
        .is_err()
    );
}

#[test]
fn the_calibrated_gain_reads_200_microstrain_as_3_volts() {
    // Full bridge, GF 2.1, 10 V excitation: 21 V per unit strain.
    let gain = CarrierSettings::calibrated_gain(200.0, 3.0, 21.0);
    let carrier = CarrierSettings { gain, ..settings() };
    let mut modulator = CarrierModulator::new(carrier, RATE).expect("valid");
    let mut demodulator = CarrierDemodulator::new(carrier, RATE).expect("valid");
    let n = RATE as usize;
    let bridge = vec![200e-6 * 21.0; n];
    let (mut a, mut b) = (vec![0.0; n], vec![0.0; n]);
    modulator.process(&bridge, &mut a);
    demodulator.process(&a, &mut b);
    let mean = b[n / 2..].iter().sum::<f64>() / (n / 2) as f64;
    assert!((mean - 3.0).abs() < 1e-3, "{mean}");
}

/// The carrier the modulator multiplies by, over `n` samples from sample `from`.
fn carrier_from(carrier_hz: f64, rate_hz: f64, from: usize, n: usize) -> Vec<f64> {
    let settings = CarrierSettings {
        carrier_hz,
        output_lowpass_hz: carrier_hz / 10.0,
        gain: 1.0,
    };
    let mut modulator = CarrierModulator::new(settings, rate_hz).expect("valid");
    let (ones, mut skipped) = (vec![1.0; 65_536], vec![0.0; 65_536]);
    let mut left = from;
    while left > 0 {
        let chunk = left.min(ones.len());
        modulator.process(&ones[..chunk], &mut skipped[..chunk]);
        left -= chunk;
    }
    let mut out = vec![0.0; n];
    modulator.process(&vec![1.0; n], &mut out);
    out
}

/// A 2 kHz carrier on 10.24 kHz repeats every 128 samples, exactly, however long the run:
/// after 10⁷ samples (16 min) it is still cos 2π·2000·k/10240 to rounding, where
/// cos(ω·k) would be 1e-9 off. A carrier with no short period (2 kHz on 10.24·π kHz) is
/// cos ω·k.
#[test]
fn the_carrier_keeps_its_phase_over_long_runs() {
    let late = carrier_from(2_000.0, 10_240.0, 10_000_003, 256);
    for k in 0..128 {
        assert_eq!(late[k].to_bits(), late[k + 128].to_bits(), "sample {k}");
        // (10⁷ + 3)·25 mod 128 = 75: the phase of sample 10⁷ + 3 + k is 2π·(25k + 75)/128.
        let exact = (2.0 * PI * ((k * 25 + 75) % 128) as f64 / 128.0).cos();
        assert!(
            (late[k] - exact).abs() < 1e-15,
            "sample {k}: {} vs {exact}",
            late[k]
        );
    }
    let rate_hz = 10_240.0 * PI;
    let early = carrier_from(2_000.0, rate_hz, 0, 64);
    for (k, &c) in early.iter().enumerate() {
        let exact = (2.0 * PI * 2_000.0 * k as f64 / rate_hz).cos();
        assert!((c - exact).abs() < 1e-14, "sample {k}: {c} vs {exact}");
    }
}
