//! Ground truth beside the measurement: which displayed lines are real components and
//! which are aliases, and of what true frequency. No real analyser can say this; the chain
//! can, because it holds the analogue signal before the ADC.
//!
//! For one analyser block (N ADC samples = N·M analogue samples, M the ADC's decimation)
//! the analogue block is analysed with the same window over the same span, so its lines
//! fall on the same Δf. Every analogue line above the ADC's Nyquist folds to
//! |f − round(f/f_s)·f_s|; a displayed line is an alias when one folded component carries
//! more than half of all the power that lands on it (in band plus folded), and it is named
//! after that component. Broadband noise, whose images are all alike, names none.

use crate::error::InstrumentError;
use crate::spectrum::{Spectrum, SpectrumEstimator};
use crate::window::Window;

/// Classifies displayed lines as real or aliased from the analogue signal.
pub struct AliasTruth {
    block: usize,
    estimator: SpectrumEstimator,
    one: Vec<f64>,
    sum: Vec<f64>,
}

impl AliasTruth {
    /// For analyser blocks of `block` ADC samples taken every `decimation`-th sample of an
    /// analogue stream at `analogue_rate_hz`, with `window`.
    pub fn new(
        block: usize,
        decimation: usize,
        analogue_rate_hz: f64,
        window: Window,
    ) -> Result<Self, InstrumentError> {
        if decimation == 0 {
            return Err(InstrumentError::setting(
                "alias truth",
                "decimation",
                decimation,
                "must be ≥ 1",
            ));
        }
        let estimator = SpectrumEstimator::of_length(block * decimation, analogue_rate_hz, window)?;
        Ok(Self {
            block,
            one: vec![0.0; estimator.lines()],
            sum: vec![0.0; estimator.lines()],
            estimator,
        })
    }

    /// Adds the analogue block of N·M samples behind one analyser block to the running sum.
    pub fn add(&mut self, analogue_block: &[f64]) {
        self.estimator
            .spectrum(analogue_block, Spectrum::Power, &mut self.one);
        self.sum
            .iter_mut()
            .zip(&self.one)
            .for_each(|(s, o)| *s += o);
    }

    /// Clears the running sum.
    pub fn restart(&mut self) {
        self.sum.iter_mut().for_each(|s| *s = 0.0);
    }

    /// For each of the first `lines` displayed lines, `None` if the line is a real
    /// component, or `Some(true frequency in Hz)` of the component aliased onto it, from
    /// the one analogue block of N·M samples that the ADC block came from.
    pub fn classify(&mut self, analogue_block: &[f64], lines: usize) -> Vec<Option<f64>> {
        self.restart();
        self.add(analogue_block);
        self.flags(lines)
    }

    /// As [`AliasTruth::classify`], from the analogue blocks added so far (their sum).
    pub fn flags(&self, lines: usize) -> Vec<Option<f64>> {
        let df = self.estimator.resolution_hz();
        let adc_lines = self.block;
        // Per displayed line: (power folded onto it, its largest contributor, that one's frequency).
        let mut folded = vec![(0.0_f64, 0.0_f64, None::<f64>); lines];
        for (j, &power) in self.sum.iter().enumerate().skip(self.block / 2 + 1) {
            // Analogue line j folds to ADC line |j − round(j/N)·N| (f_s = N·Δf).
            let image =
                j as i64 - ((j as f64 / adc_lines as f64).round() as i64) * adc_lines as i64;
            let k = image.unsigned_abs() as usize;
            if k < lines {
                let entry = &mut folded[k];
                entry.0 += power;
                if power > entry.1 {
                    entry.1 = power;
                    entry.2 = Some(j as f64 * df);
                }
            }
        }
        folded
            .iter()
            .enumerate()
            .map(|(k, &(total, largest, source))| {
                if largest > 0.5 * (total + self.sum[k]) {
                    source
                } else {
                    None
                }
            })
            .collect()
    }
}
