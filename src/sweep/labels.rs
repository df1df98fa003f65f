//! `labels.csv`: one row per case for a data set's user — its recordings, its operating
//! point and swept values, its tooth faults (`healthy` where none has a severity above
//! 0), the judged motion and the condition indicators.

use std::path::{Path, PathBuf};

use super::case_result::CaseResult;
use super::table::{condition_columns, condition_header};
use crate::recording::CsvRecorder;

/// Writes `dir/labels.csv` for `cases`, the swept parameters' columns named by `swept`.
pub fn write_labels(dir: &Path, swept: &[String], cases: &[CaseResult]) -> anyhow::Result<PathBuf> {
    let mut header: Vec<String> = ["index", "recordings", "rpm", "load_nm"]
        .map(String::from)
        .to_vec();
    header.extend(swept.iter().cloned());
    header.extend(
        [
            "fault_kind",
            "fault_severity",
            "fault_mesh",
            "fault_gear",
            "fault_tooth",
            "motion",
            "regime",
            "torque_mean_nm",
            "torque_ac_rms_nm",
            "seed",
        ]
        .map(String::from),
    );
    header.extend(condition_header());
    let mut csv = CsvRecorder::create(&dir.join("labels.csv"), &header)?;
    for c in cases {
        let mut row = vec![
            c.index.to_string(),
            c.recordings.join(" "),
            c.rpm.to_string(),
            c.load_nm.to_string(),
        ];
        row.extend(c.values.iter().cloned());
        row.extend(fault_columns(c));
        row.extend([
            c.motion.motion.to_string(),
            c.regime.to_string(),
            format!("{:.6}", c.torque_mean_nm),
            format!("{:.6}", c.torque_ac_rms_nm),
            c.seed.to_string(),
        ]);
        row.extend(condition_columns(c.condition.as_ref()));
        row.extend(condition_columns(c.measured_condition.as_ref()));
        csv.write_row(&row)?;
    }
    csv.finish()
}

/// The fault's columns: kind, severity, mesh, gear, tooth; `healthy` with severity 0 and
/// the others empty where no fault has a severity above 0; several faults joined by `+`.
fn fault_columns(c: &CaseResult) -> [String; 5] {
    let faults: Vec<_> = c.faults.iter().filter(|f| f.severity > 0.0).collect();
    if c.is_healthy() {
        return [
            "healthy".into(),
            "0".into(),
            String::new(),
            String::new(),
            String::new(),
        ];
    }
    let join = |f: &dyn Fn(&super::case_result::FaultLabel) -> String| {
        faults.iter().map(|x| f(x)).collect::<Vec<_>>().join("+")
    };
    [
        join(&|f| f.kind.clone()),
        join(&|f| f.severity.to_string()),
        join(&|f| f.mesh.clone()),
        join(&|f| f.gear.clone()),
        join(&|f| f.tooth.to_string()),
    ]
}
