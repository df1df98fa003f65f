//! Structured fuzzing of everything a user hands the tool: scenario and sweep files (the
//! shipped ones mutated), `--set` items, WAV files and their sidecars. 10 000 generated
//! inputs in process: none may panic or hang, and every rejection is an error that names
//! where the fault lies (the file, or the `--set`). The command line's numbers are
//! fuzzed through the binary (`cli_numbers`).

mod common;
mod fuzz_support;

use anyhow::Context;
use std::path::{Path, PathBuf};

use fuzz_support::{
    Tally, cli_number, fuzz, fuzz_mutated, judge, key, run_bounded, shipped, value, wav_bytes,
};
use proptest::prelude::*;
use proptest::test_runner::TestCaseError;
use testrig::scenario::{CommandLine, ScenarioSource, apply_override, build};
use testrig::sweep::{SweepPlan, build_sweep};
use testrig::wav_input::read_signal;

#[test]
fn mutated_scenarios_are_built_or_refused_with_the_place_named() {
    fuzz_mutated("scenario", 4_000, |source| {
        build(source, CommandLine::default())
    });
}

#[test]
fn mutated_rig_files_are_read_and_run_or_refused_with_the_place_named() {
    // Every rig read is also run: 20 ms at 300 rev/min and 1 N m from steady motion.
    fuzz_mutated("rig", 1_000, |source| {
        let rig = testrig::scenario::rig_topology(source)?;
        let frequencies = rig.natural_frequencies_hz();
        let schedule = rig::Schedule::constant(300.0, 1.0);
        let mut block = rig::NetworkBlock::new(&rig);
        rig::NetworkPlant::new(&rig, schedule, 5_120.0, rig::NetworkStart::Steady)
            .and_then(|mut plant| plant.run(102, &mut block))
            .with_context(|| format!("{}: run at 300 rev/min, 1 N m", source.path.display()))?;
        Ok(frequencies)
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
            // A folder for each command: the output-folder guard keeps one command's
            // files from another's.
            "analyse" => args.extend([wav.clone(), "--out".into(), format!("{out}-analyse")]),
            "run" => args.extend([scenario.clone(), "--out".into(), format!("{out}-run")]),
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
