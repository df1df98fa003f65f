//! Ground truth beside the measurement: which displayed lines are real components and
//! which are aliases, and of what true frequency. No real analyser can say this; the chain
//! can, because it holds the analogue signal before the ADC.
//!
//! For one analyser block (N ADC samples, round(N·r) analogue samples for an ADC that
//! samples once every r stream samples) the analogue block is analysed with the same window
//! over the same span, so its lines fall on the same Δf. Every analogue line above the
//! ADC's Nyquist folds to
//! |f − round(f/f_s)·f_s|; a displayed line is an alias when one folded component carries
//! more than half of all the power that lands on it (in band plus folded), and it is named
//! after that component. Broadband noise, whose images are all alike, names none. A line
//! whose whole power (in band plus folded, per block) lies below a floor (the ADC's
//! quantisation noise per line) is not flagged: nothing there can be seen.

use crate::error::InstrumentError;
use crate::spectrum::{Spectrum, SpectrumEstimator};
use crate::window::Window;

/// Longest analogue block behind one analyser block (samples): 16 Mi, 128 MiB of f64.
pub const MAX_SPAN_SAMPLES: f64 = 16_777_216.0;

/// Classifies displayed lines as real or aliased from the analogue signal.
pub struct AliasTruth {
    span: usize,
    ratio: f64,
    adc_rate_hz: f64,
    adc_resolution_hz: f64,
    estimator: SpectrumEstimator,
    one: Vec<f64>,
    sum: Vec<f64>,
    blocks: usize,
}

impl AliasTruth {
    /// For analyser blocks of `block` ADC samples, the ADC sampling a stream at
    /// `analogue_rate_hz` once every `ratio` stream samples, with `window`.
    pub fn new(
        block: usize,
        ratio: f64,
        analogue_rate_hz: f64,
        window: Window,
    ) -> Result<Self, InstrumentError> {
        let span_samples = block as f64 * ratio;
        if !(ratio.is_finite() && ratio >= 1.0 && span_samples <= MAX_SPAN_SAMPLES) {
            return Err(InstrumentError::setting(
                "alias truth",
                "rate ratio",
                ratio,
                "must be ≥ 1, with an analogue block of at most 16 Mi samples (a band too narrow for the stream rate)",
            ));
        }
        let span = span_samples.round() as usize;
        let estimator = SpectrumEstimator::of_length(span, analogue_rate_hz, window)?;
        let adc_rate_hz = analogue_rate_hz / ratio;
        Ok(Self {
            span,
            ratio,
            adc_rate_hz,
            adc_resolution_hz: adc_rate_hz / block as f64,
            one: vec![0.0; estimator.lines()],
            sum: vec![0.0; estimator.lines()],
            blocks: 0,
            estimator,
        })
    }

    /// Stream samples in the analogue block behind one analyser block: round(N·ratio).
    pub fn span(&self) -> usize {
        self.span
    }

    /// Adds the analogue block of [`AliasTruth::span`] samples behind one analyser block.
    pub fn add(&mut self, analogue_block: &[f64]) {
        self.estimator
            .spectrum(analogue_block, Spectrum::Power, &mut self.one);
        self.sum
            .iter_mut()
            .zip(&self.one)
            .for_each(|(s, o)| *s += o);
        self.blocks += 1;
    }

    /// Adds the analogue blocks behind analyser blocks [`AliasTruth::blocks`]..`count`,
    /// taken every `hop` ADC samples from the start of `analogue` (the stream since the
    /// average began), so that it can be called again as an average grows (after
    /// [`AliasTruth::restart`], every block from the first); a block that would run past
    /// the end of `analogue` is left for a later call.
    pub fn add_blocks(&mut self, analogue: &[f64], count: usize, hop: usize) {
        let hop_samples = hop as f64 * self.ratio;
        for b in self.blocks..count {
            let start = (b as f64 * hop_samples).round() as usize;
            if let Some(block) = analogue.get(start..start + self.span) {
                self.add(block);
            }
        }
    }

    /// Analogue blocks added since the last restart.
    pub fn blocks(&self) -> usize {
        self.blocks
    }

    /// Clears the running sum.
    pub fn restart(&mut self) {
        self.sum.iter_mut().for_each(|s| *s = 0.0);
        self.blocks = 0;
    }

    /// For each of the first `lines` displayed lines, `None` if the line is a real
    /// component or lies below `floor_power` (power per line, unit² rms; 0 flags every
    /// alias), or `Some(true frequency in Hz)` of the component aliased onto it, from the
    /// one analogue block that the ADC block came from.
    pub fn classify(
        &mut self,
        analogue_block: &[f64],
        lines: usize,
        floor_power: f64,
    ) -> Vec<Option<f64>> {
        self.restart();
        self.add(analogue_block);
        self.flags(lines, floor_power)
    }

    /// As [`AliasTruth::classify`], from the analogue blocks added so far (their mean).
    pub fn flags(&self, lines: usize, floor_power: f64) -> Vec<Option<f64>> {
        let floor_sum = floor_power * self.blocks as f64;
        let df = self.estimator.resolution_hz();
        let nyquist = self.adc_rate_hz / 2.0;
        // Per displayed line: (power folded onto it, its largest contributor, that one's frequency).
        let mut folded = vec![(0.0_f64, 0.0_f64, None::<f64>); lines];
        for (j, &power) in self.sum.iter().enumerate() {
            let f = j as f64 * df;
            if f <= nyquist {
                continue;
            }
            let image = (f - (f / self.adc_rate_hz).round() * self.adc_rate_hz).abs();
            let k = (image / self.adc_resolution_hz).round() as usize;
            if let Some(entry) = folded.get_mut(k) {
                entry.0 += power;
                if power > entry.1 {
                    entry.1 = power;
                    entry.2 = Some(f);
                }
            }
        }
        folded
            .iter()
            .enumerate()
            .map(|(k, &(total, largest, source))| {
                let in_band = self
                    .sum
                    .get((k as f64 * self.adc_resolution_hz / df).round() as usize)
                    .copied()
                    .unwrap_or(0.0);
                if largest > 0.5 * (total + in_band) && total + in_band > floor_sum {
                    source
                } else {
                    None
                }
            })
            .collect()
    }
}
