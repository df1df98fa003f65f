//! The thesis's facts that the judged motion can be held against beside the period of
//! each point (issue 26): how the teeth strike in the half-order motion, the 1/3-order line
//! with 2.712 N m, and the half-order line fading with 5.424 N m.

use std::fmt::Write as _;

use rig::Motion;
use rig::judge::{SUBHARMONIC_CLEAR_DB, SUBHARMONIC_VISIBLE_SHARE};

use super::case_result::CaseResult;
use super::motion_lines::listed;
use super::thesis::HEAVY_LOAD_NM;

/// Impacts per revolution if the teeth struck every fourth tooth (30 / 4): the thesis's
/// explanation of the half order.
const EVERY_FOURTH_TOOTH_PER_REV: f64 = 7.5;
/// Load at which the thesis saw a 1/3-order line (N m) ...
const THIRD_ORDER_LOAD_NM: f64 = 2.712;
/// ... at these speeds (rev/min), Fig 4.74.
const THIRD_ORDER_RPM: [f64; 2] = [1000.0, 1900.0];

/// Writes the facts section of `report.md`.
pub fn facts(md: &mut String, cases: &[CaseResult]) {
    let _ = writeln!(md, "## The thesis's facts against the judged motion\n");
    tooth_pattern(md, cases);
    third_order(md, cases);
    heavy_load_fading(md, cases);
    let _ = writeln!(
        md,
        "- The spectrum at 200 rev/min (brake-side frequency, fundamental, running harmonics; from 3.389 N m the second natural frequency): not covered by a grid that starts above 200 rev/min.\n"
    );
}

fn median(mut values: Vec<f64>) -> Option<f64> {
    values.sort_by(f64::total_cmp);
    values.get(values.len() / 2).copied()
}

/// The thesis's explanation: impacts on every fourth tooth, 7.5 a revolution, 15 teeth.
fn tooth_pattern(md: &mut String, cases: &[CaseResult]) {
    let period_two: Vec<&CaseResult> = cases
        .iter()
        .filter(|c| c.motion.motion == Motion::Periodic(2))
        .collect();
    let (Some(per_rev), Some(teeth)) = (
        median(period_two.iter().map(|c| c.impacts_per_rev).collect()),
        median(
            period_two
                .iter()
                .map(|c| {
                    c.impacts_per_tooth_per_rev
                        .iter()
                        .filter(|&&n| n > 0.0)
                        .count() as f64
                })
                .collect(),
        ),
    ) else {
        let _ = writeln!(
            md,
            "- Impacts on every fourth tooth in the half-order motion (the thesis's explanation): no period-2 point to look at."
        );
        return;
    };
    let every_fourth = (per_rev - EVERY_FOURTH_TOOTH_PER_REV).abs() < 1.0;
    let _ = writeln!(
        md,
        "- Impacts on every fourth tooth in the half-order motion (the thesis's explanation: {EVERY_FOURTH_TOOTH_PER_REV} impacts a revolution on 15 teeth): at the {} period-2 points a median {per_rev:.1} impacts a revolution on {teeth:.0} teeth — {}. `testrig simulate --out` draws the impact raster of a point.",
        period_two.len(),
        if every_fourth {
            "as the explanation has it"
        } else {
            "not the explanation's pattern"
        }
    );
}

/// Fig 4.74: a 1/3-order line at 1000 and 1900 rev/min with 2.712 N m.
fn third_order(md: &mut String, cases: &[CaseResult]) {
    let there: Vec<&CaseResult> = cases
        .iter()
        .filter(|c| c.load_nm == THIRD_ORDER_LOAD_NM && THIRD_ORDER_RPM.contains(&c.rpm))
        .collect();
    if there.is_empty() {
        let _ = writeln!(
            md,
            "- A 1/3-order line at 1000 and 1900 rev/min with 2.712 N m (Fig 4.74): not covered by this grid."
        );
        return;
    }
    let cells: Vec<String> = there
        .iter()
        .map(|c| {
            format!(
                "{} rev/min {}: {}, {}",
                c.rpm,
                c.direction,
                c.motion.motion,
                c.motion
                    .third_order_db
                    .map_or("no line".into(), |h| format!("{h:.0} dB"))
            )
        })
        .collect();
    let clear = there
        .iter()
        .filter(|c| c.motion.third_order_clear())
        .count();
    let _ = writeln!(
        md,
        "- A 1/3-order line at 1000 and 1900 rev/min with 2.712 N m (Fig 4.74): clear of the floor (≥ {SUBHARMONIC_CLEAR_DB} dB over it and at least {SUBHARMONIC_VISIBLE_SHARE:e} of the power) at {clear} of {} points ({}).",
        there.len(),
        cells.join("; ")
    );
}

/// With 5.424 N m the half-order line weakens at 1700 rev/min and is gone at 1900.
fn heavy_load_fading(md: &mut String, cases: &[CaseResult]) {
    let height = |rpm: f64| -> Vec<String> {
        cases
            .iter()
            .filter(|c| c.load_nm >= HEAVY_LOAD_NM - 1e-6 && c.rpm == rpm)
            .map(|c| {
                format!(
                    "{} {}",
                    c.motion
                        .half_order_db
                        .map_or("–".into(), |h| format!("{h:.0} dB")),
                    c.direction
                )
            })
            .collect()
    };
    let rows: Vec<String> = [1500.0, 1700.0, 1900.0]
        .into_iter()
        .map(|rpm| (rpm, height(rpm)))
        .filter(|(_, h)| !h.is_empty())
        .map(|(rpm, h)| format!("{rpm} rev/min {}", h.join(", ")))
        .collect();
    let _ = writeln!(
        md,
        "- With 5.424 N m the half-order line weakens at 1700 rev/min and is gone at 1900: half-order heights over the floor {}.",
        listed(&rows, "not covered by this grid")
    );
}
