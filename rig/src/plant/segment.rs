//! The plant's set points over time: a stretch (segment) of set points begun at a sample,
//! speed and load ramping exactly to the schedule's next knot, the oscillating load and
//! the meshes' harmonic pairs set again from the exact rotation, the motor's command held
//! at its limit after a jump; and set points changed while the plant runs.

use std::f64::consts::PI;

use crate::error::RigError;
use crate::mode::MotorMode;
use crate::schedule::SetPoints;

use super::model::SegmentRates;
use super::network_plant::{NetworkPlant, OSCILLATING_HOLD_S};

/// Relative difference of a set point from the one held below which it is the same set
/// point: a co-simulation master interpolating between two equal rows of its input table
/// (FMPy's `w0 v0 + (1 − w0) v1`) lands an ulp or two off the value, and a changed segment
/// would restart the exact stepping for nothing (1e-12 of 1300 rev/min is 1.3e-9 rev/min).
const SET_POINT_ROUNDING: f64 = 1e-12;

/// Whether `a` and `b` are the same set points to within [`SET_POINT_ROUNDING`].
fn same_set_points(a: &SetPoints, b: &SetPoints) -> bool {
    let close = |x: f64, y: f64| (x - y).abs() <= SET_POINT_ROUNDING * x.abs().max(y.abs());
    close(a.speed_rpm, b.speed_rpm)
        && close(a.load_nm, b.load_nm)
        && close(a.oscillating_load_nm, b.oscillating_load_nm)
        && close(a.oscillating_load_hz, b.oscillating_load_hz)
}

impl NetworkPlant {
    /// The set points now (during a ramp, the ramp's value at this sample).
    pub fn set_points(&self) -> SetPoints {
        self.schedule.held_over(self.time_s(), 0.0)
    }

    /// From the current sample on, holds `set` (a knob turned while the rig runs, an
    /// FMU's inputs held over a communication step); the set points it had scheduled
    /// after now are dropped. Holding the set points already held (to within 1e-12 of
    /// each, a master's rounding), with nothing scheduled after now, changes nothing: the
    /// stretch under way goes on, so a master that sets its inputs every step gets the
    /// same motion however it cuts the steps.
    pub fn hold_set_points(&mut self, set: SetPoints) -> Result<(), RigError> {
        let values = [
            set.speed_rpm,
            set.load_nm,
            set.oscillating_load_nm,
            set.oscillating_load_hz,
        ];
        if values.iter().any(|v| !v.is_finite()) {
            return Err(RigError::Schedule(format!(
                "set points must be finite, got {values:?}"
            )));
        }
        let ceiling = self.ceiling;
        if set.speed_rpm > ceiling.speed_rpm {
            return Err(RigError::Schedule(format!(
                "set speed {} rev/min: this plant was built for at most {} rev/min (its step is sized for that speed)",
                set.speed_rpm, ceiling.speed_rpm
            )));
        }
        if set.oscillating_load_hz > ceiling.oscillating_load_hz {
            return Err(RigError::Schedule(format!(
                "oscillating load at {} Hz: this plant was built for at most {} Hz",
                set.oscillating_load_hz, ceiling.oscillating_load_hz
            )));
        }
        let now = self.time_s();
        if self.schedule.next_knot_after(now).is_none() && same_set_points(&self.set_points(), &set)
        {
            return Ok(());
        }
        let mut schedule = self.schedule.clone();
        schedule.hold_from(now, set);
        schedule.validate()?;
        self.schedule = schedule;
        self.segment_end = Some(self.sample);
        Ok(())
    }

    /// Starts a stretch of set points at the current sample: speed and load ramp exactly
    /// to the next knot, the oscillating load holds (at most 0.1 s while it ramps).
    pub(super) fn begin_segment(&mut self) {
        let t = self.time_s();
        let knot = self.schedule.next_knot_after(t);
        let s = &self.schedule;
        // Held in short stretches: what enters the matrix while it ramps (the oscillating
        // load's frequency, the harmonics' speed, the brake characteristic's slope).
        let harmonics_turn = self.model.layout.has_harmonics();
        let characteristic = self
            .model
            .brake
            .as_ref()
            .is_some_and(|b| b.critical_rad_s > 0.0);
        let oscillating_ramps = s.oscillating_load_nm.ramping_at(t)
            || s.oscillating_load_hz.ramping_at(t)
            || (harmonics_turn && s.speed_rpm.ramping_at(t))
            || (characteristic && (s.speed_rpm.ramping_at(t) || s.load_nm.ramping_at(t)));
        let end_s = match (knot, oscillating_ramps) {
            (Some(k), true) => Some(k.min(t + OSCILLATING_HOLD_S)),
            (None, true) => Some(t + OSCILLATING_HOLD_S),
            (k, false) => k,
        };
        let end =
            end_s.map(|e| ((e / self.output_step_s - 1e-9).ceil() as u64).max(self.sample + 1));
        let span_s = end.map_or(0.0, |e| e as f64 * self.output_step_s - t);
        let ramp = |track: &crate::schedule::Track, scale: f64| {
            let now = track.value_at(t) * scale;
            let rate = match end_s {
                Some(e) if span_s > 0.0 && track.ramping_at(t) => {
                    (track.value_at(e) * scale - now) / span_s
                }
                _ => 0.0,
            };
            (now, rate)
        };
        let (speed, speed_rate) = ramp(&s.speed_rpm, PI / 30.0);
        let (load, load_rate) = ramp(&s.load_nm, 1.0);
        let held = s.held_over(t, end_s.map_or(0.0, |e| e - t));
        let l = &self.model.layout;
        self.u[l.set_speed()] = speed;
        self.u[l.set_rate()] = speed_rate;
        self.u[l.load()] = load;
        self.u[l.load_rate()] = load_rate;
        let (c, si) = (self.u[l.oscillating()], self.u[l.oscillating() + 1]);
        let phase = if c == 0.0 && si == 0.0 {
            0.0
        } else {
            si.atan2(c)
        };
        self.u[l.oscillating()] = held.oscillating_load_nm * phase.cos();
        self.u[l.oscillating() + 1] = held.oscillating_load_nm * phase.sin();
        let harmonic_speed = if self.model.layout.has_harmonics() {
            held.speed_rad_s()
        } else {
            0.0
        };
        self.harmonic_speed_rad_s = harmonic_speed;
        let rates = SegmentRates {
            harmonic_rad_s: harmonic_speed,
            oscillating_rad_s: held.oscillating_load_rad_s(),
            brake_characteristic_nms_per_rad: self.model.brake.as_ref().map_or(0.0, |b| {
                b.characteristic_slope(held.speed_rad_s(), held.load_nm)
            }),
        };
        if let Some(cache) = self.cache.as_mut() {
            cache.set_rates(rates);
        }
        self.resync_harmonics();
        self.segment_end = end;
        self.edge.clear();
        self.stride.drop_stride();
        self.clamp_motor();
    }

    /// Sets each harmonic pair from the exact share of the set rotation Φ of its mesh's
    /// driver.
    pub(super) fn resync_harmonics(&mut self) {
        let l = &self.model.layout;
        let phase = self.u[l.phase()];
        for (index, mesh, harmonic) in l.harmonics() {
            let angle = harmonic * self.model.meshes[mesh].share * phase;
            self.u[index] = angle.cos();
            self.u[index + 1] = angle.sin();
        }
    }

    /// After a jump of the set speed: a command beyond a limit is held at it.
    pub(super) fn clamp_motor(&mut self) {
        let Some(m) = &self.model.motor else {
            return;
        };
        let Some(limit) = m.limit_nm else {
            return;
        };
        let command = self.model.controller_nm(&self.u);
        if self.mode.motor == MotorMode::Linear && command.abs() > limit {
            let l = &self.model.layout;
            let held = limit.copysign(command);
            self.u[l.integral()] += (held - command) / m.ki_nm_per_rad;
            self.mode.motor = if command > 0.0 {
                MotorMode::LimitHigh
            } else {
                MotorMode::LimitLow
            };
        }
    }
}
