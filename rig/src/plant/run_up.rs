//! How long the drive takes to run a rig up from rest to a set speed at its torque limit:
//! the time a point from rest waits before it settles (a sweep's cases from rest), by the
//! rule `RigParams::run_up_from_rest_s` gives the 1983 rig's five bodies.

use crate::run_up_time::run_up_time_s;

use super::model::NetworkModel;
use super::network_plant::NetworkPlant;

impl NetworkModel {
    /// Time (s) the motor at its torque limit takes to bring the rig from rest to `rpm`
    /// of the motor's body against the brake's `load_nm` (and its drag). Seen at the
    /// motor: J dω/dt = limit − (load + drag)·s_b − c ω, J = Σ J_i s_i², c = Σ c_i s_i²
    /// (s_i each body's speed per the motor's): [`run_up_time_s`]. `None` where the motor has no limit (its
    /// loop runs the rig up with its own time constant), or no torque to spare.
    pub fn run_up_from_rest_s(&self, rpm: f64, load_nm: f64) -> Option<f64> {
        let limit_nm = self.motor.as_ref()?.limit_nm?;
        let braked_nm = self
            .brake
            .as_ref()
            .map_or(0.0, |b| (load_nm + b.drag_nm) * b.speed_share);
        let spare_nm = limit_nm - braked_nm;
        if spare_nm <= 0.0 {
            return None;
        }
        let seen = |per_body: &[f64]| -> f64 {
            per_body
                .iter()
                .zip(&self.speed_ratio)
                .map(|(x, s)| x * s * s)
                .sum()
        };
        let inertia = seen(&self.inertia);
        let drag = seen(&self.drag_nms_per_rad);
        let omega = rpm.abs() * std::f64::consts::PI / 30.0;
        Some(run_up_time_s(inertia, drag, spare_nm, omega))
    }
}

impl NetworkPlant {
    /// `NetworkModel::run_up_from_rest_s` of this plant's rig.
    pub fn run_up_from_rest_s(&self, rpm: f64, load_nm: f64) -> Option<f64> {
        self.model.run_up_from_rest_s(rpm, load_nm)
    }
}
