//! The parts of `report.md` a rig file's sweep adds: where no thesis holds it (a rig of
//! its own, or every case faulted), what the points held (hysteresis, coexisting motions,
//! the motor's holding: as the thesis's report says it); and each case's motion, its
//! faults and the watched gear's indicators.

use std::fmt::Write as _;

use super::case_result::CaseResult;
use super::meta::SweepMeta;
use super::motion_lines::motion_lines;

/// The report's opening for rig `rig`, whose sweep no thesis holds: what the points held.
pub(super) fn rig_summary(md: &mut String, meta: &SweepMeta, rig: &str, cases: &[CaseResult]) {
    let _ = writeln!(md, "# {}: rig `{rig}`, case by case\n", meta.name);
    let _ = writeln!(
        md,
        "{} of {} cases finished. The motion is the physics judge's on the gauged shaft's torque (`docs/physics.md`); the indicators (Lebold et al. 2000, `docs/faults.md`) are of the watched gear's synchronous average of that torque. `labels.csv` holds every case's fault, point, motion, indicators and recordings.\n",
        cases.len(),
        meta.cases
    );
    let _ = writeln!(md, "## What the points held\n");
    motion_lines(md, cases);
}

/// Each case of the sweep, a row: its point, swept values, faults, motion, half-order
/// height and the watched gear's FM4 and residual.
pub(super) fn each_case(md: &mut String, meta: &SweepMeta, cases: &[CaseResult]) {
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
}
