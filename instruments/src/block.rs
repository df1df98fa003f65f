//! The trait every instrument block implements.

use num_complex::Complex64;

/// A stage of the measuring chain working on a sampled stream.
///
/// A block keeps its state across calls, so a signal cut into buffers gives the same
/// output as in one piece; `reset` returns it to its state after construction.
pub trait Block {
    /// Returns to the state after construction: the same input then gives the same output.
    fn reset(&mut self);

    /// Processes `input` into `output` (equal lengths) without allocating.
    fn process(&mut self, input: &[f64], output: &mut [f64]);

    /// Complex frequency response at `freq_hz` (Hz), where the block is linear and
    /// time-invariant; `None` otherwise.
    fn response(&self, freq_hz: f64) -> Option<Complex64> {
        let _ = freq_hz;
        None
    }

    /// Samples the block holds back beyond what its response says (0 for most).
    fn latency(&self) -> usize {
        0
    }
}
