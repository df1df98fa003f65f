//! The latest block of every signal kept in the run's status (live runs), for a
//! script that reads the rig as it goes (Python's `testrig.Rig.read`).

use std::sync::Arc;

use super::{Sink, SinkReport};
use crate::runtime::status::{LatestBlock, SharedStatus};
use crate::vocabulary::frame::Frame;

/// Keeps each frame's channels (shared, not copied) as the status's latest block.
pub struct TapSink {
    names: Arc<[String]>,
    status: SharedStatus,
}

impl TapSink {
    /// A tap on frames whose channels are `names`.
    pub fn new(names: Vec<String>, status: SharedStatus) -> Self {
        Self {
            names: names.into(),
            status,
        }
    }
}

impl Sink for TapSink {
    fn consume(&mut self, frame: &Frame) -> anyhow::Result<()> {
        let latest = Arc::new(LatestBlock {
            start_sample: frame.start_sample,
            names: Arc::clone(&self.names),
            channels: frame.channels.clone(),
        });
        self.status.update(|st| st.latest = Some(latest));
        Ok(())
    }

    fn finish(self: Box<Self>) -> anyhow::Result<SinkReport> {
        Ok(SinkReport::default())
    }
}
