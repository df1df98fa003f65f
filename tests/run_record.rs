//! End-to-end tests of `testrig run` as an instrument of record: byte-identical recordings
//! at any pace, overruns counted, Ctrl-C, the recorded formats, and bad input.

mod common;

use std::path::Path;
use std::process::Command;

use common::{check_files, folder, has_file, read_manifest, run_ok, scenario, sets, testrig};
use sha2::Digest;

#[test]
fn recordings_are_byte_identical_at_any_pace_and_depend_on_the_seed() {
    let args = ["--duration", "2"];
    let (max_out, _) = run_ok("pace-max", &scenario("aliasing-windowing"), &args);
    let (paced_out, paced) = run_ok(
        "pace-20",
        &scenario("aliasing-windowing"),
        &["--duration", "2", "--pace", "20"],
    );
    assert_eq!(paced["pace"], "20");
    assert!(paced["wall_s"].as_f64().expect("wall") >= 2.0 / 20.0);
    for file in ["recording.wav", "recording.uff", "impacts.csv"] {
        let a = std::fs::read(max_out.join(file)).expect("max");
        let b = std::fs::read(paced_out.join(file)).expect("paced");
        assert!(a == b, "{file} differs between pace max and pace 20");
    }
    // The manifest names the scenario as run by its SHA-256.
    let text = std::fs::read(scenario("aliasing-windowing")).expect("scenario");
    let digest: String = sha2::Sha256::digest(&text)
        .iter()
        .map(|b| format!("{b:02x}"))
        .collect();
    assert_eq!(paced["scenario_sha256"].as_str(), Some(digest.as_str()));
    let (seeded_out, _) = run_ok(
        "seed",
        &scenario("aliasing-windowing"),
        &["--duration", "2", "--seed", "7"],
    );
    let a = std::fs::read(max_out.join("recording.wav")).expect("max");
    let c = std::fs::read(seeded_out.join("recording.wav")).expect("seeded");
    assert!(a != c, "the slip-ring noise follows the seed");
    for dir in [max_out, paced_out, seeded_out] {
        std::fs::remove_dir_all(dir).ok();
    }
}

fn write_scenario(dir: &Path, name: &str, text: &str) -> String {
    let path = dir.join(name);
    std::fs::write(&path, text).expect("scenario written");
    path.to_string_lossy().into_owned()
}

const MINIMAL: &str = r#"name = "minimal"
duration_s = 1

[schedule]
speed_rpm = 600
load_nm = 2.712
"#;

#[test]
fn bad_input_is_named_by_file_line_and_field_without_a_panic() {
    let dir = folder("bad");
    let cases: [(&str, String, &[&str]); 10] = [
        (
            "gate.toml",
            format!("{MINIMAL}\n[chain.tacho]\ngate_s = 1e-9\n"),
            &[":9:", "chain.tacho", "gate"],
        ),
        (
            "no-name.toml",
            MINIMAL.replace("name = \"minimal\"\n", ""),
            &[":1:1:", "top level", "missing field `name`"],
        ),
        (
            "decimate.toml",
            format!(
                "{MINIMAL}\n[record]\ndecimate = 100000000\nsignals = [\"amplifier_v\"]\nformats = [\"wav\"]\n"
            ),
            &[":9:", "record.decimate", "whole sample rate"],
        ),
        (
            "wav-size.toml",
            format!(
                "{}\n[record]\nsignals = [\"amplifier_v\"]\nformats = [\"wav\"]\n",
                MINIMAL.replace("duration_s = 1", "duration_s = 30000")
            ),
            &[":9:", "record.signals", "4 GiB"],
        ),
        (
            "negative-speed.toml",
            MINIMAL.replace("speed_rpm = 600", "speed_rpm = -600"),
            &[":5:", "speed_rpm", "[0, 10000]"],
        ),
        (
            "unknown-key.toml",
            MINIMAL.replace("load_nm", "lode_nm"),
            &[":6:", "unknown field `lode_nm`"],
        ),
        (
            "nan.toml",
            MINIMAL.replace("2.712", "nan"),
            &[":6:", "load_nm", "finite"],
        ),
        (
            "cutoff.toml",
            format!("{MINIMAL}\n[chain.filter]\nkind = \"bessel\"\ncutoff_hz = 30000\n"),
            &[":10:", "chain.filter.cutoff_hz", "Nyquist"],
        ),
        (
            "preset.toml",
            format!("{MINIMAL}\n[rig]\npreset = \"basmaji-1984\"\n"),
            &[":9:", "rig.preset", "unknown preset", "basmaji-1983"],
        ),
        (
            "order.toml",
            format!("{MINIMAL}\n[analyser]\nfmax_hz = 40000\n"),
            &[":9:", "analyser.fmax_hz", "above the stream rate"],
        ),
    ];
    for (name, text, expected) in cases {
        let path = write_scenario(&dir, name, &text);
        let out = dir.join("out");
        let output = testrig(&[
            "run",
            &path,
            "--pace",
            "max",
            "--out",
            out.to_str().expect("utf-8"),
        ]);
        let stderr = String::from_utf8_lossy(&output.stderr);
        assert_eq!(output.status.code(), Some(1), "{name}: {stderr}");
        assert!(stderr.contains(name), "{name}: {stderr}");
        for e in expected {
            assert!(stderr.contains(e), "{name}: `{e}` not in {stderr}");
        }
    }
    let missing = testrig(&["run", "no-such.toml", "--out", dir.to_str().expect("utf-8")]);
    assert_eq!(missing.status.code(), Some(1));
    assert!(String::from_utf8_lossy(&missing.stderr).contains("no-such.toml: cannot read"));
    let good = write_scenario(&dir, "good.toml", MINIMAL);
    let blocked = dir.join("a-file");
    std::fs::write(&blocked, "not a folder").expect("file");
    let unwritable = blocked.join("out");
    let output = testrig(&[
        "run",
        &good,
        "--pace",
        "max",
        "--out",
        unwritable.to_str().expect("utf-8"),
    ]);
    assert_eq!(output.status.code(), Some(1));
    assert!(String::from_utf8_lossy(&output.stderr).contains("cannot create the output folder"));
    std::fs::remove_dir_all(&dir).ok();
}

/// A run hands on the rig's own columns beside the standard inputs, named as `testrig
/// simulate` writes them (the 1983 preset at 600 rev/min and 2.712 N m, 3 s recorded as
/// CSV): the gauged shaft's torque under both names is the same number, sample for
/// sample; the motor's speed in rev/min is the tacho's input in rad/s times 30/π; the
/// 1:1 gears turn the driven gear at the set speed on average (within 0.5 %); the mesh's
/// contact is a state of +1, −1 or 0, here on the drive flank most of the time.
#[test]
fn a_run_records_the_rigs_own_columns_as_simulate_names_them() {
    let dir = folder("rig-columns");
    let signals = [
        "torque_intermediate_shaft_nm",
        "torque_intermediate_nm",
        "speed1_rad_s",
        "speed_motor_rpm",
        "speed_driven_gear_rpm",
        "contact_gears",
    ]
    .map(|s| format!("\"{s}\""))
    .join(", ");
    let text = format!(
        "{}\n[record]\nsignals = [{signals}]\nformats = [\"csv\"]\n",
        MINIMAL.replace("duration_s = 1\n", "duration_s = 3\n")
    );
    let path = write_scenario(&dir, "columns.toml", &text);
    let (out, _) = run_ok("rig-columns-run", &path, &[]);
    let rows = common::csv_rows(&out.join("recording.csv"));
    assert_eq!(rows.len(), 3 * 51_200);
    let value = |row: &std::collections::HashMap<String, String>, name: &str| -> f64 {
        row[name].parse().expect("a number")
    };
    let (mut driven_rpm, mut drive_flank) = (0.0, 0);
    for row in &rows {
        assert_eq!(
            row["torque_intermediate_shaft_nm"],
            row["torque_intermediate_nm"]
        );
        let rpm = value(row, "speed_motor_rpm");
        let rad_s = value(row, "speed1_rad_s");
        assert!((rpm - rad_s * 30.0 / std::f64::consts::PI).abs() <= 1e-9 * rpm.abs().max(1.0));
        let contact = value(row, "contact_gears");
        assert!([1.0, 0.0, -1.0].contains(&contact), "{row:?}");
        drive_flank += usize::from(contact == 1.0);
        driven_rpm += value(row, "speed_driven_gear_rpm");
    }
    // Loaded, the teeth ride on the drive flank most of the time (95 % here, measured),
    // apart between impacts.
    assert!(
        drive_flank > rows.len() / 2,
        "{drive_flank} of {}",
        rows.len()
    );
    let mean = driven_rpm / rows.len() as f64;
    assert!(
        (mean / 600.0 - 1.0).abs() < 0.005,
        "driven gear {mean} rev/min"
    );
    std::fs::remove_dir_all(&dir).ok();
}

#[test]
fn a_dropping_queue_counts_every_overrun_and_the_recording_shows_the_gaps() {
    let dir = folder("drop");
    let signals = [
        "time_s",
        "angle_motor_rad",
        "angle_input_flywheel_rad",
        "speed1_rad_s",
        "speed_input_flywheel_rpm",
        "torque_input_nm",
        "torque_intermediate_shaft_nm",
        "amplifier_v",
        "filter_v",
        "meter_v",
    ]
    .map(|s| format!("\"{s}\""))
    .join(", ");
    let text = format!(
        "{}\n[record]\nsignals = [{signals}]\nformats = [\"csv\", \"wav\"]\n",
        MINIMAL.replace(
            "duration_s = 1\n",
            "duration_s = 3\noverflow = \"drop\"\nqueue_blocks = 1\nblock_samples = 256\n"
        )
    );
    let path = write_scenario(&dir, "drop.toml", &text);
    let (out, manifest) = run_ok("drop-run", &path, &["--pace", "100"]);
    let overruns = manifest["overruns"].as_u64().expect("count");
    assert!(
        overruns > 0,
        "CSV of ten signals cannot keep up at 100x real time"
    );
    assert_eq!(
        manifest["overrun_times_s"].as_array().map(Vec::len),
        Some(overruns as usize)
    );
    // Gaps the recorder saw; drops after its last block leave no gap behind them.
    assert!(
        manifest["recording_gaps_blocks"]
            .as_u64()
            .is_some_and(|g| g > 0 && g <= overruns)
    );
    let released = (3.0 * 51_200.0 / 256.0) as u64;
    assert_eq!(
        manifest["wav_frames"].as_u64(),
        Some((released - overruns) * 256)
    );
    std::fs::remove_dir_all(&out).ok();
    std::fs::remove_dir_all(&dir).ok();
}

#[test]
fn ctrl_c_and_sigterm_close_every_file_with_the_samples_up_to_the_stop() {
    for (signal, status_code) in [("INT", 130), ("TERM", 143)] {
        let out = folder(&format!("signal-{signal}"));
        let child = Command::new(env!("CARGO_BIN_EXE_testrig"))
            .args([
                "run",
                &scenario("aliasing-windowing"),
                "--pace",
                "1",
                "--duration",
                "60",
            ])
            .args(["--out", out.to_str().expect("utf-8")])
            .stderr(std::process::Stdio::piped())
            .spawn()
            .expect("started");
        std::thread::sleep(std::time::Duration::from_millis(2500));
        let killed = Command::new("kill")
            .args([&format!("-{signal}"), &child.id().to_string()])
            .status()
            .expect("kill runs");
        assert!(killed.success());
        let output = child.wait_with_output().expect("exits");
        assert_eq!(output.status.code(), Some(status_code), "SIG{signal}");
        assert!(
            String::from_utf8_lossy(&output.stderr).contains(&format!("stopped by SIG{signal}"))
        );
        let manifest = read_manifest(&out);
        assert_eq!(manifest["ending"], "interrupted");
        check_files(&out, &manifest);
        let simulated = manifest["simulated_s"].as_f64().expect("simulated");
        assert!(simulated > 1.0 && simulated < 10.0, "{simulated}");
        let reader = hound::WavReader::open(out.join("recording.wav")).expect("a complete WAV");
        let frames = u64::from(reader.duration());
        assert_eq!(frames, (simulated * 51_200.0).round() as u64);
        assert_eq!(manifest["wav_frames"].as_u64(), Some(frames));
        std::fs::remove_dir_all(&out).ok();
    }
}

#[test]
#[ignore = "needs Python modules (python3 -m pip install -r tests/requirements.txt); run by .ci/run"]
fn a_run_records_uff58_that_pyuff_reads_and_24_bit_wav_at_its_full_scale() {
    common::require_python(&["pyuff"]);
    let (out, manifest) = run_ok(
        "uff",
        &scenario("aliasing-windowing"),
        &sets(
            &[
                "record.wav_format=int24",
                "record.signals=[\"filter_v\", \"torque_intermediate_shaft_nm\"]",
            ],
            &["--duration", "0.5"],
        ),
    );
    assert!(has_file(&manifest, "recording.uff"));
    let script = format!(
        "import pyuff\nsets = pyuff.UFF(r'{}').read_sets()\nprint(len(sets), sets[1]['num_pts'], repr(float(sets[1]['x'][1])), repr(float(sets[1]['data'][1000])), sets[1]['id1'].strip())",
        out.join("recording.uff").display()
    );
    let py = Command::new("python3")
        .args(["-c", &script])
        .output()
        .expect("python3 runs");
    assert!(
        py.status.success(),
        "pyuff failed (is it installed? .ci/run installs it): {}",
        String::from_utf8_lossy(&py.stderr)
    );
    let text = String::from_utf8_lossy(&py.stdout);
    let fields: Vec<&str> = text.split_whitespace().collect();
    assert_eq!(&fields[..2], ["2", "25600"], "{text}");
    assert!((fields[2].parse::<f64>().expect("step") - 1.0 / 51_200.0).abs() < 1e-9);
    let torque_uff: f64 = fields[3].parse().expect("value");
    // The same sample in the 24-bit WAV: full scale 100 N m for a torque.
    let mut reader = hound::WavReader::open(out.join("recording.wav")).expect("WAV");
    assert_eq!(reader.spec().bits_per_sample, 24);
    let samples: Vec<i32> = reader
        .samples::<i32>()
        .map(|s| s.expect("sample"))
        .collect();
    let torque_wav = f64::from(samples[2 * 1000 + 1]) / 8_388_607.0 * 100.0;
    assert!(
        (torque_wav - torque_uff).abs() <= 100.0 / 8_388_607.0,
        "{torque_wav} vs {torque_uff}"
    );
    assert!(
        torque_uff.abs() > 1e-3,
        "a torque, not an empty channel: {torque_uff}"
    );
    std::fs::remove_dir_all(&out).ok();
}

#[test]
fn a_rerun_into_a_used_folder_removes_the_earlier_runs_files_and_no_other() {
    let out = folder("rerun");
    let survey = |speeds: &'static str| {
        vec![
            "--set",
            speeds,
            "--set",
            "survey.settle_s=2",
            "--set",
            "survey.measure_s=4",
            "--set",
            "analyser.averages=2",
        ]
    };
    let run = |args: &[&str]| {
        let output = Command::new(env!("CARGO_BIN_EXE_testrig"))
            .args(["run", &scenario("subharmonic-2712nm"), "--pace", "max"])
            .args(args)
            .args(["--out", out.to_str().expect("utf-8")])
            .output()
            .expect("runs");
        assert!(
            output.status.success(),
            "{}",
            String::from_utf8_lossy(&output.stderr)
        );
        String::from_utf8_lossy(&output.stderr).into_owned()
    };
    run(&survey("survey.speeds_rpm=[1300, 1500]"));
    assert!(out.join("spectrum-02.csv").exists());
    std::fs::write(out.join("notes.txt"), "the user's own").expect("written");
    std::fs::write(out.join("recording.wav.partial"), "left by a killed run").expect("written");
    let said = run(&survey("survey.speeds_rpm=[1300]"));
    assert!(
        said.contains("removed") && said.contains("files of the earlier run"),
        "{said}"
    );
    let manifest = read_manifest(&out);
    check_files(&out, &manifest);
    assert!(out.join("spectrum-01.csv").exists());
    assert!(
        !out.join("spectrum-02.csv").exists(),
        "an old spectrum beside the new"
    );
    assert!(!out.join("scope-02.csv").exists());
    assert!(out.join("notes.txt").exists(), "a file no run wrote stays");
    std::fs::remove_dir_all(&out).ok();
}

#[test]
fn an_analyser_band_too_narrow_for_the_stream_is_refused_at_its_line() {
    let dir = folder("narrow-band");
    for (extra, expected) in [
        ("fmax_hz = 0.01\n", ":9:"),
        ("fmax_hz = 200\naverages = 5000\n", ":10:"),
    ] {
        let text = format!("{MINIMAL}\n[analyser]\n{extra}");
        let path = dir.join("narrow.toml");
        std::fs::write(&path, text).expect("written");
        let output = testrig(
            &[
                "run",
                path.to_str().expect("utf-8"),
                "--pace",
                "max",
                "--out",
            ]
            .into_iter()
            .chain([dir.join("out").to_str().expect("utf-8")])
            .collect::<Vec<_>>(),
        );
        let stderr = String::from_utf8_lossy(&output.stderr);
        assert!(!output.status.success());
        assert!(stderr.contains(expected), "{expected} not in {stderr}");
        assert!(!stderr.contains("panicked"), "{stderr}");
    }
}
