//! `report.md` of a sweep on a rig file's rig: no thesis to hold it against, so what the
//! points held (hysteresis, coexisting motions, the motor's holding: as a preset's
//! report), each case's motion, its faults and the watched gear's indicators, with the
//! plots.

use std::fmt::Write as _;
use std::path::{Path, PathBuf};

use super::case::CaseResult;
use super::meta::SweepMeta;
use super::motion_lines::motion_lines;
use super::report::plots_section;
use crate::recording::PartialFile;

/// Writes `dir/report.md` for the cases of a sweep on rig `rig` and returns its path.
pub fn write_rig_report(
    dir: &Path,
    meta: &SweepMeta,
    rig: &str,
    cases: &[CaseResult],
    plots: &[PathBuf],
) -> anyhow::Result<PathBuf> {
    let mut md = String::new();
    let _ = writeln!(md, "# {}: rig `{rig}`, case by case\n", meta.name);
    let _ = writeln!(
        md,
        "{} of {} cases finished. The motion is the physics judge's on the gauged shaft's torque (`docs/physics.md`); the indicators (Lebold et al. 2000, `docs/faults.md`) are of the watched gear's synchronous average of that torque. `labels.csv` holds every case's fault, point, motion, indicators and recordings.\n",
        cases.len(),
        meta.cases
    );
    let _ = writeln!(md, "## What the points held\n");
    motion_lines(&mut md, cases);
    let _ = writeln!(md, "\n## Each case\n");
    let mut header = vec!["case", "rev/min", "N m"];
    header.extend(meta.swept.iter().map(String::as_str));
    header.extend([
        "fault",
        "motion",
        "half order (dB)",
        "FM4",
        "residual RMS (N m)",
    ]);
    let _ = writeln!(md, "| {} |", header.join(" | "));
    let _ = writeln!(md, "|{}", " --- |".repeat(header.len()));
    for c in cases {
        let fault: Vec<String> = c
            .faults
            .iter()
            .filter(|f| f.severity > 0.0)
            .map(|f| format!("{} {} tooth {} {}", f.kind, f.gear, f.tooth, f.severity))
            .collect();
        let fault = if fault.is_empty() {
            "healthy".to_string()
        } else {
            fault.join(", ")
        };
        let (fm4, residual) = c.condition.map_or((String::new(), String::new()), |i| {
            (
                format!("{:.3}", i.fm4),
                format!("{:.3e}", i.residual_rms_nm),
            )
        });
        let mut row = vec![
            c.index.to_string(),
            c.rpm.to_string(),
            c.load_nm.to_string(),
        ];
        row.extend(c.values.iter().cloned());
        row.extend([
            fault,
            c.motion.motion.to_string(),
            format!("{:.1}", c.half_order_db),
            fm4,
            residual,
        ]);
        let _ = writeln!(md, "| {} |", row.join(" | "));
    }
    plots_section(&mut md, plots);
    PartialFile::write_whole(&dir.join("report.md"), md)
}
