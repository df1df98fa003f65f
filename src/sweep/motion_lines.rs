//! What a sweep's points held, in words, for any rig's `report.md`: where the run-up and
//! the run-down settle to different motions (hysteresis), where the approaches to one
//! point do (coexisting motions), and where the motor does not hold the set speed.

use std::fmt::Write as _;

use super::case_result::CaseResult;
use super::held_motions::held_motions;
use super::sequence::Direction;

/// The three lines (hysteresis where the sweep ran up, coexisting motions where a point
/// was reached twice, the motor's holding always), as bullets of `md`.
pub fn motion_lines(md: &mut String, cases: &[CaseResult]) {
    hysteresis(md, cases);
    coexisting(md, cases);
    motor_holding(md, cases);
}

/// Speeds where the run-up and the run-down settle to different motions.
fn hysteresis(md: &mut String, cases: &[CaseResult]) {
    let mut lines = Vec::new();
    for up in cases.iter().filter(|c| c.direction == Direction::Up) {
        let down = cases.iter().find(|d| {
            d.direction == Direction::Down
                && d.rpm == up.rpm
                && d.load_nm == up.load_nm
                && d.values == up.values
        });
        if let Some(down) = down.filter(|d| coexist(up, d)) {
            lines.push(format!(
                "{} rev/min, {} N m: {} ({:.2} N m AC RMS) going up, {} ({:.2} N m) coming down",
                up.rpm,
                up.load_nm,
                up.motion.motion,
                up.motion.ac_rms_nm,
                down.motion.motion,
                down.motion.ac_rms_nm
            ));
        }
    }
    if cases.iter().any(|c| c.direction == Direction::Up) {
        let _ = writeln!(
            md,
            "- Hysteresis (the run-up and the run-down settle to different motions): {}.",
            listed(&lines, "none")
        );
    }
}

/// Points reached by more than one approach where the approaches settle to different
/// motions: each motion with the approaches that reached it.
fn coexisting(md: &mut String, cases: &[CaseResult]) {
    let points = held_motions(cases);
    let reached_twice = points
        .iter()
        .any(|h| h.motions.iter().map(|(_, by)| by.len()).sum::<usize>() > 1);
    if !reached_twice {
        return;
    }
    let lines: Vec<String> = points
        .iter()
        .filter(|h| h.coexist())
        .map(|h| {
            format!(
                "{} rev/min, {} N m: {}",
                h.point.rpm,
                h.point.load_nm,
                h.describe()
            )
        })
        .collect();
    let _ = writeln!(
        md,
        "- Coexisting motions (the approaches settle to different motions): {}.",
        listed(&lines, "none")
    );
}

/// Points where the motor does not hold the set speed: its mean speed over the window
/// more than [`SPEED_HELD_FRACTION`] of the set speed off it (its torque limit reached).
fn motor_holding(md: &mut String, cases: &[CaseResult]) {
    let lost: Vec<String> = cases
        .iter()
        .filter(|c| c.speed_offset_rpm.abs() > SPEED_HELD_FRACTION * c.rpm)
        .map(|c| {
            format!(
                "{} rev/min, {} N m, {}: {:+.0} rev/min",
                c.rpm, c.load_nm, c.direction, c.speed_offset_rpm
            )
        })
        .collect();
    let _ = writeln!(
        md,
        "- The motor holds the set speed (mean within {:.0} %): {}.",
        100.0 * SPEED_HELD_FRACTION,
        if lost.is_empty() {
            "at every point".to_string()
        } else {
            format!("not at {} points — {}", lost.len(), lost.join("; "))
        }
    );
}

/// A report's list: `lines` joined by semicolons, or `empty` where there are none.
pub(super) fn listed(lines: &[String], empty: &str) -> String {
    if lines.is_empty() {
        empty.to_string()
    } else {
        lines.join("; ")
    }
}

/// Share of the set speed the window's mean speed may be off it with the speed held.
const SPEED_HELD_FRACTION: f64 = 0.01;

/// Whether two cases at one point settled to different motions: another kind, or the
/// same kind with AC RMS torques more than [`COEXIST_RMS_RATIO`] apart.
fn coexist(a: &CaseResult, b: &CaseResult) -> bool {
    let (x, y) = (a.motion.ac_rms_nm, b.motion.ac_rms_nm);
    a.motion.motion != b.motion.motion || x.max(y) > COEXIST_RMS_RATIO * x.min(y)
}

/// Ratio of AC RMS torques that tells two motions of one kind apart.
const COEXIST_RMS_RATIO: f64 = 1.2;
