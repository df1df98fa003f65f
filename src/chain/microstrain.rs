//! The chain carries strain in microstrain (µε), the unit strain-gauge users read and
//! write: the gauged shaft's stage writes µε and the bridge reads µε. The instruments
//! crate stays in SI (dimensionless strain); these two blocks convert at its boundary.

use instruments::{Block, ShaftStrain, StrainBridge};

/// Microstrain in one unit of strain.
pub const MICROSTRAIN_PER_STRAIN: f64 = 1.0e6;

/// Shaft torque (N m) to surface strain at +45° in µε.
#[derive(Clone, Copy, Debug)]
pub struct ShaftMicrostrain(pub ShaftStrain);

impl ShaftMicrostrain {
    /// µε per N m of shaft torque.
    pub fn microstrain_per_nm(&self) -> f64 {
        self.0.strain_per_nm() * MICROSTRAIN_PER_STRAIN
    }
}

impl Block for ShaftMicrostrain {
    fn reset(&mut self) {}

    fn process(&mut self, input: &[f64], output: &mut [f64]) {
        let k = self.microstrain_per_nm();
        for (y, &torque_nm) in output.iter_mut().zip(input) {
            *y = k * torque_nm;
        }
    }
}

/// The strain-gauge bridge reading strain in µε, writing volts.
#[derive(Clone, Copy, Debug)]
pub struct MicrostrainBridge(pub StrainBridge);

impl Block for MicrostrainBridge {
    fn reset(&mut self) {}

    fn process(&mut self, input: &[f64], output: &mut [f64]) {
        for (y, &microstrain) in output.iter_mut().zip(input) {
            *y = self.0.output_v(microstrain / MICROSTRAIN_PER_STRAIN);
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use instruments::BridgeArrangement;

    /// 1 N m on the Ø20 mm shaft: γ = 16 T/(π d³ G) = 7.70e-6, ε = γ/2 = 3.85 µε; through
    /// the full bridge (GF 2.1, 10 V) 2.1 × 10 V × 3.85e-6 = 80.8 µV, as the SI blocks give.
    #[test]
    fn microstrain_stages_agree_with_the_si_blocks() {
        let shaft = ShaftStrain::intermediate_shaft();
        let mut strain = ShaftMicrostrain(shaft);
        let mut out = [0.0];
        strain.process(&[1.0], &mut out);
        let gamma = 16.0 / (std::f64::consts::PI * 0.02f64.powi(3) * 82.7e9);
        assert!((out[0] - gamma / 2.0 * 1e6).abs() < 1e-9);
        let bridge = StrainBridge::new(BridgeArrangement::Full, 2.1, 10.0).expect("bridge");
        let mut volts = [0.0];
        MicrostrainBridge(bridge).process(&out, &mut volts);
        let si = bridge.output_v(shaft.strain_per_nm());
        assert!((volts[0] - si).abs() < 1e-15 * si.abs().max(1.0));
        assert!((volts[0] - 2.1 * 10.0 * gamma / 2.0).abs() < 1e-12);
    }
}
