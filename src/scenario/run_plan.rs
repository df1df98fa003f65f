//! A scenario checked and turned into settings the runtime uses directly.

use crate::vocabulary::choices::WavFormat;
use instruments::{AdcSettings, AnalyserSettings, ScopeSettings, ShaftStrain};
use rig::Schedule;

pub use super::plan_rig::PlanRig;

use super::scenario_toml::Overflow;
use crate::chain::{ChainStages, Instrument, MICROSTRAIN_PER_STRAIN};
use crate::vocabulary::signal_names::{AMPLIFIER_V, FILTER_V, STRAIN};

/// Everything a run needs, checked.
#[derive(Clone, Debug)]
pub struct Plan {
    /// Scenario name.
    pub name: String,
    /// What it rehearses.
    pub description: String,
    /// The scenario text the run used (after `--set` edits).
    pub text: String,
    /// Base seed.
    pub seed: u64,
    /// Simulated length (s).
    pub duration_s: f64,
    /// Stream rate (Hz).
    pub rate_hz: f64,
    /// Samples per block.
    pub block_samples: usize,
    /// Overflow policy at the plant's output.
    pub overflow: Overflow,
    /// Queue length (blocks).
    pub queue_blocks: usize,
    /// The rig: a preset's parameters or a rig file's rig.
    pub rig: PlanRig,
    /// Knobs over time.
    pub schedule: Schedule,
    /// Readings of the rack, in time order.
    pub measures: Vec<Measure>,
    /// Whether the measurements come from a `[survey]` grid.
    pub is_survey: bool,
    /// The measuring chain.
    pub chain: ChainPlan,
    /// The analyser, if wired.
    pub analyser: Option<AnalyserPlan>,
    /// Recordings, if any.
    pub record: Option<RecordPlan>,
    /// The ceiling of live set points the plant is built for (`None`: the schedule's).
    pub live_ceiling: Option<rig::LiveCeiling>,
    /// Commands at their virtual times.
    pub commands: Vec<crate::vocabulary::TimedCommand>,
}

/// One reading of the rack.
#[derive(Clone, Debug, PartialEq)]
pub struct Measure {
    /// When (s).
    pub at_s: f64,
    /// What it is of.
    pub label: String,
    /// Speed set point then (rev/min).
    pub speed_rpm: f64,
    /// Load set point then (N m).
    pub load_nm: f64,
}

/// The chain's stages and its calibration.
#[derive(Clone, Debug)]
pub struct ChainPlan {
    /// Every stage in running order: the standard ones and the scenario's own.
    pub stages: ChainStages,
    /// Surface strain per N m of intermediate-shaft torque (the gauged shaft).
    pub strain_per_nm: f64,
    /// Amplifier output (V) per N m of intermediate-shaft torque, static.
    pub volts_per_nm: f64,
    /// Scope, if wired.
    pub scope: Option<ScopePlan>,
}

impl ChainPlan {
    /// Whether a stage or the scope reads signal `name`.
    pub fn reads(&self, name: &str) -> bool {
        let stages = self.stages.stages();
        stages.iter().any(|s| s.inputs.iter().any(|i| i == name))
            || self.scope.as_ref().is_some_and(|s| s.input == name)
    }

    /// This chain with its strain stage and static calibration on `shaft` (a rig file's
    /// gauged shaft): the amplifier's volts per N m scale with the strain per N m.
    pub fn on_gauged_shaft(&self, shaft: ShaftStrain) -> Self {
        let strain_per_nm = shaft.strain_per_nm();
        Self {
            stages: self.stages.with_gauged_shaft(shaft),
            strain_per_nm,
            volts_per_nm: self.volts_per_nm * strain_per_nm / self.strain_per_nm,
            scope: self.scope.clone(),
        }
    }

    /// Strain (µε) per unit of signal `name`, where the signal is the gauged shaft's strain
    /// or a static calibration holds it: the amplifier's output, and the anti-alias
    /// filter's output when the filter (unity gain in its pass band) reads the amplifier.
    /// `None` for every other signal.
    pub fn microstrain_per_unit(&self, name: &str) -> Option<f64> {
        let per_volt = self.strain_per_nm * MICROSTRAIN_PER_STRAIN / self.volts_per_nm;
        let filters_amplifier = || {
            self.stages.producing(FILTER_V).is_some_and(|s| {
                matches!(s.instrument, Instrument::LowPass(_)) && s.inputs == [AMPLIFIER_V]
            })
        };
        match name {
            STRAIN => Some(1.0),
            AMPLIFIER_V => Some(per_volt),
            FILTER_V if filters_amplifier() => Some(per_volt),
            _ => None,
        }
        .filter(|k| k.is_finite())
    }
}

/// The storage oscilloscope.
#[derive(Clone, Debug)]
pub struct ScopePlan {
    /// Its settings.
    pub settings: ScopeSettings,
    /// Corner of its AC input coupling (Hz; 0 for DC).
    pub ac_coupling_hz: f64,
    /// The signal it shows.
    pub input: String,
}

/// The analyser and its ADC.
#[derive(Clone, Debug)]
pub struct AnalyserPlan {
    /// The signal its ADC samples.
    pub input: String,
    /// Analyser settings.
    pub settings: AnalyserSettings,
    /// ADC settings (ratio from the stream rate).
    pub adc: AdcSettings,
}

/// What to record.
#[derive(Clone, Debug)]
pub struct RecordPlan {
    /// Signal names, in channel order.
    pub signals: Vec<String>,
    /// Full scale of each signal (unit of the signal).
    pub full_scale: Vec<f64>,
    /// Write a WAV file in this format.
    pub wav: Option<WavFormat>,
    /// Write a CSV file.
    pub csv: bool,
    /// Write UFF58 time histories (and spectra).
    pub uff58: bool,
    /// Keep every M-th sample.
    pub decimate: usize,
    /// Record from the start (false: only once a `record` command starts it).
    pub from_start: bool,
}

impl RecordPlan {
    /// Whether signal `name` is recorded.
    pub fn records(&self, name: &str) -> bool {
        self.signals.iter().any(|s| s == name)
    }
}

impl Plan {
    /// Whether the run reads signal `name`: a stage's input, the analyser's or the
    /// scope's, or a recorded signal.
    pub fn reads(&self, name: &str) -> bool {
        self.chain.reads(name)
            || self.analyser.as_ref().is_some_and(|a| a.input == name)
            || self.record.as_ref().is_some_and(|r| r.records(name))
    }

    /// The rig's own columns the run reads (of [`crate::rig_roles::rig_columns`]): the
    /// only ones its frames carry, so that a run pays for no column it does not use.
    pub fn rig_columns_read(&self) -> Vec<usize> {
        crate::rig_roles::rig_columns_read(&self.rig.topology, |name| self.reads(name))
    }

    /// The measurements the analyser and the scope work to: the scenario's, or one at
    /// the start when it lists none.
    pub fn measurements(&self) -> Vec<Measure> {
        if !self.measures.is_empty() {
            return self.measures.clone();
        }
        vec![Measure {
            at_s: 0.0,
            label: "from the start".into(),
            speed_rpm: self.schedule.speed_rpm.value_at(0.0),
            load_nm: self.schedule.load_nm.value_at(0.0),
        }]
    }
}
