//! Reversing the load mirrors the motion: X(t) under −T equals −X(t) under +T.

mod support;

use rig::Schedule;

#[test]
fn reversing_the_load_mirrors_the_motion() {
    let mut p = support::thesis();
    // The tooth passes are tied to the driving gear's own angle, which the mirror moves;
    // the gear errors are not odd in the twist. Everything else is symmetric.
    p.tooth_shifting = false;
    let rpm = 1300.0;
    let mut ahead = support::plant(p.clone(), Schedule::constant(rpm, 2.712), 51_200.0);
    let mut behind = support::plant(p, Schedule::constant(rpm, -2.712), 51_200.0);
    let mut worst = 0.0_f64;
    let mut scale = 0.0_f64;
    for _ in 0..51_200 {
        let (a, b) = (ahead.relative_state(), behind.relative_state());
        for k in 0..10 {
            worst = worst.max((a[k] + b[k]).abs());
            scale = scale.max(a[k].abs());
        }
        ahead.skip(1).expect("run completes");
        behind.skip(1).expect("run completes");
    }
    assert!(
        ahead.impacts().len() > 20,
        "only {} impacts",
        ahead.impacts().len()
    );
    assert_eq!(ahead.impacts().len(), behind.impacts().len());
    for (a, b) in ahead.impacts().iter().zip(behind.impacts()) {
        assert!((a.time_s - b.time_s).abs() < 1e-12);
        assert_ne!(a.flank, b.flank);
    }
    assert!(
        worst < 1e-9 * scale,
        "mirror broken by {worst:e} (scale {scale:e})"
    );
}
