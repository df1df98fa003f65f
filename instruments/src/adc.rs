//! The analyser's analogue-to-digital converter. It samples the analogue stream at its
//! own rate (so with the filter off, aliasing happens for real), quantises to n bits over
//! ±range, clips with an overload count, and can add seeded triangular dither.
//!
//! When the stream rate is a whole multiple M of the ADC rate, the ADC takes every M-th
//! sample. Otherwise it samples between stream samples by windowed-sinc interpolation
//! (16 lobes each side, Kaiser window β = 12, weights normalised to unit DC gain), exact to
//! about 1e-6 of the amplitude for content below 0.4 of the stream's Nyquist frequency,
//! with a latency of 16 stream samples. Where the ratio is a fraction p/q with q ≤ 256
//! (10 240 Hz over the thesis analyser's 400 Hz is 128/5), the ADC's instants fall on q
//! phases between stream samples, counted on in whole numbers: their weights are
//! computed once, not at every sample.

use rand::{RngExt, SeedableRng};
use rand_pcg::Pcg64Mcg;

use crate::error::InstrumentError;
use crate::phase::{FractionCounter, small_fraction};

/// Lobes each side of the interpolation kernel.
const LOBES: usize = 16;
/// Taps of the interpolation kernel.
const TAPS: usize = 2 * LOBES;
/// Largest denominator q of a ratio p/q whose phases' weights are kept.
const MAX_PHASES: u64 = 256;

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
    sampling: Sampling,
    received: u64,
    next: u64,
    history: Vec<f64>,
    history_start: u64,
    overloads: u64,
    rng: Option<Pcg64Mcg>,
}

/// How the converter finds its samples in the stream, by its ratio.
#[derive(Clone, Debug)]
enum Sampling {
    /// A whole ratio M: every M-th stream sample.
    Pick(u64),
    /// A ratio p/q with 1 < q ≤ [`MAX_PHASES`]: each phase's weights, and sample
    /// `next`'s centre ⌊next·p/q⌋ and phase next·p mod q, counted on as `next` moves.
    KeptPhases {
        weights: Vec<[f64; TAPS]>,
        counter: FractionCounter,
    },
    /// Any other ratio: each sample's weights computed at its instant.
    Computed,
}

impl Sampling {
    /// The way a ratio of `ratio` stream samples per ADC sample is sampled.
    fn of(ratio: f64) -> Self {
        match small_fraction(ratio, MAX_PHASES) {
            Some((p, 1)) => Self::Pick(p),
            Some((p, q)) => Self::KeptPhases {
                weights: phase_weights(q),
                counter: FractionCounter::new(p, q),
            },
            None => Self::Computed,
        }
    }
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
        let mut adc = Self {
            settings,
            step_v: 2.0 * settings.range_v / f64::from(1u32 << settings.bits),
            sampling: Sampling::of(settings.ratio),
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
        if let Sampling::KeptPhases { counter, .. } = &mut self.sampling {
            counter.reset();
        }
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
        if matches!(self.sampling, Sampling::Pick(_)) {
            0
        } else {
            LOBES
        }
    }

    /// Converts the analogue `input`, appending the ADC samples (V) to `output`.
    pub fn convert(&mut self, input: &[f64], output: &mut Vec<f64>) {
        match self.sampling {
            Sampling::Pick(m) => self.pick(m, input, output),
            _ => self.interpolate(input, output),
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
        let mut weights = [0.0; TAPS];
        for &v in input {
            self.history.push(v);
            self.received += 1;
            loop {
                let centre = self.next_centre();
                if centre + LOBES as u64 >= self.received {
                    break;
                }
                let taps = match &self.sampling {
                    Sampling::KeptPhases {
                        weights: kept,
                        counter,
                    } => &kept[counter.phase],
                    _ => {
                        let t = self.next as f64 * self.settings.ratio;
                        kernel_weights(t - centre as f64, &mut weights);
                        &weights
                    }
                };
                let value = self.weighted_sum(centre, taps);
                let code = self.quantise(value);
                output.push(code);
                self.advance();
            }
            self.trim();
        }
    }

    /// The stream sample at or before the next ADC sample's instant next·ratio.
    fn next_centre(&self) -> u64 {
        match &self.sampling {
            Sampling::KeptPhases { counter, .. } => counter.whole,
            // ≥ 0: truncation is the floor, without a call to `floor` on baseline x86-64.
            _ => (self.next as f64 * self.settings.ratio) as u64,
        }
    }

    /// On to the next ADC sample: its centre and phase moved on by p/q where kept.
    fn advance(&mut self) {
        self.next += 1;
        if let Sampling::KeptPhases { counter, .. } = &mut self.sampling {
            counter.advance();
        }
    }

    /// Σ x[i]·w[i] over the taps around `centre`, i from centre + 1 − LOBES (samples
    /// before the stream are 0).
    fn weighted_sum(&self, centre: u64, weights: &[f64; TAPS]) -> f64 {
        let first = centre as i64 + 1 - LOBES as i64;
        let mut sum = 0.0;
        for (k, w) in weights.iter().enumerate() {
            let i = first + k as i64;
            if i >= self.history_start as i64 {
                sum += w * self.history[(i as u64 - self.history_start) as usize];
            }
        }
        sum
    }

    /// Drops history no future sample needs, in chunks. The next sample may lie beyond
    /// the samples received (a ratio above the kernel's reach): never more than is held.
    fn trim(&mut self) {
        let needed_from = (self.next_centre() + 1).saturating_sub(LOBES as u64);
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

/// The weights of each of the q phases r/q (r = 0..q) of a ratio p/q.
fn phase_weights(q: u64) -> Vec<[f64; TAPS]> {
    (0..q)
        .map(|r| {
            let mut w = [0.0; TAPS];
            kernel_weights(r as f64 / q as f64, &mut w);
            w
        })
        .collect()
}

/// The kernel's weights for an instant `offset` ∈ [0, 1) samples past the centre c, at
/// the taps i = c + 1 − LOBES ..= c + LOBES, normalised to sum to one (unit gain at DC).
/// sin π(offset + c − i) is (−1)^(c − i)·sin π·offset: one sine per instant.
fn kernel_weights(offset: f64, weights: &mut [f64; TAPS]) {
    let sin_offset = (std::f64::consts::PI * offset).sin();
    for (k, w) in weights.iter_mut().enumerate() {
        let lag = LOBES as i64 - 1 - k as i64;
        let sign = if lag % 2 == 0 { 1.0 } else { -1.0 };
        *w = kernel(offset + lag as f64, sign * sin_offset);
    }
    let total: f64 = weights.iter().sum();
    for w in weights.iter_mut() {
        *w /= total;
    }
}

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
