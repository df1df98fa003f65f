//! Shaft strain from torque: surface shear of a solid round shaft, seen by gauges at ±45°.

use crate::block::Block;
use crate::error::{InstrumentError, require_positive};
use num_complex::Complex64;

/// Torque (N m) → principal surface strain (dimensionless) of a solid round shaft in
/// torsion: γ = 16 T / (π d³ G), and gauges at ±45° see ε = ±γ/2 (the +45° one here).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ShaftStrain {
    /// Shaft diameter (m).
    pub diameter_m: f64,
    /// Shear modulus (Pa).
    pub shear_modulus_pa: f64,
}

impl ShaftStrain {
    /// The intermediate shaft of the rig: Ø20 mm steel EN1A, G ≈ 82.7 GPa (the value the
    /// thesis's stiffnesses imply, rig-spec §1).
    pub fn intermediate_shaft() -> Self {
        Self {
            diameter_m: 0.020,
            shear_modulus_pa: 82.7e9,
        }
    }

    /// A shaft of `diameter_m` and `shear_modulus_pa`, both finite and > 0.
    pub fn new(diameter_m: f64, shear_modulus_pa: f64) -> Result<Self, InstrumentError> {
        require_positive("shaft strain", "diameter", diameter_m)?;
        require_positive("shaft strain", "shear modulus", shear_modulus_pa)?;
        Ok(Self {
            diameter_m,
            shear_modulus_pa,
        })
    }

    /// Strain at +45° per unit torque (1/(N m)).
    pub fn strain_per_nm(&self) -> f64 {
        8.0 / (std::f64::consts::PI * self.diameter_m.powi(3) * self.shear_modulus_pa)
    }
}

impl Block for ShaftStrain {
    fn reset(&mut self) {}

    fn process(&mut self, input: &[f64], output: &mut [f64]) {
        let k = self.strain_per_nm();
        for (y, &torque) in output.iter_mut().zip(input) {
            *y = k * torque;
        }
    }

    fn response(&self, _freq_hz: f64) -> Option<Complex64> {
        Some(Complex64::new(self.strain_per_nm(), 0.0))
    }
}
