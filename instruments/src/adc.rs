//! The analyser's analogue-to-digital converter. It samples the analogue stream at its
//! own rate (so with the filter off, aliasing happens for real), quantises to n bits over
//! ±range, clips with an overload count, and can add seeded triangular dither.
//!
//! When the stream rate is a whole multiple M of the ADC rate, the ADC takes every M-th
//! sample. Otherwise it samples between stream samples by windowed-sinc interpolation
//! (16 lobes each side, Kaiser window β = 12, weights normalised to unit DC gain), exact to
//! about 1e-6 of the amplitude for content below 0.4 of the stream's Nyquist frequency,
//! with a latency of 16 stream samples.

use rand::{RngExt, SeedableRng};
use rand_pcg::Pcg64Mcg;

use crate::error::InstrumentError;

/// Lobes each side of the interpolation kernel.
const LOBES: usize = 16;

/// ADC settings.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct AdcSettings {
    /// Stream samples per ADC sample, ≥ 1 (ADC rate = stream rate / ratio); a whole
    /// number picks samples, any other interpolates between them.
    pub ratio: f64,
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
    whole: Option<u64>,
    received: u64,
    next: u64,
    history: Vec<f64>,
    history_start: u64,
    overloads: u64,
    rng: Option<Pcg64Mcg>,
}

impl Adc {
    /// A converter; ratio ≥ 1, 2 ≤ bits ≤ 24, range in [1e-9, 1e9] (a step of a
    /// normal number, so that every code is finite).
    pub fn new(settings: AdcSettings) -> Result<Self, InstrumentError> {
        const NAME: &str = "ADC";
        if !(settings.ratio.is_finite() && settings.ratio >= 1.0) {
            return Err(InstrumentError::setting(
                NAME,
                "rate ratio",
                settings.ratio,
                "the stream rate over the ADC rate must be ≥ 1",
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
        if !(MIN_RANGE..=MAX_RANGE).contains(&settings.range_v) {
            return Err(InstrumentError::setting(
                NAME,
                "range",
                settings.range_v,
                "the ± full scale must lie in [1e-9, 1e9] (in the signal's unit)",
            ));
        }
        let rounded = settings.ratio.round();
        let mut adc = Self {
            settings,
            step_v: 2.0 * settings.range_v / f64::from(1u32 << settings.bits),
            whole: ((settings.ratio - rounded).abs() < 1e-12 * settings.ratio)
                .then_some(rounded as u64),
            received: 0,
            next: 0,
            history: Vec::new(),
            history_start: 0,
            overloads: 0,
            rng: None,
        };
        adc.reset();
        Ok(adc)
    }

    /// Returns to the state after construction (dither sequence included).
    pub fn reset(&mut self) {
        self.received = 0;
        self.next = 0;
        self.history.clear();
        self.history_start = 0;
        self.overloads = 0;
        self.rng = self.settings.dither_seed.map(Pcg64Mcg::seed_from_u64);
    }

    /// One quantisation step (V).
    pub fn lsb_v(&self) -> f64 {
        self.step_v
    }

    /// Power per displayed line (V² rms, the analyser's power scaling) of the quantisation
    /// noise, q²/12 spread evenly over 0..fs/2, for a window of equivalent noise bandwidth
    /// `enbw_hz` at the ADC rate `adc_rate_hz`: 2·(q²/12)·ENBW/fs (Heinzel et al. 2002).
    /// The floor below which no line of the display can be told from the converter's own
    /// noise.
    pub fn quantisation_line_power(&self, enbw_hz: f64, adc_rate_hz: f64) -> f64 {
        self.step_v * self.step_v / 6.0 * enbw_hz / adc_rate_hz
    }

    /// Samples that hit full scale so far.
    pub fn overloads(&self) -> u64 {
        self.overloads
    }

    /// Stream samples the ADC holds back before it can sample (0 when it picks samples).
    pub fn latency(&self) -> usize {
        if self.whole.is_some() { 0 } else { LOBES }
    }

    /// Converts the analogue `input`, appending the ADC samples (V) to `output`.
    pub fn convert(&mut self, input: &[f64], output: &mut Vec<f64>) {
        match self.whole {
            Some(m) => self.pick(m, input, output),
            None => self.interpolate(input, output),
        }
    }

    fn pick(&mut self, m: u64, input: &[f64], output: &mut Vec<f64>) {
        for &v in input {
            if self.received == self.next * m {
                let code = self.quantise(v);
                output.push(code);
                self.next += 1;
            }
            self.received += 1;
        }
    }

    fn interpolate(&mut self, input: &[f64], output: &mut Vec<f64>) {
        for &v in input {
            self.history.push(v);
            self.received += 1;
            loop {
                let t = self.next as f64 * self.settings.ratio;
                let centre = t.floor() as u64;
                if centre + LOBES as u64 >= self.received {
                    break;
                }
                let value = self.lanczos(t, centre);
                let code = self.quantise(value);
                output.push(code);
                self.next += 1;
            }
            self.trim();
        }
    }

    /// Σ x[i]·w(t − i) / Σ w(t − i) over the 2·LOBES samples around t (samples before
    /// the stream are 0); normalising the weights makes the gain at DC exactly one.
    /// sin π(t − i) is (−1)^(i − c)·sin π(t − c) for c = ⌊t⌋: one sine per sample.
    fn lanczos(&self, t: f64, centre: u64) -> f64 {
        let sin_offset = (std::f64::consts::PI * (t - centre as f64)).sin();
        let (mut sum, mut weights) = (0.0, 0.0);
        for i in centre as i64 + 1 - LOBES as i64..=centre as i64 + LOBES as i64 {
            let sign = if (i - centre as i64) % 2 == 0 {
                1.0
            } else {
                -1.0
            };
            let w = kernel(t - i as f64, sign * sin_offset);
            weights += w;
            if i >= self.history_start as i64 {
                sum += w * self.history[(i as u64 - self.history_start) as usize];
            }
        }
        sum / weights
    }

    /// Drops history no future sample needs, in chunks. The next sample may lie beyond
    /// the samples received (a ratio above the kernel's reach): never more than is held.
    fn trim(&mut self) {
        let needed_from = ((self.next as f64 * self.settings.ratio).floor() as u64 + 1)
            .saturating_sub(LOBES as u64);
        let drop =
            (needed_from.saturating_sub(self.history_start) as usize).min(self.history.len());
        if drop > 4096 {
            self.history.drain(..drop);
            self.history_start += drop as u64;
        }
    }

    fn quantise(&mut self, v: f64) -> f64 {
        let half = f64::from(1u32 << (self.settings.bits - 1));
        let dither = self
            .rng
            .as_mut()
            .map_or(0.0, |r| r.random::<f64>() - r.random::<f64>());
        let code = (v / self.step_v + dither).round();
        let clipped = code.clamp(-half, half - 1.0);
        if clipped != code {
            self.overloads += 1;
        }
        clipped * self.step_v
    }
}

/// Smallest ± full scale accepted (in the signal's unit).
const MIN_RANGE: f64 = 1e-9;
/// Largest ± full scale accepted (in the signal's unit).
const MAX_RANGE: f64 = 1e9;

/// Kaiser window shape β.
const KAISER_BETA: f64 = 12.0;

/// Windowed sinc: sinc(x)·I0(β√(1 − (x/a)²))/I0(β), a = 16 lobes, given sin πx.
fn kernel(x: f64, sin_pi_x: f64) -> f64 {
    let a = LOBES as f64;
    if x.abs() >= a {
        return 0.0;
    }
    let window = bessel_i0(KAISER_BETA * (1.0 - (x / a).powi(2)).sqrt()) / kaiser_i0_beta();
    let sinc = if x == 0.0 {
        1.0
    } else {
        sin_pi_x / (std::f64::consts::PI * x)
    };
    sinc * window
}

/// I0(β) of the Kaiser window, computed once.
fn kaiser_i0_beta() -> f64 {
    static I0_BETA: std::sync::OnceLock<f64> = std::sync::OnceLock::new();
    *I0_BETA.get_or_init(|| bessel_i0(KAISER_BETA))
}

/// Modified Bessel function of the first kind, order 0: Σ ((x/2)^k / k!)², to rounding.
fn bessel_i0(x: f64) -> f64 {
    let (mut sum, mut term) = (1.0, 1.0);
    let half = x / 2.0;
    for k in 1..60 {
        term *= half / k as f64;
        let add = term * term;
        sum += add;
        if add < 1e-17 * sum {
            break;
        }
    }
    sum
}
