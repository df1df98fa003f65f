//! A rig of any topology, as a rig file describes it: rotating bodies (some moving in the
//! plane on their bearings), torsional shafts between two bodies or from a body to the
//! frame, external spur meshes with backlash between two gears' base circles, and
//! planetary stages (`planetary.rs`); a motor body, a brake body, and for a back-to-back
//! loop the torque locked into one shaft. SI inside, units in the names. Built from a rig file by the
//! application; checked by [`RigTopology::check`] (`check.rs`); its natural frequencies
//! by [`RigTopology::natural_frequencies_hz`] (`modes.rs`).

use serde::{Deserialize, Serialize};

use crate::mesh_stiffness::PairGeometry;
use crate::options::{ContactLaw, MeshPairs};
use crate::tooth_fault::ToothFault;

use super::planetary::{PlanarBearing, PlanetaryStage};

/// Most bodies a rig may have.
pub const MAX_BODIES: usize = 32;
/// Most meshes of every kind a rig may have: external meshes and each planetary stage's
/// sun–planet and ring–planet meshes.
pub const MAX_PLANT_MESHES: usize = 20;

/// One rotating inertia.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct Body {
    /// Its name, unique in the rig.
    pub name: String,
    /// Moment of inertia about its axis (kg m²).
    pub inertia_kgm2: f64,
    /// Bearing and windage drag on its absolute speed (N m s/rad); 0 for none.
    pub drag_nms_per_rad: f64,
    /// Its mass and bearing, if it moves in the plane (x, y beside its rotation); `None`:
    /// its axis held rigidly.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub planar: Option<PlanarBearing>,
}

/// A torsional spring-damper from a body to the frame (a rig file's shaft with
/// `between = [body, "frame"]`): it holds the body's rotation, as a housing holds a ring
/// gear.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct FrameShaft {
    /// Its name, unique among the rig's shafts.
    pub name: String,
    /// The body it holds (index).
    pub body: usize,
    /// Torsional stiffness (N m/rad).
    pub stiffness_nm_per_rad: f64,
    /// Torsional viscous damping (N m s/rad).
    pub damping_nms_per_rad: f64,
}

/// A torsional spring-damper between two bodies.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct Shaft {
    /// Its name, unique in the rig.
    pub name: String,
    /// The bodies it joins (indices into the rig's bodies).
    pub between: [usize; 2],
    /// Torsional stiffness (N m/rad).
    pub stiffness_nm_per_rad: f64,
    /// Torsional viscous damping (N m s/rad).
    pub damping_nms_per_rad: f64,
}

/// An external spur pair with backlash: a spring-damper along the line of action between
/// the two gears' base circles, apart within the backlash.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct Mesh {
    /// Its name, unique in the rig.
    pub name: String,
    /// The driving gear's body and the driven gear's body (indices).
    pub gears: [usize; 2],
    /// Teeth of the driving and the driven gear.
    pub teeth: [u32; 2],
    /// Module (m).
    pub module_m: f64,
    /// Pressure angle (degrees).
    pub pressure_angle_deg: f64,
    /// Total circular backlash at the pitch circles (mm).
    pub backlash_mm: f64,
    /// Increase of the operating centre distance over the standard m(z₁ + z₂)/2 (mm; 0:
    /// standard), where the contact ratio is taken (the 1983 rig's backlash is the
    /// 1 mm shift's, 2ΔC tan α).
    #[serde(default, skip_serializing_if = "is_zero")]
    pub centre_distance_shift_mm: f64,
    /// Direction of the line from the driver's centre to the driven gear's (degrees from
    /// the x axis; 0 when left out): where its line of action lies in the plane, which
    /// matters only where a gear moves in the plane.
    #[serde(default, skip_serializing_if = "is_zero")]
    pub centre_line_deg: f64,
    /// Stiffness of one tooth pair along the line of action (N/m).
    pub stiffness_n_per_m: f64,
    /// Damping along the line of action (N s/m).
    pub damping_ns_per_m: f64,
    /// One tooth pair always, or one and two alternating as the contact ratio says.
    pub pairs: MeshPairs,
    /// The contact law: the thesis's spring-damper on the overlap (the damper may pull),
    /// or no-pull (the force clipped at zero while the teeth still overlap).
    #[serde(default, skip_serializing_if = "is_thesis_law")]
    pub contact_law: ContactLaw,
    /// Stiffness and damping of two pairs over one pair's (with `pairs` alternating).
    pub double_pair_ratio: f64,
    /// Width of each change between one and two pairs as a fraction of the tooth pitch
    /// (0: sharp; alternating pairs only), centred on the geometric change, as a
    /// staircase of four equal steps (`rig::pair_zones`; ISO 6336-1's gradual load take-up).
    #[serde(default, skip_serializing_if = "is_zero")]
    pub stiffness_smoothing: f64,
    /// Addendum over the module (standard teeth: 1), for the contact ratio.
    pub addendum_coefficient: f64,
    /// Backlash variation C1: the free play b(1 − C1 cos θ) once per revolution of the
    /// driver (thesis eq. 5.6's B(t); run-out of the centre distance), 0 ≤ C1 < 1.
    pub backlash_variation: f64,
    /// Transmission error once per revolution of the driver, E of
    /// e = E cos θ + P cos zθ along the line of action (µm).
    pub te_once_per_rev_um: f64,
    /// Transmission error at mesh frequency (profile error), P (µm).
    pub te_mesh_frequency_um: f64,
    /// The thesis's numerical tooth shifting (§5.4.5): at each tooth pass in contact the
    /// loaded pair hands its deflection back and the next starts undeflected.
    pub tooth_shifting: bool,
    /// Run-out (eccentricity) of the driving gear's pitch circle about its axis (µm): a
    /// transmission error e cos θ along the line of action, θ the driver's angle (its high
    /// point at angle 0), once per revolution of the driver.
    #[serde(default, skip_serializing_if = "is_zero")]
    pub run_out_driver_um: f64,
    /// Run-out of the driven gear (µm): e cos θ₂ once per revolution of the driven gear.
    #[serde(default, skip_serializing_if = "is_zero")]
    pub run_out_driven_um: f64,
    /// RMS of the teeth's spacing errors, as the pair in mesh displaces the mesh along the
    /// line of action (µm; 0 off): seeded normal draws (`tooth_spacing_seed`), made
    /// zero-mean and scaled, held while that pair is in mesh (`rig::spacing`).
    #[serde(default, skip_serializing_if = "is_zero")]
    pub tooth_spacing_error_um: f64,
    /// Seed of the spacing errors' draws.
    #[serde(default)]
    pub tooth_spacing_seed: u32,
    /// C2: a gear-error torque once per revolution of the driver, −C2 cos θ on both gears
    /// (each in its own sense of rotation), whether the teeth touch or not (thesis
    /// eq. 5.1's F2, F3; N m).
    #[serde(default, skip_serializing_if = "is_zero")]
    pub gear_error_c2_nm: f64,
    /// C3: the same twice per revolution, −C3 cos 2θ (N m).
    #[serde(default, skip_serializing_if = "is_zero")]
    pub gear_error_c3_nm: f64,
    /// Faults seeded on single teeth (none: a healthy pair).
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub faults: Vec<ToothFault>,
    /// The geometry and material `stiffness_n_per_m` was derived from by the
    /// potential-energy method (a file giving `face_width_m`), for `params` to show.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub potential_energy: Option<PairGeometry>,
}

impl Mesh {
    /// Base radii of the driving and the driven gear, r_b = m z cos α / 2 (m).
    pub fn base_radii_m(&self) -> [f64; 2] {
        let cos = self.pressure_angle_deg.to_radians().cos();
        self.teeth.map(|z| self.module_m * f64::from(z) * cos / 2.0)
    }

    /// Half the free play along the line of action (m): the circular backlash j at the
    /// pitch circles is j cos α along it.
    pub fn half_backlash_m(&self) -> f64 {
        0.5 * self.backlash_mm * 1e-3 * self.pressure_angle_deg.to_radians().cos()
    }

    /// Transverse contact ratio ε of standard gears at the operating centre distance
    /// a = m(z₁ + z₂)/2 + ΔC, operating pressure angle cos α_w = (r_b1 + r_b2)/a:
    /// (√(r_a1² − r_b1²) + √(r_a2² − r_b2²) − a sin α_w) / (π m cos α).
    pub fn contact_ratio(&self) -> f64 {
        let alpha = self.pressure_angle_deg.to_radians();
        let m = self.module_m;
        let [rb1, rb2] = self.base_radii_m();
        let [z1, z2] = self.teeth.map(f64::from);
        let ra = |z: f64| m * z / 2.0 + self.addendum_coefficient * m;
        let centre = m * (z1 + z2) / 2.0 + self.centre_distance_shift_mm * 1e-3;
        let alpha_w = ((rb1 + rb2) / centre).clamp(-1.0, 1.0).acos();
        let path = (ra(z1).powi(2) - rb1 * rb1).sqrt() + (ra(z2).powi(2) - rb2 * rb2).sqrt()
            - centre * alpha_w.sin();
        path / (std::f64::consts::PI * m * alpha.cos())
    }

    /// Whether the mesh has a once-per-revolution excitation (backlash variation or
    /// transmission error): it then turns harmonic states with the driver.
    pub fn excited(&self) -> bool {
        self.backlash_variation != 0.0
            || self.te_once_per_rev_um != 0.0
            || self.te_mesh_frequency_um != 0.0
            || self.run_out_driver_um != 0.0
            || self.run_out_driven_um != 0.0
            || self.gear_error_c2_nm != 0.0
            || self.gear_error_c3_nm != 0.0
    }

    /// Speed of the driven gear per unit speed of the driver: −z₁/z₂ (external gears turn
    /// opposite ways).
    pub fn speed_ratio(&self) -> f64 {
        -f64::from(self.teeth[0]) / f64::from(self.teeth[1])
    }
}

/// Whether a contact law is the thesis's (left out of a rig's JSON).
fn is_thesis_law(law: &ContactLaw) -> bool {
    *law == ContactLaw::Thesis
}

/// Whether a number is 0 (left out of a rig's JSON).
fn is_zero(x: &f64) -> bool {
    *x == 0.0
}

/// The torque locked into one shaft of a back-to-back loop at assembly.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct LockedTorque {
    /// The shaft twisted (index).
    pub shaft: usize,
    /// The torque it carries at rest (N m).
    pub torque_nm: f64,
}

/// Strain gauges on a shaft: its surface strain at ±45° from its torque, 16 T/(π d³ G)
/// shear, half of it as strain.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct Gauge {
    /// The gauged shaft (index).
    pub shaft: usize,
    /// Its diameter where gauged (m).
    pub diameter_m: f64,
    /// Its shear modulus (Pa).
    pub shear_modulus_pa: f64,
}

impl Gauge {
    /// Strain at +45° in µε per N m of the shaft's torque: 8 / (π d³ G) · 10⁶.
    pub fn microstrain_per_nm(&self) -> f64 {
        8.0e6 / (std::f64::consts::PI * self.diameter_m.powi(3) * self.shear_modulus_pa)
    }
}

/// A DC drive's nameplate and current limit, which bound its torque: rated power at
/// rated speed is the torque at full-load current, and the armature current limit as a
/// share of full-load current bounds the torque either way (the torque constant times
/// the current).
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct DriveRatings {
    /// Rated output (W).
    pub rated_power_w: f64,
    /// Rated (top) speed (rev/min).
    pub rated_speed_rpm: f64,
    /// Full-load armature current (A), for the torque constant; `None` where not given.
    pub full_load_current_a: Option<f64>,
    /// The armature current limit as a share of full-load current (%).
    pub current_limit_pct: f64,
}

impl DriveRatings {
    /// Torque at full-load current (N m): rated power over rated speed.
    pub fn full_load_torque_nm(&self) -> f64 {
        self.rated_power_w / (self.rated_speed_rpm * std::f64::consts::PI / 30.0)
    }

    /// The torque limit either way (N m): full-load torque times the current limit.
    pub fn torque_limit_nm(&self) -> f64 {
        self.full_load_torque_nm() * self.current_limit_pct / 100.0
    }
}

/// The drive and the load: the motor's speed loop and torque limit, the brake's
/// slope, drag and characteristic (settings beyond the topology; the 1983 rig's values
/// where a file is silent).
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct DriveSettings {
    /// Most torque the motor gives either way (N m), given as a number; `None`: none
    /// given (the ratings' limit, else no limit). See [`DriveSettings::limit_nm`].
    pub torque_limit_nm: Option<f64>,
    /// The drive's nameplate and current limit, whose torque limit holds where given.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub ratings: Option<DriveRatings>,
    /// Speed-loop natural frequency (Hz) on the whole rig's inertia seen at the motor.
    pub speed_loop_hz: f64,
    /// Speed-loop damping ratio.
    pub speed_loop_damping_ratio: f64,
    /// Corner of the first-order filter on the fed-back speed (Hz).
    pub feedback_filter_hz: f64,
    /// Rise of the brake's torque with its speed about the set speed (N m s/rad).
    pub brake_slope_nms_per_rad: f64,
    /// Residual drag at the brake (N m, ≥ 0): bearing and seal friction, windage and the
    /// brake's remanence, added to the set load (and present at zero set load).
    #[serde(default, skip_serializing_if = "is_zero")]
    pub brake_drag_nm: f64,
    /// Critical speed of the eddy-current brake (rev/min of the brake body, ≥ 0; 0 off):
    /// its torque at a fixed excitation follows T ∝ 2x/(1 + x²), x = ω/ω_c (Wouterse
    /// 1991), linearised about the set point where it brakes with load and drag.
    #[serde(default, skip_serializing_if = "is_zero")]
    pub brake_critical_speed_rpm: f64,
}

impl DriveSettings {
    /// The motor's torque limit either way (N m): the ratings', else the number given;
    /// `None`: no limit.
    pub fn limit_nm(&self) -> Option<f64> {
        self.ratings
            .as_ref()
            .map(DriveRatings::torque_limit_nm)
            .or(self.torque_limit_nm)
    }
}

impl Default for DriveSettings {
    /// The 1983 rig's speed loop (0.5 Hz, ζ 0.7, 2 Hz filter; `presets.rs`), no torque
    /// limit, a brake whose torque does not depend on speed.
    fn default() -> Self {
        Self {
            torque_limit_nm: None,
            speed_loop_hz: 0.5,
            speed_loop_damping_ratio: 0.7,
            feedback_filter_hz: 2.0,
            brake_slope_nms_per_rad: 0.0,
            brake_drag_nm: 0.0,
            brake_critical_speed_rpm: 0.0,
            ratings: None,
        }
    }
}

/// A whole rig.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct RigTopology {
    /// The rig's name.
    pub name: String,
    /// What it is (free text).
    pub description: String,
    /// The published rig it is, whose findings its sweeps are held against
    /// ([`RigTopology::REPRODUCIBLE`]); `None` for a rig of its own.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub reproduces: Option<String>,
    /// Its bodies.
    pub bodies: Vec<Body>,
    /// Its shafts.
    pub shafts: Vec<Shaft>,
    /// Its meshes.
    pub meshes: Vec<Mesh>,
    /// Its shafts to the frame.
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub frame_shafts: Vec<FrameShaft>,
    /// Its planetary stages.
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub planetary: Vec<PlanetaryStage>,
    /// The body the motor drives (index).
    pub motor: Option<usize>,
    /// The body the brake loads (index).
    pub brake: Option<usize>,
    /// The torque locked into a loop's shaft, if any.
    pub locked_torque: Option<LockedTorque>,
    /// The motor's speed loop and limit, the brake's slope.
    pub drive: DriveSettings,
    /// The strain gauges, if the rig has them.
    pub gauge: Option<Gauge>,
    /// The body the tacho generator turns with (index); the motor's when `None`.
    #[serde(default)]
    pub tacho: Option<usize>,
    /// The gear the keyphasor marks (index of a body that is some mesh's gear): the gear
    /// whose revolutions the condition indicators average over; `None`: the first tooth
    /// fault's gear, else the first mesh's driven gear.
    #[serde(default)]
    pub keyphasor: Option<usize>,
}

impl RigTopology {
    /// Every mesh's name as the plant orders them: the external meshes, then each
    /// stage's `<stage>_sun_planet<k>` and `<stage>_ring_planet<k>`, k from 1.
    pub fn mesh_names(&self) -> Vec<String> {
        let mut names: Vec<String> = self.meshes.iter().map(|m| m.name.clone()).collect();
        for s in &self.planetary {
            for kind in ["sun", "ring"] {
                names.extend((1..=s.planets()).map(|k| format!("{}_{kind}_planet{k}", s.name)));
            }
        }
        names
    }

    /// Every turning part's name as the plant orders them: the bodies, then each stage's
    /// planets.
    pub fn turning_names(&self) -> Vec<String> {
        let mut names: Vec<String> = self.bodies.iter().map(|b| b.name.clone()).collect();
        for s in &self.planetary {
            names.extend((0..s.planets()).map(|k| s.planet_name(k)));
        }
        names
    }

    /// F. Basmaji's rig (PhD thesis, The City University, London, 1983), whose ch. IV
    /// findings its sweeps are held against.
    pub const BASMAJI_1983: &'static str = "basmaji-1983";

    /// The published rigs a rig file may say it reproduces.
    pub const REPRODUCIBLE: &'static [&'static str] = &[Self::BASMAJI_1983];
}
