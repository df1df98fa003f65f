//! Each mesh option shows its physical effect on the one plant of the thesis's rig
//! (`rig::preset_rig`).

mod support;

use rig::{ContactLaw, GearGeometry, MeshPairs, Schedule};

const LOAD: f64 = 2.712;
const RPM: f64 = 200.0;

#[test]
fn without_options_a_loaded_rig_is_static() {
    let mut plant =
        support::preset_plant(&support::quiet(), Schedule::constant(RPM, LOAD), 51_200.0);
    let block = support::run_for(&mut plant, 1.0);
    let torque = &block.shaft_torque_nm[1];
    assert!(
        support::std_dev(torque) < 1e-9,
        "{}",
        support::std_dev(torque)
    );
    assert!((support::mean(torque) - LOAD).abs() < 1e-9);
    assert!(plant.take_impacts().is_empty());
}

#[test]
fn tooth_shifting_kicks_the_shafts_at_tooth_pass_frequency() {
    let mut p = support::quiet();
    p.tooth_shifting = true;
    let mut plant = support::preset_plant(&p, Schedule::constant(RPM, LOAD), 51_200.0);
    let block = support::run_for(&mut plant, 3.0);
    let start = block.len() / 3;
    let (t, torque) = (&block.time_s[start..], &block.shaft_torque_nm[1][start..]);
    let tooth_hz = RPM / 60.0 * 30.0;
    let (re, im) = support::phasor(t, torque, tooth_hz);
    let at_tooth = re.hypot(im);
    let (re, im) = support::phasor(t, torque, 1.5 * tooth_hz);
    let between = re.hypot(im);
    assert!(
        support::std_dev(torque) > 1e-4,
        "no effect: {}",
        support::std_dev(torque)
    );
    assert!(
        at_tooth > 10.0 * between,
        "tooth-pass line {at_tooth:e} vs {between:e} beside it"
    );
    // Handing the overlap back removes the mesh's elastic deflection: with the load still
    // carried, the gears sit closer to the flank on average than the static T/K23.
    let p = support::quiet();
    let b = GearGeometry::of(&p).half_backlash_rad;
    let mean_overlap = support::mean(
        &block.angle_rad[1][start..]
            .iter()
            .zip(&block.angle_rad[2][start..])
            .map(|(a2, a3)| -(a3 - a2) - b)
            .collect::<Vec<_>>(),
    );
    assert!(
        mean_overlap < LOAD / p.k23_mesh_nm_per_rad,
        "{mean_overlap:e}"
    );
}

#[test]
fn two_pairs_halve_the_mesh_deflection_for_the_contact_ratio_fraction() {
    let mut p = support::quiet();
    p.mesh_pairs = MeshPairs::Alternating;
    let geometry = GearGeometry::of(&p);
    let fraction = geometry.double_pair_fraction();
    assert!(
        (geometry.contact_ratio - 1.4602).abs() < 1e-3,
        "{}",
        geometry.contact_ratio
    );
    let mut plant = support::preset_plant(&p, Schedule::constant(RPM, LOAD), 51_200.0);
    let block = support::run_for(&mut plant, 2.0);
    let b = geometry.half_backlash_rad;
    let (mut single, mut double) = (Vec::new(), Vec::new());
    for i in block.len() / 2..block.len() {
        let theta2 = block.angle_rad[1][i];
        let overlap = -(block.angle_rad[2][i] - theta2) - b;
        let within = theta2.rem_euclid(geometry.tooth_pitch_rad) / geometry.tooth_pitch_rad;
        if within < fraction {
            double.push(overlap)
        } else {
            single.push(overlap)
        }
    }
    let share = double.len() as f64 / (single.len() + double.len()) as f64;
    assert!(
        (share - fraction).abs() < 0.01,
        "double-pair share {share} vs ε − 1 = {fraction}"
    );
    let median = |v: &mut Vec<f64>| {
        v.sort_by(f64::total_cmp);
        v[v.len() / 2]
    };
    let (one, two) = (median(&mut single), median(&mut double));
    let k = p.k23_mesh_nm_per_rad;
    assert!(
        (one - LOAD / k).abs() < 0.05 * LOAD / k,
        "single-pair overlap {one:e}"
    );
    assert!(
        (two - LOAD / (2.0 * k)).abs() < 0.05 * LOAD / k,
        "double-pair overlap {two:e}"
    );
    // The stiffness changes excite the shafts at the tooth-pass frequency.
    assert!(support::std_dev(&block.shaft_torque_nm[1][block.len() / 2..]) > 1e-5);
}

#[test]
fn backlash_variation_moves_the_loaded_gears_once_per_revolution() {
    let mut p = support::quiet();
    p.backlash_variation_c1 = 0.38;
    let mut plant = support::preset_plant(&p, Schedule::constant(RPM, LOAD), 51_200.0);
    let block = support::run_for(&mut plant, 3.0);
    assert!(
        plant.take_impacts().is_empty(),
        "the load keeps the teeth together at 200 rev/min"
    );
    // Eight whole revolutions (0.6 s to 3 s) for the projection.
    let start = block.len() / 5;
    let d: Vec<f64> = (start..block.len())
        .map(|i| block.angle_rad[2][i] - block.angle_rad[1][i])
        .collect();
    let (re, im) = support::phasor(&block.time_s[start..], &d, RPM / 60.0);
    let expected = GearGeometry::of(&p).half_backlash_rad * 0.38;
    assert!(
        (re.hypot(im) - expected).abs() < 0.02 * expected,
        "{} vs {expected}",
        re.hypot(im)
    );
}

#[test]
fn the_no_pull_law_never_pulls_and_the_thesis_law_does() {
    // Share of contact samples whose flank torque pulls the teeth together: drive-flank
    // contact (+1) transmits F_XT ≥ 0, back-flank contact (−1) F_XT ≤ 0.
    let run = |law: ContactLaw| {
        let mut p = support::thesis();
        p.contact_law = law;
        let mut plant = support::preset_plant(&p, Schedule::constant(1300.0, LOAD), 51_200.0);
        let block = support::run_for(&mut plant, 2.0);
        let pulling = support::mesh_torque_nm(&p, &block)
            .iter()
            .zip(&block.contact[0])
            .filter(|&(&torque, &contact)| f64::from(contact) * torque < 0.0)
            .count();
        (pulling, plant.take_impacts().len())
    };
    let (thesis_pulling, thesis_impacts) = run(ContactLaw::Thesis);
    let (no_pull_pulling, no_pull_impacts) = run(ContactLaw::NoPull);
    assert!(thesis_impacts > 10 && no_pull_impacts > 10);
    assert!(
        thesis_pulling > 10,
        "the thesis law's damper pulls: {thesis_pulling} samples"
    );
    assert_eq!(no_pull_pulling, 0);
}
