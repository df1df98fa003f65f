//! Output rates below the internal step: the one plant (the preset's rig) takes several
//! internal steps per sample (3 at 10.24 kHz, each with ρh ≤ 0.5 in the stiffest mode),
//! and its samples are the same motion as at 51.2 kHz, sampled more sparsely.

mod support;

use rig::{NetworkBlock, Schedule};

/// The preset rig's intermediate (output, gauged) shaft, K34.
const INTERMEDIATE_SHAFT: usize = 1;

#[test]
fn samples_at_a_lower_rate_are_the_same_motion() {
    // Loaded at about 600 rev/min with a constant backlash the teeth stay together (no
    // impacts), so the two runs, whose internal steps differ, agree to rounding rather
    // than diverging after an impact.
    let mut p = support::thesis();
    p.tooth_shifting = false;
    p.backlash_variation_c1 = 0.0;
    let schedule = Schedule::constant(613.0, 2.712);
    let mut fine = support::preset_plant(&p, schedule.clone(), 51_200.0);
    let mut coarse = support::preset_plant(&p, schedule, 10_240.0);
    assert!(coarse.substeps() > 1, "the coarse plant takes substeps");
    let fine_block = support::run_for(&mut fine, 2.0);
    let coarse_block = support::run_for(&mut coarse, 2.0);
    assert!(fine.take_impacts().is_empty() && coarse.take_impacts().is_empty());
    assert_eq!(coarse_block.len(), 20_480);
    let torque = |b: &NetworkBlock, i: usize| b.shaft_torque_nm[INTERMEDIATE_SHAFT][i];
    let scale = fine_block.shaft_torque_nm[INTERMEDIATE_SHAFT]
        .iter()
        .fold(0.0_f64, |m, t| m.max(t.abs()));
    for i in 0..coarse_block.len() {
        let j = 5 * i;
        assert!((coarse_block.time_s[i] - fine_block.time_s[j]).abs() < 1e-12);
        assert!(
            (torque(&coarse_block, i) - torque(&fine_block, j)).abs() < 1e-9 * scale,
            "sample {i}: {} against {}",
            torque(&coarse_block, i),
            torque(&fine_block, j)
        );
        for k in 0..5 {
            let (a, b) = (coarse_block.angle_rad[k][i], fine_block.angle_rad[k][j]);
            assert!((a - b).abs() < 1e-9 * b.abs().max(1.0), "angle {k} at {i}");
        }
    }
}
