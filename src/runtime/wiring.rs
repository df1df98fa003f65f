//! Threads and channels as the chain is wired: plant → each instrument stage in turn →
//! every sink (one bounded channel per consumer, frames shared by `Arc`).

use std::sync::atomic::{AtomicBool, Ordering};
use std::sync::{Mutex, PoisonError};

use crossbeam_channel::{Receiver, Sender, bounded};

use super::sinks::{Sink, SinkReport};
use crate::chain::NamedStage;
use crate::chain::stage_commands::apply_to_stage;
use crate::vocabulary::frame::Frame;

/// Runs a stage: each frame in, the frame with the stage's output added, out to every
/// listener; ends when its input closes or no one listens.
pub fn run_stage(mut stage: NamedStage, input: Receiver<Frame>, outputs: Vec<Sender<Frame>>) {
    let mut outputs = outputs;
    let mut out = Vec::new();
    for frame in input {
        for pending in frame.commands.iter() {
            if let Some(outcome) = apply_to_stage(&mut stage, &pending.command) {
                pending.answer(outcome);
            }
        }
        out.clear();
        out.resize(frame.len(), 0.0);
        stage.stage.process(&frame, &mut out);
        let next = frame.with(std::mem::take(&mut out));
        outputs.retain(|tx| tx.send(next.clone()).is_ok());
        if outputs.is_empty() {
            break;
        }
    }
}

/// Runs a sink until its input closes, then finishes it. A failure stops the run (through
/// `stop`), is kept in `errors`, and the sink still closes what it has written.
pub fn run_sink(
    name: &'static str,
    mut sink: Box<dyn Sink>,
    input: Receiver<Frame>,
    stop: &AtomicBool,
    errors: &Mutex<Vec<String>>,
) -> SinkReport {
    let fail = |e: anyhow::Error| {
        stop.store(true, Ordering::Relaxed);
        errors
            .lock()
            .unwrap_or_else(PoisonError::into_inner)
            .push(format!("{name}: {e:#}"));
    };
    for frame in input {
        for pending in frame.commands.iter() {
            if let Some(outcome) = sink.command(&pending.command, &frame) {
                pending.answer(outcome);
            }
        }
        if let Err(e) = sink.consume(&frame) {
            fail(e);
            break;
        }
    }
    match sink.finish() {
        Ok(report) => report,
        Err(e) => {
            fail(e);
            SinkReport::default()
        }
    }
}

/// A bounded channel of `capacity` frames.
pub fn channel(capacity: usize) -> (Sender<Frame>, Receiver<Frame>) {
    bounded(capacity)
}
