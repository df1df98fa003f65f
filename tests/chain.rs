//! The chain as data: stages a scenario adds, rewires and reorders, checked at the file's
//! lines, and what the added instruments measure.

mod common;

use common::{csv_rows, folder, number, run_ok};
use testrig::chain::{ChainStages, Instrument, MeterSettings, StagePlan, WiringError};
use testrig::scenario::{CommandLine, ScenarioSource, build};

const BASE: &str = r#"name = "declared"
duration_s = 3

[schedule]
speed_rpm = 600
load_nm = 2.712
"#;

fn stage(output: &str, input: &str, instrument: Instrument) -> StagePlan {
    StagePlan {
        output: output.into(),
        inputs: vec![input.into()],
        instrument,
    }
}

fn meter() -> Instrument {
    Instrument::Meter(MeterSettings {
        detector: instruments::Detector::TrueRms,
        tau_s: 0.2,
        ac_coupling_hz: 0.0,
    })
}

#[test]
fn stages_run_after_the_stages_they_read_and_bad_wiring_is_named() {
    let wire = Instrument::LowPass(None);
    let plans = vec![
        stage("b_v", "a_v", meter()),
        stage("a_v", "torque_intermediate_shaft_nm", wire.clone()),
        stage("c_v", "torque_intermediate_shaft_nm", wire.clone()),
    ];
    let stages = ChainStages::ordered(plans).expect("wires");
    let order: Vec<&str> = stages.stages().iter().map(|s| s.output.as_str()).collect();
    assert_eq!(order, ["a_v", "b_v", "c_v"]);
    let mut names = testrig::vocabulary::SignalNames::plant();
    let built = stages.build(51_200.0, &mut names).expect("builds");
    assert_eq!(built.len(), 3);
    // The plant's five signals (time, gauged torque, tacho and slip-ring speeds, keyphasor)
    // come first, then each stage's output in running order.
    assert_eq!(names.index("b_v"), Some(5 + 1));
    // A wire (a low-pass without a filter) and a meter on the gauged torque read N m, not
    // volts: filters and meters keep their input's unit.
    assert_eq!(stages.unit_of("b_v"), Some("N m"));
    assert_eq!(stages.unit_of("speed1_rad_s"), Some("rad/s"));
    assert_eq!(stages.unit_of("nothing"), None);

    let looped = vec![
        stage("x_v", "y_v", wire.clone()),
        stage("y_v", "x_v", wire.clone()),
    ];
    let err = ChainStages::ordered(looped).expect_err("a loop");
    assert!(matches!(err, WiringError::UnknownInput { ref output, .. } if output == "x_v"));
    let twice = vec![stage("keyphasor_v", "torque_intermediate_shaft_nm", wire)];
    let err = ChainStages::ordered(twice).expect_err("a plant name");
    assert!(matches!(err, WiringError::DuplicateOutput { .. }), "{err}");
}

#[test]
fn a_scenario_adds_a_filter_and_a_meter_and_rewires_the_400e_to_a_later_stage() {
    let dir = folder("chain-declared");
    let text = format!(
        r#"{BASE}
[chain.meter]
input = "slow_v"

[[chain.stage]]
output = "slow_v"
input = "amplifier_v"
lowpass = {{ kind = "butterworth", order = 4, cutoff_hz = 5 }}

[[chain.stage]]
output = "rms_filter_v"
input = "filter_v"
meter = {{ detector = "true-rms", tau_s = 0.2, ac_coupling_hz = 0 }}

[[chain.stage]]
output = "ac_v"
input = "amplifier_v"
ac_coupling = {{ corner_hz = 1 }}

[record]
signals = ["amplifier_v", "slow_v", "filter_v", "rms_filter_v", "meter_v", "ac_v"]
formats = ["csv", "wav"]
"#
    );
    let path = dir.join("declared.toml");
    std::fs::write(&path, text).expect("write");
    let (out, _) = run_ok("chain-declared-run", path.to_str().expect("utf-8"), &[]);
    let rows = csv_rows(&out.join("recording.csv"));
    let late: Vec<_> = rows.iter().filter(|r| number(r, "time_s") >= 1.5).collect();
    let column = |name: &str| late.iter().map(|r| number(r, name)).collect::<Vec<f64>>();
    let mean = |v: &[f64]| v.iter().sum::<f64>() / v.len() as f64;
    let ac_rms = |v: &[f64]| {
        let m = mean(v);
        (v.iter().map(|x| (x - m).powi(2)).sum::<f64>() / v.len() as f64).sqrt()
    };
    let (amplifier, slow) = (column("amplifier_v"), column("slow_v"));
    // A Butterworth low-pass passes DC at unit gain: the static strain comes through.
    assert!(
        (mean(&slow) / mean(&amplifier) - 1.0).abs() < 0.01,
        "DC {} against {}",
        mean(&slow),
        mean(&amplifier)
    );
    // The lowest line is once per revolution (10 Hz), where a 4th-order Butterworth at
    // 5 Hz passes 1/√(1 + 2⁸) = 1/16; tooth pass (300 Hz) and the ringing far less.
    assert!(
        ac_rms(&slow) < 0.08 * ac_rms(&amplifier),
        "AC {} against {}",
        ac_rms(&slow),
        ac_rms(&amplifier)
    );
    // The added true-RMS meter (DC-coupled) reads the RMS of the filter's output.
    let filter = column("filter_v");
    let rms = (filter.iter().map(|x| x * x).sum::<f64>() / filter.len() as f64).sqrt();
    let reading = column("rms_filter_v");
    let last = reading[reading.len() - 1];
    assert!(
        (last / rms - 1.0).abs() < 0.05,
        "meter {last} against {rms}"
    );
    // The 400E now reads the slow filter's output, AC-coupled: almost nothing is left.
    let meter = column("meter_v");
    assert!(
        meter[meter.len() - 1] < 0.2 * ac_rms(&amplifier),
        "400E {} against {}",
        meter[meter.len() - 1],
        ac_rms(&amplifier)
    );
    // A 1 Hz AC coupling blocks the static strain and passes the lines from 10 Hz up
    // (gain 10/√101 = 0.995 at 10 Hz).
    let ac = column("ac_v");
    assert!(
        mean(&ac).abs() < 0.02 * mean(&amplifier),
        "DC through: {}",
        mean(&ac)
    );
    assert!(
        (ac_rms(&ac) / ac_rms(&amplifier) - 1.0).abs() < 0.05,
        "AC {} against {}",
        ac_rms(&ac),
        ac_rms(&amplifier)
    );
    let sidecar = std::fs::read_to_string(out.join("recording.wav.json")).expect("sidecar");
    let sidecar: serde_json::Value = serde_json::from_str(&sidecar).expect("JSON");
    let slow_entry = sidecar["channels"]
        .as_array()
        .expect("channels")
        .iter()
        .find(|c| c["name"] == "slow_v")
        .expect("slow_v in the sidecar");
    assert_eq!(slow_entry["unit"], "V");
}

fn refusal(extra: &str) -> String {
    let src = ScenarioSource {
        path: "wired.toml".into(),
        text: format!("{BASE}{extra}"),
    };
    match build(&src, CommandLine::default()) {
        Ok(_) => panic!("accepted:\n{extra}"),
        Err(e) => format!("{e:#}"),
    }
}

#[test]
fn bad_wiring_is_refused_at_its_line_and_field() {
    let cases: [(&str, &[&str]); 8] = [
        (
            "\n[[chain.stage]]\noutput = \"x_v\"\ninput = \"nowhere_v\"\nlowpass = { cutoff_hz = 50 }\n",
            &[
                "wired.toml:10:",
                "chain.stage #1.input",
                "`nowhere_v`",
                "not a signal before it",
            ],
        ),
        (
            "\n[[chain.stage]]\noutput = \"filter_v\"\ninput = \"amplifier_v\"\nlowpass = { cutoff_hz = 50 }\n",
            &["wired.toml:9:", "chain.stage #1.output", "already a signal"],
        ),
        (
            "\n[[chain.stage]]\noutput = \"x_v\"\ninput = \"amplifier_v\"\n",
            &["wired.toml:9:", "chain.stage #1", "exactly one instrument"],
        ),
        (
            "\n[[chain.stage]]\noutput = \"x_v\"\ninput = \"amplifier_v\"\nmeter = {}\nac_coupling = { corner_hz = 1 }\n",
            &["wired.toml:9:", "chain.stage #1", "exactly one instrument"],
        ),
        (
            "\n[chain.meter]\ninput = \"x_v\"\n\n[[chain.stage]]\noutput = \"x_v\"\ninput = \"meter_v\"\nmeter = {}\n",
            &[
                "wired.toml:9:",
                "chain.meter.input",
                "not a signal before it",
            ],
        ),
        (
            "\n[[chain.stage]]\noutput = \"x_v\"\ninput = \"amplifier_v\"\nlowpass = { cutoff_hz = 30000 }\n",
            &["chain.stage #1.lowpass.cutoff_hz", "Nyquist"],
        ),
        (
            "\n[analyser]\nfmax_hz = 200\ninput = \"slip_ring_v\"\n",
            &[
                "wired.toml:10:",
                "analyser.input",
                "`slip_ring_v` is not a signal of this run",
            ],
        ),
        (
            "\n[chain.scope]\nvolts_per_div = 1\nseconds_per_div = 0.01\ninput = \"x\"\n",
            &["wired.toml:11:", "chain.scope.input", "`x` is not a signal"],
        ),
    ];
    for (extra, expected) in cases {
        let message = refusal(extra);
        for part in expected {
            assert!(message.contains(part), "{part:?} not in {message}");
        }
    }
}

/// The chain carries strain in µε: the recorded `strain` is the shaft torque times
/// 8/(π d³ G) × 10⁶ = 3.85 µε/N m (Ø20 mm, G 82.7 GPa) with the unit µε in the sidecar,
/// and the amplifier's and the filter's volts stand for 200/3 µε per volt (the default
/// calibration, 3 V for 200 µε), as the scope's strain axis draws them.
#[test]
fn strain_is_recorded_and_calibrated_in_microstrain() {
    let text = format!(
        "{BASE}\n[record]\nsignals = [\"strain\", \"torque_intermediate_shaft_nm\"]\nformats = [\"wav\", \"csv\"]\n"
    );
    let dir = folder("microstrain");
    let path = dir.join("strain.toml");
    std::fs::write(&path, &text).expect("scenario written");
    let (out, _) = run_ok("microstrain-run", path.to_str().expect("utf-8"), &[]);
    let rows = csv_rows(&out.join("recording.csv"));
    let per_nm = 8.0 / (std::f64::consts::PI * 0.02f64.powi(3) * 82.7e9) * 1e6;
    assert!((per_nm - 3.849).abs() < 1e-3);
    for row in rows.iter().step_by(997) {
        let strain = number(row, "strain");
        let torque = number(row, "torque_intermediate_shaft_nm");
        assert!(
            (strain - per_nm * torque).abs() < 1e-9 * (1.0 + strain.abs()),
            "{strain} µε at {torque} N m"
        );
    }
    let sidecar: serde_json::Value = serde_json::from_str(
        &std::fs::read_to_string(out.join("recording.wav.json")).expect("sidecar"),
    )
    .expect("json");
    assert_eq!(sidecar["channels"][0]["unit"], "µε");
    let plan = build(
        &ScenarioSource {
            path: "strain.toml".into(),
            text,
        },
        CommandLine::default(),
    )
    .expect("builds");
    let per_volt = plan
        .chain
        .microstrain_per_unit("amplifier_v")
        .expect("calibrated");
    assert!((per_volt - 200.0 / 3.0).abs() < 1e-9, "{per_volt}");
    assert_eq!(plan.chain.microstrain_per_unit("filter_v"), Some(per_volt));
    assert_eq!(plan.chain.microstrain_per_unit("strain"), Some(1.0));
    assert_eq!(plan.chain.microstrain_per_unit("tacho_v"), None);
    std::fs::remove_dir_all(&dir).ok();
    std::fs::remove_dir_all(&out).ok();
}
