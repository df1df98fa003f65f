//! `testrig simulate --approach`: one point reached as the lab would reach it. At
//! 1500 rev/min and 5.424 N m the rig with its drive as built holds two motions: the slow
//! run-up arrives on period 1, the run-down on period 2 with a larger torque. From rest
//! the 1983 rig and its rig file start alike and run up alike. Bad ramps are refused.

mod common;

use common::{csv_rows, folder, json_of, number, rig_file, testrig};

fn point(approach: &str) -> serde_json::Value {
    json_of(&[
        "simulate",
        "--preset",
        "basmaji-1983-drive",
        "--rpm",
        "1500",
        "--load",
        "5.424",
        "--rate",
        "10240",
        "--settle",
        "60",
        "--duration",
        "30",
        "--approach",
        approach,
        "--json",
    ])
}

#[test]
fn the_run_up_and_the_run_down_reach_different_motions_at_one_point() {
    let (up, down) = (point("up"), point("down"));
    // The lab's slow ramps, at 10 rev/min per second: from 250 and from 2000 rev/min.
    assert_eq!(up["approach"]["start"], "ramp");
    assert_eq!(up["approach"]["from_rpm"], 250.0);
    assert_eq!(up["approach"]["ramp_s"], 125.0);
    assert_eq!(up["simulated_s"], 215.0);
    assert_eq!(down["approach"]["from_rpm"], 2000.0);
    assert_eq!(down["simulated_s"], 140.0);
    let motion = |v: &serde_json::Value| v["motion"]["motion"].as_str().unwrap_or("").to_string();
    let rms = |v: &serde_json::Value| v["torque_ac_rms_nm"].as_f64().expect("number");
    assert_eq!(motion(&up), "period-1");
    assert_eq!(motion(&down), "period-2");
    assert!(
        rms(&down) > 1.3 * rms(&up),
        "two motions of different size: {} against {} N m",
        rms(&down),
        rms(&up)
    );
    for v in [&up, &down] {
        assert!(v["speed_offset_rpm"].as_f64().expect("number").abs() < 1.0);
    }
}

#[test]
fn from_rest_the_1983_rig_and_its_rig_file_start_and_run_up_alike() {
    let dir = folder("approach-rest");
    let run = |extra: [&str; 2], name: &str| {
        let out = dir.path().join(name);
        let mut args = vec![
            "simulate",
            "--rpm",
            "1300",
            "--load",
            "2.712",
            "--approach",
            "rest",
            "--settle",
            "0",
            "--duration",
            "2",
            "--rate",
            "1000",
            "--out",
            out.to_str().expect("path"),
        ];
        args.extend(extra);
        let done = testrig(&args);
        assert!(
            done.status.success(),
            "{}",
            String::from_utf8_lossy(&done.stderr)
        );
        csv_rows(&out.join("signals.csv"))
    };
    let preset = run(["--preset", "basmaji-1983"], "preset");
    let file = rig_file("basmaji-1983");
    let rig = run(["--rig", &file], "rig");
    // At t = 0 every body stands, the shafts carry the load, the motor is at its limit.
    for body in 1..=5 {
        assert_eq!(number(&preset[0], &format!("speed{body}_rad_s")), 0.0);
    }
    assert!((number(&preset[0], "torque_intermediate_shaft_nm") - 2.712).abs() < 1e-9);
    assert!((number(&rig[0], "torque_intermediate_nm") - 2.712).abs() < 1e-9);
    let mut worst: f64 = 0.0;
    for (a, b) in preset.iter().zip(&rig) {
        for (x, y) in [
            ("torque_input_shaft_nm", "torque_input_nm"),
            ("torque_intermediate_shaft_nm", "torque_intermediate_nm"),
            ("torque_final_shaft_nm", "torque_final_nm"),
            ("motor_torque_nm", "motor_torque_nm"),
        ] {
            worst = worst.max((number(a, x) - number(b, y)).abs());
        }
    }
    assert_eq!(preset.len(), rig.len());
    assert!(worst < 1e-4, "the two plants differ by {worst} N m");
}

#[test]
fn a_ramp_that_is_no_ramp_or_too_long_is_refused() {
    for (rate, says) in [
        ("0", "positive number of rev/min per second"),
        ("-5", "positive number of rev/min per second"),
        ("1e-9", "the ramp's"),
    ] {
        let done = testrig(&[
            "simulate",
            "--rpm",
            "1300",
            "--load",
            "0",
            "--approach",
            "up",
            "--ramp-rate",
            rate,
        ]);
        let err = String::from_utf8_lossy(&done.stderr);
        assert!(!done.status.success(), "{rate}");
        assert!(err.contains(says) && !err.contains("panicked"), "{err}");
    }
}
