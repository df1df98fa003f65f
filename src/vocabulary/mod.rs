//! The words every layer of the application shares, below all of them: the rig's commands
//! and their replies, the control channel that carries them to the plant, the frames of
//! samples and the signals' names, the display types of the panel, and the choices a
//! scenario names (window, filter, WAV format…). It depends on no other module of this
//! crate.

pub mod choices;
pub mod command;
pub mod control;
pub mod display;
pub mod frame;
pub mod limits;
pub mod seeds;
pub mod signal_names;

pub use command::{Command, Reply, Target, TimedCommand};
pub use control::{CommandInbox, ControlHandle, Pending, Request};
pub use display::{LiveSpectrum, LiveTrace};
pub use frame::{Frame, SignalNames};
