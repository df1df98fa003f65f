//! The unit passed between threads: a block of samples of every signal produced so far,
//! with its sequence number.

use std::sync::Arc;

use rig::Impact;

/// One block of samples. Channels are shared (`Arc`), so a stage that adds its output
/// copies only pointers; channel `i` is named by the run's [`SignalNames`] entry `i`.
#[derive(Clone, Debug)]
pub struct Frame {
    /// Sequence number, from 0, one per block the plant released.
    pub seq: u64,
    /// Index of the first sample in the run.
    pub start_sample: u64,
    /// The samples, one channel per signal.
    pub channels: Vec<Arc<[f64]>>,
    /// Contacts that started within the block.
    pub impacts: Arc<[Impact]>,
}

impl Frame {
    /// Samples per channel.
    pub fn len(&self) -> usize {
        self.channels.first().map_or(0, |c| c.len())
    }

    /// Whether the block holds no samples.
    pub fn is_empty(&self) -> bool {
        self.len() == 0
    }

    /// A copy of this frame with `channel` added at the end.
    pub fn with(&self, channel: Vec<f64>) -> Self {
        let mut channels = Vec::with_capacity(self.channels.len() + 1);
        channels.extend(self.channels.iter().cloned());
        channels.push(channel.into());
        Self {
            seq: self.seq,
            start_sample: self.start_sample,
            channels,
            impacts: Arc::clone(&self.impacts),
        }
    }
}

/// Names of a run's channels in frame order; every stage appends the one it produces.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct SignalNames(Vec<String>);

impl SignalNames {
    /// Appends `name`, returning its channel index.
    pub fn push(&mut self, name: &str) -> usize {
        self.0.push(name.to_string());
        self.0.len() - 1
    }

    /// Channel index of `name`.
    pub fn index(&self, name: &str) -> Option<usize> {
        self.0.iter().position(|n| n == name)
    }

    /// All names in order.
    pub fn names(&self) -> &[String] {
        &self.0
    }
}
