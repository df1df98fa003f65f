//! The ADC: quantisation noise, clipping, decimation, dither.

use instruments::{Adc, AdcSettings};
use std::f64::consts::PI;

fn settings(bits: u32) -> AdcSettings {
    AdcSettings {
        ratio: 1.0,
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
        ratio: 3.0,
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

#[test]
fn a_fractional_rate_samples_between_stream_samples_exactly() {
    // 51.2 kHz stream, 4 kHz ADC: 12.8 stream samples per ADC sample.
    let ratio = 51_200.0 / 4_000.0;
    let mut adc = interpolating_adc(ratio);
    let tone = |t: f64| (2.0 * PI * 1_234.5 * t).sin() + 0.3 * (2.0 * PI * 2_200.0 * t + 1.0).sin();
    let input: Vec<f64> = (0..51_200).map(|k| tone(k as f64 / 51_200.0)).collect();
    // All samples whose kernel lies inside the stream are out; the first 2 ms see the
    // stream's start (zeros before it) and are skipped; splitting the stream differently
    // gives the same samples.
    let output = converted_in_chunks_and_whole(&mut adc, &input, 1000, ratio);
    let worst = worst_error(&output, 8, |k| tone(k as f64 / 4_000.0));
    assert!(worst < 2e-6, "interpolation error {worst}");
    assert_eq!(adc.latency(), 16);
}

/// Issue 23, item 1: a 44.1 kHz stream sampled for a 200 Hz band (ratio 110.25, beyond
/// the kernel's reach of 16 samples) panicked once the kept history was trimmed past its
/// end. Any ratio must work: every sample comes out, right, in any split of the stream.
#[test]
fn a_ratio_beyond_the_kernel_reach_samples_a_long_stream() {
    let rate_hz = 44_100.0;
    let ratio = rate_hz / 400.0;
    let mut adc = interpolating_adc(ratio);
    let tone = |t: f64| (2.0 * PI * 50.0 * t).sin();
    let n = 44_100 * 5;
    let input: Vec<f64> = (0..n).map(|k| tone(k as f64 / rate_hz)).collect();
    let output = converted_in_chunks_and_whole(&mut adc, &input, 4096, ratio);
    let worst = worst_error(&output, 1, |k| tone(k as f64 / 400.0));
    assert!(worst < 1e-5, "interpolation error {worst}");
}

/// A ratio that is no fraction of a small denominator (4π stream samples per ADC sample)
/// has its weights computed at every sample; one a hair from 64/5 (1e-10 off, beyond the
/// 1e-12 at which it counts as 64/5) likewise. Both sample a tone as exactly as the
/// weights kept for the 5 phases of 64/5, and the last agrees with them to the shift of
/// its instants (at most 1e-10 · 12.8 · 4000 samples ≈ 5e-6 of a stream period late).
#[test]
fn ratios_with_and_without_kept_phases_sample_alike() {
    let tone = |t: f64| (2.0 * PI * 310.0 * t).sin();
    let input: Vec<f64> = (0..51_200).map(|k| tone(k as f64 / 51_200.0)).collect();
    let sampled = |ratio: f64| {
        let mut adc = interpolating_adc(ratio);
        let output = converted_in_chunks_and_whole(&mut adc, &input, 777, ratio);
        let adc_hz = 51_200.0 / ratio;
        let worst = worst_error(&output, 8, |k| tone(k as f64 / adc_hz));
        assert!(worst < 2e-6, "ratio {ratio}: interpolation error {worst}");
        output
    };
    sampled(4.0 * PI);
    let kept = sampled(12.8);
    let computed = sampled(12.8 * (1.0 + 1e-10));
    assert_eq!(kept.len(), computed.len());
    let apart = kept
        .iter()
        .zip(&computed)
        .skip(8)
        .map(|(a, b)| (a - b).abs())
        .fold(0.0, f64::max);
    // The instants drift by up to 1e-10 · 4000 · 12.8 stream samples, 5.1e-6 samples of a
    // tone of 310 Hz at 51.2 kHz: 2π · 310 / 51 200 · 5.1e-6 ≈ 2e-7 of its amplitude,
    // below one code of this converter (2.4e-7): the two agree to within one code.
    assert!(
        apart < 3e-7,
        "the kept and computed weights differ by {apart}"
    );
    assert!(
        apart > 0.0,
        "the hair's breadth must be taken as a different ratio"
    );
}

/// `input` converted in chunks of `chunk` samples, checked to hold every sample whose
/// kernel (16 samples each side) lies inside the stream at `ratio`, and to equal the
/// samples of the whole stream converted at once after a reset.
fn converted_in_chunks_and_whole(
    adc: &mut Adc,
    input: &[f64],
    chunk: usize,
    ratio: f64,
) -> Vec<f64> {
    let mut output = Vec::new();
    for part in input.chunks(chunk) {
        adc.convert(part, &mut output);
    }
    assert_eq!(
        output.len(),
        ((input.len() - 1 - 16) as f64 / ratio).floor() as usize + 1
    );
    adc.reset();
    let mut whole = Vec::new();
    adc.convert(input, &mut whole);
    assert_eq!(output, whole);
    output
}

/// A 24-bit ADC of ±2 V sampling every `ratio` stream samples.
fn interpolating_adc(ratio: f64) -> Adc {
    Adc::new(AdcSettings {
        ratio,
        bits: 24,
        range_v: 2.0,
        dither_seed: None,
    })
    .expect("valid")
}

/// Largest |sample − truth(k)| after the first `skip` samples.
fn worst_error(output: &[f64], skip: usize, truth: impl Fn(usize) -> f64) -> f64 {
    output
        .iter()
        .enumerate()
        .skip(skip)
        .map(|(k, &v)| (v - truth(k)).abs())
        .fold(0.0, f64::max)
}

/// Issue 23: a range of 5e-324 (the panel's `set_adc_range`) was accepted, giving a step
/// of 0 and codes of ±inf·0. The range must keep the step a normal number.
#[test]
fn a_range_too_small_or_too_large_for_finite_codes_is_refused() {
    for range_v in [5e-324, 1e-12, 1e12, f64::INFINITY] {
        let refused = Adc::new(AdcSettings {
            range_v,
            ..settings(12)
        });
        let message = refused.err().map(|e| e.to_string()).unwrap_or_default();
        assert!(message.contains("range"), "{range_v}: {message}");
    }
    for range_v in [1e-9, 1e9] {
        assert!(
            Adc::new(AdcSettings {
                range_v,
                ..settings(24)
            })
            .is_ok()
        );
    }
}
