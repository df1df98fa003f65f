//! Evaluating candidates: every target point from every approach, in parallel over all
//! candidates of a generation.

use rayon::prelude::*;
use rig::{Approach, Judgement};
use serde::{Deserialize, Serialize};

use crate::sweep::{Case, CaseRig, Direction, run_case};
use crate::vocabulary::seeds::case_seed;

use super::calibration_plan::{ApproachKind, CalibrationPlan, Expect, Scoring, TargetPoint};
use super::free_param::params_at;
use super::objective::{
    FAILED_LOSS_DB, LOSS_CAP_DB, PointOutcome, hinge_db, motion_loss_db, motion_matches,
    natural_loss_db, verdict_matches,
};

/// One candidate's result.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct Evaluation {
    /// Objective (dB): the weighted mean point loss plus the natural-frequency losses.
    pub objective: f64,
    /// Points matched from every approach.
    pub matched: usize,
    /// Points evaluated.
    pub points: usize,
    /// Each point.
    pub outcomes: Vec<PointOutcome>,
    /// Natural frequencies of the targets' modes (Hz; null if the rig has no such mode).
    pub natural_hz: Vec<Option<f64>>,
    /// Why the candidate could not be evaluated, if so.
    pub error: Option<String>,
}

/// The case of `point` from `approach` on `rig`.
fn case_of(plan: &CalibrationPlan, point: &TargetPoint, kind: ApproachKind, rig: &CaseRig) -> Case {
    let approach = match kind {
        ApproachKind::Static => Approach::Static,
        ApproachKind::FromBelow => Approach::ramp_to(point.rpm, plan.approach_rpm, plan.ramp_s),
        ApproachKind::FromAbove => Approach::ramp_to(point.rpm, -plan.approach_rpm, plan.ramp_s),
    };
    Case {
        index: point.index,
        rpm: point.rpm,
        load_nm: point.load_nm,
        values: Vec::new(),
        rig: rig.clone(),
        seed: case_seed(plan.sweep.seed, point.index),
        approach,
        direction: Direction::Static,
        series: None,
        kick_rad_s: 0.0,
    }
}

/// Evaluates each of `candidates` (unit-box coordinates) on `points`, in parallel on the
/// current rayon pool.
pub fn evaluate_all(
    plan: &CalibrationPlan,
    candidates: &[Vec<f64>],
    points: &[TargetPoint],
) -> Vec<Evaluation> {
    let params: Vec<anyhow::Result<CaseRig>> = candidates
        .iter()
        .map(|x| params_at(&plan.base, &plan.free, x))
        .collect();
    let jobs: Vec<(usize, &CaseRig, usize, usize)> = params
        .iter()
        .enumerate()
        .filter_map(|(c, rig)| rig.as_ref().ok().map(|rig| (c, rig)))
        .flat_map(|(c, rig)| {
            (0..points.len())
                .flat_map(move |p| (0..plan.approaches.len()).map(move |a| (c, rig, p, a)))
        })
        .collect();
    let heights: Vec<CaseOutcome> = jobs
        .par_iter()
        .map(|&(candidate, rig, point, approach)| {
            let case = case_of(plan, &points[point], plan.approaches[approach], rig);
            let result = run_case(&plan.sweep, &case, None)
                .map(|r| CaseSeen {
                    height_db: r.half_order_db,
                    regime: r.regime.to_string(),
                    motion: r.motion,
                })
                .map_err(|e| {
                    let p = &points[point];
                    format!("{} rev/min, {} N m: {e:#}", p.rpm, p.load_nm)
                });
            CaseOutcome {
                candidate,
                point,
                approach,
                result,
            }
        })
        .collect();
    params
        .iter()
        .enumerate()
        .map(|(c, rig)| match rig {
            Err(e) => failed(format!("{e:#}")),
            Ok(rig) => {
                let mine: Vec<&CaseOutcome> = heights.iter().filter(|h| h.candidate == c).collect();
                assemble(plan, rig, points, &mine)
            }
        })
        .collect()
}

/// One case of one candidate: what it showed, or why it failed.
struct CaseOutcome {
    candidate: usize,
    point: usize,
    approach: usize,
    result: Result<CaseSeen, String>,
}

/// What a case showed: the half-order line's height (dB), the regime and the judge's
/// motion.
struct CaseSeen {
    height_db: f64,
    regime: String,
    motion: Judgement,
}

/// One candidate's evaluation from its cases' results.
fn assemble(
    plan: &CalibrationPlan,
    rig: &CaseRig,
    points: &[TargetPoint],
    cases: &[&CaseOutcome],
) -> Evaluation {
    if let Some(Err(e)) = cases.iter().map(|c| &c.result).find(|r| r.is_err()) {
        return failed(e.clone());
    }
    let line_db = plan.sweep.line_db;
    let mut outcomes = Vec::with_capacity(points.len());
    for (p, point) in points.iter().enumerate() {
        let mut heights = vec![f64::NAN; plan.approaches.len()];
        let mut regimes = vec![String::new(); plan.approaches.len()];
        let mut motions: Vec<Option<&Judgement>> = vec![None; plan.approaches.len()];
        for case in cases.iter().filter(|c| c.point == p) {
            if let Ok(seen) = &case.result {
                heights[case.approach] = seen.height_db;
                regimes[case.approach] = match plan.scoring {
                    Scoring::Line => seen.regime.clone(),
                    Scoring::Motion => seen.motion.motion.to_string(),
                };
                motions[case.approach] = Some(&seen.motion);
            }
        }
        let (loss, matched) = match plan.scoring {
            Scoring::Line => (
                heights
                    .iter()
                    .map(|&h| hinge_db(point.expect, h, line_db, plan.margin_db))
                    .fold(0.0, f64::max),
                heights
                    .iter()
                    .all(|&h| verdict_matches(point.expect, h, line_db)),
            ),
            Scoring::Motion => (
                motions
                    .iter()
                    .map(|m| {
                        m.map_or(LOSS_CAP_DB, |m| {
                            motion_loss_db(point.expect, m, plan.margin_db)
                        })
                    })
                    .fold(0.0, f64::max),
                motions
                    .iter()
                    .all(|m| m.is_some_and(|m| motion_matches(point.expect, m))),
            ),
        };
        outcomes.push(PointOutcome {
            index: point.index,
            rpm: point.rpm,
            load_nm: point.load_nm,
            expect_present: point.expect == Expect::Present,
            heights_db: heights
                .iter()
                .map(|h| h.is_finite().then_some(*h))
                .collect(),
            regimes,
            loss_db: point.weight * loss,
            matched,
        });
    }
    let weights: f64 = points.iter().map(|p| p.weight).sum();
    let mut objective = if weights > 0.0 {
        outcomes.iter().map(|o| o.loss_db).sum::<f64>() / weights
    } else {
        0.0
    };
    // The modal analysis only where a natural frequency is a target.
    let modes_hz = if plan.natural.is_empty() {
        Vec::new()
    } else {
        rig.natural_hz()
    };
    let natural_hz: Vec<f64> = plan
        .natural
        .iter()
        .map(|n| modes_hz.get(n.mode - 1).copied().unwrap_or(f64::NAN))
        .collect();
    objective += plan
        .natural
        .iter()
        .zip(&natural_hz)
        .map(|(n, &hz)| natural_loss_db(n, hz))
        .sum::<f64>();
    Evaluation {
        objective,
        matched: outcomes.iter().filter(|o| o.matched).count(),
        points: outcomes.len(),
        outcomes,
        natural_hz: natural_hz
            .iter()
            .map(|h| h.is_finite().then_some(*h))
            .collect(),
        error: None,
    }
}

fn failed(error: String) -> Evaluation {
    Evaluation {
        objective: FAILED_LOSS_DB,
        matched: 0,
        points: 0,
        outcomes: Vec::new(),
        natural_hz: Vec::new(),
        error: Some(error),
    }
}
