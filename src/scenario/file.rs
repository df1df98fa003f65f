//! The scenario file as written (TOML): every table and key, with defaults. Unknown keys
//! are rejected. `scenarios/README.md` shows each in use.

use std::collections::BTreeMap;

use serde::Deserialize;
use toml::Spanned;

use super::values::{Finite, NonNegative, Positive, SpeedRpm};

/// The whole file.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct ScenarioFile {
    /// Short name, used in titles and file metadata.
    pub name: String,
    /// What the scenario rehearses.
    #[serde(default)]
    pub description: String,
    /// Base seed of every random source (slip-ring noise, ADC dither); `--seed` overrides.
    #[serde(default)]
    pub seed: u64,
    /// Simulated run length (s); with a survey, the survey's own length when left out.
    pub duration_s: Option<Spanned<Positive>>,
    /// Rate of the true signals and of the analogue chain (Hz).
    #[serde(default = "default_rate")]
    pub rate_hz: Spanned<Positive>,
    /// Samples per block passed between threads.
    #[serde(default = "default_block")]
    pub block_samples: Spanned<usize>,
    /// What happens when a consumer falls behind the paced plant.
    #[serde(default)]
    pub overflow: Overflow,
    /// Blocks a channel holds before the plant waits (lossless) or drops (drop).
    #[serde(default = "default_queue")]
    pub queue_blocks: Spanned<usize>,
    /// The rig: preset and overrides.
    #[serde(default)]
    pub rig: RigFile,
    /// Speed and load over time (leave out with a survey).
    pub schedule: Option<Spanned<ScheduleFile>>,
    /// A grid of test points, each set, settled and measured in turn.
    pub survey: Option<Spanned<SurveyFile>>,
    /// Instants at which the experimenter reads the meters, starts the analyser and arms
    /// the scope.
    #[serde(default)]
    pub measure: Vec<Spanned<MeasureFile>>,
    /// The measuring chain as wired.
    #[serde(default)]
    pub chain: ChainFile,
    /// The Fourier analyser (left out: no spectra).
    pub analyser: Option<AnalyserFile>,
    /// What to record (left out: nothing but the manifest, readings and impacts).
    pub record: Option<RecordFile>,
}

fn default_rate() -> Spanned<Positive> {
    Spanned::new(0..0, Positive(51_200.0))
}

fn default_block() -> Spanned<usize> {
    Spanned::new(0..0, 1024)
}

fn default_queue() -> Spanned<usize> {
    Spanned::new(0..0, 16)
}

/// Consumer overflow policy.
#[derive(Clone, Copy, Debug, Default, Deserialize, PartialEq, Eq)]
#[serde(rename_all = "kebab-case")]
pub enum Overflow {
    /// The plant waits for the slowest consumer: nothing is lost (the default).
    #[default]
    Lossless,
    /// As a data-acquisition card: a block that finds the queue full is dropped, counted
    /// and reported with its time.
    Drop,
}

/// `[rig]`.
#[derive(Debug, Default, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct RigFile {
    /// Named parameter set (`testrig params` shows one).
    pub preset: Option<Spanned<String>>,
    /// Total circular backlash at the pitch circle (mm), set through the centre distance.
    pub backlash_mm: Option<Spanned<Positive>>,
    /// Any parameter by name, as `testrig params` lists them.
    #[serde(default)]
    pub set: BTreeMap<String, Spanned<toml::Value>>,
}

/// `[schedule]`: the knobs at the start and their changes.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct ScheduleFile {
    /// Motor speed set point at the start (rev/min).
    pub speed_rpm: SpeedRpm,
    /// Brake load at the start (N m); negative drives from the brake side.
    pub load_nm: Finite,
    /// Changes in time order.
    #[serde(default)]
    pub change: Vec<Spanned<ChangeFile>>,
    /// The function generator on the brake coil (oscillating load).
    pub function_generator: Option<FunctionGeneratorFile>,
}

/// `[[schedule.change]]`: at a time, turn a knob to a new value, at once or over a ramp.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct ChangeFile {
    /// When the change starts (s).
    pub at_s: NonNegative,
    /// Ramp time (s); 0 or left out for a step.
    #[serde(default)]
    pub ramp_s: Option<NonNegative>,
    /// New speed set point (rev/min).
    pub speed_rpm: Option<SpeedRpm>,
    /// New brake load (N m).
    pub load_nm: Option<Finite>,
}

/// `[schedule.function_generator]`: an AC current added to the brake's DC coil current.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct FunctionGeneratorFile {
    /// AC amplitude of the coil current (A).
    pub amplitude_a: NonNegative,
    /// Frequency (Hz); the thesis found the brake usable around 15 Hz.
    pub frequency_hz: NonNegative,
    /// Brake torque per ampere about the operating point (N m/A).
    #[serde(default = "default_torque_per_amp")]
    pub torque_per_amp: Positive,
    /// Coil time constant L/R (s).
    #[serde(default = "default_coil_tau")]
    pub coil_time_constant_s: Positive,
}

fn default_torque_per_amp() -> Positive {
    Positive(5.0)
}

fn default_coil_tau() -> Positive {
    Positive(0.01)
}

/// `[survey]`: every speed with every load, in turn.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct SurveyFile {
    /// Speeds (rev/min), outer loop.
    pub speeds_rpm: Vec<SpeedRpm>,
    /// Loads (N m), inner loop.
    pub loads_nm: Vec<Finite>,
    /// Time from setting a point to reading it (s).
    pub settle_s: Positive,
    /// Time the point is then held while the instruments measure (s).
    pub measure_s: Positive,
}

/// `[[measure]]`: one reading of the rack.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct MeasureFile {
    /// When (s).
    pub at_s: NonNegative,
    /// What the reading is of.
    #[serde(default)]
    pub label: String,
}

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
}

/// `[chain.gauges]`.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct GaugesFile {
    /// full, half or quarter.
    #[serde(default = "default_arrangement")]
    pub arrangement: Spanned<String>,
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
            arrangement: default_arrangement(),
            gauge_factor: default_gauge_factor(),
            gauge_factor_error: default_zero(),
            excitation_v: default_excitation(),
        }
    }
}

fn default_arrangement() -> Spanned<String> {
    Spanned::new(0..0, "full".into())
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
    #[serde(default = "default_carrier")]
    pub carrier_hz: Spanned<Positive>,
    /// Corner of the output low-pass (Hz).
    #[serde(default = "default_output_lowpass")]
    pub output_lowpass_hz: Spanned<Positive>,
}

impl Default for AmplifierFile {
    fn default() -> Self {
        Self {
            calibration_microstrain: default_cal_microstrain(),
            calibration_v: default_cal_v(),
            carrier_hz: default_carrier(),
            output_lowpass_hz: default_output_lowpass(),
        }
    }
}

fn default_cal_microstrain() -> Positive {
    Positive(200.0)
}

fn default_cal_v() -> Positive {
    Positive(3.0)
}

fn default_carrier() -> Spanned<Positive> {
    Spanned::new(0..0, Positive(10_000.0))
}

fn default_output_lowpass() -> Spanned<Positive> {
    Spanned::new(0..0, Positive(5_000.0))
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
    #[serde(default = "default_filter_kind")]
    pub kind: Spanned<String>,
    /// Order 1–12.
    #[serde(default = "default_filter_order")]
    pub order: Spanned<usize>,
    /// Cut-off (Hz), below the stream's Nyquist frequency.
    #[serde(default = "default_filter_cutoff")]
    pub cutoff_hz: Spanned<Positive>,
}

impl Default for FilterFile {
    fn default() -> Self {
        Self {
            kind: default_filter_kind(),
            order: default_filter_order(),
            cutoff_hz: default_filter_cutoff(),
        }
    }
}

fn default_filter_kind() -> Spanned<String> {
    Spanned::new(0..0, "butterworth".into())
}

fn default_filter_order() -> Spanned<usize> {
    Spanned::new(0..0, 8)
}

fn default_filter_cutoff() -> Spanned<Positive> {
    Spanned::new(0..0, Positive(2_000.0))
}

/// `[chain.meter]`: the RMS voltmeter.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct MeterFile {
    /// average (the HP 400E, RMS-calibrated for sines) or true-rms.
    #[serde(default = "default_detector")]
    pub detector: Spanned<String>,
    /// Detector time constant (s).
    #[serde(default = "default_meter_tau")]
    pub tau_s: Positive,
    /// Corner (Hz) of the AC coupling (the 400E is an AC meter, specified from 10 Hz); 0
    /// couples DC, so the static strain is read too.
    #[serde(default = "default_coupling")]
    pub ac_coupling_hz: Spanned<NonNegative>,
}

impl Default for MeterFile {
    fn default() -> Self {
        Self {
            detector: default_detector(),
            tau_s: default_meter_tau(),
            ac_coupling_hz: default_coupling(),
        }
    }
}

fn default_coupling() -> Spanned<NonNegative> {
    Spanned::new(0..0, NonNegative(1.0))
}

fn default_detector() -> Spanned<String> {
    Spanned::new(0..0, "average".into())
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
    pub gate_s: Positive,
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

fn default_gate() -> Positive {
    Positive(1.0)
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
    pub seconds_per_div: Positive,
    /// Trigger level (V).
    #[serde(default = "default_zero")]
    pub trigger_v: Finite,
    /// rising or falling.
    #[serde(default = "default_slope")]
    pub slope: Spanned<String>,
    /// Corner (Hz) of the AC input coupling (a Tektronix AC input: about 1.6 Hz); 0 for DC.
    #[serde(default = "default_scope_coupling")]
    pub ac_coupling_hz: Spanned<NonNegative>,
}

fn default_scope_coupling() -> Spanned<NonNegative> {
    Spanned::new(0..0, NonNegative(1.6))
}

fn default_slope() -> Spanned<String> {
    Spanned::new(0..0, "rising".into())
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
    /// thesis (fs = 2 Fmax, N/2 lines) or 2.56.
    #[serde(default = "default_sampling")]
    pub sampling: Spanned<String>,
    /// uniform, hanning or flattop.
    #[serde(default = "default_window")]
    pub window: Spanned<String>,
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
}

fn default_analyser_block() -> Spanned<usize> {
    Spanned::new(0..0, 1024)
}

fn default_sampling() -> Spanned<String> {
    Spanned::new(0..0, "thesis".into())
}

fn default_window() -> Spanned<String> {
    Spanned::new(0..0, "hanning".into())
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

/// `[record]`: signals streamed to disk for the whole run.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct RecordFile {
    /// Signal names (`testrig run --list-signals`, or scenarios/README.md).
    pub signals: Vec<Spanned<String>>,
    /// Any of wav, csv, uff58.
    pub formats: Vec<Spanned<String>>,
    /// WAV sample format: float32 or int24.
    #[serde(default = "default_wav_format")]
    pub wav_format: Spanned<String>,
    /// Keep every M-th sample (no filtering: what is above the new Nyquist aliases).
    #[serde(default = "default_decimate")]
    pub decimate: Spanned<usize>,
    /// Full scale of a signal in its unit for int24 WAV (defaults by unit).
    #[serde(default)]
    pub full_scale: BTreeMap<String, Spanned<Positive>>,
}

fn default_wav_format() -> Spanned<String> {
    Spanned::new(0..0, "float32".into())
}

fn default_decimate() -> Spanned<usize> {
    Spanned::new(0..0, 1)
}
