//! The storage oscilloscope (Tektronix 564 with 2B67 time base): volts/div, time/div over
//! ten divisions, a trigger level and slope, repeated or single sweeps, and the stored
//! trace as data. The stream passes through unchanged.

use crate::block::Block;
use crate::error::InstrumentError;

/// Trigger slope.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Slope {
    /// Trigger on a rising crossing of the level.
    Rising,
    /// Trigger on a falling crossing.
    Falling,
}

/// Sweep mode.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum SweepMode {
    /// Sweep on every trigger; the stored trace is the latest complete one.
    Repeat,
    /// Sweep once on the first trigger and hold it.
    Single,
    /// Sweep on every trigger, and free-run when none comes: a sweep starts by itself
    /// once the scope has waited a sweep's length without a trigger (a real scope's AUTO,
    /// which shows a flat or slow signal instead of a blank screen).
    Auto,
}

/// Scope settings.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ScopeSettings {
    /// Vertical scale (V per division).
    pub volts_per_div: f64,
    /// Horizontal scale (s per division, ten divisions).
    pub seconds_per_div: f64,
    /// Trigger level (V).
    pub trigger_v: f64,
    /// Trigger slope.
    pub slope: Slope,
    /// Sweep mode.
    pub mode: SweepMode,
}

/// Vertical half-height of the screen (divisions); the trace clips beyond it.
pub const HALF_HEIGHT_DIV: f64 = 4.0;

/// The oscilloscope.
#[derive(Clone, Debug, PartialEq)]
pub struct Scope {
    settings: ScopeSettings,
    sweep_samples: usize,
    step_s: f64,
    previous: Option<f64>,
    sweeping: Vec<f64>,
    armed: bool,
    stored: Option<Vec<f64>>,
    sweeps: u64,
    /// Samples seen since the last sweep ended without a trigger (for AUTO's free run).
    waited: usize,
}

/// Slowest time base (s/div): the Tektronix 2B67's 5 s/div.
pub const SLOWEST_S_PER_DIV: f64 = 5.0;

/// Most samples one stored sweep may hold (16 Mi samples, 128 MiB).
pub const MAX_SWEEP_SAMPLES: f64 = 16_777_216.0;

impl Scope {
    /// A scope on a stream at `rate_hz`: V/div finite and > 0, s/div in (0, 5] (the
    /// 2B67's slowest), a sweep of 2 to 16 Mi samples.
    pub fn new(settings: ScopeSettings, rate_hz: f64) -> Result<Self, InstrumentError> {
        let valid = settings.volts_per_div.is_finite()
            && settings.volts_per_div > 0.0
            && settings.seconds_per_div > 0.0
            && settings.seconds_per_div <= SLOWEST_S_PER_DIV
            && rate_hz > 0.0
            && settings.trigger_v.is_finite();
        let sweep = (10.0 * settings.seconds_per_div * rate_hz).round();
        if !(valid && sweep.is_finite() && (2.0..=MAX_SWEEP_SAMPLES).contains(&sweep)) {
            return Err(InstrumentError::setting(
                "oscilloscope",
                "scales",
                format!(
                    "{} V/div, {} s/div, trigger {} V, a sweep of {sweep} samples at {rate_hz} Hz",
                    settings.volts_per_div, settings.seconds_per_div, settings.trigger_v
                ),
                "V/div > 0, s/div in (0, 5], a sweep of 2 to 16 Mi samples",
            ));
        }
        Ok(Self {
            settings,
            sweep_samples: sweep as usize,
            step_s: 1.0 / rate_hz,
            previous: None,
            sweeping: Vec::with_capacity(sweep as usize),
            armed: true,
            stored: None,
            sweeps: 0,
            waited: 0,
        })
    }

    /// Sweeps completed and stored since the scope was made.
    pub fn sweeps(&self) -> u64 {
        self.sweeps
    }

    /// Its settings.
    pub fn settings(&self) -> ScopeSettings {
        self.settings
    }

    /// The stored sweep as (time from the trigger in s, vertical position in divisions,
    /// clipped to ±4), or `None` before the first complete sweep.
    pub fn trace(&self) -> Option<Vec<(f64, f64)>> {
        let v = self.settings.volts_per_div;
        self.stored.as_ref().map(|trace| {
            trace
                .iter()
                .enumerate()
                .map(|(k, &x)| {
                    (
                        k as f64 * self.step_s,
                        (x / v).clamp(-HALF_HEIGHT_DIV, HALF_HEIGHT_DIV),
                    )
                })
                .collect()
        })
    }

    fn triggers(&self, previous: f64, now: f64) -> bool {
        let level = self.settings.trigger_v;
        match self.settings.slope {
            Slope::Rising => previous < level && now >= level,
            Slope::Falling => previous > level && now <= level,
        }
    }
}

impl Block for Scope {
    fn reset(&mut self) {
        self.previous = None;
        self.sweeping.clear();
        self.armed = true;
        self.stored = None;
        self.waited = 0;
    }

    fn process(&mut self, input: &[f64], output: &mut [f64]) {
        output.copy_from_slice(input);
        for &x in input {
            let triggered = self.armed && self.previous.is_some_and(|p| self.triggers(p, x));
            let free_run = self.settings.mode == SweepMode::Auto
                && self.armed
                && self.waited >= self.sweep_samples;
            if !self.sweeping.is_empty() || triggered || free_run {
                self.sweeping.push(x);
                self.waited = 0;
            } else {
                self.waited += 1;
            }
            if self.sweeping.len() == self.sweep_samples {
                self.stored = Some(std::mem::take(&mut self.sweeping));
                self.sweeps += 1;
                self.sweeping.reserve(self.sweep_samples);
                self.armed = self.settings.mode != SweepMode::Single;
            }
            self.previous = Some(x);
        }
    }
}
