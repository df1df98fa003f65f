//! Named access to every parameter: list, read and override by name.

use crate::error::RigError;
use crate::geometry::{GearGeometry, centre_distance_shift_m};
use crate::nearest::did_you_mean;
use crate::options::{ContactLaw, MeshPairs};
use crate::params::RigParams;

/// One parameter as the command line and scenarios see it.
pub struct ParamSpec {
    /// Name used by `--set NAME=VALUE` and in scenarios.
    pub name: &'static str,
    /// Unit of the value ("1" for dimensionless, "-" for a choice or switch).
    pub unit: &'static str,
    /// What it means and where the preset value comes from.
    pub meaning: &'static str,
    get: fn(&RigParams) -> String,
    set: fn(&mut RigParams, &ParamValue) -> Result<(), String>,
}

/// A parameter's value as a caller holds it, before it is checked against the
/// parameter's type: a number, a switch, or text (a name such as `no-pull`, or a number
/// written out, as `--set NAME=VALUE` gives it).
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum ParamValue<'a> {
    /// A number (an integer parameter takes a whole one).
    Number(f64),
    /// On or off.
    Switch(bool),
    /// Text, parsed as the parameter's type.
    Text(&'a str),
}

impl ParamSpec {
    /// The parameter's current value in `params`, as text.
    pub fn value(&self, params: &RigParams) -> String {
        (self.get)(params)
    }
}

/// A value type that can be read from and written to text, or taken from a
/// [`ParamValue`] of its own kind.
trait ParamText: Sized {
    fn parse_text(text: &str) -> Result<Self, String>;
    fn show(&self) -> String;
    /// The value of a number or switch (without text between); text is parsed.
    fn from_value(value: &ParamValue) -> Result<Self, String> {
        match value {
            ParamValue::Text(text) => Self::parse_text(text),
            ParamValue::Number(x) => Err(format!("{x} is not a value of this parameter")),
            ParamValue::Switch(b) => Err(format!("{b} is not a value of this parameter")),
        }
    }
}

impl ParamText for f64 {
    fn parse_text(text: &str) -> Result<Self, String> {
        let value: f64 = text
            .trim()
            .parse()
            .map_err(|_| format!("`{text}` is not a number"))?;
        if value.is_finite() {
            Ok(value)
        } else {
            Err(format!("`{text}` is not a finite number"))
        }
    }
    fn show(&self) -> String {
        format!("{self}")
    }
    fn from_value(value: &ParamValue) -> Result<Self, String> {
        match *value {
            ParamValue::Number(x) if x.is_finite() => Ok(x),
            ParamValue::Number(x) => Err(format!("{x} is not a finite number")),
            ParamValue::Switch(b) => Err(format!("{b} is not a number")),
            ParamValue::Text(text) => Self::parse_text(text),
        }
    }
}

impl ParamText for u32 {
    fn parse_text(text: &str) -> Result<Self, String> {
        text.trim()
            .parse()
            .map_err(|_| format!("`{text}` is not a whole number"))
    }
    fn show(&self) -> String {
        format!("{self}")
    }
    fn from_value(value: &ParamValue) -> Result<Self, String> {
        match *value {
            ParamValue::Number(x)
                if x.fract() == 0.0 && (0.0..=f64::from(u32::MAX)).contains(&x) =>
            {
                Ok(x as u32)
            }
            ParamValue::Number(x) => Err(format!("{x} is not a whole number ≥ 0")),
            ParamValue::Switch(b) => Err(format!("{b} is not a whole number")),
            ParamValue::Text(text) => Self::parse_text(text),
        }
    }
}

impl ParamText for bool {
    fn parse_text(text: &str) -> Result<Self, String> {
        match text.trim() {
            "true" | "on" | "1" => Ok(true),
            "false" | "off" | "0" => Ok(false),
            _ => Err(format!("`{text}` is not true/false")),
        }
    }
    fn show(&self) -> String {
        format!("{self}")
    }
    fn from_value(value: &ParamValue) -> Result<Self, String> {
        match *value {
            ParamValue::Switch(b) => Ok(b),
            ParamValue::Number(x) => Err(format!("{x} is not true/false")),
            ParamValue::Text(text) => Self::parse_text(text),
        }
    }
}

impl ParamText for ContactLaw {
    fn parse_text(text: &str) -> Result<Self, String> {
        Self::parse(text.trim()).ok_or_else(|| format!("`{text}` is not one of {}", Self::NAMES))
    }
    fn show(&self) -> String {
        self.name().to_string()
    }
}

impl ParamText for MeshPairs {
    fn parse_text(text: &str) -> Result<Self, String> {
        Self::parse(text.trim()).ok_or_else(|| format!("`{text}` is not one of {}", Self::NAMES))
    }
    fn show(&self) -> String {
        self.name().to_string()
    }
}

macro_rules! param_specs {
    ($( $field:ident, $unit:literal, $meaning:literal; )*) => {
        /// Every parameter of [`RigParams`], in declaration order.
        pub static PARAM_SPECS: &[ParamSpec] = &[
            $( ParamSpec {
                name: stringify!($field),
                unit: $unit,
                meaning: $meaning,
                get: |p| ParamText::show(&p.$field),
                set: |p, value| {
                    p.$field = ParamText::from_value(value)?;
                    Ok(())
                },
            }, )*
        ];
    };
}

param_specs! {
    j1_motor_kgm2, "kg m^2", "M1 DC motor rotor inertia (thesis App. B: 0.0163)";
    j2_input_flywheel_kgm2, "kg m^2", "M2 fixed flywheel + driving gear (App. B: 0.355)";
    j3_driven_gear_kgm2, "kg m^2", "M3 driven gear alone (App. B: 0.00865)";
    j4_output_flywheel_kgm2, "kg m^2", "M4 movable output flywheel (App. B: 0.45)";
    j5_brake_kgm2, "kg m^2", "M5 eddy-current brake rotor (App. B: 0.015)";
    k12_input_shaft_nm_per_rad, "N m/rad", "K12 input shaft, dia 20 x 250 mm (App. C: 5196.2)";
    k23_mesh_nm_per_rad, "N m/rad", "K23 one tooth pair in contact (App. C: 1.3e6)";
    k34_intermediate_shaft_nm_per_rad, "N m/rad", "K34 intermediate shaft, dia 20 x 500 mm, strain gauges (App. C: 2598.1)";
    k45_final_shaft_nm_per_rad, "N m/rad", "K45 final shaft, dia 20 x 300 mm (App. C: 4330.2)";
    c12_input_shaft_nms_per_rad, "N m s/rad", "C12 input shaft damping (thesis FCN1-3: 9.03376 x M1 = 0.1473)";
    c23_mesh_nms_per_rad, "N m s/rad", "C23 mesh contact damping, one pair (FCN1-3: 382.726 x M2 = 135.8)";
    c34_intermediate_shaft_nms_per_rad, "N m s/rad", "C34 intermediate shaft damping (FCN1-3: 0.0946)";
    c45_final_shaft_nms_per_rad, "N m s/rad", "C45 final shaft damping (FCN1-3: 0.1589)";
    teeth, "1", "teeth on each gear of the 1:1 pair (thesis: 30)";
    module_m, "m", "gear module (thesis: 5 mm, PCD 150 mm)";
    pressure_angle_deg, "deg", "standard pressure angle (thesis: 20)";
    addendum_coefficient, "1", "addendum / module (standard full depth: 1.0; thesis silent)";
    centre_distance_shift_m, "m", "centre distance increase setting the backlash 2B1 = 2 dC tan(alpha) (experiments: 1.0 mm)";
    contact_law, "-", "mesh contact law: thesis (eq. 5.6, damper may pull) or no-pull (torque clipped at 0)";
    tooth_shifting, "-", "numerical tooth shifting at every tooth pass (thesis 5.4.5)";
    backlash_variation_c1, "1", "C1 in B(1 - C1 cos Omega t) (thesis 6.5.1: 0.38)";
    gear_error_c2_nm, "N m", "C2 once-per-rev gear error torque on M2 and M3 (thesis: not given)";
    gear_error_c3_nm, "N m", "C3 twice-per-rev gear error torque on M2 and M3 (thesis: not given)";
    mesh_pairs, "-", "tooth pairs sharing the load: single (thesis) or alternating (contact ratio from geometry)";
    double_pair_stiffness_ratio, "1", "mesh stiffness and damping with two pairs / one pair (two pairs in parallel: 2)";
    mesh_stiffness_smoothing, "1", "width of each single/double pair change as a fraction of the pitch, 4-step staircase (thesis: one pair, 0 = sharp)";
    speed_loop_hz, "Hz", "closed speed-loop natural frequency on the whole rig inertia (thesis silent: 0.5)";
    speed_loop_damping_ratio, "1", "closed speed-loop damping ratio (thesis silent: 0.7)";
    speed_feedback_filter_hz, "Hz", "low-pass on the controller's speed feedback (thesis silent: 2)";
    drive_rated_power_w, "W", "DC drive nameplate output: Hainsworth Speedrange 2.0 hp = 1491.4";
    drive_rated_speed_rpm, "rev/min", "DC drive rated speed: max 2000; rated power there gives the full-load torque 7.12 N m";
    drive_full_load_current_a, "A", "DC drive full-load armature current: F.L.C. 10.0 A; torque constant = full-load torque / F.L.C. = 0.712 N m/A";
    drive_current_limit_pct, "%", "armature current limit / F.L.C.: the torque limit either way (100 = 7.12 N m; drives of the day set 100-200 for intermittent duty)";
    brake_speed_slope_nms_per_rad, "N m s/rad", "brake torque slope with speed (thesis: constant torque, 0)";
    brake_drag_nm, "N m", "residual drag added to the set load: bearings, seals, windage, brake remanence (thesis: none, 0)";
    bearing_drag_nms_per_rad, "N m s/rad", "speed-proportional bearing and windage drag on each of the five bodies (thesis: none, 0)";
    brake_critical_speed_rpm, "rev/min", "eddy-current brake critical speed, T ~ 2x/(1+x^2), x = w/wc, set load at set speed (Wouterse 1991; thesis: constant torque, 0 = off)";
    te_once_per_rev_um, "um", "once-per-rev transmission error as a mesh displacement, arc at the pitch circle (thesis: none, 0)";
    te_mesh_frequency_um, "um", "profile error at mesh frequency (teeth x rev) as a mesh displacement, arc at the pitch circle (thesis: none, 0)";
    tooth_spacing_error_um, "um", "RMS of the tooth-pair spacing errors, each pair displaced by its own error while in mesh, arc at the pitch circle (thesis: none, 0; it cites them as why impacts skip teeth)";
    tooth_spacing_seed, "1", "seed of the tooth-pair spacing errors (normal, made zero-mean, scaled to the RMS)";
}

/// Parameters derived from others that can be set by name too: each sets the stored
/// parameter it is derived from. `backlash_mm` is the total circular backlash 2B₁ at the
/// pitch circle, set through the centre-distance shift (2B₁ = 2 ΔC tan α, rig-spec §1).
pub static DERIVED_SPECS: &[ParamSpec] = &[ParamSpec {
    name: "backlash_mm",
    unit: "mm",
    meaning: "total circular backlash 2B1 at the pitch circle, > 0; sets centre_distance_shift_m (experiments: 1.0 mm)",
    get: |p| format!("{}", GearGeometry::of(p).circular_backlash_m * 1e3),
    set: |p, value| {
        let backlash_mm = f64::from_value(value)?;
        if backlash_mm <= 0.0 {
            return Err(format!("{backlash_mm}: a circular backlash > 0 (mm)"));
        }
        p.centre_distance_shift_m = centre_distance_shift_m(p, backlash_mm * 1e-3);
        Ok(())
    },
}];

/// Looks a parameter up by name, stored ([`PARAM_SPECS`]) or derived ([`DERIVED_SPECS`]).
pub fn param_spec(name: &str) -> Result<&'static ParamSpec, RigError> {
    PARAM_SPECS
        .iter()
        .chain(DERIVED_SPECS)
        .find(|spec| spec.name == name)
        .ok_or_else(|| RigError::UnknownParameter {
            name: name.to_string(),
            near: did_you_mean(
                name,
                PARAM_SPECS.iter().chain(DERIVED_SPECS).map(|s| s.name),
            ),
        })
}

/// Sets one parameter by name from its text form, then validates the whole set.
pub fn set_param(params: &mut RigParams, name: &str, text: &str) -> Result<(), RigError> {
    set_param_value(params, name, ParamValue::Text(text))
}

/// Sets one parameter by name to `value` (a number, a switch or text, checked against
/// the parameter's type), then validates the whole set.
pub fn set_param_value(
    params: &mut RigParams,
    name: &str,
    value: ParamValue,
) -> Result<(), RigError> {
    let spec = param_spec(name)?;
    let mut changed = params.clone();
    (spec.set)(&mut changed, &value).map_err(|allowed| RigError::InvalidParameter {
        name: name.to_string(),
        value: match value {
            ParamValue::Number(x) => x.to_string(),
            ParamValue::Switch(b) => b.to_string(),
            ParamValue::Text(text) => text.to_string(),
        },
        allowed,
    })?;
    changed.validate()?;
    *params = changed;
    Ok(())
}
