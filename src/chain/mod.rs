//! The measuring chain as data: each stage a described instrument (output signal, unit,
//! full scale, inputs, how it is built), one table of the rig's standard stages, and the
//! builder that the scenario check, the threaded run and the sweeps' inline chain share.
//!
//! Files: the measuring chain as data: `instrument.rs` every kind of stage with its
//! settings (unit, full scale, inputs, how it is built); `microstrain.rs` the strain signal
//! in µε (the gauged shaft's stage writes it, the bridge reads it); `analysed.rs` a sampled
//! signal through filter, ADC and analyser with its alias truth (`analyse` and Python's
//! `testrig.analyse`); `stage_plan.rs` a described stage (`StagePlan`) and a built one
//! (`NamedStage`); `chain_stages.rs` the list in running order (unknown, duplicate or
//! looping names refused) and built; `standard.rs` the rig's standard chain as one table;
//! `stage.rs` a stage at work on frames; `stage_commands.rs` filter and gain changes on a
//! stage; `inline.rs` the stages driven in turn on one thread (sweep cases, `analyse`);
//! `analyser_setup.rs` the analyser's one way in (settings + ADC + stream rate → built
//! analyser, ADC and alias truth, or an `AnalyserSetupError` naming the setting), used by
//! the scenario reader, the panel and `analyse`; `spectrum_metadata.rs` a written
//! spectrum's `# key: value` lines; `voltmeters.rs` the meter's and DVM's settings;
//! `measurement.rs` one measurement: an analogue stream through the ADC into the analyser,
//! with its alias truth (`Measurement`, the one driver of ADC → analyser);
//! `analyser_setup.rs` also holds `AnalyserWords`, the analyser in a user's words checked
//! in one place; `low_pass_words.rs` the anti-alias filter in a user's words
//! (`LowPassWords`: the cut-off follows the band where left out, checked against Nyquist);
//! `phasor.rs` a rotating phasor for single-frequency DFTs.

pub(crate) mod analysed;
pub(crate) mod analyser_setup;
pub(crate) mod chain_stages;
pub(crate) mod gear_condition;
pub(crate) mod inline;
pub(crate) mod instrument;
pub(crate) mod low_pass_words;
pub(crate) mod measurement;
pub(crate) mod microstrain;
mod phasor;
mod planetary_lines;
pub(crate) mod spectrum_metadata;
pub(crate) mod stage;
pub(crate) mod stage_commands;
pub(crate) mod stage_plan;
pub(crate) mod standard;
pub(crate) mod voltmeters;
mod watched_gear;

pub use analysed::{analyse_analogue, anti_aliased};
pub use analyser_setup::{AdcChoice, AnalyserSetting, AnalyserSetup, AnalyserWords};
pub use chain_stages::{ChainStages, WiringError};
pub(crate) use gear_condition::whole_turns;
pub use gear_condition::{GearCondition, GearConditionReport};
pub use inline::InlineChain;
pub use instrument::Instrument;
pub use low_pass_words::{LowPassError, LowPassWords};
pub use measurement::{AnalysedSpectrum, Measurement, Truth};
pub use microstrain::{MICROSTRAIN_PER_STRAIN, MicrostrainBridge, ShaftMicrostrain};
pub use planetary_lines::{StageLines, stage_lines};
pub use spectrum_metadata::{SpectrumFacts, spectrum_metadata};
pub use stage::Stage;
pub use stage_plan::{NamedStage, StagePlan};
pub use standard::{StandardChain, standard_stages};
pub use voltmeters::{DvmSettings, MeterSettings};
pub use watched_gear::{sensed_stage, watched_gear};
