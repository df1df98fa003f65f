//! The analyser's analogue-to-digital converter: it samples the analogue stream every M-th
//! sample (so with the filter off, aliasing happens for real), quantises to n bits over
//! ±range, clips with an overload count, and can add seeded triangular dither.

use rand::{RngExt, SeedableRng};
use rand_pcg::Pcg64Mcg;

use crate::error::InstrumentError;

/// ADC settings.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct AdcSettings {
    /// Keep every `decimation`-th sample of the analogue stream (ADC rate = stream rate / M).
    pub decimation: usize,
    /// Resolution (bits), 2..=24.
    pub bits: u32,
    /// Full scale ±range (V).
    pub range_v: f64,
    /// Triangular dither of ±1 LSB, from this seed; `None` for none.
    pub dither_seed: Option<u64>,
}

/// The converter, with its state across buffers.
#[derive(Clone, Debug)]
pub struct Adc {
    settings: AdcSettings,
    step_v: f64,
    phase: usize,
    overloads: u64,
    rng: Option<Pcg64Mcg>,
}

impl Adc {
    /// A converter; decimation ≥ 1, 2 ≤ bits ≤ 24, range finite and > 0.
    pub fn new(settings: AdcSettings) -> Result<Self, InstrumentError> {
        const NAME: &str = "ADC";
        if settings.decimation == 0 {
            return Err(InstrumentError::setting(
                NAME,
                "decimation",
                0,
                "must be ≥ 1",
            ));
        }
        if !(2..=24).contains(&settings.bits) {
            return Err(InstrumentError::setting(
                NAME,
                "bits",
                settings.bits,
                "must lie in 2..=24",
            ));
        }
        if !(settings.range_v.is_finite() && settings.range_v > 0.0) {
            return Err(InstrumentError::setting(
                NAME,
                "range",
                settings.range_v,
                "must be finite and > 0 V",
            ));
        }
        let mut adc = Self {
            settings,
            step_v: 2.0 * settings.range_v / f64::from(1u32 << settings.bits),
            phase: 0,
            overloads: 0,
            rng: None,
        };
        adc.reset();
        Ok(adc)
    }

    /// Returns to the state after construction (dither sequence included).
    pub fn reset(&mut self) {
        self.phase = 0;
        self.overloads = 0;
        self.rng = self.settings.dither_seed.map(Pcg64Mcg::seed_from_u64);
    }

    /// One quantisation step (V).
    pub fn lsb_v(&self) -> f64 {
        self.step_v
    }

    /// Samples that hit full scale so far.
    pub fn overloads(&self) -> u64 {
        self.overloads
    }

    /// Converts the analogue `input`, appending the ADC samples (V) to `output`.
    pub fn convert(&mut self, input: &[f64], output: &mut Vec<f64>) {
        let half = f64::from(1u32 << (self.settings.bits - 1));
        for &v in input {
            if self.phase == 0 {
                let dither = self
                    .rng
                    .as_mut()
                    .map_or(0.0, |r| r.random::<f64>() - r.random::<f64>());
                let code = (v / self.step_v + dither).round();
                let clipped = code.clamp(-half, half - 1.0);
                if clipped != code {
                    self.overloads += 1;
                }
                output.push(clipped * self.step_v);
            }
            self.phase = (self.phase + 1) % self.settings.decimation;
        }
    }
}
