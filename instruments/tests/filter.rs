//! The anti-alias filter against its analytic response and the analog prototype.

use instruments::{AntiAliasFilter, Block, FilterKind, LowPassSpec};
use num_complex::Complex64;
use std::f64::consts::PI;

const RATE: f64 = 51_200.0;

fn filter(kind: FilterKind, order: usize, cutoff_hz: f64) -> AntiAliasFilter {
    AntiAliasFilter::new(
        Some(LowPassSpec {
            kind,
            order,
            cutoff_hz,
        }),
        RATE,
    )
    .expect("valid filter")
}

fn db(x: f64) -> f64 {
    20.0 * x.log10()
}

/// Complex gain measured by driving a unit sine for 2 s and projecting the last second.
fn measured_gain(f: &mut AntiAliasFilter, freq_hz: f64) -> Complex64 {
    let n = (2.0 * RATE) as usize;
    let input: Vec<f64> = (0..n)
        .map(|k| (2.0 * PI * freq_hz * k as f64 / RATE).sin())
        .collect();
    let mut output = vec![0.0; n];
    f.reset();
    f.process(&input, &mut output);
    let half = n / 2;
    let mut acc = Complex64::new(0.0, 0.0);
    for (k, &y) in output.iter().enumerate().skip(half) {
        let phase = 2.0 * PI * freq_hz * k as f64 / RATE;
        acc += y * Complex64::new(phase.sin(), phase.cos());
    }
    // sin(ωt + θ)·|H| projected on e^{-j(ωt - π/2)} gives |H| e^{jθ} × N/2.
    acc * 2.0 / (n - half) as f64
}

fn check_against_response(kind: FilterKind, order: usize, cutoff_hz: f64) {
    let mut f = filter(kind, order, cutoff_hz);
    for freq in [50.0, 300.0, 900.0, 1500.0, 1900.0, 2000.0] {
        let want = f.response(freq).expect("linear");
        let got = measured_gain(&mut f, freq);
        let gain_error = db(got.norm()) - db(want.norm());
        let phase_error = (got / want).arg().to_degrees();
        assert!(
            gain_error.abs() < 0.01,
            "{kind:?} {order} at {freq} Hz: {gain_error} dB"
        );
        assert!(
            phase_error.abs() < 0.1,
            "{kind:?} {order} at {freq} Hz: {phase_error}°"
        );
    }
}

#[test]
fn butterworth_output_matches_its_response_in_the_pass_band() {
    check_against_response(FilterKind::Butterworth, 4, 2_000.0);
    check_against_response(FilterKind::Butterworth, 8, 2_000.0);
}

#[test]
fn bessel_output_matches_its_response_in_the_pass_band() {
    check_against_response(FilterKind::Bessel, 4, 2_000.0);
    check_against_response(FilterKind::Bessel, 6, 2_000.0);
}

#[test]
fn both_families_are_3_db_down_at_the_cutoff() {
    for kind in [FilterKind::Butterworth, FilterKind::Bessel] {
        for order in 1..=8 {
            let f = filter(kind, order, 1_800.0);
            let at_cutoff = db(f.response(1_800.0).expect("linear").norm());
            assert!(
                (at_cutoff + 3.0103).abs() < 1e-3,
                "{kind:?} {order}: {at_cutoff} dB"
            );
            assert!((f.response(0.0).expect("linear").norm() - 1.0).abs() < 1e-12);
        }
    }
}

#[test]
fn butterworth_matches_the_analog_prototype_through_the_bilinear_map() {
    // |H|² = 1 / (1 + (Ω/Ω_c)^{2n}) with Ω = 2 f_s tan(π f / f_s).
    let (order, cutoff) = (6, 2_000.0);
    let f = filter(FilterKind::Butterworth, order, cutoff);
    let warp = |hz: f64| (PI * hz / RATE).tan();
    for freq in [10.0, 500.0, 1_999.0, 2_500.0, 8_000.0, 20_000.0] {
        let ratio = warp(freq) / warp(cutoff);
        let want = 1.0 / (1.0 + ratio.powi(2 * order as i32)).sqrt();
        let got = f.response(freq).expect("linear").norm();
        assert!(
            (got - want).abs() < 1e-9 * want.max(1e-6),
            "{freq} Hz: {got} vs {want}"
        );
    }
}

#[test]
fn bessel_group_delay_is_flat_in_the_pass_band() {
    let f = filter(FilterKind::Bessel, 6, 2_000.0);
    let delay = |hz: f64| {
        let dh = 0.01;
        let (a, b) = (
            f.response(hz - dh).expect("linear"),
            f.response(hz + dh).expect("linear"),
        );
        -(b / a).arg() / (2.0 * PI * 2.0 * dh)
    };
    let d0 = delay(20.0);
    // Within 2 % of the DC group delay up to half the cut-off (a Butterworth of the same
    // order departs by far more).
    for hz in [200.0, 500.0, 1_000.0] {
        assert!(
            (delay(hz) - d0).abs() < 0.02 * d0,
            "{hz} Hz: {} vs {d0}",
            delay(hz)
        );
    }
}

#[test]
fn a_signal_cut_into_buffers_gives_the_same_output_and_reset_reproduces_it() {
    let mut f = filter(FilterKind::Butterworth, 5, 1_000.0);
    let input: Vec<f64> = (0..10_000)
        .map(|k| ((k * 7919) % 1000) as f64 / 500.0 - 1.0)
        .collect();
    let mut whole = vec![0.0; input.len()];
    f.process(&input, &mut whole);
    f.reset();
    let mut pieces = vec![0.0; input.len()];
    let mut start = 0;
    for len in [1, 7, 100, 333, 2048].iter().cycle() {
        if start >= input.len() {
            break;
        }
        let end = (start + len).min(input.len());
        f.process(&input[start..end], &mut pieces[start..end]);
        start = end;
    }
    assert_eq!(whole, pieces);
}

#[test]
fn bypass_passes_the_signal_and_bad_settings_are_refused() {
    let mut bypass = AntiAliasFilter::new(None, RATE).expect("valid");
    let input = [1.0, -2.0, 3.5];
    let mut output = [0.0; 3];
    bypass.process(&input, &mut output);
    assert_eq!(input, output);
    let above_nyquist = LowPassSpec {
        kind: FilterKind::Butterworth,
        order: 4,
        cutoff_hz: 30_000.0,
    };
    let err = AntiAliasFilter::new(Some(above_nyquist), RATE).expect_err("cut-off above Nyquist");
    assert!(err.to_string().contains("cut-off"), "{err}");
    let no_order = LowPassSpec {
        kind: FilterKind::Bessel,
        order: 0,
        cutoff_hz: 100.0,
    };
    assert!(AntiAliasFilter::new(Some(no_order), RATE).is_err());
}
