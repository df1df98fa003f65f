//! The ADC: quantisation noise, clipping, decimation, dither.

use instruments::{Adc, AdcSettings};
use std::f64::consts::PI;

fn settings(bits: u32) -> AdcSettings {
    AdcSettings {
        decimation: 1,
        bits,
        range_v: 1.0,
        dither_seed: None,
    }
}

#[test]
fn a_full_scale_sine_has_the_ideal_snr() {
    for bits in [8, 12, 16] {
        let mut adc = Adc::new(settings(bits)).expect("valid");
        let n = 1 << 16;
        let amplitude = 1.0 - adc.lsb_v();
        // 1031 cycles in 65536 samples (coprime): every code exercised, no repetition.
        let input: Vec<f64> = (0..n)
            .map(|k| amplitude * (2.0 * PI * 1031.0 * k as f64 / n as f64).sin())
            .collect();
        let mut output = Vec::new();
        adc.convert(&input, &mut output);
        let signal: f64 = input.iter().map(|v| v * v).sum();
        let noise: f64 = input
            .iter()
            .zip(&output)
            .map(|(a, b)| (a - b).powi(2))
            .sum();
        let snr = 10.0 * (signal / noise).log10();
        let ideal = 6.02 * f64::from(bits) + 1.76;
        assert!(
            (snr - ideal).abs() < 0.5,
            "{bits} bits: {snr} dB vs {ideal} dB"
        );
        assert_eq!(adc.overloads(), 0);
    }
}

#[test]
fn overrange_clips_and_is_counted() {
    let mut adc = Adc::new(settings(12)).expect("valid");
    let mut output = Vec::new();
    adc.convert(&[0.5, 1.5, -2.0, 0.0], &mut output);
    assert_eq!(adc.overloads(), 2);
    assert!((output[1] - (1.0 - adc.lsb_v())).abs() < 1e-15);
    assert_eq!(output[2], -1.0);
}

#[test]
fn decimation_keeps_every_mth_sample_across_buffers() {
    let mut adc = Adc::new(AdcSettings {
        decimation: 3,
        ..settings(16)
    })
    .expect("valid");
    let input: Vec<f64> = (0..10).map(|k| k as f64 / 20.0).collect();
    let mut output = Vec::new();
    adc.convert(&input[..4], &mut output);
    adc.convert(&input[4..], &mut output);
    let expected: Vec<f64> = [0, 3, 6, 9]
        .iter()
        .map(|&k| (input[k] / adc.lsb_v()).round() * adc.lsb_v())
        .collect();
    assert_eq!(output, expected);
}

#[test]
fn dither_is_seeded_and_reproducible_after_reset() {
    let mut adc = Adc::new(AdcSettings {
        dither_seed: Some(42),
        ..settings(8)
    })
    .expect("valid");
    let input = vec![0.1234; 100];
    let (mut first, mut second) = (Vec::new(), Vec::new());
    adc.convert(&input, &mut first);
    adc.reset();
    adc.convert(&input, &mut second);
    assert_eq!(first, second);
    // Dither spreads a constant input over neighbouring codes whose mean tracks the input.
    let mean = first.iter().sum::<f64>() / first.len() as f64;
    assert!(first.iter().any(|&v| v != first[0]));
    assert!((mean - 0.1234).abs() < adc.lsb_v());
    assert!(Adc::new(settings(1)).is_err());
}
