//! Taking samples: the true signals at the output rate, and the bounds that stop a blown-up run.

use crate::error::RigError;
use crate::layout::{Layout, N_MECH, REV, V0, VF, X0, Z};
use crate::mode::Mode;
use crate::model::ModelConstants;
use crate::records::Flank;
use crate::signals::SignalBlock;

use super::chunk::{CHUNK, SampleFrame};
use super::mesh_position::{flank_overlap, tooth_at};
use super::state::{Plant, SPEED_LIMIT_RAD_S, TWIST_LIMIT_RAD};

impl Plant {
    /// Advances `samples` output samples, appending each (the state at t = n / rate, then one step) to `out`.
    /// On an error the block keeps every sample taken before it.
    pub fn run(&mut self, samples: usize, out: &mut SignalBlock) -> Result<(), RigError> {
        self.advance_samples(samples, Some(out))
    }

    /// Advances `samples` output samples without recording them.
    pub fn skip(&mut self, samples: usize) -> Result<(), RigError> {
        self.advance_samples(samples, None)
    }

    /// Takes `samples` samples (appended to `out` if given), advancing one output period
    /// after each: whole runs on the fast path, the rest one at a time. On an error, `out`
    /// keeps every sample taken before it.
    fn advance_samples(
        &mut self,
        samples: usize,
        mut out: Option<&mut SignalBlock>,
    ) -> Result<(), RigError> {
        let mut done = 0;
        while done < samples {
            let (first, mode) = (self.step_index, self.mode);
            let limit = CHUNK.min(samples - done);
            let (taken, switched) = match out.as_deref_mut() {
                Some(block) => {
                    let run = self.fast_run::<true>(limit);
                    self.frame_in(mode).append(&self.chunk, run.0, first, block);
                    run
                }
                None => self.fast_run::<false>(limit),
            };
            switched?;
            done += taken;
            if taken > 0 {
                continue;
            }
            if !self.within_bounds() {
                return Err(self.blow_up());
            }
            if let Some(block) = out.as_deref_mut() {
                self.chunk.store(0, &self.u);
                self.frame_in(self.mode)
                    .append(&self.chunk, 1, self.step_index, block);
            }
            for _ in 0..self.substeps {
                self.advance_step()?;
            }
            done += 1;
        }
        Ok(())
    }

    /// What a sample needs besides the state, for `mode` and the current segment.
    pub(super) fn frame_in(&self, mode: Mode) -> SampleFrame<'_> {
        SampleFrame {
            mc: &self.mc,
            mode,
            segment: self.segment,
            step_s: self.step_s,
            steps_per_sample: self.substeps,
            tooth_pitch_rad: self.geometry.tooth_pitch_rad,
            teeth: f64::from(self.params.teeth),
        }
    }

    /// Tooth of the driving gear in mesh at its angle `theta2` (rad), 0..teeth.
    pub(super) fn tooth_at(&self, theta2: f64) -> u32 {
        tooth_at(
            theta2,
            self.geometry.tooth_pitch_rad,
            f64::from(self.params.teeth),
        )
    }

    /// Whether the state is within its bounds (see [`within_bounds`]).
    #[inline]
    pub(super) fn within_bounds(&self) -> bool {
        within_bounds(&self.u)
    }

    /// The error for a state that left its bounds, saying which bound.
    #[cold]
    pub(super) fn blow_up(&self) -> RigError {
        let u = &self.u;
        let reason = if !u[..N_MECH].iter().all(|v| v.is_finite()) {
            "the state is no longer finite".to_string()
        } else if (0..4).any(|i| (u[X0 + i] - u[X0 + i + 1]).abs() > TWIST_LIMIT_RAD) {
            format!("a shaft or the mesh is twisted by more than {TWIST_LIMIT_RAD} rad")
        } else {
            format!("a speed departs from the set speed by more than {SPEED_LIMIT_RAD_S} rad/s")
        };
        RigError::BlowUp {
            t_s: self.time_at(0.0),
            reason,
            state: u[..10].to_vec(),
        }
    }
}

/// Whether `u` is finite, every twist within 1 rad and every relative speed within 10⁴ rad/s.
#[inline]
pub(super) fn within_bounds(u: &[f64; Layout::MAX_LEN]) -> bool {
    let twist_ok = (0..4).all(|i| (u[X0 + i] - u[X0 + i + 1]).abs() <= TWIST_LIMIT_RAD);
    let speed_ok = (0..5).all(|i| u[V0 + i].abs() <= SPEED_LIMIT_RAD_S);
    twist_ok && speed_ok && u[VF].is_finite() && u[Z].is_finite()
}

/// Overlap of `flank` (rad, > 0 when the teeth overlap) and its rate (rad/s) in state `u`,
/// whose harmonic states hold cos φ and sin φ (and cos zφ, sin zφ where `layout` has
/// them) of that instant, and the spacing error of the pair in mesh where it has one.
#[inline]
pub(super) fn flank_gap(
    mc: &ModelConstants,
    layout: &Layout,
    speed_rad_s: f64,
    u: &[f64; Layout::MAX_LEN],
    flank: Flank,
) -> (f64, f64) {
    let mesh = [u[X0 + 1], u[X0 + 2], u[V0 + 1], u[V0 + 2]];
    let (cos_z, sin_z) = layout.mesh.map_or((0.0, 0.0), |m| (u[m], u[m + 1]));
    let harmonics = [u[REV], u[REV + 1], cos_z, sin_z];
    let spacing = layout.spacing.map_or(0.0, |s| u[s]);
    flank_overlap(mc, speed_rad_s, flank.sign(), mesh, harmonics, spacing)
}
