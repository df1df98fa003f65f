//! A rig of any topology, as a rig file describes it: rotating bodies, torsional shafts
//! between two bodies, and external spur meshes with backlash between two gears' base
//! circles; a motor body, a brake body, and for a back-to-back loop the torque locked
//! into one shaft. SI inside, units in the names. Built from a rig file by the
//! application; checked by [`RigTopology::check`] (`topology_check.rs`); its natural
//! frequencies by [`RigTopology::natural_frequencies_hz`] (`topology_modes.rs`).

use serde::Serialize;

/// Most bodies a rig may have.
pub const MAX_BODIES: usize = 32;
/// Most meshes a rig may have.
pub const MAX_MESHES: usize = 4;

/// One rotating inertia.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Body {
    /// Its name, unique in the rig.
    pub name: String,
    /// Moment of inertia about its axis (kg m²).
    pub inertia_kgm2: f64,
}

/// A torsional spring-damper between two bodies.
#[derive(Clone, Debug, PartialEq, Serialize)]
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
#[derive(Clone, Debug, PartialEq, Serialize)]
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
    /// Stiffness of one tooth pair along the line of action (N/m).
    pub stiffness_n_per_m: f64,
    /// Damping along the line of action (N s/m).
    pub damping_ns_per_m: f64,
}

impl Mesh {
    /// Base radii of the driving and the driven gear, r_b = m z cos α / 2 (m).
    pub fn base_radii_m(&self) -> [f64; 2] {
        let cos = self.pressure_angle_deg.to_radians().cos();
        self.teeth.map(|z| self.module_m * f64::from(z) * cos / 2.0)
    }

    /// Speed of the driven gear per unit speed of the driver: −z₁/z₂ (external gears turn
    /// opposite ways).
    pub fn speed_ratio(&self) -> f64 {
        -f64::from(self.teeth[0]) / f64::from(self.teeth[1])
    }
}

/// The torque locked into one shaft of a back-to-back loop at assembly.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct LockedTorque {
    /// The shaft twisted (index).
    pub shaft: usize,
    /// The torque it carries at rest (N m).
    pub torque_nm: f64,
}

/// A whole rig.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct RigTopology {
    /// The rig's name.
    pub name: String,
    /// What it is (free text).
    pub description: String,
    /// Its bodies.
    pub bodies: Vec<Body>,
    /// Its shafts.
    pub shafts: Vec<Shaft>,
    /// Its meshes.
    pub meshes: Vec<Mesh>,
    /// The body the motor drives (index).
    pub motor: Option<usize>,
    /// The body the brake loads (index).
    pub brake: Option<usize>,
    /// The torque locked into a loop's shaft, if any.
    pub locked_torque: Option<LockedTorque>,
}
