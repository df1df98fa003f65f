//! The function generator (Feedback TWG 300) and the eddy-current brake (JAY-JAY DM3/50):
//! an AC signal of set frequency and amplitude added to the DC coil current command; the
//! coil current follows through the coil's inductive lag (first order, τ = L/R); the brake
//! torque is proportional to the coil current about the operating point. The output is the
//! brake torque set point for the plant.

use num_complex::Complex64;

use crate::block::Block;
use crate::error::InstrumentError;

/// Brake drive settings.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct BrakeDriveSettings {
    /// AC amplitude of the coil current command (A).
    pub ac_amplitude_a: f64,
    /// AC frequency (Hz); the thesis found the brake usable around 15 Hz.
    pub ac_frequency_hz: f64,
    /// Coil time constant L/R (s).
    pub coil_time_constant_s: f64,
    /// Brake torque per ampere of coil current about the operating point (N m/A).
    pub torque_per_amp: f64,
}

/// Input: the DC coil current command (A) per sample; output: brake torque (N m).
#[derive(Clone, Debug, PartialEq)]
pub struct BrakeDrive {
    settings: BrakeDriveSettings,
    step_s: f64,
    alpha: f64,
    sample: u64,
    current_a: f64,
    started: bool,
}

impl BrakeDrive {
    /// A drive on a stream at `rate_hz`.
    pub fn new(settings: BrakeDriveSettings, rate_hz: f64) -> Result<Self, InstrumentError> {
        let s = settings;
        let valid = rate_hz > 0.0
            && s.coil_time_constant_s > 0.0
            && s.ac_amplitude_a >= 0.0
            && s.ac_frequency_hz >= 0.0
            && s.torque_per_amp.is_finite();
        if !valid {
            return Err(InstrumentError::setting(
                "brake drive",
                "settings",
                format!(
                    "coil time constant {} s, AC {} A at {} Hz, {} N m/A",
                    s.coil_time_constant_s, s.ac_amplitude_a, s.ac_frequency_hz, s.torque_per_amp
                ),
                "time constant > 0, amplitude and frequency ≥ 0",
            ));
        }
        Ok(Self {
            settings,
            step_s: 1.0 / rate_hz,
            alpha: 1.0 - (-1.0 / (rate_hz * s.coil_time_constant_s)).exp(),
            sample: 0,
            current_a: 0.0,
            started: false,
        })
    }

    /// Coil current now (A).
    pub fn current_a(&self) -> f64 {
        self.current_a
    }
}

impl Block for BrakeDrive {
    fn reset(&mut self) {
        self.sample = 0;
        self.current_a = 0.0;
        self.started = false;
    }

    fn process(&mut self, input: &[f64], output: &mut [f64]) {
        let s = self.settings;
        for (y, &dc) in output.iter_mut().zip(input) {
            let t = self.sample as f64 * self.step_s;
            let command =
                dc + s.ac_amplitude_a * (std::f64::consts::TAU * s.ac_frequency_hz * t).sin();
            if !self.started {
                // The coil starts settled at the first DC command.
                self.current_a = dc;
                self.started = true;
            }
            self.current_a += self.alpha * (command - self.current_a);
            *y = s.torque_per_amp * self.current_a;
            self.sample += 1;
        }
    }

    /// From coil current command to torque: k / (1 + jωτ) (continuous-time lag).
    fn response(&self, freq_hz: f64) -> Option<Complex64> {
        let s = self.settings;
        Some(
            Complex64::new(s.torque_per_amp, 0.0)
                / Complex64::new(
                    1.0,
                    std::f64::consts::TAU * freq_hz * s.coil_time_constant_s,
                ),
        )
    }
}
