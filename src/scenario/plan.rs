//! A scenario checked and turned into settings the runtime uses directly.

use instruments::{
    AdcSettings, AnalyserSettings, CarrierSettings, Detector, DigitalVoltmeter, InstrumentError,
    LowPassSpec, ScopeSettings, ShaftStrain, SlipRingSettings, StrainBridge, Voltmeter,
};
use rig::{RigParams, Schedule};

use super::file::Overflow;

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
    /// Preset name.
    pub preset: String,
    /// Rig parameters after overrides.
    pub params: RigParams,
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

/// The chain's settings.
#[derive(Clone, Debug)]
pub struct ChainPlan {
    /// Shaft under the gauges.
    pub shaft: ShaftStrain,
    /// Gauges and bridge.
    pub bridge: StrainBridge,
    /// Carrier amplifier.
    pub carrier: CarrierSettings,
    /// Slip rings, if wired.
    pub slip_rings: Option<SlipRingSettings>,
    /// Anti-alias filter (`None`: bypassed).
    pub filter: Option<LowPassSpec>,
    /// RMS meter detector, time constant (s) and AC-coupling corner (Hz; 0 for DC).
    pub meter: MeterSettings,
    /// Tacho DVM gate (s), time constant (s), resolution (V).
    pub dvm: DvmSettings,
    /// Scope, if wired, and its AC-coupling corner (Hz; 0 for DC).
    pub scope: Option<(ScopeSettings, f64)>,
}

impl ChainPlan {
    /// Amplifier output (V) per N m of intermediate-shaft torque, static.
    pub fn volts_per_nm(&self) -> f64 {
        self.shaft.strain_per_nm() * self.bridge.output_v(1.0) * self.carrier.gain
    }
}

/// The analyser and its ADC.
#[derive(Clone, Copy, Debug)]
pub struct AnalyserPlan {
    /// Analyser settings.
    pub settings: AnalyserSettings,
    /// ADC settings (ratio from the stream rate).
    pub adc: AdcSettings,
}

/// How WAV samples are stored.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum WavFormat {
    /// 32-bit IEEE float, sample = value / scale.
    Float32,
    /// 24-bit integer, full scale = scale.
    Int24,
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
}

impl Plan {
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

/// The RMS voltmeter on the amplifier output (the HP 400E or a true-RMS meter).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct MeterSettings {
    /// Average-responding (400E) or true RMS.
    pub detector: Detector,
    /// Detector time constant (s).
    pub tau_s: f64,
    /// Corner of the AC coupling (Hz); 0 couples DC.
    pub ac_coupling_hz: f64,
}

impl MeterSettings {
    /// The meter on a stream at `rate_hz`.
    pub fn build(&self, rate_hz: f64) -> Result<Voltmeter, InstrumentError> {
        let meter = Voltmeter::new(self.detector, rate_hz, self.tau_s)?;
        if self.ac_coupling_hz > 0.0 {
            meter.ac_coupled(self.ac_coupling_hz, rate_hz)
        } else {
            Ok(meter)
        }
    }
}

/// The digital voltmeter reading the tacho.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct DvmSettings {
    /// Gate time (s).
    pub gate_s: f64,
    /// RMS converter time constant (s).
    pub tau_s: f64,
    /// Display resolution (V).
    pub resolution_v: f64,
}

impl DvmSettings {
    /// The DVM on a stream at `rate_hz`.
    pub fn build(&self, rate_hz: f64) -> Result<DigitalVoltmeter, InstrumentError> {
        DigitalVoltmeter::new(rate_hz, self.gate_s, self.tau_s, self.resolution_v)
    }
}
