//! The scenario file as written (TOML): every table and key, with defaults. Unknown keys
//! are rejected. `scenarios/README.md` shows each in use.

use std::collections::BTreeMap;

use serde::Deserialize;
use toml::Spanned;

pub use super::chain_toml::{AnalyserFile, ChainFile};
use super::values::{LoadNm, NonNegative, Positive, SpeedRpm};
use crate::vocabulary::TimedCommand;
use crate::vocabulary::choices::{RecordFormatChoice, WavFormatChoice};

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
    /// The plant built for live commands (as `testrig panel` builds it).
    pub live: Option<LiveFile>,
    /// Commands at their virtual times, as an operator gave them (a panel's session).
    #[serde(default)]
    pub command: Vec<TimedCommand>,
}

/// `[live]`: the highest set points live commands may bring; the plant's internal step
/// and states are made for them.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct LiveFile {
    /// Highest speed set point (rev/min).
    pub max_speed_rpm: SpeedRpm,
    /// Highest oscillating-load frequency (Hz).
    pub max_oscillating_load_hz: NonNegative,
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
    /// Any parameter by name, as `testrig params` lists them (for a rig file, by path,
    /// as `testrig params --rig` lists them).
    #[serde(default)]
    pub set: BTreeMap<String, Spanned<toml::Value>>,
    /// A rig file (`rigs/basmaji-1983.toml`), relative to this file, instead of a preset.
    pub file: Option<Spanned<String>>,
    /// `[[rig.fault]]`: tooth faults seeded on the rig file's meshes, each naming its mesh.
    #[serde(default)]
    pub fault: Vec<crate::scenario::rig_file_toml::FaultToml>,
}

/// `[schedule]`: the knobs at the start and their changes.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct ScheduleFile {
    /// Motor speed set point at the start (rev/min).
    pub speed_rpm: SpeedRpm,
    /// Brake load at the start (N m), ≥ 0.
    pub load_nm: LoadNm,
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
    /// New brake load (N m), ≥ 0.
    pub load_nm: Option<LoadNm>,
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
    pub loads_nm: Vec<LoadNm>,
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

/// `[record]`: signals streamed to disk for the whole run.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct RecordFile {
    /// Signal names (`testrig run --list-signals`, or scenarios/README.md).
    pub signals: Vec<Spanned<String>>,
    /// Any of wav, csv, uff58 (wav, with its JSON sidecar, when left out).
    #[serde(default = "default_formats")]
    pub formats: Vec<RecordFormatChoice>,
    /// WAV sample format: float32 or int24.
    #[serde(default)]
    pub wav_format: WavFormatChoice,
    /// Keep every M-th sample (no filtering: what is above the new Nyquist aliases).
    #[serde(default = "default_decimate")]
    pub decimate: Spanned<usize>,
    /// Record from the start (false: only once a `record` command starts it).
    #[serde(default = "default_true")]
    pub from_start: bool,
    /// Full scale of a signal in its unit for int24 WAV (defaults by unit).
    #[serde(default)]
    pub full_scale: BTreeMap<String, Spanned<Positive>>,
}

fn default_formats() -> Vec<RecordFormatChoice> {
    vec![RecordFormatChoice::Wav]
}

fn default_decimate() -> Spanned<usize> {
    Spanned::new(0..0, 1)
}

fn default_true() -> bool {
    true
}
