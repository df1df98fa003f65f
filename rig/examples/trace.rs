use rig::*;
fn main() {
    let mut p = preset("basmaji-1983").unwrap();
    p.gear_error_c2_nm = 2.0;
    let mut plant = Plant::new(p, Schedule::constant(900.0, 0.0), PlantConfig::default()).unwrap();
    let mut block = SignalBlock::default();
    for _ in 0..20 {
        let x = plant.relative_state();
        let s = plant.sample();
        println!("t={:.6} d={:.6e} X2={:.3e} X3={:.3e} V3={:.3e} mesh={:.4} contact={} mode={:?}", s.time_s, x[2]-x[1], x[1], x[2], x[7], s.mesh_torque_nm, s.contact, plant.mode());
        if plant.run(100, &mut block).is_err() { break; }
    }
}
