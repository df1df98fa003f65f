//! The fast path: runs of output samples in one mode. Each stride or step is one fused
//! product; the switch checks, the bounds and the samples are done on locals. A step
//! that may switch goes to the exact path and ends the run; a run also stops before a
//! set-point change or a re-sync of the harmonic states (the one-at-a-time path in
//! `advance_step` takes those).

use crate::error::RigError;
use crate::fused_step::{FUSED_ROWS, FusedRows, MAX_ROW_EVENTS};
use crate::layout::{Layout, N_MECH};

use super::output::within_bounds;
use super::segment_start::rotate;
use super::state::{Plant, RESYNC_STEPS};
use super::stepping::StepEnds;

impl Plant {
    /// Takes up to `limit` samples on the fast path (their states stored in the chunk when
    /// `RECORD`), each after `substeps` internal steps, all in the mode it starts in: a
    /// step that may switch is taken on the exact path, the rest of its output period one
    /// step at a time, and the run ends there. Returns how many samples it took (maybe
    /// none) and the error of the exact path, if any (the samples before it, and that of
    /// the failing period, are taken).
    pub(super) fn fast_run<const RECORD: bool>(
        &mut self,
        limit: usize,
    ) -> (usize, Result<(), RigError>) {
        let first = self.step_index;
        let per_sample = self.substeps as usize;
        let Some(count) = self.run_length(limit) else {
            return (0, Ok(()));
        };
        self.cache.ensure(self.mode);
        let system = self.cache.built(self.mode);
        let rotations = self.cache.rotations();
        let stride = &system.stride;
        let stride_rotations = self.cache.rotations_by(stride.steps);
        let segment = self.segment;
        let targets = self.angle_targets(system);
        let (speed, h) = (self.segment.set.speed_rad_s(), self.step_s);
        let mut u = self.u;
        let mut edge = self.edge.unwrap_or_else(|| system.row_event_values(&u));
        // Internal steps taken; samples stored so far, and the step of the next.
        let mut taken = 0;
        let (mut samples, mut next_sample) = (0, 0);
        // After a stride that may switch, single steps up to here.
        let mut singles_until = 0;
        while taken < count {
            let step = first + taken as u64;
            if !within_bounds(&u) {
                break;
            }
            let phase_rad = segment.phase_after((step - segment.start_step) as f64, h);
            // Whether a switch may fall within the `steps` from `u` that end at `end`.
            let may_switch = |edge: &[f64; 2 * MAX_ROW_EVENTS],
                              end: &FusedRows,
                              u: &[f64; Layout::MAX_LEN],
                              steps: usize| {
                let ends = StepEnds {
                    start: edge,
                    end,
                    u0: u,
                    phase_rad,
                    speed_rad_s: speed,
                    step_s: steps as f64 * h,
                };
                ends.may_switch(&targets)
            };
            let m = stride.steps;
            if m > 1 && taken >= singles_until && count - taken >= m {
                let end = stride.end(&u);
                if !may_switch(&edge, &end, &u, m) {
                    // The samples inside the stride, written out here: behind a helper
                    // taking a closure this loop ran 15 % slower (measured).
                    let mut k = next_sample - taken;
                    if RECORD && k == 0 {
                        self.chunk.store(samples, &u);
                    }
                    if k == 0 {
                        samples += 1;
                        k += per_sample;
                    }
                    // No tooth pass inside a stride: one spacing error for all of it.
                    let spacing = self.chunk.spacing_of(&u);
                    while k < m {
                        if RECORD {
                            let (c, s) = rotated(&u, self.cache.phase_rotation_by(k));
                            self.chunk
                                .store_parts(samples, &stride.sample(k, &u), c, s, spacing);
                        }
                        samples += 1;
                        k += per_sample;
                    }
                    next_sample = taken + k;
                    take_end(&mut u, &mut edge, &end, stride_rotations);
                    taken += m;
                    continue;
                }
                singles_until = taken + m;
            }
            let end = system.step(&u);
            let switches = may_switch(&edge, &end, &u, 1);
            if taken == next_sample {
                if RECORD {
                    self.chunk.store(samples, &u);
                }
                samples += 1;
                next_sample += per_sample;
            }
            if switches {
                let mut step_end = u;
                step_end[..N_MECH].copy_from_slice(&end[..N_MECH]);
                rotate(&mut step_end, rotations);
                self.u = u;
                self.edge = None;
                self.step_index = step;
                let finished = self.finish_period_exactly(step_end, next_sample - taken - 1);
                return (samples, finished);
            }
            take_end(&mut u, &mut edge, &end, rotations);
            taken += 1;
        }
        self.u = u;
        self.edge = Some(edge);
        self.step_index = first + taken as u64;
        (samples, Ok(()))
    }

    /// Internal steps of the next fast run (whole output periods, up to `limit` samples,
    /// ending before a re-sync of the harmonic states and the segment's end), or None.
    fn run_length(&self, limit: usize) -> Option<usize> {
        let first = self.step_index;
        let per_sample = self.substeps as usize;
        let mut steps_left = (first / RESYNC_STEPS + 1) * RESYNC_STEPS - first;
        if let Some(end) = self.segment.end_step {
            steps_left = steps_left.min(end.saturating_sub(first));
        }
        if first.is_multiple_of(RESYNC_STEPS) || steps_left < per_sample as u64 {
            return None;
        }
        Some((limit * per_sample).min(steps_left as usize / per_sample * per_sample))
    }

    /// Takes the current step on the exact path (`step_end` being its end without a
    /// switch), then the `rest` steps of its output period one at a time.
    #[inline(never)]
    fn finish_period_exactly(
        &mut self,
        step_end: [f64; Layout::MAX_LEN],
        rest: usize,
    ) -> Result<(), RigError> {
        self.advance_exactly(step_end)?;
        self.step_index += 1;
        for _ in 0..rest {
            self.advance_step()?;
        }
        Ok(())
    }
}

/// Moves `u` to the end of a step or stride: its mechanical states from `end`, its
/// harmonic pairs turned by `rotations`, and the row events there into `edge`.
#[inline(always)]
fn take_end(
    u: &mut [f64; Layout::MAX_LEN],
    edge: &mut [f64; 2 * MAX_ROW_EVENTS],
    end: &FusedRows,
    rotations: &[(usize, f64, f64)],
) {
    u[..N_MECH].copy_from_slice(&end[..N_MECH]);
    rotate(u, rotations);
    edge.copy_from_slice(&end[N_MECH..FUSED_ROWS]);
}

/// The harmonic pair at `index` of `u` turned by (cos, sin).
#[inline(always)]
fn rotated(u: &[f64; Layout::MAX_LEN], (index, cos, sin): (usize, f64, f64)) -> (f64, f64) {
    let (c, s) = (u[index], u[index + 1]);
    (c * cos - s * sin, s * cos + c * sin)
}
