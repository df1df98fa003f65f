//! What a sample reports, as rows of one matrix per mode over the state: each body's angle
//! and speed (in its own sense of rotation), each shaft's torque, each mesh's force along
//! its line of action and the motor's torque (the last two depend on the mode). A sample
//! is then one product.

use crate::mode::MotorMode;

use super::mode::NetMode;
use super::model::NetworkModel;

/// The outputs of a sample in one mode.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct OutputRows {
    /// Rows of each column (a multiple of 4): angles, speeds, shaft torques, mesh forces,
    /// motor torque, then zeros.
    pub rows: usize,
    /// The matrix, column-major, one column per state of the padded state.
    pub columns: Vec<f64>,
}

impl OutputRows {
    /// The outputs of `mode`, the meshes' harmonic pairs turning with the set speed
    /// `speed_rad_s`.
    pub fn of(model: &NetworkModel, mode: &NetMode, speed_rad_s: f64) -> Self {
        let forms = output_forms(model, mode, speed_rad_s);
        let rows = forms.len().div_ceil(4) * 4;
        let mut columns = vec![0.0; rows * model.layout.padded()];
        for (row, form) in forms.iter().enumerate() {
            for &(state, c) in form {
                columns[state * rows + row] += c;
            }
        }
        Self { rows, columns }
    }
}

/// Each output as a linear form of the state, in the order of [`OutputRows`].
fn output_forms(model: &NetworkModel, mode: &NetMode, speed_rad_s: f64) -> Vec<Vec<(usize, f64)>> {
    let l = &model.layout;
    let mut forms = Vec::new();
    for i in 0..l.bodies {
        let sense = model.sense[i];
        forms.push(vec![
            (l.angle(i), sense),
            (l.phase(), sense * model.speed_ratio[i]),
        ]);
    }
    for i in 0..l.bodies {
        forms.push(vec![(l.speed(i), model.sense[i])]);
    }
    for s in &model.shafts {
        let [a, b] = s.between;
        let sense = model.sense[a];
        forms.push(vec![
            (l.angle(a), sense * s.stiffness_nm_per_rad),
            (l.angle(b), -sense * s.stiffness_nm_per_rad),
            (l.unit(), sense * s.preload_nm),
        ]);
    }
    for i in 0..model.meshes.len() {
        let state = mode.meshes[i];
        forms.push(state.pushing_flank().map_or_else(Vec::new, |flank| {
            model.force_terms(i, state, flank, speed_rad_s)
        }));
    }
    forms.push(motor_form(model, mode.motor));
    forms
}

/// The motor's torque as a form in `motor` mode (none without a motor).
fn motor_form(model: &NetworkModel, motor: MotorMode) -> Vec<(usize, f64)> {
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
