//! The regime of the last stretch of a live run: a window of [`REGIME_WINDOW_S`] that is
//! summarised and started afresh each time it fills.

use rig::{Impact, Regime, RegimeCriteria, RevolutionSample, SignalBlock, SteadyWindow};

use super::plant_source::REGIME_WINDOW_S;

/// The window being filled and the regime of the last full one.
pub struct RollingRegime {
    window: SteadyWindow,
    teeth: u32,
    step_s: f64,
    filled_s: f64,
    last: Option<Regime>,
}

impl RollingRegime {
    /// For a plant of `teeth` teeth sampled every `step_s`.
    pub fn new(teeth: u32, step_s: f64) -> Self {
        Self {
            window: SteadyWindow::new(teeth, step_s),
            teeth,
            step_s,
            filled_s: 0.0,
            last: None,
        }
    }

    /// Adds a block made at `speed_rad_s`; returns the regime when a window has just filled.
    pub fn add(
        &mut self,
        block: &SignalBlock,
        speed_rad_s: f64,
        impacts: &[Impact],
        revolutions: &[RevolutionSample],
    ) -> Option<Regime> {
        self.window.add_block(block, speed_rad_s);
        self.window.add_impacts(impacts);
        self.window.add_revolutions(revolutions);
        self.filled_s += block.len() as f64 * self.step_s;
        if self.filled_s < REGIME_WINDOW_S {
            return None;
        }
        let regime = self.window.regime(&RegimeCriteria::default());
        self.window = SteadyWindow::new(self.teeth, self.step_s);
        self.filled_s = 0.0;
        self.last = Some(regime);
        self.last
    }
}
