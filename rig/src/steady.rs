//! What a run at fixed set points shows once settled: the summary a steady point reports
//! (`simulate --json`, a sweep's case, a scenario's point verdict).

use serde::Serialize;

use crate::judge::Judgement;
use crate::regime::Regime;

/// What a settled run shows (the measuring window only).
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct SteadySummary {
    /// Length of the measuring window (s).
    pub measured_s: f64,
    /// Contact starts in the window, every mesh's.
    pub impacts: usize,
    /// Contact starts per revolution of the motor's body.
    pub impacts_per_rev: f64,
    /// The first mesh's contact starts in the window on each tooth of its driving gear,
    /// from tooth 1.
    pub impacts_per_tooth: Vec<u64>,
    /// Period-k or aperiodic: the judge's period, aperiodic where it finds none, period 1
    /// where nothing vibrates.
    pub regime: Regime,
    /// Whether any mesh's teeth ever lose contact in the window.
    pub separates: bool,
    /// Share of samples with the first mesh apart.
    pub apart_fraction: f64,
    /// Mean torque of the judged shaft (the gauged one; the 1983 rig's intermediate,
    /// output shaft) (N m).
    pub torque_mean_nm: f64,
    /// RMS of the judged shaft's torque, mean included (N m).
    pub torque_rms_nm: f64,
    /// RMS of the judged shaft's torque about its mean (N m).
    pub torque_ac_rms_nm: f64,
    /// Whole revolutions of the motor's body in the window.
    pub revolutions: usize,
    /// Mean speed of the motor over the window less the set speed (rev/min): near 0
    /// where the motor holds the set speed, negative where its torque limit lets it sag.
    pub speed_offset_rpm: f64,
    /// The physics judge's verdict on the judged shaft's torque, with its numbers.
    pub motion: Judgement,
}
