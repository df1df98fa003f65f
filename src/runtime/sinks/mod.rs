//! The ends of the chain: each consumes every frame in its own thread and writes files.

pub(crate) mod analyser;
pub(crate) mod analyser_live;
pub(crate) mod measure_clock;
pub(crate) mod monitor;
pub(crate) mod recorder;
pub(crate) mod scope;
pub(crate) mod scope_live;
pub(crate) mod tap;

use std::path::PathBuf;

use crate::vocabulary::Refusal;
use crate::vocabulary::RigCommand;
use crate::vocabulary::frame::Frame;

/// A consumer of frames.
pub trait Sink: Send {
    /// Takes one frame.
    fn consume(&mut self, frame: &Frame) -> anyhow::Result<()>;
    /// Closes the sink's files (everything consumed is kept) and reports.
    fn finish(self: Box<Self>) -> anyhow::Result<SinkReport>;
    /// Carries out `command` (taking effect at `frame`'s start, before its samples) if it
    /// is this sink's: `Some(outcome)`, else `None`.
    fn command(&mut self, _command: &RigCommand, _frame: &Frame) -> Option<Result<(), Refusal>> {
        None
    }
}

/// What a sink leaves behind.
#[derive(Debug, Default)]
pub struct SinkReport {
    /// Files written.
    pub files: Vec<PathBuf>,
    /// Facts for the manifest, by key.
    pub facts: Vec<(&'static str, serde_json::Value)>,
    /// What the sink could not do (a spectrum short of its averages, a measurement never
    /// reached), for the console and the manifest's `warnings`.
    pub warnings: Vec<String>,
}
