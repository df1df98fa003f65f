//! Windowed spectra of one block of samples with their scalings stated (Heinzel, Rüdiger
//! & Schilling 2002): with S1 = Σw, S2 = Σw², the power spectrum is 2|X|²/S1² (unit² rms
//! per line), the power spectral density 2|X|²/(f_s S2) (unit²/Hz), the linear spectrum
//! √(power spectrum) (unit rms); DC and Nyquist lines are not doubled.

use std::sync::Arc;

use num_complex::Complex64;
use rustfft::{Fft, FftPlanner};

use crate::error::{InstrumentError, require_positive};
use crate::window::Window;

/// Which spectrum, with its unit.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Spectrum {
    /// 2|X|²/S1²: a sinusoid's line reads its mean square (unit² rms).
    Power,
    /// 2|X|²/(f_s S2): noise density (unit²/Hz).
    Density,
    /// √(2|X|²/S1²): a sinusoid's line reads its rms amplitude (unit rms).
    Linear,
}

impl Spectrum {
    /// How the values are scaled, for metadata.
    pub fn scaling(self) -> &'static str {
        match self {
            Self::Power => "power spectrum 2|X|^2/S1^2 (unit^2 rms)",
            Self::Density => "power spectral density 2|X|^2/(fs S2) (unit^2/Hz)",
            Self::Linear => "linear spectrum sqrt(2|X|^2/S1^2) (unit rms)",
        }
    }
}

/// Computes windowed spectra of blocks of N samples (N a power of two) at one rate.
pub struct SpectrumEstimator {
    window: Window,
    weights: Vec<f64>,
    s1: f64,
    s2: f64,
    rate_hz: f64,
    fft: Arc<dyn Fft<f64>>,
    buffer: Vec<Complex64>,
    scratch: Vec<Complex64>,
}

impl SpectrumEstimator {
    /// An estimator for blocks of `n` samples at `rate_hz` with `window`; `n` a power of
    /// two from 16 to 2²⁰, as an analyser offers.
    pub fn new(n: usize, rate_hz: f64, window: Window) -> Result<Self, InstrumentError> {
        if !(n.is_power_of_two() && (16..=1 << 20).contains(&n)) {
            return Err(InstrumentError::setting(
                "Fourier analyser",
                "block size",
                n,
                "must be a power of two from 16 to 1048576",
            ));
        }
        Self::of_length(n, rate_hz, window)
    }

    /// An estimator for blocks of any length `n` ≥ 2 (for ground truth over a span that
    /// is not a power of two).
    pub fn of_length(n: usize, rate_hz: f64, window: Window) -> Result<Self, InstrumentError> {
        const NAME: &str = "spectrum";
        if n < 2 {
            return Err(InstrumentError::setting(
                NAME,
                "block size",
                n,
                "must be at least 2",
            ));
        }
        require_positive(NAME, "sample rate", rate_hz)?;
        let weights = window.coefficients(n);
        let fft = FftPlanner::new().plan_fft_forward(n);
        let scratch = vec![Complex64::default(); fft.get_inplace_scratch_len()];
        Ok(Self {
            window,
            s1: weights.iter().sum(),
            s2: weights.iter().map(|w| w * w).sum(),
            weights,
            rate_hz,
            fft,
            buffer: vec![Complex64::default(); n],
            scratch,
        })
    }

    /// Number of lines written by [`SpectrumEstimator::spectrum`]: N/2 + 1 (DC to Nyquist).
    pub fn lines(&self) -> usize {
        self.weights.len() / 2 + 1
    }

    /// Line spacing Δf = f_s / N (Hz).
    pub fn resolution_hz(&self) -> f64 {
        self.rate_hz / self.weights.len() as f64
    }

    /// Equivalent noise bandwidth f_s S2 / S1² (Hz).
    pub fn enbw_hz(&self) -> f64 {
        self.rate_hz * self.s2 / (self.s1 * self.s1)
    }

    /// The window in use.
    pub fn window(&self) -> Window {
        self.window
    }

    /// The spectrum of `block` (N samples) into `out` (N/2 + 1 lines).
    pub fn spectrum(&mut self, block: &[f64], kind: Spectrum, out: &mut [f64]) {
        let n = self.weights.len();
        assert!(
            block.len() == n && out.len() == n / 2 + 1,
            "block of N samples into N/2 + 1 lines"
        );
        for ((b, &x), &w) in self.buffer.iter_mut().zip(block).zip(&self.weights) {
            *b = Complex64::new(x * w, 0.0);
        }
        self.fft
            .process_with_scratch(&mut self.buffer, &mut self.scratch);
        let scale = match kind {
            Spectrum::Power | Spectrum::Linear => 2.0 / (self.s1 * self.s1),
            Spectrum::Density => 2.0 / (self.rate_hz * self.s2),
        };
        for (k, (o, x)) in out.iter_mut().zip(&self.buffer).enumerate() {
            let edge = if k == 0 || k == n / 2 { 0.5 } else { 1.0 };
            let power = edge * scale * x.norm_sqr();
            *o = if kind == Spectrum::Linear {
                power.sqrt()
            } else {
                power
            };
        }
    }
}
