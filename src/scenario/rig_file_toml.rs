//! The rig file's schema (TOML; `docs/rig-files.md`): bodies, shafts, meshes, planetary
//! stages, the motor's
//! and the brake's body, the torque locked into a loop, the gauged shaft, the tacho's
//! body and the keyphasor's gear. Unknown keys are refused; every
//! value keeps its place in the file for errors.

use serde::Deserialize;
use toml::Spanned;

/// A rig file.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct RigFileToml {
    /// The rig's name.
    pub name: Spanned<String>,
    /// What it is.
    #[serde(default)]
    pub description: Option<String>,
    /// The published rig it is (`"basmaji-1983"`): its healthy sweeps are then held
    /// against that publication's findings, as a preset's are.
    #[serde(default)]
    pub reproduces: Option<Spanned<String>>,
    /// `[[body]]` tables.
    #[serde(default, rename = "body")]
    pub bodies: Vec<BodyToml>,
    /// `[[shaft]]` tables.
    #[serde(default, rename = "shaft")]
    pub shafts: Vec<ShaftToml>,
    /// `[[mesh]]` tables.
    #[serde(default, rename = "mesh")]
    pub meshes: Vec<MeshToml>,
    /// `[[planetary]]` tables.
    #[serde(default)]
    pub planetary: Vec<PlanetaryToml>,
    /// `[motor]`: the body the motor drives, its speed loop and torque limit.
    pub motor: Option<MotorToml>,
    /// `[brake]`: the body the brake loads.
    pub brake: Option<BrakeToml>,
    /// `[locked_torque]`: a back-to-back loop's locked-in torque.
    pub locked_torque: Option<LockedTorqueToml>,
    /// `[gauge]`: the strain gauges' shaft.
    pub gauge: Option<GaugeToml>,
    /// `[tacho]`: the body the tacho generator turns with.
    pub tacho: Option<TachoToml>,
    /// `[keyphasor]`: the gear whose revolutions it marks.
    pub keyphasor: Option<KeyphasorToml>,
}

/// `[keyphasor]`: a once-per-revolution mark on a gear.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct KeyphasorToml {
    /// The gear, by its body's name: a gear of some mesh.
    pub gear: Spanned<String>,
}

/// `[tacho]`: the tacho generator on a body.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct TachoToml {
    /// The body, by name; the motor's when the file has no `[tacho]`.
    pub body: Spanned<String>,
}

/// `[gauge]`: strain gauges on a shaft.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct GaugeToml {
    /// The shaft, by name.
    pub shaft: Spanned<String>,
    /// Its diameter where gauged (m).
    pub diameter_m: Spanned<f64>,
    /// Its shear modulus (Pa); steel's 80 GPa when left out.
    #[serde(default)]
    pub shear_modulus_pa: Option<Spanned<f64>>,
}

/// `[[body]]`: one rotating inertia.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct BodyToml {
    /// Unique name.
    pub name: Spanned<String>,
    /// Moment of inertia (kg m²).
    pub inertia_kgm2: Spanned<f64>,
    /// Bearing and windage drag (N m s/rad); 0 when left out.
    #[serde(default)]
    pub drag_nms_per_rad: Option<Spanned<f64>>,
    /// Mass (kg): with `bearing_stiffness_n_per_m`, the body moves in the plane.
    #[serde(default)]
    pub mass_kg: Option<Spanned<f64>>,
    /// Its bearing's radial stiffness to the frame (N/m), isotropic.
    #[serde(default)]
    pub bearing_stiffness_n_per_m: Option<Spanned<f64>>,
    /// Its bearing's radial damping (N s/m); 0 when left out.
    #[serde(default)]
    pub bearing_damping_ns_per_m: Option<Spanned<f64>>,
}

/// `[[shaft]]`: a torsional spring-damper between two bodies.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct ShaftToml {
    /// Unique name.
    pub name: Spanned<String>,
    /// The two bodies it joins, by name.
    pub between: Spanned<Vec<Spanned<String>>>,
    /// Torsional stiffness (N m/rad).
    pub stiffness_nm_per_rad: Spanned<f64>,
    /// Torsional damping (N m s/rad); 0 when left out.
    #[serde(default)]
    pub damping_nms_per_rad: Option<Spanned<f64>>,
}

/// `[[mesh]]`: an external spur pair with backlash.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct MeshToml {
    /// Unique name.
    pub name: Spanned<String>,
    /// The driving gear's body.
    pub driver: Spanned<String>,
    /// The driven gear's body.
    pub driven: Spanned<String>,
    /// Teeth of the driver and the driven gear.
    pub teeth: Spanned<Vec<u32>>,
    /// Module (m).
    pub module_m: Spanned<f64>,
    /// Pressure angle (degrees); 20 when left out.
    #[serde(default)]
    pub pressure_angle_deg: Option<Spanned<f64>>,
    /// Total circular backlash at the pitch circles (mm).
    pub backlash_mm: Spanned<f64>,
    /// Operating centre distance over the standard (mm), for the contact ratio; 0 when
    /// left out.
    #[serde(default)]
    pub centre_distance_shift_mm: Option<Spanned<f64>>,
    /// Direction of the line from the driver's centre to the driven gear's (degrees);
    /// 0 when left out.
    #[serde(default)]
    pub centre_line_deg: Option<Spanned<f64>>,
    /// Stiffness of one tooth pair along the line of action (N/m); left out, the
    /// potential-energy method gives it from `face_width_m` (docs/faults.md).
    #[serde(default)]
    pub stiffness_n_per_m: Option<Spanned<f64>>,
    /// Face width (m), for the potential-energy method.
    #[serde(default)]
    pub face_width_m: Option<Spanned<f64>>,
    /// Young's modulus (Pa) for the potential-energy method; steel's 206 GPa when left
    /// out.
    #[serde(default)]
    pub youngs_modulus_pa: Option<Spanned<f64>>,
    /// Poisson's ratio for the potential-energy method; steel's 0.3 when left out.
    #[serde(default)]
    pub poisson_ratio: Option<Spanned<f64>>,
    /// The gears' bore diameter (m) for the potential-energy method's fillet foundation;
    /// each gear's base radius when left out (a bore radius of half the base radius).
    #[serde(default)]
    pub bore_diameter_m: Option<Spanned<f64>>,
    /// Damping along the line of action (N s/m); 0 when left out.
    #[serde(default)]
    pub damping_ns_per_m: Option<Spanned<f64>>,
    /// `single` or `alternating`; single when left out.
    #[serde(default)]
    pub pairs: Option<Spanned<String>>,
    /// `thesis` or `no-pull`; thesis when left out.
    #[serde(default)]
    pub contact_law: Option<Spanned<String>>,
    /// Two pairs' stiffness over one's; 2 when left out.
    #[serde(default)]
    pub double_pair_ratio: Option<Spanned<f64>>,
    /// Width of each change between one and two pairs over the pitch; 0 when left out.
    #[serde(default)]
    pub stiffness_smoothing: Option<Spanned<f64>>,
    /// Addendum over the module; 1 when left out.
    #[serde(default)]
    pub addendum_coefficient: Option<Spanned<f64>>,
    /// Backlash variation C1; 0 when left out.
    #[serde(default)]
    pub backlash_variation: Option<Spanned<f64>>,
    /// Transmission error once per revolution (µm); 0 when left out.
    #[serde(default)]
    pub te_once_per_rev_um: Option<Spanned<f64>>,
    /// Transmission error at mesh frequency (µm); 0 when left out.
    #[serde(default)]
    pub te_mesh_frequency_um: Option<Spanned<f64>>,
    /// The thesis's numerical tooth shifting; false when left out.
    #[serde(default)]
    pub tooth_shifting: Option<bool>,
    /// RMS of the tooth-pair spacing errors along the line of action (µm); 0 when left out.
    #[serde(default)]
    pub tooth_spacing_error_um: Option<Spanned<f64>>,
    /// Seed of the spacing errors; 0 when left out.
    #[serde(default)]
    pub tooth_spacing_seed: Option<u32>,
    /// Run-out of the driving gear (µm); 0 when left out.
    #[serde(default)]
    pub run_out_driver_um: Option<Spanned<f64>>,
    /// Run-out of the driven gear (µm); 0 when left out.
    #[serde(default)]
    pub run_out_driven_um: Option<Spanned<f64>>,
    /// Gear-error torque once per revolution of the driver, C2 (N m); 0 when left out.
    #[serde(default)]
    pub gear_error_c2_nm: Option<Spanned<f64>>,
    /// Gear-error torque twice per revolution, C3 (N m); 0 when left out.
    #[serde(default)]
    pub gear_error_c3_nm: Option<Spanned<f64>>,
    /// `[[mesh.fault]]`: faults seeded on single teeth.
    #[serde(default)]
    pub fault: Vec<FaultToml>,
}

/// `[[planetary]]`: a planetary stage on three bodies of the file.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct PlanetaryToml {
    /// Unique name; its planets are `<name>_planet<k>`.
    pub name: Spanned<String>,
    /// The sun's body.
    pub sun: Spanned<String>,
    /// The ring's body.
    pub ring: Spanned<String>,
    /// The carrier's body.
    pub carrier: Spanned<String>,
    /// Number of planets, 1 to 8.
    pub planets: Spanned<u32>,
    /// Each planet's angle on the carrier (degrees); equally spaced when left out.
    #[serde(default)]
    pub planet_angles_deg: Option<Spanned<Vec<f64>>>,
    /// Each planet's moment of inertia (kg m²).
    pub planet_inertia_kgm2: Spanned<f64>,
    /// Each planet's tangential pin position error (µm); none when left out.
    #[serde(default)]
    pub planet_pin_errors_um: Option<Spanned<Vec<f64>>>,
    /// Each planet's mass (kg): with `planet_bearing_stiffness_n_per_m`, planets move on
    /// their pins' bearings.
    #[serde(default)]
    pub planet_mass_kg: Option<Spanned<f64>>,
    /// Each pin bearing's radial stiffness (N/m).
    #[serde(default)]
    pub planet_bearing_stiffness_n_per_m: Option<Spanned<f64>>,
    /// Each pin bearing's radial damping (N s/m); 0 when left out.
    #[serde(default)]
    pub planet_bearing_damping_ns_per_m: Option<Spanned<f64>>,
    /// Teeth of the sun, each planet and the ring.
    pub teeth: Spanned<StageTeethToml>,
    /// Module (m).
    pub module_m: Spanned<f64>,
    /// Pressure angle (degrees); 20 when left out.
    #[serde(default)]
    pub pressure_angle_deg: Option<Spanned<f64>>,
    /// Base diameters as a publication gives them (m); m z cos α when left out.
    #[serde(default)]
    pub base_diameter_m: Option<Spanned<StageDiametersToml>>,
    /// Radius of the planets' centres (m); the centre distance when left out.
    #[serde(default)]
    pub carrier_radius_m: Option<Spanned<f64>>,
    /// The sun–planet meshes.
    pub sun_planet: Spanned<StageMeshToml>,
    /// The ring–planet meshes.
    pub ring_planet: Spanned<StageMeshToml>,
    /// `[[planetary.fault]]`: faults seeded on single teeth of the sun, a planet or the
    /// ring (`gear = "sun" | "ring" | "planet<k>"`).
    #[serde(default)]
    pub fault: Vec<FaultToml>,
    /// A transducer on the ring: its signal `sensor_<stage>_n`.
    #[serde(default)]
    pub ring_sensor: Option<Spanned<RingSensorToml>>,
}

/// `ring_sensor = { angle_deg = 90.0, window_deg = 120.0 }`.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct RingSensorToml {
    /// Its place on the ring (degrees from the first planet's place at the start, the way
    /// the planets' angles are measured).
    pub angle_deg: f64,
    /// The window's full width over a planet's passage (degrees); 360/N when left out.
    #[serde(default)]
    pub window_deg: Option<f64>,
}

/// `teeth = { sun = 24, planet = 36, ring = 96 }`.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct StageTeethToml {
    /// The sun's.
    pub sun: u32,
    /// Each planet's.
    pub planet: u32,
    /// The ring's.
    pub ring: u32,
}

/// `base_diameter_m = { sun = …, planet = …, ring = … }` (m).
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct StageDiametersToml {
    /// The sun's (m).
    pub sun: f64,
    /// Each planet's (m).
    pub planet: f64,
    /// The ring's (m).
    pub ring: f64,
}

/// A stage's mesh: `{ stiffness_n_per_m = …, damping_ns_per_m = …, backlash_mm = … }`.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct StageMeshToml {
    /// Stiffness along the line of action (N/m).
    pub stiffness_n_per_m: f64,
    /// Damping along the line of action (N s/m); 0 when left out.
    #[serde(default)]
    pub damping_ns_per_m: f64,
    /// Total circular backlash at the pitch circles (mm).
    pub backlash_mm: f64,
    /// `single` or `alternating`; single when left out.
    #[serde(default)]
    pub pairs: Option<Spanned<String>>,
    /// Two pairs' stiffness over one's; 2 when left out.
    #[serde(default)]
    pub double_pair_ratio: Option<Spanned<f64>>,
    /// Width of each change between one and two pairs over the pitch; 0 when left out.
    #[serde(default)]
    pub stiffness_smoothing: Option<Spanned<f64>>,
}

/// `[[mesh.fault]]`: a fault on one tooth of the mesh above it (a sweep's
/// `[[rig.fault]]`: of the mesh it names).
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct FaultToml {
    /// The mesh, by name: a sweep's `[[rig.fault]]` only (in a rig file the fault belongs
    /// to the mesh above it).
    #[serde(default)]
    pub mesh: Option<Spanned<String>>,
    /// `driver` or `driven`.
    pub gear: Spanned<String>,
    /// The tooth, 1..=z of that gear.
    pub tooth: Spanned<u32>,
    /// `crack`, `pit` or `broken`.
    pub kind: Spanned<String>,
    /// The pitted share of the contact width, or the broken share of the face, 0..=1.
    pub severity: Spanned<f64>,
}

/// `[motor]`: the body it drives, its speed loop and its torque limit.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct MotorToml {
    /// The body, by name.
    pub body: Spanned<String>,
    /// Most torque either way (N m); no limit when left out.
    #[serde(default)]
    pub torque_limit_nm: Option<Spanned<f64>>,
    /// Speed-loop natural frequency (Hz); 0.5 when left out.
    #[serde(default)]
    pub speed_loop_hz: Option<Spanned<f64>>,
    /// Speed-loop damping ratio; 0.7 when left out.
    #[serde(default)]
    pub speed_loop_damping_ratio: Option<Spanned<f64>>,
    /// Speed feedback filter corner (Hz); 2 when left out.
    #[serde(default)]
    pub feedback_filter_hz: Option<Spanned<f64>>,
    /// The drive's rated output (W): with `rated_speed_rpm`, its torque limit instead of
    /// `torque_limit_nm`.
    #[serde(default)]
    pub rated_power_w: Option<Spanned<f64>>,
    /// The drive's rated speed (rev/min).
    #[serde(default)]
    pub rated_speed_rpm: Option<Spanned<f64>>,
    /// The drive's full-load armature current (A), for its torque constant.
    #[serde(default)]
    pub full_load_current_a: Option<Spanned<f64>>,
    /// The armature current limit over full-load current (%); 100 when left out.
    #[serde(default)]
    pub current_limit_pct: Option<Spanned<f64>>,
}

/// `[brake]`: the body it loads and its torque's slope with speed.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct BrakeToml {
    /// The body, by name.
    pub body: Spanned<String>,
    /// Rise of torque with speed (N m s/rad); 0 when left out.
    #[serde(default)]
    pub slope_nms_per_rad: Option<Spanned<f64>>,
    /// Residual drag added to the set load (N m); 0 when left out.
    #[serde(default)]
    pub drag_nm: Option<Spanned<f64>>,
    /// The eddy-current characteristic's critical speed (rev/min); 0 (off) when left out.
    #[serde(default)]
    pub critical_speed_rpm: Option<Spanned<f64>>,
}

/// `[locked_torque]`: the twist locked into one shaft of a back-to-back loop.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct LockedTorqueToml {
    /// The shaft, by name.
    pub shaft: Spanned<String>,
    /// The torque it carries at rest (N m).
    pub torque_nm: Spanned<f64>,
}
