//! The fuzzing harness of `tests/fuzz.rs`: seeded generators of values, keys, mutations
//! and command-line numbers, the runner that fails on panics, hangs and unclear errors,
//! and the tally of inputs built and refused.

use std::path::{Path, PathBuf};
use std::time::{Duration, Instant};

use proptest::prelude::*;
use proptest::test_runner::{Config, RngAlgorithm, TestCaseError, TestRng, TestRunner};
use testrig::scenario::ScenarioSource;

/// Longest any one input may take before it counts as a hang.
pub const HANG: Duration = Duration::from_secs(5);

pub fn shipped(kind: &str) -> Vec<(PathBuf, String)> {
    let scenarios = Path::new(env!("CARGO_MANIFEST_DIR")).join("scenarios");
    // Rig files live in their own folder; scenarios and sweeps beside it.
    let dir = if kind == "rig" {
        scenarios.join("rigs")
    } else {
        scenarios
    };
    let mut files: Vec<(PathBuf, String)> = std::fs::read_dir(&dir)
        .expect("scenarios/")
        .map(|e| e.expect("entry").path())
        .filter(|p| p.extension().is_some_and(|e| e == "toml"))
        .map(|p| {
            let text = std::fs::read_to_string(&p).expect("readable");
            (p, text)
        })
        .filter(|(_, text)| {
            kind == "rig" || (kind == "sweep") == text.lines().any(|l| l.trim() == "[grid]")
        })
        .collect();
    files.sort();
    files
}

/// Values a hand or a script might write: edge numbers, any float or integer, strings,
/// arrays, tables, and text that is no TOML at all.
pub fn value() -> impl Strategy<Value = String> {
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
pub fn key() -> impl Strategy<Value = String> {
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
pub enum Mutation {
    Replace(usize, String),
    Delete(usize),
    Double(usize),
    Insert(usize, String, String),
    Cut(usize),
}

pub fn mutation() -> impl Strategy<Value = Mutation> {
    prop_oneof![
        4 => (any::<usize>(), value()).prop_map(|(l, v)| Mutation::Replace(l, v)),
        1 => any::<usize>().prop_map(Mutation::Delete),
        1 => any::<usize>().prop_map(Mutation::Double),
        2 => (any::<usize>(), key(), value()).prop_map(|(l, k, v)| Mutation::Insert(l, k, v)),
        1 => any::<usize>().prop_map(Mutation::Cut),
    ]
}

pub fn mutate(text: &str, mutations: &[Mutation]) -> String {
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
pub fn fuzz<S: Strategy>(
    cases: u32,
    strategy: S,
    check: impl Fn(S::Value) -> Result<(), TestCaseError>,
) where
    S::Value: std::fmt::Debug,
{
    fuzz_within(cases, HANG, strategy, check);
}

/// As [`fuzz`], an input slower than `limit` failing (whole runs of the binary get the
/// limit of [`run_bounded`], which a loaded 2-core machine needs).
pub fn fuzz_within<S: Strategy>(
    cases: u32,
    limit: Duration,
    strategy: S,
    check: impl Fn(S::Value) -> Result<(), TestCaseError>,
) where
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
            let took = started.elapsed();
            prop_assert!(took < limit, "slower than {limit:?} ({took:?}): {text}");
            Ok(())
        })
        .expect("every input handled without a panic, a hang or an unclear error");
}

/// Inputs built and inputs refused by one fuzz test; both must occur, or the generator
/// exercises only one side.
#[derive(Default)]
pub struct Tally {
    built: std::sync::atomic::AtomicUsize,
    refused: std::sync::atomic::AtomicUsize,
}

impl Tally {
    pub fn count(&self, built: bool) {
        let counter = if built { &self.built } else { &self.refused };
        counter.fetch_add(1, std::sync::atomic::Ordering::Relaxed);
    }

    /// Prints the tally and checks that each side has at least 2 % of `cases`.
    pub fn check(&self, what: &str, cases: usize) {
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
pub fn clear(message: &str, path: &Path) -> bool {
    let file = path.display().to_string();
    (message.starts_with(&file) || message.starts_with("--set ")) && message.len() > file.len() + 5
}

/// Counts `result` in `tally`; an error must name its place (see [`clear`]).
pub fn judge<T>(
    tally: &Tally,
    result: anyhow::Result<T>,
    path: &Path,
) -> Result<(), TestCaseError> {
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
pub fn fuzz_mutated<T>(
    kind: &str,
    cases: u32,
    build: impl Fn(&ScenarioSource) -> anyhow::Result<T>,
) {
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

/// A small valid WAV (16-bit, two channels) to mutate.
pub fn wav_bytes(float: bool) -> Vec<u8> {
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

/// Numbers a command line may carry, most of them out of range.
pub fn cli_number() -> impl Strategy<Value = String> {
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

/// Time a whole run of the binary may take before it counts as a hang.
pub const RUN_HANG: Duration = Duration::from_secs(30);

/// Runs the binary with `args`; ends it after [`RUN_HANG`] (a hang).
pub fn run_bounded(args: &[String]) -> Result<std::process::Output, String> {
    let child = std::process::Command::new(env!("CARGO_BIN_EXE_testrig"))
        .args(args)
        .stdout(std::process::Stdio::piped())
        .stderr(std::process::Stdio::piped())
        .spawn()
        .map_err(|e| e.to_string())?;
    let pid = child.id();
    // The output is read while the child runs, so that a child writing more than a pipe
    // holds never waits on the test.
    let (send, receive) = std::sync::mpsc::channel();
    std::thread::spawn(move || {
        let _ = send.send(child.wait_with_output());
    });
    match receive.recv_timeout(RUN_HANG) {
        Ok(output) => output.map_err(|e| e.to_string()),
        Err(_) => {
            let _ = std::process::Command::new("kill")
                .args(["-9", &pid.to_string()])
                .status();
            Err(format!("hung: {args:?}"))
        }
    }
}
