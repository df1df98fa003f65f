//! RMS voltmeters: the HP 400E as it is (average-responding, RMS-calibrated) and a true-RMS
//! meter beside it. Both settle as a first-order detector with time constant τ.

use crate::ac_coupling::AcCoupling;
use crate::block::Block;
use crate::error::InstrumentError;

/// π/(2√2): the sine's RMS over its mean absolute value, the 400E's calibration factor.
pub const FORM_FACTOR_SINE: f64 = std::f64::consts::PI / (2.0 * std::f64::consts::SQRT_2);

/// What the meter's detector responds to.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Detector {
    /// Mean of |v| scaled by 1.1107 (HP 400E): right for sines only.
    AverageRmsCalibrated,
    /// √(mean v²).
    TrueRms,
}

/// A voltmeter whose output stream is its reading (V).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Voltmeter {
    detector: Detector,
    alpha: f64,
    state: f64,
    coupling: Option<AcCoupling>,
}

impl Voltmeter {
    /// A meter at `rate_hz` whose detector settles with time constant `tau_s` (the 400E
    /// needs about 1 s: τ = 0.2 s gives 99 % in 1 s).
    pub fn new(detector: Detector, rate_hz: f64, tau_s: f64) -> Result<Self, InstrumentError> {
        if !(rate_hz.is_finite() && rate_hz > 0.0 && tau_s.is_finite() && tau_s > 0.0) {
            return Err(InstrumentError::setting(
                "voltmeter",
                "rate or time constant",
                format!("{rate_hz} Hz, {tau_s} s"),
                "both finite and > 0",
            ));
        }
        Ok(Self {
            detector,
            alpha: 1.0 - (-1.0 / (rate_hz * tau_s)).exp(),
            state: 0.0,
            coupling: None,
        })
    }

    /// The meter AC-coupled: a first-order high-pass with corner `corner_hz` (the HP 400E
    /// is specified from 10 Hz; its corner lies below) on a stream at `rate_hz`.
    pub fn ac_coupled(mut self, corner_hz: f64, rate_hz: f64) -> Result<Self, InstrumentError> {
        self.coupling = Some(AcCoupling::new(corner_hz, rate_hz)?);
        Ok(self)
    }

    /// The reading now (V).
    pub fn reading(&self) -> f64 {
        match self.detector {
            Detector::AverageRmsCalibrated => FORM_FACTOR_SINE * self.state,
            Detector::TrueRms => self.state.max(0.0).sqrt(),
        }
    }
}

impl Block for Voltmeter {
    fn reset(&mut self) {
        self.state = 0.0;
        if let Some(c) = &mut self.coupling {
            c.reset();
        }
    }

    fn process(&mut self, input: &[f64], output: &mut [f64]) {
        for (y, &x) in output.iter_mut().zip(input) {
            let v = match &mut self.coupling {
                Some(c) => c.tick(x),
                None => x,
            };
            let detected = match self.detector {
                Detector::AverageRmsCalibrated => v.abs(),
                Detector::TrueRms => v * v,
            };
            self.state += self.alpha * (detected - self.state);
            *y = self.reading();
        }
    }
}
