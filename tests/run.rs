//! End-to-end tests of `testrig run` on every shipped scenario (shortened) and what the
//! chain shows: the half-order line, the meters against the truth, scope sweeps, aliases.

mod common;

use std::path::Path;

use common::{check_files, csv_rows, has_file, number, run_ok, scenario, sets, spectrum};

/// The overrides that shorten a subharmonic survey to one short point at 1100 rev/min.
const ONE_SUBHARMONIC_POINT: [&str; 4] = [
    "survey.speeds_rpm=[1100]",
    "survey.settle_s=2",
    "survey.measure_s=2",
    "analyser.averages=1",
];

/// Shortened runs of each shipped scenario: (file stem, `--set` items, other arguments).
const SHORTENED: [(&str, &[&str], &[&str]); 9] = [
    (
        "aliasing-windowing",
        &["analyser.averages=1"],
        &["--duration", "6"],
    ),
    (
        "load-series-200rpm",
        &[
            "survey.loads_nm=[0.0, 5.424]",
            "survey.settle_s=2",
            "survey.measure_s=3",
            "analyser.block=256",
            "analyser.averages=2",
        ],
        &[],
    ),
    (
        "panel",
        &["analyser.averages=2", "record.from_start=true"],
        &["--duration", "6"],
    ),
    ("planetary-run", &[], &[]),
    (
        "rms-survey",
        &[
            "survey.speeds_rpm=[200, 600]",
            "survey.loads_nm=[0.0, 2.712]",
            "survey.settle_s=2",
        ],
        &[],
    ),
    ("subharmonic-0nm", &ONE_SUBHARMONIC_POINT, &[]),
    ("subharmonic-2712nm", &ONE_SUBHARMONIC_POINT, &[]),
    ("subharmonic-5424nm", &ONE_SUBHARMONIC_POINT, &[]),
    ("two-stage-run", &[], &[]),
];

/// Whether a shipped file is for another command: a sweep (`testrig sweep`) or a
/// calibration (`testrig calibrate`) rather than a scenario.
fn is_sweep(path: &str) -> bool {
    std::fs::read_to_string(path).is_ok_and(|t| {
        t.lines()
            .any(|l| l.trim() == "[grid]" || l.starts_with("campaign = "))
    })
}

#[test]
fn every_shipped_scenario_runs_end_to_end_shortened() {
    let dir = format!("{}/scenarios", env!("CARGO_MANIFEST_DIR"));
    let mut shipped: Vec<String> = std::fs::read_dir(&dir)
        .expect("scenarios/")
        .filter_map(|e| {
            let name = e.expect("entry").file_name().to_string_lossy().into_owned();
            name.strip_suffix(".toml").map(String::from)
        })
        .filter(|stem| !is_sweep(&format!("{dir}/{stem}.toml")))
        .collect();
    shipped.sort();
    let tested: Vec<&str> = SHORTENED.iter().map(|(n, _, _)| *n).collect();
    assert_eq!(
        shipped, tested,
        "every shipped scenario has a shortened run here"
    );
    for (name, items, extra) in SHORTENED {
        let (out, manifest) = run_ok(name, &scenario(name), &sets(items, extra));
        assert_eq!(manifest["ending"], "completed", "{name}");
        check_files(&out, &manifest);
        for key in [
            "scenario_sha256",
            "seed",
            "version",
            "simulated_s",
            "wall_s",
            "pace",
            "lateness_ms",
            "overruns",
            "impacts",
            "points",
            "files",
        ] {
            assert!(!manifest[key].is_null(), "{name}: manifest lacks {key}");
        }
        for point in manifest["points"].as_array().expect("points") {
            assert!(
                point["motion"]["motion"].is_string() && point["label"].is_string(),
                "{name}: {point}"
            );
        }
        assert_eq!(manifest["overruns"], 0, "{name}");
        assert!(
            has_file(&manifest, "readings.csv") && has_file(&manifest, "impacts.csv"),
            "{name}"
        );
        std::fs::remove_dir_all(&out).ok();
    }
}

#[test]
fn the_subharmonic_scenario_shows_the_half_order_line_through_the_whole_chain() {
    let (out, manifest) = run_ok(
        "half-order",
        &scenario("subharmonic-2712nm"),
        &sets(
            &[
                "survey.speeds_rpm=[1300]",
                "survey.settle_s=4",
                "survey.measure_s=6",
                "analyser.averages=4",
            ],
            &[],
        ),
    );
    // One point, judged over its 6 s settled window, the same verdict in the manifest,
    // readings.csv and the spectrum's metadata.
    let points = manifest["points"].as_array().expect("points");
    assert_eq!(points.len(), 1);
    assert_eq!(points[0]["motion"]["motion"], "period-2");
    assert!((points[0]["measured_s"].as_f64().expect("s") - 6.0).abs() < 0.05);
    let readings = csv_rows(&out.join("readings.csv"));
    assert_eq!(readings[0]["motion"], "period-2");
    let text = std::fs::read_to_string(out.join("spectrum-01.csv")).expect("spectrum");
    assert!(text.contains("# motion: period-2"), "{text}");
    let lines = spectrum(&out.join("spectrum-01.csv"));
    let half_order_hz = 1300.0 / 60.0 / 2.0;
    let at = |f: f64| {
        lines
            .iter()
            .min_by(|a, b| (a.0 - f).abs().total_cmp(&(b.0 - f).abs()))
            .map(|l| l.1)
            .expect("lines")
    };
    let mut powers: Vec<f64> = lines.iter().map(|l| l.1).collect();
    powers.sort_by(f64::total_cmp);
    let median = powers[powers.len() / 2];
    assert!(
        at(half_order_hz) > 100.0 * median,
        "half order {} vs median {median}",
        at(half_order_hz)
    );
    assert!(has_file(&manifest, "scope-01.png") && has_file(&manifest, "scope-01.svg"));
    assert!(has_file(&manifest, "spectrum-01.png") && has_file(&manifest, "spectrum-01.svg"));
    std::fs::remove_dir_all(&out).ok();
}

fn survey_readings(
    tag: &str,
    detector: &str,
    coupling_hz: f64,
) -> Vec<std::collections::HashMap<String, String>> {
    let detector = format!("chain.meter.detector={detector}");
    let coupling = format!("chain.meter.ac_coupling_hz={coupling_hz}");
    let (out, manifest) = run_ok(
        tag,
        &scenario("rms-survey"),
        &sets(
            &[
                "survey.speeds_rpm=[200, 600]",
                "survey.loads_nm=[0.0, 2.712]",
                "survey.settle_s=8",
                &detector,
                &coupling,
            ],
            &[],
        ),
    );
    assert!(has_file(&manifest, "rms-survey.png") && has_file(&manifest, "rms-survey.svg"));
    let rows = csv_rows(&out.join("readings.csv"));
    std::fs::remove_dir_all(&out).ok();
    rows
}

#[test]
fn the_rms_survey_reads_the_tacho_and_the_meter_against_the_truth() {
    let true_rms = survey_readings("survey-true", "true-rms", 0.0);
    let hp_400e = survey_readings("survey-400e", "average", 1.0);
    assert_eq!(true_rms.len(), 4);
    for (t, a) in true_rms.iter().zip(&hp_400e) {
        let speed = number(t, "speed_set_rpm");
        // 40 V per 1000 rev/min, shown to 0.1 V (2.5 rev/min).
        assert!((number(t, "dvm_rpm") - speed).abs() <= 2.5, "{t:?}");
        // Static strain of a solid Ø20 mm shaft: 3.85 µε per N m.
        let load = number(t, "load_set_nm");
        assert!((number(t, "static_microstrain") - 3.849 * load).abs() < 0.01 * load + 1e-9);
        // A DC-coupled true-RMS meter reads √(mean² + ac²) of the strain, over the slip
        // rings' noise floor (about 0.1 µε here): to 3 % where the load keeps the motion
        // steady. At no load the rattle is aperiodic and comes in bursts: the meter's
        // 0.2 s detector weighs the last few tenths of a second, the truth the whole last
        // second, and which bursts fall where changes with the last bit of any rounding
        // (−25 % seen after a change of summation order), so there only to 40 %: still
        // far from a meter that lost the mean (−100 % at load) or read the peak (+40 %
        // on a sine).
        let tolerance = if load > 0.0 { 0.03 } else { 0.40 };
        let per_nm = 3.849;
        let mean = number(t, "true_torque_mean_nm") * per_nm;
        let truth = mean.hypot(number(t, "true_ac_rms_microstrain"));
        let true_reading = number(t, "meter_microstrain");
        assert!(
            (true_reading - truth).abs() < tolerance * truth + 0.2,
            "{true_reading} vs {truth}: {t:?}"
        );
        // The AC-coupled 400E reads 1.1107·mean|v| of the AC part, and mean|v| ≤ RMS: never
        // more than 11 % above the AC RMS (low on the peaky strain of rattling teeth).
        let ac = number(a, "true_ac_rms_microstrain");
        if ac > 0.5 {
            let ratio = number(a, "meter_microstrain") / ac;
            assert!(ratio < 1.1107 * 1.02, "{a:?}");
        }
    }
}

#[test]
fn the_load_series_stores_one_scope_sweep_per_load() {
    let (out, manifest) = run_ok(
        "load-series",
        &scenario("load-series-200rpm"),
        &sets(
            &[
                "survey.loads_nm=[2.712]",
                "survey.settle_s=2",
                "survey.measure_s=3",
                "analyser.block=256",
                "analyser.averages=2",
            ],
            &[],
        ),
    );
    assert!(has_file(&manifest, "scope-01.csv"));
    let trace = csv_rows(&out.join("scope-01.csv"));
    // Ten divisions of 30 ms at 51.2 kHz: 300 ms, one revolution at 200 rev/min.
    assert_eq!(trace.len(), 15_360);
    // At the scenario's V/div the trace stays on the screen's ±4 divisions and is not a
    // flat line: the once-per-revolution wave and the ripple stand out (rms above half a
    // division).
    let text = std::fs::read_to_string(scenario("load-series-200rpm")).expect("scenario");
    let table: toml::Table = toml::from_str(&text).expect("TOML");
    let per_div = table["chain"]["scope"]["volts_per_div"]
        .as_float()
        .expect("volts_per_div");
    let volts: Vec<f64> = trace.iter().map(|r| number(r, "amplifier_v")).collect();
    assert!(volts.iter().all(|v| v.abs() <= 4.0 * per_div + 1e-12));
    let mean = volts.iter().sum::<f64>() / volts.len() as f64;
    let rms_div = (volts.iter().map(|v| (v - mean).powi(2)).sum::<f64>() / volts.len() as f64)
        .sqrt()
        / per_div;
    assert!(rms_div > 0.5, "a flat trace: {rms_div} div rms");
    std::fs::remove_dir_all(&out).ok();
}

#[test]
fn the_aliasing_study_flags_aliases_that_the_filter_removes() {
    let open = ["analyser.averages=2"];
    let filtered = [
        "analyser.averages=2",
        "chain.filter.kind=butterworth",
        "chain.filter.cutoff_hz=180",
    ];
    let shortened = ["--duration", "7"];
    let study = scenario("aliasing-windowing");
    let (open_out, _) = run_ok("alias-open", &study, &sets(&open, &shortened));
    let (filtered_out, _) = run_ok("alias-filtered", &study, &sets(&filtered, &shortened));
    let aliased_power = |dir: &Path| -> (usize, f64) {
        let lines = spectrum(&dir.join("spectrum-01.csv"));
        let flagged: Vec<_> = lines.iter().filter(|l| l.2).collect();
        (flagged.len(), flagged.iter().map(|l| l.1).sum())
    };
    let (open_count, open_power) = aliased_power(&open_out);
    let (filtered_count, filtered_power) = aliased_power(&filtered_out);
    assert!(
        open_count > 0,
        "with the filter off the mesh and natural frequencies alias"
    );
    // An 8th-order Butterworth at 180 Hz takes 13 dB off at 217 Hz and more above: what
    // folds onto the band's top (the only aliases here) drops by more than 10 dB.
    assert!(
        filtered_count < open_count && filtered_power < 0.1 * open_power,
        "{filtered_count} lines / {filtered_power} vs {open_count} / {open_power}"
    );
    std::fs::remove_dir_all(&open_out).ok();
    std::fs::remove_dir_all(&filtered_out).ok();
}

/// The `alias_of_hz` column of a spectrum CSV: the true frequency of each flagged line.
fn alias_sources(path: &Path) -> Vec<f64> {
    spectrum_rows(path)
        .into_iter()
        .filter_map(|row| row[2].parse().ok())
        .collect()
}

fn spectrum_rows(path: &Path) -> Vec<Vec<String>> {
    let text = std::fs::read_to_string(path).expect("spectrum CSV");
    text.lines()
        .filter(|l| !l.starts_with('#'))
        .skip(1)
        .map(|l| l.split(',').map(str::to_string).collect())
        .collect()
}

#[test]
fn the_aliasing_study_does_what_its_documented_commands_say() {
    let study = scenario("aliasing-windowing");
    let (open, _) = run_ok("alias-doc-open", &study, &[]);
    let (filtered, _) = run_ok(
        "alias-doc-filtered",
        &study,
        &["--set", "chain.filter.kind=butterworth"],
    );
    let (guarded, _) = run_ok(
        "alias-doc-guarded",
        &study,
        &[
            "--set",
            "chain.filter.kind=butterworth",
            "--set",
            "analyser.sampling=2.56",
        ],
    );
    let open_sources = alias_sources(&open.join("spectrum-01.csv"));
    assert!(!open_sources.is_empty(), "with the filter off lines alias");
    // The mesh line (30 teeth x 1300/60 = 650 Hz) folds to 150 Hz and is flagged as such.
    let rows = spectrum_rows(&open.join("spectrum-01.csv"));
    let mesh = rows
        .iter()
        .find(|row| row[2].parse::<f64>().is_ok_and(|f| (f - 650.0).abs() < 1.0))
        .unwrap_or_else(|| panic!("no line flagged as the 650 Hz mesh line: {open_sources:?}"));
    let shown_hz: f64 = mesh[0].parse().expect("frequency");
    assert!(
        (shown_hz - 150.0).abs() < 1.0,
        "the mesh line shows at {shown_hz} Hz"
    );
    // The filter's cut-off follows the analyser's band (Fmax 200 Hz), not 2 kHz.
    let text = std::fs::read_to_string(filtered.join("spectrum-01.csv")).expect("CSV");
    assert!(
        text.contains("# filter: Butterworth order 8 at 200 Hz"),
        "cut-off at Fmax"
    );
    // With fs = 2·Fmax there is no guard band: only what lies just above Fmax, where the
    // 8th-order filter has taken less than 7 dB, still folds onto the top of the display.
    let filtered_sources = alias_sources(&filtered.join("spectrum-01.csv"));
    assert!(
        filtered_sources.iter().all(|&f| f < 1.1 * 200.0),
        "aliases from far above the band remain (the mesh line among them?): {filtered_sources:?}"
    );
    // With fs = 2.56·Fmax everything that folds into the band lies above 1.56·Fmax, where
    // the filter has taken 60 dB: every flagged alias is gone.
    let guarded_sources = alias_sources(&guarded.join("spectrum-01.csv"));
    assert!(guarded_sources.is_empty(), "{guarded_sources:?}");
    for dir in [open, filtered, guarded] {
        std::fs::remove_dir_all(dir).ok();
    }
}
