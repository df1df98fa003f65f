//! The carrier amplifier (Tektronix 3C66 style) as two blocks sharing one carrier: the
//! modulator (the AC-excited bridge: bridge output × cos ω_c t) before the slip rings, and
//! the demodulator after them (×2 cos ω_c t, a second-order Butterworth low-pass, and the
//! calibrated gain). What the low-pass leaves of the 2ω_c product is the carrier ripple.

use num_complex::Complex64;

use crate::biquad::Biquad;
use crate::block::Block;
use crate::error::InstrumentError;
use crate::lowpass::{AntiAliasFilter, FilterKind, LowPassSpec};
use crate::phase::{FractionCounter, small_fraction};

/// Carrier settings shared by modulator and demodulator.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct CarrierSettings {
    /// Carrier frequency (Hz); below the stream's Nyquist (the 3C66's is not known: a parameter).
    pub carrier_hz: f64,
    /// Corner of the output low-pass (Hz).
    pub output_lowpass_hz: f64,
    /// Output volts per volt of bridge output (the calibration, e.g. 3 V on the scope for
    /// the bridge voltage of 200 µε).
    pub gain: f64,
}

impl CarrierSettings {
    /// The gain that makes `microstrain_per_div` on the amplifier's scale read
    /// `volts_per_div` at its output, for a bridge giving `bridge_volts_per_strain` (V per
    /// unit strain: GF·E_in for the full bridge). The thesis's scope shows 3 V for 200 µε.
    pub fn calibrated_gain(
        microstrain_per_div: f64,
        volts_per_div: f64,
        bridge_volts_per_strain: f64,
    ) -> f64 {
        volts_per_div / (microstrain_per_div * 1e-6 * bridge_volts_per_strain)
    }
}

fn check(settings: &CarrierSettings, rate_hz: f64) -> Result<(), InstrumentError> {
    let nyquist = rate_hz / 2.0;
    if !(settings.carrier_hz > 0.0 && settings.carrier_hz < nyquist / 2.0) {
        return Err(InstrumentError::setting(
            "carrier amplifier",
            "carrier",
            settings.carrier_hz,
            format!(
                "must lie in (0, {}) Hz so that 2ω_c stays below the stream's Nyquist",
                nyquist / 2.0
            ),
        ));
    }
    if !(settings.output_lowpass_hz > 0.0 && settings.output_lowpass_hz < settings.carrier_hz) {
        return Err(InstrumentError::setting(
            "carrier amplifier",
            "output low-pass",
            settings.output_lowpass_hz,
            "must lie between 0 and the carrier frequency",
        ));
    }
    if !settings.gain.is_finite() {
        return Err(InstrumentError::setting(
            "carrier amplifier",
            "gain",
            settings.gain,
            "must be finite",
        ));
    }
    Ok(())
}

/// Largest number of samples q over which a tabulated carrier repeats.
const MAX_TABULATED_SAMPLES: u64 = 1024;

/// The carrier cos ω_c t at the stream's samples k = 0, 1, …, counted on one sample at a
/// time. Where f_c/f_s is p/q in lowest terms with q ≤ 1024 (2 kHz on 10.24 kHz is
/// 25/128), the q values cos 2π·r/q are tabulated and read at r = k·p mod q, counted in
/// whole numbers: one phase error of rounding for any k, where cos(ω·k) loses the
/// phase's low bits as k grows (1e-10 rad after 10⁶ samples). Otherwise cos(ω·k).
#[derive(Clone, Debug, PartialEq)]
enum CarrierWave {
    /// cos 2π·r/q for r in 0..q, and k·p mod q.
    Tabulated(Vec<f64>, FractionCounter),
    /// ω per sample and k.
    Computed(f64, u64),
}

impl CarrierWave {
    fn new(carrier_hz: f64, rate_hz: f64) -> Self {
        let cycles_per_sample = carrier_hz / rate_hz;
        match small_fraction(cycles_per_sample, MAX_TABULATED_SAMPLES) {
            Some((p, q)) => Self::Tabulated(
                (0..q)
                    .map(|r| (std::f64::consts::TAU * r as f64 / q as f64).cos())
                    .collect(),
                FractionCounter::new(p, q),
            ),
            None => Self::Computed(std::f64::consts::TAU * cycles_per_sample, 0),
        }
    }

    /// Back to sample 0.
    fn reset(&mut self) {
        match self {
            Self::Tabulated(_, counter) => counter.reset(),
            Self::Computed(_, sample) => *sample = 0,
        }
    }

    /// cos ω_c t at the next sample, then on by one sample.
    fn next_value(&mut self) -> f64 {
        match self {
            Self::Tabulated(table, counter) => {
                let value = table[counter.phase];
                counter.advance();
                value
            }
            Self::Computed(omega_per_sample, sample) => {
                let value = (*omega_per_sample * *sample as f64).cos();
                *sample += 1;
                value
            }
        }
    }
}

/// The AC-excited bridge: multiplies the (DC-equivalent) bridge output by the carrier.
#[derive(Clone, Debug, PartialEq)]
pub struct CarrierModulator {
    carrier: CarrierWave,
}

impl CarrierModulator {
    /// A modulator at stream rate `rate_hz`.
    pub fn new(settings: CarrierSettings, rate_hz: f64) -> Result<Self, InstrumentError> {
        check(&settings, rate_hz)?;
        Ok(Self {
            carrier: CarrierWave::new(settings.carrier_hz, rate_hz),
        })
    }
}

impl Block for CarrierModulator {
    fn reset(&mut self) {
        self.carrier.reset();
    }

    fn process(&mut self, input: &[f64], output: &mut [f64]) {
        for (y, &v) in output.iter_mut().zip(input) {
            *y = v * self.carrier.next_value();
        }
    }
}

/// Synchronous demodulation, output low-pass and calibrated gain.
#[derive(Clone, Debug, PartialEq)]
pub struct CarrierDemodulator {
    carrier: CarrierWave,
    gain: f64,
    lowpass: AntiAliasFilter,
}

impl CarrierDemodulator {
    /// A demodulator at stream rate `rate_hz`, in step with a modulator built alike.
    pub fn new(settings: CarrierSettings, rate_hz: f64) -> Result<Self, InstrumentError> {
        check(&settings, rate_hz)?;
        let spec = LowPassSpec {
            kind: FilterKind::Butterworth,
            order: 2,
            cutoff_hz: settings.output_lowpass_hz,
        };
        Ok(Self {
            carrier: CarrierWave::new(settings.carrier_hz, rate_hz),
            gain: settings.gain,
            lowpass: AntiAliasFilter::new(Some(spec), rate_hz)?,
        })
    }

    /// The output low-pass's sections.
    pub fn lowpass_sections(&self) -> &[Biquad] {
        self.lowpass.sections()
    }
}

impl Block for CarrierDemodulator {
    fn reset(&mut self) {
        self.carrier.reset();
        self.lowpass.reset();
    }

    fn process(&mut self, input: &[f64], output: &mut [f64]) {
        for (y, &v) in output.iter_mut().zip(input) {
            let mixed = 2.0 * v * self.carrier.next_value();
            *y = self.gain * self.lowpass.tick(mixed);
        }
    }

    /// From bridge output (before modulation) to amplifier output, for the baseband:
    /// the gain times the output low-pass.
    fn response(&self, freq_hz: f64) -> Option<Complex64> {
        self.lowpass.response(freq_hz).map(|h| h * self.gain)
    }
}
