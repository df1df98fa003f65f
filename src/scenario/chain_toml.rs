//! The measuring chain and the analyser as a scenario (or sweep) file writes them:
//! `[chain.*]` and `[analyser]`, with defaults.

use serde::Deserialize;
use toml::Spanned;

use super::values::{Finite, NonNegative, Positive};
use crate::vocabulary::choices::{
    ArrangementChoice, DetectorChoice, FilterChoice, SamplingChoice, SlopeChoice, WindowChoice,
};

/// `[chain]`: the measuring chain. Stages left out take their defaults; slip rings and the
/// scope are wired only when their table is present.
#[derive(Debug, Default, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct ChainFile {
    /// Strain gauges and bridge.
    #[serde(default)]
    pub gauges: GaugesFile,
    /// Carrier amplifier.
    #[serde(default)]
    pub amplifier: AmplifierFile,
    /// Slip rings between the shaft and the amplifier.
    pub slip_rings: Option<SlipRingsFile>,
    /// Anti-alias low-pass before the analyser.
    #[serde(default)]
    pub filter: FilterFile,
    /// The RMS voltmeter on the amplifier output.
    #[serde(default)]
    pub meter: MeterFile,
    /// Tacho and its digital voltmeter.
    #[serde(default)]
    pub tacho: TachoFile,
    /// Storage oscilloscope on the amplifier output.
    pub scope: Option<ScopeFile>,
    /// Further stages (`[[chain.stage]]`), each reading any signal of the run.
    #[serde(default)]
    pub stage: Vec<StageFile>,
}

/// `[[chain.stage]]`: a further instrument in the chain, e.g. a second filter or a meter
/// on another signal. Exactly one of its instrument tables is given.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct StageFile {
    /// Name of the signal it adds (new; recordable, and readable by the analyser, the
    /// scope and other stages).
    pub output: Spanned<String>,
    /// The signal it reads: a plant signal or a stage's output.
    pub input: Spanned<String>,
    /// A low-pass filter, as `[chain.filter]` writes it (without `input`).
    pub lowpass: Option<FilterFile>,
    /// An RMS voltmeter, as `[chain.meter]` writes it (without `input`).
    pub meter: Option<MeterFile>,
    /// A first-order AC coupling (high-pass).
    pub ac_coupling: Option<AcCouplingFile>,
}

/// `ac_coupling = { corner_hz = … }` of a `[[chain.stage]]`.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct AcCouplingFile {
    /// Corner frequency (Hz).
    pub corner_hz: Positive,
}

/// `[chain.gauges]`.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct GaugesFile {
    /// full, half or quarter.
    #[serde(default)]
    pub arrangement: ArrangementChoice,
    /// Nominal gauge factor.
    #[serde(default = "default_gauge_factor")]
    pub gauge_factor: Positive,
    /// Relative error of the actual gauge factor.
    #[serde(default = "default_zero")]
    pub gauge_factor_error: Finite,
    /// Bridge excitation (V).
    #[serde(default = "default_excitation")]
    pub excitation_v: Positive,
}

impl Default for GaugesFile {
    fn default() -> Self {
        Self {
            arrangement: ArrangementChoice::default(),
            gauge_factor: default_gauge_factor(),
            gauge_factor_error: default_zero(),
            excitation_v: default_excitation(),
        }
    }
}

fn default_gauge_factor() -> Positive {
    Positive(2.1)
}

fn default_zero() -> Finite {
    Finite(0.0)
}

fn default_excitation() -> Positive {
    Positive(5.0)
}

/// `[chain.amplifier]`: the carrier amplifier and its calibration.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct AmplifierFile {
    /// Microstrain of the calibration (the thesis: 200 µε ...).
    #[serde(default = "default_cal_microstrain")]
    pub calibration_microstrain: Positive,
    /// ... giving this output (V) (the thesis: 3 V).
    #[serde(default = "default_cal_v")]
    pub calibration_v: Positive,
    /// Carrier frequency (Hz), below a quarter of the stream rate.
    /// Left out: 10 kHz, or a fifth of the stream rate where that is lower.
    pub carrier_hz: Option<Spanned<Positive>>,
    /// Corner of the output low-pass (Hz).
    /// Left out: half the carrier frequency.
    pub output_lowpass_hz: Option<Spanned<Positive>>,
}

impl Default for AmplifierFile {
    fn default() -> Self {
        Self {
            calibration_microstrain: default_cal_microstrain(),
            calibration_v: default_cal_v(),
            carrier_hz: None,
            output_lowpass_hz: None,
        }
    }
}

fn default_cal_microstrain() -> Positive {
    Positive(200.0)
}

fn default_cal_v() -> Positive {
    Positive(3.0)
}

/// `[chain.slip_rings]`.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct SlipRingsFile {
    /// RMS of the broadband relative resistance fluctuation.
    pub broadband_rms: NonNegative,
    /// Once-per-revolution relative fluctuation.
    pub per_rev_amplitude: NonNegative,
    /// Additive contact noise (V rms).
    pub contact_noise_v_rms: NonNegative,
}

/// `[chain.filter]`: the anti-alias low-pass.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct FilterFile {
    /// none, butterworth or bessel.
    #[serde(default)]
    pub kind: FilterChoice,
    /// Order 1–12.
    #[serde(default = "default_filter_order")]
    pub order: Spanned<usize>,
    /// Cut-off (Hz), below the stream's Nyquist frequency. Left out: the analyser's
    /// Fmax (as `testrig analyse` does), or [`DEFAULT_CUTOFF_HZ`] with no analyser.
    #[serde(default)]
    pub cutoff_hz: Option<Spanned<Positive>>,
    /// The signal it filters (left out: `amplifier_v`).
    #[serde(default)]
    pub input: Option<Spanned<String>>,
}

impl Default for FilterFile {
    fn default() -> Self {
        Self {
            kind: FilterChoice::default(),
            order: default_filter_order(),
            cutoff_hz: None,
            input: None,
        }
    }
}

fn default_filter_order() -> Spanned<usize> {
    Spanned::new(0..0, 8)
}

/// Anti-alias cut-off when the scenario gives none and has no analyser (Hz).
pub const DEFAULT_CUTOFF_HZ: f64 = 2_000.0;

/// `[chain.meter]`: the RMS voltmeter.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct MeterFile {
    /// average (the HP 400E, RMS-calibrated for sines) or true-rms.
    #[serde(default)]
    pub detector: DetectorChoice,
    /// Detector time constant (s).
    #[serde(default = "default_meter_tau")]
    pub tau_s: Positive,
    /// Corner (Hz) of the AC coupling (the 400E is an AC meter, specified from 10 Hz); 0
    /// couples DC, so the static strain is read too.
    #[serde(default = "default_coupling")]
    pub ac_coupling_hz: Spanned<NonNegative>,
    /// The signal it reads (left out: `amplifier_v`).
    #[serde(default)]
    pub input: Option<Spanned<String>>,
}

impl Default for MeterFile {
    fn default() -> Self {
        Self {
            detector: DetectorChoice::default(),
            tau_s: default_meter_tau(),
            ac_coupling_hz: default_coupling(),
            input: None,
        }
    }
}

fn default_coupling() -> Spanned<NonNegative> {
    Spanned::new(0..0, NonNegative(1.0))
}

fn default_meter_tau() -> Positive {
    Positive(0.2)
}

/// `[chain.tacho]`: the digital voltmeter reading the tacho.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct TachoFile {
    /// Gate (s).
    #[serde(default = "default_gate")]
    pub gate_s: Spanned<Positive>,
    /// RMS converter time constant (s).
    #[serde(default = "default_dvm_tau")]
    pub tau_s: Positive,
    /// Display resolution (V).
    #[serde(default = "default_resolution")]
    pub resolution_v: Positive,
}

impl Default for TachoFile {
    fn default() -> Self {
        Self {
            gate_s: default_gate(),
            tau_s: default_dvm_tau(),
            resolution_v: default_resolution(),
        }
    }
}

fn default_gate() -> Spanned<Positive> {
    Spanned::new(0..0, Positive(1.0))
}

fn default_dvm_tau() -> Positive {
    Positive(0.3)
}

fn default_resolution() -> Positive {
    Positive(0.1)
}

/// `[chain.scope]`: the storage oscilloscope, one single sweep armed at each measurement.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct ScopeFile {
    /// V per division.
    pub volts_per_div: Positive,
    /// s per division (ten divisions).
    pub seconds_per_div: Spanned<Positive>,
    /// Trigger level (V).
    #[serde(default = "default_zero")]
    pub trigger_v: Finite,
    /// rising or falling.
    #[serde(default)]
    pub slope: SlopeChoice,
    /// Corner (Hz) of the AC input coupling (a Tektronix AC input: about 1.6 Hz); 0 for DC.
    #[serde(default = "default_scope_coupling")]
    pub ac_coupling_hz: Spanned<NonNegative>,
    /// The signal it shows (left out: `amplifier_v`).
    #[serde(default)]
    pub input: Option<Spanned<String>>,
}

fn default_scope_coupling() -> Spanned<NonNegative> {
    Spanned::new(0..0, NonNegative(1.6))
}

/// `[analyser]`: the HP 5451C with its ADC, started at each measurement.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct AnalyserFile {
    /// Block size N (a power of two).
    #[serde(default = "default_analyser_block")]
    pub block: Spanned<usize>,
    /// Top of the band (Hz).
    pub fmax_hz: Spanned<Positive>,
    /// thesis (fs = 2 Fmax, N/2 lines) or 2.56 (as text or as a number).
    #[serde(default)]
    pub sampling: SamplingChoice,
    /// uniform, hanning or flattop.
    #[serde(default)]
    pub window: WindowChoice,
    /// Spectra averaged (linear: sum, then divide).
    #[serde(default = "default_averages")]
    pub averages: Spanned<usize>,
    /// Overlap of successive blocks (%).
    #[serde(default)]
    pub overlap_pct: Option<Spanned<NonNegative>>,
    /// ADC resolution (bits).
    #[serde(default = "default_bits")]
    pub bits: Spanned<u32>,
    /// ADC full scale ±range (V).
    #[serde(default = "default_range")]
    pub range_v: Positive,
    /// Triangular dither of ±1 LSB.
    #[serde(default)]
    pub dither: bool,
    /// The signal its ADC samples (left out: `filter_v`).
    #[serde(default)]
    pub input: Option<Spanned<String>>,
}

fn default_analyser_block() -> Spanned<usize> {
    Spanned::new(0..0, 1024)
}

fn default_averages() -> Spanned<usize> {
    Spanned::new(0..0, 10)
}

fn default_bits() -> Spanned<u32> {
    Spanned::new(0..0, 12)
}

fn default_range() -> Positive {
    Positive(5.0)
}
