//! The objective: a hinge on each point's half-order height against its threshold, so
//! the search sees progress before a verdict flips; and the score (points matched) beside it.

use rig::judge::{
    CHAOS_K_MIN, Judgement, LINE_FRACTION_MIN, Motion, SPREAD_MAX, SUBHARMONIC_CLEAR_DB,
};
use serde::{Deserialize, Serialize};

use super::calibration_plan::{Expect, NaturalTarget};

/// Largest loss one point adds (dB): a point far off counts no more than this.
pub const LOSS_CAP_DB: f64 = 40.0;

/// Objective of a candidate that could not be evaluated (bad parameters, a blown-up run).
pub const FAILED_LOSS_DB: f64 = 2.0 * LOSS_CAP_DB;

/// What one point showed for one candidate.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct PointOutcome {
    /// Target point index.
    pub index: usize,
    /// Speed (rev/min).
    pub rpm: f64,
    /// Load (N m).
    pub load_nm: f64,
    /// Whether the line is expected.
    pub expect_present: bool,
    /// Half-order height over its neighbours (dB) from each approach, in the plan's order
    /// (null when the line could not be measured).
    pub heights_db: Vec<Option<f64>>,
    /// Regime from each approach.
    pub regimes: Vec<String>,
    /// Loss (dB × weight): the worst approach's hinge.
    pub loss_db: f64,
    /// Whether every approach gives the expected finding.
    pub matched: bool,
}

/// The hinge loss (dB, 0 … [`LOSS_CAP_DB`]) of a half-order height `height_db` (NaN:
/// no line) against `line_db`, needing `margin_db` of clearance either way.
pub fn hinge_db(expect: Expect, height_db: f64, line_db: f64, margin_db: f64) -> f64 {
    let h = if height_db.is_nan() {
        f64::NEG_INFINITY
    } else {
        height_db
    };
    let loss = match expect {
        Expect::Present => line_db + margin_db - h,
        Expect::Absent => h - (line_db - margin_db),
    };
    loss.clamp(0.0, LOSS_CAP_DB)
}

/// Whether `height_db` gives the expected verdict (present when ≥ `line_db`, as the sweep decides).
pub fn verdict_matches(expect: Expect, height_db: f64, line_db: f64) -> bool {
    let present = height_db >= line_db;
    present == (expect == Expect::Present)
}

/// Loss (dB) of natural frequency `hz` against `target`: `weight` per tolerance outside it.
pub fn natural_loss_db(target: &NaturalTarget, hz: f64) -> f64 {
    if !hz.is_finite() {
        return FAILED_LOSS_DB;
    }
    let outside = ((hz - target.hz).abs() - target.tolerance_hz).max(0.0);
    (target.weight * outside / target.tolerance_hz).min(FAILED_LOSS_DB)
}

/// The period the thesis's motion has where the half-order line is `expect`ed: 2 where
/// present, 1 where absent.
fn expected_period(expect: Expect) -> usize {
    match expect {
        Expect::Present => 2,
        Expect::Absent => 1,
    }
}

/// Loss (dB, 0 … [`LOSS_CAP_DB`]) of a judged motion against the thesis's there: how far
/// the expected period's spread and line fraction fall short of the judge's thresholds
/// (10 log10 of the ratio), for period 2 the half-order line's shortfall under
/// [`SUBHARMONIC_CLEAR_DB`] + `margin_db`, and up to 10 dB for chaos (K above
/// [`CHAOS_K_MIN`]). 0 only for the clean motion the thesis saw.
pub fn motion_loss_db(expect: Expect, judged: &Judgement, margin_db: f64) -> f64 {
    let k = expected_period(expect);
    let over = |value: f64, limit: f64| 10.0 * (value / limit).max(1.0).log10();
    let spread = judged.spread.get(k - 1).copied().flatten().unwrap_or(1.0);
    let missing = 1.0
        - judged
            .line_fraction
            .get(k - 1)
            .copied()
            .flatten()
            .unwrap_or(0.0);
    let mut loss = over(spread, SPREAD_MAX) + over(missing, 1.0 - LINE_FRACTION_MIN);
    if k == 2 {
        let height = judged.half_order_db.unwrap_or(0.0);
        loss += (SUBHARMONIC_CLEAR_DB + margin_db - height).max(0.0);
    }
    let chaos = judged.chaos_k.unwrap_or(0.0);
    loss += 10.0 * ((chaos - CHAOS_K_MIN) / (1.0 - CHAOS_K_MIN)).clamp(0.0, 1.0);
    loss.clamp(0.0, LOSS_CAP_DB)
}

/// Whether the judged motion is the thesis's where the line is `expect`ed: period 1, or
/// period 2 with the half-order line clear of the floor.
pub fn motion_matches(expect: Expect, judged: &Judgement) -> bool {
    match expect {
        Expect::Absent => judged.motion == Motion::Periodic(1),
        Expect::Present => judged.motion == Motion::Periodic(2) && judged.half_order_clear(),
    }
}

#[cfg(test)]
mod tests {
    use rig::judge::{Judgement, Motion};

    use super::{LOSS_CAP_DB, motion_loss_db, motion_matches};
    use crate::calibrate::calibration_plan::Expect;

    fn judged(
        motion: Motion,
        spread: [f64; 2],
        fraction: [f64; 2],
        half_db: f64,
        k: f64,
    ) -> Judgement {
        Judgement {
            motion,
            ac_rms_nm: 1.0,
            spread: spread.map(Some).to_vec(),
            line_fraction: fraction.map(Some).to_vec(),
            half_order_db: Some(half_db),
            third_order_db: None,
            half_order_share: Some(0.1),
            third_order_share: None,
            chaos_k: Some(k),
        }
    }

    #[test]
    fn clean_motion_costs_nothing_and_chaos_costs_most() {
        let period_two = judged(Motion::Periodic(2), [0.3, 1e-6], [0.2, 0.9999], 120.0, 0.0);
        assert_eq!(motion_loss_db(Expect::Present, &period_two, 3.0), 0.0);
        assert!(motion_matches(Expect::Present, &period_two));
        // Where the thesis saw period 1, the same motion scatters every revolution.
        let wrong = motion_loss_db(Expect::Absent, &period_two, 3.0);
        assert!(wrong > 5.0, "{wrong}");
        assert!(!motion_matches(Expect::Absent, &period_two));
        let near = judged(Motion::QuasiPeriodic, [0.3, 0.08], [0.2, 0.93], 25.0, 0.1);
        let chaos = judged(Motion::Chaotic, [0.6, 0.6], [0.2, 0.4], 12.0, 0.95);
        let (near, chaos) = (
            motion_loss_db(Expect::Present, &near, 3.0),
            motion_loss_db(Expect::Present, &chaos, 3.0),
        );
        assert!(
            0.0 < near && near < chaos && chaos <= LOSS_CAP_DB,
            "{near} {chaos}"
        );
    }
}
