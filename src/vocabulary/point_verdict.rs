//! The judged motion of one measured point of a run: what the plant's thread found over
//! the point's settled window, sent on a frame to the sinks that write the point's rows
//! (readings, spectra) and kept for the manifest and the terminal.

use std::collections::VecDeque;
use std::sync::Arc;

use rig::SteadySummary;
use serde::Serialize;

use super::GearIndicators;

/// The verdict on measurement `index` (of the plan's measurements, from 0).
#[derive(Clone, Debug, Serialize)]
pub struct PointVerdict {
    /// Which measurement (0-based, in the plan's order).
    pub index: usize,
    /// Start of the judged window (s of simulated time).
    pub from_s: f64,
    /// The window's summary: regime, the judge's motion, torques, impacts.
    #[serde(flatten)]
    pub summary: SteadySummary,
    /// The driven gear's condition indicators over the window (the true output-shaft
    /// torque averaged synchronously over its revolutions; none under two revolutions).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub condition: Option<GearIndicators>,
}

/// The verdicts a sink has been sent so far, by measurement.
#[derive(Clone, Debug, Default)]
struct PointVerdicts(Vec<Option<Arc<PointVerdict>>>);

impl PointVerdicts {
    fn add(&mut self, verdicts: &[Arc<PointVerdict>]) {
        for verdict in verdicts {
            if self.0.len() <= verdict.index {
                self.0.resize(verdict.index + 1, None);
            }
            self.0[verdict.index] = Some(Arc::clone(verdict));
        }
    }

    fn get(&self, index: usize) -> Option<&Arc<PointVerdict>> {
        self.0.get(index).and_then(Option::as_ref)
    }
}

/// What a row learns of its point's motion.
#[derive(Clone, Debug)]
pub enum RowMotion {
    /// The row belongs to no judged point (a run without measurements of its own, an
    /// average started by a command).
    NoPoint,
    /// Its point's verdict.
    Judged(Arc<PointVerdict>),
    /// Its point's window never ended (a stopped run).
    Unjudged,
}

impl RowMotion {
    /// The motion's name as a row shows it: the judged motion, "unjudged", or nothing.
    pub fn label(&self) -> String {
        match self {
            Self::NoPoint => String::new(),
            Self::Judged(v) => v.summary.motion.motion.to_string(),
            Self::Unjudged => "unjudged".into(),
        }
    }
}

/// A sink's rows waiting, in the order they were made, for the verdicts on their points
/// (which come on later frames): each row is let go once its verdict is in, or at once
/// when it belongs to no point, or at the run's end as unjudged.
pub struct AwaitingVerdicts<T> {
    waiting: VecDeque<(Option<usize>, T)>,
    verdicts: PointVerdicts,
}

impl<T> Default for AwaitingVerdicts<T> {
    fn default() -> Self {
        Self {
            waiting: VecDeque::new(),
            verdicts: PointVerdicts::default(),
        }
    }
}

impl<T> AwaitingVerdicts<T> {
    /// Keeps the verdicts a frame carried.
    pub fn add_verdicts(&mut self, verdicts: &[Arc<PointVerdict>]) {
        self.verdicts.add(verdicts);
    }

    /// Queues `row` of measurement `point` (`None`: of no judged point).
    pub fn push(&mut self, point: Option<usize>, row: T) {
        self.waiting.push_back((point, row));
    }

    /// The rows ready, in order, with their motion; at the run's `end`, all of them.
    pub fn take_ready(&mut self, end: bool) -> Vec<(T, RowMotion)> {
        let mut ready = Vec::new();
        while let Some((point, _)) = self.waiting.front() {
            let motion = match point.map(|p| self.verdicts.get(p)) {
                None => RowMotion::NoPoint,
                Some(Some(verdict)) => RowMotion::Judged(Arc::clone(verdict)),
                Some(None) if end => RowMotion::Unjudged,
                Some(None) => break,
            };
            let (_, row) = self.waiting.pop_front().expect("a front");
            ready.push((row, motion));
        }
        ready
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn verdict(index: usize) -> Arc<PointVerdict> {
        // A still window: no torque, no impacts, the judge's verdict on nothing.
        let motion = rig::judge(&rig::JudgeInput {
            torque_nm: &[0.0; 1024],
            rate_hz: 51_200.0,
            running_hz: 10.0,
            revolution_torque_nm: &[],
        });
        let summary = rig::SteadySummary {
            measured_s: 0.02,
            impacts: 0,
            impacts_per_rev: 0.0,
            impacts_per_tooth: vec![0; 30],
            regime: rig::Regime::Periodic(1),
            separates: false,
            apart_fraction: 0.0,
            torque_mean_nm: 0.0,
            torque_rms_nm: 0.0,
            torque_ac_rms_nm: 0.0,
            revolutions: 0,
            speed_offset_rpm: 0.0,
            motion,
        };
        Arc::new(PointVerdict {
            index,
            from_s: 0.0,
            summary,
            condition: None,
        })
    }

    #[test]
    fn rows_wait_in_order_for_their_points_and_the_rest_go_unjudged_at_the_end() {
        let mut rows = AwaitingVerdicts::default();
        rows.push(None, "start");
        rows.push(Some(0), "point 1");
        rows.push(Some(1), "point 2");
        let ready = rows.take_ready(false);
        assert_eq!(ready.len(), 1, "a row of no point goes at once");
        assert!(matches!(ready[0].1, RowMotion::NoPoint));
        // The verdict on point 2 alone lets nothing go: point 1 is still ahead of it.
        rows.add_verdicts(&[verdict(1)]);
        assert!(rows.take_ready(false).is_empty());
        rows.add_verdicts(&[verdict(0)]);
        let ready = rows.take_ready(false);
        let names: Vec<&str> = ready.iter().map(|(r, _)| *r).collect();
        assert_eq!(names, ["point 1", "point 2"]);
        rows.push(Some(2), "point 3");
        assert!(rows.take_ready(false).is_empty());
        let last = rows.take_ready(true);
        assert!(matches!(last[0].1, RowMotion::Unjudged));
        assert_eq!(last[0].1.label(), "unjudged");
    }
}
