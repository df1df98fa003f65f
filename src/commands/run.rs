//! `testrig run`: rehearse an experiment from a scenario file.

use std::io::IsTerminal;
use std::process::ExitCode;

use anyhow::{Context, bail};
use testrig::runtime::Ending;
use testrig::runtime::{FolderRun, Pace, RunOptions, RunResult, StopSignals, run_into_folder};
use testrig::scenario::{CommandLine, ScenarioSource, build, measurement_warnings};
use testrig::vocabulary::check_simulated_s;

use crate::cli::RunArgs;

/// Exit status of a `--strict` run that ended with warnings, its files complete.
const WARNED: u8 = 3;

pub fn run(args: &RunArgs) -> anyhow::Result<ExitCode> {
    let pace = args.pace;
    if let Some(d) = args.duration {
        check_simulated_s(d, false).map_err(|e| anyhow::anyhow!("--duration {d}: {e}"))?;
    }
    let source = ScenarioSource::read_with(&args.scenario, &args.overrides)?;
    let plan = build(
        &source,
        CommandLine {
            duration_s: args.duration,
            seed: args.seed,
        },
    )?;
    let predicted = measurement_warnings(&plan);
    if args.strict && !predicted.is_empty() {
        bail!(
            "{}: --strict and measurements that cannot complete (nothing was run):\n  {}",
            args.scenario.display(),
            predicted.join("\n  ")
        );
    }
    for warning in &predicted {
        eprintln!("warning: {warning}");
    }
    let signals = StopSignals::install().context("cannot install the signal handlers")?;
    let options = RunOptions {
        pace,
        out: args.out.clone(),
        stop: signals.flag(),
        console: std::io::stderr().is_terminal(),
        control: None,
        replace: args.replace,
    };
    let FolderRun {
        result,
        ending,
        removed,
    } = run_into_folder(&args.scenario, &plan, &options)?;
    if removed > 0 {
        eprintln!(
            "testrig: removed {removed} files of the earlier run in {}",
            args.out.display()
        );
    }
    let failed = ending == Ending::Failed;
    print_summary(&plan, &args.out, &result, pace);
    if failed {
        let all = result.failures();
        bail!(
            "{} (files up to the stop are kept in {})",
            all.join("; "),
            args.out.display()
        );
    }
    if ending == Ending::Interrupted {
        let (number, name) = signals
            .received()
            .unwrap_or((signal_hook::consts::SIGINT, "a signal"));
        eprintln!("testrig: stopped by {name}; every sample up to the stop is in the files");
        return Ok(ExitCode::from(128 + number as u8));
    }
    let warnings = result.warnings();
    if predicted.is_empty() {
        for warning in &warnings {
            eprintln!("warning: {warning}");
        }
    } else if !warnings.is_empty() {
        eprintln!(
            "testrig: {}, as foreseen above, listed in {}",
            count_of(warnings.len(), "warning"),
            args.out.join("manifest.json").display()
        );
    }
    if args.strict && !warnings.is_empty() {
        eprintln!(
            "testrig: --strict: {} (listed in manifest.json)",
            count_of(warnings.len(), "warning")
        );
        return Ok(ExitCode::from(WARNED));
    }
    Ok(ExitCode::SUCCESS)
}

fn print_summary(
    plan: &testrig::scenario::Plan,
    out: &std::path::Path,
    result: &RunResult,
    pace: Pace,
) {
    let p = &result.plant;
    let files: usize = result.sinks.iter().map(|s| s.files.len()).sum();
    println!(
        "{}: {:.1} s simulated in {:.2} s wall (pace {}), {} impacts, {} overruns",
        plan.name,
        result.simulated_s(),
        result.wall_s,
        pace.label(),
        p.impacts,
        p.overruns
    );
    let measures = plan.measurements();
    for verdict in &p.points {
        let motion = &verdict.summary.motion;
        let half_order = motion.half_order_db.map_or(String::new(), |h| {
            format!(", half order {h:.0} dB over the floor")
        });
        println!(
            "  {}: {}{half_order} (judged over {:.1} s from {:.1} s)",
            measures[verdict.index].label,
            motion.motion,
            verdict.summary.measured_s,
            verdict.from_s,
        );
    }
    if matches!(pace, Pace::Factor(_)) {
        println!(
            "lateness p50 {:.3} ms, p99 {:.3} ms, max {:.3} ms; CPU {:.1} % of one core",
            p.lateness.quantile_s(0.5) * 1e3,
            p.lateness.quantile_s(0.99) * 1e3,
            p.lateness.max_s() * 1e3,
            100.0 * result.cpu_s / result.wall_s.max(1e-9)
        );
    }
    println!("{} files and manifest.json in {}", files, out.display());
}

/// `n` things in words: "1 warning", "2 warnings".
fn count_of(n: usize, thing: &str) -> String {
    if n == 1 {
        format!("1 {thing}")
    } else {
        format!("{n} {thing}s")
    }
}
