//! The chain on one thread: every stage in turn on a frame, each adding its output as a
//! channel. The sweeps' cases and `testrig analyse` drive their stages here, and so does
//! the chain's thread of `testrig run` and the panel (`runtime::wiring::run_chain`).

use std::sync::Arc;

use super::stage_plan::NamedStage;
use crate::vocabulary::frame::Frame;

/// Stages in running order, driven on the caller's thread.
pub struct InlineChain {
    stages: Vec<NamedStage>,
}

impl InlineChain {
    /// The stages `stages`, in running order (as [`super::ChainStages::build`] gives them).
    pub fn new(stages: Vec<NamedStage>) -> Self {
        Self { stages }
    }

    /// The stages, in running order.
    pub fn stages(&self) -> &[NamedStage] {
        &self.stages
    }

    /// The stages, in running order, to carry out their commands.
    pub fn stages_mut(&mut self) -> &mut [NamedStage] {
        &mut self.stages
    }

    /// `frame` with every stage's output added, in order.
    pub fn process(&mut self, mut frame: Frame) -> Frame {
        for stage in &mut self.stages {
            // The channel made where the frame keeps it, in one allocation: a vector
            // turned into the frame's `Arc` was a second allocation and a copy, and the
            // frame with it a copy too (9 % of a sweep case's chain, measured).
            let mut out: Arc<[f64]> = std::iter::repeat_n(0.0, frame.len()).collect();
            let samples = Arc::get_mut(&mut out).expect("a channel just made has one owner");
            stage.stage.process(&frame, samples);
            frame.channels.push(out);
        }
        frame
    }
}
