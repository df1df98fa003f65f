//! What an operator can do to the running rig, as JSON (`{"cmd": "set_speed", "rpm":
//! 1300}`) and as a scenario's `[[command]]` entries, each addressed to one part of it.

use serde::{Deserialize, Serialize};

use crate::vocabulary::choices::{FilterChoice, WindowChoice};
use crate::vocabulary::signal_names::{AMPLIFIER_V, FILTER_V};

/// One command.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(tag = "cmd", rename_all = "snake_case", deny_unknown_fields)]
pub enum RigCommand {
    /// Motor speed set point (rev/min).
    SetSpeed {
        /// rev/min.
        rpm: f64,
    },
    /// Brake load set point (N m).
    SetLoad {
        /// N m.
        nm: f64,
    },
    /// The brake's oscillating load; amplitude 0 switches it off.
    SetOscillatingLoad {
        /// Amplitude (N m).
        nm: f64,
        /// Frequency (Hz).
        hz: f64,
    },
    /// Carrier amplifier gain (output V per V of bridge output).
    SetAmplifierGain {
        /// V/V.
        gain: f64,
    },
    /// Anti-alias filter.
    SetFilter {
        /// none, butterworth or bessel.
        kind: FilterChoice,
        /// Order 1–12.
        #[serde(default = "default_order")]
        order: usize,
        /// Cut-off (Hz), below half the stream rate.
        cutoff_hz: f64,
    },
    /// ADC full scale ±range (V).
    SetAdcRange {
        /// V.
        range_v: f64,
    },
    /// Analyser settings; those left out stay. A change restarts the average.
    SetAnalyser {
        /// Top of the band (Hz).
        #[serde(default)]
        fmax_hz: Option<f64>,
        /// Block size (a power of two).
        #[serde(default)]
        block: Option<usize>,
        /// uniform, hanning or flattop.
        #[serde(default)]
        window: Option<WindowChoice>,
        /// Spectra averaged.
        #[serde(default)]
        averages: Option<usize>,
        /// Overlap of successive blocks (%).
        #[serde(default)]
        overlap_pct: Option<f64>,
    },
    /// Starts a fresh average now (a measurement: its spectrum is written when complete).
    StartAverage,
    /// Holds the average: no more blocks are added until the next start.
    HoldAverage,
    /// Scope settings; those left out stay.
    SetScope {
        /// V per division.
        #[serde(default)]
        volts_per_div: Option<f64>,
        /// s per division.
        #[serde(default)]
        seconds_per_div: Option<f64>,
        /// Trigger level (V).
        #[serde(default)]
        trigger_v: Option<f64>,
        /// auto (sweep on every trigger) or single.
        #[serde(default)]
        mode: Option<ScopeMode>,
    },
    /// Arms the scope for one stored sweep (written as a file when it has triggered).
    ArmScope,
    /// Starts (`on`) or stops the recording.
    Record {
        /// Recording on or off.
        on: bool,
    },
    /// Writes the current spectrum and scope trace (CSV, PNG, SVG) into the output folder.
    SaveDisplays,
    /// Ends the session: every file is closed, manifest and session written.
    Quit,
}

fn default_order() -> usize {
    8
}

/// The live scope's sweep mode.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum ScopeMode {
    /// A new sweep on every trigger.
    Auto,
    /// One sweep, then hold until armed again.
    Single,
}

/// The part of the rig a command is for.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum Target {
    /// The plant's thread (set points, quit).
    Plant,
    /// The chain stage writing this signal.
    Stage(&'static str),
    /// The analyser and its ADC.
    Analyser,
    /// The scope.
    Scope,
    /// The recorder.
    Recorder,
    /// The analyser and the scope together (each saves its display).
    Displays,
}

impl RigCommand {
    /// Who carries it out.
    pub fn target(&self) -> Target {
        match self {
            Self::SetSpeed { .. } | Self::SetLoad { .. } | Self::SetOscillatingLoad { .. } => {
                Target::Plant
            }
            Self::Quit => Target::Plant,
            Self::SetAmplifierGain { .. } => Target::Stage(AMPLIFIER_V),
            Self::SetFilter { .. } => Target::Stage(FILTER_V),
            Self::SetAdcRange { .. }
            | Self::SetAnalyser { .. }
            | Self::StartAverage
            | Self::HoldAverage => Target::Analyser,
            Self::SetScope { .. } | Self::ArmScope => Target::Scope,
            Self::Record { .. } => Target::Recorder,
            Self::SaveDisplays => Target::Displays,
        }
    }
}

/// A command and the virtual time it took effect at: the start of the block it came
/// with, `at_s` = that block's first sample / stream rate.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct TimedCommand {
    /// Virtual time (s).
    pub at_s: f64,
    /// The command.
    #[serde(flatten)]
    pub command: RigCommand,
}

/// The answer to a command.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct Reply {
    /// Whether it was carried out.
    pub ok: bool,
    /// Virtual time it took effect at (s), or when it was refused.
    pub at_s: f64,
    /// Why it was refused (with the allowed range).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub error: Option<String>,
}
