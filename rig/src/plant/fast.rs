//! The fast path: runs of whole output samples in which no switching function can cross.
//! Each step is one fused product; the switch checks, the bounds and the sample are done
//! on locals, and the run stops before the first step that needs the exact path, a
//! set-point change or a re-sync of the harmonic states (the one-at-a-time path in
//! `advance_step` takes those).

use crate::layout::N_MECH;
use crate::propagator::{FUSED_ROWS, MAX_ROW_EVENTS};
use crate::signals::Sample;

use super::output::within_bounds;
use super::segments::rotate;
use super::state::{Plant, RESYNC_STEPS};
use super::stepping::StepEnds;

impl Plant {
    /// Fills the leading slots (written only when `RECORD`) with fast-path samples,
    /// advancing one output period after each; returns how many it took (maybe none).
    pub(super) fn fast_run<const RECORD: bool>(&mut self, slots: &mut [Sample]) -> usize {
        let first = self.step_index;
        if self.substeps != 1
            || first.is_multiple_of(RESYNC_STEPS)
            || Some(first) == self.segment.end_step
        {
            return 0;
        }
        let mut limit = (first / RESYNC_STEPS + 1) * RESYNC_STEPS - first;
        if let Some(end) = self.segment.end_step {
            limit = limit.min(end - first);
        }
        let count = (slots.len() as u64).min(limit) as usize;
        self.cache.ensure(self.mode);
        let system = self.cache.built(self.mode);
        let rotations = self.cache.rotations();
        let frame = self.frame();
        let targets = self.angle_targets(system);
        let (speed, h) = (self.segment.set.speed_rad_s(), self.step_s);
        let mut u = self.u;
        let mut edge = self.edge.unwrap_or_else(|| system.row_event_values(&u));
        let mut taken = 0;
        while taken < count {
            let step = first + taken as u64;
            if !within_bounds(&u) {
                break;
            }
            let end = system.step(&u);
            let ends = StepEnds {
                start: &edge,
                end: &end,
                u0: &u,
                phase_rad: frame.phase_rad(step),
                speed_rad_s: speed,
                step_s: h,
            };
            if ends.may_switch(&targets) {
                break;
            }
            if RECORD {
                slots[taken] = frame.sample(&u, step);
            }
            u[..N_MECH].copy_from_slice(&end[..N_MECH]);
            rotate(&mut u, rotations);
            edge = [0.0; 2 * MAX_ROW_EVENTS];
            edge.copy_from_slice(&end[N_MECH..FUSED_ROWS]);
            taken += 1;
        }
        self.u = u;
        self.edge = Some(edge);
        self.step_index = first + taken as u64;
        taken
    }
}
