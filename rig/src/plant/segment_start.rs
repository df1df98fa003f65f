//! Set-point segments: starting one, the phase of the set rotation, and the harmonic states.

use crate::error::RigError;
use crate::layout::{LOAD, Layout, REV, V0, VF, X0};
use crate::model::Frequencies;
use crate::schedule::SetPoints;

use super::segment::Segment;
use super::state::Plant;

impl Plant {
    /// Holds `set` from the current sample on, as a knob turned while the rig runs (the
    /// schedule's later knots are dropped); a new stretch of set points starts at the next
    /// internal step, exactly as at a knot of the schedule. Refused, with nothing changed,
    /// outside the schedule's ranges or above the ceiling the plant was built for.
    pub fn set_points_from_now(&mut self, set: SetPoints) -> Result<(), RigError> {
        let c = self.ceiling;
        if set.speed_rpm > c.speed_rpm || set.oscillating_load_hz > c.oscillating_load_hz {
            return Err(RigError::Schedule(format!(
                "{} rev/min, {} Hz: this plant was built for at most {} rev/min and {} Hz of oscillating load",
                set.speed_rpm, set.oscillating_load_hz, c.speed_rpm, c.oscillating_load_hz
            )));
        }
        if set.oscillating_load_nm > 0.0 && self.layout.osc.is_none() {
            return Err(RigError::Schedule(
                "this plant was built without an oscillating load".into(),
            ));
        }
        let mut schedule = self.schedule.clone();
        schedule.hold_from(self.time_at(0.0), set);
        schedule.validate()?;
        self.schedule = schedule;
        self.segment.end_step = Some(self.step_index);
        Ok(())
    }

    /// Starts a new stretch of constant set points at the current step.
    #[inline(never)]
    pub(super) fn begin_segment(&mut self) {
        let t = self.time_at(0.0);
        let next_knot = self.schedule.next_knot_after(t);
        let ramping = self.schedule.ramping_at(t);
        let end = match (ramping, next_knot) {
            (true, Some(knot)) => Some(knot.min(t + self.setpoint_update_s)),
            (true, None) => Some(t + self.setpoint_update_s),
            (false, knot) => knot,
        };
        let set = self.schedule.held_over(t, end.map_or(0.0, |e| e - t));
        let old = self.segment;
        let delta_speed = set.speed_rad_s() - old.set.speed_rad_s();
        for v in &mut self.u[V0..V0 + 5] {
            *v -= delta_speed;
        }
        self.u[VF] -= delta_speed;
        if delta_speed != 0.0 {
            self.clamp_controller();
        }
        self.u[LOAD] = set.load_nm + self.params.brake_drag_nm;
        let frequencies = Frequencies {
            rotation_rad_s: set.speed_rad_s(),
            oscillating_load_rad_s: set.oscillating_load_rad_s(),
            brake_characteristic_nms_per_rad: self
                .mc
                .brake_characteristic_slope(set.speed_rad_s(), self.u[LOAD]),
        };
        self.segment = Segment {
            start_step: self.step_index,
            end_step: end
                .map(|e| ((e / self.step_s - 1e-6).ceil() as u64).max(self.step_index + 1)),
            phase_rad: self.phase_rad(0.0),
            osc_phase_rad: self.osc_phase_rad(0.0),
            set,
        };
        if frequencies != self.cache.frequencies() || self.step_index == 0 {
            self.cache.set_frequencies(frequencies);
        }
        self.resync_harmonics(0.0);
    }

    /// Sets the harmonic states from the exact phases at `tau_s` into the step.
    #[inline(never)]
    pub(super) fn resync_harmonics(&mut self, tau_s: f64) {
        self.edge = None;
        let phase = self.phase_rad(tau_s);
        self.u[REV] = phase.cos();
        self.u[REV + 1] = phase.sin();
        if let Some(rev2) = self.layout.rev2 {
            self.u[rev2] = (2.0 * phase).cos();
            self.u[rev2 + 1] = (2.0 * phase).sin();
        }
        if let Some(mesh) = self.layout.mesh {
            let z_phase = self.mc.teeth * phase;
            self.u[mesh] = z_phase.cos();
            self.u[mesh + 1] = z_phase.sin();
        }
        if let Some(osc) = self.layout.osc {
            let psi = self.osc_phase_rad(tau_s);
            let amplitude = self.segment.set.oscillating_load_nm;
            self.u[osc] = amplitude * psi.cos();
            self.u[osc + 1] = amplitude * psi.sin();
        }
    }

    /// Time of the current step's start plus `tau_s` (s).
    pub(super) fn time_at(&self, tau_s: f64) -> f64 {
        self.step_index as f64 * self.step_s + tau_s
    }

    /// Set rotation φ (rad) at `tau_s` into the current step.
    pub(super) fn phase_rad(&self, tau_s: f64) -> f64 {
        let elapsed = (self.step_index - self.segment.start_step) as f64 * self.step_s + tau_s;
        self.segment.phase_rad + self.segment.set.speed_rad_s() * elapsed
    }

    pub(super) fn osc_phase_rad(&self, tau_s: f64) -> f64 {
        let elapsed = (self.step_index - self.segment.start_step) as f64 * self.step_s + tau_s;
        self.segment.osc_phase_rad + self.segment.set.oscillating_load_rad_s() * elapsed
    }

    /// Absolute angle of the driving gear θ2 = φ + X2 (rad) at `tau_s` into the step.
    pub(super) fn driving_gear_angle_rad(&self, tau_s: f64) -> f64 {
        self.phase_rad(tau_s) + self.u[X0 + 1]
    }
}

/// Turns each harmonic pair of `u` by one step: (index of the cos state, cos ωh, sin ωh).
pub(super) fn rotate(u: &mut [f64; Layout::MAX_LEN], rotations: &[(usize, f64, f64)]) {
    for &(index, cos, sin) in rotations {
        let (c, s) = (u[index], u[index + 1]);
        u[index] = c * cos - s * sin;
        u[index + 1] = s * cos + c * sin;
    }
}
