//! The objective: a hinge on each point's half-order height against its threshold, so
//! the search sees progress before a verdict flips; and the score (points matched) beside it.

use serde::{Deserialize, Serialize};

use super::plan::{Expect, NaturalTarget};

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
