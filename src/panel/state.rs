//! The panel's state as the API serves it: the rack's readings, the set points, the run's
//! health and the displays, from the run's shared status.

use std::sync::Arc;

use instruments::CROMPTON_PARKINSON_V_PER_RPM;
use serde::Serialize;

use crate::runtime::status::Status;
use crate::vocabulary::display::{AppliedChain, LiveSpectrum, LiveTrace};

/// One snapshot of the panel.
#[derive(Clone, Debug, Serialize)]
pub struct PanelState {
    /// Virtual time (s).
    pub simulated_s: f64,
    /// Speed set point (rev/min).
    pub speed_set_rpm: f64,
    /// Brake load set point (N m).
    pub load_set_nm: f64,
    /// Oscillating load amplitude (N m).
    pub oscillating_load_nm: f64,
    /// Oscillating load frequency (Hz).
    pub oscillating_load_hz: f64,
    /// Tacho DVM display (V).
    pub dvm_v: f64,
    /// The DVM display as a speed (rev/min, 0.04 V per rev/min).
    pub dvm_rpm: f64,
    /// RMS meter reading (V).
    pub meter_v: f64,
    /// Analyser averages taken and set.
    pub averages: [usize; 2],
    /// ADC overloads so far.
    pub adc_overloads: u64,
    /// Blocks dropped at a full queue.
    pub overruns: u64,
    /// Lateness of the last release (ms).
    pub lateness_ms: f64,
    /// Contact starts so far.
    pub impacts: u64,
    /// Regime of the last full 10 s after settling (`period-k`, `aperiodic`), or
    /// `settling` for the first 15 s after the set points change.
    pub regime: Option<String>,
    /// The physics judge's motion of the last full 10 s after settling (`period-k`,
    /// `quasi-periodic`, `chaotic`, `no-vibration`), or `settling` for the first 15 s after the
    /// set points change.
    pub motion: Option<String>,
    /// Whether the recorder is writing.
    pub recording: bool,
    /// The analyser's display.
    pub spectrum: Option<Arc<LiveSpectrum>>,
    /// The scope's latest trace.
    pub trace: Option<Arc<LiveTrace>>,
    /// The chain's settings in effect: amplifier gain and anti-alias filter.
    pub chain: AppliedChain,
}

impl PanelState {
    /// The panel as `status` holds it, for a stream at `rate_hz`.
    pub fn of(status: &Status, rate_hz: f64) -> Self {
        let set = status.set_points.unwrap_or(rig::SetPoints {
            speed_rpm: 0.0,
            load_nm: 0.0,
            oscillating_load_nm: 0.0,
            oscillating_load_hz: 0.0,
        });
        Self {
            simulated_s: status.simulated_samples as f64 / rate_hz,
            speed_set_rpm: set.speed_rpm,
            load_set_nm: set.load_nm,
            oscillating_load_nm: set.oscillating_load_nm,
            oscillating_load_hz: set.oscillating_load_hz,
            dvm_v: status.dvm_v,
            dvm_rpm: status.dvm_v / CROMPTON_PARKINSON_V_PER_RPM,
            meter_v: status.meter_v,
            averages: [status.averages.0, status.averages.1],
            adc_overloads: status.adc_overloads,
            overruns: status.overruns,
            lateness_ms: status.lateness_s * 1e3,
            impacts: status.impacts,
            regime: status.regime.clone(),
            motion: status.motion.clone(),
            recording: status.recording,
            spectrum: status.spectrum.clone(),
            trace: status.trace.clone(),
            chain: status.chain.clone(),
        }
    }
}
