//! Windows and spectrum scalings against their known figures (Heinzel et al. 2002).

use instruments::{Spectrum, SpectrumEstimator, Window};
use rand::{RngExt, SeedableRng};
use rand_pcg::Pcg64Mcg;
use std::f64::consts::PI;

const N: usize = 1024;
const RATE: f64 = 1024.0;

fn sine(freq_hz: f64, amplitude: f64) -> Vec<f64> {
    (0..N)
        .map(|k| amplitude * (2.0 * PI * freq_hz * k as f64 / RATE + 0.3).sin())
        .collect()
}

fn power(window: Window, signal: &[f64]) -> Vec<f64> {
    let mut estimator = SpectrumEstimator::new(N, RATE, window).expect("valid");
    let mut out = vec![0.0; estimator.lines()];
    estimator.spectrum(signal, Spectrum::Power, &mut out);
    out
}

fn peak_db(lines: &[f64], mean_square: f64) -> f64 {
    10.0 * (lines.iter().copied().fold(0.0, f64::max) / mean_square).log10()
}

#[test]
fn a_bin_centred_sine_reads_its_mean_square() {
    let amplitude = 2.0;
    for window in [Window::Uniform, Window::Hanning, Window::FlatTop] {
        let lines = power(window, &sine(100.0, amplitude));
        let error = peak_db(&lines, amplitude * amplitude / 2.0);
        assert!(error.abs() < 0.01, "{window:?}: {error} dB");
    }
}

#[test]
fn half_a_bin_off_the_windows_lose_their_known_scalloping() {
    let amplitude = 1.0;
    let loss = |window| -peak_db(&power(window, &sine(100.5, amplitude)), 0.5);
    assert!(
        (loss(Window::Hanning) - 1.42).abs() < 0.01,
        "Hann: {} dB",
        loss(Window::Hanning)
    );
    assert!(
        loss(Window::FlatTop).abs() < 0.02,
        "flat-top: {} dB",
        loss(Window::FlatTop)
    );
    // The rectangular window's slow sidelobes let the negative-frequency image add to the
    // line, so its loss departs from the infinite-record 3.92 dB by a few hundredths.
    assert!(
        (loss(Window::Uniform) - 3.92).abs() < 0.05,
        "uniform: {} dB",
        loss(Window::Uniform)
    );
}

#[test]
fn equivalent_noise_bandwidths_are_the_known_ones() {
    let enbw_bins = |window| {
        SpectrumEstimator::new(N, RATE, window)
            .expect("valid")
            .enbw_hz()
            / (RATE / N as f64)
    };
    assert!((enbw_bins(Window::Uniform) - 1.0).abs() < 1e-12);
    assert!((enbw_bins(Window::Hanning) - 1.5).abs() < 1e-12);
    // Heinzel et al. give 3.77 bins for this flat-top.
    assert!(
        (enbw_bins(Window::FlatTop) - 3.77).abs() < 0.01,
        "{}",
        enbw_bins(Window::FlatTop)
    );
}

#[test]
fn white_noise_density_integrates_to_its_variance() {
    let sigma = 0.5;
    let mut rng = Pcg64Mcg::seed_from_u64(7);
    let mut gaussian = move || {
        // Box–Muller from two uniforms in (0, 1].
        let (u1, u2): (f64, f64) = (1.0 - rng.random::<f64>(), rng.random::<f64>());
        sigma * (-2.0 * u1.ln()).sqrt() * (2.0 * PI * u2).cos()
    };
    // A flat-top tapers hard, so each block carries fewer independent samples (S2²/S4):
    // its scatter at 100 averages is about 0.7 %, twice Hann's; it gets 2 %.
    for (window, tolerance) in [
        (Window::Hanning, 0.01),
        (Window::Uniform, 0.01),
        (Window::FlatTop, 0.02),
    ] {
        let mut estimator = SpectrumEstimator::new(N, RATE, window).expect("valid");
        let mut sum = vec![0.0; estimator.lines()];
        let mut one = vec![0.0; estimator.lines()];
        let averages = 100;
        for _ in 0..averages {
            let block: Vec<f64> = (0..N).map(|_| gaussian()).collect();
            estimator.spectrum(&block, Spectrum::Density, &mut one);
            sum.iter_mut().zip(&one).for_each(|(s, o)| *s += o);
        }
        let variance: f64 =
            sum.iter().map(|s| s / averages as f64).sum::<f64>() * estimator.resolution_hz();
        assert!(
            (variance / (sigma * sigma) - 1.0).abs() < tolerance,
            "{window:?}: {variance}"
        );
    }
}

#[test]
fn the_linear_spectrum_is_the_root_of_the_power_spectrum() {
    let signal = sine(37.0, 1.5);
    let mut estimator = SpectrumEstimator::new(N, RATE, Window::Hanning).expect("valid");
    let (mut p, mut l) = (vec![0.0; estimator.lines()], vec![0.0; estimator.lines()]);
    estimator.spectrum(&signal, Spectrum::Power, &mut p);
    estimator.spectrum(&signal, Spectrum::Linear, &mut l);
    for (a, b) in p.iter().zip(&l) {
        assert!((a.sqrt() - b).abs() <= 1e-15 * (1.0 + b));
    }
    assert!(
        (l[37] - 1.5 / 2f64.sqrt()).abs() < 1e-3,
        "rms amplitude {}",
        l[37]
    );
    assert!(
        SpectrumEstimator::new(1000, RATE, Window::Hanning).is_err(),
        "N must be a power of two"
    );
}
