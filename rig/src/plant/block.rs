//! What a run of a rig gives: per sample each body's angle and speed, each shaft's
//! torque, each mesh's force and contact, the translations of bodies that move in the
//! plane, the motor's torque; and each impact.

use super::mode::Contact;
use crate::topology::{RigCoordinates, RigTopology};

/// True signals of a rig, one entry per output sample (SI). Angles, speeds and shaft
/// torques are taken in each body's own sense of rotation: positive the way it turns
/// when the motor turns forward (a driven gear of an external pair turns the other way),
/// so a shaft carrying drive torque reads positive on either side of a mesh.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct NetworkBlock {
    /// Sample times (s).
    pub time_s: Vec<f64>,
    /// Each turning part's angle in its sense of rotation (rad), `[part][sample]`: the
    /// bodies, then the planets (`RigTopology::turning_names`).
    pub angle_rad: Vec<Vec<f64>>,
    /// Each turning part's speed in its sense of rotation (rad/s), `[part][sample]`.
    pub speed_rad_s: Vec<Vec<f64>>,
    /// Each shaft's elastic torque k·twist + locked torque (N m), `[shaft][sample]`.
    pub shaft_torque_nm: Vec<Vec<f64>>,
    /// Each mesh's force along the line of action (N), `[mesh][sample]`, in
    /// `RigTopology::mesh_names`' order.
    pub mesh_force_n: Vec<Vec<f64>>,
    /// Each mesh's contact, +1 drive flank, −1 back flank, 0 apart, `[mesh][sample]`.
    pub contact: Vec<Vec<i8>>,
    /// The x and y (m) of each body that moves in the plane, in the bodies' order:
    /// `[2 k]` its x, `[2 k + 1]` its y (empty for a torsional rig; the plant's
    /// `block()` shapes it).
    pub translation_m: Vec<Vec<f64>>,
    /// The motor's torque (N m).
    pub motor_torque_nm: Vec<f64>,
}

impl NetworkBlock {
    /// An empty block shaped for `rig`: a column per turning part (bodies, then planets),
    /// shaft and mesh (external, then the stages'), and x and y per body and planet that
    /// moves in the plane.
    pub fn new(rig: &RigTopology) -> Self {
        Self::shaped(
            rig.turning_names().len(),
            rig.shafts.len() + rig.frame_shafts.len(),
            rig.mesh_names().len(),
            RigCoordinates::translation_count(rig),
        )
    }

    /// An empty block of these sizes.
    pub(super) fn shaped(bodies: usize, shafts: usize, meshes: usize, translations: usize) -> Self {
        Self {
            time_s: Vec::new(),
            angle_rad: vec![Vec::new(); bodies],
            speed_rad_s: vec![Vec::new(); bodies],
            shaft_torque_nm: vec![Vec::new(); shafts],
            mesh_force_n: vec![Vec::new(); meshes],
            contact: vec![Vec::new(); meshes],
            translation_m: vec![Vec::new(); translations],
            motor_torque_nm: Vec::new(),
        }
    }

    /// Number of samples.
    pub fn len(&self) -> usize {
        self.time_s.len()
    }

    /// Whether it holds no sample.
    pub fn is_empty(&self) -> bool {
        self.time_s.is_empty()
    }

    /// Empties it, keeping its shape and memory.
    pub fn clear(&mut self) {
        self.time_s.clear();
        let columns = self
            .angle_rad
            .iter_mut()
            .chain(&mut self.speed_rad_s)
            .chain(&mut self.shaft_torque_nm)
            .chain(&mut self.mesh_force_n)
            .chain(&mut self.translation_m);
        for c in columns {
            c.clear();
        }
        for c in &mut self.contact {
            c.clear();
        }
        self.motor_torque_nm.clear();
    }
}

/// One impact: teeth of a mesh meeting across the backlash.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct NetworkImpact {
    /// Its instant (s).
    pub time_s: f64,
    /// The mesh (index in the rig file's order).
    pub mesh: usize,
    /// The flank struck.
    pub flank: Contact,
    /// The rate δ' the teeth close at, along the line of action (m/s).
    pub approach_m_s: f64,
    /// The teeth of the pair struck, driver's and driven's (1..=z; tooth 1 of each in mesh
    /// at the start).
    pub teeth: [u32; 2],
}
