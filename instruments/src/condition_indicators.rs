//! The condition indicators of gear diagnostics (Lebold, McClintic, Campbell, Byington &
//! Maynard 2000, "Review of vibration analysis methods for gearbox diagnostics and
//! prognostics", 54th MFPT): from the time-synchronous average of one gear's revolution,
//! its regular, difference and residual signals and the statistics on them.
//!
//! Definitions taken here (orders are per revolution of the averaged gear, z its teeth):
//! the **regular** signal holds the shaft's orders 1 to [`SHAFT_ORDERS`], the mesh
//! harmonics m·z and their first-order sidebands m·z ± 1; the **difference** signal is the
//! average less the regular signal; the **residual** signal the average less the shaft
//! orders and the mesh harmonics (sidebands kept). FM0 = peak-to-peak of the average over
//! the sum of the mesh harmonics' amplitudes; FM4, M6A, M8A = the 4th, 6th, 8th normalised
//! moments of the difference signal (N Σd⁴/(Σd²)², N² Σd⁶/(Σd²)³, N³ Σd⁸/(Σd²)⁴, d about
//! its mean); NA4 = the residual's 4th moment over the square of its variance averaged
//! with earlier runs' (a single run: its kurtosis); the sideband level = the first-order
//! sidebands of the first mesh harmonic over the RMS of the average; RMS, crest factor
//! (largest magnitude about the mean over the RMS about the mean) and kurtosis of the raw
//! signal. A Gaussian signal gives kurtosis, FM4 and NA4 of 3, M6A of 15, M8A of 105.

use num_complex::Complex;
use rustfft::FftPlanner;

/// Shaft orders counted as regular (orders 1 to this).
pub const SHAFT_ORDERS: usize = 3;

/// The indicators of one averaged revolution.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ConditionIndicators {
    /// Peak-to-peak of the average over the sum of the mesh harmonics' amplitudes.
    pub fm0: f64,
    /// Kurtosis of the difference signal.
    pub fm4: f64,
    /// Normalised 6th moment of the difference signal.
    pub m6a: f64,
    /// Normalised 8th moment of the difference signal.
    pub m8a: f64,
    /// The residual's 4th moment over its variance (averaged with earlier runs') squared.
    pub na4: f64,
    /// First-order sidebands of the first mesh harmonic over the RMS of the average.
    pub sideband_level: f64,
    /// RMS of the average about its mean (the signal's unit).
    pub rms: f64,
    /// Largest magnitude about the mean over the RMS about the mean, of the average.
    pub crest_factor: f64,
    /// Kurtosis of the average.
    pub kurtosis: f64,
}

/// The average split into its parts (same length as the average).
#[derive(Clone, Debug, PartialEq)]
pub struct GearSignals {
    /// Shaft orders, mesh harmonics and their first-order sidebands.
    pub regular: Vec<f64>,
    /// The average less the regular signal.
    pub difference: Vec<f64>,
    /// The average less the shaft orders and the mesh harmonics.
    pub residual: Vec<f64>,
    /// Amplitude of each mesh harmonic m·z (m = 1, 2, …; the signal's unit).
    pub mesh_amplitudes: Vec<f64>,
    /// Amplitudes of the sidebands z − 1 and z + 1.
    pub first_sidebands: [f64; 2],
}

/// The parts of `average` (one revolution of a gear of `teeth` teeth).
pub fn gear_signals(average: &[f64], teeth: usize) -> GearSignals {
    let n = average.len();
    let mut spectrum: Vec<Complex<f64>> = average.iter().map(|&x| Complex::new(x, 0.0)).collect();
    FftPlanner::new().plan_fft_forward(n).process(&mut spectrum);
    let top = n / 2;
    let amplitude = |k: usize| {
        let scale = if k == 0 || 2 * k == n { 1.0 } else { 2.0 };
        scale * spectrum[k].norm() / n as f64
    };
    let mesh: Vec<usize> = (1..).map(|m| m * teeth).take_while(|&k| k < top).collect();
    let shaft = 1..=SHAFT_ORDERS.min(top.saturating_sub(1));
    let sidebands: Vec<usize> = mesh
        .iter()
        .flat_map(|&k| [k - 1, k + 1])
        .filter(|&k| k > 0 && k < top)
        .collect();
    let keep = |orders: &[usize]| -> Vec<f64> {
        let mut kept = vec![Complex::new(0.0, 0.0); n];
        for &k in orders {
            kept[k] = spectrum[k];
            kept[n - k] = spectrum[n - k];
        }
        FftPlanner::new().plan_fft_inverse(n).process(&mut kept);
        kept.iter().map(|c| c.re / n as f64).collect()
    };
    let shaft_and_mesh: Vec<usize> = shaft.clone().chain(mesh.iter().copied()).collect();
    let mut regular_orders = shaft_and_mesh.clone();
    regular_orders.extend(&sidebands);
    regular_orders.sort_unstable();
    regular_orders.dedup();
    let regular = keep(&regular_orders);
    let mean = average.iter().sum::<f64>() / n as f64;
    let shaft_mesh = keep(&shaft_and_mesh);
    GearSignals {
        difference: average
            .iter()
            .zip(&regular)
            .map(|(x, r)| x - r - mean)
            .collect(),
        residual: average
            .iter()
            .zip(&shaft_mesh)
            .map(|(x, r)| x - r - mean)
            .collect(),
        regular,
        mesh_amplitudes: mesh.iter().map(|&k| amplitude(k)).collect(),
        first_sidebands: [teeth - 1, teeth + 1].map(|k| if k < top { amplitude(k) } else { 0.0 }),
    }
}

/// The `order`-th central moment of `x`: the mean of (x − x̄)^p (2 gives the variance).
pub fn central_moment(x: &[f64], order: i32) -> f64 {
    let n = x.len() as f64;
    let mean = x.iter().sum::<f64>() / n;
    x.iter().map(|v| (v - mean).powi(order)).sum::<f64>() / n
}

/// The normalised `order`-th moment of `x` about its mean: N^(p/2 − 1) Σ(x − x̄)^p /
/// (Σ(x − x̄)²)^(p/2), the central moment over the variance to the power p/2; 4 gives
/// the kurtosis.
pub fn normalised_moment(x: &[f64], order: i32) -> f64 {
    central_moment(x, order) / central_moment(x, 2).powi(order / 2)
}

/// The indicators of `average` (one revolution of a gear of `teeth` teeth), NA4 against
/// `earlier_residual_variances` (those of earlier runs of the trend; empty: this run alone).
pub fn condition_indicators(
    average: &[f64],
    teeth: usize,
    earlier_residual_variances: &[f64],
) -> ConditionIndicators {
    let parts = gear_signals(average, teeth);
    let mean = average.iter().sum::<f64>() / average.len() as f64;
    let rms = central_moment(average, 2).sqrt();
    let peak = average.iter().map(|x| (x - mean).abs()).fold(0.0, f64::max);
    let (max, min) = average
        .iter()
        .fold((f64::NEG_INFINITY, f64::INFINITY), |(hi, lo), &x| {
            (hi.max(x), lo.min(x))
        });
    let variance = central_moment(&parts.residual, 2);
    let trend = (variance + earlier_residual_variances.iter().sum::<f64>())
        / (1 + earlier_residual_variances.len()) as f64;
    let fourth = central_moment(&parts.residual, 4);
    ConditionIndicators {
        fm0: (max - min) / parts.mesh_amplitudes.iter().sum::<f64>(),
        fm4: normalised_moment(&parts.difference, 4),
        m6a: normalised_moment(&parts.difference, 6),
        m8a: normalised_moment(&parts.difference, 8),
        na4: fourth / (trend * trend),
        sideband_level: parts.first_sidebands.iter().sum::<f64>() / rms,
        rms,
        crest_factor: peak / rms,
        kurtosis: normalised_moment(average, 4),
    }
}
