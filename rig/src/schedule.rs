//! The operating schedule: speed, load and oscillating load over time, as an
//! experimenter turns the knobs (holds, steps, ramps).

use crate::error::RigError;

/// A set point over time: piecewise linear between knots, held before the first and
/// after the last. Two knots at the same time make a step.
#[derive(Clone, Debug, PartialEq)]
pub struct Track {
    knots: Vec<(f64, f64)>,
}

impl Track {
    /// A value held for ever.
    pub fn hold(value: f64) -> Self {
        Self {
            knots: vec![(0.0, value)],
        }
    }

    /// Adds a step to `value` at `t_s`.
    pub fn step_to(mut self, t_s: f64, value: f64) -> Self {
        let held = self.value_at(t_s);
        self.knots.push((t_s, held));
        self.knots.push((t_s, value));
        self
    }

    /// Drops the knots after `t_s` and steps to `value` there.
    pub fn hold_from(&mut self, t_s: f64, value: f64) {
        let held = self.value_at(t_s);
        self.knots.retain(|&(t, _)| t <= t_s);
        self.knots.push((t_s, held));
        self.knots.push((t_s, value));
    }

    /// Adds a ramp from the value held at `from_s` to `value` at `to_s`.
    pub fn ramp_to(mut self, from_s: f64, to_s: f64, value: f64) -> Self {
        let held = self.value_at(from_s);
        self.knots.push((from_s, held));
        self.knots.push((to_s, value));
        self
    }

    /// The set value at `t_s` (after a step at exactly `t_s`, the new value).
    pub fn value_at(&self, t_s: f64) -> f64 {
        let after = self.knots.partition_point(|&(t, _)| t <= t_s);
        match (
            after.checked_sub(1).map(|i| self.knots[i]),
            self.knots.get(after),
        ) {
            (None, Some(&(_, v))) => v,
            (Some((_, v)), None) => v,
            (Some((t0, v0)), Some(&(t1, v1))) => v0 + (v1 - v0) * (t_s - t0) / (t1 - t0),
            (None, None) => 0.0,
        }
    }

    /// Whether the value changes continuously just after `t_s` (a ramp is under way).
    pub fn ramping_at(&self, t_s: f64) -> bool {
        let after = self.knots.partition_point(|&(t, _)| t <= t_s);
        match (
            after.checked_sub(1).map(|i| self.knots[i]),
            self.knots.get(after),
        ) {
            (Some((_, v0)), Some(&(_, v1))) => v0 != v1,
            _ => false,
        }
    }

    /// The first knot time strictly after `t_s`.
    pub fn next_knot_after(&self, t_s: f64) -> Option<f64> {
        self.knots.iter().map(|&(t, _)| t).find(|&t| t > t_s)
    }

    /// Smallest and largest value the track takes.
    pub fn range(&self) -> (f64, f64) {
        let values = self.knots.iter().map(|&(_, v)| v);
        (
            values.clone().fold(f64::INFINITY, f64::min),
            values.fold(f64::NEG_INFINITY, f64::max),
        )
    }
}

/// Speed and load set points over a run.
#[derive(Clone, Debug, PartialEq)]
pub struct Schedule {
    /// Motor speed set point (rev/min).
    pub speed_rpm: Track,
    /// Brake load torque (N m), positive resisting the rotation.
    pub load_nm: Track,
    /// Amplitude of the oscillating load from the function generator (N m).
    pub oscillating_load_nm: Track,
    /// Frequency of the oscillating load (Hz).
    pub oscillating_load_hz: Track,
}

/// Highest speed set point accepted (rev/min).
pub const MAX_SPEED_RPM: f64 = 10_000.0;

impl Schedule {
    /// A constant speed and load, no oscillating load.
    pub fn constant(speed_rpm: f64, load_nm: f64) -> Self {
        Self {
            speed_rpm: Track::hold(speed_rpm),
            load_nm: Track::hold(load_nm),
            oscillating_load_nm: Track::hold(0.0),
            oscillating_load_hz: Track::hold(0.0),
        }
    }

    /// Checks the ranges: speed in [0, 10000] rev/min (0 or a normal number: a subnormal
    /// speed overflows the plant's phase arithmetic), oscillating amplitude and frequency ≥ 0.
    pub fn validate(&self) -> Result<(), RigError> {
        let (low, high) = self.speed_rpm.range();
        if low < 0.0 || high > MAX_SPEED_RPM || low.is_subnormal() {
            return Err(RigError::Schedule(format!(
                "speed set point must lie in [0, {MAX_SPEED_RPM}] rev/min, got {low}..{high}"
            )));
        }
        if self.oscillating_load_nm.range().0 < 0.0 || self.oscillating_load_hz.range().0 < 0.0 {
            return Err(RigError::Schedule(
                "oscillating load amplitude and frequency must be ≥ 0".into(),
            ));
        }
        Ok(())
    }

    /// From `t_s` on, holds `set` (the knots after `t_s` are dropped): a knob turned
    /// while the rig runs.
    pub fn hold_from(&mut self, t_s: f64, set: SetPoints) {
        let tracks = [
            (&mut self.speed_rpm, set.speed_rpm),
            (&mut self.load_nm, set.load_nm),
            (&mut self.oscillating_load_nm, set.oscillating_load_nm),
            (&mut self.oscillating_load_hz, set.oscillating_load_hz),
        ];
        for (track, value) in tracks {
            track.hold_from(t_s, value);
        }
    }

    fn tracks(&self) -> [&Track; 4] {
        [
            &self.speed_rpm,
            &self.load_nm,
            &self.oscillating_load_nm,
            &self.oscillating_load_hz,
        ]
    }

    /// Whether any set point ramps just after `t_s`.
    pub fn ramping_at(&self, t_s: f64) -> bool {
        self.tracks().iter().any(|track| track.ramping_at(t_s))
    }

    /// The first knot of any track strictly after `t_s`.
    pub fn next_knot_after(&self, t_s: f64) -> Option<f64> {
        self.tracks()
            .iter()
            .filter_map(|track| track.next_knot_after(t_s))
            .reduce(f64::min)
    }

    /// The set points held over [t_s, t_s + span_s]: at the middle of the span while a
    /// ramp runs (a staircase centred on the ramp), else the value at `t_s`.
    pub fn held_over(&self, t_s: f64, span_s: f64) -> SetPoints {
        let at = if self.ramping_at(t_s) {
            t_s + 0.5 * span_s
        } else {
            t_s
        };
        SetPoints {
            speed_rpm: self.speed_rpm.value_at(at),
            load_nm: self.load_nm.value_at(at),
            oscillating_load_nm: self.oscillating_load_nm.value_at(at),
            oscillating_load_hz: self.oscillating_load_hz.value_at(at),
        }
    }
}

/// The highest set points live commands may bring (`NetworkPlant::live`).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct LiveCeiling {
    /// Highest speed set point (rev/min).
    pub speed_rpm: f64,
    /// Highest oscillating-load frequency (Hz); 0 allows no oscillating load.
    pub oscillating_load_hz: f64,
}

/// The set points at one instant.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SetPoints {
    /// Motor speed set point (rev/min).
    pub speed_rpm: f64,
    /// Brake load (N m).
    pub load_nm: f64,
    /// Oscillating load amplitude (N m).
    pub oscillating_load_nm: f64,
    /// Oscillating load frequency (Hz).
    pub oscillating_load_hz: f64,
}

impl SetPoints {
    /// Set speed Ω (rad/s).
    pub fn speed_rad_s(&self) -> f64 {
        self.speed_rpm * std::f64::consts::PI / 30.0
    }

    /// Oscillating load angular frequency (rad/s).
    pub fn oscillating_load_rad_s(&self) -> f64 {
        2.0 * std::f64::consts::PI * self.oscillating_load_hz
    }
}
