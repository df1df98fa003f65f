//! The AC tacho-generator (Crompton Parkinson: 40 V per 1000 rev/min) and the digital
//! voltmeter that reads it (Schlumberger A200).

use crate::block::Block;
use crate::error::{InstrumentError, require_positive};
use crate::phase::wrapped;

/// The rig's tacho: 40 V rms per 1000 rev/min (V rms per rev/min).
pub const CROMPTON_PARKINSON_V_PER_RPM: f64 = 0.04;

/// An AC tacho-generator on the motor shaft: input the shaft speed (rad/s), output its
/// terminal voltage (V). Amplitude and frequency are proportional to speed:
/// v = √2 · k · n · sin ψ · (1 + r sin θ), n in rev/min, ψ' = (poles/2)·ω the electrical
/// phase, θ = 2ψ/poles the shaft angle (r: once-per-revolution ripple).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Tacho {
    /// RMS volts per rev/min (the rig's: 40 V per 1000 rev/min = 0.04).
    pub volts_rms_per_rpm: f64,
    /// Magnet poles (2 gives one electrical cycle per revolution).
    pub poles: u32,
    /// Relative once-per-revolution amplitude ripple.
    pub ripple: f64,
    step_s: f64,
    phase_rad: f64,
}

impl Tacho {
    /// The rig's tacho at stream rate `rate_hz`: 0.04 V rms per rev/min, 4 poles (thesis
    /// silent), no ripple.
    pub fn crompton_parkinson(rate_hz: f64) -> Result<Self, InstrumentError> {
        require_positive("tacho", "sample rate", rate_hz)?;
        Ok(Self {
            volts_rms_per_rpm: CROMPTON_PARKINSON_V_PER_RPM,
            poles: 4,
            ripple: 0.0,
            step_s: 1.0 / rate_hz,
            phase_rad: 0.0,
        })
    }
}

impl Block for Tacho {
    fn reset(&mut self) {
        self.phase_rad = 0.0;
    }

    fn process(&mut self, input: &[f64], output: &mut [f64]) {
        let pairs = f64::from(self.poles) / 2.0;
        for (y, &speed_rad_s) in output.iter_mut().zip(input) {
            let rpm = speed_rad_s * 30.0 / std::f64::consts::PI;
            // Without ripple the factor is exactly 1: its sine is not taken.
            let ripple = if self.ripple == 0.0 {
                1.0
            } else {
                1.0 + self.ripple * (self.phase_rad / pairs).sin()
            };
            *y = std::f64::consts::SQRT_2
                * self.volts_rms_per_rpm
                * rpm
                * self.phase_rad.sin()
                * ripple;
            self.phase_rad = wrapped(
                self.phase_rad + pairs * speed_rad_s * self.step_s,
                std::f64::consts::TAU * pairs,
            );
        }
    }
}

/// A digital voltmeter on AC: a true-RMS converter (v² through two first-order stages of
/// time constant τ, then the square root), whose output the display samples at the end of
/// each gate interval, rounds to its resolution and holds (0 before the first gate).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct DigitalVoltmeter {
    gate_samples: usize,
    resolution_v: f64,
    alpha: f64,
    stages: [f64; 2],
    count: usize,
    shown_v: f64,
}

impl DigitalVoltmeter {
    /// A meter at `rate_hz` with gate `gate_s`, converter time constant `tau_s` and display
    /// `resolution_v` (thesis silent; the rig's A200 taken as 0.1 V on its 200 V range, a
    /// 1 s gate and τ = 0.3 s).
    pub fn new(
        rate_hz: f64,
        gate_s: f64,
        tau_s: f64,
        resolution_v: f64,
    ) -> Result<Self, InstrumentError> {
        let gate_samples = (rate_hz * gate_s).round();
        let valid = gate_samples >= 1.0
            && gate_samples.is_finite()
            && tau_s.is_finite()
            && tau_s > 0.0
            && resolution_v.is_finite()
            && resolution_v > 0.0;
        if !valid {
            return Err(InstrumentError::setting(
                "digital voltmeter",
                "gate, time constant or resolution",
                format!("{gate_s} s, {tau_s} s, {resolution_v} V"),
                "a gate of at least one sample, a time constant > 0 and a resolution > 0",
            ));
        }
        Ok(Self {
            gate_samples: gate_samples as usize,
            resolution_v,
            alpha: 1.0 - (-1.0 / (rate_hz * tau_s)).exp(),
            stages: [0.0; 2],
            count: 0,
            shown_v: 0.0,
        })
    }

    /// What the display shows now (V).
    pub fn shown_v(&self) -> f64 {
        self.shown_v
    }
}

impl Block for DigitalVoltmeter {
    fn reset(&mut self) {
        self.stages = [0.0; 2];
        self.count = 0;
        self.shown_v = 0.0;
    }

    fn process(&mut self, input: &[f64], output: &mut [f64]) {
        for (y, &v) in output.iter_mut().zip(input) {
            self.stages[0] += self.alpha * (v * v - self.stages[0]);
            self.stages[1] += self.alpha * (self.stages[0] - self.stages[1]);
            self.count += 1;
            if self.count == self.gate_samples {
                self.shown_v = (self.stages[1].max(0.0).sqrt() / self.resolution_v).round()
                    * self.resolution_v;
                self.count = 0;
            }
            *y = self.shown_v;
        }
    }
}
