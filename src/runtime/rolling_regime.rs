//! The motion of the last stretch of a live run: after each change of the set points the
//! rig is left [`SETTLE_S`] to settle (the panel says "settling"), then windows of
//! [`REGIME_WINDOW_S`] are summarised, each started afresh when the one before fills. The
//! physics judge (a spectrum of the window) runs in a thread of its own, so that the
//! paced thread is never held up by it, and gives the regime with the motion.

use std::sync::Arc;
use std::sync::atomic::{AtomicU64, Ordering};

use rig::SetPoints;

use super::run_plant::{RunBlock, RunPlant, RunWindow};
use super::status::SharedStatus;

/// Length of the windows the judge decides a live run's regime and motion on (s).
pub const REGIME_WINDOW_S: f64 = 10.0;

/// Time left to settle after the set points change before a window starts (s): the
/// fundamental's transient (17.7 Hz, damping ratio about 0.002, time constant 4.5 s) is
/// down to about 4 % of its start by then, and the speed loop (0.5 Hz) has settled.
pub const SETTLE_S: f64 = 15.0;

/// What the panel shows while the rig settles.
pub const SETTLING: &str = "settling";

/// The window being filled; the shared status receives each full window's verdicts.
pub struct RollingRegime {
    window: RunWindow,
    step_s: f64,
    /// Time settled so far since the last change of set points (s), up to [`SETTLE_S`].
    settled_s: f64,
    filled_s: f64,
    held: Option<SetPoints>,
    /// Counts set-point changes: a judge's thread reports only if none came since it began.
    generation: Arc<AtomicU64>,
    status: SharedStatus,
}

impl RollingRegime {
    /// For `plant`, reporting into `status`.
    pub fn new(plant: &RunPlant, status: SharedStatus) -> Self {
        Self {
            window: plant.window(false),
            step_s: plant.output_step_s(),
            settled_s: 0.0,
            filled_s: 0.0,
            held: None,
            generation: Arc::new(AtomicU64::new(0)),
            status,
        }
    }

    /// Adds `plant`'s block of `samples` samples made under `set`; when a window has just
    /// filled, the judge's regime and motion go to the status when the judge's thread is
    /// done.
    pub fn add(&mut self, plant: &RunPlant, block: &RunBlock, samples: usize, set: &SetPoints) {
        if self.held.as_ref() != Some(set) {
            self.restart(plant, *set);
        }
        let block_s = samples as f64 * self.step_s;
        if self.settled_s < SETTLE_S {
            self.settled_s += block_s;
            return;
        }
        self.window.add(block, set);
        self.filled_s += block_s;
        if self.filled_s < REGIME_WINDOW_S {
            return;
        }
        let full = std::mem::replace(&mut self.window, plant.window(false));
        self.filled_s = 0.0;
        let status = self.status.clone();
        let generation = Arc::clone(&self.generation);
        let began = generation.load(Ordering::Relaxed);
        // Without a thread the panel keeps the last motion: nothing else depends on it.
        let _ = std::thread::Builder::new()
            .name("judge".into())
            .spawn(move || {
                let (regime, motion) = full.judged();
                if generation.load(Ordering::Relaxed) == began {
                    status.update(|s| {
                        s.regime = Some(regime);
                        s.motion = Some(motion);
                    });
                }
            });
    }

    /// New set points: the window so far is dropped and the rig left to settle again.
    fn restart(&mut self, plant: &RunPlant, set: SetPoints) {
        self.held = Some(set);
        self.generation.fetch_add(1, Ordering::Relaxed);
        self.window = plant.window(false);
        self.settled_s = 0.0;
        self.filled_s = 0.0;
        self.status.update(|s| {
            s.regime = Some(SETTLING.to_string());
            s.motion = Some(SETTLING.to_string());
        });
    }
}
