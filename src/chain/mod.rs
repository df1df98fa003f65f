//! The measuring chain as data: each stage a described instrument (output signal, unit,
//! full scale, inputs, how it is built), one table of the rig's standard stages, and the
//! builder that the scenario check, the threaded run and the sweeps' inline chain share.

pub(crate) mod analysed;
pub(crate) mod analyser_setup;
pub(crate) mod chain_stages;
pub(crate) mod inline;
pub(crate) mod instrument;
pub(crate) mod low_pass_words;
pub(crate) mod measurement;
pub(crate) mod microstrain;
pub(crate) mod spectrum_metadata;
pub(crate) mod stage;
pub(crate) mod stage_commands;
pub(crate) mod stage_plan;
pub(crate) mod standard;
pub(crate) mod voltmeters;

pub use analysed::{analyse_analogue, anti_aliased};
pub use analyser_setup::{AdcChoice, AnalyserSetting, AnalyserSetup, AnalyserWords};
pub use chain_stages::{ChainStages, WiringError};
pub use inline::InlineChain;
pub use instrument::Instrument;
pub use low_pass_words::{LowPassError, LowPassWords};
pub use measurement::{AnalysedSpectrum, Measurement, Truth};
pub use microstrain::{MICROSTRAIN_PER_STRAIN, MicrostrainBridge, ShaftMicrostrain};
pub use spectrum_metadata::{SpectrumFacts, spectrum_metadata};
pub use stage::Stage;
pub use stage_plan::{NamedStage, StagePlan};
pub use standard::{StandardChain, standard_stages};
pub use voltmeters::{DvmSettings, MeterSettings};
