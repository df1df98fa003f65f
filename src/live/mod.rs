//! The rig operated live: commands to the running rig, the session they make, and the
//! front panel that sends them (`testrig panel`).

pub mod command;
pub mod control;
pub mod display;
pub mod server;
pub mod session;
pub mod stage_commands;
pub mod state;

pub use command::{Command, Reply, Target, TimedCommand};
pub use control::{CommandInbox, ControlHandle, Pending, Request};
pub use display::{LiveSpectrum, LiveTrace};
