//! Recorders: streams of samples to files that other tools read.

pub mod uff58;
pub mod wav;

pub use uff58::{Uff58Abscissa, Uff58Record, write_uff58};
pub use wav::{ChannelInfo, WavRecorder};
