//! The judged motion of one measured point of a run: what the plant's thread found over
//! the point's settled window, sent on a frame to the sinks that write the point's rows
//! (readings, spectra) and kept for the manifest and the terminal.

use std::sync::Arc;

use rig::SteadySummary;
use serde::Serialize;

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
}

/// The verdicts a sink has been sent so far, by measurement.
#[derive(Clone, Debug, Default)]
pub struct PointVerdicts(Vec<Option<Arc<PointVerdict>>>);

impl PointVerdicts {
    /// Keeps `verdicts` (those a frame carried).
    pub fn add(&mut self, verdicts: &[Arc<PointVerdict>]) {
        for verdict in verdicts {
            if self.0.len() <= verdict.index {
                self.0.resize(verdict.index + 1, None);
            }
            self.0[verdict.index] = Some(Arc::clone(verdict));
        }
    }

    /// The verdict on measurement `index`, once it has come.
    pub fn get(&self, index: usize) -> Option<&PointVerdict> {
        self.0.get(index).and_then(|v| v.as_deref())
    }
}

/// The motion's name for a row of measurement `index`: the judged motion, or
/// "unjudged" where the point's window did not end (a stopped run).
pub fn motion_label(verdict: Option<&PointVerdict>) -> String {
    verdict.map_or("unjudged".into(), |v| v.summary.motion.motion.to_string())
}
