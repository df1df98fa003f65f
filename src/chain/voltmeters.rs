//! The settings of the rack's two voltmeters, each building its instrument.

use instruments::{Detector, DigitalVoltmeter, InstrumentError, Voltmeter};

/// An RMS voltmeter (the HP 400E or a true-RMS meter).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct MeterSettings {
    /// Average-responding (400E) or true RMS.
    pub detector: Detector,
    /// Detector time constant (s).
    pub tau_s: f64,
    /// Corner of the AC coupling (Hz); 0 couples DC.
    pub ac_coupling_hz: f64,
}

impl MeterSettings {
    /// The meter on a stream at `rate_hz`.
    pub fn build(&self, rate_hz: f64) -> Result<Voltmeter, InstrumentError> {
        let meter = Voltmeter::new(self.detector, rate_hz, self.tau_s)?;
        if self.ac_coupling_hz > 0.0 {
            meter.ac_coupled(self.ac_coupling_hz, rate_hz)
        } else {
            Ok(meter)
        }
    }
}

/// The digital voltmeter reading the tacho.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct DvmSettings {
    /// Gate time (s).
    pub gate_s: f64,
    /// RMS converter time constant (s).
    pub tau_s: f64,
    /// Display resolution (V).
    pub resolution_v: f64,
}

impl DvmSettings {
    /// The DVM on a stream at `rate_hz`.
    pub fn build(&self, rate_hz: f64) -> Result<DigitalVoltmeter, InstrumentError> {
        DigitalVoltmeter::new(rate_hz, self.gate_s, self.tau_s, self.resolution_v)
    }
}
