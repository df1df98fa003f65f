//! Reading a WAV file (ours, scipy's 64-bit float, any recorder's) as an analogue signal,
//! with the units and scales of its JSON sidecar when one lies beside it.
//!
//! Files: a WAV read by channel number or sidecar name; `float64.rs` for what hound does
//! not read.

pub(crate) mod float64;
pub(crate) mod sidecar;
pub(crate) mod signal;

pub use signal::{WavSignal, read_signal};
