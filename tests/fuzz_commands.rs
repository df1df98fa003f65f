//! Structured fuzzing of the live commands: a panel session's worth of commands with
//! edge values (NaN, infinities, huge and tiny numbers, zero, any integer, wrong names)
//! at random virtual times, written as a scenario's `[[command]]` entries and run through
//! every part of the rig they address. No run may panic or hang; each refused command is
//! a warning naming its time; a run may end only by a clear error.

mod common;
#[allow(dead_code)]
mod fuzz_support;

use std::cell::Cell;

use fuzz_support::{RUN_HANG, fuzz_within, run_bounded};
use proptest::prelude::*;

/// A number as TOML writes it: the edges, then any float.
fn number() -> impl Strategy<Value = String> {
    prop_oneof![
        prop::sample::select(vec![
            "nan", "inf", "-inf", "0.0", "-0.0", "-1.0", "1e308", "1e-300", "5e-324", "0.5",
            "2.712", "1300.0", "200.0", "1e6",
        ])
        .prop_map(str::to_string),
        any::<f64>().prop_map(|v| format!("{v:?}")),
        (0.0..3000.0f64).prop_map(|v| format!("{v:?}")),
    ]
}

/// A count: edges and any unsigned integer TOML can hold.
fn count() -> impl Strategy<Value = String> {
    prop_oneof![
        prop::sample::select(vec![
            "0", "1", "2", "12", "13", "1024", "1048576", "1048577"
        ])
        .prop_map(str::to_string),
        (0..i64::MAX).prop_map(|v| v.to_string()),
    ]
}

/// An analyser block: wrong ones and those up to 4096 (larger blocks are allowed but each
/// saved display then plots hundreds of thousands of lines, seconds per file).
fn block() -> impl Strategy<Value = String> {
    prop::sample::select(vec![
        "0",
        "1",
        "1000",
        "16",
        "256",
        "1024",
        "4096",
        "18446744073709551615",
    ])
    .prop_map(str::to_string)
}

/// One `[[command]]` entry at virtual time `at_s`.
fn command() -> impl Strategy<Value = String> {
    let body = prop_oneof![
        number().prop_map(|v| format!("cmd = \"set_speed\"\nrpm = {v}")),
        number().prop_map(|v| format!("cmd = \"set_load\"\nnm = {v}")),
        (number(), number()).prop_map(|(a, f)| format!("cmd = \"set_oscillating_load\"\nnm = {a}\nhz = {f}")),
        number().prop_map(|v| format!("cmd = \"set_amplifier_gain\"\ngain = {v}")),
        (prop::sample::select(vec!["none", "butterworth", "bessel"]), count(), number())
            .prop_map(|(k, o, c)| format!("cmd = \"set_filter\"\nkind = \"{k}\"\norder = {o}\ncutoff_hz = {c}")),
        number().prop_map(|v| format!("cmd = \"set_adc_range\"\nrange_v = {v}")),
        (number(), block(), prop::sample::select(vec!["uniform", "hanning", "flattop"]), count(), number())
            .prop_map(|(f, b, w, a, o)| format!(
                "cmd = \"set_analyser\"\nfmax_hz = {f}\nblock = {b}\nwindow = \"{w}\"\naverages = {a}\noverlap_pct = {o}"
            )),
        (number(), number(), number(), prop::sample::select(vec!["auto", "single"]))
            .prop_map(|(v, s, t, m)| format!(
                "cmd = \"set_scope\"\nvolts_per_div = {v}\nseconds_per_div = {s}\ntrigger_v = {t}\nmode = \"{m}\""
            )),
        prop::sample::select(vec![
            "cmd = \"start_average\"",
            "cmd = \"hold_average\"",
            "cmd = \"arm_scope\"",
            "cmd = \"record\"\non = true",
            "cmd = \"record\"\non = false",
            "cmd = \"save_displays\"",
        ])
        .prop_map(str::to_string),
    ];
    (0.0..1.5f64, body).prop_map(|(at, body)| format!("[[command]]\nat_s = {at:?}\n{body}\n"))
}

#[test]
#[ignore = "12 whole runs: .ci/run runs it (cargo test --test fuzz_commands -- --ignored)"]
fn fuzzed_commands_are_carried_out_or_refused_without_a_panic() {
    let dir = common::folder("fuzz-commands");
    let base = std::fs::read_to_string(common::scenario("panel")).expect("panel.toml");
    let base = testrig::scenario::apply_override(&base, "analyser.averages=2").expect("applies");
    let (runs, stopped, refused) = (Cell::new(0), Cell::new(0), Cell::new(0));
    fuzz_within(
        12,
        RUN_HANG,
        prop::collection::vec(command(), 40),
        |commands| {
            let text = format!("{base}\n{}", commands.join("\n"));
            let path = dir.join("commands.toml");
            std::fs::write(&path, &text).expect("written");
            let out = dir.join("out");
            let args: Vec<String> = ["run", path.to_str().expect("utf-8"), "--pace", "max"]
                .iter()
                .map(|s| s.to_string())
                .chain([
                    "--duration".into(),
                    "3".into(),
                    "--out".into(),
                    out.display().to_string(),
                ])
                .collect();
            let output = run_bounded(&args).map_err(TestCaseError::fail)?;
            let stderr = String::from_utf8_lossy(&output.stderr);
            prop_assert!(!stderr.contains("panicked"), "{stderr}");
            runs.set(runs.get() + 1);
            if !output.status.success() {
                // Only the plant may stop a run: an accepted set point it could not follow.
                prop_assert!(stderr.contains("the plant stopped"), "{stderr}");
                stopped.set(stopped.get() + 1);
                return Ok(());
            }
            let manifest = std::fs::read_to_string(out.join("manifest.json")).expect("manifest");
            refused.set(refused.get() + manifest.matches("was refused").count());
            Ok(())
        },
    );
    eprintln!(
        "MEASURED fuzzed commands: {} runs of 40, {} stopped by the plant, {} commands refused",
        runs.get(),
        stopped.get(),
        refused.get()
    );
    assert!(refused.get() > 0, "the generator exercises refusals");
    std::fs::remove_dir_all(&dir).ok();
}
