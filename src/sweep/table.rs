//! The sweep's results on disk: one JSON per case as it finishes (`cases/case-NNNN.json`,
//! written whole or not at all), and `cases.csv`, one row per case in index order.

use std::path::{Path, PathBuf};

use anyhow::Context;

use super::case::CaseResult;
use crate::recording::{CsvRecorder, PartialFile};

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
    let mut all: Vec<CaseResult> = Vec::new();
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
                all.push(case);
            }
        }
    }
    all.sort_by_key(|c| c.index);
    all.dedup_by_key(|c| c.index);
    Ok(all)
}

/// Writes `dir/cases.csv`: index, rpm, load_nm, the swept parameters, then the results.
pub fn write_table(dir: &Path, swept: &[String], cases: &[CaseResult]) -> anyhow::Result<PathBuf> {
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
            "averages",
            "seed",
        ]
        .map(String::from),
    );
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
            c.averages.to_string(),
            c.seed.to_string(),
        ]);
        csv.write_row(&row)?;
    }
    csv.finish()
}
