//! The sweep's results on disk: one JSON per case as it finishes (`cases/case-NNNN.json`,
//! written whole or not at all), and `cases.csv`, one row per case in index order.

use std::path::{Path, PathBuf};

use anyhow::Context;

use super::case_result::CaseResult;
use super::thesis::{physics_match, thesis_motion};
use crate::recording::{CsvRecorder, PartialFile};
use crate::vocabulary::GearIndicators;

/// Folder of the per-case files inside a sweep's output folder.
pub const CASES_DIR: &str = "cases";

/// Path of case `index`'s JSON in `dir`.
pub fn case_path(dir: &Path, index: usize) -> PathBuf {
    dir.join(CASES_DIR).join(format!("case-{index:05}.json"))
}

/// Writes one case's JSON.
pub fn write_case(dir: &Path, result: &CaseResult) -> anyhow::Result<()> {
    let file = PartialFile::new(&case_path(dir, result.index));
    let mut out = file.create()?;
    serde_json::to_writer(&mut out, result).context("writing a case")?;
    std::io::Write::flush(&mut out)?;
    drop(out);
    file.commit()?;
    Ok(())
}

/// Every finished case in the `cases/` folders of `dirs`, sorted by index (a case found in
/// two folders is taken once).
pub fn read_cases(dirs: &[PathBuf]) -> anyhow::Result<Vec<CaseResult>> {
    let mut all: Vec<(CaseResult, &PathBuf)> = Vec::new();
    for dir in dirs {
        let folder = dir.join(CASES_DIR);
        let entries = std::fs::read_dir(&folder)
            .with_context(|| format!("{}: no sweep results here", folder.display()))?;
        for entry in entries {
            let path = entry?.path();
            if path.extension().is_some_and(|e| e == "json") {
                let text = std::fs::read_to_string(&path)?;
                let case: CaseResult = serde_json::from_str(&text)
                    .with_context(|| format!("{}: not a case result", path.display()))?;
                all.push((case, dir));
            }
        }
    }
    all.sort_by_key(|(c, _)| c.index);
    if let Some(pair) = all.windows(2).find(|w| w[0].0.index == w[1].0.index) {
        anyhow::bail!(
            "case {} is in {} and in {}: each case belongs to one folder (a folder given twice, or shards of different splits)",
            pair[0].0.index,
            pair[0].1.display(),
            pair[1].1.display()
        );
    }
    Ok(all.into_iter().map(|(c, _)| c).collect())
}

/// Writes `dir/cases.csv`: index, rpm, load_nm, the swept parameters, then the results.
/// The thesis's motion and the match are left empty unless `thesis` (a sweep held
/// against the thesis, `SweepMeta::held_against_thesis`) and the case healthy.
pub fn write_table(
    dir: &Path,
    swept: &[String],
    cases: &[CaseResult],
    thesis: bool,
) -> anyhow::Result<PathBuf> {
    let mut header: Vec<String> = ["index", "rpm", "load_nm"].map(String::from).to_vec();
    header.extend(swept.iter().cloned());
    header.extend(
        [
            "regime",
            "period",
            "half_order",
            "first_order",
            "second_order",
            "half_order_db",
            "half_order_present",
            "impacts_per_rev",
            "teeth_struck",
            "impacts_per_tooth_per_rev_max",
            "separates",
            "apart_fraction",
            "torque_mean_nm",
            "torque_ac_rms_nm",
            "speed_offset_rpm",
            "averages",
            "seed",
            "direction",
            "motion",
            "motion_period",
            "spread_1rev",
            "spread_2rev",
            "spread_3rev",
            "spread_4rev",
            "line_fraction_1",
            "line_fraction_2",
            "line_fraction_3",
            "line_fraction_4",
            "half_order_floor_db",
            "third_order_floor_db",
            "chaos_k",
            "thesis_motion",
            "physics_match",
            "kick_rad_s",
        ]
        .map(String::from),
    );
    header.extend(condition_header());
    let mut csv = CsvRecorder::create(&dir.join("cases.csv"), &header)?;
    for c in cases {
        let mut row: Vec<String> = vec![
            c.index.to_string(),
            c.rpm.to_string(),
            c.load_nm.to_string(),
        ];
        row.extend(c.values.iter().cloned());
        let struck = c
            .impacts_per_tooth_per_rev
            .iter()
            .filter(|&&n| n > 0.0)
            .count();
        let most = c
            .impacts_per_tooth_per_rev
            .iter()
            .copied()
            .fold(0.0, f64::max);
        row.extend([
            c.regime.to_string(),
            c.regime.period().unwrap_or(0).to_string(),
            format!("{:e}", c.half_order),
            format!("{:e}", c.first_order),
            format!("{:e}", c.second_order),
            format!("{:.2}", c.half_order_db),
            c.half_order_present.to_string(),
            format!("{:.4}", c.impacts_per_rev),
            struck.to_string(),
            format!("{most:.4}"),
            c.separates.to_string(),
            format!("{:.6}", c.apart_fraction),
            format!("{:.6}", c.torque_mean_nm),
            format!("{:.6}", c.torque_ac_rms_nm),
            format!("{:.3}", c.speed_offset_rpm),
            c.averages.to_string(),
            c.seed.to_string(),
        ]);
        row.extend(judge_columns(c, thesis));
        row.push(format!("{:.6}", c.kick_rad_s));
        row.extend(condition_columns(c.condition.as_ref()));
        row.extend(condition_columns(c.measured_condition.as_ref()));
        csv.write_row(&row)?;
    }
    csv.finish()
}

/// The condition indicators' column names: the true torque's, then the measured
/// signal's (`measured_` before each name).
pub fn condition_header() -> Vec<String> {
    let truth = GearIndicators::COLUMNS.map(String::from);
    let measured = GearIndicators::COLUMNS.map(|c| format!("measured_{c}"));
    truth.into_iter().chain(measured).collect()
}

/// The condition indicators' columns of `condition` (empty where none were taken).
pub fn condition_columns(condition: Option<&GearIndicators>) -> Vec<String> {
    match condition {
        None => vec![String::new(); GearIndicators::COLUMNS.len()],
        Some(i) => {
            let values = i.values();
            let (count, indicators) = values.split_last().unwrap_or((&0.0, &[]));
            let mut row: Vec<String> = indicators.iter().map(|v| format!("{v:.6e}")).collect();
            row.push(format!("{count}"));
            row
        }
    }
}

/// The judge's columns of a case: direction, motion, its numbers, the thesis's motion at
/// the point and whether they match (empty where the thesis decides nothing).
fn judge_columns(c: &CaseResult, thesis: bool) -> Vec<String> {
    let m = &c.motion;
    let number =
        |v: Option<f64>, digits: usize| v.map_or(String::new(), |v| format!("{v:.digits$}"));
    let mut row = vec![
        c.direction.to_string(),
        m.motion.to_string(),
        m.motion.period().unwrap_or(0).to_string(),
    ];
    row.extend((0..4).map(|k| number(m.spread.get(k).copied().flatten(), 6)));
    row.extend((0..4).map(|k| number(m.line_fraction.get(k).copied().flatten(), 6)));
    row.extend([
        number(m.half_order_db, 2),
        number(m.third_order_db, 2),
        number(m.chaos_k, 4),
    ]);
    let expected = thesis_motion(c.rpm, c.load_nm).filter(|_| thesis && c.is_healthy());
    row.push(expected.map_or(String::new(), |e| e.to_string()));
    row.push(expected.map_or(String::new(), |_| physics_match(c).to_string()));
    row
}
