//! Taking samples: the true signals at the output rate, and the bounds that stop a blown-up run.

use crate::error::RigError;
use crate::layout::{N_MECH, V0, VF, X0, Z};
use crate::mode::{MeshMode, MotorMode};
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
            let mut taken = 0;
            let mut result = Ok(());
            while taken < n {
                result = self.take_sample(&mut chunk[taken]);
                if result.is_err() {
                    break;
                }
                taken += 1;
            }
            out.extend_from_samples(&chunk[..taken]);
            result?;
            done += n;
        }
        Ok(())
    }

    /// Stores the sample now in `slot`, then advances one output period.
    #[inline]
    pub(super) fn take_sample(&mut self, slot: &mut Sample) -> Result<(), RigError> {
        if !self.within_bounds() {
            return Err(self.blow_up());
        }
        *slot = self.sample();
        for _ in 0..self.substeps {
            self.advance_step()?;
        }
        Ok(())
    }

    /// Advances `samples` output samples without recording them.
    pub fn skip(&mut self, samples: usize) -> Result<(), RigError> {
        for _ in 0..samples {
            if !self.within_bounds() {
                return Err(self.blow_up());
            }
            for _ in 0..self.substeps {
                self.advance_step()?;
            }
        }
        Ok(())
    }

    /// The true signals now.
    pub fn sample(&self) -> Sample {
        let u = &self.u;
        let phase = self.phase_rad(0.0);
        let omega = self.segment.set.speed_rad_s();
        Sample {
            time_s: self.time_at(0.0),
            angle_rad: std::array::from_fn(|i| phase + u[X0 + i]),
            speed_rad_s: std::array::from_fn(|i| omega + u[V0 + i]),
            shaft_torque_nm: self.mc.shaft_torques_nm(u),
            mesh_torque_nm: self.mesh_torque_nm(),
            motor_torque_nm: self.motor_torque_nm(),
            contact: self.mode.mesh.contact_code(),
            tooth: self.tooth_at(phase + u[X0 + 1]),
        }
    }

    /// Mesh torque F_XT on the driven gear (N m).
    pub fn mesh_torque_nm(&self) -> f64 {
        let (k, c) = self.mc.mesh_spring(self.mode.pairs);
        let push = |(overlap, rate): (f64, f64)| k * overlap + c * rate;
        match self.mode.mesh {
            MeshMode::Drive => push(self.gap(Flank::Drive)),
            MeshMode::Back => -push(self.gap(Flank::Back)),
            _ => 0.0,
        }
    }

    /// Motor torque on M1 (N m).
    pub fn motor_torque_nm(&self) -> f64 {
        match self.mode.motor {
            MotorMode::Linear => self.mc.controller_torque_nm(&self.u),
            MotorMode::LimitHigh => self.mc.torque_limit_nm,
            MotorMode::LimitLow => -self.mc.torque_limit_nm,
        }
    }

    pub(super) fn tooth_at(&self, theta2: f64) -> u32 {
        let teeth = i64::from(self.params.teeth);
        ((theta2 / self.geometry.tooth_pitch_rad).floor() as i64).rem_euclid(teeth) as u32
    }

    /// Whether the state is finite, every twist within 1 rad and every relative speed within 10⁴ rad/s.
    #[inline]
    pub(super) fn within_bounds(&self) -> bool {
        let u = &self.u;
        let twist_ok = (0..4).all(|i| (u[X0 + i] - u[X0 + i + 1]).abs() <= TWIST_LIMIT_RAD);
        let speed_ok = (0..5).all(|i| u[V0 + i].abs() <= SPEED_LIMIT_RAD_S);
        twist_ok && speed_ok && u[VF].is_finite() && u[Z].is_finite()
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
