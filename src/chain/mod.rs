//! The measuring chain as data: each stage a described instrument (output signal, unit,
//! full scale, inputs, how it is built), one table of the rig's standard stages, and the
//! builder that the scenario check, the threaded run and the sweeps' inline chain share.

pub mod analyser_setup;
pub mod chain_stages;
pub mod inline;
pub mod instrument;
pub mod spectrum_metadata;
pub mod stage;
pub mod stage_commands;
pub mod stage_plan;
pub mod standard;
pub mod voltmeters;

pub use chain_stages::{ChainStages, WiringError};
pub use inline::InlineChain;
pub use instrument::Instrument;
pub use stage::Stage;
pub use stage_plan::{NamedStage, StagePlan};
pub use standard::{StandardChain, standard_stages};
pub use voltmeters::{DvmSettings, MeterSettings};
