use rig::*;
fn main() {
    let p = preset("basmaji-1983").unwrap();
    let mut plant = Plant::new(p, Schedule::constant(1300.0, 2.712), PlantConfig::default()).unwrap();
    let mut block = SignalBlock::default();
    for _ in 0..40 {
        let x = plant.relative_state();
        let s = plant.sample();
        println!("t={:.6} d={:.6e} X2={:.3e} V2={:.3e} V3={:.3e} mesh={:.4} T34={:.4} motor={:.4} contact={}", s.time_s, x[2]-x[1], x[1], x[6], x[7], s.mesh_torque_nm, s.shaft_torque_nm[1], s.motor_torque_nm, s.contact);
        if plant.run(2, &mut block).is_err() { break; }
    }
}
