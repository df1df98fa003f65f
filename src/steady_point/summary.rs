//! What a point's measuring window reports: the steady summary's keys, then every body,
//! shaft and mesh of the rig.

use rig::{
    Judgement, Motion, NetworkImpact, Regime, RigTopology, SteadySummary, impacts_per_tooth,
};
use serde::Serialize;

/// One shaft over the window.
#[derive(Clone, Debug, Serialize)]
pub struct ShaftSummary {
    /// Its name.
    pub name: String,
    /// Mean torque (N m).
    pub torque_mean_nm: f64,
    /// RMS of the torque about its mean (N m).
    pub torque_ac_rms_nm: f64,
}

/// One mesh over the window.
#[derive(Clone, Debug, Serialize)]
pub struct MeshSummary {
    /// Its name.
    pub name: String,
    /// Impacts in the window.
    pub impacts: usize,
    /// Share of the window with the teeth apart.
    pub apart_fraction: f64,
}

/// One body over the window.
#[derive(Clone, Debug, Serialize)]
pub struct BodySummary {
    /// Its name.
    pub name: String,
    /// Mean speed in its sense of rotation (rev/min).
    pub speed_mean_rpm: f64,
}

/// The measuring window of a rig's point: the keys of the steady summary
/// (`rig::SteadySummary`), so that `simulate --json` reads alike for a preset and a rig
/// file (the judged shaft's torque; the impacts of every mesh, in all and per revolution
/// of the motor's body; the first mesh's impacts on each tooth of its driving gear, from
/// tooth 1, and its time apart; the regime, the motor's speed offset), then the rig's
/// own: every body, shaft and mesh.
#[derive(Clone, Debug, Serialize)]
pub struct RigPointSummary {
    /// The window in the steady summary's keys.
    #[serde(flatten)]
    pub steady: SteadySummary,
    /// The motor's mean torque (N m).
    pub motor_torque_mean_nm: f64,
    /// Each body.
    pub bodies: Vec<BodySummary>,
    /// Each shaft.
    pub shafts: Vec<ShaftSummary>,
    /// Each mesh.
    pub meshes: Vec<MeshSummary>,
    /// The shaft judged (the gauged one, else the last).
    pub judged_shaft: String,
    /// The watched gear's condition: the judged shaft's torque averaged synchronously
    /// over its revolutions (`null` without a mesh or under two revolutions).
    pub condition: Option<serde_json::Value>,
}

/// A rig's window in the steady summary's keys: its `bodies`, `shafts` and `meshes` as
/// summed, its `motion` over `measured_s` and whole `revolutions` of the motor's body,
/// the shaft judged `judged`, the motor's body set to `rpm` (rev/min), `impacts` the
/// window's.
pub(super) fn steady_summary(
    rig: &RigTopology,
    (bodies, shafts, meshes): (&[BodySummary], &[ShaftSummary], &[MeshSummary]),
    (motion, measured_s, revolutions): (Judgement, f64, usize),
    judged: usize,
    rpm: f64,
    impacts: &[NetworkImpact],
) -> SteadySummary {
    let shaft = shafts.get(judged);
    let (mean, ac) = shaft.map_or((0.0, 0.0), |s| (s.torque_mean_nm, s.torque_ac_rms_nm));
    let teeth = rig.meshes.first().map_or(0, |m| m.teeth[0]);
    let first_mesh = impacts.iter().filter(|i| i.mesh == 0);
    let motor_rpm = rig.motor.map_or(rpm, |m| bodies[m].speed_mean_rpm);
    SteadySummary {
        measured_s,
        impacts: impacts.len(),
        impacts_per_rev: impacts.len() as f64 / revolutions.max(1) as f64,
        // Teeth are numbered 1..=z, the counts from tooth 1 at index 0.
        impacts_per_tooth: impacts_per_tooth(teeth, first_mesh.map(|i| i.teeth[0] - 1)),
        regime: regime_of(motion.motion),
        separates: meshes.iter().any(|m| m.apart_fraction > 0.0),
        apart_fraction: meshes.first().map_or(0.0, |m| m.apart_fraction),
        torque_mean_nm: mean,
        torque_rms_nm: ac.hypot(mean),
        torque_ac_rms_nm: ac,
        revolutions,
        speed_offset_rpm: motor_rpm - rpm,
        motion,
    }
}

/// The regime a rig's window reports: the judge's period of the judged shaft's torque (at
/// rest: period 1), aperiodic otherwise.
pub fn regime_of(motion: Motion) -> Regime {
    match motion {
        Motion::Periodic(k) => Regime::Periodic(k),
        Motion::NoVibration => Regime::Periodic(1),
        _ => Regime::Aperiodic,
    }
}
