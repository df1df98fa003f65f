//! `testrig simulate --rig` on the shipped rig files: columns named after the rig, the
//! load carried through both stages of a reduction, fields set by path, a loop's locked
//! torque, bad arguments refused; `--approach rest` starting the rig at rest with the
//! motor at its limit; the summary of the 1983 rig as a file in a preset's keys, equal
//! to the preset's.

mod common;

use common::{folder, json_of, rig_file, testrig};

#[test]
fn simulate_runs_a_rig_file_naming_its_columns_after_the_rig_and_sets_fields_by_path() {
    let out = folder("simulate-rig-file");
    let dir = out.path().join("run");
    let dir_text = dir.to_str().expect("path");
    let report = json_of(&[
        "simulate",
        "--rig",
        &rig_file("two-stage"),
        "--rpm",
        "1200",
        "--load",
        "45",
        "--settle",
        "1",
        "--duration",
        "0.5",
        "--out",
        dir_text,
        "--json",
    ]);
    // The load goes through both stages: 45 N m at the output, 15 and 5 N m before.
    let shaft = |name: &str| -> f64 {
        report["shafts"]
            .as_array()
            .expect("shafts")
            .iter()
            .find(|s| s["name"] == name)
            .unwrap_or_else(|| panic!("no shaft {name}"))["torque_mean_nm"]
            .as_f64()
            .expect("number")
    };
    assert!((shaft("output") - 45.0).abs() < 1e-3, "{report}");
    assert!((shaft("intermediate") - 15.0).abs() < 1e-3, "{report}");
    assert!((shaft("input") - 5.0).abs() < 1e-3, "{report}");
    let mut csv = csv::Reader::from_path(dir.join("signals.csv")).expect("signals.csv");
    let header: Vec<String> = csv
        .headers()
        .expect("header")
        .iter()
        .map(String::from)
        .collect();
    for column in [
        "time_s",
        "speed_motor_rpm",
        "speed_brake_rpm",
        "angle_wheel1_rad",
        "torque_output_nm",
        "contact_stage1",
        "force_stage2_n",
        "motor_torque_nm",
        "strain_output_ue",
    ] {
        assert!(header.iter().any(|h| h == column), "{column} in {header:?}");
    }
    let rows: Vec<csv::StringRecord> = csv.records().map(|r| r.expect("row")).collect();
    assert_eq!(rows.len(), 25_600, "0.5 s at 51.2 kHz");
    let at = |row: &csv::StringRecord, name: &str| -> f64 {
        let i = header.iter().position(|h| h == name).expect("column");
        row[i].parse().expect("number")
    };
    // 45 N m on the Ø40 mm steel shaft: 8 T / (π d³ G) = 22.4 µε.
    let strain = at(&rows[100], "strain_output_ue");
    let expected = 8.0 * 45.0 / (std::f64::consts::PI * 0.04_f64.powi(3) * 80.0e9) * 1e6;
    assert!(
        (strain / expected - 1.0).abs() < 1e-4,
        "{strain} µε against {expected}"
    );
    assert!((at(&rows[100], "speed_brake_rpm") - 1200.0 / 9.0).abs() < 1e-3);

    // --set by path: drag on the first wheel costs the motor c (1/3)² Ω more; a path
    // that does not exist, or a value the check refuses, is named.
    let dragged = json_of(&[
        "simulate",
        "--rig",
        &rig_file("two-stage"),
        "--rpm",
        "1200",
        "--load",
        "45",
        "--settle",
        "1",
        "--duration",
        "0.5",
        "--set",
        "body.wheel1.drag_nms_per_rad=0.1",
        "--json",
    ]);
    let motor = dragged["motor_torque_mean_nm"]
        .as_f64()
        .expect("motor torque");
    let expected = 45.0 / 9.0 + 0.1 / 9.0 * 1200.0 * std::f64::consts::PI / 30.0;
    assert!(
        (motor - expected).abs() < 1e-3,
        "{motor} N m against {expected}"
    );
    let loop_rig = testrig(&[
        "simulate",
        "--rig",
        &rig_file("fzg-back-to-back"),
        "--rpm",
        "1450",
        "--load",
        "5",
    ]);
    let err = String::from_utf8_lossy(&loop_rig.stderr);
    assert!(
        !loop_rig.status.success() && err.contains("--load 5") && err.contains("no [brake]"),
        "{err}"
    );
    for (set, says) in [
        ("mesh.stage9.backlash_mm=0.4", "mesh.stage9.backlash_mm"),
        ("mesh.stage1.backlash_mm=-1", "backlash_mm"),
    ] {
        let out = testrig(&[
            "simulate",
            "--rig",
            &rig_file("two-stage"),
            "--rpm",
            "600",
            "--load",
            "10",
            "--set",
            set,
        ]);
        let err = String::from_utf8_lossy(&out.stderr);
        assert!(!out.status.success() && err.contains(says), "{set}: {err}");
    }
}

#[test]
fn simulate_approach_rest_starts_the_rig_at_rest_with_the_motor_at_its_limit() {
    let dir = folder("rig-approach-rest");
    let out = dir.path().join("run");
    let args = [
        "simulate",
        "--rig",
        &rig_file("basmaji-1983"),
        "--rpm",
        "1300",
        "--load",
        "2.712",
        "--approach",
        "rest",
        "--settle",
        "0",
        "--duration",
        "1",
        "--rate",
        "1000",
        "--out",
        out.to_str().expect("path"),
    ];
    let run = testrig(&args);
    assert!(
        run.status.success(),
        "{}",
        String::from_utf8_lossy(&run.stderr)
    );
    let rows = common::csv_rows(&out.join("signals.csv"));
    let first = &rows[0];
    for body in [
        "motor",
        "input_flywheel",
        "driven_gear",
        "output_flywheel",
        "brake",
    ] {
        assert_eq!(common::number(first, &format!("speed_{body}_rpm")), 0.0);
    }
    // 1300 rev/min asked of a rig at rest: the speed loop saturates at the 7.12 N m limit,
    // and the rig gains speed at (limit − load) / ΣJ at most.
    let limit = 7.120909241507619;
    assert!((common::number(first, "motor_torque_nm") - limit).abs() < 1e-9);
    let last = &rows[rows.len() - 1];
    let speed_rad_s = common::number(last, "speed_motor_rpm") * std::f64::consts::PI / 30.0;
    let inertia = 0.0163 + 0.355 + 0.00865 + 0.45 + 0.015;
    let most = (limit - 2.712) / inertia * 0.999;
    assert!(
        speed_rad_s > 0.8 * most && speed_rad_s < 1.05 * most,
        "{speed_rad_s} rad/s after 1 s; (limit − load)/ΣJ gives {most}"
    );
}

/// The 1983 rig through `--rig scenarios/rigs/basmaji-1983.toml` and through its preset at
/// 1300 rev/min, 2.712 N m (the half-order motion, the teeth parting every revolution),
/// settled 20 s (the preset's `regime`, read from its once-per-revolution states, still
/// calls the motion aperiodic after 3 s; a rig file's is the judge's period):
/// the rig file's summary holds every key of the preset's, and they agree: the same
/// impacts, regime and motion, the whole revolutions within one, the time apart, the
/// judged shaft's torque and the motor's speed offset within 1e-6 of each other.
/// (`impacts_per_tooth` is compared as a pattern: the two plants number the driving
/// gear's teeth from neighbouring teeth.)
#[test]
fn a_rig_files_summary_holds_a_presets_keys_with_the_presets_values() {
    let point = [
        "--rpm",
        "1300",
        "--load",
        "2.712",
        "--settle",
        "20",
        "--duration",
        "2",
    ];
    let run = |door: &[&str]| {
        let args: Vec<&str> = ["simulate"]
            .iter()
            .chain(door)
            .chain(&point)
            .chain(&["--json"])
            .copied()
            .collect();
        json_of(&args)
    };
    let file = rig_file("basmaji-1983");
    let rig = run(&["--rig", &file]);
    let preset = run(&["--preset", "basmaji-1983"]);
    let keys = preset.as_object().expect("an object");
    for key in keys.keys().filter(|k| k.as_str() != "preset") {
        assert!(
            rig.get(key).is_some(),
            "the rig file's summary lacks `{key}`"
        );
    }
    for key in ["impacts", "regime", "separates"] {
        assert_eq!(rig[key], preset[key], "{key}");
    }
    assert_eq!(rig["motion"]["motion"], preset["motion"]["motion"]);
    assert_eq!(preset["regime"], "period-2", "the half-order motion");
    // Whole revolutions in the window: 43.3 turn, counted from where each plant's
    // once-per-revolution mark falls (the motor's body or the driving gear).
    let turns = |s: &serde_json::Value| s["revolutions"].as_f64().expect("revolutions");
    assert!((turns(&rig) - turns(&preset)).abs() <= 1.0);
    assert!((turns(&preset) - 1300.0 / 60.0 * 2.0).abs() < 1.0);
    for key in [
        "apart_fraction",
        "torque_mean_nm",
        "torque_rms_nm",
        "torque_ac_rms_nm",
        "speed_offset_rpm",
    ] {
        let (a, b) = (
            rig[key].as_f64().expect(key),
            preset[key].as_f64().expect(key),
        );
        assert!(
            (a - b).abs() <= 1e-6 * b.abs().max(1.0),
            "{key}: rig file {a}, preset {b}"
        );
    }
    let teeth = |summary: &serde_json::Value| -> Vec<u64> {
        let mut t: Vec<u64> = summary["impacts_per_tooth"]
            .as_array()
            .expect("teeth")
            .iter()
            .map(|v| v.as_u64().expect("count"))
            .collect();
        t.sort_unstable();
        t
    };
    assert_eq!(
        teeth(&rig),
        teeth(&preset),
        "the same counts on the teeth struck"
    );
}
