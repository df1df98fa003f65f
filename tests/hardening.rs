//! Regressions of the hardening issue (23): inputs that once crashed or silently failed
//! the rig. Each test failed before its fix.

mod common;
mod panel_support;

use common::{folder, read_manifest, run_ok, scenario, testrig};
use panel_support::Panel;

/// A 44.1 kHz recording analysed for a 200 Hz band: the ADC samples at a ratio of
/// 110.25 stream samples, which panicked (exit 101). It now shows the recording's 50 Hz
/// tone where it is.
#[test]
fn a_recording_at_any_rate_is_analysed() {
    let dir = folder("adc-ratio");
    let wav = dir.join("tone-44100.wav");
    let spec = hound::WavSpec {
        channels: 1,
        sample_rate: 44_100,
        bits_per_sample: 32,
        sample_format: hound::SampleFormat::Float,
    };
    let mut writer = hound::WavWriter::create(&wav, spec).expect("writable");
    for k in 0..44_100 * 30 {
        let t = k as f64 / 44_100.0;
        writer
            .write_sample((0.5 * (std::f64::consts::TAU * 50.0 * t).sin()) as f32)
            .expect("sample");
    }
    writer.finalize().expect("finalised");
    let out = dir.join("out");
    let output = testrig(&[
        "analyse",
        wav.to_str().expect("utf-8"),
        "--fmax",
        "200",
        "--out",
        out.to_str().expect("utf-8"),
    ]);
    assert!(
        output.status.success(),
        "{}",
        String::from_utf8_lossy(&output.stderr)
    );
    let lines = common::spectrum(&out.join("spectrum.csv"));
    let peak = lines
        .iter()
        .max_by(|a, b| a.1.total_cmp(&b.1))
        .expect("lines");
    let resolution_hz = lines[1].0 - lines[0].0;
    assert!(
        (peak.0 - 50.0).abs() <= resolution_hz,
        "peak at {} Hz",
        peak.0
    );
    std::fs::remove_dir_all(&dir).ok();
}

/// The run's analyser at an fmax whose ADC rate does not divide the stream's (150 Hz:
/// 300 Hz from 51.2 kHz) panicked in its thread while the run exited 0 with no spectrum.
/// The spectrum is now written and the run completes.
#[test]
fn a_run_whose_adc_rate_does_not_divide_the_stream_writes_its_spectrum() {
    let (out, manifest) = run_ok(
        "adc-ratio-run",
        &scenario("subharmonic-2712nm"),
        &[
            "--duration",
            "21",
            "--set",
            "analyser.fmax_hz=150",
            "--set",
            "analyser.averages=4",
        ],
    );
    assert_eq!(manifest["ending"], "completed", "{manifest}");
    let lines = common::spectrum(&out.join("spectrum-01.csv"));
    let top_hz = lines.last().expect("lines").0;
    assert!((top_hz - 150.0).abs() < 1.0, "band ends at {top_hz} Hz");
    assert!(
        read_manifest(&out)["errors"]
            .as_array()
            .is_some_and(Vec::is_empty)
    );
    std::fs::remove_dir_all(&out).ok();
}

/// A sweep file whose grid is `rpm` speeds by `loads` loads (and the tooth counts given).
fn huge_sweep(rpm: usize, loads: usize, teeth: &str) -> String {
    let speeds: Vec<String> = (0..rpm).map(|i| format!("{}", 100 + i % 2900)).collect();
    let loads: Vec<String> = (0..loads).map(|i| format!("{}", i % 5)).collect();
    format!(
        "name = \"huge\"\nrate_hz = 10240\n\n[grid]\nrpm = [{}]\nload_nm = [{}]\nset = {{ teeth = [{teeth}] }}\n\n[case]\nsettle_s = 1\nmeasure_s = 2\n\n[analyser]\nfmax_hz = 200\nblock = 512\naverages = 1\n",
        speeds.join(", "),
        loads.join(", ")
    )
}

/// A grid of 10⁷ points allocated 3.5 GB before running anything, and 10¹¹ aborted. The
/// cases are now counted first: above a million the sweep is refused at once, naming the
/// file, the count and the limit, with nothing written.
#[test]
fn a_sweep_of_more_cases_than_the_limit_is_refused_before_it_starts() {
    let dir = folder("huge-sweep");
    for (rpm, loads, teeth, count) in [
        (1000, 1001, "30", "1001000 cases"),
        (10_000, 10_000, "29, 30, 31", "300000000 cases"),
    ] {
        let file = dir.join("huge.toml");
        std::fs::write(&file, huge_sweep(rpm, loads, teeth)).expect("sweep file");
        let out = dir.join("out");
        let started = std::time::Instant::now();
        let output = testrig(&[
            "sweep",
            file.to_str().expect("utf-8"),
            "--out",
            out.to_str().expect("utf-8"),
        ]);
        let stderr = String::from_utf8_lossy(&output.stderr);
        assert_eq!(output.status.code(), Some(1), "{stderr}");
        assert!(
            stderr.contains("huge.toml") && stderr.contains("grid") && stderr.contains(count),
            "{stderr}"
        );
        assert!(stderr.contains("more than 1000000"), "{stderr}");
        assert!(!out.join("cases.csv").exists());
        assert!(
            started.elapsed().as_secs() < 60,
            "refused only after {:?}",
            started.elapsed()
        );
    }
    std::fs::remove_dir_all(&dir).ok();
}

/// Slip-ring fluctuations of 1e308 gave an all-NaN recording without a word. They are
/// relative fluctuations of the contact resistance, at most 1; beyond it the scenario is
/// refused at its line, naming the field.
#[test]
fn slip_ring_noise_beyond_any_contact_is_refused_by_name() {
    let dir = folder("slip-nan");
    let out = dir.join("out");
    let output = testrig(&[
        "run",
        &scenario("subharmonic-2712nm"),
        "--pace",
        "max",
        "--set",
        "chain.slip_rings.broadband_rms=1e308",
        "--out",
        out.to_str().expect("utf-8"),
    ]);
    let stderr = String::from_utf8_lossy(&output.stderr);
    assert_eq!(output.status.code(), Some(1), "{stderr}");
    assert!(
        stderr.contains("subharmonic-2712nm.toml")
            && stderr.contains("broadband_rms")
            && stderr.contains("[0, 1]"),
        "{stderr}"
    );
    assert!(!out.join("recording.wav").exists());
    std::fs::remove_dir_all(&dir).ok();
}

/// At `--pace 0.001` a block is due seconds away, and SIGTERM waited for it: 18 s to
/// stop. The paced wait now looks at the stop flag every 50 ms: the run stops within a
/// second, its files complete and the manifest saying it was interrupted.
#[test]
fn a_stop_signal_ends_a_slowly_paced_run_within_a_second() {
    let out = folder("slow-stop");
    let mut child = std::process::Command::new(env!("CARGO_BIN_EXE_testrig"))
        .args([
            "run",
            &scenario("subharmonic-2712nm"),
            "--pace",
            "0.001",
            "--out",
            out.to_str().expect("utf-8"),
        ])
        .stdout(std::process::Stdio::null())
        .stderr(std::process::Stdio::piped())
        .spawn()
        .expect("starts");
    std::thread::sleep(std::time::Duration::from_millis(1500));
    let signalled = std::time::Instant::now();
    let killed = std::process::Command::new("kill")
        .args(["-TERM", &child.id().to_string()])
        .status()
        .expect("kill runs");
    assert!(killed.success());
    let status = child.wait().expect("ends");
    let took = signalled.elapsed();
    assert!(took.as_secs_f64() < 1.0, "stopped after {took:?}");
    assert_eq!(status.code(), Some(128 + 15), "{status:?}");
    assert_eq!(read_manifest(&out)["ending"], "interrupted");
    std::fs::remove_dir_all(&out).ok();
}

/// `set_analyser` with a block of 2²⁰ took the memory to 3 GB and the plant 1.2 s late.
/// Blocks are bounded to 16 384 samples, refused naming the block, as every analyser
/// setting (panel, scenario, `analyse`) comes through one check.
#[test]
fn an_analyser_block_beyond_the_limit_is_refused_by_name() {
    let adc = testrig::chain::AdcChoice {
        bits: 12,
        range_v: 5.0,
        dither_seed: None,
    };
    let words = testrig::chain::AnalyserWords {
        block: 1 << 20,
        ..testrig::chain::AnalyserWords::of(
            &instruments::AnalyserSettings::thesis(1024, 200.0),
            adc,
        )
    };
    let refused = words.set_up(51_200.0);
    let error = refused.err().expect("refused");
    assert_eq!(error.setting(), testrig::chain::AnalyserSetting::Block);
    assert!(
        error.to_string().contains("block 1048576: at most 16384"),
        "{error}"
    );
    let largest = testrig::chain::AnalyserWords {
        block: 16_384,
        ..words
    };
    assert!(largest.set_up(51_200.0).is_ok());
    // The band's top is checked in the same one place, for every front end.
    let no_band = testrig::chain::AnalyserWords {
        fmax_hz: 0.0,
        ..largest
    };
    let error = no_band.set_up(51_200.0).err().expect("refused");
    assert_eq!(error.setting(), testrig::chain::AnalyserSetting::FmaxHz);
}

/// A full disk (here a file-size limit, `ulimit -f`, which fails writes the same way)
/// gave an error naming no file, a truncated file under its final name and no manifest.
/// Now the error names the file, the manifest records the failure, and every file with
/// a final name is complete: the recording that could not be finished keeps its partial
/// name.
#[test]
fn a_write_that_fails_names_its_file_and_leaves_no_truncated_file() {
    let out = folder("full-disk");
    let command = format!(
        "ulimit -f 2000; exec '{}' run '{}' --pace max --out '{}'",
        env!("CARGO_BIN_EXE_testrig"),
        scenario("subharmonic-2712nm"),
        out.display()
    );
    let output = std::process::Command::new("sh")
        .args(["-c", &command])
        .output()
        .expect("sh runs");
    let stderr = String::from_utf8_lossy(&output.stderr);
    assert_eq!(output.status.code(), Some(1), "{stderr}");
    assert!(stderr.contains("recording.wav"), "{stderr}");
    let manifest = read_manifest(&out);
    assert_eq!(manifest["ending"], "failed", "{manifest}");
    let errors = manifest["errors"].to_string();
    assert!(
        errors.contains("recording.wav") && errors.contains("too large"),
        "{errors}"
    );
    assert!(
        !out.join("recording.wav").exists(),
        "a truncated recording kept its name"
    );
    assert!(out.join("recording.wav.partial").exists());
    for listed in manifest["files"].as_array().expect("files") {
        let name = listed["path"].as_str().or(listed.as_str()).unwrap_or("");
        assert!(!name.contains("partial"), "{name} listed as a result");
    }
    std::fs::remove_dir_all(&out).ok();
}

/// Waits (at most 60 s) until `ready` holds.
fn wait_until(what: &str, ready: impl Fn() -> bool) {
    let start = std::time::Instant::now();
    while !ready() {
        assert!(
            start.elapsed() < std::time::Duration::from_secs(60),
            "{what} within 60 s"
        );
        std::thread::sleep(std::time::Duration::from_millis(20));
    }
}

/// A run killed with SIGKILL after its first spectrum leaves finished files and no
/// manifest; they once stayed beside the next run's in the same folder. The journal of
/// finished files names them and their scenario: a run of another scenario is refused
/// there until told `--replace`, and then removes exactly those (a file of the user's
/// stays).
#[test]
fn files_of_a_killed_run_do_not_stand_beside_the_next_runs() {
    let out = folder("killed-run");
    std::fs::create_dir_all(&out).expect("folder");
    std::fs::write(out.join("notes.txt"), "mine").expect("user file");
    let mut child = std::process::Command::new(env!("CARGO_BIN_EXE_testrig"))
        .args([
            "run",
            &scenario("subharmonic-2712nm"),
            "--pace",
            "20",
            "--out",
        ])
        .arg(&out)
        .stdout(std::process::Stdio::null())
        .stderr(std::process::Stdio::null())
        .spawn()
        .expect("starts");
    wait_until("the first spectrum", || {
        out.join("spectrum-01.png").is_file()
    });
    child.kill().expect("SIGKILL");
    child.wait().expect("ended");
    assert!(!out.join("manifest.json").exists());
    let journal = std::fs::read_to_string(out.join("files.journal")).expect("journal");
    assert!(journal.lines().any(|l| l == "spectrum-01.csv"), "{journal}");

    // The next run, of another scenario (no analyser: it writes no spectra), into the
    // same folder: refused, nothing removed, until told to replace.
    let text = "name = \"after\"\nduration_s = 1\n\n[schedule]\nspeed_rpm = 600\nload_nm = 2.712\n\n[record]\nsignals = [\"filter_v\"]\nformats = [\"csv\"]\n";
    let next = out.join("after.toml");
    std::fs::write(&next, text).expect("scenario");
    let args = [
        "run",
        next.to_str().expect("utf-8"),
        "--pace",
        "max",
        "--out",
        out.to_str().expect("utf-8"),
    ];
    let refused = testrig(&args);
    let said = String::from_utf8_lossy(&refused.stderr);
    assert!(!refused.status.success(), "{said}");
    assert!(
        said.contains("another run (scenario `subharmonic-2712nm`)") && said.contains("--replace"),
        "{said}"
    );
    assert!(
        out.join("spectrum-01.csv").exists(),
        "nothing removed when refused"
    );
    let status = testrig(&[&args[..], &["--replace"]].concat());
    assert!(
        status.status.success(),
        "{}",
        String::from_utf8_lossy(&status.stderr)
    );
    let mut left: Vec<String> = std::fs::read_dir(&out)
        .expect("folder")
        .map(|e| e.expect("entry").file_name().to_string_lossy().into_owned())
        .collect();
    left.sort();
    assert!(
        left.iter()
            .all(|name| !name.starts_with("spectrum") && !name.starts_with("scope")),
        "{left:?}"
    );
    assert!(left.contains(&"notes.txt".to_string()), "{left:?}");
    assert!(!left.contains(&"files.journal".to_string()), "{left:?}");
    let manifest = read_manifest(&out);
    for name in left {
        let listed = manifest["files"]
            .as_array()
            .expect("files")
            .iter()
            .any(|f| f == name.as_str());
        assert!(
            listed || ["notes.txt", "after.toml"].contains(&name.as_str()),
            "{name} is neither the new run's nor the user's"
        );
    }
    std::fs::remove_dir_all(&out).ok();
}

/// A panel session killed with SIGKILL kept no `session.toml` (it was written at the
/// end): the session is now a journal, each command appended as it takes effect, so the
/// file holds every command carried out before the kill and reads as a scenario.
#[test]
fn a_killed_panel_session_keeps_every_command_carried_out() {
    let out = folder("killed-panel");
    let mut panel = Panel::start(&out, &["--pace", "5"]);
    for command in [
        r#"{"cmd": "set_speed", "rpm": 1234}"#,
        r#"{"cmd": "set_load", "nm": 1.5}"#,
    ] {
        let (status, reply) = panel.command(command);
        assert_eq!(status, 200, "{command}: {reply}");
    }
    panel.child.kill().expect("SIGKILL");
    panel.child.wait().expect("ended");
    let text = std::fs::read_to_string(out.join("session.toml")).expect("session.toml");
    let session: toml::Value = toml::from_str(&text).expect("TOML");
    let commands = session["command"].as_array().expect("commands");
    assert_eq!(commands.len(), 2, "{text}");
    assert_eq!(commands[0]["cmd"].as_str(), Some("set_speed"));
    assert_eq!(commands[0]["rpm"].as_float(), Some(1234.0));
    assert_eq!(commands[1]["nm"].as_float(), Some(1.5));
    let built = testrig::scenario::build(
        &testrig::scenario::ScenarioSource {
            path: "session.toml".into(),
            text,
        },
        testrig::scenario::CommandLine::default(),
    );
    assert!(
        built.is_ok(),
        "{:#}",
        built.err().map(|e| e.to_string()).unwrap_or_default()
    );
    std::fs::remove_dir_all(&out).ok();
}

/// A finished run's folder: a rerun of its scenario replaces its files; another
/// scenario is refused there (its manifest names the scenario) until `--replace`.
#[test]
fn another_scenarios_run_is_refused_in_a_finished_runs_folder() {
    let out = folder("other-scenario");
    std::fs::create_dir_all(&out).expect("folder");
    let write = |name: &str| {
        let path = out.join(format!("{name}.toml"));
        let text = format!(
            "name = \"{name}\"\nduration_s = 0.5\n\n[schedule]\nspeed_rpm = 600\nload_nm = 1\n"
        );
        std::fs::write(&path, text).expect("scenario");
        path.to_str().expect("utf-8").to_string()
    };
    let (first, second) = (write("first"), write("second"));
    let dir = out.to_str().expect("utf-8");
    let run = |scenario: &str, extra: &[&str]| {
        testrig(&[&["run", scenario, "--pace", "max", "--out", dir][..], extra].concat())
    };
    assert!(run(&first, &[]).status.success());
    assert!(
        run(&first, &[]).status.success(),
        "a rerun replaces its own"
    );
    let refused = run(&second, &[]);
    let said = String::from_utf8_lossy(&refused.stderr);
    assert!(
        !refused.status.success() && said.contains("scenario `first`"),
        "{said}"
    );
    assert_eq!(read_manifest(&out)["scenario"], "first", "nothing replaced");
    assert!(run(&second, &["--replace"]).status.success());
    assert_eq!(read_manifest(&out)["scenario"], "second");
    std::fs::remove_dir_all(&out).ok();
}
