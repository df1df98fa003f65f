//! Writes `tests/reference/thesis-plant-1983.json`: the thesis plant's run of every case of
//! `rig_support/thesis_reference.rs`, before that plant is retired. Run once:
//! `cargo test --release --test thesis_reference_gen -- --ignored`.

mod rig_support;

use rig::NetworkStart;
use rig_support::thesis_reference::{
    REFERENCE_FILE, Reference, ReferenceFile, TORQUE_EVERY, cases,
};
use rig_support::{RATE_HZ, plant};

#[test]
#[ignore = "writes the reference file; run once, before the thesis plant is retired"]
fn write_the_thesis_plants_reference() {
    let mut file = ReferenceFile {
        made_by: "tests/thesis_reference_gen.rs: rig::Plant (the thesis plant) at 51.2 kHz, \
                  before its retirement (issue 45)"
            .to_string(),
        cases: Default::default(),
    };
    for case in cases() {
        let samples = (case.seconds * RATE_HZ) as usize;
        let mut thesis = rig::Plant::new(
            case.params.clone(),
            case.schedule.clone(),
            rig::PlantConfig::default(),
        )
        .expect("thesis plant");
        if case.from_ours {
            let ours = plant(&case.rig, case.schedule.clone(), NetworkStart::Steady);
            let speed = case.schedule.speed_rpm.value_at(0.0) * std::f64::consts::PI / 30.0;
            thesis.set_relative_state(
                thesis_state(ours.state_rad(), ours.speed_ratios(), speed),
                rig::MeshMode::Drive,
            );
        }
        let mut block = rig::SignalBlock::default();
        thesis.run(samples, &mut block).expect("run");
        let torque = &block.shaft_torque_nm[rig::INTERMEDIATE_SHAFT];
        let reference = Reference {
            torque_nm: torque.iter().step_by(TORQUE_EVERY).copied().collect(),
            torque_scale_nm: torque.iter().fold(0.0_f64, |m, x| m.max(x.abs())),
            impacts_s: thesis.drain_impacts().iter().map(|i| i.time_s).collect(),
        };
        eprintln!("{}: {} impacts", case.key, reference.impacts_s.len());
        file.cases.insert(case.key, reference);
    }
    let path = format!("{}/{REFERENCE_FILE}", env!("CARGO_MANIFEST_DIR"));
    let text = serde_json::to_string(&file).expect("json");
    std::fs::write(path, text + "\n").expect("written");
}

/// The thesis plant's relative state [X1..X5, V1..V5, Vf, z] of the 1983 file's state
/// `u` (angles less their share of the set rotation, absolute speeds, each about its own
/// axis; filtered speed, integral), `ratios` each body's speed ratio: the thesis counts
/// every body in the direction of rotation and its speeds relative to the set speed.
fn thesis_state(u: &[f64], ratios: &[f64], set_speed_rad_s: f64) -> [f64; 12] {
    let mut x = [0.0; 12];
    for i in 0..5 {
        let sense = ratios[i].signum();
        x[i] = sense * u[i];
        x[5 + i] = sense * u[5 + i] - set_speed_rad_s;
    }
    x[10] = u[10] - set_speed_rad_s;
    x[11] = u[11];
    x
}
