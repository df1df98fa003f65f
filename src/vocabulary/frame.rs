//! The unit passed between threads: a block of samples of every signal produced so far,
//! with its sequence number.

use std::sync::Arc;

use rig::{Impact, NetworkImpact, SetPoints, SignalBlock};

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
    /// Contacts that started within the block.
    pub impacts: FrameImpacts,
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
    pub fn of_channels(channels: Vec<Vec<f64>>) -> Self {
        Self {
            seq: 0,
            start_sample: 0,
            channels: channels.into_iter().map(Arc::from).collect(),
            impacts: FrameImpacts::default(),
            commands: Arc::new([]),
            set_points: None,
            points: Arc::new([]),
        }
    }

    /// A frame of the plant's true signals, channels in the order of
    /// [`rig::COLUMN_NAMES`].
    pub fn of_block(
        seq: u64,
        start_sample: u64,
        block: &SignalBlock,
        impacts: Vec<Impact>,
    ) -> Self {
        let mut channels: Vec<Arc<[f64]>> = Vec::with_capacity(rig::COLUMN_NAMES.len());
        channels.push(block.time_s.as_slice().into());
        for v in block
            .angle_rad
            .iter()
            .chain(&block.speed_rad_s)
            .chain(&block.shaft_torque_nm)
        {
            channels.push(v.as_slice().into());
        }
        channels.push(block.mesh_torque_nm.as_slice().into());
        channels.push(block.motor_torque_nm.as_slice().into());
        channels.push(block.contact.iter().map(|&c| f64::from(c)).collect());
        channels.push(block.tooth.iter().map(|&t| f64::from(t)).collect());
        Self {
            seq,
            start_sample,
            channels,
            impacts: FrameImpacts::Gears(impacts.into()),
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

    /// A copy of this frame with `channel` added at the end.
    pub fn with(&self, channel: Vec<f64>) -> Self {
        let mut channels = Vec::with_capacity(self.channels.len() + 1);
        channels.extend(self.channels.iter().cloned());
        channels.push(channel.into());
        Self {
            seq: self.seq,
            start_sample: self.start_sample,
            channels,
            impacts: self.impacts.clone(),
            commands: Arc::clone(&self.commands),
            set_points: self.set_points,
            points: Arc::clone(&self.points),
        }
    }
}

/// The contacts that started within a frame's block, as its plant logs them.
#[derive(Clone, Debug)]
pub enum FrameImpacts {
    /// The thesis's plant: its one gear pair's impacts.
    Gears(Arc<[Impact]>),
    /// A rig file's plant: each mesh's impacts.
    Meshes(Arc<[NetworkImpact]>),
}

impl Default for FrameImpacts {
    fn default() -> Self {
        Self::Gears(Arc::new([]))
    }
}

impl FrameImpacts {
    /// How many contacts started.
    pub fn len(&self) -> usize {
        match self {
            Self::Gears(i) => i.len(),
            Self::Meshes(i) => i.len(),
        }
    }

    /// Whether none did.
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

    /// The plant's channels, in the order of [`rig::COLUMN_NAMES`].
    pub fn plant() -> Self {
        Self(rig::COLUMN_NAMES.iter().map(|n| n.to_string()).collect())
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
