//! What the FMU refuses or where it fails: one message, reported to the importer through
//! its logger with `fmi3Error`.

/// A refused call or value, or a plant that failed; the message says which and why.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
#[error("{0}")]
pub struct FmuError(pub String);

impl From<rig::RigError> for FmuError {
    fn from(e: rig::RigError) -> Self {
        Self(e.to_string())
    }
}

impl From<rig::TopologyError> for FmuError {
    fn from(e: rig::TopologyError) -> Self {
        Self(e.to_string())
    }
}
