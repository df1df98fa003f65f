//! A stretch of internal steps under one set of set points, and the set rotation φ in it.

use crate::schedule::SetPoints;

/// The set points held over the current stretch of internal steps.
#[derive(Clone, Copy, Debug)]
pub(super) struct Segment {
    pub(super) start_step: u64,
    pub(super) end_step: Option<u64>,
    pub(super) phase_rad: f64,
    pub(super) osc_phase_rad: f64,
    pub(super) set: SetPoints,
}

impl Segment {
    /// Set rotation φ (rad) `steps` internal steps of `step_s` into the segment.
    #[inline(always)]
    pub(super) fn phase_after(&self, steps: f64, step_s: f64) -> f64 {
        self.phase_rad + self.set.speed_rad_s() * (steps * step_s)
    }
}
