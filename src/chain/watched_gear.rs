//! The gear a point's condition indicators watch, and the signal their synchronous
//! average takes: a marked, faulted or meshing gear and a shaft's torque, or a planetary
//! stage's carrier and its ring sensor.

use rig::{FaultedGear, RigTopology};

/// The gear a point's condition indicators watch: the `[keyphasor]`'s gear, else the
/// first tooth fault's gear, else the first mesh's driven gear, else the first planetary
/// stage's carrier where its ring is held; (body, teeth). Such a carrier counts the
/// ring's teeth: its turn holds z_r mesh periods (carrier-synchronous averaging). A stage
/// whose ring turns (its carrier held, or a differential's) has no whole mesh periods a
/// carrier turn, and is not watched so.
pub fn watched_gear(rig: &RigTopology) -> Option<(usize, u32)> {
    let speeds = rig.relative_speeds();
    let carrier = |body: usize| {
        rig.planetary
            .iter()
            .find(|s| s.carrier == body && speeds[s.ring] == Some(0.0))
            .map(|s| (body, s.teeth.ring))
    };
    let marked = rig.keyphasor.and_then(|body| {
        rig.meshes
            .iter()
            .find_map(|m| {
                (0..2)
                    .find(|&side| m.gears[side] == body)
                    .map(|side| (body, m.teeth[side]))
            })
            .or_else(|| carrier(body))
    });
    let faulted = || {
        rig.meshes.iter().find_map(|m| {
            m.faults.first().map(|f| match f.gear {
                FaultedGear::Driver => (m.gears[0], m.teeth[0]),
                FaultedGear::Driven => (m.gears[1], m.teeth[1]),
            })
        })
    };
    marked
        .or_else(faulted)
        .or_else(|| rig.meshes.first().map(|m| (m.gears[1], m.teeth[1])))
        .or_else(|| rig.planetary.first().and_then(|s| carrier(s.carrier)))
}

/// The signal a watched carrier's average takes: its stage's ring sensor, if it has one
/// (the stage's index).
pub fn sensed_stage(rig: &RigTopology, watched: Option<(usize, u32)>) -> Option<usize> {
    let (gear, _) = watched?;
    rig.planetary
        .iter()
        .position(|s| s.carrier == gear && s.ring_sensor.is_some())
}
