//! The condition indicators of a faulted rig file's gear (issue 35): they grow with a
//! pit's and a crack's severity, and `simulate --rig --out` draws the averaged revolution
//! with the faulted tooth where the average dips.

mod common;
mod rig_support;

use rig_support::faulted::{loaded_600_rpm, rig_with};
use testrig::scenario::read_rig_file;

/// The condition indicators of the faulted gear's synchronous average (`simulate --rig`'s
/// `condition`) grow with a pit and with a root crack: at 600 rev/min and 5.424 N m the
/// residual signal's RMS, FM4 and the first sidebands of the mesh frequency (mesh order ±
/// the gear's rotation) rise with every step of severity 0.2 to 0.8, and the healthy pair
/// leaves no residual.
#[test]
fn the_condition_indicators_rise_with_a_pits_and_a_cracks_severity() {
    let dir = common::folder("fault-indicators");
    for kind in ["pit", "crack"] {
        let rig = rig_with(
            dir.path(),
            &format!(
                "[[mesh.fault]]\ngear = \"driven\"\ntooth = 7\nkind = \"{kind}\"\nseverity = 0.0\n"
            ),
        );
        let indicators = |severity: f64| {
            let mut faulted = rig.clone();
            faulted
                .set_field("mesh.gears.fault1.severity", severity)
                .expect("set");
            let c = loaded_600_rpm(&faulted)
                .summary
                .condition
                .expect("a condition");
            assert_eq!(c["gear"], "driven_gear");
            assert!(c["revolutions_averaged"].as_u64().expect("count") >= 90);
            let number = |key: &str| c[key].as_f64().expect(key);
            (
                number("residual_rms_nm"),
                number("fm4"),
                number("sideband_level"),
            )
        };
        let (healthy_residual, _, _) = indicators(0.0);
        assert!(healthy_residual < 1e-9, "{kind}: {healthy_residual} N m");
        let faulted: Vec<(f64, f64, f64)> = [0.2, 0.4, 0.6, 0.8].map(indicators).to_vec();
        for pair in faulted.windows(2) {
            let (a, b) = (pair[0], pair[1]);
            assert!(b.0 > a.0, "{kind}: residual RMS {} then {}", a.0, b.0);
            assert!(b.1 > a.1, "{kind}: FM4 {} then {}", a.1, b.1);
            assert!(b.2 > a.2, "{kind}: sideband level {} then {}", a.2, b.2);
        }
        assert!(faulted[0].0 > 1e3 * healthy_residual.max(1e-12));
    }
}

/// `simulate --rig … --out` draws the faulted gear's averaged revolution with its faulted
/// tooth marked; the average's dip lies where that tooth is in mesh.
#[test]
fn simulate_out_draws_the_averaged_revolution_with_the_faulted_tooth() {
    let dir = common::folder("fault-average");
    let fault = "[[mesh.fault]]\ngear = \"driven\"\ntooth = 7\nkind = \"crack\"\nseverity = 0.5\n";
    rig_with(dir.path(), fault);
    let file = dir.path().join("faulted.toml");
    let out = dir.path().join("out");
    let summary = common::json_of(&[
        "simulate",
        "--rig",
        file.to_str().expect("utf-8"),
        "--rpm",
        "600",
        "--load",
        "5.424",
        "--settle",
        "10",
        "--duration",
        "10",
        "--rate",
        "10240",
        "--out",
        out.to_str().expect("utf-8"),
        "--json",
    ]);
    assert_eq!(summary["condition"]["gear"], "driven_gear");
    let png = std::fs::read(out.join("synchronous-average.png")).expect("the plot");
    assert_eq!(&png[..8], b"\x89PNG\r\n\x1a\n");
    assert!(out.join("synchronous-average.svg").exists());
    let manifest = common::read_manifest(&out);
    assert!(common::has_file(&manifest, "synchronous-average.png"));
    // The averaged revolution's lowest torque falls where tooth 7 is in mesh: over
    // [6/30, 7/30) of the driven gear's turn from its pulse.
    let rig = read_rig_file(&file).expect("rig");
    let average = loaded_600_rpm(&rig).average_nm.expect("an average");
    let lowest = average
        .iter()
        .enumerate()
        .min_by(|a, b| a.1.total_cmp(b.1))
        .map(|(i, _)| i as f64 / average.len() as f64)
        .expect("points");
    assert!(
        (6.0 / 30.0..7.0 / 30.0).contains(&lowest),
        "the lowest torque at {lowest} of the turn"
    );
}
