//! The rig's parameter set: every number of the plant, in SI units, with where it comes from.

use serde::{Deserialize, Serialize};

use crate::error::RigError;
use crate::options::{ContactLaw, MeshPairs};

/// Every parameter of the plant (SI units; names carry the unit).
///
/// The preset `basmaji-1983` holds the thesis's own numbers (rig-spec §1–2); see
/// [`crate::presets`]. Fields are public so that code can build a rig directly; the
/// command line and scenarios change them by name through [`crate::param_table`].
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct RigParams {
    /// M1: DC motor rotor inertia (kg m²).
    pub j1_motor_kgm2: f64,
    /// M2: input flywheel plus driving gear inertia (kg m²).
    pub j2_input_flywheel_kgm2: f64,
    /// M3: driven gear inertia (kg m²).
    pub j3_driven_gear_kgm2: f64,
    /// M4: output (movable) flywheel inertia (kg m²).
    pub j4_output_flywheel_kgm2: f64,
    /// M5: eddy-current brake rotor inertia (kg m²).
    pub j5_brake_kgm2: f64,
    /// K12: input shaft torsional stiffness, motor to input flywheel (N m/rad).
    pub k12_input_shaft_nm_per_rad: f64,
    /// K23: mesh stiffness of one tooth pair in contact (N m/rad, about the gear axis).
    pub k23_mesh_nm_per_rad: f64,
    /// K34: intermediate shaft stiffness, driven gear to output flywheel (N m/rad).
    pub k34_intermediate_shaft_nm_per_rad: f64,
    /// K45: final shaft stiffness, output flywheel to brake (N m/rad).
    pub k45_final_shaft_nm_per_rad: f64,
    /// C12: input shaft viscous damping (N m s/rad).
    pub c12_input_shaft_nms_per_rad: f64,
    /// C23: mesh contact damping of one tooth pair (N m s/rad).
    pub c23_mesh_nms_per_rad: f64,
    /// C34: intermediate shaft viscous damping (N m s/rad).
    pub c34_intermediate_shaft_nms_per_rad: f64,
    /// C45: final shaft viscous damping (N m s/rad).
    pub c45_final_shaft_nms_per_rad: f64,
    /// Number of teeth on each gear of the 1:1 pair.
    pub teeth: u32,
    /// Gear module (m).
    pub module_m: f64,
    /// Standard pressure angle (degrees).
    pub pressure_angle_deg: f64,
    /// Addendum as a multiple of the module (1.0 for standard full-depth teeth).
    pub addendum_coefficient: f64,
    /// Increase of the centre distance over standard, which sets the backlash (m).
    pub centre_distance_shift_m: f64,
    /// Contact law of the mesh.
    pub contact_law: ContactLaw,
    /// Numerical tooth shifting at every tooth pass (thesis §5.4.5).
    pub tooth_shifting: bool,
    /// C1: relative backlash variation once per revolution, B(1 − C1 cos Ωt) (dimensionless).
    pub backlash_variation_c1: f64,
    /// C2: once-per-revolution gear error torque amplitude on M2 and M3 (N m).
    pub gear_error_c2_nm: f64,
    /// C3: twice-per-revolution gear error torque amplitude on M2 and M3 (N m).
    pub gear_error_c3_nm: f64,
    /// How many tooth pairs share the load: one always, or alternating one/two by the contact ratio.
    pub mesh_pairs: MeshPairs,
    /// Mesh stiffness and damping with two pairs in contact, as a multiple of one pair's.
    pub double_pair_stiffness_ratio: f64,
    /// Width of each change between one and two pairs in contact, as a fraction of the
    /// tooth pitch (0: sharp steps; see `pair_zones`). Only with alternating pairs.
    pub mesh_stiffness_smoothing: f64,
    /// Natural frequency of the closed speed loop on the whole rig's inertia (Hz); 0 turns
    /// the loop off (motor torque zero, for free-vibration studies).
    pub speed_loop_hz: f64,
    /// Damping ratio of the closed speed loop (dimensionless).
    pub speed_loop_damping_ratio: f64,
    /// Corner of the first-order low-pass on the controller's speed feedback (Hz).
    pub speed_feedback_filter_hz: f64,
    /// The DC drive's nameplate rated output (W): Hainsworth Speedrange, 2.0 hp.
    pub drive_rated_power_w: f64,
    /// Its rated (top) speed (rev/min): 2000.
    pub drive_rated_speed_rpm: f64,
    /// Its full-load armature current (A): F.L.C. 10.0 A.
    pub drive_full_load_current_a: f64,
    /// The armature current limit as a share of full-load current (%): the drive's torque
    /// is its torque constant times the current, so this bounds the torque either way.
    pub drive_current_limit_pct: f64,
    /// Slope of the brake torque with speed about the set point (N m s/rad); 0 is the thesis's constant torque.
    pub brake_speed_slope_nms_per_rad: f64,
    /// Residual drag at the brake (N m, ≥ 0): bearing and seal friction, windage and the
    /// brake's remanence, present at zero set load and added to the set load.
    pub brake_drag_nm: f64,
    /// Speed-proportional drag of bearings and windage on each of the five bodies
    /// (N m s/rad, ≥ 0): a torque −c·ω on each, ω its absolute speed. 0 in the thesis.
    pub bearing_drag_nms_per_rad: f64,
    /// Critical speed of the eddy-current brake (rev/min, ≥ 0): its torque at a fixed
    /// excitation follows T ∝ 2x/(1 + x²), x = ω/ω_c (Wouterse 1991), peaking at ω_c; the
    /// excitation is set so that it brakes with the set load at the set speed. 0 is the
    /// thesis's torque independent of speed.
    pub brake_critical_speed_rpm: f64,
    /// Once-per-revolution transmission error as a displacement of the mesh (µm of arc at
    /// the pitch circle), e(φ) = E cos φ: it shifts both flanks' contact the same way,
    /// unlike the backlash variation C1 (which widens and narrows the free play) and the
    /// error torques C2, C3 (which act whether the teeth touch or not). 0 in the thesis.
    pub te_once_per_rev_um: f64,
    /// Profile error at mesh frequency as a displacement of the mesh (µm of arc at the
    /// pitch circle), e_z(φ) = P cos zφ with z the teeth: the same error on every tooth,
    /// added to the once-per-revolution one and acting like it on both flanks. 0 in the
    /// thesis.
    pub te_mesh_frequency_um: f64,
    /// RMS of the tooth-pair spacing errors (µm of arc at the pitch circle, ≥ 0; 0 off):
    /// each of the `teeth` pairs (with a 1:1 ratio tooth i always meets tooth i) sits
    /// displaced by its own error while it is in mesh, a mesh displacement constant over
    /// the pair's pitch and acting on both flanks. Drawn from a normal distribution
    /// seeded by `tooth_spacing_seed`, made zero-mean and scaled to this RMS. 0 in the
    /// thesis, which cites random spacing errors (Harris; Gregory) as why impacts skip
    /// teeth.
    pub tooth_spacing_error_um: f64,
    /// Seed of the tooth-pair spacing errors.
    pub tooth_spacing_seed: u32,
}

impl RigParams {
    /// The five inertias M1..M5 (kg m²).
    pub fn inertias_kgm2(&self) -> [f64; 5] {
        [
            self.j1_motor_kgm2,
            self.j2_input_flywheel_kgm2,
            self.j3_driven_gear_kgm2,
            self.j4_output_flywheel_kgm2,
            self.j5_brake_kgm2,
        ]
    }

    /// Total inertia of the rig (kg m²).
    pub fn total_inertia_kgm2(&self) -> f64 {
        self.inertias_kgm2().iter().sum()
    }

    /// Speed-loop gains (Kp in N m s/rad, Ki in N m/rad) placing the closed loop on the
    /// whole rig's inertia J at ω_n = 2π·`speed_loop_hz` with damping `speed_loop_damping_ratio`:
    /// Ki = J ω_n², Kp = 2 ζ ω_n J.
    pub fn speed_loop_gains(&self) -> (f64, f64) {
        let j = self.total_inertia_kgm2();
        let wn = 2.0 * std::f64::consts::PI * self.speed_loop_hz;
        (2.0 * self.speed_loop_damping_ratio * wn * j, j * wn * wn)
    }

    /// Checks every value against its physical range; the error names the parameter.
    /// The drive's torque constant (N m/A) from its nameplate: rated power over rated
    /// speed is the torque at full-load current.
    pub fn torque_constant_nm_per_a(&self) -> f64 {
        self.full_load_torque_nm() / self.drive_full_load_current_a
    }

    /// Torque at full-load current (N m): rated power at rated speed.
    pub fn full_load_torque_nm(&self) -> f64 {
        self.drive_rated_power_w / (self.drive_rated_speed_rpm * std::f64::consts::PI / 30.0)
    }

    /// The motor's torque limit either way (N m): the torque constant times the armature
    /// current limit.
    pub fn motor_torque_limit_nm(&self) -> f64 {
        self.full_load_torque_nm() * (self.drive_current_limit_pct / 100.0)
    }

    /// Time the drive takes to run the rig up from rest to `rpm` against `load_nm` at
    /// its torque limit (s): J dω/dt = limit − load − brake drag − 5 c ω, so ω rises
    /// towards ω∞ = (limit − load − brake drag) / 5c with time constant J / 5c. Where
    /// `rpm` lies at or above ω∞ (the motor cannot hold it), the time to come within 1 %
    /// of ω∞. `None` where the limit cannot turn the rig against load and brake drag.
    pub fn run_up_from_rest_s(&self, rpm: f64, load_nm: f64) -> Option<f64> {
        let omega = rpm * std::f64::consts::PI / 30.0;
        let spare_nm = self.motor_torque_limit_nm() - load_nm - self.brake_drag_nm;
        if spare_nm <= 0.0 {
            return None;
        }
        let drag = 5.0 * self.bearing_drag_nms_per_rad;
        Some(crate::run_up_time::run_up_time_s(
            self.total_inertia_kgm2(),
            drag,
            spare_nm,
            omega,
        ))
    }

    pub fn validate(&self) -> Result<(), RigError> {
        self.check_positive()?;
        self.check_finite()?;
        self.check_options()?;
        self.check_geometry()?;
        self.check_loop_and_mesh()
    }

    /// The inertias, stiffnesses, module, controller and torque limit: finite and > 0.
    fn check_positive(&self) -> Result<(), RigError> {
        let positive = [
            ("j1_motor_kgm2", self.j1_motor_kgm2),
            ("j2_input_flywheel_kgm2", self.j2_input_flywheel_kgm2),
            ("j3_driven_gear_kgm2", self.j3_driven_gear_kgm2),
            ("j4_output_flywheel_kgm2", self.j4_output_flywheel_kgm2),
            ("j5_brake_kgm2", self.j5_brake_kgm2),
            (
                "k12_input_shaft_nm_per_rad",
                self.k12_input_shaft_nm_per_rad,
            ),
            ("k23_mesh_nm_per_rad", self.k23_mesh_nm_per_rad),
            (
                "k34_intermediate_shaft_nm_per_rad",
                self.k34_intermediate_shaft_nm_per_rad,
            ),
            (
                "k45_final_shaft_nm_per_rad",
                self.k45_final_shaft_nm_per_rad,
            ),
            ("module_m", self.module_m),
            (
                "double_pair_stiffness_ratio",
                self.double_pair_stiffness_ratio,
            ),
            ("speed_loop_damping_ratio", self.speed_loop_damping_ratio),
            ("speed_feedback_filter_hz", self.speed_feedback_filter_hz),
            ("drive_rated_power_w", self.drive_rated_power_w),
            ("drive_rated_speed_rpm", self.drive_rated_speed_rpm),
            ("drive_full_load_current_a", self.drive_full_load_current_a),
            ("drive_current_limit_pct", self.drive_current_limit_pct),
        ];
        for (name, value) in positive {
            require(name, value, value > 0.0, "must be a finite number > 0")?;
        }
        Ok(())
    }

    /// Damping, error torques and the brake slope: finite (any sign).
    fn check_finite(&self) -> Result<(), RigError> {
        let any_finite = [
            (
                "c12_input_shaft_nms_per_rad",
                self.c12_input_shaft_nms_per_rad,
            ),
            ("c23_mesh_nms_per_rad", self.c23_mesh_nms_per_rad),
            (
                "c34_intermediate_shaft_nms_per_rad",
                self.c34_intermediate_shaft_nms_per_rad,
            ),
            (
                "c45_final_shaft_nms_per_rad",
                self.c45_final_shaft_nms_per_rad,
            ),
            ("gear_error_c2_nm", self.gear_error_c2_nm),
            ("gear_error_c3_nm", self.gear_error_c3_nm),
            (
                "brake_speed_slope_nms_per_rad",
                self.brake_speed_slope_nms_per_rad,
            ),
        ];
        for (name, value) in any_finite {
            require(name, value, true, "must be a finite number")?;
        }
        Ok(())
    }

    /// The options off at 0: drags, the brake characteristic, transmission and spacing errors, residual drag.
    fn check_options(&self) -> Result<(), RigError> {
        for (name, value) in [
            ("bearing_drag_nms_per_rad", self.bearing_drag_nms_per_rad),
            ("brake_critical_speed_rpm", self.brake_critical_speed_rpm),
        ] {
            require(
                name,
                value,
                value >= 0.0,
                "must be a finite number ≥ 0 (0: off)",
            )?;
        }
        for (name, value) in [
            ("te_once_per_rev_um", self.te_once_per_rev_um),
            ("te_mesh_frequency_um", self.te_mesh_frequency_um),
        ] {
            require(name, value, true, "must be a finite number")?;
        }
        require(
            "tooth_spacing_error_um",
            self.tooth_spacing_error_um,
            self.tooth_spacing_error_um >= 0.0,
            "must be a finite RMS ≥ 0 µm (0: off)",
        )?;
        require(
            "brake_drag_nm",
            self.brake_drag_nm,
            self.brake_drag_nm >= 0.0,
            "must be a finite torque ≥ 0 N m",
        )?;
        Ok(())
    }

    /// The gears: teeth, pressure angle, addendum, centre-distance shift.
    fn check_geometry(&self) -> Result<(), RigError> {
        let teeth = f64::from(self.teeth);
        require(
            "teeth",
            teeth,
            self.teeth >= 5,
            "must be a whole number ≥ 5",
        )?;
        let alpha = self.pressure_angle_deg;
        require(
            "pressure_angle_deg",
            alpha,
            alpha > 0.0 && alpha < 45.0,
            "must lie in (0, 45) degrees",
        )?;
        let ha = self.addendum_coefficient;
        require(
            "addendum_coefficient",
            ha,
            ha > 0.0 && ha <= 1.5,
            "must lie in (0, 1.5]",
        )?;
        let shift = self.centre_distance_shift_m;
        require(
            "centre_distance_shift_m",
            shift,
            shift >= 0.0 && shift < self.module_m,
            "must lie in [0, module_m)",
        )?;
        Ok(())
    }

    /// The speed loop, the mesh stiffness smoothing and the backlash variation.
    fn check_loop_and_mesh(&self) -> Result<(), RigError> {
        let loop_hz = self.speed_loop_hz;
        require(
            "speed_loop_hz",
            loop_hz,
            loop_hz >= 0.0,
            "must be a finite number ≥ 0 (0 switches the speed loop off)",
        )?;
        let smoothing = self.mesh_stiffness_smoothing;
        require(
            "mesh_stiffness_smoothing",
            smoothing,
            (0.0..=1.0).contains(&smoothing),
            "must lie in [0, 1] (a fraction of the tooth pitch)",
        )?;
        let c1 = self.backlash_variation_c1;
        require(
            "backlash_variation_c1",
            c1,
            (0.0..1.0).contains(&c1),
            "must lie in [0, 1)",
        )?;
        Ok(())
    }
}

fn require(name: &str, value: f64, ok: bool, allowed: &str) -> Result<(), RigError> {
    if value.is_finite() && ok {
        Ok(())
    } else {
        Err(RigError::InvalidParameter {
            name: name.to_string(),
            value: value.to_string(),
            allowed: allowed.to_string(),
        })
    }
}
