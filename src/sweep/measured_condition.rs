//! The watched gear's condition as the chain measures it: the analyser's input (the
//! anti-alias filter's output by default, the slip rings' and amplifier's noise in it),
//! read as torque by the chain's static calibration, averaged synchronously over the
//! gear's once-per-revolution pulses. The true torque's indicators beside it are the
//! ground truth; these are what a condition-monitoring system on the rig would compute.

use super::grid::SweepPlan;
use crate::chain::GearCondition;
use crate::vocabulary::GearIndicators;

/// The measured condition of one case's window.
pub struct MeasuredCondition {
    condition: GearCondition,
    nm_per_unit: f64,
}

impl MeasuredCondition {
    /// For the sweep `plan` on a gauged shaft of `microstrain_per_nm` (µε per N m);
    /// `None` where the analyser's input has no static calibration to torque (a signal
    /// other than the strain, the amplifier's or the filter's output on it).
    pub fn new(plan: &SweepPlan, microstrain_per_nm: f64) -> Option<Self> {
        let microstrain_per_unit = plan.chain.microstrain_per_unit(&plan.analyser.input)?;
        Some(Self {
            condition: GearCondition::new(plan.rate_hz),
            nm_per_unit: microstrain_per_unit / microstrain_per_nm,
        })
    }

    /// Room for a window of `samples` samples ([`GearCondition::reserve`]).
    pub fn reserve(&mut self, samples: usize) {
        self.condition.reserve(samples);
    }

    /// Adds samples at `time_s` of the watched gear's absolute angle (rad) and of the
    /// analyser's input (its unit).
    pub fn add(&mut self, time_s: &[f64], gear_angle_rad: &[f64], signal: &[f64]) {
        let torque_nm: Vec<f64> = signal.iter().map(|v| v * self.nm_per_unit).collect();
        self.condition
            .add_samples(time_s, gear_angle_rad, &torque_nm);
    }

    /// The indicators of the window for a gear of `teeth` teeth, if two revolutions were
    /// taken.
    pub fn report(&self, teeth: u32) -> Option<GearIndicators> {
        self.condition
            .report(teeth as usize)
            .as_ref()
            .map(GearIndicators::from)
    }
}
