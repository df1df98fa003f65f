//! Threads and channels as the chain is wired: plant → the instrument stages in turn (one
//! thread) → every sink (one bounded channel per consumer, frames shared by `Arc`).

use std::sync::atomic::{AtomicBool, Ordering};
use std::sync::{Mutex, PoisonError};

use crossbeam_channel::{Receiver, Sender, bounded};

use super::sinks::{Sink, SinkReport};
use crate::chain::stage_commands::{apply_to_stage, echo_stage};
use crate::chain::{InlineChain, NamedStage};
use crate::runtime::status::SharedStatus;
use crate::vocabulary::frame::Frame;

/// Runs the chain's stages in turn in one thread (`chain::InlineChain`, as sweeps run
/// them): each frame in, its commands carried out by the stages they address, each stage
/// adding its output to the frame, out to every listener; ends when its input closes or
/// no one listens. What each stage applies is echoed in `status` (at the start and after
/// every command it carries out, before the answer goes: a client reading the state after
/// its reply sees what it set). One thread rather than one a stage: a block wakes one
/// thread instead of a dozen, which on two cores costs more than the stages' arithmetic.
pub fn run_chain(
    stages: Vec<NamedStage>,
    input: Receiver<Frame>,
    outputs: Vec<Sender<Frame>>,
    status: &SharedStatus,
) {
    let mut outputs = outputs;
    let mut chain = InlineChain::new(stages);
    status.update(|st| {
        for stage in chain.stages() {
            echo_stage(stage, &mut st.chain);
        }
    });
    for frame in input {
        for pending in frame.commands.iter() {
            for stage in chain.stages_mut() {
                if let Some(outcome) = apply_to_stage(stage, &pending.command) {
                    status.update(|st| echo_stage(stage, &mut st.chain));
                    pending.answer(outcome);
                }
            }
        }
        let frame = chain.process(frame);
        outputs.retain(|tx| tx.send(frame.clone()).is_ok());
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

/// Runs `work`, a stage's or a sink's thread named `name`. A panic in it fails the run
/// as an error would: the run is stopped, the error names the thread and the panic, and
/// `fallback` stands for what the thread would have returned. Nothing recorded so far is
/// lost: the other threads finish and close their files.
pub fn guarded<T>(
    name: &str,
    stop: &AtomicBool,
    errors: &Mutex<Vec<String>>,
    fallback: T,
    work: impl FnOnce() -> T,
) -> T {
    match std::panic::catch_unwind(std::panic::AssertUnwindSafe(work)) {
        Ok(value) => value,
        Err(payload) => {
            let what = payload
                .downcast_ref::<&str>()
                .map(|s| s.to_string())
                .or_else(|| payload.downcast_ref::<String>().cloned())
                .unwrap_or_else(|| "no message".into());
            stop.store(true, Ordering::Relaxed);
            errors
                .lock()
                .unwrap_or_else(PoisonError::into_inner)
                .push(format!("{name}: the thread failed (a panic: {what})"));
            fallback
        }
    }
}

/// A bounded channel of `capacity` frames.
pub fn channel(capacity: usize) -> (Sender<Frame>, Receiver<Frame>) {
    bounded(capacity)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A thread that panics fails the run as an error would: the run is told to stop, the
    /// error names the thread and the panic, and the fallback stands in for its result.
    #[test]
    fn a_panicking_thread_stops_the_run_with_its_name_and_message() {
        let stop = AtomicBool::new(false);
        let errors = Mutex::new(Vec::new());
        let value = guarded("analyser", &stop, &errors, 7, || -> i32 {
            panic!("range end index 4174 out of range")
        });
        assert_eq!(value, 7);
        assert!(stop.load(Ordering::Relaxed));
        let errors = errors.into_inner().expect("no poison");
        assert_eq!(errors.len(), 1);
        assert!(
            errors[0].starts_with("analyser: ") && errors[0].contains("4174 out of range"),
            "{errors:?}"
        );
        let calm = guarded("scope", &stop, &Mutex::new(Vec::new()), 0, || 3);
        assert_eq!(calm, 3);
    }
}
