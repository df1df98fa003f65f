//! The equations of motion (thesis eqs. 5.1–5.6 with drive, brake and forcing) as the
//! matrix of a linear system, one per [`Mode`].

use nalgebra::DMatrix;

use crate::eddy_current::characteristic_slope_nms_per_rad;
use crate::geometry::GearGeometry;
use crate::layout::{LOAD, Layout, REV, UNIT, V0, VF, X0, Z};
use crate::mode::{Engagement, Mode, MotorMode, PairZone};
use crate::params::RigParams;
use crate::spacing::spacing_errors_rad;

/// The plant's constants in the form the equations use (SI units).
#[derive(Clone, Debug, PartialEq)]
pub struct ModelConstants {
    /// Inertias M1..M5 (kg m²).
    pub inertia_kgm2: [f64; 5],
    /// Shaft stiffnesses K12, K34, K45 (N m/rad).
    pub shaft_stiffness_nm_per_rad: [f64; 3],
    /// Shaft damping C12, C34, C45 (N m s/rad).
    pub shaft_damping_nms_per_rad: [f64; 3],
    /// Mesh stiffness of one pair (N m/rad).
    pub mesh_stiffness_nm_per_rad: f64,
    /// Mesh damping of one pair (N m s/rad).
    pub mesh_damping_nms_per_rad: f64,
    /// Two-pair stiffness and damping over one pair's.
    pub double_pair_ratio: f64,
    /// Free play B₀ each side of centre (rad).
    pub half_backlash_rad: f64,
    /// Backlash variation C1 (dimensionless).
    pub backlash_variation: f64,
    /// Once-per-rev gear error C2 (N m).
    pub gear_error_1_nm: f64,
    /// Twice-per-rev gear error C3 (N m).
    pub gear_error_2_nm: f64,
    /// Speed-loop proportional gain Kp (N m s/rad).
    pub kp_nms_per_rad: f64,
    /// Speed-loop integral gain Ki (N m/rad).
    pub ki_nm_per_rad: f64,
    /// Speed feedback filter corner (rad/s).
    pub filter_rad_s: f64,
    /// Motor torque limit (N m).
    pub torque_limit_nm: f64,
    /// Brake torque slope with speed (N m s/rad).
    pub brake_slope_nms_per_rad: f64,
    /// Bearing and windage drag on each body (N m s/rad).
    pub bearing_drag_nms_per_rad: f64,
    /// Critical speed of the eddy-current brake (rad/s); 0: torque independent of speed.
    pub brake_critical_rad_s: f64,
    /// Once-per-revolution transmission error E of e(φ) = E cos φ + P cos zφ (rad about
    /// the gear axis).
    pub te_once_rad: f64,
    /// Mesh-frequency (profile) transmission error P of e(φ) = E cos φ + P cos zφ (rad
    /// about the gear axis).
    pub te_mesh_rad: f64,
    /// Teeth z on each gear: the mesh frequency is zΩ.
    pub teeth: f64,
    /// Spacing error of each tooth pair (rad about the gear axis), pair i in mesh while
    /// the driving gear's tooth i is; empty when off (`spacing::spacing_errors_rad`).
    pub spacing_rad: Vec<f64>,
}

/// Spring and damper pairs of the shafts: (body i, body j) for K12, K34, K45.
const SHAFTS: [(usize, usize); 3] = [(0, 1), (2, 3), (3, 4)];

impl ModelConstants {
    /// Collects the constants of `params`.
    pub fn of(params: &RigParams) -> Self {
        let (kp, ki) = params.speed_loop_gains();
        let geometry = GearGeometry::of(params);
        Self {
            inertia_kgm2: params.inertias_kgm2(),
            shaft_stiffness_nm_per_rad: [
                params.k12_input_shaft_nm_per_rad,
                params.k34_intermediate_shaft_nm_per_rad,
                params.k45_final_shaft_nm_per_rad,
            ],
            shaft_damping_nms_per_rad: [
                params.c12_input_shaft_nms_per_rad,
                params.c34_intermediate_shaft_nms_per_rad,
                params.c45_final_shaft_nms_per_rad,
            ],
            mesh_stiffness_nm_per_rad: params.k23_mesh_nm_per_rad,
            mesh_damping_nms_per_rad: params.c23_mesh_nms_per_rad,
            double_pair_ratio: params.double_pair_stiffness_ratio,
            half_backlash_rad: geometry.half_backlash_rad,
            backlash_variation: params.backlash_variation_c1,
            gear_error_1_nm: params.gear_error_c2_nm,
            gear_error_2_nm: params.gear_error_c3_nm,
            kp_nms_per_rad: kp,
            ki_nm_per_rad: ki,
            filter_rad_s: 2.0 * std::f64::consts::PI * params.speed_feedback_filter_hz,
            torque_limit_nm: params.motor_torque_limit_nm(),
            brake_slope_nms_per_rad: params.brake_speed_slope_nms_per_rad,
            bearing_drag_nms_per_rad: params.bearing_drag_nms_per_rad,
            brake_critical_rad_s: params.brake_critical_speed_rpm * std::f64::consts::PI / 30.0,
            te_once_rad: params.te_once_per_rev_um * 1e-6 / geometry.pitch_radius_m,
            te_mesh_rad: params.te_mesh_frequency_um * 1e-6 / geometry.pitch_radius_m,
            teeth: f64::from(params.teeth),
            spacing_rad: spacing_errors_rad(params),
        }
    }

    /// Spacing error (rad) of the pair whose driving tooth is `tooth`; 0 when off.
    pub fn spacing_of_tooth(&self, tooth: u32) -> f64 {
        self.spacing_rad.get(tooth as usize).copied().unwrap_or(0.0)
    }

    /// Slope (N m s/rad) of the eddy-current brake's characteristic at the set speed
    /// `speed_rad_s`, braking `torque_nm` there (`crate::eddy_current`).
    pub fn brake_characteristic_slope(&self, speed_rad_s: f64, torque_nm: f64) -> f64 {
        characteristic_slope_nms_per_rad(torque_nm, speed_rad_s, self.brake_critical_rad_s)
    }

    /// Drag torque (N m) of bearings and windage on each body at the set speed (at rest relative to it).
    pub fn bearing_drag_nm(&self, speed_rad_s: f64) -> f64 {
        self.bearing_drag_nms_per_rad * speed_rad_s
    }

    /// Transmission error e = E cos φ + P cos zφ (rad) and its rate ė (rad/s) at
    /// `harmonics` = [cos φ, sin φ, cos zφ, sin zφ] of the set rotation.
    #[inline(always)]
    pub fn transmission_error(&self, speed_rad_s: f64, harmonics: [f64; 4]) -> (f64, f64) {
        let [cos, sin, cos_z, sin_z] = harmonics;
        let mesh_rad_s = self.teeth * speed_rad_s;
        (
            self.te_once_rad * cos + self.te_mesh_rad * cos_z,
            -self.te_once_rad * speed_rad_s * sin - self.te_mesh_rad * mesh_rad_s * sin_z,
        )
    }

    /// Mesh stiffness (N m/rad) and damping (N m s/rad) with `pairs` in contact.
    pub fn mesh_spring(&self, pairs: PairZone) -> (f64, f64) {
        let ratio = 1.0 + (self.double_pair_ratio - 1.0) * pairs.share_of_second_pair();
        (
            ratio * self.mesh_stiffness_nm_per_rad,
            ratio * self.mesh_damping_nms_per_rad,
        )
    }

    /// Elastic torques of the three shafts K(Xi − Xj) (N m), positive when transmitting drive torque.
    pub fn shaft_torques_nm(&self, x: &[f64]) -> [f64; 3] {
        let mut torque = [0.0; 3];
        for (t, (&(i, j), &k)) in torque.iter_mut().zip(self.shafts()) {
            *t = k * (x[X0 + i] - x[X0 + j]);
        }
        torque
    }

    /// The three shafts in order: (body i, body j) of K(Xi − Xj) and the stiffness K (N m/rad).
    pub fn shafts(&self) -> impl Iterator<Item = (&(usize, usize), &f64)> {
        SHAFTS.iter().zip(&self.shaft_stiffness_nm_per_rad)
    }

    /// Output of the PI speed controller before the limit (N m).
    pub fn controller_torque_nm(&self, x: &[f64]) -> f64 {
        -self.kp_nms_per_rad * x[VF] + self.ki_nm_per_rad * x[Z]
    }
}

/// What of the set points enters the matrix: angular frequencies (rad/s) and the brake's
/// slope there.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Frequencies {
    /// Set speed Ω (rad/s): the gear errors and backlash variation turn at Ω and 2Ω.
    pub rotation_rad_s: f64,
    /// Oscillating load frequency (rad/s).
    pub oscillating_load_rad_s: f64,
    /// Slope of the eddy-current brake's characteristic at the set point (N m s/rad).
    pub brake_characteristic_nms_per_rad: f64,
}

/// Builds A of u' = A u for the augmented state `u` (see [`crate::layout`]) in `mode`.
pub fn system_matrix(
    mc: &ModelConstants,
    layout: &Layout,
    mode: Mode,
    freq: Frequencies,
) -> DMatrix<f64> {
    let mut a = DMatrix::zeros(layout.len, layout.len);
    for i in 0..5 {
        a[(X0 + i, V0 + i)] = 1.0;
    }
    for ((&(i, j), &k), &c) in SHAFTS
        .iter()
        .zip(&mc.shaft_stiffness_nm_per_rad)
        .zip(&mc.shaft_damping_nms_per_rad)
    {
        add_spring(&mut a, &mc.inertia_kgm2, (i, j), k, c);
    }
    add_mesh(&mut a, mc, layout, mode, freq.rotation_rad_s);
    add_gear_errors(&mut a, mc, layout);
    add_brake(&mut a, mc, layout, freq.brake_characteristic_nms_per_rad);
    add_bearing_drag(&mut a, mc, freq.rotation_rad_s);
    add_motor(&mut a, mc, mode.motor);
    for (index, w) in harmonic_pairs(mc, layout, freq) {
        add_rotation(&mut a, index, w);
    }
    a
}

/// The harmonic pairs of `layout` with the angular frequency each turns at (rad/s):
/// (index of the cos state, ω) for φ, 2φ, the oscillating load's ψ and zφ.
pub fn harmonic_pairs(
    mc: &ModelConstants,
    layout: &Layout,
    freq: Frequencies,
) -> Vec<(usize, f64)> {
    let optional = [
        (layout.rev2, 2.0 * freq.rotation_rad_s),
        (layout.osc, freq.oscillating_load_rad_s),
        (layout.mesh, mc.teeth * freq.rotation_rad_s),
    ];
    std::iter::once((REV, freq.rotation_rad_s))
        .chain(
            optional
                .into_iter()
                .filter_map(|(index, w)| index.map(|i| (i, w))),
        )
        .collect()
}

/// A spring k and damper c between bodies i and j.
fn add_spring(a: &mut DMatrix<f64>, inertia: &[f64; 5], (i, j): (usize, usize), k: f64, c: f64) {
    for (body, sign) in [(i, 1.0), (j, -1.0)] {
        let row = V0 + body;
        let scale = sign / inertia[body];
        a[(row, X0 + i)] -= k * scale;
        a[(row, X0 + j)] += k * scale;
        a[(row, V0 + i)] -= c * scale;
        a[(row, V0 + j)] += c * scale;
    }
}

/// Mesh torque F_XT on M3 (and −F_XT on M2), thesis eq. (5.6) with B(t) = B₀(1 − C1 cos φ):
/// spring and damper act on the tooth overlap δ (drive flank δ = −d − B, back flank
/// δ = d − B, d = X3 − X2): drive F_XT = K δ + C δ', back F_XT = −(K δ + C δ').
///
/// With B constant this is (5.6) exactly (δ' = ∓ḋ). With the backlash variation the
/// thesis's damper acts on ḋ alone, which makes the pair transmit C·Ḃ with its spring
/// unloaded and chatter at the boundary; here it acts on the overlap rate ḋ ± Ḃ.
///
/// The transmission error e = E cos φ + P cos zφ adds K e + C ė on either flank.
fn add_mesh(
    a: &mut DMatrix<f64>,
    mc: &ModelConstants,
    layout: &Layout,
    mode: Mode,
    rotation_rad_s: f64,
) {
    let flank = match mode.mesh.engagement() {
        Engagement::Free => return,
        Engagement::Drive => 1.0,
        Engagement::Back => -1.0,
    };
    let (k, c) = mc.mesh_spring(mode.pairs);
    add_spring(a, &mc.inertia_kgm2, (2, 1), k, c);
    let b0 = mc.half_backlash_rad;
    let bc = b0 * mc.backlash_variation;
    let e = mc.te_once_rad;
    // F_XT = −K d − C ḋ (the spring above) − flank·K·B₀ + flank·K·B₀C1 cos φ − flank·C·B₀C1·Ω sin φ
    // + K E cos φ − C E Ω sin φ (the transmission error, the same on either flank).
    for (body, sign) in [(2, 1.0), (1, -1.0)] {
        let scale = flank * sign / mc.inertia_kgm2[body];
        a[(V0 + body, UNIT)] -= k * b0 * scale;
        a[(V0 + body, REV)] += k * bc * scale;
        a[(V0 + body, REV + 1)] -= c * bc * rotation_rad_s * scale;
        let scale = sign / mc.inertia_kgm2[body];
        a[(V0 + body, REV)] += k * e * scale;
        a[(V0 + body, REV + 1)] -= c * e * rotation_rad_s * scale;
        if let Some(mesh) = layout.mesh {
            let p = mc.te_mesh_rad;
            a[(V0 + body, mesh)] += k * p * scale;
            a[(V0 + body, mesh + 1)] -= c * p * mc.teeth * rotation_rad_s * scale;
        }
        // The spacing error s of the pair in mesh: K s, constant over the pair's pitch.
        if let Some(spacing) = layout.spacing {
            a[(V0 + body, spacing)] += k * scale;
        }
    }
}

/// Bearing and windage drag −c(Ω + Vi) on each body.
fn add_bearing_drag(a: &mut DMatrix<f64>, mc: &ModelConstants, rotation_rad_s: f64) {
    let c = mc.bearing_drag_nms_per_rad;
    if c == 0.0 {
        return;
    }
    for (body, j) in mc.inertia_kgm2.iter().enumerate() {
        a[(V0 + body, V0 + body)] -= c / j;
        a[(V0 + body, UNIT)] -= c * rotation_rad_s / j;
    }
}

/// Gear error torques F2 = F3 = −C2 cos φ − C3 cos 2φ on M2 and M3.
fn add_gear_errors(a: &mut DMatrix<f64>, mc: &ModelConstants, layout: &Layout) {
    for body in [1, 2] {
        let row = V0 + body;
        a[(row, REV)] -= mc.gear_error_1_nm / mc.inertia_kgm2[body];
        if let Some(rev2) = layout.rev2 {
            a[(row, rev2)] -= mc.gear_error_2_nm / mc.inertia_kgm2[body];
        }
    }
}

/// Brake torque on M5: load T_L + slope·V5 + oscillating part A sin ψ, all resisting; the
/// slope is the set one plus the eddy-current characteristic's at the set point.
fn add_brake(a: &mut DMatrix<f64>, mc: &ModelConstants, layout: &Layout, characteristic: f64) {
    let row = V0 + 4;
    let j5 = mc.inertia_kgm2[4];
    a[(row, LOAD)] -= 1.0 / j5;
    a[(row, V0 + 4)] -= (mc.brake_slope_nms_per_rad + characteristic) / j5;
    if let Some(osc) = layout.osc {
        a[(row, osc + 1)] -= 1.0 / j5;
    }
}

/// Motor torque on M1 from the PI speed loop on the filtered speed, or the limit.
fn add_motor(a: &mut DMatrix<f64>, mc: &ModelConstants, motor: MotorMode) {
    let j1 = mc.inertia_kgm2[0];
    a[(VF, V0)] = mc.filter_rad_s;
    a[(VF, VF)] = -mc.filter_rad_s;
    match motor {
        MotorMode::Linear => {
            a[(V0, VF)] -= mc.kp_nms_per_rad / j1;
            a[(V0, Z)] += mc.ki_nm_per_rad / j1;
            a[(Z, VF)] = -1.0;
        }
        MotorMode::LimitHigh | MotorMode::LimitLow => {
            let sign = if motor == MotorMode::LimitHigh {
                1.0
            } else {
                -1.0
            };
            a[(V0, UNIT)] += sign * mc.torque_limit_nm / j1;
            // The integrator tracks so that the command stays at the limit (an analogue PI
            // whose output clamp holds the integrator): ki·Ż = kp·V̇F.
            if mc.ki_nm_per_rad > 0.0 {
                let gain = mc.kp_nms_per_rad * mc.filter_rad_s / mc.ki_nm_per_rad;
                a[(Z, V0)] = gain;
                a[(Z, VF)] = -gain;
            }
        }
    }
}

/// A harmonic pair (cos, sin) at `index` turning at `w` rad/s.
fn add_rotation(a: &mut DMatrix<f64>, index: usize, w: f64) {
    a[(index, index + 1)] = -w;
    a[(index + 1, index)] = w;
}
