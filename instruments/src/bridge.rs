//! Strain-gauge Wheatstone bridge: full (four active gauges, torsion only), half (two
//! active) or quarter (one active, nonlinear) arrangement.

use crate::block::Block;
use crate::error::{InstrumentError, require_positive};

/// How many arms of the bridge carry active gauges.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum BridgeArrangement {
    /// Four active gauges at ±45° (the rig): E_out = GF·E_in·ε, exactly linear.
    Full,
    /// Two active gauges at ±45° in adjacent arms: E_out = GF·E_in·ε/2, linear.
    Half,
    /// One active gauge: E_out = E_in·GF ε / (4 + 2 GF ε), slightly nonlinear.
    Quarter,
}

/// A bridge turning strain (dimensionless) into output voltage (V), read by an amplifier
/// of infinite input impedance (so the gauges' resistance does not enter).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct StrainBridge {
    /// Arrangement of active gauges.
    pub arrangement: BridgeArrangement,
    /// Nominal gauge factor (SHOWA N22-FA: about 2.1).
    pub gauge_factor: f64,
    /// Relative deviation of the gauges' actual factor from nominal (e.g. 0.01 for +1 %).
    pub gauge_factor_error: f64,
    /// Bridge excitation (V).
    pub excitation_v: f64,
}

impl StrainBridge {
    /// A bridge; gauge factor and excitation finite and > 0, the factor error within ±50 %.
    pub fn new(
        arrangement: BridgeArrangement,
        gauge_factor: f64,
        excitation_v: f64,
    ) -> Result<Self, InstrumentError> {
        require_positive("strain bridge", "gauge factor", gauge_factor)?;
        require_positive("strain bridge", "excitation", excitation_v)?;
        Ok(Self {
            arrangement,
            gauge_factor,
            gauge_factor_error: 0.0,
            excitation_v,
        })
    }

    /// Output voltage (V) at strain `epsilon`, from the Wheatstone bridge itself: active
    /// arms at R(1 ± GF ε), the rest at R.
    pub fn output_v(&self, epsilon: f64) -> f64 {
        let x = self.gauge_factor * (1.0 + self.gauge_factor_error) * epsilon;
        let e = self.excitation_v;
        match self.arrangement {
            BridgeArrangement::Full => e * ((1.0 + x) / 2.0 - (1.0 - x) / 2.0),
            BridgeArrangement::Half => e * ((1.0 + x) / 2.0 - 0.5),
            BridgeArrangement::Quarter => e * ((1.0 + x) / (2.0 + x) - 0.5),
        }
    }
}

impl Block for StrainBridge {
    fn reset(&mut self) {}

    fn process(&mut self, input: &[f64], output: &mut [f64]) {
        for (y, &epsilon) in output.iter_mut().zip(input) {
            *y = self.output_v(epsilon);
        }
    }
}
