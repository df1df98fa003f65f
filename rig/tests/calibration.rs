//! The hand-calibrated preset's rig on the one plant against the thesis's measured
//! fundamental: 13.33 Hz, seen as the running speed (≈ 780 rev/min) at which the output
//! shaft resonates once per revolution.
//! With backlash the teeth separate at that resonance and the rig softens, so the peak of
//! the once-per-revolution response lies below the linear 17.84 Hz (1070 rev/min) of App. C.

mod support;

use rig::{RigParams, Schedule, preset};

/// The preset rig's intermediate (output, gauged) shaft, K34.
const INTERMEDIATE_SHAFT: usize = 1;

/// Amplitude (N m) of the once-per-revolution component of the output-shaft torque of the
/// one plant of `params`' rig at `rpm` and `load_nm`, over 60 revolutions after 8 s of
/// settling.
fn first_order_nm(params: &RigParams, rpm: f64, load_nm: f64) -> f64 {
    let mut plant = support::preset_plant(params, Schedule::constant(rpm, load_nm), 51_200.0);
    plant.skip(8 * 51_200).expect("settles");
    let revolution_s = 60.0 / rpm;
    let block = support::run_for(&mut plant, 60.0 * revolution_s);
    let (re, im) = support::phasor(
        &block.time_s,
        &block.shaft_torque_nm[INTERMEDIATE_SHAFT],
        rpm / 60.0,
    );
    re.hypot(im)
}

/// The speed (rev/min) of the largest once-per-revolution response from 600 to 900
/// rev/min in steps of 25.
fn first_order_peak_rpm(params: &RigParams, load_nm: f64) -> f64 {
    (0..13)
        .map(|k| 600.0 + 25.0 * f64::from(k))
        .map(|rpm| (rpm, first_order_nm(params, rpm, load_nm)))
        .fold((0.0, f64::NEG_INFINITY), |best, (rpm, a)| {
            if a > best.1 { (rpm, a) } else { best }
        })
        .0
}

#[test]
fn the_hand_calibrated_rig_resonates_once_per_revolution_near_780_rev_per_min() {
    // The preset chosen by hand keeps the measured fundamental's resonance; the searched
    // `basmaji-1983-calibrated` was not asked for it and puts it at 850–900 rev/min
    // (docs/calibration.md).
    let calibrated = preset("basmaji-1983-hand").expect("preset");
    // The thesis's stiffnesses are kept: its linear fundamental is App. C's 17.84 Hz.
    let thesis = support::thesis();
    assert_eq!(
        calibrated.k34_intermediate_shaft_nm_per_rad,
        thesis.k34_intermediate_shaft_nm_per_rad
    );
    // Loaded (the thesis quotes no load for its 13.33 Hz), the peak lies within 12 % of
    // 780 rev/min; it rises with the load, which keeps the teeth together for longer.
    let near_780 = 780.0 * 0.88..=780.0 * 1.12;
    let mut peaks = Vec::new();
    for load_nm in [2.712, 5.424] {
        let peak = first_order_peak_rpm(&calibrated, load_nm);
        eprintln!("MEASURED calibrated, {load_nm} N m: peak at {peak} rev/min");
        assert!(
            near_780.contains(&peak),
            "{load_nm} N m: once-per-revolution peak at {peak} rev/min"
        );
        peaks.push(peak);
    }
    assert!(peaks[1] > peaks[0], "{peaks:?}");
    // A shaft softened to put the *linear* fundamental at 13.33 Hz (K34 1449.5 N m/rad)
    // puts the softened resonance far lower: the test tells the two apart.
    let softened = RigParams {
        k34_intermediate_shaft_nm_per_rad: 1449.5,
        ..calibrated.clone()
    };
    let peak = first_order_peak_rpm(&softened, 2.712);
    eprintln!("MEASURED softened shaft, 2.712 N m: peak at {peak} rev/min");
    assert!(
        peak < *near_780.start(),
        "softened shaft: peak at {peak} rev/min"
    );
}
