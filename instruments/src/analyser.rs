//! The Fourier analyser in the style of the HP 5451C: blocks of N ADC samples, a window,
//! a spectrum with stated scaling, averaging (linear as the App. E program does it, i.e.
//! sum then divide; exponential; peak hold), overlap, and the displayed lines for the
//! thesis's or the modern sampling convention.

use crate::error::InstrumentError;
use crate::spectrum::{Spectrum, SpectrumEstimator};
use crate::window::Window;

/// How Fmax relates to the ADC rate and how many lines are shown.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Sampling {
    /// As the thesis states it: f_s = 2·Fmax, N/2 lines (Δf = 1/T).
    Thesis,
    /// As analysers since the 1980s: f_s = 2.56·Fmax, N/2.56 lines up to Fmax.
    Modern,
}

/// How successive spectra are combined.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Averaging {
    /// Sum of the spectra divided by their count (App. E: count loop, divide).
    Linear,
    /// Each new spectrum weighted 1/`weight` against the running average.
    Exponential {
        /// Averaging weight (≥ 1).
        weight: usize,
    },
    /// The largest value seen on each line.
    PeakHold,
}

/// The analyser's settings.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct AnalyserSettings {
    /// Block size N (a power of two).
    pub block: usize,
    /// Top of the displayed band (Hz).
    pub fmax_hz: f64,
    /// Sampling convention.
    pub sampling: Sampling,
    /// Window.
    pub window: Window,
    /// Which spectrum.
    pub spectrum: Spectrum,
    /// Averaging mode.
    pub averaging: Averaging,
    /// Spectra to average (≥ 1).
    pub averages: usize,
    /// Overlap of successive blocks, a fraction in [0, 1).
    pub overlap: f64,
}

impl AnalyserSettings {
    /// The thesis's setting (App. E): Hanning, power spectrum, 10 linear averages, no overlap.
    pub fn thesis(block: usize, fmax_hz: f64) -> Self {
        Self {
            block,
            fmax_hz,
            sampling: Sampling::Thesis,
            window: Window::Hanning,
            spectrum: Spectrum::Power,
            averaging: Averaging::Linear,
            averages: 10,
            overlap: 0.0,
        }
    }

    /// ADC rate the setting needs (Hz).
    pub fn sample_rate_hz(&self) -> f64 {
        match self.sampling {
            Sampling::Thesis => 2.0 * self.fmax_hz,
            Sampling::Modern => 2.56 * self.fmax_hz,
        }
    }

    /// Number of displayed lines, DC included.
    pub fn displayed_lines(&self) -> usize {
        match self.sampling {
            Sampling::Thesis => self.block / 2,
            Sampling::Modern => (self.block as f64 / 2.56).floor() as usize + 1,
        }
    }

    /// Samples between the starts of successive blocks.
    pub fn hop(&self) -> usize {
        ((self.block as f64 * (1.0 - self.overlap)).round() as usize).max(1)
    }
}

/// One displayed line.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Line {
    /// Line frequency (Hz).
    pub frequency_hz: f64,
    /// Averaged value in the spectrum's unit.
    pub value: f64,
}

/// The analyser with its input buffer and running average.
pub struct Analyser {
    settings: AnalyserSettings,
    estimator: SpectrumEstimator,
    pending: Vec<f64>,
    one: Vec<f64>,
    average: Vec<f64>,
    count: usize,
}

impl Analyser {
    /// An analyser; the settings are checked (N a power of two, Fmax > 0, averages ≥ 1,
    /// overlap in [0, 1), exponential weight ≥ 1).
    pub fn new(settings: AnalyserSettings) -> Result<Self, InstrumentError> {
        const NAME: &str = "Fourier analyser";
        if !(settings.fmax_hz.is_finite() && settings.fmax_hz > 0.0) {
            return Err(InstrumentError::setting(
                NAME,
                "Fmax",
                settings.fmax_hz,
                "must be finite and > 0 Hz",
            ));
        }
        if settings.averages == 0 {
            return Err(InstrumentError::setting(NAME, "averages", 0, "must be ≥ 1"));
        }
        if !(0.0..1.0).contains(&settings.overlap) {
            return Err(InstrumentError::setting(
                NAME,
                "overlap",
                settings.overlap,
                "must lie in [0, 1)",
            ));
        }
        if settings.averaging == (Averaging::Exponential { weight: 0 }) {
            return Err(InstrumentError::setting(
                NAME,
                "exponential weight",
                0,
                "must be ≥ 1",
            ));
        }
        let estimator =
            SpectrumEstimator::new(settings.block, settings.sample_rate_hz(), settings.window)?;
        let lines = estimator.lines();
        Ok(Self {
            settings,
            estimator,
            pending: Vec::with_capacity(2 * settings.block),
            one: vec![0.0; lines],
            average: vec![0.0; lines],
            count: 0,
        })
    }

    /// The settings.
    pub fn settings(&self) -> &AnalyserSettings {
        &self.settings
    }

    /// Takes ADC samples; every complete block (at the hop) joins the average until the
    /// set number of averages is reached (further samples are then ignored, as the
    /// analyser stops at the end of its count).
    pub fn push(&mut self, samples: &[f64]) {
        let n = self.settings.block;
        for &x in samples {
            if self.is_complete() {
                return;
            }
            self.pending.push(x);
            if self.pending.len() == n {
                self.estimator
                    .spectrum(&self.pending, self.settings.spectrum, &mut self.one);
                self.accumulate();
                self.pending.drain(..self.settings.hop());
            }
        }
    }

    fn accumulate(&mut self) {
        self.count += 1;
        let k = self.count as f64;
        for (a, &x) in self.average.iter_mut().zip(&self.one) {
            *a = match self.settings.averaging {
                Averaging::Linear => *a + x,
                Averaging::Exponential { weight } => {
                    let w = (weight as f64).min(k);
                    *a + (x - *a) / w
                }
                Averaging::PeakHold => a.max(x),
            };
        }
    }

    /// Spectra averaged so far (n of N).
    pub fn average_count(&self) -> usize {
        self.count
    }

    /// Whether the set number of averages has been taken.
    pub fn is_complete(&self) -> bool {
        self.count >= self.settings.averages
    }

    /// Starts a new average.
    pub fn restart(&mut self) {
        self.pending.clear();
        self.average.iter_mut().for_each(|a| *a = 0.0);
        self.count = 0;
    }

    /// The displayed lines of the average so far (linear averages divided by their count).
    pub fn display(&self) -> Vec<Line> {
        let divisor = match self.settings.averaging {
            Averaging::Linear => self.count.max(1) as f64,
            _ => 1.0,
        };
        let df = self.estimator.resolution_hz();
        (0..self.settings.displayed_lines().min(self.average.len()))
            .map(|k| Line {
                frequency_hz: k as f64 * df,
                value: self.average[k] / divisor,
            })
            .collect()
    }

    /// The displayed lines in dB (10·log10 of the value), as the 5451C's log display.
    pub fn display_db(&self) -> Vec<Line> {
        self.display()
            .into_iter()
            .map(|line| Line {
                value: 10.0 * line.value.log10(),
                ..line
            })
            .collect()
    }

    /// Equivalent noise bandwidth of the window (Hz).
    pub fn enbw_hz(&self) -> f64 {
        self.estimator.enbw_hz()
    }
}
