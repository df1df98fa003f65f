//! The words every layer of the application shares, below all of them: the rig's commands
//! and their replies, the control channel that carries them to the plant, the frames of
//! samples and the signals' names, the display types of the panel, and the choices a
//! scenario names (window, filter, WAV format…). It depends on no other module of this
//! crate.

pub(crate) mod choices;
pub(crate) mod command;
pub(crate) mod control;
pub(crate) mod display;
pub(crate) mod frame;
pub(crate) mod limits;
pub(crate) mod point_verdict;
pub(crate) mod refusal;
pub(crate) mod seeds;
pub(crate) mod signal_names;

pub use choices::SamplingChoice;
pub use command::{Reply, RigCommand, Target, TimedCommand};
pub use control::{CommandInbox, ControlHandle, MAX_QUEUED_COMMANDS, Pending, Request};
pub use display::{AppliedChain, AppliedFilter, LiveSpectrum, LiveTrace};
pub use frame::{Frame, SignalNames};
pub use limits::{
    DEFAULT_LIVE_CEILING, MAX_SIMULATED_S, check_load_nm, check_load_within_motor,
    check_simulated_s, check_speed_rpm, max_load_nm,
};
pub use point_verdict::{PointVerdict, PointVerdicts, motion_label};
pub use refusal::Refusal;
pub use signal_names::FILTER_V;
