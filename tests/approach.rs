//! `testrig simulate --approach`: one point reached as the lab would reach it. At
//! 1500 rev/min and 5.424 N m the rig with its drive as built holds two motions: the slow
//! run-up arrives on period 1, the run-down on period 2 with a larger torque. From rest
//! the 1983 rig and its rig file start alike and run up alike. Bad ramps are refused.

mod common;

use common::{csv_rows, folder, json_of, number, rig_file, testrig, testrig_ok};

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

/// From rest the preset and its rig file are one rig: the same signals to the byte; at
/// t = 0 every body stands and the shafts carry the load.
#[test]
fn from_rest_the_1983_preset_and_its_rig_file_start_and_run_up_alike() {
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
        testrig_ok(&args);
        out.join("signals.csv")
    };
    let preset = run(["--preset", "basmaji-1983"], "preset");
    let file = rig_file("basmaji-1983");
    let rig = run(["--rig", &file], "rig");
    let bytes = |path: &std::path::Path| std::fs::read(path).expect("signals.csv");
    assert!(
        bytes(&preset) == bytes(&rig),
        "the preset and its file differ"
    );
    let rows = csv_rows(&preset);
    assert_eq!(rows.len(), 2000);
    for body in [
        "motor",
        "input_flywheel",
        "driven_gear",
        "output_flywheel",
        "brake",
    ] {
        assert_eq!(number(&rows[0], &format!("speed_{body}_rpm")), 0.0);
    }
    for shaft in ["input", "intermediate", "final"] {
        let torque = number(&rows[0], &format!("torque_{shaft}_nm"));
        assert!((torque - 2.712).abs() < 1e-9, "{shaft}: {torque} N m");
    }
    // The motor at its limit (2 hp at 2000 rev/min: 7.121 N m) against the load turns the
    // whole rig (0.84495 kg m²) up at (7.121 − 2.712) / 0.84495 rad/s².
    let last = rows.last().expect("rows");
    let (t, speed) = (number(last, "time_s"), number(last, "speed_motor_rpm"));
    let limit_nm = 2.0 * 745.699_872 / (2000.0 * std::f64::consts::PI / 30.0);
    let expected = (limit_nm - 2.712) / 0.84495 * t * 30.0 / std::f64::consts::PI;
    assert!(
        (speed - expected).abs() < 0.02 * expected,
        "after {t} s from rest the motor runs at {speed} rev/min, {expected} expected"
    );
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
