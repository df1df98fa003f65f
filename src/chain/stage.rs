//! An instrument at work on frames: it reads channels of each frame and writes one more.

use instruments::{Block, SlipRing};

use crate::vocabulary::frame::Frame;

/// One instrument working on frames.
pub trait Stage: Send {
    /// Writes the stage's output for `frame` into `out` (the frame's length).
    fn process(&mut self, frame: &Frame, out: &mut [f64]);
}

/// A [`Block`] reading channel `input`.
pub fn block_stage<B: Block + Send + 'static>(block: B, input: usize) -> Box<dyn Stage> {
    Box::new(BlockStage { block, input })
}

/// Slip rings reading channel `input`, turning at the mean over each block of channel
/// `speed` (rad/s).
pub fn slip_ring_stage(rings: SlipRing, input: usize, speed: usize) -> Box<dyn Stage> {
    Box::new(SlipRingStage {
        rings,
        input,
        speed,
    })
}

struct BlockStage<B> {
    block: B,
    input: usize,
}

impl<B: Block + Send> Stage for BlockStage<B> {
    fn process(&mut self, frame: &Frame, out: &mut [f64]) {
        self.block.process(&frame.channels[self.input], out);
    }
}

struct SlipRingStage {
    rings: SlipRing,
    input: usize,
    speed: usize,
}

impl Stage for SlipRingStage {
    fn process(&mut self, frame: &Frame, out: &mut [f64]) {
        let speeds = &frame.channels[self.speed];
        let mean = speeds.iter().sum::<f64>() / speeds.len().max(1) as f64;
        self.rings.set_rotation_hz(mean / std::f64::consts::TAU);
        self.rings.process(&frame.channels[self.input], out);
    }
}
