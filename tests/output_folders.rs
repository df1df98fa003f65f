//! The output-folder guard across commands: every command that writes a folder leaves a
//! manifest or journal the guard reads, so that no command writes its files beside
//! another's unless told to replace them (`--replace`, which removes only what the
//! earlier manifest or journal lists).

mod common;

use common::testrig;

#[test]
fn a_run_into_a_folder_simulate_wrote_is_refused_and_with_replace_removes_its_files() {
    let scratch = common::folder("simulate-guard");
    let dir = scratch.to_str().expect("utf-8");
    let simulate = testrig(&[
        "simulate",
        "--rpm",
        "600",
        "--load",
        "1",
        "--settle",
        "0.2",
        "--duration",
        "0.3",
        "--rate",
        "5120",
        "--out",
        dir,
    ]);
    assert!(
        simulate.status.success(),
        "{}",
        String::from_utf8_lossy(&simulate.stderr)
    );
    for name in [
        "signals.csv",
        "impacts.csv",
        "summary.json",
        "manifest.json",
    ] {
        assert!(scratch.join(name).is_file(), "{name}");
    }
    let scenario = format!(
        "{}/scenarios/aliasing-windowing.toml",
        env!("CARGO_MANIFEST_DIR")
    );
    let run = |extra: &[&str]| {
        let mut args = vec![
            "run",
            scenario.as_str(),
            "--pace",
            "max",
            "--duration",
            "0.5",
            "--out",
            dir,
        ];
        args.extend(extra);
        testrig(&args)
    };
    let refused = run(&[]);
    assert!(!refused.status.success());
    let stderr = String::from_utf8_lossy(&refused.stderr);
    assert!(
        stderr.contains("scenario `simulate`") && stderr.contains("--replace"),
        "{stderr}"
    );
    assert!(
        scratch.join("signals.csv").is_file(),
        "nothing removed when refused"
    );
    let replaced = run(&["--replace"]);
    assert!(
        replaced.status.success(),
        "{}",
        String::from_utf8_lossy(&replaced.stderr)
    );
    // The run writes an impacts.csv of its own; these are simulate's alone.
    for name in ["signals.csv", "summary.json", "impact-raster.png"] {
        assert!(
            !scratch.join(name).exists(),
            "{name} of simulate left beside the run"
        );
    }
}

#[test]
fn analyse_leaves_a_manifest_the_guard_reads_and_sweep_and_run_folders_stay_apart() {
    let scratch = common::folder("folders-apart");
    let run_dir = scratch.join("run");
    let dir = run_dir.to_str().expect("utf-8");
    let scenario = format!(
        "{}/scenarios/aliasing-windowing.toml",
        env!("CARGO_MANIFEST_DIR")
    );
    let run = |out: &str, extra: &[&str]| {
        let mut args = vec![
            "run",
            scenario.as_str(),
            "--pace",
            "max",
            "--duration",
            "3",
            "--out",
            out,
        ];
        args.extend(extra);
        testrig(&args)
    };
    let ran = run(dir, &[]);
    assert!(
        ran.status.success(),
        "{}",
        String::from_utf8_lossy(&ran.stderr)
    );
    // analyse writes its own folder with a manifest and a journal.
    let analysed_dir = scratch.join("analysed");
    let wav = run_dir.join("recording.wav");
    let analyse = |extra: &[&str]| {
        let mut args = vec![
            "analyse",
            wav.to_str().expect("utf-8"),
            "--channel",
            "amplifier_v",
            "--fmax",
            "200",
            "--block",
            "256",
            "--averages",
            "2",
            "--out",
            analysed_dir.to_str().expect("utf-8"),
        ];
        args.extend(extra);
        testrig(&args)
    };
    let analysed = analyse(&[]);
    assert!(
        analysed.status.success(),
        "{}",
        String::from_utf8_lossy(&analysed.stderr)
    );
    let manifest: serde_json::Value = serde_json::from_str(
        &std::fs::read_to_string(analysed_dir.join("manifest.json")).expect("manifest"),
    )
    .expect("JSON");
    assert_eq!(manifest["scenario"], "analyse");
    assert!(
        manifest["files"]
            .as_array()
            .expect("files")
            .iter()
            .any(|f| f == "spectrum.csv")
    );
    // A rerun of analyse replaces its own files; a run into its folder is refused.
    assert!(analyse(&[]).status.success());
    let refused = run(analysed_dir.to_str().expect("utf-8"), &[]);
    let stderr = String::from_utf8_lossy(&refused.stderr);
    assert!(
        !refused.status.success() && stderr.contains("scenario `analyse`"),
        "{stderr}"
    );
    let replaced = run(analysed_dir.to_str().expect("utf-8"), &["--replace"]);
    assert!(
        replaced.status.success(),
        "{}",
        String::from_utf8_lossy(&replaced.stderr)
    );
    assert!(
        !analysed_dir.join("spectrum.csv").exists(),
        "analyse's spectrum removed"
    );
    // A sweep into a run's folder is refused, and a run into a sweep's folder.
    let sweep_file = format!(
        "{}/scenarios/thesis-campaign.toml",
        env!("CARGO_MANIFEST_DIR")
    );
    let sweep = testrig(&["sweep", &sweep_file, "--out", dir]);
    let stderr = String::from_utf8_lossy(&sweep.stderr);
    assert!(
        !sweep.status.success() && stderr.contains("holds the files of a run"),
        "{stderr}"
    );
    let sweep_dir = scratch.join("sweep");
    std::fs::create_dir_all(&sweep_dir).expect("folder");
    std::fs::write(sweep_dir.join("sweep.json"), r#"{"name": "a-sweep"}"#).expect("marker");
    let refused = run(sweep_dir.to_str().expect("utf-8"), &["--replace"]);
    let stderr = String::from_utf8_lossy(&refused.stderr);
    assert!(
        !refused.status.success() && stderr.contains("a sweep's cases (`a-sweep`"),
        "{stderr}"
    );
}
