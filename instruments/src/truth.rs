//! Ground truth beside the measurement: which displayed lines are real components and
//! which are aliases, and of what true frequency. No real analyser can say this; the chain
//! can, because it holds the analogue signal before the ADC.
//!
//! For one analyser block (N ADC samples = N·M analogue samples, M the ADC's decimation)
//! the analogue block is analysed with the same window over the same span, so its lines
//! fall on the same Δf. Every analogue line above the ADC's Nyquist folds to
//! |f − round(f/f_s)·f_s|; a displayed line is an alias when the power folded onto it
//! exceeds the power truly there, and it is named after its largest folded contributor.

use crate::error::InstrumentError;
use crate::spectrum::{Spectrum, SpectrumEstimator};
use crate::window::Window;

/// Classifies displayed lines as real or aliased from the analogue signal.
pub struct AliasTruth {
    block: usize,
    estimator: SpectrumEstimator,
    analogue: Vec<f64>,
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
        if decimation == 0 || !decimation.is_power_of_two() {
            return Err(InstrumentError::setting(
                "alias truth",
                "decimation",
                decimation,
                "must be a power of two ≥ 1",
            ));
        }
        let estimator = SpectrumEstimator::new(block * decimation, analogue_rate_hz, window)?;
        Ok(Self {
            block,
            analogue: vec![0.0; estimator.lines()],
            estimator,
        })
    }

    /// For each of the first `lines` displayed lines, `None` if the line is a real
    /// component, or `Some(true frequency in Hz)` of the component aliased onto it, from
    /// the analogue block of N·M samples that the ADC block came from.
    pub fn classify(&mut self, analogue_block: &[f64], lines: usize) -> Vec<Option<f64>> {
        self.estimator
            .spectrum(analogue_block, Spectrum::Power, &mut self.analogue);
        let df = self.estimator.resolution_hz();
        let adc_lines = self.block;
        let mut folded = vec![(0.0_f64, 0.0_f64, None::<f64>); lines];
        for (j, &power) in self.analogue.iter().enumerate().skip(self.block / 2 + 1) {
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
            .map(|(k, &(total, _, source))| {
                if total > self.analogue[k] {
                    source
                } else {
                    None
                }
            })
            .collect()
    }
}
