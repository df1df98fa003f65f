//! Slip rings (IDM PL-OT): the contact resistance of the rings fluctuates, broadband and
//! once per revolution, which modulates the signal they carry; the contacts also add noise.
//!
//! Model: v_out = v_in·(1 + σ_b n_b(t) + a_rev sin(2π f_rev t + φ)) + σ_n n_n(t), with
//! n_b, n_n independent seeded white Gaussian sequences. Placed after the carrier
//! modulator, the additive part lands beside the carrier, where the demodulator sees it.

use crate::block::Block;
use crate::error::InstrumentError;
use crate::noise::GaussianSource;
use crate::phase::wrapped;

/// Largest RMS contact noise accepted (V): far beyond any slip ring (microvolts), yet
/// bounded so that every sample stays finite.
const MAX_CONTACT_NOISE_V: f64 = 1000.0;

/// Slip-ring settings.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SlipRingSettings {
    /// RMS of the broadband relative fluctuation (dimensionless).
    pub broadband_rms: f64,
    /// Amplitude of the once-per-revolution relative fluctuation (dimensionless).
    pub per_rev_amplitude: f64,
    /// RMS of the additive contact noise (V).
    pub contact_noise_v_rms: f64,
    /// Seed of the noise.
    pub seed: u64,
}

/// The slip-ring block.
#[derive(Clone, Debug)]
pub struct SlipRing {
    settings: SlipRingSettings,
    step_s: f64,
    rotation_hz: f64,
    phase_rad: f64,
    broadband: GaussianSource,
    contact: GaussianSource,
}

impl SlipRing {
    /// Slip rings on a stream at `rate_hz`, turning at `rotation_hz` (rev/s).
    pub fn new(
        settings: SlipRingSettings,
        rate_hz: f64,
        rotation_hz: f64,
    ) -> Result<Self, InstrumentError> {
        let relative = [settings.broadband_rms, settings.per_rev_amplitude];
        if relative
            .iter()
            .any(|v| !(v.is_finite() && (0.0..=1.0).contains(v)))
        {
            return Err(InstrumentError::setting(
                "slip rings",
                "broadband_rms and per_rev_amplitude",
                format!("{:?} and {:?}", relative[0], relative[1]),
                "relative fluctuations of the contact resistance: each in [0, 1] (1 = 100 %)",
            ));
        }
        let noise = settings.contact_noise_v_rms;
        if !(noise.is_finite() && (0.0..=MAX_CONTACT_NOISE_V).contains(&noise)) {
            return Err(InstrumentError::setting(
                "slip rings",
                "contact_noise_v_rms",
                noise,
                "must lie in [0, 1000] V",
            ));
        }
        if !(rate_hz.is_finite() && rate_hz > 0.0 && rotation_hz.is_finite()) {
            return Err(InstrumentError::setting(
                "slip rings",
                "rates",
                format!("{rate_hz} Hz, {rotation_hz} rev/s"),
                "finite, stream rate > 0",
            ));
        }
        Ok(Self {
            settings,
            step_s: 1.0 / rate_hz,
            rotation_hz,
            phase_rad: 0.0,
            // Two independent streams from one seed.
            broadband: GaussianSource::new(settings.seed.wrapping_mul(2)),
            contact: GaussianSource::new(settings.seed.wrapping_mul(2).wrapping_add(1)),
        })
    }

    /// Changes the rotation speed (rev/s) for the once-per-revolution part.
    pub fn set_rotation_hz(&mut self, rotation_hz: f64) {
        self.rotation_hz = rotation_hz;
    }
}

impl Block for SlipRing {
    fn reset(&mut self) {
        self.phase_rad = 0.0;
        self.broadband.reset();
        self.contact.reset();
    }

    fn process(&mut self, input: &[f64], output: &mut [f64]) {
        let s = self.settings;
        for (y, &v) in output.iter_mut().zip(input) {
            let gain = 1.0
                + s.broadband_rms * self.broadband.sample()
                + s.per_rev_amplitude * self.phase_rad.sin();
            *y = v * gain + s.contact_noise_v_rms * self.contact.sample();
            self.phase_rad = wrapped(
                self.phase_rad + std::f64::consts::TAU * self.rotation_hz * self.step_s,
                std::f64::consts::TAU,
            );
        }
    }
}
