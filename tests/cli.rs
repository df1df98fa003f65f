//! End-to-end tests of the `testrig` binary.

mod common;

use std::process::Command;

use common::{json, testrig};

fn numbers(value: &serde_json::Value) -> Vec<f64> {
    value
        .as_array()
        .expect("an array")
        .iter()
        .map(|v| v.as_f64().expect("a number"))
        .collect()
}

/// App. C from `testrig modes` on the 1983 rig (the preset is its rig file). With the
/// teeth apart: the motor side at 91.90 Hz, the brake side at 86.28 and 88.7 Hz, as App. C
/// gives them. With the gear pair rigid: App. C's whole rig (17.84, 86.95, 91.95 Hz)
/// leaves the driven gear's inertia out, ours counts it, so each lies within 0.7 % of
/// App. C's (measured: 17.73, 86.95, 91.90); and the rigid pair is the limit of a stiff
/// one: with the mesh a million times stiffer, the modes in contact are the rigid modes
/// to 1e-5.
#[test]
fn modes_reproduce_appendix_c() {
    let out = json(&testrig(&["modes", "--json"]));
    let apart = out["meshes_apart"].as_array().expect("the parts");
    assert_eq!(apart.len(), 2, "{apart:?}");
    assert!((numbers(&apart[0]["natural_hz"])[0] - 91.90).abs() < 0.01);
    let brake = numbers(&apart[1]["natural_hz"]);
    assert!(
        (brake[0] - 86.28).abs() < 0.05 && (brake[1] - 88.7).abs() < 0.05,
        "{brake:?}"
    );
    let rigid = numbers(&out["rigid_meshes"]["natural_hz"]);
    assert_eq!(rigid.len(), 3);
    for (got, app_c) in rigid.iter().zip([17.84, 86.95, 91.95]) {
        assert!((got / app_c - 1.0).abs() < 0.007, "{rigid:?}");
    }
    assert!(
        (rigid[0] - 17.84).abs() > 0.05,
        "the driven gear's inertia counts"
    );
    assert_eq!(numbers(&out["natural_hz"]).len(), 4);
    let stiff = json(&testrig(&[
        "modes",
        "--json",
        "--set",
        "mesh.gears.stiffness_n_per_m=2.617e14",
    ]));
    let in_contact = numbers(&stiff["natural_hz"]);
    for (a, b) in in_contact.iter().zip(&rigid) {
        assert!(
            (a / b - 1.0).abs() < 1e-5,
            "{in_contact:?} against {rigid:?}"
        );
    }
}

#[test]
fn simulate_reports_the_summary_keys() {
    let out = json(&testrig(&[
        "simulate",
        "--rpm",
        "600",
        "--load",
        "2.712",
        "--settle",
        "2",
        "--duration",
        "1",
        "--json",
    ]));
    for key in [
        "simulated_s",
        "wall_s",
        "impacts",
        "regime",
        "separates",
        "torque_mean_nm",
        "torque_rms_nm",
    ] {
        assert!(out.get(key).is_some(), "missing {key}");
    }
    assert_eq!(out["simulated_s"].as_f64(), Some(3.0));
    assert!((out["torque_mean_nm"].as_f64().expect("number") - 2.712).abs() < 0.05);
    assert!(
        out["regime"].as_str().expect("text").starts_with("period-")
            || out["regime"] == "aperiodic"
    );
}

#[test]
fn simulate_writes_signals_impacts_and_summary() {
    let dir = common::folder("cli-simulate");
    let out = testrig(&[
        "simulate",
        "--rpm",
        "1300",
        "--load",
        "2.712",
        "--settle",
        "0.5",
        "--duration",
        "0.2",
        "--rate",
        "10240",
        "--out",
        dir.to_str().expect("utf-8"),
    ]);
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let signals = std::fs::read_to_string(dir.join("signals.csv")).expect("signals.csv");
    let mut lines = signals.lines();
    let header = lines.next().expect("header");
    // The preset's rig file names the columns after its bodies, shafts and mesh.
    assert!(header.starts_with("time_s,speed_motor_rpm"), "{header}");
    assert!(header.contains(",torque_intermediate_nm,"), "{header}");
    assert_eq!(lines.count(), 2048);
    assert!(dir.join("summary.json").exists());
    // One header, then one row per impact: time, mesh, flank, closing speed, teeth.
    let impacts = std::fs::read_to_string(dir.join("impacts.csv")).expect("impacts.csv");
    let mut rows = impacts.lines();
    assert_eq!(
        rows.next(),
        Some("time_s,mesh,flank,closing_speed_m_s,driver_tooth,driven_tooth")
    );
    let rows: Vec<&str> = rows.collect();
    assert!(!rows.is_empty(), "1300 rev/min, 2.712 N m impacts");
    for row in rows {
        let fields: Vec<&str> = row.split(',').collect();
        assert!(
            fields.len() == 6
                && fields[0].parse::<f64>().is_ok()
                && fields[1] == "gears"
                && ["drive", "back"].contains(&fields[2])
                && fields[4]
                    .parse::<u32>()
                    .is_ok_and(|t| (1..=30).contains(&t)),
            "{row}"
        );
    }
    assert!(!dir.join("signals.csv.partial").exists());
    std::fs::remove_dir_all(&dir).ok();
}

#[test]
fn overrides_reach_the_model() {
    let out = json(&testrig(&[
        "modes",
        "--json",
        "--set",
        "k12_input_shaft_nm_per_rad=20784.8",
    ]));
    // Four times the stiffness doubles the motor-side frequency (teeth apart).
    let motor_side = numbers(&out["meshes_apart"][0]["natural_hz"]);
    assert!((motor_side[0] - 2.0 * 91.90).abs() < 0.02);
}

#[test]
fn bad_input_names_the_field_and_fails_cleanly() {
    let cases: [(&[&str], &str); 5] = [
        (&["modes", "--preset", "nope"], "nope"),
        (&["modes", "--set", "teeth=abc"], "teeth"),
        (&["modes", "--set", "flywheel=2"], "flywheel"),
        (&["simulate", "--rpm", "-5", "--load", "0"], "speed"),
        (
            &[
                "simulate",
                "--rpm",
                "600",
                "--load",
                "0",
                "--duration",
                "NaN",
            ],
            "--duration",
        ),
    ];
    for (args, word) in cases {
        let out = testrig(args);
        let stderr = String::from_utf8_lossy(&out.stderr);
        assert!(!out.status.success(), "{args:?} must fail");
        assert!(stderr.contains(word), "{args:?}: {stderr}");
        assert!(!stderr.contains("panicked"), "{stderr}");
    }
}

#[test]
fn a_closed_pipe_ends_the_output_quietly_without_a_panic() {
    use std::os::unix::process::ExitStatusExt;
    for command in [&["modes"][..], &["params"], &["modes", "--json"]] {
        let mut child = Command::new(env!("CARGO_BIN_EXE_testrig"))
            .args(command)
            .stdout(std::process::Stdio::piped())
            .stderr(std::process::Stdio::piped())
            .spawn()
            .expect("starts");
        // Close the reading end at once, as `| head -0` would: every write hits EPIPE.
        drop(child.stdout.take());
        let output = child.wait_with_output().expect("ends");
        let stderr = String::from_utf8_lossy(&output.stderr);
        assert!(!stderr.contains("panicked"), "{command:?}: {stderr}");
        assert!(
            output.status.success() || output.status.signal() == Some(libc::SIGPIPE),
            "{command:?}: {:?}",
            output.status
        );
    }
}

#[test]
fn a_file_given_to_the_wrong_command_is_sent_to_the_right_one() {
    let dir = env!("CARGO_MANIFEST_DIR");
    let campaign = format!("{dir}/scenarios/thesis-campaign.toml");
    let scratch = common::folder("wrong-command");
    let out = scratch.to_str().expect("utf-8");
    let run = testrig(&["run", &campaign, "--out", out]);
    let stderr = String::from_utf8_lossy(&run.stderr);
    assert!(!run.status.success());
    assert!(
        stderr.contains("this is a sweep file") && stderr.contains("testrig sweep"),
        "{stderr}"
    );
    let scenario = format!("{dir}/scenarios/subharmonic-2712nm.toml");
    let sweep = testrig(&["sweep", &scenario, "--out", out]);
    let stderr = String::from_utf8_lossy(&sweep.stderr);
    assert!(!sweep.status.success());
    assert!(
        stderr.contains("this is a scenario file") && stderr.contains("testrig run"),
        "{stderr}"
    );
    assert!(!std::path::Path::new(out).join("manifest.json").exists());
}

/// The motor's limit counts the rig's residual drag with the load: 5.424 N m with 3 N m
/// of drag (8.4 N m) is beyond the 2 hp motor's 7.12 N m and refused before any run,
/// naming the drag; with the preset's 0.6 N m it runs.
#[test]
fn a_load_and_drag_beyond_the_motor_are_refused_naming_the_drag() {
    let args = |drag: &'static str| {
        [
            "simulate",
            "--preset",
            "basmaji-1983-rig",
            "--set",
            drag,
            "--rpm",
            "600",
            "--load",
            "5.424",
            "--settle",
            "1",
            "--duration",
            "1",
        ]
    };
    let refused = testrig(&args("brake_drag_nm=3.0"));
    let said = String::from_utf8_lossy(&refused.stderr);
    assert!(
        !refused.status.success()
            && said.contains("brake_drag_nm")
            && said.contains("more than the motor can hold"),
        "{said}"
    );
    let runs = testrig(&args("brake_drag_nm=0.6"));
    assert!(
        runs.status.success(),
        "{}",
        String::from_utf8_lossy(&runs.stderr)
    );
    // The rig file of the same preset: the same check, the same words.
    let file = common::rig_file("basmaji-1983-rig");
    let file_args = |drag: &'static str| {
        let mut args: Vec<&str> = args("").to_vec();
        args[1] = "--rig";
        args[2] = file.as_str();
        args[4] = drag;
        args
    };
    let refused = testrig(&file_args("brake.drag_nm=3.0"));
    let said = String::from_utf8_lossy(&refused.stderr);
    assert!(
        !refused.status.success()
            && said.contains("drag_nm")
            && said.contains("more than the motor can hold"),
        "{said}"
    );
    let runs = testrig(&file_args("brake.drag_nm=0.6"));
    assert!(
        runs.status.success(),
        "{}",
        String::from_utf8_lossy(&runs.stderr)
    );
}

/// `simulate` averages the output-shaft torque synchronously over the driven gear's
/// revolutions: a period-1 motion is all synchronous (the average keeps its whole AC RMS),
/// a period-2 motion's half-order content averages away.
#[test]
fn the_synchronous_average_keeps_a_period_1_motion_and_drops_the_half_order_of_period_2() {
    let point = |rpm: &str| -> serde_json::Value {
        let out = testrig(&[
            "simulate",
            "--rpm",
            rpm,
            "--load",
            "2.712",
            "--duration",
            "10",
            "--json",
        ]);
        assert!(
            out.status.success(),
            "{}",
            String::from_utf8_lossy(&out.stderr)
        );
        serde_json::from_slice(&out.stdout).expect("JSON")
    };
    let share = |p: &serde_json::Value| {
        p["condition"]["rms_nm"].as_f64().expect("rms")
            / p["torque_ac_rms_nm"].as_f64().expect("ac rms")
    };
    let slow = point("600");
    assert_eq!(slow["motion"]["motion"], "period-1");
    assert!((share(&slow) - 1.0).abs() < 1e-3, "{}", share(&slow));
    let revolutions = slow["revolutions"].as_u64().expect("count");
    let averaged = slow["condition"]["revolutions_averaged"]
        .as_u64()
        .expect("count");
    assert!(
        revolutions - averaged <= 1,
        "{revolutions} against {averaged}"
    );
    let fast = point("1300");
    assert_eq!(fast["motion"]["motion"], "period-2");
    assert!(share(&fast) < 0.5, "{}", share(&fast));
    for key in [
        "fm0",
        "fm4",
        "m6a",
        "m8a",
        "na4",
        "sideband_level",
        "crest_factor",
        "kurtosis",
    ] {
        assert!(
            fast["condition"][key].as_f64().is_some_and(f64::is_finite),
            "{key}"
        );
    }
}
