//! What the rig-file plant tests share: the shipped rig files, a plant and its run at
//! 51.2 kHz, means over a tail, bodies and shafts by name, a run-up schedule.

#![allow(dead_code)]

pub mod faulted;
pub mod thesis_reference;

use rig::{NetworkBlock, NetworkPlant, NetworkStart, RigTopology, Schedule, Track};
use testrig::scenario::read_rig_file;

pub const RATE_HZ: f64 = 51_200.0;

pub fn shipped(name: &str) -> RigTopology {
    let path = format!("{}/scenarios/rigs/{name}.toml", env!("CARGO_MANIFEST_DIR"));
    read_rig_file(std::path::Path::new(&path)).expect("a shipped rig file")
}

pub fn plant(rig: &RigTopology, schedule: Schedule, start: NetworkStart) -> NetworkPlant {
    NetworkPlant::new(rig, schedule, RATE_HZ, start).expect("plant")
}

pub fn run(plant: &mut NetworkPlant, rig: &RigTopology, seconds: f64) -> NetworkBlock {
    let mut block = NetworkBlock::new(rig);
    plant
        .run((seconds * RATE_HZ).round() as usize, &mut block)
        .expect("run");
    block
}

pub fn mean(x: &[f64]) -> f64 {
    x.iter().sum::<f64>() / x.len() as f64
}

/// The last `seconds` of a column.
pub fn tail(x: &[f64], seconds: f64) -> &[f64] {
    &x[x.len() - (seconds * RATE_HZ) as usize..]
}

pub fn index(names: impl Iterator<Item = String>, name: &str) -> usize {
    names
        .into_iter()
        .position(|n| n == name)
        .unwrap_or_else(|| panic!("no `{name}`"))
}

pub fn body(rig: &RigTopology, name: &str) -> usize {
    index(rig.bodies.iter().map(|b| b.name.clone()), name)
}

pub fn shaft(rig: &RigTopology, name: &str) -> usize {
    index(rig.shafts.iter().map(|s| s.name.clone()), name)
}

/// Speed from rest to `rpm` and load from 0 to `load_nm` over 2 s, then held.
pub fn run_up(rpm: f64, load_nm: f64) -> Schedule {
    let ramp = |value| Track::hold(0.0).ramp_to(0.0, 2.0, value);
    Schedule {
        speed_rpm: ramp(rpm),
        load_nm: ramp(load_nm),
        ..Schedule::constant(0.0, 0.0)
    }
}
