//! What the front panel shows, as the sinks last left it: the analyser's display with
//! its alias truth, and the scope's latest trace. Serialised into the API's `state`.

use serde::Serialize;

/// The analyser's display now.
#[derive(Clone, Debug, Default, PartialEq, Serialize)]
pub struct LiveSpectrum {
    /// Frequency of each line (Hz).
    pub frequency_hz: Vec<f64>,
    /// Power of each line (`unit`² rms: V² through the chain), at least the floor.
    pub power_v2: Vec<f64>,
    /// The chain's noise floor per line (`unit`² rms): the ADC's quantisation noise through
    /// the window; lines below it are shown at it.
    pub floor_v2: f64,
    /// For each line, the true frequency (Hz) of the component aliased onto it, if any.
    pub alias_of_hz: Vec<Option<f64>>,
    /// Averages taken.
    pub averages: usize,
    /// Averages asked for.
    pub averages_set: usize,
    /// Whether the average is complete (or held).
    pub complete: bool,
    /// Running speed of the motor shaft when the average started (Hz), for order marks.
    pub running_hz: f64,
    /// The analysed signal.
    pub signal: String,
    /// The analysed signal's unit (`V` through the chain; `N` for a force sensor read
    /// directly): `power_v2`, `floor_v2` and `adc_range_v` are in it (squared for the
    /// powers), their names kept for the API's readers.
    pub unit: String,
    /// Window name.
    pub window: String,
    /// Top of the band (Hz).
    pub fmax_hz: f64,
    /// Block size N in effect.
    pub block: usize,
    /// Overlap of successive blocks in effect (%).
    pub overlap_pct: f64,
    /// The ADC's ± range in effect (in `unit`).
    pub adc_range_v: f64,
}

/// The scope's latest trace.
#[derive(Clone, Debug, Default, PartialEq, Serialize)]
pub struct LiveTrace {
    /// Time from the trigger of each point (s).
    pub time_s: Vec<f64>,
    /// Vertical position of each point (divisions, ±4 on screen).
    pub divisions: Vec<f64>,
    /// `unit` per division.
    pub volts_per_div: f64,
    /// s per division.
    pub seconds_per_div: f64,
    /// Trigger level (in `unit`).
    pub trigger_v: f64,
    /// `auto` or `single`.
    pub mode: String,
    /// The signal shown.
    pub signal: String,
    /// The shown signal's unit: `volts_per_div` and `trigger_v` are in it.
    pub unit: String,
}

/// The chain's settings in effect, as the panel echoes them: what was applied, so that a
/// refused or clamped setting shows.
#[derive(Clone, Debug, Default, PartialEq, Serialize)]
pub struct AppliedChain {
    /// The carrier amplifier's gain (V/V), if the chain has one.
    pub amplifier_gain: Option<f64>,
    /// The anti-alias filter, if the chain has one.
    pub filter: Option<AppliedFilter>,
}

/// The anti-alias filter in effect.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct AppliedFilter {
    /// `none`, `butterworth` or `bessel`.
    pub kind: String,
    /// Its order (0 without a filter).
    pub order: usize,
    /// Its cut-off (Hz; 0 without a filter).
    pub cutoff_hz: f64,
}
