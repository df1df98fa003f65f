//! Errors of the plant: bad parameters, bad schedules, a rig's faults at their place, and a
//! run that went wrong.

/// Everything the plant can refuse or report.
#[derive(Debug, thiserror::Error)]
pub enum RigError {
    /// A parameter value outside its physical range.
    #[error("parameter `{name}` = {value}: {allowed}")]
    InvalidParameter {
        /// Parameter name as `testrig params` lists it.
        name: String,
        /// The value given.
        value: String,
        /// What is allowed.
        allowed: String,
    },
    /// A parameter name that does not exist.
    #[error("unknown parameter `{name}`{near} (`testrig params` lists them all)")]
    UnknownParameter {
        /// The name given.
        name: String,
        /// The nearest known names as a clause ("; did you mean `x`?"), or empty.
        near: String,
    },
    /// A preset name that does not exist.
    #[error("unknown preset `{name}` (known: {known})")]
    UnknownPreset {
        /// The name given.
        name: String,
        /// The presets there are.
        known: String,
    },
    /// A set-point schedule that cannot be run.
    #[error("schedule: {0}")]
    Schedule(String),
    /// A run option (output rate, durations) out of range.
    #[error("run option `{name}` = {value}: {allowed}")]
    InvalidOption {
        /// Option name.
        name: &'static str,
        /// The value given.
        value: String,
        /// What is allowed.
        allowed: &'static str,
    },
    /// The state left physical bounds or stopped being finite.
    #[error(
        "simulation blew up at t = {t_s:.6} s: {reason}; mechanical state (the bodies' angles less their share of the set rotation, rad; their speeds, rad/s; the speed loop's filtered speed and integral): {state:?}"
    )]
    BlowUp {
        /// Simulated time of detection (s).
        t_s: f64,
        /// What was seen.
        reason: String,
        /// The mechanical state when it was seen (`NetworkPlant::state_rad`).
        state: Vec<f64>,
    },
    /// A rig (from a rig file) the plant cannot run (its fault's message, once: not
    /// also as a source, which a chain of causes would print twice).
    #[error("rig: {0}")]
    Topology(TopologyError),
    /// Contact switches without end inside one step (a Zeno sequence).
    #[error("contact chatter at t = {t_s:.9} s: more than {limit} switches within one step")]
    Chatter {
        /// Simulated time (s).
        t_s: f64,
        /// The switch limit per step.
        limit: usize,
    },
}

impl From<TopologyError> for RigError {
    fn from(e: TopologyError) -> Self {
        Self::Topology(e)
    }
}

/// Where in a rig a fault lies: a table of the rig file (`body`, `shaft`, `mesh`,
/// `motor`, `brake`, `locked_torque`), the item's index in it, and the field.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct TopologyPlace {
    /// The table.
    pub table: &'static str,
    /// The item's index in its table (0 for a single table).
    pub index: usize,
    /// The field.
    pub field: &'static str,
}

/// A fault of a rig, at its place.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
#[error("{message}")]
pub struct TopologyError {
    /// Where.
    pub place: TopologyPlace,
    /// What is wrong and what is allowed.
    pub message: String,
}
