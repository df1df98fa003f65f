//! Why the rig refuses a command: typed at its source (a limit, an instrument's settings,
//! a command sent to a part that does not take it, work behind the command that failed),
//! turned into words only in the reply to the client.

use instruments::InstrumentError;

use super::limits::LimitError;

/// A command refused, with why.
#[derive(Debug, thiserror::Error)]
pub enum Refusal {
    /// A set point or setting beyond its bounds; `what` names it.
    #[error("{what}: {source}")]
    Limit {
        /// The set point or setting, in the client's words ("speed", "load", …).
        what: &'static str,
        /// The bound it breaks.
        source: LimitError,
    },
    /// The plant refuses the new set points.
    #[error("{0}")]
    Plant(#[from] rig::RigError),
    /// An instrument refuses its new settings.
    #[error("{0}")]
    Instrument(#[from] InstrumentError),
    /// A setting refused by its own check, in words naming the field and the value.
    #[error("{0}")]
    Setting(String),
    /// The command went to a part of the rig that does not take it.
    #[error("{0}")]
    NotFor(String),
    /// The work behind the command (a file written, a measurement closed) failed.
    #[error("{0}")]
    Failed(String),
}

impl Refusal {
    /// The failure `error` of the work behind a command, with its causes.
    pub fn failed(error: &anyhow::Error) -> Self {
        Self::Failed(format!("{error:#}"))
    }
}
