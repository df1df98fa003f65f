//! Recorders: WAV with its sidecar, and UFF58 read back by pyuff (installed by .ci/run).

mod common;

use std::process::Command;

use testrig::recording::{ChannelInfo, Uff58Abscissa, Uff58Record, WavRecorder, write_uff58};

use common::folder;

#[test]
fn a_wav_recording_holds_scaled_frames_and_its_sidecar_says_how() {
    let dir = folder("wav");
    let path = dir.join("run.wav");
    let channels = vec![
        ChannelInfo {
            name: "torque_intermediate_shaft".into(),
            unit: "N m".into(),
            scale: 100.0,
            full_scale: 100.0,
        },
        ChannelInfo {
            name: "speed1".into(),
            unit: "rad/s".into(),
            scale: 500.0,
            full_scale: 500.0,
        },
    ];
    let mut recorder =
        WavRecorder::create(&path, 51_200, channels, "scenario text").expect("created");
    assert!(
        dir.join("run.wav.partial").exists() && !path.exists(),
        "no final name before finishing"
    );
    for k in 0..1000 {
        recorder
            .write_frame(&[2.712 + k as f64 * 1e-3, 136.1])
            .expect("written");
    }
    recorder.finish().expect("finished");
    let mut reader = hound::WavReader::open(&path).expect("readable");
    assert_eq!(reader.spec().channels, 2);
    assert_eq!(reader.spec().sample_rate, 51_200);
    let samples: Vec<f32> = reader
        .samples::<f32>()
        .map(|s| s.expect("sample"))
        .collect();
    assert_eq!(samples.len(), 2000);
    assert!((f64::from(samples[0]) * 100.0 - 2.712).abs() < 1e-5);
    assert!((f64::from(samples[1]) * 500.0 - 136.1).abs() < 1e-4);
    let sidecar: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(dir.join("run.wav.json")).expect("sidecar"))
            .expect("json");
    assert_eq!(sidecar["channels"][0]["unit"], "N m");
    assert_eq!(sidecar["channels"][1]["scale"], 500.0);
    assert_eq!(sidecar["sample_rate_hz"], 51_200);
    std::fs::remove_dir_all(&dir).ok();
}

#[test]
#[ignore = "needs Python modules (python3 -m pip install -r tests/requirements.txt); run by .ci/run"]
fn pyuff_reads_our_dataset_58() {
    common::require_python(&["pyuff", "numpy"]);
    let dir = folder("uff");
    let path = dir.join("strain.uff");
    let values: Vec<f64> = (0..37)
        .map(|k| (k as f64 * 0.3).sin() * 1e-5 - 2.5e-7 * k as f64)
        .collect();
    let mut file = std::fs::File::create(&path).expect("writable");
    let time = Uff58Record {
        description: "strain, intermediate shaft",
        source: "testrig",
        function_type: 1,
        response_name: "shaft",
        response_node: 3,
        ordinate_type: 3,
        ordinate_unit: "µε",
        abscissa: Uff58Abscissa::Time {
            start_s: 0.5,
            step_s: 1.0 / 51_200.0,
        },
        values: &values,
    };
    write_uff58(&mut file, &time).expect("written");
    let spectrum = Uff58Record {
        function_type: 12,
        abscissa: Uff58Abscissa::Frequency {
            start_hz: 0.0,
            step_hz: 3.90625,
        },
        ..time.clone()
    };
    write_uff58(&mut file, &spectrum).expect("written");
    drop(file);
    let script = format!(
        "import pyuff, numpy as np\nsets = pyuff.UFF(r'{}').read_sets()\nprint(len(sets), sets[0]['func_type'], sets[1]['func_type'], sets[0]['num_pts'], repr(float(sets[0]['abscissa_min'])), repr(float(sets[0]['data'][5])), repr(float(sets[1]['x'][2])), sets[0]['ordinate_axis_units_lab'].strip(), sets[0]['id1'].strip())",
        path.display()
    );
    let out = Command::new("python3")
        .args(["-c", &script])
        .output()
        .expect("python3 runs");
    assert!(
        out.status.success(),
        "pyuff failed (is it installed? .ci/run installs it): {}",
        String::from_utf8_lossy(&out.stderr)
    );
    let text = String::from_utf8_lossy(&out.stdout);
    let fields: Vec<&str> = text.split_whitespace().collect();
    assert_eq!(&fields[..4], ["2", "1", "12", "37"], "{text}");
    assert!((fields[4].parse::<f64>().expect("number") - 0.5).abs() < 1e-5);
    assert!(
        (fields[5].parse::<f64>().expect("number") - values[5]).abs() < 1e-17,
        "{text}"
    );
    assert!(
        (fields[6].parse::<f64>().expect("number") - 7.8125).abs() < 1e-4,
        "{text}"
    );
    assert_eq!(fields[7], "microstrain", "{text}");
    assert!(text.contains("strain, intermediate shaft"));
    std::fs::remove_dir_all(&dir).ok();
}

/// Dataset 58 is fixed-column ASCII: a µε unit is written as `microstrain`, and every
/// line stays ASCII and within 80 columns.
#[test]
fn uff58_writes_a_microstrain_unit_in_ascii() {
    let mut bytes = Vec::new();
    let record = Uff58Record {
        description: "strain",
        source: "testrig",
        function_type: 1,
        response_name: "strain",
        response_node: 1,
        ordinate_type: 3,
        ordinate_unit: "µε",
        abscissa: Uff58Abscissa::Time {
            start_s: 0.0,
            step_s: 1e-3,
        },
        values: &[1.0, 2.0],
    };
    write_uff58(&mut bytes, &record).expect("written");
    let text = String::from_utf8(bytes).expect("utf-8");
    assert!(text.is_ascii(), "{text}");
    assert!(text.lines().all(|l| l.len() <= 80), "{text}");
    assert!(text.contains("microstrain"), "{text}");
}
