//! The unit passed between threads: a block of samples of every signal produced so far,
//! with its sequence number.

use std::sync::Arc;

use rig::{NetworkImpact, SetPoints};

use crate::vocabulary::Pending;
use crate::vocabulary::point_verdict::PointVerdict;

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
    /// Contacts that started within the block, each mesh's.
    pub impacts: Arc<[NetworkImpact]>,
    /// Commands that take effect at the block's start, for the stages and sinks they
    /// address (each carries them out before the block's samples).
    pub commands: Arc<[Pending]>,
    /// The set points the block was made under (live runs and commands use them).
    pub set_points: Option<SetPoints>,
    /// Measured points whose judged window ended before this block (or with it, on the
    /// run's last frame): the sinks add the motion to those points' rows.
    pub points: Arc<[Arc<PointVerdict>]>,
}

impl Frame {
    /// A frame of the signals `channels` from the stream's start, without impacts,
    /// commands or set points (a recording's channels).
    pub fn of_channels(channels: Vec<Arc<[f64]>>) -> Self {
        Self {
            seq: 0,
            start_sample: 0,
            channels,
            impacts: Arc::new([]),
            commands: Arc::new([]),
            set_points: None,
            points: Arc::new([]),
        }
    }

    /// This frame carrying the verdicts on `points`.
    pub fn with_points(mut self, points: Vec<Arc<PointVerdict>>) -> Self {
        self.points = points.into();
        self
    }

    /// This frame carrying `commands`, made under `set_points`.
    pub fn with_commands(mut self, commands: Vec<Pending>, set_points: SetPoints) -> Self {
        self.commands = commands.into();
        self.set_points = Some(set_points);
        self
    }

    /// Samples per channel.
    pub fn len(&self) -> usize {
        self.channels.first().map_or(0, |c| c.len())
    }

    /// Whether the block holds no samples.
    pub fn is_empty(&self) -> bool {
        self.len() == 0
    }
}

/// Names of a run's channels in frame order; every stage appends the one it produces.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct SignalNames(Vec<String>);

impl SignalNames {
    /// The signals `names`, in order (a chain on other signals than the plant's).
    pub fn of(names: &[&str]) -> Self {
        Self(names.iter().map(|n| n.to_string()).collect())
    }

    /// The signals the plant hands the chain
    /// (`crate::vocabulary::signal_names::PLANT_SIGNALS`).
    pub fn plant() -> Self {
        Self::of(&super::signal_names::PLANT_SIGNALS)
    }

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
