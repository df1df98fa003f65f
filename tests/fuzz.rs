//! Structured fuzzing of everything a user hands the tool: scenario and sweep files (the
//! shipped ones mutated), `--set` items, WAV files and their sidecars. 10 000 generated
//! inputs in process: none may panic or hang, and every rejection is an error that names
//! where the fault lies (the file, or the `--set`). The command line's numbers are
//! fuzzed through the binary (`cli_numbers`).

mod common;

use std::path::{Path, PathBuf};
use std::time::{Duration, Instant};

use proptest::prelude::*;
use proptest::test_runner::{Config, RngAlgorithm, TestCaseError, TestRng, TestRunner};
use testrig::scenario::{CommandLine, ScenarioSource, apply_override, build};
use testrig::sweep::{SweepPlan, build_sweep};
use testrig::wav_input::read_signal;

/// Longest any one input may take before it counts as a hang.
const HANG: Duration = Duration::from_secs(5);

fn shipped(kind: &str) -> Vec<(PathBuf, String)> {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("scenarios");
    let mut files: Vec<(PathBuf, String)> = std::fs::read_dir(&dir)
        .expect("scenarios/")
        .map(|e| e.expect("entry").path())
        .filter(|p| p.extension().is_some_and(|e| e == "toml"))
        .map(|p| {
            let text = std::fs::read_to_string(&p).expect("readable");
            (p, text)
        })
        .filter(|(_, text)| (kind == "sweep") == text.lines().any(|l| l.trim() == "[grid]"))
        .collect();
    files.sort();
    files
}

/// Values a hand or a script might write: edge numbers, any float or integer, strings,
/// arrays, tables, and text that is no TOML at all.
fn value() -> impl Strategy<Value = String> {
    prop_oneof![
        prop::sample::select(vec![
            "nan",
            "inf",
            "-inf",
            "-1",
            "0",
            "-0.0",
            "1e308",
            "-1e308",
            "1e-320",
            "[]",
            "{}",
            "true",
            "\"\"",
            "[1, -2, nan]",
            "[0.0, 1e9]",
            "18446744073709551615",
            "\"none\"",
        ])
        .prop_map(str::to_string),
        any::<f64>().prop_map(|v| format!("{v:?}")),
        any::<i64>().prop_map(|v| v.to_string()),
        (0.0..20_000.0f64).prop_map(|v| format!("{v}")),
        "[a-z0-9_.:-]{0,10}".prop_map(|s| format!("\"{s}\"")),
        "\\PC{0,12}",
    ]
}

/// Keys a scenario or sweep holds (and a few it does not).
fn key() -> impl Strategy<Value = String> {
    prop_oneof![
        prop::sample::select(vec![
            "name",
            "seed",
            "duration_s",
            "rate_hz",
            "block_samples",
            "queue_blocks",
            "overflow",
            "speed_rpm",
            "load_nm",
            "at_s",
            "ramp_s",
            "fmax_hz",
            "block",
            "averages",
            "overlap_pct",
            "bits",
            "range_v",
            "window",
            "sampling",
            "kind",
            "order",
            "cutoff_hz",
            "carrier_hz",
            "output_lowpass_hz",
            "decimate",
            "signals",
            "formats",
            "wav_format",
            "teeth",
            "backlash_mm",
            "preset",
            "settle_s",
            "measure_s",
            "rpm",
            "volts_per_div",
            "seconds_per_div",
            "gate_s",
            "tau_s",
            "detector",
            "arrangement",
            "gauge_factor",
            "excitation_v",
            "amplitude_a",
            "frequency_hz",
            "line_db",
            "j1_motor_kgm2",
            "k23_mesh_nm_per_rad",
        ])
        .prop_map(str::to_string),
        "[a-z_]{1,12}",
    ]
}

/// One mutation of a text: a value replaced, a line deleted or doubled, a line inserted,
/// or the text cut short.
#[derive(Clone, Debug)]
enum Mutation {
    Replace(usize, String),
    Delete(usize),
    Double(usize),
    Insert(usize, String, String),
    Cut(usize),
}

fn mutation() -> impl Strategy<Value = Mutation> {
    prop_oneof![
        4 => (any::<usize>(), value()).prop_map(|(l, v)| Mutation::Replace(l, v)),
        1 => any::<usize>().prop_map(Mutation::Delete),
        1 => any::<usize>().prop_map(Mutation::Double),
        2 => (any::<usize>(), key(), value()).prop_map(|(l, k, v)| Mutation::Insert(l, k, v)),
        1 => any::<usize>().prop_map(Mutation::Cut),
    ]
}

fn mutate(text: &str, mutations: &[Mutation]) -> String {
    let mut lines: Vec<String> = text.lines().map(str::to_string).collect();
    for m in mutations {
        let n = lines.len().max(1);
        match m {
            Mutation::Replace(at, v) if !lines.is_empty() => {
                let line = &mut lines[at % n];
                if let Some((k, _)) = line.split_once('=') {
                    *line = format!("{k}= {v}");
                }
            }
            Mutation::Delete(at) if !lines.is_empty() => {
                lines.remove(at % n);
            }
            Mutation::Double(at) if !lines.is_empty() => {
                let line = lines[at % n].clone();
                lines.insert(at % n, line);
            }
            Mutation::Insert(at, k, v) => lines.insert(at % (n + 1), format!("{k} = {v}")),
            Mutation::Cut(at) => {
                let joined = lines.join("\n");
                let mut cut = at % (joined.len() + 1);
                while !joined.is_char_boundary(cut) {
                    cut -= 1;
                }
                lines = joined[..cut].lines().map(str::to_string).collect();
            }
            _ => {}
        }
    }
    lines.join("\n") + "\n"
}

/// Runs `cases` inputs of `strategy` through `check`; fails on a panic (proptest reports
/// it), on an unclear error, or on an input slower than [`HANG`].
fn fuzz<S: Strategy>(cases: u32, strategy: S, check: impl Fn(S::Value) -> Result<(), TestCaseError>)
where
    S::Value: std::fmt::Debug,
{
    // Seeded: the same inputs every run (the project's rule for random sources).
    let rng = TestRng::from_seed(RngAlgorithm::ChaCha, &[19; 32]);
    let config = Config {
        cases,
        failure_persistence: None,
        ..Config::default()
    };
    let mut runner = TestRunner::new_with_rng(config, rng);
    runner
        .run(&strategy, |input| {
            let started = Instant::now();
            let text = format!("{input:?}");
            check(input)?;
            prop_assert!(started.elapsed() < HANG, "slower than {HANG:?}: {text}");
            Ok(())
        })
        .expect("every input handled without a panic, a hang or an unclear error");
}

/// Inputs built and inputs refused by one fuzz test; both must occur, or the generator
/// exercises only one side.
#[derive(Default)]
struct Tally {
    built: std::sync::atomic::AtomicUsize,
    refused: std::sync::atomic::AtomicUsize,
}

impl Tally {
    fn count(&self, built: bool) {
        let counter = if built { &self.built } else { &self.refused };
        counter.fetch_add(1, std::sync::atomic::Ordering::Relaxed);
    }

    /// Prints the tally and checks that each side has at least 2 % of `cases`.
    fn check(&self, what: &str, cases: usize) {
        let built = self.built.load(std::sync::atomic::Ordering::Relaxed);
        let refused = self.refused.load(std::sync::atomic::Ordering::Relaxed);
        println!("{what}: {built} built, {refused} refused with a clear error, 0 panics");
        assert!(
            built + refused >= cases,
            "{what}: {built} + {refused} < {cases}"
        );
        assert!(
            built * 50 >= cases && refused * 50 >= cases,
            "{what}: one-sided"
        );
    }
}

/// An error is clear when it names where the fault is: the file (with line where there is
/// one) or the `--set` that wrote it.
fn clear(message: &str, path: &Path) -> bool {
    let file = path.display().to_string();
    (message.starts_with(&file) || message.starts_with("--set ")) && message.len() > file.len() + 5
}

/// Counts `result` in `tally`; an error must name its place (see [`clear`]).
fn judge<T>(tally: &Tally, result: anyhow::Result<T>, path: &Path) -> Result<(), TestCaseError> {
    tally.count(result.is_ok());
    if let Err(e) = result {
        let message = format!("{e:#}");
        if std::env::var("FUZZ_SHOW").is_ok() {
            println!("{message}");
        }
        prop_assert!(clear(&message, path), "unclear: {message}");
    }
    Ok(())
}

/// `cases` mutations of the shipped files of `kind`, each handed to `build`.
fn fuzz_mutated<T>(kind: &str, cases: u32, build: impl Fn(&ScenarioSource) -> anyhow::Result<T>) {
    let files = shipped(kind);
    let strategy = (0..files.len(), prop::collection::vec(mutation(), 1..4));
    let tally = Tally::default();
    fuzz(cases, strategy, |(index, mutations)| {
        let (path, text) = &files[index];
        let source = ScenarioSource {
            path: path.clone(),
            text: mutate(text, &mutations),
        };
        judge(&tally, build(&source), path)
    });
    tally.check(kind, cases as usize);
}

#[test]
fn mutated_scenarios_are_built_or_refused_with_the_place_named() {
    fuzz_mutated("scenario", 4_000, |source| {
        build(source, CommandLine::default())
    });
}

#[test]
fn mutated_sweeps_are_built_or_refused_with_the_place_named() {
    fuzz_mutated("sweep", 2_000, |source| -> anyhow::Result<SweepPlan> {
        source
            .parse_sweep()
            .and_then(|file| build_sweep(source, &file))
    });
}

#[test]
fn set_items_are_applied_or_refused_naming_the_set() {
    let files = shipped("scenario");
    let paths = prop::sample::select(vec![
        "seed",
        "duration_s",
        "teeth",
        "backlash_mm",
        "schedule.speed_rpm",
        "schedule.load_nm",
        "analyser.averages",
        "analyser.range_v",
        "analyser.fmax_hz",
        "analyser.overlap_pct",
        "analyser.window",
        "chain.filter.cutoff_hz",
        "chain.filter.order",
        "record.decimate",
        "survey.settle_s",
        "rig.set.c1_backlash_variation",
        "brake_drag_nm",
        "chain.scope.seconds_per_div",
        "chain.meter.tau_s",
    ]);
    let item = prop_oneof![
        4 => (paths, value()).prop_map(|(k, v)| format!("{k}={v}")),
        1 => (key(), value()).prop_map(|(k, v)| format!("{k}={v}")),
        1 => (
            prop::sample::select(vec!["schedule", "analyser", "chain.filter", "rig.set", "record", "survey"]),
            key(),
            value()
        )
            .prop_map(|(t, k, v)| format!("{t}.{k}={v}")),
        1 => "\\PC{0,20}",
    ];
    let tally = Tally::default();
    fuzz(2_000, (0..files.len(), item), |(index, item)| {
        let (path, text) = &files[index];
        let edited = match apply_override(text, &item) {
            Ok(edited) => edited,
            Err(e) => {
                tally.count(false);
                let message = format!("{e:#}");
                prop_assert!(message.starts_with("--set "), "unclear: {message}");
                return Ok(());
            }
        };
        let source = ScenarioSource {
            path: path.clone(),
            text: edited,
        };
        judge(&tally, build(&source, CommandLine::default()), path)
    });
    tally.check("--set items", 2_000);
}

/// A small valid WAV (16-bit, two channels) to mutate.
fn wav_bytes(float: bool) -> Vec<u8> {
    let spec = hound::WavSpec {
        channels: 2,
        sample_rate: 8_000,
        bits_per_sample: if float { 32 } else { 16 },
        sample_format: if float {
            hound::SampleFormat::Float
        } else {
            hound::SampleFormat::Int
        },
    };
    let mut cursor = std::io::Cursor::new(Vec::new());
    let mut writer = hound::WavWriter::new(&mut cursor, spec).expect("writer");
    for k in 0..400 {
        if float {
            writer
                .write_sample((k as f32 * 0.01).sin())
                .expect("sample");
            writer.write_sample(0.5f32).expect("sample");
        } else {
            writer.write_sample((k * 37 % 2000) as i16).expect("sample");
            writer.write_sample(-7i16).expect("sample");
        }
    }
    writer.finalize().expect("closed");
    cursor.into_inner()
}

#[test]
fn damaged_wav_files_and_sidecars_are_read_or_refused_naming_the_file() {
    let dir = common::folder("fuzz-wav");
    let originals = [wav_bytes(false), wav_bytes(true)];
    let bytes_edit = prop::collection::vec((any::<usize>(), any::<u8>()), 0..8);
    let sidecar = prop_oneof![
        Just(None),
        Just(Some(
            r#"{"channels":[{"name":"a_v","unit":"V","scale":2.0},{"name":"b","unit":"N m","scale":1e300,"full_scale":0.0}]}"#
                .to_string()
        )),
        "\\PC{0,40}".prop_map(Some),
    ];
    let channel = prop_oneof![
        Just("0".to_string()),
        Just("1".to_string()),
        Just("a_v".to_string()),
        "\\PC{0,6}",
        any::<u64>().prop_map(|v| v.to_string()),
    ];
    let start = prop_oneof![Just(0.0), any::<f64>(), 0.0..0.06f64];
    let length = prop::option::of(prop_oneof![any::<f64>(), 0.0..0.06f64]);
    let strategy = (
        0..2usize,
        bytes_edit,
        prop::option::of(any::<usize>()),
        sidecar,
        channel,
        start,
        length,
    );
    let counter = std::sync::atomic::AtomicUsize::new(0);
    let tally = Tally::default();
    fuzz(
        2_000,
        strategy,
        |(which, edits, cut, sidecar, channel, start, length)| {
            let mut bytes = originals[which].clone();
            for (at, byte) in edits {
                let n = bytes.len();
                bytes[at % n] = byte;
            }
            if let Some(cut) = cut {
                bytes.truncate(cut % (bytes.len() + 1));
            }
            let k = counter.fetch_add(1, std::sync::atomic::Ordering::Relaxed);
            let path = dir.join(format!("input-{}.wav", k % 4));
            std::fs::write(&path, &bytes).expect("written");
            let side = PathBuf::from(format!("{}.json", path.display()));
            match &sidecar {
                Some(text) => std::fs::write(&side, text).expect("written"),
                None => {
                    std::fs::remove_file(&side).ok();
                }
            }
            let read = read_signal(&path, &channel, start, length);
            tally.count(read.is_ok());
            match read {
                Ok(signal) => {
                    prop_assert!(signal.rate_hz > 0.0);
                }
                Err(e) => {
                    let message = format!("{e:#}");
                    let named = message.contains(&path.display().to_string())
                        || message.starts_with("--channel")
                        || message.starts_with("--start")
                        || message.starts_with("--length");
                    prop_assert!(named, "unclear: {message}");
                }
            }
            Ok(())
        },
    );
    tally.check("WAV files", 2_000);
    std::fs::remove_dir_all(&dir).ok();
}

/// Numbers a command line may carry, most of them out of range.
fn cli_number() -> impl Strategy<Value = String> {
    prop_oneof![
        prop::sample::select(vec![
            "nan",
            "NaN",
            "inf",
            "-inf",
            "-1",
            "0",
            "-0",
            "1e308",
            "1e-308",
            "",
            "x",
            "1,5",
            "0x10",
            "+3",
            "1e",
            "--",
            "18446744073709551616",
        ])
        .prop_map(str::to_string),
        any::<f64>().prop_map(|v| format!("{v:e}")),
        any::<i32>().prop_map(|v| v.to_string()),
    ]
}

/// Runs the binary with `args`; ends it after 30 s (a hang).
fn run_bounded(args: &[String]) -> Result<std::process::Output, String> {
    let mut child = std::process::Command::new(env!("CARGO_BIN_EXE_testrig"))
        .args(args)
        .stdout(std::process::Stdio::piped())
        .stderr(std::process::Stdio::piped())
        .spawn()
        .map_err(|e| e.to_string())?;
    let started = Instant::now();
    while child.try_wait().map_err(|e| e.to_string())?.is_none() {
        if started.elapsed() > Duration::from_secs(30) {
            child.kill().ok();
            return Err(format!("hung: {args:?}"));
        }
        std::thread::sleep(Duration::from_millis(5));
    }
    child.wait_with_output().map_err(|e| e.to_string())
}

#[test]
fn cli_numbers_are_used_or_refused_naming_the_flag() {
    let dir = common::folder("fuzz-cli");
    let wav = dir.join("tone.wav");
    std::fs::write(&wav, wav_bytes(true)).expect("written");
    let wav = wav.display().to_string();
    let out = dir.join("out").display().to_string();
    let scenario = Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("scenarios/aliasing-windowing.toml")
        .display()
        .to_string();
    // Each command with its flags at small valid values; one or two of them fuzzed.
    let commands: Vec<Vec<(&str, &str)>> = vec![
        vec![
            ("simulate", ""),
            ("--rpm", "600"),
            ("--load", "1"),
            ("--duration", "0.05"),
            ("--settle", "0"),
            ("--rate", "1000"),
        ],
        vec![
            ("analyse", ""),
            ("--fmax", "1000"),
            ("--block", "64"),
            ("--averages", "1"),
            ("--overlap", "0"),
            ("--bits", "12"),
            ("--range", "1"),
            ("--cutoff", "900"),
            ("--start", "0"),
            ("--length", "0.04"),
        ],
        vec![
            ("run", ""),
            ("--pace", "max"),
            ("--duration", "0.05"),
            ("--seed", "3"),
        ],
        vec![("modes", ""), ("--set", "teeth=30")],
    ];
    let strategy = (
        0..commands.len(),
        prop::collection::vec((any::<usize>(), cli_number()), 1..3),
    );
    let tally = Tally::default();
    let cases: u32 = std::env::var("FUZZ_CLI_CASES")
        .ok()
        .and_then(|s| s.parse().ok())
        .unwrap_or(500);
    fuzz(cases, strategy, |(which, fuzzed)| {
        let flags = &commands[which];
        let mut values: Vec<String> = flags.iter().map(|(_, v)| v.to_string()).collect();
        for (at, number) in &fuzzed {
            let k = 1 + at % (flags.len() - 1);
            values[k] = match flags[k].0 {
                "--set" => format!("teeth={number}"),
                // A valid but long simulated time is a long run, not a hang: times the
                // tool accepts (up to 10⁶ s) above 1 s are cut to 1 s; larger ones stay,
                // to be refused.
                "--duration" | "--settle" => match number.parse::<f64>() {
                    Ok(t) if t > 1.0 && t <= 1.0e6 => "1".to_string(),
                    _ => number.clone(),
                },
                _ => number.clone(),
            };
        }
        let mut args = vec![flags[0].0.to_string()];
        match flags[0].0 {
            "analyse" => args.extend([wav.clone(), "--out".into(), out.clone()]),
            "run" => args.extend([scenario.clone(), "--out".into(), out.clone()]),
            _ => {}
        }
        for (k, (flag, _)) in flags.iter().enumerate().skip(1) {
            // `--flag=value`, so that a value such as `-1` or `--` stays the flag's.
            args.push(format!("{flag}={}", values[k]));
        }
        let output = run_bounded(&args).map_err(TestCaseError::fail)?;
        let stderr = String::from_utf8_lossy(&output.stderr);
        prop_assert!(!stderr.contains("panicked"), "{args:?}: {stderr}");
        tally.count(output.status.success());
        if !output.status.success() {
            // clap's own refusals (exit 2) and ours (exit 1) both name the flag or value.
            let named = flags.iter().skip(1).any(|(f, _)| stderr.contains(f))
                || fuzzed
                    .iter()
                    .any(|(_, n)| !n.is_empty() && stderr.contains(n.as_str()));
            prop_assert!(named, "{args:?}: {stderr}");
        }
        Ok(())
    });
    tally.check("command lines", cases as usize);
    std::fs::remove_dir_all(&dir).ok();
}
