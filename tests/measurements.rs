//! Measurements that cannot complete are never lost in silence: a shortened run warns on
//! the console and in the manifest, and `--strict` makes the same run fail.

mod common;

use common::{folder, read_manifest, scenario, testrig};

/// `testrig run` of the shipped scenario `name` unpaced into `out`, with `extra` arguments.
fn run(name: &str, out: &std::path::Path, extra: &[&str]) -> std::process::Output {
    let scenario = scenario(name);
    let mut args = vec!["run", &scenario, "--pace", "max"];
    args.extend(extra);
    args.extend(["--out", out.to_str().expect("utf-8")]);
    testrig(&args)
}

fn warnings(manifest: &serde_json::Value) -> Vec<String> {
    manifest["warnings"]
        .as_array()
        .expect("warnings")
        .iter()
        .map(|w| w.as_str().expect("text").to_string())
        .collect()
}

#[test]
fn a_shortened_run_warns_of_every_spectrum_it_loses() {
    let out = folder("short-run");
    let output = run("subharmonic-2712nm", &out, &["--duration", "30"]);
    assert!(output.status.success(), "a warning is not a failure");
    let stderr = String::from_utf8_lossy(&output.stderr);
    // Measurement 2 starts at 29 s: one second left for 10 averages of 1.28 s.
    assert!(
        stderr.contains("warning: measurement 2 (1000 rev/min, 2.712 N m) at 29 s: 10 averages need 12.800 s, the run's end leaves 1.000 s: 0 of 10 averages"),
        "{stderr}"
    );
    let listed = warnings(&read_manifest(&out));
    assert!(
        listed
            .iter()
            .any(|w| w.contains("measurement 2") && w.contains("0 of 10 averages"))
    );
    let unreached_spectra = listed
        .iter()
        .filter(|w| w.contains("not reached") && w.ends_with("no spectrum"))
        .count();
    assert_eq!(unreached_spectra, 5, "measurements 3-7: {listed:?}");
    std::fs::remove_dir_all(&out).ok();
}

#[test]
fn strict_refuses_a_run_whose_measurements_cannot_complete() {
    let out = folder("strict-refused");
    let output = run(
        "subharmonic-2712nm",
        &out,
        &["--duration", "30", "--strict"],
    );
    assert!(!output.status.success());
    let stderr = String::from_utf8_lossy(&output.stderr);
    assert!(
        stderr.contains("--strict") && stderr.contains("nothing was run"),
        "{stderr}"
    );
    assert!(!out.join("manifest.json").exists(), "nothing was run");
    std::fs::remove_dir_all(&out).ok();
}

#[test]
fn strict_fails_a_run_that_ends_with_warnings_and_keeps_its_files() {
    // A ±1 mV range overloads the ADC on every sample: a run-time warning.
    let out = folder("strict-overload");
    let output = run(
        "aliasing-windowing",
        &out,
        &["--set", "analyser.range_v=0.001", "--strict"],
    );
    assert_eq!(output.status.code(), Some(3));
    let manifest = read_manifest(&out);
    assert_eq!(manifest["ending"], "completed");
    // Counted in words: "1 warning", "2 warnings" (issue 24).
    let count = warnings(&manifest).len();
    let said = String::from_utf8_lossy(&output.stderr);
    let words = if count == 1 {
        "1 warning ".to_string()
    } else {
        format!("{count} warnings ")
    };
    assert!(said.contains(&format!("--strict: {words}")), "{said}");
    assert!(
        warnings(&manifest)
            .iter()
            .any(|w| w.contains("the ADC overloaded")),
        "{manifest}"
    );
    assert!(out.join("spectrum-01.csv").exists(), "the files are kept");
    std::fs::remove_dir_all(&out).ok();
}

/// The main job warns of nothing: its decimated recording is low-passed before every 8th
/// sample is kept. A run that does warn (cut short before its measurements) has every
/// warning it printed in its manifest.
#[test]
fn the_main_job_warns_of_nothing_and_every_printed_warning_is_in_the_manifest() {
    let out = folder("no-warning");
    let output = run("subharmonic-2712nm", &out, &[]);
    let stderr = String::from_utf8_lossy(&output.stderr);
    assert!(output.status.success(), "{stderr}");
    assert!(!stderr.contains("warning"), "{stderr}");
    let manifest = read_manifest(&out);
    assert_eq!(manifest["warnings"].as_array().map(Vec::len), Some(0));
    let decimation = manifest["recording_decimation"].as_str().expect("stated");
    assert!(
        decimation.contains("every 8th sample") && decimation.contains("2560 Hz"),
        "{decimation}"
    );

    let short = folder("short-warnings");
    let output = run("subharmonic-2712nm", &short, &["--duration", "30"]);
    let stderr = String::from_utf8_lossy(&output.stderr);
    assert!(output.status.success(), "{stderr}");
    let printed: Vec<&str> = stderr
        .lines()
        .filter_map(|l| l.strip_prefix("warning: "))
        .collect();
    assert!(!printed.is_empty(), "{stderr}");
    let listed = read_manifest(&short)["warnings"].clone();
    for warning in printed {
        assert!(
            listed
                .as_array()
                .expect("warnings")
                .iter()
                .any(|w| w == warning),
            "printed but not in the manifest: {warning}"
        );
    }
}
