//! `manifest.json`: what was run, how, and every file written.

use std::path::Path;

use anyhow::Context;
use serde_json::{Value, json};
use sha2::{Digest, Sha256};

use super::pacing::Pace;
use super::threaded_run::RunResult;
use crate::recording::{PartialFile, end_journal};
use crate::scenario::{AnalyserPlan, Plan, measurement_warnings};

/// How the run ended.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Ending {
    /// It ran its whole length.
    Completed,
    /// Ctrl-C stopped it; files hold every sample up to the stop.
    Interrupted,
    /// An error stopped it; files hold every sample up to the error.
    Failed,
}

impl Ending {
    fn label(self) -> &'static str {
        match self {
            Self::Completed => "completed",
            Self::Interrupted => "interrupted",
            Self::Failed => "failed",
        }
    }
}

/// Writes `dir/manifest.json` for `result` of `plan` from `scenario_path` at `pace`.
pub fn write_manifest(
    dir: &Path,
    scenario_path: &Path,
    plan: &Plan,
    pace: Pace,
    result: &RunResult,
    ending: Ending,
) -> anyhow::Result<()> {
    let p = &result.plant;
    let simulated_s = result.simulated_s();
    let mut files: Vec<String> = result
        .sinks
        .iter()
        .flat_map(|s| &s.files)
        .map(|f| relative(dir, f))
        .collect();
    files.push("manifest.json".into());
    files.sort();
    let ms = |s: f64| s * 1e3;
    let mut manifest = json!({
        "scenario": plan.name,
        "scenario_file": scenario_path.display().to_string(),
        "scenario_sha256": sha256_hex(plan.text.as_bytes()),
        "seed": plan.seed,
        "version": env!("CARGO_PKG_VERSION"),
        "preset": plan.rig.preset,
        "rig": plan.rig.name(),
        "ending": ending.label(),
        "errors": result.failures(),
        "simulated_s": simulated_s,
        "wall_s": result.wall_s,
        "realtime_factor": simulated_s / result.wall_s.max(1e-9),
        "cpu_s": result.cpu_s,
        "cpu_share_of_one_core": result.cpu_s / result.wall_s.max(1e-9),
        "peak_rss_mib": result.peak_rss_mib,
        "pace": pace.label(),
        "block_samples": plan.block_samples,
        "lateness_ms": {
            "p50": ms(p.lateness.quantile_s(0.5)),
            "p99": ms(p.lateness.quantile_s(0.99)),
            "max": ms(p.lateness.max_s()),
            "releases": p.lateness.count(),
        },
        "overflow": format!("{:?}", plan.overflow).to_lowercase(),
        "overruns": p.overruns,
        "overrun_times_s": p.overrun_times_s,
        "impacts": p.impacts,
        "points": points(plan, result),
        "warnings": all_warnings(plan, result),
        "files": files,
        "analyser": plan.analyser.as_ref().map(analyser_settings),
    });
    if let Value::Object(map) = &mut manifest {
        for (key, value) in result.sinks.iter().flat_map(|s| &s.facts) {
            map.insert((*key).to_string(), value.clone());
        }
    }
    let file = PartialFile::new(&dir.join("manifest.json"));
    let mut out = file.create()?;
    serde_json::to_writer_pretty(&mut out, &manifest).context("writing manifest.json")?;
    std::io::Write::flush(&mut out)?;
    drop(out);
    file.commit()?;
    // The manifest now lists the run's files: the journal kept against a kill is done.
    end_journal(dir)
}

/// Writes `dir/manifest.json` for a command other than `run` that wrote `files` into
/// `dir` (`simulate`): named `command` in the field the output-folder guard reads as the
/// run's scenario, with `details` beside the file list; ends the folder's journal.
pub fn write_command_manifest(
    dir: &Path,
    command: &str,
    files: &[std::path::PathBuf],
    details: Value,
) -> anyhow::Result<()> {
    let mut names: Vec<String> = files.iter().map(|f| relative(dir, f)).collect();
    names.push("manifest.json".into());
    names.sort();
    let manifest = json!({
        "scenario": command,
        "version": env!("CARGO_PKG_VERSION"),
        "files": names,
        "details": details,
    });
    let text = serde_json::to_string_pretty(&manifest).context("manifest.json")?;
    PartialFile::write_whole(&dir.join("manifest.json"), text)?;
    end_journal(dir)
}

/// Each measured point with its set points and judged motion (the window's regime,
/// the judge's verdict and numbers, torques, impacts), in the plan's order.
fn points(plan: &Plan, result: &RunResult) -> Vec<Value> {
    let measures = plan.measurements();
    result
        .plant
        .points
        .iter()
        .map(|verdict| {
            let measure = &measures[verdict.index];
            let mut point = json!({
                "label": measure.label,
                "at_s": measure.at_s,
                "speed_set_rpm": measure.speed_rpm,
                "load_set_nm": measure.load_nm,
            });
            if let (Value::Object(map), Ok(Value::Object(judged))) =
                (&mut point, serde_json::to_value(verdict.as_ref()))
            {
                map.extend(judged);
            }
            point
        })
        .collect()
}

/// Every warning of the run: those foreseen from the plan before it started (what `run`
/// prints first), then those of the run itself, each once.
fn all_warnings(plan: &Plan, result: &RunResult) -> Vec<String> {
    let mut warnings = measurement_warnings(plan);
    for warning in result.warnings() {
        if !warnings.contains(&warning) {
            warnings.push(warning);
        }
    }
    warnings
}

fn relative(dir: &Path, file: &Path) -> String {
    file.strip_prefix(dir).unwrap_or(file).display().to_string()
}

/// Lower-case hex SHA-256 of `bytes`.
pub fn sha256_hex(bytes: &[u8]) -> String {
    Sha256::digest(bytes)
        .iter()
        .map(|b| format!("{b:02x}"))
        .collect()
}

/// The analyser's settings in effect (after any `--set`), as the manifest records them.
fn analyser_settings(analyser: &AnalyserPlan) -> Value {
    let s = &analyser.settings;
    json!({
        "input": analyser.input,
        "fmax_hz": s.fmax_hz,
        "block": s.block,
        "window": s.window.name(),
        "averages": s.averages,
        "overlap_pct": 100.0 * s.overlap,
        "sampling": format!("{:?}", s.sampling),
        "adc_bits": analyser.adc.bits,
        "adc_range_v": analyser.adc.range_v,
    })
}
