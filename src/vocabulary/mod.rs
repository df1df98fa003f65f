//! The words every layer of the application shares, below all of them: the rig's commands
//! and their replies, the control channel that carries them to the plant, the frames of
//! samples and the signals' names, the display types of the panel, and the choices a
//! scenario names (window, filter, WAV format…). It depends on no other module of this
//! crate.
//!
//! Files: the words all share: `command.rs` the rig's commands (`RigCommand`, JSON and
//! TOML) and replies; `control.rs` how they travel (`ControlHandle` for senders with the
//! session's log, `CommandInbox` in the plant's thread, `Pending` on a frame with its reply
//! channel); `frame.rs` the block of samples passed between threads and `SignalNames`;
//! `signal_names.rs` every signal's name and the plant signals' units;
//! `display.rs` the panel's spectrum and trace and the chain's settings in effect (what the
//! page echoes); `choices.rs` a scenario's named choices (window, filter, sampling, WAV
//! format…) mapped onto the instruments' types; `limits.rs` every input bound (speed, load
//! — with the residual drag, within the motor's limit — simulated time, averages) with its
//! typed `LimitError`; `seeds.rs` every derived seed (each noise source in a run and in a
//! sweep case, each case of a grid); `gear_indicators.rs` a gear's condition indicators as
//! a row; `input_names.rs` how a caller names a point's inputs in errors, and the checks
//! of its times

pub(crate) mod choices;
pub(crate) mod command;
pub(crate) mod control;
pub(crate) mod display;
pub(crate) mod frame;
pub(crate) mod gear_indicators;
pub(crate) mod input_names;
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
pub use gear_indicators::GearIndicators;
pub use input_names::{FLAG_NAMES, InputNames, check_times};
pub use limits::{
    DEFAULT_LIVE_CEILING, MAX_SIMULATED_S, check_load_nm, check_load_within, check_simulated_s,
    check_speed_rpm, max_load_nm,
};
pub use point_verdict::{AwaitingVerdicts, PointVerdict, RowMotion};
pub use refusal::Refusal;
pub use signal_names::FILTER_V;
