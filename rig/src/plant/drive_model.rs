//! The drive's and the brake's constants as the equations take them: the motor's speed
//! loop and limit, the brake's body, sense, slope, drag and eddy-current characteristic.

use crate::eddy_current::characteristic_slope_nms_per_rad;

/// The motor's speed loop.
#[derive(Clone, Debug, PartialEq)]
pub struct MotorModel {
    /// The body it drives.
    pub body: usize,
    /// Proportional gain (N m s/rad).
    pub kp_nms_per_rad: f64,
    /// Integral gain (N m/rad).
    pub ki_nm_per_rad: f64,
    /// Speed filter corner (rad/s).
    pub filter_rad_s: f64,
    /// Torque limit (N m), if any.
    pub limit_nm: Option<f64>,
}

/// The brake.
#[derive(Clone, Debug, PartialEq)]
pub struct BrakeModel {
    /// The body it loads.
    pub body: usize,
    /// +1 where the brake body turns the motor's way, −1 where it turns against it.
    pub direction: f64,
    /// Rise of its torque with speed (N m s/rad).
    pub slope_nms_per_rad: f64,
    /// Residual drag added to the set load (N m).
    pub drag_nm: f64,
    /// The eddy-current characteristic's critical speed (rad/s of the brake body); 0 off.
    pub critical_rad_s: f64,
    /// The brake body's speed per unit speed of the motor's body (|s|).
    pub speed_share: f64,
}

impl BrakeModel {
    /// Slope (N m s/rad) of the eddy-current brake's torque with its speed at the motor's
    /// set speed `speed_rad_s`, braking `load_nm` and its drag there, linearised about the
    /// brake's own set speed (`crate::eddy_current`).
    pub fn characteristic_slope(&self, speed_rad_s: f64, load_nm: f64) -> f64 {
        characteristic_slope_nms_per_rad(
            load_nm + self.drag_nm,
            self.speed_share * speed_rad_s,
            self.critical_rad_s,
        )
    }
}
