//! What a sample reports that depends on the mode, as linear forms of the state: each
//! mesh's force along its line of action and the motor's torque (built with each mode's
//! system, so that a sample is a few sparse products).

use crate::mode::MotorMode;

use super::mode::NetMode;
use super::model::NetworkModel;

/// A linear form of the state: (index, coefficient).
pub type Form = Vec<(usize, f64)>;

/// The mode-dependent outputs of a sample.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct OutputForms {
    /// Each mesh's force (N): its spring-damper on the flank that pushes; empty apart or
    /// clipped.
    pub mesh_force_n: Vec<Form>,
    /// The motor's torque (N m): the speed loop's command or the limit it is held at;
    /// empty without a motor.
    pub motor_torque_nm: Form,
}

impl OutputForms {
    /// The outputs of `mode`, the meshes' harmonic pairs turning with the set speed
    /// `speed_rad_s`.
    pub fn of(model: &NetworkModel, mode: &NetMode, speed_rad_s: f64) -> Self {
        let mesh_force_n = (0..model.meshes.len())
            .map(|i| {
                let state = mode.meshes[i];
                state.pushing_flank().map_or_else(Vec::new, |flank| {
                    model.force_terms(i, state, flank, speed_rad_s)
                })
            })
            .collect();
        Self {
            mesh_force_n,
            motor_torque_nm: motor_form(model, mode.motor),
        }
    }
}

/// The motor's torque as a form in `motor` mode.
fn motor_form(model: &NetworkModel, motor: MotorMode) -> Form {
    let Some(m) = &model.motor else {
        return Vec::new();
    };
    let l = &model.layout;
    let limit = m.limit_nm.unwrap_or(f64::INFINITY);
    match motor {
        MotorMode::Linear => vec![
            (l.set_speed(), m.kp_nms_per_rad),
            (l.filtered(), -m.kp_nms_per_rad),
            (l.integral(), m.ki_nm_per_rad),
        ],
        MotorMode::LimitHigh => vec![(l.unit(), limit)],
        MotorMode::LimitLow => vec![(l.unit(), -limit)],
    }
}

/// The value of `form` at `u`.
#[inline]
pub fn value(form: &[(usize, f64)], u: &[f64]) -> f64 {
    form.iter().map(|&(i, c)| c * u[i]).sum()
}
