//! The steady state of a rig at a set speed and brake load: every body turning at its
//! share of the motor's speed, each shaft and mesh twisted to carry the torques of load,
//! drag and a loop's locked-in torque, the motor giving what they take. At 0 rev/min and
//! no load this is the rig at rest, a loop still carrying its locked torque.
//!
//! With the meshes on given flanks the twists (and the translations of bodies on
//! bearings) solve K q = f + T_m e_motor (one angle held: the rigid rotation is free), T_m from the balance of power Σ s_i f_i + T_m = 0.
//! The meshes' flanks are tried in turn (each drive, back, then apart) until every mesh
//! is consistent: pressing its flank, or apart within its backlash; a mesh carrying
//! nothing rests on its drive flank. A loop without locked torque rests with a mesh
//! apart.

use nalgebra::{DMatrix, DVector};

use crate::error::RigError;
use crate::mode::PairZone;
use crate::topology::RigTopology;
use crate::topology::add_coupling;

use super::mesh_model::MeshModel;
use super::mode::{Contact, MeshState};
use super::model::NetworkModel;

/// Force (N) a mesh may pull with and still count as resting on its flank.
const FLANK_TOLERANCE_N: f64 = 1e-6;

/// A steady state.
#[derive(Clone, Debug, PartialEq)]
pub struct Equilibrium {
    /// Each coordinate (`NetLayout`): each body's angle (rad), the first mesh's driver
    /// (or the motor's body) at 0, then the translations (m).
    pub angles_rad: Vec<f64>,
    /// Each mesh's state.
    pub meshes: Vec<MeshState>,
    /// The motor's torque (N m).
    pub motor_torque_nm: f64,
}

/// The steady state at `speed_rad_s` of the motor's body and `load_nm` on the brake,
/// each mesh's pairs at `levels`.
pub fn equilibrium(
    model: &NetworkModel,
    speed_rad_s: f64,
    load_nm: f64,
    levels: &[PairZone],
) -> Result<Equilibrium, RigError> {
    let count = model.meshes.len();
    for combination in 0..3_usize.pow(count as u32) {
        let meshes: Vec<MeshState> = (0..count)
            .map(|i| MeshState {
                contact: [Contact::Drive, Contact::Back, Contact::Apart]
                    [combination / 3_usize.pow(i as u32) % 3],
                level: levels[i],
                ..MeshState::APART
            })
            .collect();
        let Ok(solved) = solve(model, speed_rad_s, load_nm, &meshes) else {
            continue;
        };
        if (0..count).all(|i| rests(model, i, meshes[i], &solved.angles_rad)) {
            return Ok(solved);
        }
    }
    Err(RigError::Schedule(format!(
        "no steady state at {:.1} rev/min and {load_nm} N m: the meshes find no flanks to rest on",
        speed_rad_s * 30.0 / std::f64::consts::PI
    )))
}

/// Whether mesh `i` in `state` is consistent at `angles`: pressing its flank, or apart
/// within the backlash.
fn rests(model: &NetworkModel, i: usize, state: MeshState, angles: &[f64]) -> bool {
    let force = flank_force(model, i, state, angles);
    let m = &model.meshes[i];
    match state.contact {
        Contact::Drive => force >= -FLANK_TOLERANCE_N,
        Contact::Back => force <= FLANK_TOLERANCE_N,
        Contact::Apart => {
            deflection_m(m, 1.0, angles) + m.start_offset_m(1.0) <= 0.0
                && deflection_m(m, -1.0, angles) + m.start_offset_m(-1.0) >= 0.0
        }
    }
}

/// The spring force (N) of mesh `i` on its flank at `angles`.
fn flank_force(model: &NetworkModel, i: usize, state: MeshState, angles: &[f64]) -> f64 {
    let m = &model.meshes[i];
    let (k, _) = m.spring(state);
    match state.contact {
        Contact::Drive => k * (deflection_m(m, 1.0, angles) + m.start_offset_m(1.0)),
        Contact::Back => k * (deflection_m(m, -1.0, angles) + m.start_offset_m(-1.0)),
        Contact::Apart => 0.0,
    }
}

/// A mesh's deflection (m) on `flank` at the coordinates `angles`.
fn deflection_m(m: &MeshModel, flank: f64, angles: &[f64]) -> f64 {
    m.terms(flank).map(|(j, c)| c * angles[j]).sum()
}

/// The twists with the meshes on the flanks of `meshes`.
fn solve(
    model: &NetworkModel,
    speed_rad_s: f64,
    load_nm: f64,
    meshes: &[MeshState],
) -> Result<Equilibrium, RigError> {
    let n = model.layout.coordinates;
    let mut k = DMatrix::<f64>::zeros(n, n);
    let mut f = DVector::<f64>::zeros(n);
    for (i, drag) in model.drag_nms_per_rad.iter().enumerate() {
        f[i] -= drag * model.speed_ratio[i] * speed_rad_s;
    }
    if let Some(b) = &model.brake {
        f[b.body] -= b.direction * (load_nm + b.drag_nm);
    }
    for s in &model.shafts {
        let [a, b] = s.between;
        add_coupling(&mut k, &[(a, 1.0), (b, -1.0)], s.stiffness_nm_per_rad);
        f[a] -= s.preload_nm;
        f[b] += s.preload_nm;
    }
    for s in &model.supports {
        add_coupling(&mut k, &s.terms, s.stiffness);
    }
    for (m, state) in model.meshes.iter().zip(meshes) {
        let (spring, _) = m.spring(*state);
        let flank = match state.contact {
            Contact::Drive => 1.0,
            Contact::Back => -1.0,
            Contact::Apart => continue,
        };
        let offset = m.start_offset_m(flank);
        let terms: Vec<(usize, f64)> = m.terms(flank).collect();
        add_coupling(&mut k, &terms, spring);
        for &(x, rx) in &terms {
            f[x] -= spring * rx * offset;
        }
    }
    let power: f64 = f.iter().zip(&model.speed_ratio).map(|(t, s)| t * s).sum();
    let reference = model.motor.as_ref().map_or(0, |m| m.body);
    let motor_torque_nm = -power / model.speed_ratio[reference];
    match &model.motor {
        Some(_) => f[reference] += motor_torque_nm,
        None if power.abs() > 1e-9 * (1.0 + f.amax()) => {
            return Err(RigError::Schedule(
                "this rig has no motor to carry its load or drag: run it at rest".into(),
            ));
        }
        None => {}
    }
    // The rigid rotation is free: the first mesh's driver is held at angle 0 (as the
    // thesis starts its driving gear, tooth 0 in mesh), else the motor's body.
    let held = model.meshes.first().map_or(reference, |m| m.gears[0]);
    let keep: Vec<usize> = (0..n).filter(|&i| i != held).collect();
    let reduced = DMatrix::from_fn(n - 1, n - 1, |r, c| k[(keep[r], keep[c])]);
    let rhs = DVector::from_fn(n - 1, |r, _| f[keep[r]]);
    let twist = reduced.lu().solve(&rhs).ok_or_else(|| {
        RigError::Schedule("the rig's stiffness is singular: a body is held by nothing".into())
    })?;
    let mut angles_rad = vec![0.0; n];
    for (r, &i) in keep.iter().enumerate() {
        angles_rad[i] = twist[r];
    }
    Ok(Equilibrium {
        angles_rad,
        meshes: meshes.to_vec(),
        motor_torque_nm,
    })
}

/// The constants of a checked topology, assembled: a loop's twisted shaft carries its
/// locked torque at rest ([`assembly_preload_nm`]).
pub fn assembled(rig: &RigTopology) -> Result<NetworkModel, RigError> {
    let mut model = NetworkModel::of(rig);
    if let Some(locked) = &rig.locked_torque {
        model.shafts[locked.shaft].preload_nm =
            assembly_preload_nm(&model, locked.shaft, locked.torque_nm)?;
    }
    Ok(model)
}

/// The untwisted torque T0 of a loop's shaft `shaft` that leaves it carrying
/// `locked_nm` at rest: the loop is linear on fixed flanks, so the torque carried at rest
/// is a T0 + c; two solves give a and c.
pub fn assembly_preload_nm(
    model: &NetworkModel,
    shaft: usize,
    locked_nm: f64,
) -> Result<f64, RigError> {
    let mut trial = model.clone();
    let levels = vec![PairZone::ONE; model.meshes.len()];
    let mut carried = |preload: f64| -> Result<(f64, Vec<MeshState>), RigError> {
        trial.shafts[shaft].preload_nm = preload;
        let rest = equilibrium(&trial, 0.0, 0.0, &levels)?;
        let s = &trial.shafts[shaft];
        let [a, b] = s.between;
        let twist = rest.angles_rad[a] - rest.angles_rad[b];
        Ok((s.stiffness_nm_per_rad * twist + preload, rest.meshes))
    };
    let (first, flanks) = carried(locked_nm)?;
    let (second, same) = carried(2.0 * locked_nm)?;
    let slope = (second - first) / locked_nm;
    if locked_nm == 0.0 || flanks != same || slope <= 0.0 {
        return Ok(locked_nm);
    }
    Ok(locked_nm + (locked_nm - first) / slope)
}
