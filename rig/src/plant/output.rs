//! Taking samples: the true signals at the output rate, and the bounds that stop a blown-up run.

use crate::error::RigError;
use crate::layout::{Layout, N_MECH, REV, V0, VF, X0, Z};
use crate::mode::{MeshMode, Mode, MotorMode};
use crate::model::ModelConstants;
use crate::records::Flank;
use crate::signals::{Sample, SignalBlock};

use super::state::{CHUNK, Plant, SPEED_LIMIT_RAD_S, TWIST_LIMIT_RAD};

impl Plant {
    /// Advances `samples` output samples, appending each (the state at t = n / rate, then one step) to `out`.
    /// On an error the block keeps every sample taken before it.
    pub fn run(&mut self, samples: usize, out: &mut SignalBlock) -> Result<(), RigError> {
        let mut chunk = [self.sample(); CHUNK];
        let mut done = 0;
        while done < samples {
            let n = CHUNK.min(samples - done);
            let taken = self.advance_samples::<true>(&mut chunk[..n]);
            let count = match &taken {
                Ok(()) => n,
                Err((count, _)) => *count,
            };
            out.extend_from_samples(&chunk[..count]);
            taken.map_err(|(_, error)| error)?;
            done += n;
        }
        Ok(())
    }

    /// Advances `samples` output samples without recording them.
    pub fn skip(&mut self, samples: usize) -> Result<(), RigError> {
        let mut scratch = [self.sample(); CHUNK];
        let mut done = 0;
        while done < samples {
            let n = CHUNK.min(samples - done);
            self.advance_samples::<false>(&mut scratch[..n])
                .map_err(|(_, error)| error)?;
            done += n;
        }
        Ok(())
    }

    /// Takes one sample per slot (written only when `RECORD`), advancing one output period
    /// after each: whole runs on the fast path, the rest one at a time. An error comes
    /// with the number of slots filled before it.
    fn advance_samples<const RECORD: bool>(
        &mut self,
        slots: &mut [Sample],
    ) -> Result<(), (usize, RigError)> {
        let mut k = 0;
        while k < slots.len() {
            k += self.fast_run::<RECORD>(&mut slots[k..]);
            if k == slots.len() {
                break;
            }
            if !self.within_bounds() {
                return Err((k, self.blow_up()));
            }
            if RECORD {
                slots[k] = self.sample();
            }
            for _ in 0..self.substeps {
                self.advance_step().map_err(|error| (k, error))?;
            }
            k += 1;
        }
        Ok(())
    }

    /// The true signals now.
    pub fn sample(&self) -> Sample {
        self.frame().sample(&self.u, self.step_index)
    }

    /// What a sample needs besides the state, for the current mode and segment.
    pub(super) fn frame(&self) -> SampleFrame<'_> {
        SampleFrame {
            mc: &self.mc,
            mode: self.mode,
            speed_rad_s: self.segment.set.speed_rad_s(),
            step_s: self.step_s,
            segment_phase_rad: self.segment.phase_rad,
            segment_start: self.segment.start_step,
            tooth_pitch_rad: self.geometry.tooth_pitch_rad,
            teeth: i64::from(self.params.teeth),
        }
    }

    /// Mesh torque F_XT on the driven gear (N m).
    pub fn mesh_torque_nm(&self) -> f64 {
        self.frame().mesh_torque_nm(&self.u)
    }

    /// Motor torque on M1 (N m).
    pub fn motor_torque_nm(&self) -> f64 {
        self.frame().motor_torque_nm(&self.u)
    }

    pub(super) fn tooth_at(&self, theta2: f64) -> u32 {
        self.frame().tooth_at(theta2)
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

/// Everything a sample needs besides the state: mode, set rotation and gear data.
pub(super) struct SampleFrame<'a> {
    mc: &'a ModelConstants,
    mode: Mode,
    speed_rad_s: f64,
    step_s: f64,
    segment_phase_rad: f64,
    segment_start: u64,
    tooth_pitch_rad: f64,
    teeth: i64,
}

impl SampleFrame<'_> {
    /// Set rotation φ (rad) at internal step `step`.
    #[inline]
    pub(super) fn phase_rad(&self, step: u64) -> f64 {
        let elapsed = (step - self.segment_start) as f64 * self.step_s;
        self.segment_phase_rad + self.speed_rad_s * elapsed
    }

    /// The true signals of state `u` at internal step `step`.
    #[inline]
    pub(super) fn sample(&self, u: &[f64; Layout::MAX_LEN], step: u64) -> Sample {
        let phase = self.phase_rad(step);
        Sample {
            time_s: step as f64 * self.step_s,
            angle_rad: std::array::from_fn(|i| phase + u[X0 + i]),
            speed_rad_s: std::array::from_fn(|i| self.speed_rad_s + u[V0 + i]),
            shaft_torque_nm: self.mc.shaft_torques_nm(u),
            mesh_torque_nm: self.mesh_torque_nm(u),
            motor_torque_nm: self.motor_torque_nm(u),
            contact: self.mode.mesh.contact_code(),
            tooth: self.tooth_at(phase + u[X0 + 1]),
        }
    }

    /// Mesh torque F_XT (N m): K δ + C δ' of the engaged flank, signed by flank.
    #[inline]
    fn mesh_torque_nm(&self, u: &[f64; Layout::MAX_LEN]) -> f64 {
        let (k, c) = self.mc.mesh_spring(self.mode.pairs);
        let push = |(overlap, rate): (f64, f64)| k * overlap + c * rate;
        match self.mode.mesh {
            MeshMode::Drive => push(flank_gap(self.mc, self.speed_rad_s, u, Flank::Drive)),
            MeshMode::Back => -push(flank_gap(self.mc, self.speed_rad_s, u, Flank::Back)),
            _ => 0.0,
        }
    }

    /// Motor torque on M1 (N m).
    #[inline]
    fn motor_torque_nm(&self, u: &[f64; Layout::MAX_LEN]) -> f64 {
        match self.mode.motor {
            MotorMode::Linear => self.mc.controller_torque_nm(u),
            MotorMode::LimitHigh => self.mc.torque_limit_nm,
            MotorMode::LimitLow => -self.mc.torque_limit_nm,
        }
    }

    /// Tooth of the driving gear in mesh at its angle `theta2` (rad), 0..teeth.
    #[inline]
    pub(super) fn tooth_at(&self, theta2: f64) -> u32 {
        ((theta2 / self.tooth_pitch_rad).floor() as i64).rem_euclid(self.teeth) as u32
    }
}

/// Overlap of `flank` (rad, > 0 when the teeth overlap) and its rate (rad/s) in state `u`,
/// whose harmonic states hold cos φ and sin φ of that instant.
#[inline]
pub(super) fn flank_gap(
    mc: &ModelConstants,
    speed_rad_s: f64,
    u: &[f64; Layout::MAX_LEN],
    flank: Flank,
) -> (f64, f64) {
    let b0 = mc.half_backlash_rad;
    let c1 = mc.backlash_variation;
    let b = b0 * (1.0 - c1 * u[REV]);
    let b_rate = b0 * c1 * speed_rad_s * u[REV + 1];
    let d = u[X0 + 2] - u[X0 + 1];
    let d_rate = u[V0 + 2] - u[V0 + 1];
    match flank {
        Flank::Drive => (-d - b, -d_rate - b_rate),
        Flank::Back => (d - b, d_rate - b_rate),
    }
}
