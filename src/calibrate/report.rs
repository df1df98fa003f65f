//! What a calibration leaves: the best set as a preset file every command takes, its
//! figures as JSON, the convergence plot and `report.md`.

use std::fmt::Write as _;
use std::path::{Path, PathBuf};

use serde::Serialize;

use super::calibration_plan::{ApproachKind, CalibrationPlan};
use super::evaluate::Evaluation;
use super::free_param::{FreeRange, params_at};
use super::log::EvaluationRecord;
use super::objective::PointOutcome;
use crate::plots::{SearchPoint, write_convergence};
use crate::recording::PartialFile;
use crate::scenario::preset_file::is_preset_file;
use crate::sweep::CaseRig;

/// The best set and how it scores.
#[derive(Clone, Debug, Serialize)]
pub struct CalibrationResult {
    /// Calibration name.
    pub name: String,
    /// Evaluations in the logs.
    pub evaluations: usize,
    /// Restarts begun (all shards).
    pub restarts: usize,
    /// The best evaluation's number.
    pub best_evaluation: usize,
    /// The free parameters' best values, by name.
    pub values: std::collections::BTreeMap<String, String>,
    /// Objective on the points the search saw (dB).
    pub objective_db: f64,
    /// Points the search saw, matched from every approach, of them.
    pub training_score: (usize, usize),
    /// Points held out, matched, of them (cross-validation).
    pub held_out_score: Option<(usize, usize)>,
    /// All target points, matched, of them.
    pub score: (usize, usize),
}

/// The record with the lowest objective (the earliest of equals).
pub fn best_record(records: &[EvaluationRecord]) -> Option<&EvaluationRecord> {
    records
        .iter()
        .filter(|r| r.result.error.is_none())
        .min_by(|a, b| {
            a.result
                .objective
                .total_cmp(&b.result.objective)
                .then(a.evaluation.cmp(&b.evaluation))
        })
}

/// The preset file of `best` on `plan`'s base: the base preset's name and every value that
/// differs from it (the free parameters and the campaign's own settings such as its backlash).
pub fn preset_text(
    plan: &CalibrationPlan,
    best: &EvaluationRecord,
    result: &CalibrationResult,
) -> anyhow::Result<String> {
    let rig = params_at(&plan.base, &plan.free, &best.x)?;
    let params = match &rig {
        CaseRig::Preset { params, .. } => params,
        CaseRig::File(file) => return Ok(rig_set_text(plan, best, result, file)),
    };
    // A file cannot be the base of another: then the thesis's preset is.
    let base_name = if is_preset_file(&plan.sweep.preset) {
        rig::PRESET_NAMES[0]
    } else {
        plan.sweep.preset.as_str()
    };
    let preset = rig::preset(base_name)?;
    let mut text = String::new();
    let _ = writeln!(
        text,
        "# Written by `testrig calibrate` ({}): evaluation {} of {}, objective {:.3} dB,\n# {} of {} target points matched from every approach.\n# Use it as `--preset PATH` or `[rig] preset = \"PATH\"`.",
        plan.name,
        best.evaluation,
        result.evaluations,
        best.result.objective,
        result.score.0,
        result.score.1
    );
    let _ = writeln!(text, "base = \"{base_name}\"\n\n[set]");
    for spec in rig::PARAM_SPECS {
        let value = spec.value(params);
        if value != spec.value(&preset) {
            let quoted = if value.parse::<f64>().is_ok() || value == "true" || value == "false" {
                value
            } else {
                format!("\"{value}\"")
            };
            let _ = writeln!(text, "{} = {quoted}", spec.name);
        }
    }
    Ok(text)
}

/// The best of a rig file's calibration as the `[rig.set]` table a sweep file takes: each
/// free parameter's path and value.
fn rig_set_text(
    plan: &CalibrationPlan,
    best: &EvaluationRecord,
    result: &CalibrationResult,
    rig: &rig::RigTopology,
) -> String {
    let mut text = String::new();
    let _ = writeln!(
        text,
        "# Written by `testrig calibrate` ({}): evaluation {} of {}, objective {:.3} dB,\n# {} of {} target points matched from every approach, on rig file `{}`.\n# Paste into a sweep file's [rig] table beside `file = ...`.\n\n[rig.set]",
        plan.name,
        best.evaluation,
        result.evaluations,
        best.result.objective,
        result.score.0,
        result.score.1,
        rig.name
    );
    for (p, &x) in plan.free.iter().zip(&best.x) {
        let value = match p.value(x) {
            toml::Value::String(word) => format!("\"{word}\""),
            other => other.to_string(),
        };
        let _ = writeln!(text, "\"{}\" = {value}", p.name);
    }
    text
}

/// Writes `preset.toml` (a rig file's calibration: `rig-set.toml`), `result.json`,
/// `convergence.{png,svg}` and `report.md` into `dir`.
pub fn write_outputs(
    dir: &Path,
    plan: &CalibrationPlan,
    records: &[EvaluationRecord],
    best: &EvaluationRecord,
    full: &Evaluation,
    result: &CalibrationResult,
) -> anyhow::Result<Vec<PathBuf>> {
    let mut files = Vec::new();
    let best_rig = match plan.base {
        CaseRig::Preset { .. } => "preset.toml",
        CaseRig::File(_) => "rig-set.toml",
    };
    files.push(PartialFile::write_whole(
        &dir.join(best_rig),
        preset_text(plan, best, result)?,
    )?);
    files.push(PartialFile::write_whole(
        &dir.join("result.json"),
        serde_json::to_string_pretty(result)?,
    )?);
    // Shards' logs one after another, numbered in one sequence.
    let points: Vec<SearchPoint> = records
        .iter()
        .enumerate()
        .map(|(n, r)| SearchPoint {
            evaluation: n,
            objective_db: r.result.objective,
            restart: r.restart,
        })
        .collect();
    let title = format!("{}: objective per evaluation", plan.name);
    files.extend(write_convergence(
        &dir.join("convergence"),
        &title,
        &points,
    )?);
    files.push(PartialFile::write_whole(
        &dir.join("report.md"),
        report_text(plan, best, full, result),
    )?);
    Ok(files)
}

fn report_text(
    plan: &CalibrationPlan,
    best: &EvaluationRecord,
    full: &Evaluation,
    r: &CalibrationResult,
) -> String {
    let mut md = String::new();
    let pct = |(a, b): (usize, usize)| {
        if b == 0 {
            0.0
        } else {
            100.0 * a as f64 / b as f64
        }
    };
    let _ = writeln!(md, "# Calibration {}\n", plan.name);
    let _ = writeln!(
        md,
        "{} evaluations ({} restarts), CMA-ES over {} free parameters; each evaluation runs every target point from {} ({} s settling, {} s measured). Best: evaluation {}, objective {:.3} dB.\n",
        r.evaluations,
        r.restarts,
        plan.free.len(),
        approaches_text(&plan.approaches),
        plan.sweep.settle_s,
        plan.sweep.measure_s,
        best.evaluation,
        r.objective_db
    );
    let _ = writeln!(
        md,
        "**Score: {} of {} target points = {:.0} %** matched from every approach.",
        r.score.0,
        r.score.1,
        pct(r.score)
    );
    if let Some(held) = r.held_out_score {
        let _ = writeln!(
            md,
            "Cross-validation: searched on {} of {} points ({:.0} % matched), held out {} ({} matched, {:.0} %).",
            r.training_score.1,
            r.score.1,
            pct(r.training_score),
            held.1,
            held.0,
            pct(held)
        );
    }
    let _ = writeln!(
        md,
        "\n## Free parameters\n\n| name | range | best |\n|---|---|---|"
    );
    for p in &plan.free {
        let range = match &p.range {
            FreeRange::Linear { min, max } => format!("{min} … {max}"),
            FreeRange::Log { min, max } => format!("{min} … {max} (log)"),
            FreeRange::Choice(values) => values.join(", "),
        };
        let value = best.values.get(&p.name).cloned().unwrap_or_default();
        let _ = writeln!(md, "| `{}` | {range} | {value} |", p.name);
    }
    let _ = writeln!(
        md,
        "\n## Points (half-order height over its neighbours, dB, per approach; threshold {} dB)\n\n| rev/min | N m | expected | heights | regimes | matched |\n|---|---|---|---|---|---|",
        plan.sweep.line_db
    );
    for o in &full.outcomes {
        let _ = writeln!(md, "{}", point_row(o));
    }
    let _ = writeln!(md, "\n![convergence](convergence.png)");
    md
}

fn point_row(o: &PointOutcome) -> String {
    let heights: Vec<String> = o
        .heights_db
        .iter()
        .map(|h| h.map_or("–".into(), |h| format!("{h:.1}")))
        .collect();
    format!(
        "| {} | {} | {} | {} | {} | {} |",
        o.rpm,
        o.load_nm,
        if o.expect_present {
            "present"
        } else {
            "absent"
        },
        heights.join(" / "),
        o.regimes.join(" / "),
        if o.matched { "yes" } else { "**no**" }
    )
}

fn approaches_text(list: &[ApproachKind]) -> String {
    list.iter()
        .map(|a| match a {
            ApproachKind::Static => "a static start",
            ApproachKind::FromBelow => "below",
            ApproachKind::FromAbove => "above",
        })
        .collect::<Vec<_>>()
        .join(" and ")
}
