//! `testrig simulate --rig` on the shipped rig files: columns named after the rig, the
//! load carried through both stages of a reduction, fields set by path, a loop's locked
//! torque, bad arguments refused; `--approach rest` starting the rig at rest with the
//! motor at its limit; a preset running as its rig file, the thesis's names as paths.

mod common;

use common::{folder, json_of, named_number, rig_file, testrig};

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
    let shaft = |name: &str| named_number(&report, "shafts", name, "torque_mean_nm");
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

/// A preset is the short name of its rig file: the 1983 rig through `--preset` and
/// through `--rig scenarios/rigs/basmaji-1983.toml` at 1300 rev/min, 2.712 N m (the
/// half-order motion, the teeth parting every revolution), settled 20 s, gives the same
/// summary, key for key and value for value (the door's own keys and the wall time
/// aside); a thesis's name set on the preset (`brake_drag_nm`) is its rig path set on the
/// file (`brake.drag_nm`), and the gauged shaft carries it beside the load (to 20 mN m:
/// the mean of a rattling window is the load's within 6 mN m).
#[test]
fn a_preset_runs_as_its_rig_file_and_takes_the_thesis_names_as_rig_paths() {
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
        let mut summary = json_of(&args);
        let map = summary.as_object_mut().expect("an object");
        for key in ["preset", "rig_file", "wall_s", "realtime_factor"] {
            map.remove(key);
        }
        summary
    };
    let file = rig_file("basmaji-1983");
    let preset = run(&["--preset", "basmaji-1983"]);
    assert_eq!(run(&["--rig", &file]), preset);
    assert_eq!(preset["regime"], "period-2", "the half-order motion");
    assert_eq!(preset["motion"]["motion"], "period-2");
    let turns = preset["revolutions"].as_f64().expect("revolutions");
    assert!((turns - 1300.0 / 60.0 * 2.0).abs() < 1.0, "{turns}");
    // One mesh: every impact falls on one of the driving gear's 30 teeth.
    let per_tooth: Vec<u64> = preset["impacts_per_tooth"]
        .as_array()
        .expect("teeth")
        .iter()
        .map(|n| n.as_u64().expect("a count"))
        .collect();
    assert_eq!(per_tooth.len(), 30);
    assert_eq!(
        per_tooth.iter().sum::<u64>(),
        preset["impacts"].as_u64().expect("impacts"),
        "{per_tooth:?}"
    );
    let named = run(&["--preset", "basmaji-1983", "--set", "brake_drag_nm=1.5"]);
    let by_path = run(&["--rig", &file, "--set", "brake.drag_nm=1.5"]);
    assert_eq!(named, by_path);
    let torque = |s: &serde_json::Value| s["torque_mean_nm"].as_f64().expect("torque");
    assert!(
        (torque(&named) - torque(&preset) - 1.5).abs() < 0.02,
        "the drag adds to the load the gauged shaft carries: {} against {} N m",
        torque(&named),
        torque(&preset)
    );
}

/// A gear train of six external stages (more than the four a rig file once held; the
/// limit is twenty meshes in all): each stage turns its wheel at 2/3 of its pinion's
/// speed, so the brake turns at (2/3)⁶ of the motor's, and in steady motion the motor
/// gives the brake's load times that ratio (no drag, every mesh loaded on its drive flank).
#[test]
fn a_six_stage_gear_train_turns_at_the_product_of_its_ratios_and_balances_its_torque() {
    let stages = 6;
    let mut text = String::from(
        "name = \"six-stage\"\n[[body]]\nname = \"motor\"\ninertia_kgm2 = 0.01\n\
         [[body]]\nname = \"brake\"\ninertia_kgm2 = 0.05\n",
    );
    for k in 0..stages {
        text.push_str(&format!(
            "[[body]]\nname = \"pinion{k}\"\ninertia_kgm2 = 0.001\n\
             [[body]]\nname = \"wheel{k}\"\ninertia_kgm2 = 0.002\n\
             [[mesh]]\nname = \"stage{k}\"\ndriver = \"pinion{k}\"\ndriven = \"wheel{k}\"\n\
             teeth = [20, 30]\nmodule_m = 0.003\nbacklash_mm = 0.1\n\
             stiffness_n_per_m = 3.0e8\ndamping_ns_per_m = 1500.0\n"
        ));
        let from = if k == 0 {
            "motor".to_string()
        } else {
            format!("wheel{}", k - 1)
        };
        text.push_str(&format!(
            "[[shaft]]\nname = \"shaft{k}\"\nbetween = [\"{from}\", \"pinion{k}\"]\n\
             stiffness_nm_per_rad = 20000.0\ndamping_nms_per_rad = 0.5\n"
        ));
    }
    text.push_str(&format!(
        "[[shaft]]\nname = \"output\"\nbetween = [\"wheel{}\", \"brake\"]\n\
         stiffness_nm_per_rad = 20000.0\ndamping_nms_per_rad = 0.5\n\
         [motor]\nbody = \"motor\"\n[brake]\nbody = \"brake\"\n",
        stages - 1
    ));
    let dir = folder("six-stage");
    let path = dir.path().join("six-stage.toml");
    std::fs::write(&path, text).expect("rig file");
    let report = json_of(&[
        "simulate",
        "--rig",
        path.to_str().expect("utf-8"),
        "--rpm",
        "1500",
        "--load",
        "20",
        "--settle",
        "2",
        "--duration",
        "1",
        "--json",
    ]);
    let ratio = (2.0_f64 / 3.0).powi(stages);
    let brake_rpm = named_number(&report, "bodies", "brake", "speed_mean_rpm");
    assert!(
        (brake_rpm / 1500.0 - ratio).abs() < 1e-6 * ratio,
        "brake {brake_rpm} rev/min against {}",
        1500.0 * ratio
    );
    let motor_nm = report["motor_torque_mean_nm"].as_f64().expect("number");
    assert!(
        (motor_nm - 20.0 * ratio).abs() < 1e-6,
        "motor {motor_nm} N m against {}",
        20.0 * ratio
    );
    assert_eq!(report["impacts"], 0, "{report}");
}
