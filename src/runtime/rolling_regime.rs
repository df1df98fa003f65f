//! The motion of the last stretch of a live run: a window of [`REGIME_WINDOW_S`] that is
//! summarised and started afresh each time it fills. The regime (cheap) is taken in the
//! plant's thread; the physics judge (a spectrum of the window) runs in a thread of its
//! own, so that the paced thread is never held up by it.

use rig::{Impact, RegimeCriteria, RevolutionSample, SignalBlock, SteadyWindow};

use super::status::SharedStatus;

/// Longest stretch at the end of a run whose once-per-revolution samples decide the regime (s).
pub const REGIME_WINDOW_S: f64 = 10.0;

/// The window being filled; the shared status receives each full window's verdicts.
pub struct RollingRegime {
    window: SteadyWindow,
    teeth: u32,
    step_s: f64,
    filled_s: f64,
    status: SharedStatus,
}

impl RollingRegime {
    /// For a plant of `teeth` teeth sampled every `step_s`, reporting into `status`.
    pub fn new(teeth: u32, step_s: f64, status: SharedStatus) -> Self {
        Self {
            window: SteadyWindow::new(teeth, step_s),
            teeth,
            step_s,
            filled_s: 0.0,
            status,
        }
    }

    /// Adds a block made at `speed_rad_s`; when a window has just filled, its regime goes
    /// to the status at once and its judged motion when the judge's thread is done.
    pub fn add(
        &mut self,
        block: &SignalBlock,
        speed_rad_s: f64,
        impacts: &[Impact],
        revolutions: &[RevolutionSample],
    ) {
        self.window.add_block(block, speed_rad_s);
        self.window.add_impacts(impacts);
        self.window.add_revolutions(revolutions);
        self.filled_s += block.len() as f64 * self.step_s;
        if self.filled_s < REGIME_WINDOW_S {
            return;
        }
        let full = std::mem::replace(&mut self.window, SteadyWindow::new(self.teeth, self.step_s));
        self.filled_s = 0.0;
        let regime = full.regime(&RegimeCriteria::default());
        self.status.update(|s| s.regime = Some(regime));
        let status = self.status.clone();
        // Without a thread the panel keeps the last motion: nothing else depends on it.
        let _ = std::thread::Builder::new()
            .name("judge".into())
            .spawn(move || {
                let motion = full.judgement().motion;
                status.update(|s| s.motion = Some(motion));
            });
    }
}
